#include "pneumachaos/core/time_series.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

TimeSeries::TimeSeries(double rate_Hz, double start_s) : rate_Hz_(rate_Hz), start_s_(start_s) {
  if (!(std::isfinite(rate_Hz) && rate_Hz > 0.0)) {
    throw Error("rate",
                fmt::format("sample rate must be a positive number of Hz, got {}", rate_Hz));
  }
}

std::size_t TimeSeries::add_channel(std::string name, std::string unit) {
  if (has_channel(name)) throw Error("channel " + name, "a channel of that name exists already");
  if (size() != 0) throw Error("channel " + name, "channels must be added before any sample");
  channels_.push_back({std::move(name), std::move(unit), {}});
  return channels_.size() - 1;
}

std::size_t TimeSeries::add_channel(std::string name, std::string unit,
                                    std::vector<double> values) {
  if (has_channel(name)) throw Error("channel " + name, "a channel of that name exists already");
  if (!channels_.empty() && values.size() != size()) {
    throw Error("channel " + name, fmt::format("{} values for a series of {} samples",
                                               values.size(), size()));
  }
  channels_.push_back({std::move(name), std::move(unit), std::move(values)});
  return channels_.size() - 1;
}

void TimeSeries::append(std::span<const double> row) {
  if (row.size() != channels_.size()) {
    throw Error("TimeSeries::append",
                fmt::format("row has {} values for {} channels", row.size(), channels_.size()));
  }
  for (std::size_t c = 0; c < row.size(); ++c) channels_[c].values.push_back(row[c]);
}

std::size_t TimeSeries::size() const noexcept {
  return channels_.empty() ? 0 : channels_.front().values.size();
}

bool TimeSeries::has_channel(const std::string& name) const noexcept {
  return std::any_of(channels_.begin(), channels_.end(),
                     [&](const Channel& c) { return c.name == name; });
}

const Channel& TimeSeries::channel(const std::string& name) const {
  for (const auto& c : channels_) {
    if (c.name == name) return c;
  }
  std::string known;
  for (const auto& c : channels_) known += (known.empty() ? "" : ", ") + c.name;
  throw Error("channel " + name, "no such channel; the series has: " + known);
}

}  // namespace pneumachaos
