#pragma once
// Library errors name the option field that was wrong (e.g. "lyapunov.measure_s"); a user
// typed a flag. Commands run their library calls through this so the message names the flag.

#include <map>
#include <string>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::cli {

/// Field name as the library reports it -> the flag the user typed.
using FlagNames = std::map<std::string, std::string>;

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
