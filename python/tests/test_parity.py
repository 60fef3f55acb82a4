"""The module at parity with the command line: the same numbers from the same record and
seed, and bad arguments refused by name at the call (docs/python.md)."""

import json
import os
import subprocess

import numpy as np
import pytest

import pneumachaos as pc

CLI = os.environ.get("PNEUMACHAOS_CLI", "")
REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SIMPLE_RIG = os.path.join(REPO, "docs", "variants", "simple_rig.toml")


def numbers(tree, path=""):
    """Every number and word of a JSON tree by its path, for a field-by-field comparison."""
    if isinstance(tree, dict):
        out = {}
        for key, value in tree.items():
            out.update(numbers(value, f"{path}/{key}"))
        return out
    if isinstance(tree, list):
        out = {}
        for i, value in enumerate(tree):
            out.update(numbers(value, f"{path}/{i}"))
        return out
    return {path: tree}


@pytest.mark.skipif(not CLI, reason="PNEUMACHAOS_CLI names the command line (set by CTest)")
def test_analyze_gives_the_command_lines_verdict_and_numbers(tmp_path):
    """Both run their defaults (39 surrogates, 5 verdict seeds, Wolf) on the same samples and
    seed: every field of the JSON is equal but the ones that name the input."""
    v = pc.simulate(duration_s=3.0).v[1000:]
    record = tmp_path / "v.csv"
    np.savetxt(record, v, fmt="%.17g", header="v", comments="")
    out = tmp_path / "cli.json"
    subprocess.run([CLI, "analyze", str(record), "--rate", "1000", "--seed", "3", "--json",
                    str(out)], check=True, capture_output=True)
    cli = json.loads(out.read_text())
    py = pc.analyze(v, 1000.0, seed=3)
    assert py["surrogate"]["count"] == cli["surrogate"]["count"] == 39
    assert py.verdict == cli["verdict"]
    naming = {"/source", "/series/name"}  # the file and column vs "<array>" and "x"
    a = {k: x for k, x in numbers(cli).items() if k not in naming}
    b = {k: x for k, x in numbers(py.json).items() if k not in naming}
    assert a == b


def test_a_path_given_to_scenario_is_refused_naming_from_toml():
    with pytest.raises(ValueError, match=r"Scenario\.from_toml\(path\)"):
        pc.Scenario("my_rig.toml")
    with pytest.raises(ValueError, match=r"Scenario\.from_toml"):
        pc.Scenario(3)


def test_scenario_without_an_argument_is_the_default():
    assert pc.Scenario().to_toml() == pc.Scenario.default().to_toml()
    assert pc.Scenario(None).to_toml() == pc.Scenario.default().to_toml()
    assert "Scenario.from_toml" in pc.Scenario.__init__.__doc__


def test_a_string_where_a_list_is_expected_is_refused_naming_the_argument(tmp_path):
    with pytest.raises(ValueError, match=r"^grid: expected a list of strings"):
        pc.stability_map(grid="circuit.S1_mm2=1:2:1")
    with pytest.raises(ValueError, match=r"^grid: expected a list of strings"):
        pc.sweep(grid="circuit.S1_mm2=1:2:1", out=str(tmp_path / "map"))
    t = np.arange(200) * 1e-3
    with pytest.raises(ValueError, match=r"^free: expected a list of strings"):
        pc.fit(t, t, t + 2e5, t + 2e5, free="circuit.S1_mm2")
    with pytest.raises(ValueError, match=r"^models: expected a list of strings"):
        pc.friction(t, t, t + 2e5, t + 2e5, models="classic")
    assert not (tmp_path / "map").exists()


def test_friction_takes_lists_like_analyze():
    rig = pc.Scenario.from_toml(SIMPLE_RIG).set("circuit.S2_mm2", 0.2)
    run = pc.simulate(rig, duration_s=3.0)
    arrays = pc.friction(run.t, run.v, run.P1, run.P2, rig, models=["classic"])
    lists = pc.friction(list(run.t), list(run.v), list(run.P1), list(run.P2), rig,
                        models=["classic"])
    assert lists == arrays


def test_an_empty_array_is_refused_naming_the_argument():
    with pytest.raises(ValueError, match=r"^x: the array is empty"):
        pc.analyze([], 1000.0)
    t = np.arange(200) * 1e-3
    with pytest.raises(ValueError, match=r"^P2: the array is empty"):
        pc.friction(t, t, t, np.array([]))


def test_a_complex_array_is_refused():
    x = np.exp(1j * np.linspace(0, 100, 2000))
    with pytest.raises(ValueError, match=r"^x: expected real numbers, got a complex array"):
        pc.analyze(x, 1000.0)


def test_results_behave_as_mappings():
    r = pc.analyze(np.sin(np.linspace(0, 200, 2000)), 100.0, surrogates=0, wolf=False)
    assert "verdict" in r and "nonsense" not in r
    assert list(r.keys()) == list(r.json.keys())
    assert dict(r.items()) == r.json
    assert json.loads(r.to_json()) == r.json
    sim = pc.simulate(duration_s=0.05)
    assert "v" in sim and list(sim.keys()) == sim.channels
    assert np.array_equal(dict(sim.items())["P1"], sim.P1)
    assert json.loads(sim.to_json())["v"] == sim.v.tolist()


def test_the_module_namespace_holds_only_its_api():
    public = {name for name in dir(pc) if not name.startswith("_")}
    assert public == set(pc.__all__)
    for name in ("io", "np", "os", "sys", "json", "time"):
        assert not hasattr(pc, name), name


def test_pressures_in_kpa_are_refused_as_on_the_command_line():
    """Arrays are SI with absolute pressures; kPa values read as Pa are refused, not fitted."""
    rig = pc.Scenario.from_toml(SIMPLE_RIG).set("circuit.S2_mm2", 0.2)
    run = pc.simulate(rig, duration_s=1.0)
    with pytest.raises(ValueError, match=r"column P1, sample 1: .*look like gauge values or kPa"):
        pc.friction(run.t, run.v, run.P1 / 1000, run.P2 / 1000, rig)


def test_friction_and_fit_take_the_command_lines_options():
    """--window and --max-iterations of friction, --segment, --pressure-scale,
    --velocity-scale and --max-iterations of fit: reachable, checked by name."""
    rig = pc.Scenario.from_toml(SIMPLE_RIG).set("circuit.S2_mm2", 0.2)
    run = pc.simulate(rig, duration_s=3.0)
    args = (run.t, run.v, run.P1, run.P2, rig)
    f = pc.friction(*args, models=["classic"], window=7)
    assert f["fits"]["classic"]["Fc_N"]["value"] > 0
    with pytest.raises(ValueError, match=r"^window: expected an odd number of samples >= 3, got 4"):
        pc.friction(*args, window=4)
    with pytest.raises(RuntimeError, match="did not converge"):
        pc.friction(*args, models=["lugre"], max_iterations=1)
    with pytest.raises(ValueError, match=r"^segment_s: expected a number > 0"):
        pc.fit(*args, free=["circuit.S2_mm2"], segment_s=0)
    r = pc.fit(*args, free=["circuit.S2_mm2"], segment_s=0.5, velocity_scale_mm_per_s=20.0)
    assert r["parameters"]["circuit.S2_mm2"]["value"] == pytest.approx(0.2, rel=0.05)
