"""pneumachaos for notebooks: simulate a pneumatic cylinder, analyse any record for chaos.

Bad input raises ValueError with the same message as the command line; a run that fails
(solver, step budget, a file that cannot be written) raises RuntimeError. Long calls release
the GIL, so threads of a notebook keep running.
"""

# The module's names are its API alone (__all__); what it uses is imported under a leading
# underscore.
import io as _io
import json as _json
import os as _os
import sys as _sys
import time as _time
from collections.abc import Mapping as _Mapping

import numpy as _np

from . import _core

__all__ = ["Scenario", "SimulationResult", "AnalysisResult", "simulate", "analyze",
           "stability", "stability_map", "model_lyapunov", "friction", "fit", "sweep",
           "calibrate", "reproduce"]


class Scenario:
    """Every parameter of a run. Keys and units as in `pneumachaos scenario --keys`."""

    def __init__(self, core=None):
        """Scenario() is the built-in default scenario, as Scenario.default(). `core` is for the
        module's own use (a compiled scenario, as the other constructors pass it); a file is
        loaded with Scenario.from_toml(path), and anything else is refused."""
        if core is None:
            core = _core.Scenario.default()
        elif isinstance(core, (str, bytes, _os.PathLike)):
            raise ValueError(f"Scenario: got the path {core!r}; load a scenario file with "
                             "Scenario.from_toml(path)")
        elif not isinstance(core, _core.Scenario):
            raise ValueError(f"Scenario: expected no argument (the default scenario), got "
                             f"{type(core).__name__}; use Scenario.default() or "
                             "Scenario.from_toml(path)")
        self._core = core

    @classmethod
    def default(cls):
        """The built-in default scenario (the virtual rig)."""
        return cls(_core.Scenario.default())

    @classmethod
    def from_toml(cls, path):
        """A scenario file on top of the defaults, validated."""
        return cls(_core.Scenario.from_toml(str(path)))

    def set(self, key, value):
        """Sets one key in its unit (e.g. set("circuit.S2_mm2", 0.05)) IN PLACE: this scenario
        changes, and the same object is returned for chaining, so after `s2 = s.set(...)` s2
        IS s. For a changed copy that leaves this scenario alone, use with_value(key, value)."""
        if isinstance(value, str):
            self._core.set_word(key, value)
        elif isinstance(value, bool) or not isinstance(value, (int, float, _np.floating, _np.integer)):
            raise ValueError(f"Scenario.set: {key}: expected a number or a word, got {value!r}")
        else:
            self._core.set_number(key, float(value))
        return self

    def with_value(self, key, value):
        """A copy of this scenario with one key set in its unit; this scenario is unchanged:
        `fast = s.with_value("circuit.S2_mm2", 1.0)`."""
        return self.copy().set(key, value)

    def get(self, key):
        """The key's value as text in its unit."""
        return self._core.get(key)

    @staticmethod
    def keys():
        """Every key with its unit, default, description and allowed values (list of dicts)."""
        return _core.key_infos()

    def to_toml(self):
        return self._core.to_toml()

    def copy(self):
        return Scenario(self._core.copy())


class SimulationResult(_Mapping):
    """A time response: t, x, v, P1, P2, ... as numpy arrays (SI units, see .units), reached
    as attributes (r.v) or as a mapping of channel names (r["v"], "v" in r, r.keys(),
    r.items()); to_json() gives the whole result as JSON text."""

    def __init__(self, raw):
        self.ok = raw["ok"]
        self.summary = raw["summary"]
        self.termination = raw["termination"]
        self.rate_Hz = raw.get("rate_Hz")
        self.units = dict(raw.get("units", {}))
        self._channels = dict(raw.get("channels", {}))

    def __getattr__(self, name):
        channels = self.__dict__.get("_channels", {})
        if name in channels:
            return channels[name]
        raise AttributeError(f"no channel {name!r}; the record has {sorted(channels)}")

    @property
    def channels(self):
        return list(self._channels)

    def __getitem__(self, name):
        return self._channels[name]

    def __iter__(self):
        return iter(self._channels)

    def __len__(self):
        return len(self._channels)

    def to_json(self):
        return _json.dumps({key: (value.tolist() if isinstance(value, _np.ndarray) else value)
                            for key, value in self.to_dict().items()})

    def to_dict(self):
        return {"summary": self.summary, "termination": self.termination,
                "rate_Hz": self.rate_Hz, "units": self.units, **self._channels}


class AnalysisResult(_Mapping):
    """Every index of `pneumachaos analyze`: a mapping of its --json output's fields
    (r["lyapunov"], "verdict" in r, r.keys(), r.items(); the same dict in .json, the same
    text from to_json()) and the curves as numpy arrays (.curves: frequency_Hz, psd, acf,
    divergence, wolf_*)."""

    def __init__(self, text, curves):
        self._text = text
        self.json = _json.loads(text)
        self.curves = dict(curves)

    @property
    def verdict(self):
        return self.json["verdict"]

    def __getitem__(self, key):
        return self.json[key]

    def __iter__(self):
        return iter(self.json)

    def __len__(self):
        return len(self.json)

    def to_json(self):
        return self._text


def _scenario(scenario):
    if scenario is None:
        return Scenario.default()
    if not isinstance(scenario, Scenario):
        raise ValueError(f"expected a pneumachaos.Scenario, got {type(scenario).__name__}")
    return scenario


def simulate(scenario=None, duration_s=None, rate_Hz=None, seed=0):
    """Simulates the scenario; duration_s and rate_Hz override run.duration_s / run.rate_Hz.
    With any transducer.* key set, the record also holds v_measured, P1_measured and
    P2_measured as the transducers give them, their noise drawn from `seed` (default 0): the
    same channels as `pneumachaos simulate --seed` writes. Raises RuntimeError when the run
    fails (the summary says why)."""
    seed = _seed("seed", seed)
    s = _scenario(scenario).copy()
    if duration_s is not None:
        s.set("run.duration_s", duration_s)
    if rate_Hz is not None:
        s.set("run.rate_Hz", rate_Hz)
    result = SimulationResult(_core.simulate(s._core, seed))
    if not result.ok:
        raise RuntimeError(f"simulate: {result.summary}")
    return result


def _samples(x):
    """A record's samples as an array; the compiled core checks them (1-D, real, finite, not
    empty) naming the argument."""
    return x if isinstance(x, _np.ndarray) else _np.asarray(x)


def _names(value, argument):
    """A list of strings from a list or tuple; a single string is refused naming the argument
    (it would be read as its characters)."""
    if isinstance(value, (str, bytes)):
        raise ValueError(f"{argument}: expected a list of strings, got the string {value!r}; "
                         f"write [{value!r}]")
    return [str(v) for v in value]


def analyze(x, rate_Hz, wolf=True, dimension=0, delay=0, theiler=0, seed=1, verdict_seeds=5,
            velocity=True, embedding_spread=True, surrogates=39, from_s=None, to_s=None,
            judge="strict", jacobian=False):
    """Chaos indices and the regime verdict of a uniformly sampled 1-D record x [any unit] at
    rate_Hz, with the numbers of `pneumachaos analyze` given the same record, seed and options.
    dimension, delay (samples), theiler (samples): 0 = automatic. seed: the 0-1 test's and the
    surrogates'; verdict_seeds (odd): seeds the verdict is decided on where a random test could
    turn it (verdict["seed_agreement"] holds the tally). velocity: x is a velocity, where zero
    means rest, and stick-slip is judged from its rests; False for any other signal (not
    judged). embedding_spread: the divergence exponent's uncertainty also covers its values at
    embedding dimensions m - 1 and m + 1. surrogates: IAAFT surrogates for the test against
    linear noise (default 39 as on the command line; 0 = off, else 19 to 999). from_s, to_s:
    analyse only the samples from/up to these times [s], the first sample at 0 s (as --from
    and --to, e.g. from_s=2 to skip a start-up transient; default: the whole record).
    judge: "strict" or "paper" (--judge): with "paper" Wolf's estimator runs on every record,
    as the paper ran it; the paper's three indices are in result["paper_judge"] either way.
    jacobian: also estimate the exponents from local Jacobians, a second estimate of the
    largest beside the divergence curve's (--jacobian-exponents; result["lyapunov"]["jacobian"])."""
    if judge not in ("strict", "paper"):
        raise ValueError(f"judge: expected 'strict' or 'paper', got {judge!r}")
    if judge == "paper" and not wolf:
        raise ValueError("judge: the paper's judge reads Wolf's exponent; keep wolf=True")
    options = _core.AnalysisOptions()
    options.wolf = bool(wolf)
    options.paper_judge = judge == "paper"
    options.jacobian = bool(jacobian)
    options.velocity = bool(velocity)
    options.embedding_spread = bool(embedding_spread)
    for name, value in (("dimension", dimension), ("delay", delay), ("theiler", theiler),
                        ("seed", seed), ("verdict_seeds", verdict_seeds),
                        ("surrogates", surrogates)):
        setattr(options, name, _whole(name, value, 0))
    return AnalysisResult(*_core.analyze(_samples(x), float(rate_Hz), options,
                                         _number_or_none("from_s", from_s),
                                         _number_or_none("to_s", to_s)))


def stability(scenario=None, position_mm=None):
    """Equilibrium, the paper's a1/b1 and damping coefficient, the full model's eigenvalues
    and both verdicts, as `pneumachaos stability --json` gives them. position_mm: the piston
    position the chamber volumes are taken at, 0 to the stroke (--position-mm; default:
    cylinder.frozen_position_mm when the scenario sets it, else mid-stroke)."""
    return _json.loads(_core.stability_json(_scenario(scenario)._core,
                                            _number_or_none("position_mm", position_mm)))


def stability_map(scenario=None, grid=(), position_mm=None):
    """The stability verdict over a grid ("KEY=FROM:TO:STEP" strings; default: the paper's
    S1 x S2 grid) as a dict of numpy arrays, one per column of `stability --map`;
    position_mm as in stability()."""
    text = _core.stability_map_csv(_scenario(scenario)._core, _names(grid, "grid"),
                                   _number_or_none("position_mm", position_mm))
    table = _np.genfromtxt(_io.StringIO(text), delimiter=",", names=True, dtype=None,
                          encoding="utf-8", deletechars="", autostrip=True)
    return {name: _np.atleast_1d(table[name]) for name in table.dtype.names}


def model_lyapunov(scenario=None, transient_s=5.0, measure_s=40.0, renormalize_s=0.02,
                   separation=1e-3, tolerance_factor=1.0, until_stroke_end=True):
    """The model's own largest Lyapunov exponent (two trajectories, renormalised), as
    `pneumachaos lyapunov --json` gives it with --transient, --measure, --renormalize,
    --separation, --tolerance-factor and --[no-]until-stroke-end (same defaults). separation:
    the initial separation in scaled units (1 = 10 kPa on P1), at least 1e6 x the relative
    tolerance (1e-9 x tolerance_factor); until_stroke_end=False fails the run at a stroke end
    during the measurement instead of ending it there. The running estimate (--running-out)
    is result["lyapunov"]["running"]: its "t" and "lambda" values."""
    options = _core.ModelLyapunovOptions()  # the command line's defaults
    for name, value in (("transient_s", transient_s), ("measure_s", measure_s),
                        ("renormalize_s", renormalize_s), ("separation", separation)):
        setattr(options, name, _number(name, value))
    options.until_stroke_end = _flag("until_stroke_end", until_stroke_end)
    return _json.loads(_core.model_lyapunov_json(_scenario(scenario)._core, options,
                                                _number("tolerance_factor", tolerance_factor)))


def _number(name, value):
    """A real number (its range is the library's to check, naming the argument)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, _np.integer, _np.floating)):
        raise ValueError(f"{name}: expected a number, got {value!r}")
    return float(value)


def _number_or_none(name, value):
    return None if value is None else _number(name, value)


def _flag(name, value):
    """True or False; anything else (a string "false" would read as True) is refused."""
    if not isinstance(value, (bool, _np.bool_)):
        raise ValueError(f"{name}: expected True or False, got {value!r}")
    return bool(value)


def _seed(name, value):
    """A seed as the command line takes it: a whole number from 0 to 2**64 - 1."""
    value = _whole(name, value, 0)
    if value >= 2 ** 64:
        raise ValueError(f"{name}: expected a whole number below 2**64, got {value!r}")
    return value


def _whole(name, value, least):
    """A whole number >= least, else ValueError naming the argument."""
    if isinstance(value, bool) or not isinstance(value, (int, _np.integer)) or value < least:
        raise ValueError(f"{name}: expected a whole number >= {least}, got {value!r}")
    return int(value)


def _positive(name, value):
    """A number > 0, else ValueError naming the argument."""
    if isinstance(value, bool) or not isinstance(value, (int, float, _np.integer, _np.floating)) \
            or not value > 0:
        raise ValueError(f"{name}: expected a number > 0, got {value!r}")
    return float(value)


def friction(t, v, P1, P2, scenario=None, models=(), pressure_dependent=False, window=None,
             max_iterations=200):
    """Seal friction from a measured record, as `pneumachaos friction --json` gives it: t [s],
    v [m/s], P1 and P2 [Pa, absolute] as 1-D arrays (or lists) of one length; geometry and
    moving mass from the scenario; models from "classic", "stribeck", "stribeck_delta", "lugre"
    (default all). window: the Savitzky-Golay window in samples (odd, >= 3; default: chosen from
    the noise); max_iterations: allowed to each fit (default 200), as --window and
    --max-iterations. result["scenario_toml"] is what --scenario-out writes: the preferred
    model as a scenario [friction] table (None when no model converged with Fc <= Fs).
    Raises ValueError for bad input, RuntimeError when no fit converges."""
    window = 0 if window is None else _whole("window", window, 1)
    text, table = _core.friction_json(_samples(t), _samples(v), _samples(P1), _samples(P2),
                                      _scenario(scenario)._core, _names(models, "models"),
                                      bool(pressure_dependent), window,
                                      _whole("max_iterations", max_iterations, 1))
    result = _json.loads(text)
    result["scenario_toml"] = table or None
    return result


def fit(t, v, P1, P2, scenario=None, free=(), segment_s=0.2, pressure_scale_Pa=1000.0,
        velocity_scale_mm_per_s=30.0, max_iterations=50):
    """Identifies the scenario keys named in `free` (default: S1, S2, the seal's Fc and Fs)
    from a measured record by segment-wise simulation, as `pneumachaos fit --json` gives it,
    with its --segment, --pressure-scale, --velocity-scale and --max-iterations (same
    defaults). result["scenario"] is the fitted Scenario (what --scenario-out writes as TOML:
    result["scenario"].to_toml()). Raises ValueError for bad input, RuntimeError when the fit
    does not converge."""
    options = _core.FitOptions()
    options.segment_s = _positive("segment_s", segment_s)
    options.pressure_scale_Pa = _positive("pressure_scale_Pa", pressure_scale_Pa)
    options.velocity_scale_mm_per_s = _positive("velocity_scale_mm_per_s", velocity_scale_mm_per_s)
    options.max_iterations = _whole("max_iterations", max_iterations, 1)
    text, fitted = _core.fit_json(_samples(t), _samples(v), _samples(P1), _samples(P2),
                                  _scenario(scenario)._core, _names(free, "free"), options)
    result = _json.loads(text)
    result["scenario"] = Scenario(fitted)
    return result


def _print_progress(command="sweep"):
    state = {"last": 0.0}

    def show(done, total):
        now = _time.monotonic()
        if done == total or now - state["last"] >= 1.0:
            state["last"] = now
            end = "\n" if done == total else ""
            print(f"\r{command}: {done}/{total} runs", end=end, file=_sys.stderr, flush=True)
    return show


# The variables MPI launchers set (src/sweep/distribution.cpp reads the same ones to decide
# that a sweep is distributed over ranks).
_MPI_LAUNCHER_VARIABLES = ("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK")


def _refuse_under_mpi(command="sweep"):
    """A sweep in this module runs on threads of one process. Under mpirun every rank would
    run the whole sweep into the same directory (two writers), and the MPI module that shares
    runs between ranks belongs to the command line, not to the Python package, so the call is
    refused before anything is written. reproduce runs its maps as sweeps: the same holds."""
    launcher = next((v for v in _MPI_LAUNCHER_VARIABLES if v in _os.environ), None)
    if launcher is not None:
        raise RuntimeError(
            f"{command}: started under an MPI launcher ({launcher} is set): the Python module "
            "runs sweeps on the threads of one process and cannot share them between MPI "
            "ranks. Run Python without mpirun (threads=N uses N cores), or distribute the "
            f"work with the command line: mpirun -np N pneumachaos {command} ...")


def _progress(progress, command):
    """True: a printed "command: done/total runs" line; False: nothing; or the callable."""
    if progress is True:
        return _print_progress(command)
    if progress is False:
        return None
    if not callable(progress):
        raise ValueError(f"{command}: progress: expected True, False or a callable, got "
                         f"{progress!r}")
    return progress


def sweep(scenario=None, grid=(), repeats=5, seed=1, out=None, threads=0, resume=False,
          progress=True, wolf=False, surrogates=0, model_exponent=False, model_transient_s=None,
          model_measure_s=None, model_renormalize_s=None, adaptive=False, adaptive_motion=False,
          adaptive_step=4, replay=None, judge="strict"):
    """Repeated runs over a grid into directory `out` (journaled, resumable); returns the
    summary counts. The per-run and per-point tables are out/runs.csv and out/points.csv.
    progress: True prints "sweep: done/total runs" at most once a second, False prints
    nothing, a callable is called as progress(done, total) after every run. The rest are the
    CLI's --wolf, --surrogates and --model-exponent with --model-transient, --model-measure
    and --model-renormalize (docs/sweep.md): e.g. model_exponent=True stores each run's model
    exponent, so the verdict can be checked against it (bench/verdict_vs_model.py); the
    model settings need model_exponent=True (defaults 1 s, 0 = the rest of the run, 0.02 s).
    adaptive=True (a grid of two axes) is the CLI's --adaptive with --adaptive-step: a coarse
    lattice, then only the cells whose points differ; the summary gains inferred_points and
    points.csv's `inferred` column marks the points filled from their cell, not run;
    adaptive_motion=True (--adaptive-motion) also refines where the motion changes between
    settling and oscillating (about twice the runs).
    judge="paper" (--judge paper) also judges every run by the paper's three indices (Wolf's
    estimator runs on each): runs.csv paper_chaotic, points.csv paper_chaos_incidence, and the
    summary gains paper_chaos_full_points and paper_chaos_any_points.
    replay=(POINT, REPEAT) is --replay: that one run of this sweep again, bit for bit, nothing
    written (out not needed); returns {"run": its runs.csv fields as text by column, "record":
    the SimulationResult the analysis judged, with v_measured, P1_measured, P2_measured}."""
    if judge not in ("strict", "paper"):
        raise ValueError(f"sweep: judge: expected 'strict' or 'paper', got {judge!r}")
    spec = _sweep_spec(scenario, grid, repeats, seed, (wolf, judge == "paper"), surrogates,
                       model_exponent, (model_transient_s, model_measure_s, model_renormalize_s),
                       adaptive, adaptive_motion, adaptive_step)
    if replay is not None:
        return _replay(spec, replay)
    if not out:
        raise ValueError("sweep: out: a directory for the results is required")
    _refuse_under_mpi()
    _whole("sweep: threads", threads, 0)
    progress = _progress(progress, "sweep")
    return _core.sweep(spec, str(out), int(threads), bool(resume), progress)


def _sweep_spec(scenario, grid, repeats, seed, judges, surrogates, model_exponent, model_times,
                adaptive, adaptive_motion, adaptive_step):
    """What sweep() runs, checked naming each argument; judges: (wolf, the paper's judge)."""
    for name, value in (("repeats", repeats), ("seed", seed), ("surrogates", surrogates),
                        ("adaptive_step", adaptive_step)):
        _whole(f"sweep: {name}", value, 0)
    model = _core.ModelExponentSpec()  # the command line's defaults
    model.enabled = bool(model_exponent)
    for name, value in zip(("transient_s", "measure_s", "renormalize_s"), model_times):
        if value is None:
            continue
        if not model.enabled:
            raise ValueError(f"sweep: model_{name}: needs model_exponent=True")
        setattr(model, name, float(value))
    if _flag("sweep: adaptive_motion", adaptive_motion) and not adaptive:
        raise ValueError("sweep: adaptive_motion: needs adaptive=True")
    return _core.sweep_spec(_scenario(scenario)._core, _names(grid, "grid"), int(repeats),
                            int(seed), bool(judges[0]), bool(judges[1]), int(surrogates), model,
                            bool(adaptive),
                            bool(adaptive_motion), int(adaptive_step))


def _replay(spec, replay):
    """sweep(replay=(POINT, REPEAT)): the run again, as `sweep --replay POINT:REPEAT`."""
    if isinstance(replay, (str, bytes)) or not hasattr(replay, "__len__") or len(replay) != 2 \
            or any(isinstance(i, bool) or not isinstance(i, (int, _np.integer)) or i < 0
                   for i in replay):
        raise ValueError(f"sweep: replay: expected (POINT, REPEAT), two whole numbers >= 0, "
                         f"got {replay!r}")
    raw = _core.sweep_replay(spec, int(replay[0]), int(replay[1]))
    return {"run": dict(raw["run"]), "record": SimulationResult(raw["record"])}


def calibrate(spec, out_dir, threads=0, resume=False):
    """Runs the calibration SPEC (a TOML file, docs/guide/calibrate.md) into out_dir, as
    `pneumachaos calibrate SPEC --out DIR`; resume=True continues one journalled there. Returns
    calibration.json as a dict: the best point, its fitted and its predicted claims."""
    _whole("calibrate: threads", threads, 0)
    if not out_dir:
        raise ValueError("calibrate: out_dir: a directory for the results is required")
    return _json.loads(_core.calibrate_json(str(spec), str(out_dir), int(threads), bool(resume)))


def reproduce(scenario=None, out="report", quick=False, full_maps=False, threads=0,
              progress=True):
    """The paper's figures and claims as an HTML report in directory `out`, as `pneumachaos
    reproduce --out OUT [--quick] [--full-maps] [--threads N]` makes it (the same code and
    numbers); scenario: the rig (default: the built-in virtual rig). Run again into the same
    directory it resumes its sweeps. progress as in sweep(): True prints "reproduce:
    done/total runs" (total: at most, with adaptive maps), a callable gets (done, total).
    Returns {"claims": claims.json as a dict, "report": the path of index.html}."""
    if not isinstance(out, (str, _os.PathLike)) or not str(out):
        raise ValueError(f"reproduce: out: expected a directory for the report, got {out!r}")
    options = (_flag("reproduce: quick", quick), _flag("reproduce: full_maps", full_maps),
               _whole("reproduce: threads", threads, 0))
    progress = _progress(progress, "reproduce")
    rig = None if scenario is None else _scenario(scenario)._core
    _refuse_under_mpi("reproduce")
    claims, report = _core.reproduce(rig, str(out), *options, progress)
    return {"claims": _json.loads(claims), "report": report}
