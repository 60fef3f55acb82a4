#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

Error::Error(std::string where, const std::string& message)
    : std::runtime_error(where.empty() ? message : where + ": " + message),
      where_(std::move(where)),
      message_(message) {}

Error::Error(ErrorField field, const std::string& detail, const std::string& message)
    : Error(std::string(field.label) + detail, message) {
  field_ = field.id;
  detail_ = detail;
}

}  // namespace pneumachaos
