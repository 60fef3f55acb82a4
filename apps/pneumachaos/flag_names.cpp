#include "flag_names.hpp"

namespace pneumachaos::cli {

const FlagNames& common_flag_names() {
  static const FlagNames names{{"override", "--set"},
                               {"grid", "--grid"},
                               {"grid axis", "--grid"},
                               {"repeats", "--repeats"},
                               {"output directory", "--out"},
                               {"sampling rate", "--rate"},
                               {"model exponent transient", "--model-transient"},
                               {"model exponent measure", "--model-measure"},
                               {"model exponent renormalize", "--model-renormalize"},
                               {"free parameter", "--free"},
                               {"adaptive", "--adaptive"},
                               {"adaptive step", "--adaptive-step"}};
  return names;
}

std::string where_as_typed(const std::string& where, const FlagNames& names) {
  // The longest place that is the whole of `where` or is followed by ": " or " " wins, so
  // "grid axis X" becomes "--grid X" and a file named "gridded.csv" is left alone.
  const FlagNames::value_type* best = nullptr;
  for (const auto& entry : names) {
    const std::string& place = entry.first;
    if (!where.starts_with(place)) continue;
    const std::string rest = where.substr(place.size());
    if (!(rest.empty() || rest.starts_with(": ") || rest.starts_with(" "))) continue;
    if (best == nullptr || place.size() > best->first.size()) best = &entry;
  }
  return best == nullptr ? where : best->second + where.substr(best->first.size());
}

std::string message_as_typed(const Error& e, const FlagNames& names) {
  const std::string where = where_as_typed(e.where(), names);
  return where.empty() ? e.message() : where + ": " + e.message();
}

void rethrow_with_flag(const Error& e, const FlagNames& names) {
  const std::string where = where_as_typed(e.where(), names);
  if (where == e.where()) throw;
  // Keep the message, replace the place.
  if (dynamic_cast<const RunError*>(&e) != nullptr) throw RunError(where, e.message());
  throw Error(where, e.message());
}

}  // namespace pneumachaos::cli
