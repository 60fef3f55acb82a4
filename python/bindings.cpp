// The compiled half of the Python package: thin wrappers over the library, returning the
// same JSON the command line prints (one source for field names and units) and numpy arrays
// for the long series. python/pneumachaos/__init__.py builds the user-facing API on top.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "pneumachaos/analysis/analysis_output.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/calibrate/calibrate.hpp"
#include "pneumachaos/identify/fit.hpp"
#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/identify/friction_fits.hpp"
#include "pneumachaos/identify/friction_output.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/report/reproduce.hpp"
#include "pneumachaos/simulate/event_integrator.hpp"
#include "pneumachaos/simulate/lyapunov_output.hpp"
#include "pneumachaos/simulate/measured_channels.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/stability/run_start.hpp"
#include "pneumachaos/stability/stability_map.hpp"
#include "pneumachaos/stability/stability_output.hpp"
#include "pneumachaos/sweep/sweep.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"
// The command line's translation of a library field's id into the name the user typed; here
// the names are the Python arguments.
#include "flag_names.hpp"

namespace py = pybind11;
using namespace pneumachaos;

namespace {

// A vector handed to numpy without a copy: the array owns it through a capsule.
py::array_t<double> to_numpy(std::vector<double>&& v) {
  auto* owned = new std::vector<double>(std::move(v));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>(static_cast<py::ssize_t>(owned->size()), owned->data(),
                             free_when_done);
}

py::array_t<double> copy_to_numpy(const std::vector<double>& v) {
  return to_numpy(std::vector<double>(v));
}

// A 1-D float array from Python, checked as the CLI checks a record; `name` is the argument.
std::vector<double> series_from(const py::array& in, const std::string& name = "x") {
  if (in.ndim() != 1) {
    throw Error(name, "expected a 1-D array of samples, got " + std::to_string(in.ndim()) +
                          " dimensions");
  }
  if (in.dtype().kind() == 'c')
    throw Error(name, "expected real numbers, got a complex array (take .real or abs() first)");
  if (in.size() == 0) throw Error(name, "the array is empty: expected the record's samples");
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(in);
  if (!a) throw Error(name, "expected an array of numbers");
  std::vector<double> x(a.data(), a.data() + a.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw Error(name, "sample " + std::to_string(i) + " is not a finite number");
    }
  }
  return x;
}

// A measured record (t [s], v [m/s], P1, P2 [Pa absolute]) from four arrays.
identify::MeasuredRecord record_from(const py::array& t, const py::array& v, const py::array& p1,
                                     const py::array& p2) {
  return identify::record_from_columns(series_from(t, "t"), series_from(v, "v"),
                                       series_from(p1, "P1"), series_from(p2, "P2"), {},
                                       "<arrays>");
}

// `pneumachaos friction` on arrays: the same estimate, fits and JSON.
// window: the Savitzky-Golay window in samples, 0 = chosen from the noise (the CLI's default).
// Returns the JSON and the preferred model as the scenario [friction] table of --scenario-out
// ("" when no model converged with Fc <= Fs).
py::tuple friction_py(const py::array& t, const py::array& v, const py::array& p1,
                      const py::array& p2, const Scenario& scenario,
                      const std::vector<std::string>& models, bool pressure_dependent,
                      long long window, int max_iterations) {
  const identify::MeasuredRecord record = record_from(t, v, p1, p2);
  identify::FrictionFitOptions fit =
      identify::fit_options_for(scenario, models, pressure_dependent, "models");
  fit.max_iterations = max_iterations;
  identify::EstimateSpec settings = identify::estimate_spec_from(scenario);
  if (window != 0) identify::set_smoothing_window(settings, window, "window");
  std::string json, table;
  {
    py::gil_scoped_release release;
    const identify::FrictionEstimate estimate = identify::estimate_friction(record, settings);
    const identify::FrictionFits fits = identify::fit_friction(estimate, fit);
    identify::require_converged(fits);
    json = identify::friction_json(estimate, fits, settings, record.source);
    if (const identify::ModelFit* preferred = fits.preferred())
      table = identify::friction_scenario_toml(*preferred, record.source);
  }
  return py::make_tuple(json, table);
}

// `pneumachaos fit` on arrays: the free keys identified, as its JSON, and the fitted scenario
// (what --scenario-out writes).
py::tuple fit_py(const py::array& t, const py::array& v, const py::array& p1, const py::array& p2,
                 const Scenario& start, std::vector<std::string> free,
                 const identify::FitOptions& options) {
  const identify::MeasuredRecord record = record_from(t, v, p1, p2);
  if (free.empty()) free = identify::default_free_keys(start);
  identify::check_free_keys(start, free);
  identify::FitResult result;
  {
    py::gil_scoped_release release;
    result = identify::fit_model(record, start, free, options);
  }
  return py::make_tuple(identify::fit_json(result, options, record), result.scenario);
}

// A Python progress callable as the runners call it: from a worker thread without the GIL,
// so it takes the GIL; an exception there must not cross into the runner. None: no callback.
std::function<void(std::size_t, std::size_t)> progress_callback(const py::object& progress,
                                                                const char* what) {
  if (progress.is_none()) return {};
  return [&progress, what](std::size_t done, std::size_t total) {
    py::gil_scoped_acquire hold;
    try {
      progress(done, total);
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable(what);
    }
  };
}

void check_rate(double rate_Hz) {
  if (!(std::isfinite(rate_Hz) && rate_Hz > 0.0)) throw Error("rate_Hz", "must be a positive number");
}

// A record's channels into `out` as simulate() returns them: t and each channel as numpy
// arrays, their units, the rate.
void add_channels(py::dict& out, TimeSeries&& series) {
  std::vector<double> t(series.size());
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = series.time_s(k);
  py::dict channels, units;
  channels["t"] = to_numpy(std::move(t));
  units["t"] = "s";
  out["rate_Hz"] = series.rate_Hz();
  for (Channel& c : std::move(series).take_channels()) {
    units[py::str(c.name)] = c.unit;
    channels[py::str(c.name)] = to_numpy(std::move(c.values));
  }
  out["channels"] = channels;
  out["units"] = units;
}

// A run as simulate() returns it: how it ended and, when it succeeded, its channels.
py::dict simulation_dict(SimulationResult&& r, const Plant& plant) {
  py::dict out;
  out["ok"] = r.summary.ok();
  out["summary"] = describe(r.summary, !plant.seal_friction().has_stiction());
  out["termination"] = std::string(termination_name(r.summary.termination));
  if (r.summary.ok()) add_channels(out, std::move(r.series));
  return out;
}

// seed: of the transducers' noise, as `simulate --seed`.
py::dict simulate_py(const Scenario& scenario, std::uint64_t seed) {
  const Plant plant(scenario);
  SimulationResult r;
  {
    py::gil_scoped_release release;
    r = simulate_from(plant, run_start_state(plant, scenario.run), scenario.run);
  }
  if (r.summary.ok()) add_scenario_measured_channels(r.series, scenario, seed);
  return simulation_dict(std::move(r), plant);
}

// `sweep --replay POINT:REPEAT`: the run's runs.csv fields (name -> text, as the file holds
// them) and its record as simulate() returns one (with the measured channels the analysis saw).
py::dict sweep_replay_py(const SweepSpec& spec, std::size_t point, std::size_t repeat) {
  std::pair<SweepRun, RunRecord> replayed;
  {
    py::gil_scoped_release release;
    replayed = replay_run(spec, point, repeat, "replay");
  }
  auto& [run, record] = replayed;
  py::dict fields;
  for (const auto& [name, value] : record.named_fields()) fields[py::str(name)] = value;
  py::dict out;
  out["run"] = fields;
  out["record"] = simulation_dict(std::move(run.sim), Plant(run.scenario));
  return out;
}

// The samples of x between from_s and to_s [s] (times from the first sample, 0 s), as
// analyze --from/--to cut a record; none given: x whole.
std::vector<double> windowed(std::vector<double> x, double rate_Hz, std::optional<double> from_s,
                             std::optional<double> to_s) {
  if (!from_s && !to_s) return x;
  TimeSeries series(rate_Hz);
  series.add_channel("x", "", std::move(x));
  const TimeSeries cut = cli::with_flag_names(
      cli::FlagNames{{kWindowFromField.id, "from_s"}, {kWindowToField.id, "to_s"}},
      [&] { return time_window(series, from_s, to_s); });
  return cut.channel("x").values;
}

py::tuple analyze_py(const py::array& x_in, double rate_Hz, const AnalysisOptions& options,
                     std::optional<double> from_s, std::optional<double> to_s) {
  check_rate(rate_Hz);
  const std::vector<double> x = windowed(series_from(x_in), rate_Hz, from_s, to_s);
  AnalysisResult r;
  {
    py::gil_scoped_release release;
    r = analyze_series(x, rate_Hz, options);
  }
  py::dict curves;
  curves["frequency_Hz"] = copy_to_numpy(r.spectrum.frequency_Hz);
  curves["psd"] = copy_to_numpy(r.spectrum.psd);
  curves["acf"] = copy_to_numpy(r.acf.r);
  curves["divergence"] = copy_to_numpy(r.divergence.curve);
  curves["wolf_time_s"] = copy_to_numpy(r.wolf.running_time_s);
  curves["wolf_per_s"] = copy_to_numpy(r.wolf.running_per_s);
  return py::make_tuple(analysis_json(r, "<array>", "x", ""), curves);
}

StabilityOptions stability_options(const Scenario& scenario, std::optional<double> position_mm) {
  StabilityOptions options;
  if (position_mm) set_piston_position(options, scenario, *position_mm, "position_mm");
  return options;
}

std::string stability_map_csv(const Scenario& scenario, const std::vector<std::string>& grid,
                              std::optional<double> position_mm) {
  const StabilityOptions options = stability_options(scenario, position_mm);
  std::vector<GridAxis> axes;
  for (const auto& g : grid) axes.push_back(parse_grid_axis(g));
  if (axes.empty()) axes = paper_valve_grid();
  std::ostringstream csv;
  {
    py::gil_scoped_release release;
    const StabilityMap map = stability_map(scenario, axes, options);
    write_stability_map_csv(csv, map, scenario.ambient_pressure_Pa);
  }
  return csv.str();
}

// What a sweep runs, from sweep()'s arguments: the same spec for the whole sweep and for
// one run of it replayed.
SweepSpec sweep_spec_py(const Scenario& scenario, const std::vector<std::string>& grid,
                        std::size_t repeats, std::uint64_t seed, bool wolf, bool paper_judge,
                        std::size_t surrogates,
                        const ModelExponentSpec& model_exponent, bool adaptive,
                        bool adaptive_motion, std::size_t adaptive_step) {
  SweepSpec spec;
  spec.base = scenario;
  for (const auto& g : grid) spec.axes.push_back(parse_grid_axis(g));
  if (spec.axes.empty()) spec.axes = paper_valve_grid();
  spec.repeats = repeats;
  spec.seed = seed;
  spec.wolf = wolf;
  spec.paper_judge = paper_judge;
  spec.surrogates = surrogates;
  spec.model_exponent = model_exponent;
  spec.adaptive.enabled = adaptive;
  spec.adaptive.follow_motion = adaptive_motion;
  spec.adaptive.coarse_step = adaptive_step;
  return spec;
}

py::dict sweep_py(const SweepSpec& spec, const std::string& out, std::size_t threads, bool resume,
                  const py::object& progress) {
  SweepOptions o;
  o.out_dir = out;
  o.threads = threads;
  o.resume = resume;
  o.progress = false;
  o.on_progress = progress_callback(progress, "pneumachaos.sweep progress callback");
  SweepSummary s;
  {
    py::gil_scoped_release release;
    s = run_sweep(spec, o);
  }
  py::dict d;
  d["runs"] = s.runs;
  d["failed"] = s.failed;
  d["points"] = s.points;
  d["stick_slip_points"] = s.stick_slip_points;
  d["chaos_full_points"] = s.chaos_full_points;
  d["chaos_any_points"] = s.chaos_any_points;
  if (spec.adaptive.enabled) d["inferred_points"] = s.inferred_points;
  if (spec.paper_judge) {
    d["paper_chaos_full_points"] = s.paper_chaos_full_points;
    d["paper_chaos_any_points"] = s.paper_chaos_any_points;
  }
  if (spec.model_exponent.enabled) {
    d["model_chaos_full_points"] = s.model_chaos_full_points;
    d["model_chaos_any_points"] = s.model_chaos_any_points;
  }
  return d;
}

// `pneumachaos lyapunov --json`; an error about an option names its Python argument.
std::string model_lyapunov_py(const Scenario& s, const ModelLyapunovOptions& o,
                              double tolerance_factor) {
  if (!(std::isfinite(tolerance_factor) && tolerance_factor > 0.0))
    throw Error("tolerance_factor", "must be a positive number");
  const cli::FlagNames names{{ModelLyapunovOptions::kMeasureField.id, "measure_s"},
                             {ModelLyapunovOptions::kRenormalizeField.id, "renormalize_s"},
                             {ModelLyapunovOptions::kTransientField.id, "transient_s"},
                             {ModelLyapunovOptions::kSeparationField.id, "separation"},
                             {IntegratorOptions::kRelativeToleranceField.id, "tolerance_factor"},
                             {IntegratorOptions::kAbsoluteToleranceField.id, "tolerance_factor"}};
  const ModelLyapunovResult r = cli::with_flag_names(names, [&] {
    py::gil_scoped_release release;
    return plant_lyapunov(Plant(s), s.run, o, tolerance_factor);
  });
  if (!r.ok) throw RunError("model_lyapunov", r.message);
  return lyapunov_json(r, o);
}

// `pneumachaos reproduce`: the same report, resumed when run again into the same directory;
// returns claims.json's text and the report's path. rig: none for the built-in virtual rig.
py::tuple reproduce_py(const std::optional<Scenario>& rig, const std::string& out, bool quick,
                       bool full_maps, std::size_t threads, const py::object& progress) {
  ReproduceOptions o;
  o.out_dir = out;
  o.quick = quick;
  o.full_maps = full_maps;
  o.threads = threads;
  o.progress = false;
  o.on_progress = progress_callback(progress, "pneumachaos.reproduce progress callback");
  if (rig) {
    o.rig = *rig;
    o.rig_source = "a scenario given to pneumachaos.reproduce";
  }
  ReproduceResult r;
  {
    py::gil_scoped_release release;
    r = reproduce(o);
  }
  std::ifstream in(out + "/claims.json");
  std::stringstream text;
  text << in.rdbuf();
  return py::make_tuple(text.str(), r.index_html);
}

void bind_scenario(py::module_& m) {
  py::class_<Scenario>(m, "Scenario")
      .def_static("default", &default_scenario)
      .def_static("from_toml", [](const std::string& path) { return build_scenario(path, {}); })
      .def("set_number",
           [](Scenario& s, const std::string& key, double v) {
             Scenario next = s;
             apply_setting(next, key, v, "Scenario.set");
             next.validate();
             s = next;
           })
      .def("set_word",
           [](Scenario& s, const std::string& key, const std::string& v) {
             Scenario next = s;
             apply_setting(next, key, v, "Scenario.set");
             next.validate();
             s = next;
           })
      .def("get", [](const Scenario& s, const std::string& key) { return setting_text(s, key); })
      .def("to_toml", [](const Scenario& s) { return scenario_to_toml(s); })
      .def("copy", [](const Scenario& s) { return s; });
  m.def("key_infos", [] {
    py::list out;
    const Scenario d = default_scenario();
    for (const auto& k : scenario_key_infos()) {
      py::dict e;
      e["key"] = k.key;
      e["unit"] = k.unit;
      e["default"] = setting_text(d, k.key);
      e["description"] = k.description;
      e["allowed"] = k.choices.empty() ? k.range : k.choices;
      out.append(e);
    }
    return out;
  });
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "pneumachaos compiled core (use the pneumachaos package)";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const RunError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    } catch (const Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  bind_scenario(m);
  // fit's options in the command line's units (mm/s for the velocity scale) and defaults.
  py::class_<identify::FitOptions>(m, "FitOptions")
      .def(py::init<>())
      .def_readwrite("segment_s", &identify::FitOptions::segment_length_s)
      .def_readwrite("pressure_scale_Pa", &identify::FitOptions::pressure_scale_Pa)
      .def_property(
          "velocity_scale_mm_per_s",
          [](const identify::FitOptions& o) { return o.velocity_scale_m_per_s * 1e3; },
          [](identify::FitOptions& o, double mm) { o.velocity_scale_m_per_s = mm * 1e-3; })
      .def_readwrite("max_iterations", &identify::FitOptions::max_iterations);
  py::class_<AnalysisOptions>(m, "AnalysisOptions")
      .def(py::init<>())
      .def_readwrite("wolf", &AnalysisOptions::wolf)
      .def_readwrite("jacobian", &AnalysisOptions::jacobian)
      .def_readwrite("velocity", &AnalysisOptions::velocity)
      .def_readwrite("embedding_spread", &AnalysisOptions::embedding_spread)
      .def_readwrite("paper_judge", &AnalysisOptions::paper_judge)
      .def_readwrite("dimension", &AnalysisOptions::dimension)
      .def_readwrite("delay", &AnalysisOptions::delay)
      .def_readwrite("theiler", &AnalysisOptions::theiler)
      .def_readwrite("seed", &AnalysisOptions::seed)
      .def_readwrite("verdict_seeds", &AnalysisOptions::verdict_seeds)
      .def_property(
          "surrogates", [](const AnalysisOptions& o) { return o.surrogates.count; },
          [](AnalysisOptions& o, std::size_t n) { o.surrogates.count = n; });
  m.def("simulate", &simulate_py);
  m.def("analyze", &analyze_py);
  m.def("stability_json", [](const Scenario& s, std::optional<double> position_mm) {
    const StabilityOptions options = stability_options(s, position_mm);
    py::gil_scoped_release release;
    return stability_json(s, analyze_stability(Plant(s), options));
  });
  m.def("stability_map_csv", &stability_map_csv);
  // The model exponent's options in the command line's units and defaults.
  py::class_<ModelLyapunovOptions>(m, "ModelLyapunovOptions")
      .def(py::init<>())
      .def_readwrite("transient_s", &ModelLyapunovOptions::transient_s)
      .def_readwrite("measure_s", &ModelLyapunovOptions::measure_s)
      .def_readwrite("renormalize_s", &ModelLyapunovOptions::renormalize_s)
      .def_readwrite("separation", &ModelLyapunovOptions::separation)
      .def_readwrite("until_stroke_end", &ModelLyapunovOptions::until_terminal_event);
  m.def("model_lyapunov_json", &model_lyapunov_py);
  m.def("reproduce", &reproduce_py);
  py::class_<ModelExponentSpec>(m, "ModelExponentSpec")
      .def(py::init<>())
      .def_readwrite("enabled", &ModelExponentSpec::enabled)
      .def_readwrite("transient_s", &ModelExponentSpec::transient_s)
      .def_readwrite("measure_s", &ModelExponentSpec::measure_s)
      .def_readwrite("renormalize_s", &ModelExponentSpec::renormalize_s);
  py::class_<SweepSpec>(m, "SweepSpec");
  m.def("sweep_spec", &sweep_spec_py);
  m.def("sweep", &sweep_py);
  m.def("sweep_replay", &sweep_replay_py);
  m.def("friction_json", &friction_py);
  m.def("fit_json", &fit_py);
  // calibrate (docs/guide/calibrate.md): runs or resumes SPEC into out_dir and returns its
  // calibration.json (best point, fitted and predicted claims).
  m.def("calibrate_json", [](const std::string& spec_path, const std::string& out_dir,
                             std::size_t threads, bool resume) {
    const CalibrationSpec spec = read_calibration_spec(spec_path);
    CalibrateOptions o;
    o.out_dir = out_dir;
    o.threads = threads;
    o.resume = resume;
    o.progress = false;
    {
      py::gil_scoped_release release;
      calibrate(spec, o);
    }
    std::ifstream in(out_dir + "/calibration.json");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  });
}
