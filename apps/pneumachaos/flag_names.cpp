#include "flag_names.hpp"

namespace pneumachaos::cli {

void rethrow_with_flag(const Error& e, const FlagNames& names) {
  const auto it = names.find(e.where());
  if (it == names.end()) throw;
  // what() is "where: message"; keep the message, replace the place.
  const std::string message = std::string(e.what()).substr(e.where().size() + 2);
  if (dynamic_cast<const RunError*>(&e) != nullptr) throw RunError(it->second, message);
  throw Error(it->second, message);
}

}  // namespace pneumachaos::cli
