"""Every option of the command line has its Python counterpart: the table below names it for
each subcommand, and the test reads `pneumachaos CMD --help` from the built binary, so an
option added to the command line without an entry here fails until its counterpart (or the
reason it has none) is written down."""

import inspect
import os
import re
import subprocess

import pytest

import pneumachaos as pc

CLI = os.environ.get("PNEUMACHAOS_CLI", "")


def kw(function, argument, default=inspect.Parameter.empty):
    """The option is `argument` of pneumachaos.`function`, with the command line's default
    when one is given here."""
    return ("keyword", function, argument, default)


def api(path):
    """The option is reached through the attribute `path` of the module (e.g. Scenario.set)."""
    return ("api", path)


def plumbing(reason):
    """The option moves data between files and the terminal; Python passes values instead."""
    return ("plumbing", reason)


HELP = plumbing("the command's usage text; Python has help() and the docstrings")
QUIET = plumbing("the terminal's progress line; the Python calls print nothing of their own")
SCENARIO = api("Scenario.from_toml")
SET = api("Scenario.set")
COLUMNS = plumbing("header names of a record file's columns; Python takes the arrays")
UNITS = plumbing("units of a record file's columns; Python takes SI arrays")

# option (or positional) -> its counterpart, per subcommand.
OPTIONS = {
    "simulate": {
        "-h,--help": HELP, "scenario": SCENARIO, "--set": SET,
        "--duration": kw("simulate", "duration_s", None),
        "--rate": kw("simulate", "rate_Hz", None),
        "--seed": kw("simulate", "seed", 0),
        "-o,--output": plumbing("the CSV file; Python returns the channels as arrays"),
        "--quiet": QUIET,
    },
    "scenario": {
        "-h,--help": HELP, "scenario": SCENARIO, "--set": SET,
        "--keys": api("Scenario.keys"),
    },
    "stability": {
        "-h,--help": HELP, "scenario": SCENARIO, "--set": SET,
        "--json": plumbing("JSON on standard output; Python returns it as a dict"),
        "--position-mm": kw("stability", "position_mm", None),
        "--map": api("stability_map"),
        "--grid": kw("stability_map", "grid", ()),
        "-o,--output": plumbing("the map's CSV file; Python returns its columns as arrays"),
    },
    "analyze": {
        "-h,--help": HELP,
        "file": plumbing("the record's file; Python takes its samples as an array"),
        "--column": plumbing("which column of the file; Python takes that column's array"),
        "--quantity": kw("analyze", "velocity", True),
        "--rate": kw("analyze", "rate_Hz"),
        "--units": UNITS,
        "--from": kw("analyze", "from_s", None),
        "--to": kw("analyze", "to_s", None),
        "--json": plumbing("the JSON file; Python returns the same fields (result.json)"),
        "--series-out": plumbing("CSV files of the curves; Python returns them as arrays "
                                 "(result.curves)"),
        "--no-wolf": kw("analyze", "wolf", True),
        "--judge": kw("analyze", "judge", "strict"),
        "--jacobian-exponents": kw("analyze", "jacobian", False),
        "--quiet": QUIET,
        "--explain": plumbing("a paragraph for the terminal; the evidence is in "
                              "result['verdict']"),
        "--no-embedding-spread": kw("analyze", "embedding_spread", True),
        "--surrogates": kw("analyze", "surrogates", 39),
        "--seed": kw("analyze", "seed", 1),
        "--verdict-seeds": kw("analyze", "verdict_seeds", 5),
        "--dimension": kw("analyze", "dimension", 0),
        "--delay": kw("analyze", "delay", 0),
        "--theiler": kw("analyze", "theiler", 0),
    },
    "sweep": {
        "-h,--help": HELP, "scenario": SCENARIO, "--set": SET,
        "--grid": kw("sweep", "grid", ()),
        "--repeats": kw("sweep", "repeats", 5),
        "--seed": kw("sweep", "seed", 1),
        "--threads": kw("sweep", "threads", 0),
        "--out": kw("sweep", "out", None),
        "--resume": kw("sweep", "resume", False),
        "--wolf": kw("sweep", "wolf", False),
        "--judge": kw("sweep", "judge", "strict"),
        "--surrogates": kw("sweep", "surrogates", 0),
        "--model-exponent": kw("sweep", "model_exponent", False),
        "--model-transient": kw("sweep", "model_transient_s", None),
        "--model-measure": kw("sweep", "model_measure_s", None),
        "--model-renormalize": kw("sweep", "model_renormalize_s", None),
        "--adaptive": kw("sweep", "adaptive", False),
        "--adaptive-motion": kw("sweep", "adaptive_motion", False),
        "--adaptive-step": kw("sweep", "adaptive_step", 4),
        "--replay": kw("sweep", "replay", None),
        "-o,--record": plumbing("the replayed record's CSV file; Python returns the record"),
    },
    "lyapunov": {
        "-h,--help": HELP, "scenario": SCENARIO, "--set": SET,
        "--transient": kw("model_lyapunov", "transient_s", 5.0),
        "--measure": kw("model_lyapunov", "measure_s", 40.0),
        "--renormalize": kw("model_lyapunov", "renormalize_s", 0.02),
        "--separation": kw("model_lyapunov", "separation", 1e-3),
        "--tolerance-factor": kw("model_lyapunov", "tolerance_factor", 1.0),
        "--until-stroke-end,--no-until-stroke-end": kw("model_lyapunov", "until_stroke_end", True),
        "--running-out": plumbing("the running estimate's CSV file; Python returns it in "
                                  "result['lyapunov']['running']"),
        "--json": plumbing("JSON on standard output; Python returns it as a dict"),
        "--quiet": QUIET,
    },
    "reproduce": {
        "-h,--help": HELP,
        "scenario": kw("reproduce", "scenario", None), "--set": SET,
        "--out": kw("reproduce", "out", "report"),
        "--quick": kw("reproduce", "quick", False),
        "--full-maps": kw("reproduce", "full_maps", False),
        "--threads": kw("reproduce", "threads", 0),
    },
    "friction": {
        "-h,--help": HELP,
        "file": plumbing("the record's file; Python takes t, v, P1, P2 as arrays"),
        "scenario": kw("friction", "scenario", None), "--set": SET,
        "--json": plumbing("the JSON file; Python returns the same fields as a dict"),
        "--series-out": plumbing("CSV files of F(t), F(v) and the model curves for plotting; "
                                 "the fitted values are in the returned dict"),
        "--scenario-out": plumbing("the TOML file; Python returns its text as "
                                   "result['scenario_toml']"),
        "--model": kw("friction", "models", ()),
        "--pressure-dependent": kw("friction", "pressure_dependent", False),
        "--window": kw("friction", "window", None),
        "--max-iterations": kw("friction", "max_iterations", 200),
        "--column-t": COLUMNS, "--column-v": COLUMNS, "--column-P1": COLUMNS,
        "--column-P2": COLUMNS, "--column-x": COLUMNS, "--column-a": COLUMNS,
        "--units": UNITS,
        "--quiet": QUIET,
    },
    "fit": {
        "-h,--help": HELP,
        "record": plumbing("the record's file; Python takes t, v, P1, P2 as arrays"),
        "scenario": kw("fit", "scenario", None), "--set": SET,
        "--quiet": QUIET,
        "--free": kw("fit", "free", ()),
        "--json": plumbing("the JSON file; Python returns the same fields as a dict"),
        "--scenario-out": plumbing("the TOML file; Python returns the fitted Scenario as "
                                   "result['scenario']"),
        "--plot-out": plumbing("the validation figure's files (CSV, gnuplot, PNG) for a "
                               "reader of the directory"),
        "--column-t": COLUMNS, "--column-v": COLUMNS, "--column-P1": COLUMNS,
        "--column-P2": COLUMNS, "--column-x": COLUMNS, "--column-a": COLUMNS,
        "--units": UNITS,
        "--segment": kw("fit", "segment_s", 0.2),
        "--pressure-scale": kw("fit", "pressure_scale_Pa", 1000.0),
        "--velocity-scale": kw("fit", "velocity_scale_mm_per_s", 30.0),
        "--max-iterations": kw("fit", "max_iterations", 50),
        "--verbose": plumbing("Ceres's iteration log on standard error"),
    },
    "calibrate": {
        "-h,--help": HELP,
        "spec": kw("calibrate", "spec"),
        "--out": kw("calibrate", "out_dir"),
        "--threads": kw("calibrate", "threads", 0),
        "--resume": kw("calibrate", "resume", False),
    },
}

# An option's line in CLI11's help: two spaces, its names (commas, no blanks), maybe a
# {default}; a positional's: two spaces and its name.
_OPTION = re.compile(r"^  (-[^\s{]+)")
_POSITIONAL = re.compile(r"^  ([A-Za-z]\w*)\s")


def cli_options(command):
    """The options and positionals `pneumachaos COMMAND --help` lists, as the table names them."""
    text = subprocess.run([CLI, command, "--help"], check=True, capture_output=True,
                          text=True).stdout
    found, section = [], None
    for line in text.splitlines():
        if line.rstrip() in ("Positionals:", "Options:"):
            section = line.rstrip()
            continue
        match = (_OPTION if section == "Options:" else _POSITIONAL).match(line)
        if section and match:
            found.append(match.group(1))
    return found


def cli_commands():
    text = subprocess.run([CLI, "--help"], check=True, capture_output=True, text=True).stdout
    commands = text.split("Subcommands:", 1)[1]
    return [m.group(1) for m in re.finditer(r"^  (\w+)\s", commands, re.MULTILINE)]


needs_cli = pytest.mark.skipif(not CLI, reason="PNEUMACHAOS_CLI names the command line "
                                                "(set by CTest)")


def missing_counterparts(command, listed):
    """The options of `listed` without an entry in the table, or whose entry names an argument
    or attribute the module does not have, or a default other than the command line's."""
    table = OPTIONS.get(command, {})
    problems = []
    for option in listed:
        entry = table.get(option)
        if entry is None:
            problems.append(f"{command} {option}: no entry in OPTIONS")
        elif entry[0] == "keyword":
            _, function, argument, default = entry
            target = getattr(pc, function, None)
            parameters = inspect.signature(target).parameters if target else {}
            if argument not in parameters:
                problems.append(f"{command} {option}: pneumachaos.{function} has no {argument}")
            elif default is not inspect.Parameter.empty and \
                    parameters[argument].default != default:
                problems.append(f"{command} {option}: {function}({argument}=) defaults to "
                                f"{parameters[argument].default!r}, the command line to "
                                f"{default!r}")
        elif entry[0] == "api":
            target = pc
            for part in entry[1].split("."):
                target = getattr(target, part, None)
            if target is None:
                problems.append(f"{command} {option}: pneumachaos.{entry[1]} does not exist")
        elif not entry[1]:
            problems.append(f"{command} {option}: plumbing without a reason")
    return problems


@needs_cli
def test_every_subcommand_is_in_the_table():
    assert sorted(cli_commands()) == sorted(OPTIONS)


@needs_cli
@pytest.mark.parametrize("command", sorted(OPTIONS))
def test_every_option_has_a_python_counterpart(command):
    listed = cli_options(command)
    assert "-h,--help" in listed  # the help was read
    assert missing_counterparts(command, listed) == []
    # An entry for an option the command no longer has is stale.
    assert sorted(set(OPTIONS[command]) - set(listed)) == []


@needs_cli
def test_a_new_option_without_an_entry_fails():
    """The check itself can fail: an option the table does not know is reported."""
    problems = missing_counterparts("simulate", cli_options("simulate") + ["--brand-new"])
    assert problems == ["simulate --brand-new: no entry in OPTIONS"]
