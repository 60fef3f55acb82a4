#pragma once
// The one error family for bad user input (docs/architecture.md).

#include <stdexcept>
#include <string>

namespace pneumachaos {

/// Raised for bad user input: a scenario key, a file line, a command-line value.
/// `where()` names the place (file:line:column, a scenario key, a flag) and `what()` holds
/// the full message "where: what was wrong, what was expected".
class Error : public std::runtime_error {
 public:
  Error(std::string where, const std::string& message);
  [[nodiscard]] const std::string& where() const noexcept { return where_; }
  /// What was wrong, without the place: what() is where() + ": " + message().
  [[nodiscard]] const std::string& message() const noexcept { return message_; }

 private:
  std::string where_;
  std::string message_;
};

/// Raised when a run with valid input cannot complete: an output that cannot be written (a
/// full disk), a computation that failed. The CLI exits 3 for these, 2 for other Errors.
class RunError : public Error {
 public:
  using Error::Error;
};

}  // namespace pneumachaos
