#include "flag_names.hpp"

#include "pneumachaos/identify/fit.hpp"
#include "pneumachaos/io/csv_reader.hpp"
#include "pneumachaos/model/parameter_grid.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos::cli {

const FlagNames& common_flag_names() {
  static const FlagNames names{
      {kOverrideField.id, "--set"},
      {kGridField.id, "--grid"},
      {kGridAxisField.id, "--grid"},
      {SweepSpec::kRepeatsField.id, "--repeats"},
      {CsvSeriesOptions::kRateField.id, "--rate"},
      {ModelExponentSpec::kTransientField.id, "--model-transient"},
      {ModelExponentSpec::kMeasureField.id, "--model-measure"},
      {ModelExponentSpec::kRenormalizeField.id, "--model-renormalize"},
      {identify::kFreeKeysField.id, "--free"},
      {AdaptiveSpec::kEnabledField.id, "--adaptive"},
      {AdaptiveSpec::kCoarseStepField.id, "--adaptive-step"}};
  return names;
}

std::string where_as_typed(const Error& e, const FlagNames& names) {
  if (e.field().empty()) return e.where();
  const auto it = names.find(e.field());
  return it == names.end() ? e.where() : it->second + e.detail();
}

std::string message_as_typed(const Error& e, const FlagNames& names) {
  const std::string where = where_as_typed(e, names);
  return where.empty() ? e.message() : where + ": " + e.message();
}

void rethrow_with_flag(const Error& e, const FlagNames& names) {
  const std::string where = where_as_typed(e, names);
  if (where == e.where()) throw;
  // Keep the message, replace the place.
  if (dynamic_cast<const RunError*>(&e) != nullptr) throw RunError(where, e.message());
  throw Error(where, e.message());
}

}  // namespace pneumachaos::cli
