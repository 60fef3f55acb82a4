#pragma once
// The one error family for bad user input (docs/architecture.md).

#include <stdexcept>
#include <string>
#include <string_view>

namespace pneumachaos {

/// The option or input an Error concerns, for callers that name it their own way (the
/// command line names the flag that set it). Each is declared once, next to the options it
/// belongs to (e.g. SweepSpec::kRepeatsField). `id` is stable and machine-readable
/// ("sweep.repeats"); `label` is the words the message uses for it ("repeats").
struct ErrorField {
  std::string_view id;
  std::string_view label;
};

/// Raised for bad user input: a scenario key, a file line, a command-line value.
/// `where()` names the place (file:line:column, a scenario key, a flag) and `what()` holds
/// the full message "where: what was wrong, what was expected".
class Error : public std::runtime_error {
 public:
  Error(std::string where, const std::string& message);
  /// An error about `field`: where() is the field's label followed by `detail` as given
  /// (e.g. " circuit.S1_mm2=3:2:1" or ": friction.Fx_N"; often empty).
  Error(ErrorField field, const std::string& detail, const std::string& message);
  Error(ErrorField field, const std::string& message) : Error(field, std::string(), message) {}
  [[nodiscard]] const std::string& where() const noexcept { return where_; }
  /// What was wrong, without the place: what() is where() + ": " + message().
  [[nodiscard]] const std::string& message() const noexcept { return message_; }
  /// The id of the field the error concerns, or "" when it names none.
  [[nodiscard]] const std::string& field() const noexcept { return field_; }
  /// where() after the field's label (what identifies the input further); "" without a field.
  [[nodiscard]] const std::string& detail() const noexcept { return detail_; }

 private:
  std::string where_;
  std::string message_;
  std::string field_;
  std::string detail_;
};

/// Raised when a run with valid input cannot complete: an output that cannot be written (a
/// full disk), a computation that failed. The CLI exits 3 for these, 2 for other Errors.
class RunError : public Error {
 public:
  using Error::Error;
};

}  // namespace pneumachaos
