#include "pneumachaos/model/parameter_grid.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_keys.hpp"

namespace pneumachaos {
namespace {

// `axis` is the axis's text as detail() of the error (" KEY=FROM:TO:STEP").
double number(const std::string& text, const std::string& what, const std::string& axis) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || text.empty() || !std::isfinite(v)) {
    throw Error(kGridAxisField, axis,
                fmt::format("{} must be a finite number, got \"{}\"", what, text));
  }
  return v;
}

// A trial value of `key`, whose errors (unknown key) name the axis they came from.
SettingValue key_setting(const std::string& key, const std::string& axis) {
  try {
    return parse_setting_text(key, "0", "");
  } catch (const Error& e) {
    throw Error(kGridAxisField, axis + ": " + e.where(), e.message());
  }
}

}  // namespace

GridAxis parse_grid_axis(const std::string& text) {
  const std::string where = " " + text;  // detail() of every error about the axis
  const auto bad = [&](const std::string& why) { return Error(kGridAxisField, where, why); };
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw bad("expected KEY=FROM:TO:STEP, e.g. circuit.S2_mm2=0.05:4.40:0.15");
  }
  GridAxis axis;
  axis.key = text.substr(0, eq);
  // A word-valued key cannot be gridded; parse_setting_text also rejects unknown keys.
  if (!std::holds_alternative<double>(key_setting(axis.key, where))) {
    throw bad(axis.key + " takes a word, not a number; only numeric keys can be gridded");
  }
  const std::string range = text.substr(eq + 1);
  const auto c1 = range.find(':');
  const auto c2 = c1 == std::string::npos ? c1 : range.find(':', c1 + 1);
  if (c2 == std::string::npos) throw bad("expected FROM:TO:STEP after the key");
  const double from = number(range.substr(0, c1), "FROM", where);
  const double to = number(range.substr(c1 + 1, c2 - c1 - 1), "TO", where);
  const double step = number(range.substr(c2 + 1), "STEP", where);
  if (!(step > 0.0)) throw bad(fmt::format("STEP must be positive, got {}", step));
  if (from > to) throw bad(fmt::format("FROM {} lies above TO {}", from, to));
  const double count = std::floor((to - from) / step + 1e-6) + 1.0;
  if (count > 1e5) throw bad(fmt::format("{} values is more than 100000", count));
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
    // Rounded to 12 significant digits so that 2.45 + 5 * 0.05 is 2.7, as the user meant.
    const double v = from + static_cast<double>(i) * step;
    axis.values.push_back(std::stod(fmt::format("{:.12g}", v)));
  }
  return axis;
}

std::vector<GridAxis> paper_valve_grid() {
  return {parse_grid_axis("circuit.S1_mm2=2.45:3.70:0.05"),
          parse_grid_axis("circuit.S2_mm2=0.05:4.40:0.15")};
}

void validate_grid(const std::vector<GridAxis>& axes) {
  if (axes.empty()) throw Error(kGridField, "at least one grid axis is needed");
  for (std::size_t i = 0; i < axes.size(); ++i) {
    if (axes[i].values.empty())
      throw Error(kGridAxisField, " " + axes[i].key, "the axis has no values");
    for (std::size_t j = 0; j < i; ++j) {
      if (axes[i].key == axes[j].key)
        throw Error(kGridAxisField, " " + axes[i].key, "the key is gridded twice");
    }
  }
}

std::size_t grid_size(const std::vector<GridAxis>& axes) {
  std::size_t n = 1;
  for (const auto& a : axes) n *= a.values.size();
  return n;
}

std::vector<std::size_t> grid_index(const std::vector<GridAxis>& axes, std::size_t flat) {
  std::vector<std::size_t> index(axes.size());
  for (std::size_t i = axes.size(); i-- > 0;) {
    index[i] = flat % axes[i].values.size();
    flat /= axes[i].values.size();
  }
  return index;
}

Scenario scenario_at(const Scenario& base, const std::vector<GridAxis>& axes,
                     const std::vector<std::size_t>& index) {
  Scenario s = base;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    apply_setting(s, axes[i].key, axes[i].values.at(index[i]), "grid point");
  }
  return s;
}

}  // namespace pneumachaos
