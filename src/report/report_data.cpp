// report_data.js: the maps' cells and runs and the claims' cells, for the page's own script
// (src/report/assets/report.js).
#include "report/report_data.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "pneumachaos/io/csv_fields.hpp"
#include "pneumachaos/model/scenario_keys.hpp"

namespace pneumachaos {
namespace {

using Json = nlohmann::ordered_json;

// A grid axis as `--grid` takes it: parse_grid_axis gives back the same values.
std::string grid_text(const GridAxis& a) {
  const double step = a.values.size() > 1 ? a.values[1] - a.values[0] : 1.0;
  return fmt::format("{}={:g}:{:g}:{:g}", a.key, a.values.front(), a.values.back(), step);
}

// runs.csv as written: its header, and each point's lines as their text fields, so the page
// shows exactly the numbers of the file.
struct RunsTable {
  std::vector<std::string> columns;
  std::map<std::size_t, std::vector<std::vector<std::string>>> by_point;
};

std::size_t column(const RunsTable& t, const std::string& name, const std::string& path) {
  std::size_t i = 0;
  while (i < t.columns.size() && t.columns[i] != name) ++i;
  if (i == t.columns.size()) throw Error(path, "has no " + name + " column");
  return i;
}

std::string runs_path(const MapData& m, const std::string& report_dir) {
  return report_dir + "/" + m.sweep_dir + "/runs.csv";
}

RunsTable read_runs(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, "cannot read the map's runs for report_data.js");
  RunsTable t;
  std::string line;
  std::getline(in, line);
  t.columns = split_csv_fields(line);
  const std::size_t point_col = column(t, "point", path);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> f = split_csv_fields(line);
    if (f.size() != t.columns.size()) throw Error(path, "a line has the wrong number of fields");
    t.by_point[std::stoul(f[point_col])].push_back(std::move(f));
  }
  return t;
}

Json cell_json(const PointSummary& p, const RunsTable& runs) {
  Json c = {{"point", p.point},
            {"x", p.coordinates.at(0)},
            {"y", p.coordinates.at(1)},
            {"runs", p.runs},
            {"failed", p.failed},
            {"chaos", p.chaos_incidence},
            // null where the map was not judged by the paper's three indices
            {"paper_chaos", std::isfinite(p.paper_chaos_incidence) ? Json(p.paper_chaos_incidence)
                                                                   : Json(nullptr)},
            {"stick_slip", p.stick_slip_incidence},
            {"inferred", p.inferred}};
  Json regimes = Json::object();
  const auto& names = sweep_regime_names();
  for (std::size_t i = 0; i < names.size() && i < p.regime_incidence.size(); ++i)
    if (p.regime_incidence[i] > 0) regimes[names[i]] = p.regime_incidence[i];
  c["regimes"] = regimes;
  const auto it = runs.by_point.find(p.point);
  c["rows"] = it == runs.by_point.end() ? Json::array() : Json(it->second);
  return c;
}

Json map_json(const MapData& m, const std::string& report_dir) {
  const RunsTable runs = read_runs(runs_path(m, report_dir));
  Json cells = Json::array();
  for (const PointSummary& p : m.summary.per_point) cells.push_back(cell_json(p, runs));
  return {{"figure", m.figure},
          {"title", m.title},
          {"sweep", m.sweep_dir},
          {"scenario", m.scenario_file},
          {"axes", {m.spec.axes.at(0).key, m.spec.axes.at(1).key}},
          {"x", m.spec.axes[0].values},
          {"y", m.spec.axes[1].values},
          {"repeats", m.spec.repeats},
          {"paper_judged", m.spec.paper_judge},
          // A run's command is this with " --replay P:R -o run_P_R.csv": written once per map,
          // as the full map would otherwise carry it thousands of times.
          {"replay", "pneumachaos sweep " + replay_arguments(m)},
          {"runs_file", runs_file(m)},
          {"columns", runs.columns},
          {"cells", cells}};
}

}  // namespace

std::string set_arguments(const Scenario& from, const Scenario& to) {
  std::string s;
  for (const KeyInfo& k : scenario_key_infos()) {
    const std::string before = setting_text(from, k.key);
    std::string after = setting_text(to, k.key);
    if (k.key == "load.mass_kg") after = fmt::format("{}", to.load.mass_kg);
    if (after != before) s += fmt::format("{}--set {}={}", s.empty() ? "" : " ", k.key, after);
  }
  return s;
}

std::vector<RunKey> map_run_keys(const MapData& m, const std::string& report_dir) {
  const std::string path = runs_path(m, report_dir);
  const RunsTable runs = read_runs(path);
  const std::size_t repeat_col = column(runs, "repeat", path);
  std::vector<RunKey> keys;
  for (const auto& [point, rows] : runs.by_point)
    for (const auto& f : rows) keys.push_back({point, std::stoul(f[repeat_col])});
  return keys;
}

std::string runs_file(const MapData& m) { return "runs/" + m.figure + ".js"; }

std::string replay_arguments(const MapData& m) {
  std::string s = m.scenario_args.empty() ? "" : m.scenario_args + " ";
  for (const GridAxis& a : m.spec.axes) s += "--grid " + grid_text(a) + " ";
  // A run judged by both judges stores Wolf's exponent and the paper's judgement too.
  if (m.spec.paper_judge) s += "--judge paper ";
  else if (m.spec.wolf) s += "--wolf ";
  return s + fmt::format("--repeats {} --seed {}", m.spec.repeats, m.spec.seed);
}

std::string report_data_js(const std::vector<MapData>& maps, const std::vector<Claim>& claims,
                           const std::string& report_dir) {
  Json j;
  j["maps"] = Json::array();
  for (const MapData& m : maps) j["maps"].push_back(map_json(m, report_dir));
  j["claims"] = Json::array();
  for (const Claim& c : claims)
    j["claims"].push_back({{"id", c.id},
                           {"figure", c.figure},
                           {"verdict", c.verdict},
                           {"ours", c.ours},
                           {"cells", c.cells}});
  return "window.PNEUMACHAOS_REPORT = " + j.dump() + ";\n";
}

}  // namespace pneumachaos
