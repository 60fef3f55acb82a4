#pragma once
// Library errors name the option field or the input that was wrong (e.g. "lyapunov.measure_s",
// "override friction.Fx_N", "grid axis circuit.S1_mm2=3:2:1"); a user typed a flag. The CLI
// translates those places into the flags they came from, so the library never names a flag.

#include <map>
#include <string>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::cli {

/// Place as the library reports it (or its first word(s), before ": " or " ") -> the flag.
using FlagNames = std::map<std::string, std::string>;

/// The places every command shares: scenario overrides, sweep grids and repeats, the output
/// directory, a record's sampling rate.
const FlagNames& common_flag_names();

/// `where` with a leading place of `names` replaced by its flag; unchanged when none matches.
std::string where_as_typed(const std::string& where, const FlagNames& names);

/// e.what() with its place translated by where_as_typed.
std::string message_as_typed(const Error& e, const FlagNames& names);

/// The same error, of the same kind (Error or RunError), naming the flag instead of the field.
[[noreturn]] void rethrow_with_flag(const Error& e, const FlagNames& names);

/// Runs f(); an Error from it that names a field in `names` is re-raised naming the flag.
template <typename F>
decltype(auto) with_flag_names(const FlagNames& names, F&& f) {
  try {
    return f();
  } catch (const Error& e) {
    rethrow_with_flag(e, names);
  }
}

}  // namespace pneumachaos::cli
