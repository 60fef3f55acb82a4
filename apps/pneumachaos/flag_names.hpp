#pragma once
// Library errors name the option field or the input that was wrong (e.g. "lyapunov.measure_s",
// "override friction.Fx_N", "grid axis circuit.S1_mm2=3:2:1") and carry the field's id
// (ErrorField, declared next to the options); a user typed a flag. The CLI maps those ids to
// the flags that set them, so the library never names a flag and no message is parsed.

#include <map>
#include <string>
#include <string_view>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::cli {

/// A library field's id (ErrorField::id) -> the flag that sets it.
using FlagNames = std::map<std::string_view, std::string>;

/// The fields every command shares: scenario overrides, sweep grids, repeats and the model
/// exponent, adaptive maps, a record's sampling rate, the fit's free keys.
const FlagNames& common_flag_names();

/// The place as the user typed it: e.where() with the field's label replaced by the flag of
/// `names` (the rest, e.detail(), kept); e.where() when the error's field is not in `names`.
std::string where_as_typed(const Error& e, const FlagNames& names);

/// e.what() with its place translated by where_as_typed.
std::string message_as_typed(const Error& e, const FlagNames& names);

/// The same error, of the same kind (Error or RunError), naming the flag instead of the field.
[[noreturn]] void rethrow_with_flag(const Error& e, const FlagNames& names);

/// Runs f(); an Error from it about a field in `names` is re-raised naming the flag.
template <typename F>
decltype(auto) with_flag_names(const FlagNames& names, F&& f) {
  try {
    return f();
  } catch (const Error& e) {
    rethrow_with_flag(e, names);
  }
}

}  // namespace pneumachaos::cli
