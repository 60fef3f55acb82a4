#pragma once
// One vocabulary for the validate() of every options, spec, settings and params struct of the
// public API (in the spirit of Ceres' OPTION_GT/OPTION_GE checks). Each refusal is an Error
// (bad input: the command line exits 2) naming the field as section.field, its value and the
// range it must lie in:
//
//   verdict.min_samples = 0: must be >= 1
//
// Every check is written so that a NaN fails it: a NaN is outside every range.

#include <string_view>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::validation {

/// A field named by its id, "section.field", which is also the label its messages use. The
/// string must outlive the call (a literal, or an ErrorField's own strings).
constexpr ErrorField field(std::string_view id) { return ErrorField{id, id}; }

/// Throws Error unless `ok`: the message reads "<id> = <value>: must be <range>" (the field's
/// id, section.field, whatever its label), where() is "<id> = <value>", field() the id and
/// detail() " = <value>" (the command line replaces the id by the option that set it).
void require(bool ok, ErrorField field, double value, std::string_view range);

// The ranges. `why`, when given, is appended to the range in parentheses, e.g. "> 1 (the bounds
// must enclose the start)".

/// value > bound
void require_gt(ErrorField field, double value, double bound, std::string_view why = {});
/// value >= bound
void require_ge(ErrorField field, double value, double bound, std::string_view why = {});
/// value < bound
void require_lt(ErrorField field, double value, double bound, std::string_view why = {});
/// value <= bound
void require_le(ErrorField field, double value, double bound, std::string_view why = {});
/// lo <= value <= hi: "must be between lo and hi"
void require_between(ErrorField field, double value, double lo, double hi,
                     std::string_view why = {});
/// lo <= value < hi: "must be >= lo and < hi"
void require_ge_lt(ErrorField field, double value, double lo, double hi, std::string_view why = {});
/// lo < value <= hi: "must be > lo and <= hi"
void require_gt_le(ErrorField field, double value, double lo, double hi, std::string_view why = {});
/// lo < value < hi: "must be > lo and < hi"
void require_gt_lt(ErrorField field, double value, double lo, double hi, std::string_view why = {});
/// a finite value > bound: "must be finite and > bound"
void require_finite_gt(ErrorField field, double value, double bound, std::string_view why = {});
/// a finite value >= bound: "must be finite and >= bound"
void require_finite_ge(ErrorField field, double value, double bound, std::string_view why = {});
/// a finite number: "must be a finite number"
void require_finite(ErrorField field, double value, std::string_view why = {});

}  // namespace pneumachaos::validation
