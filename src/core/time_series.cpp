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

TimeSeries time_window(const TimeSeries& series, std::optional<double> from_s,
                       std::optional<double> to_s) {
  const std::size_t n = series.size();
  const double first = series.start_s();
  const double last = n == 0 ? first : series.time_s(n - 1);
  const auto check_inside = [&](std::optional<double> t, ErrorField name) {
    if (!t) return;
    if (!std::isfinite(*t) || *t < first || *t > last)
      throw Error(name, fmt::format("{} s lies outside the record, which spans {:.6g} to {:.6g} s",
                                    *t, first, last));
  };
  check_inside(from_s, kWindowFromField);
  check_inside(to_s, kWindowToField);
  // A bound typed as a sample's time selects that sample, whatever its rounding.
  constexpr double kSlack = 1e-6;  // of a sample
  const double rate = series.rate_Hz();
  const std::size_t begin =
      from_s ? static_cast<std::size_t>(std::max(0.0, std::ceil((*from_s - first) * rate - kSlack)))
             : 0;
  const std::size_t end =
      to_s ? std::min(n, static_cast<std::size_t>(std::floor((*to_s - first) * rate + kSlack)) + 1)
           : n;
  if (end < begin + 2) {
    throw Error(to_s ? kWindowToField : kWindowFromField,
                fmt::format("the window {:.6g} to {:.6g} s holds {} sample(s); at least 2 are "
                            "needed",
                            from_s.value_or(first), to_s.value_or(last),
                            end > begin ? end - begin : 0));
  }
  TimeSeries out(series.rate_Hz(), series.time_s(begin));
  for (const Channel& c : series.channels()) {
    out.add_channel(c.name, c.unit,
                    std::vector<double>(c.values.begin() + static_cast<std::ptrdiff_t>(begin),
                                        c.values.begin() + static_cast<std::ptrdiff_t>(end)));
  }
  return out;
}

}  // namespace pneumachaos
