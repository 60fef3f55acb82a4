#include "pneumachaos/core/validation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace pneumachaos::validation {
namespace {

std::string with_why(std::string range, std::string_view why) {
  if (!why.empty()) range += fmt::format(" ({})", why);
  return range;
}

}  // namespace

void require(bool ok, ErrorField field, double value, std::string_view range) {
  if (ok) return;
  // The message names the field by its id (section.field) whatever its label.
  throw Error(ErrorField{field.id, field.id}, fmt::format(" = {}", value),
              fmt::format("must be {}", range));
}

void require_gt(ErrorField field, double value, double bound, std::string_view why) {
  require(value > bound, field, value, with_why(fmt::format("> {}", bound), why));
}

void require_ge(ErrorField field, double value, double bound, std::string_view why) {
  require(value >= bound, field, value, with_why(fmt::format(">= {}", bound), why));
}

void require_lt(ErrorField field, double value, double bound, std::string_view why) {
  require(value < bound, field, value, with_why(fmt::format("< {}", bound), why));
}

void require_le(ErrorField field, double value, double bound, std::string_view why) {
  require(value <= bound, field, value, with_why(fmt::format("<= {}", bound), why));
}

void require_between(ErrorField field, double value, double lo, double hi, std::string_view why) {
  require(value >= lo && value <= hi, field, value,
          with_why(fmt::format("between {} and {}", lo, hi), why));
}

void require_ge_lt(ErrorField field, double value, double lo, double hi, std::string_view why) {
  require(value >= lo && value < hi, field, value,
          with_why(fmt::format(">= {} and < {}", lo, hi), why));
}

void require_gt_le(ErrorField field, double value, double lo, double hi, std::string_view why) {
  require(value > lo && value <= hi, field, value,
          with_why(fmt::format("> {} and <= {}", lo, hi), why));
}

void require_gt_lt(ErrorField field, double value, double lo, double hi, std::string_view why) {
  require(value > lo && value < hi, field, value,
          with_why(fmt::format("> {} and < {}", lo, hi), why));
}

void require_finite_gt(ErrorField field, double value, double bound, std::string_view why) {
  require(std::isfinite(value) && value > bound, field, value,
          with_why(fmt::format("finite and > {}", bound), why));
}

void require_finite_ge(ErrorField field, double value, double bound, std::string_view why) {
  require(std::isfinite(value) && value >= bound, field, value,
          with_why(fmt::format("finite and >= {}", bound), why));
}

void require_finite(ErrorField field, double value, std::string_view why) {
  require(std::isfinite(value), field, value, with_why("a finite number", why));
}

}  // namespace pneumachaos::validation
