#pragma once
// The message of the Error a piece of code throws, for tests of what bad input is told.
#include <functional>
#include <string>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

/// e.what() of the Error that f throws; "(no error)" when it throws none.
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace pneumachaos
