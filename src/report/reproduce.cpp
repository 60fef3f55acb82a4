#include "pneumachaos/report/reproduce.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/report/claim_rules.hpp"
#include "pneumachaos/report/figures.hpp"
#include "pneumachaos/stability/stability_analysis.hpp"
#include "progress.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"

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

// The chaotic example starts at rest; its analysis and Fig. 7 skip the start-up.
constexpr double kSettle_s = 2.0;

SimulationResult run(Scenario s, double duration_s) {
  s.run.duration_s = duration_s;
  const Plant plant(s);
  SimulationResult r = simulate(plant, s.run);
  if (!r.summary.ok()) throw Error("reproduce", "a simulation failed: " + r.summary.message);
  return r;
}

// The paper's model for Fig. 2: one rigid mass, eq. (4) friction, volumes following the piston.
Scenario paper_model(CircuitKind kind, double S1_mm2, double S2_mm2) {
  Scenario s = simple_rig_scenario();
  s.friction.kind = FrictionKind::kClassic;
  s.circuit.kind = kind;
  s.circuit.S1_m2 = S1_mm2 * 1e-6;
  s.circuit.S2_m2 = S2_mm2 * 1e-6;
  return s;
}

// Fig. 2 reduced to the claim's numbers: the settled part starts after 1 s of the 3 s records.
CircuitContrast contrast(const std::vector<LabelledRecord>& in,
                         const std::vector<LabelledRecord>& out) {
  CircuitContrast c;
  const auto add = [](const LabelledRecord& r, std::vector<double>& fl, std::vector<double>& mean) {
    const auto& v = r.series.channel("v").values;
    const auto from = static_cast<std::size_t>(r.series.rate_Hz());
    fl.push_back(relative_fluctuation(v, from));
    double sum = 0.0;
    for (std::size_t k = from; k < v.size(); ++k) sum += v[k];
    mean.push_back(from < v.size() ? sum / (v.size() - from) : 0.0);
  };
  for (const auto& r : in) add(r, c.meter_in_fluctuation, c.meter_in_mean);
  for (const auto& r : out) add(r, c.meter_out_fluctuation, c.meter_out_mean);
  return c;
}

std::optional<DampingChange> damping_change(const Scenario& before, const Scenario& after) {
  const StabilityResult b = analyze_stability(Plant(before));
  const StabilityResult a = analyze_stability(Plant(after));
  if (!b.has_equilibrium() || !a.has_equilibrium()) return std::nullopt;
  return DampingChange{b.paper.a1, a.paper.a1, b.paper.b1, a.paper.b1, b.max_real_part_per_s,
                       a.max_real_part_per_s};
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
  SignRuleCounts c;
  for (std::size_t i = 0; i < map.points.size() && i < sweep.per_point.size(); ++i) {
    const StabilityResult& r = map.points[i].result;
    if (!map.points[i].error.empty() || !r.has_equilibrium()) continue;
    // regime_incidence[0] is "steady" (sweep_regime_names()).
    const bool steady = sweep.per_point[i].regime_incidence.at(0) >= 0.5;
    if (r.paper.verdict == StabilityVerdict::kDamped) {
      ++c.damped;
      c.damped_steady += steady ? 1 : 0;
    } else {
      ++c.excited;
      c.excited_moving += steady ? 0 : 1;
    }
  }
  return c;
}

// The maps' grid and run-to-run variation (docs/virtual_rig.md).
SweepSpec map_spec(const Scenario& base, bool quick) {
  SweepSpec spec;
  spec.base = base;
  spec.base.variation.friction_rel_sd = 0.03;
  spec.base.variation.texture_rel = 0.02;
  spec.axes = quick ? std::vector<GridAxis>{parse_grid_axis("circuit.S1_mm2=2.45:3.70:0.25"),
                                            parse_grid_axis("circuit.S2_mm2=0.05:0.95:0.15")}
                    : paper_valve_grid();
  spec.repeats = quick ? 2 : 5;
  if (quick) spec.base.run.duration_s = 5.0;
  return spec;
}

// The Fig. 7 and Fig. 3 numbers of the claims, from the settled record v (which starts at
// sample `settle` of the full friction channel F).
void add_example_inputs(ClaimInputs& ci, const AnalysisResult& a, const std::vector<double>& v,
                        const std::vector<double>& F, std::size_t settle) {
  if (a.divergence.found_linear_region) {
    ci.example_lambda = a.divergence.lambda_per_s;
    // The claim tests the rise (3 sigma), as the verdict does: the slope's uncertainty
    // (docs/analysis.md "Divergence exponent's uncertainty").
    ci.example_uncertainty = a.divergence.slope_uncertainty_per_s;
  }
  ci.example_chaotic = a.verdict.chaotic;
  ci.example_peak_share = a.spectrum.peak_share;
  ci.example_acf_after_1s = acf_envelope_after(a.acf.r, a.acf.rate_Hz, 1.0);
  // Low speed: up to a quarter of the example's largest speed.
  const double vmax = v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
  ci.friction_slope_vmax = 0.25 * vmax;
  const std::vector<double> F_settled(F.begin() + static_cast<std::ptrdiff_t>(settle), F.end());
  ci.friction_slope = low_speed_slope(v, F_settled, ci.friction_slope_vmax);
  ci.friction_loop = measure_friction_loop(v, F_settled);
  ci.fold_stretch = measure_fold_stretch(v, a.rate_Hz, a.dimension.dimension, a.delay.delay,
                                         a.theiler);
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

// The conclusion's Fig. 5 and Fig. 6 changes at the example point, by the linear analysis.
void add_damping_inputs(ClaimInputs& ci, const Scenario& base) {
  Scenario high_ps = base, heavy = base;
  apply_setting(high_ps, "supply.pressure_MPa", 0.30, "reproduce");
  apply_setting(heavy, "load.mass_kg", 3.0, "reproduce");
  ci.higher_ps = damping_change(base, high_ps);
  ci.heavier = damping_change(base, heavy);
}

// The report's figures and the inputs of its claims, gathered stage by stage.
class ReportBuilder {
 public:
  explicit ReportBuilder(const ReproduceOptions& o)
      : o_(o),
        fig_dir_(o.out_dir + "/figures"),
        base_(default_scenario()),
        spec_(map_spec(base_, o.quick)),
        stage_(o.progress, 9, 4 * spec_.runs()) {}

  // Fig. 2: the paper's own model in both circuits, at three valve openings each.
  void time_responses() {
    stage_.stage("Fig. 2: time responses of the paper's model");
    std::vector<LabelledRecord> in, out;
    for (double S : {0.2, 0.35, 0.6}) {
      in.push_back({fmt::format("S1 = {} mm^2", S),
                    run(paper_model(CircuitKind::kMeterIn, S, 20.0), 3.0).series});
      out.push_back({fmt::format("S2 = {} mm^2", S),
                     run(paper_model(CircuitKind::kMeterOut, 2.7, S), 3.0).series});
    }
    add(time_responses_figure(in, out));
    claims_.fig2 = contrast(in, out);
  }

  // Fig. 7: the chaotic example, analysed on its settled record (the first kSettle_s, rest
  // and start-up, are left out), beside the model's own exponent.
  void chaotic_example() {
    stage_.stage("Fig. 7: the chaotic example and its indices");
    example_ = run(base_, record_s());
    const auto& v_all = example_.series.channel("v").values;
    const auto settle = static_cast<std::size_t>(kSettle_s * example_.series.rate_Hz());
    const std::vector<double> v(v_all.begin() + static_cast<std::ptrdiff_t>(settle), v_all.end());
    const AnalysisResult a = analyze_series(v, example_.series.rate_Hz());
    // The model's exponent after 1 s of start-up over the rest of the record, which with the
    // volumes following the piston ends at the stroke end (docs/virtual_rig.md).
    ModelLyapunovOptions lo;
    lo.transient_s = 1.0;
    lo.measure_s = record_s() - lo.transient_s;
    lo.until_terminal_event = true;
    const ModelLyapunovResult model = plant_lyapunov(Plant(base_), base_.run, lo);
    for (const auto& f : chaotic_example_figures(v, example_.series.rate_Hz(), kSettle_s, a,
                                                 model.running_time_s, model.running_per_s)) {
      add(f);
    }
    add_example_inputs(claims_, a, v, example_.series.channel("F_friction").values, settle);
    if (model.ok) {
      claims_.example_model_lambda = model.lambda_per_s;
      claims_.example_model_uncertainty = model.uncertainty_per_s;
    }
  }

  // Fig. 3: friction against velocity in chaotic oscillation and in stick-slip.
  void friction_loops() {
    stage_.stage("Fig. 3: friction-velocity loops");
    Scenario stick = base_;
    stick.circuit.S2_m2 = 0.05e-6;
    const TimeSeries stick_run = run(stick, 5.0).series;
    const double seconds = o_.quick ? 1.0 : 2.0;
    add(friction_loops_figure({{"chaotic oscillation (S2 = 0.35 mm^2)", example_.series},
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

  // Figs. 4-6 and the 4.5 kg condition: one resumable sweep each.
  void maps() {
    struct Condition {
      std::string name, title, key;
      double value;
    };
    const std::vector<Condition> conditions = {
        {"fig4_map_ps025_m15", "Fig. 4: Ps 0.25 MPa, m 1.5 kg", "", 0.0},
        {"fig5_map_ps030_m15", "Fig. 5: Ps 0.30 MPa, m 1.5 kg", "supply.pressure_MPa", 0.30},
        {"fig6_map_ps025_m30", "Fig. 6: Ps 0.25 MPa, m 3.0 kg", "load.mass_kg", 3.0},
        {"fig6b_map_ps025_m45", "Ps 0.25 MPa, m 4.5 kg (the paper: no chaos)", "load.mass_kg",
         4.5}};
    for (const Condition& c : conditions) {
      stage_.stage("sweep: " + c.title);
      SweepSpec s = spec_;
      if (!c.key.empty()) apply_setting(s.base, c.key, c.value, "reproduce");
      SweepOptions so;
      so.out_dir = o_.out_dir + "/sweeps/" + c.name.substr(c.name.find("map_") + 4);
      so.threads = o_.threads;
      so.progress = o_.progress;
      so.on_progress = [this](std::size_t done, std::size_t) { stage_.sweep_runs(done); };
      // A second run of reproduce resumes (or re-reads) the sweeps of the first.
      so.resume = true;
      maps_.push_back(run_sweep(s, so));
      stage_.runs_done(s.runs());
      add(incidence_map_figure(c.name, c.title, s, maps_.back()));
    }
  }

  // The claims table and the page.
  ReproduceResult finish() {
    stage_.stage("claims and report");
    claims_.spec = spec_;
    claims_.base = maps_[0];
    claims_.high_ps = maps_[1];
    claims_.double_m = maps_[2];
    claims_.triple_m = maps_[3];
    add_damping_inputs(claims_, base_);
    claims_.sign_rule = sign_rule_counts(smap_, maps_[0]);
    result_.claims = evaluate_claims(claims_);
    const std::string settings = fmt::format(
        "{} grid ({} x {} points), {} runs per point, {} s records{}, 3 % friction variation "
        "and a 2 % bore texture per run; chaotic example: {}.",
        o_.quick ? "quick" : "the paper's", spec_.axes[0].values.size(),
        spec_.axes[1].values.size(), spec_.repeats, spec_.base.run.duration_s,
        base_.cylinder.volumes_frozen() ? "" : " or up to the stroke end", example_length());
    result_.index_html = o_.out_dir + "/index.html";
    AtomicFile html(result_.index_html);
    html.stream() << report_html(result_.figures, result_.claims, scenario_to_toml(base_),
                                 settings);
    html.commit();
    return result_;
  }

 private:
  void add(const FigureSpec& spec) { result_.figures.push_back(render_figure(spec, fig_dir_)); }
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
};

}  // namespace

ReproduceResult reproduce(const ReproduceOptions& o) {
  check_out_dir(o.out_dir);
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir + "/figures", ec);
  if (ec) throw Error(o.out_dir, "cannot create the report directory: " + ec.message());
  ReportBuilder report(o);
  report.time_responses();
  report.chaotic_example();
  report.friction_loops();
  report.stability();
  report.maps();
  return report.finish();
}

}  // namespace pneumachaos
