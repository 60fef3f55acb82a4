#include "pneumachaos/report/reproduce.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>

#include "pneumachaos/analysis/spectrum.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/claims/claim_rules.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/stability/run_start.hpp"
#include "pneumachaos/stability/stability_analysis.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"
#include "progress.hpp"
#include "pneumachaos/claims/example_run.hpp"
#include "report/figures.hpp"
#include "report/report_assets.hpp"
#include "report/report_data.hpp"
#include "report/run_traces.hpp"

namespace pneumachaos {
namespace {

// An --out that exists must be empty or hold an earlier report (its page, figures or the
// sweeps of an interrupted run): anything else is refused rather than mixed with the report.
void check_out_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (!fs::is_directory(dir, ec)) throw Error(dir, "exists and is not a directory");
  if (fs::is_empty(dir, ec)) return;
  for (const char* mark : {"index.html", "figures", "sweeps"}) {
    if (fs::exists(fs::path(dir) / mark, ec)) return;
  }
  throw Error(dir,
              "exists and is not an earlier report (no index.html, figures/ or sweeps/); "
              "choose a new or empty directory");
}

// A report directory holds one rig's report at one grid: the first run writes what it runs
// into rig.toml, and a run of another rig or grid is refused there, before any figure of the
// report in it is overwritten (its sweeps could not be resumed anyway).
void claim_out_dir(const std::string& dir, const std::string& identity) {
  const std::string path = dir + "/rig.toml";
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    std::ifstream in(path, std::ios::binary);
    const std::string held((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (held == identity) return;
    throw Error(path, "this directory holds the report of another rig or grid (the rig and "
                      "options it ran are in this file): choose a new --out");
  }
  AtomicFile f(path);
  f.stream() << identity;
  f.commit();
}

SimulationResult run(Scenario s, double duration_s) {
  s.run.duration_s = duration_s;
  const Plant plant(s);
  SimulationResult r = simulate_from(plant, run_start_state(plant, s.run), s.run);
  if (!r.summary.ok()) throw Error("reproduce", "a simulation failed: " + r.summary.message);
  return r;
}

// The paper's model for Fig. 2 under the paper's own assumptions: one rigid mass, eq. (4)
// friction, volumes following the piston; meter-out with P1 = Ps (Section 3.2: the supply
// valve open wide) and meter-in with the rod side at atmosphere (Section 3.3).
constexpr double kOpenValve_mm2 = 20.0;  // a fully open 1/4" valve: its pressure drop is < 1e-4
Scenario paper_model(CircuitKind kind, double S_mm2) {
  Scenario s = simple_rig_scenario();
  s.friction.kind = FrictionKind::kClassic;
  s.circuit.kind = kind;
  const bool out = kind == CircuitKind::kMeterOut;
  s.circuit.S1_m2 = (out ? kOpenValve_mm2 : S_mm2) * 1e-6;
  s.circuit.S2_m2 = (out ? S_mm2 : kOpenValve_mm2) * 1e-6;
  return s;
}

// Fig. 2's openings and record length.
constexpr std::array<double, 3> kFig2Areas_mm2 = {0.2, 0.35, 0.6};
constexpr double kFig2Record_s = 3.0;

// Eq. (11)'s supply-pressure trend: the rig in a meter-in circuit (rod side at atmosphere)
// at each Fig. 2 opening, Ps 0.25 -> 0.30 MPa.
std::vector<DampingPair> meter_in_supply_trend(const Scenario& rig) {
  std::vector<DampingPair> out;
  for (double S : kFig2Areas_mm2) {
    Scenario before = rig;
    before.circuit.kind = CircuitKind::kMeterIn;
    before.circuit.S1_m2 = S * 1e-6;
    before.circuit.S2_m2 = kOpenValve_mm2 * 1e-6;
    Scenario after = before;
    apply_setting(after, "supply.pressure_MPa", 0.30, "reproduce");
    const StabilityResult b = analyze_stability(Plant(before));
    const StabilityResult a = analyze_stability(Plant(after));
    if (!b.has_equilibrium() || !a.has_equilibrium()) continue;
    out.push_back({b.paper.b1, a.paper.b1, b.max_real_part_per_s, a.max_real_part_per_s});
  }
  return out;
}

// The paper's a1 and b1 at the example point, total moving mass 1.5 -> 3.0 kg.
std::optional<LoadCoefficients> load_coefficients(const Scenario& base) {
  Scenario heavy = base;
  heavy.set_total_moving_mass(3.0);
  const StabilityResult b = analyze_stability(Plant(base));
  const StabilityResult a = analyze_stability(Plant(heavy));
  if (!b.has_equilibrium() || !a.has_equilibrium()) return std::nullopt;
  return LoadCoefficients{b.paper.a1, a.paper.a1, b.paper.b1, a.paper.b1};
}

// The seal's steady friction-velocity curve from 0.5 mm/s to v_max, at the rig's pressure
// gains' zero point (gauge sum 0; the default rig has no pressure dependence).
std::vector<std::array<double, 2>> steady_curve(const Plant& plant, double v_max) {
  std::vector<std::array<double, 2>> c;
  for (double v = 0.5e-3; v <= v_max; v += 0.5e-3) {
    c.push_back({v, plant.seal_friction().steady_force_N(FrictionInput{v, 0.0, 0.0})});
  }
  return c;
}

// The paper's sign verdict per point against the runs of the same point (same grid order).
SignRuleCounts sign_rule_counts(const StabilityMap& map, const SweepSummary& sweep) {
  std::vector<std::optional<bool>> damped(map.points.size());
  for (std::size_t i = 0; i < map.points.size(); ++i) {
    const StabilityResult& r = map.points[i].result;
    if (map.points[i].error.empty() && r.has_equilibrium())
      damped[i] = r.paper.verdict == StabilityVerdict::kDamped;
  }
  return count_sign_rule(damped, sweep);
}

MapGrid map_grid(const SweepSpec& spec) { return {spec.axes[0].values, spec.axes[1].values}; }

// The paper's conditions of Fig. 4 and Fig. 7: Ps 0.25 MPa and m = 1.5 kg, its total moving
// mass (piston, rod and load: the paper's notation list).
Scenario paper_conditions(Scenario s) {
  apply_setting(s, "supply.pressure_MPa", 0.25, "reproduce");
  s.set_total_moving_mass(1.5);
  return s;
}

// The maps' grid and run-to-run variation (docs/notes/virtual_rig.md).
SweepSpec map_spec(const Scenario& base, bool quick, bool full_maps) {
  SweepSpec spec;
  spec.base = base;
  spec.base.variation.friction_rel_sd = 0.03;
  spec.base.variation.texture_rel = 0.02;
  spec.axes = quick ? std::vector<GridAxis>{parse_grid_axis("circuit.S1_mm2=2.45:3.70:0.25"),
                                            parse_grid_axis("circuit.S2_mm2=0.05:0.95:0.15")}
                    : paper_valve_grid();
  spec.repeats = quick ? 2 : 5;
  if (quick) spec.base.run.duration_s = 5.0;
  // Adaptive maps (docs/sweep.md, "Adaptive maps"): the grid's borders are run to single steps,
  // the uniform cells inferred; on the paper's maps every point's classes agree with the full
  // grid's at about a fifth of the runs. The motion is not followed (that costs three times the
  // runs): the claims that read it count the coarse lattice, which every map runs.
  spec.adaptive.enabled = !full_maps;
  // Every run judged twice, by the verdict and by the paper's three indices, so each map and
  // each chaos claim can be read under both from the same runs.
  spec.paper_judge = true;
  return spec;
}

// The letters of Fig. 3 for one record: of the loops that start within its last `seconds`,
// the one with the most marks (the latest among equals), as `pneumachaos friction` finds them.
std::vector<LoopLabel> loop_letters(const TimeSeries& run, const Scenario& s, double seconds) {
  const identify::FrictionEstimate e = identify::estimate_friction_of_run(run, s);
  const auto n = run.size(), window = static_cast<std::size_t>(seconds * run.rate_Hz());
  const identify::Excursion* best = nullptr;
  for (const auto& x : e.excursions)
    if (x.begin + window >= n && (best == nullptr || x.marks.size() >= best->marks.size()))
      best = &x;
  std::vector<LoopLabel> out;
  if (best != nullptr)
    for (const auto& m : best->marks) out.push_back({m.label, m.v_m_per_s, m.F_N});
  return out;
}

// The report's figures and the inputs of its claims, gathered stage by stage.
class ReportBuilder {
 public:
  explicit ReportBuilder(const ReproduceOptions& o)
      : o_(o),
        fig_dir_(o.out_dir + "/figures"),
        base_(paper_conditions(o.rig ? *o.rig : default_scenario())),
        spec_(map_spec(base_, o.quick, o.full_maps)),
        stage_(o.progress, 10, 4 * spec_.runs(), o.on_progress) {}

  // What this report runs, as rig.toml holds it.
  [[nodiscard]] std::string identity() const {
    return fmt::format("# pneumachaos reproduce{}: the rig under the Fig. 4 conditions\n",
                       o_.quick ? " --quick" : "") +
           scenario_to_toml(base_);
  }

  // Fig. 2: the paper's own model in both circuits, at three valve openings each, under the
  // assumptions of its Sections 3.2 and 3.3.
  void time_responses() {
    stage_.stage("Fig. 2: time responses of the paper's model");
    std::vector<LabelledRecord> in, out;
    CircuitTransients t;
    for (double S : kFig2Areas_mm2) {
      out.push_back({fmt::format("S2 = {} mm^2", S),
                     run(paper_model(CircuitKind::kMeterOut, S), kFig2Record_s).series});
      in.push_back({fmt::format("S1 = {} mm^2", S),
                    run(paper_model(CircuitKind::kMeterIn, S), kFig2Record_s).series});
      t.areas_mm2.push_back(S);
      const double rate = out.back().series.rate_Hz();
      t.meter_out.push_back(settling(out.back().series.channel("v").values, rate));
      t.meter_in.push_back(settling(in.back().series.channel("v").values, rate));
    }
    add(time_responses_figure(out, in));
    claims_.fig2 = t;
  }

  // Fig. 7: the chaotic example, analysed on its settled record (the first kSettle_s, rest
  // and start-up, are left out), beside the model's own exponent.
  void chaotic_example() {
    stage_.stage("Fig. 7: the chaotic example and its indices");
    const ExampleRun e = run_example(base_, record_s(), true);
    example_ = e.sim;
    for (const auto& f : chaotic_example_figures(e.v, example_.series.rate_Hz(), kExampleSettle_s,
                                                 e.analysis, e.model.running_time_s,
                                                 e.model.running_per_s)) {
      add(f);
    }
    add_example_inputs(claims_, e);
  }

  // Fig. 3: friction against velocity in chaotic oscillation and in stick-slip.
  void friction_loops() {
    stage_.stage("Fig. 3: friction-velocity loops");
    Scenario stick = base_;
    stick.circuit.S2_m2 = 0.05e-6;
    const TimeSeries stick_run = run(stick, 5.0).series;
    const double seconds = o_.quick ? 1.0 : 2.0;
    add(friction_loops_figure({{fmt::format("the Fig. 7 point (S2 = 0.35 mm^2, judged {})", claims_.example_regime),
                                example_.series},
                               {"stick-slip (S2 = 0.05 mm^2)", stick_run}},
                              seconds, steady_curve(Plant(base_), 0.2),
                              {loop_letters(example_.series, base_, seconds),
                               loop_letters(stick_run, stick, seconds)}));
  }

  void stability() {
    stage_.stage("stability map");
    smap_ = stability_map(base_, spec_.axes);
    add(stability_map_figure(smap_));
  }

  // Figs. 4-6 and the 4.5 kg condition: one resumable sweep each; m is the total moving mass.
  void maps() {
    struct Condition {
      std::string name, title;
      double Ps_MPa, m_kg;
    };
    const std::vector<Condition> conditions = {
        {"fig4_map_ps025_m15", "Fig. 4: Ps 0.25 MPa, m 1.5 kg", 0.25, 1.5},
        {"fig5_map_ps030_m15", "Fig. 5: Ps 0.30 MPa, m 1.5 kg", 0.30, 1.5},
        {"fig6_map_ps025_m30", "Fig. 6: Ps 0.25 MPa, m 3.0 kg", 0.25, 3.0},
        {"fig6b_map_ps025_m45", "Ps 0.25 MPa, m 4.5 kg (the paper: no chaos)", 0.25, 4.5}};
    for (const Condition& c : conditions) {
      stage_.stage("sweep: " + c.title);
      SweepSpec s = spec_;
      apply_setting(s.base, "supply.pressure_MPa", c.Ps_MPa, "reproduce");
      s.base.set_total_moving_mass(c.m_kg);
      SweepOptions so;
      // Adaptive and full maps keep their own folders, so either resumes its own sweeps.
      const std::string sweep_dir = "sweeps/" + std::string(o_.full_maps ? "" : "adaptive_") +
                                    c.name.substr(c.name.find("map_") + 4);
      so.out_dir = o_.out_dir + "/" + sweep_dir;
      so.threads = o_.threads;
      so.progress = o_.progress;
      so.on_progress = [this](std::size_t done, std::size_t) { stage_.sweep_runs(done); };
      RunTraces& traces = *traces_.emplace_back(std::make_unique<RunTraces>());
      so.on_run = [&traces](const SweepRun& r) { traces.keep(r); };
      // A second run of reproduce resumes (or re-reads) the sweeps of the first.
      so.resume = true;
      maps_.push_back(run_sweep(s, so));
      stage_.runs_done(maps_.back().runs);
      add(incidence_map_figure(c.name, c.title, s, maps_.back()));
      add(incidence_map_figure(c.name + "_paper_judge",
                               c.title + ", chaos as the paper judged it (spectrum, ACF, Wolf)", s,
                               under_paper_judge(maps_.back())));
      const std::string toml = "figures/" + c.name + "_scenario.toml";
      // The built-in rig is reached to the last bit from the defaults with --set; a rig of the
      // user's through its scenario as printed (15 digits: the runs again, to rounding).
      keep_map_data({c.name, c.title, sweep_dir, toml,
                     o_.rig ? toml : set_arguments(default_scenario(), s.base), s, maps_.back()});
    }
  }

  // Per map, its runs' records, spectra and autocorrelations for the page's run panel, as the
  // sweeps kept them; a run a sweep resumed from its journal is simulated again (the same
  // record to the last bit; docs/notes/explorable_report.md).
  void run_traces() {
    stage_.stage("run records, spectra and autocorrelations for the page");
    std::error_code ec;
    std::filesystem::create_directories(o_.out_dir + "/runs", ec);
    if (ec) throw Error(o_.out_dir + "/runs", "cannot create: " + ec.message());
    for (std::size_t i = 0; i < map_data_.size(); ++i) {
      const MapData& m = map_data_[i];
      write_file(o_.out_dir + "/" + runs_file(m),
                 traces_[i]->js(m, map_run_keys(m, o_.out_dir), o_.threads));
    }
  }

  // The claims table, claims.json and the page.
  ReproduceResult finish() {
    stage_.stage("claims and report");
    claims_.grid = map_grid(spec_);
    claims_.base = maps_[0];
    claims_.high_ps = maps_[1];
    claims_.double_m = maps_[2];
    claims_.triple_m = maps_[3];
    claims_.meter_in_ps = meter_in_supply_trend(base_);
    claims_.heavier = load_coefficients(base_);
    claims_.sign_rule = sign_rule_counts(smap_, maps_[0]);
    result_.claims = evaluate_claims(claims_);
    result_.paper_claims = evaluate_claims(under_paper_judge(claims_));
    write_file(o_.out_dir + "/claims.json", claims_json(result_.claims, result_.paper_claims));
    write_file(o_.out_dir + "/report_data.js",
               report_data_js(map_data_, result_.claims, o_.out_dir));
    write_report_assets(o_.out_dir);
    result_.index_html = (std::filesystem::path(o_.out_dir) / "index.html").string();
    write_file(result_.index_html,
               report_html(result_.figures, result_.claims, scenario_to_toml(spec_.base),
                           settings(), o_.rig ? o_.rig_source : std::string(),
                           result_.paper_claims));
    return result_;
  }

 private:
  void add(const FigureSpec& spec) { result_.figures.push_back(render_figure(spec, fig_dir_)); }
  // A map for the page's explorer, with the scenario its sweep ran, so that `sweep --replay`
  // from the report folder runs any of its runs again.
  void keep_map_data(MapData m) {
    write_file(o_.out_dir + "/" + m.scenario_file, scenario_to_toml(m.spec.base));
    map_data_.push_back(std::move(m));
  }
  static void write_file(const std::string& path, const std::string& text) {
    AtomicFile f(path);
    f.stream() << text;
    f.commit();
  }
  [[nodiscard]] std::size_t runs_made() const {
    std::size_t n = 0;
    for (const SweepSummary& m : maps_) n += m.runs;
    return n;
  }
  // What the maps and the example ran with, as the page states it.
  [[nodiscard]] std::string settings() const {
    const VariationParams& v = spec_.base.variation;
    return fmt::format(
        "Maps: {} grid ({} x {} points, {}: {} of {} runs made), {} runs per point, {} s "
        "records{}, {:g} % seal "
        "friction scatter and a {:g} % bore texture per run, each run judged twice: by the "
        "regime verdict and by the paper's three indices (Wolf's estimator on every run); m is "
        "the total moving mass{}. A full-length run's spectrum has bins of {:.2g} Hz (the "
        "paper's judge counts a line within one bin either side), a run ended by the stroke "
        "coarser ones. "
        "Chaotic example (Figs. 3 and 7): Ps 0.25 MPa, m {:g} kg, no scatter or texture, {}.",
        o_.quick ? "quick" : "the paper's", spec_.axes[0].values.size(),
        spec_.axes[1].values.size(),
        o_.full_maps ? "every point simulated"
                     : "refined adaptively, the uniform cells' points inferred",
        runs_made(), maps_.size() * spec_.runs(), spec_.repeats,
        spec_.base.run.duration_s,
        base_.cylinder.volumes_frozen() ? "" : " or up to the stroke end",
        100 * v.friction_rel_sd, 100 * v.texture_rel,
        base_.load.coupling == LoadCoupling::kSpring
            ? fmt::format(" (piston and rod {:g} kg, the rest the load on its mount)",
                          base_.load.piston_mass_kg)
            : std::string(" (one rigid body)"),
        map_run_resolution_Hz(), base_.total_moving_mass_kg(), example_length());
  }
  // The bin width of a map run's Welch spectrum, for a record of the runs' full length.
  [[nodiscard]] double map_run_resolution_Hz() const {
    const RunParams& r = spec_.base.run;
    const auto samples = static_cast<std::size_t>(r.duration_s * r.sample_rate_Hz) + 1;
    return r.sample_rate_Hz / static_cast<double>(welch_segment_length(samples));
  }
  [[nodiscard]] double record_s() const { return o_.quick ? 10.0 : 30.0; }
  // The example's record as it ran: a stroke end shortens it, and the page says so.
  [[nodiscard]] std::string example_length() const {
    const IntegrationSummary& s = example_.summary;
    return s.termination == Termination::kTerminalEvent
               ? fmt::format("{:.1f} s record (ended at the stroke end; {} s asked)", s.t_final_s,
                             record_s())
               : fmt::format("{} s record", record_s());
  }

  const ReproduceOptions& o_;
  const std::string fig_dir_;
  const Scenario base_;
  const SweepSpec spec_;
  ReproduceProgress stage_;
  ReproduceResult result_;
  ClaimInputs claims_;
  SimulationResult example_;
  StabilityMap smap_;
  std::vector<SweepSummary> maps_;
  std::vector<MapData> map_data_;
  std::vector<std::unique_ptr<RunTraces>> traces_;  ///< per map, filled by its sweep's workers
};

}  // namespace

void ReproduceOptions::validate() const {
  if (out_dir.empty())
    throw Error(validation::field("reproduce.out_dir"), "", "name the report's output directory");
}

ReproduceResult reproduce(const ReproduceOptions& o) {
  o.validate();
  check_out_dir(o.out_dir);
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir + "/figures", ec);
  if (ec) throw Error(o.out_dir, "cannot create the report directory: " + ec.message());
  ReportBuilder report(o);
  claim_out_dir(o.out_dir, report.identity());
  report.time_responses();
  report.chaotic_example();
  report.friction_loops();
  report.stability();
  report.maps();
  report.run_traces();
  return report.finish();
}

}  // namespace pneumachaos
