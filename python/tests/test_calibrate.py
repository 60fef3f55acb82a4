"""pneumachaos.calibrate: the CLI's calibration from Python (docs/guide/calibrate.md)."""

import json
import os

import pytest

import pneumachaos as pc

SPEC = """
[[free]]
key = "friction.Fc_N"
lower = 15
upper = 30
source = "measured for 32-40 mm seals (docs/notes/virtual_rig.md)"

[objective]
kind = "claims"
example = true
example_record_s = 4
claims = { fig7_spectrum = 1, fig7_acf = 2 }

[optimizer]
population = 5
max_evaluations = 10
seed = 2
"""


def test_calibrate_runs_resumes_and_reports(tmp_path):
    spec = tmp_path / "spec.toml"
    spec.write_text(SPEC)
    out = tmp_path / "out"
    r = pc.calibrate(str(spec), str(out), threads=1)
    assert r["evaluations"] == 10
    (best,) = r["best"]["parameters"]
    assert best["key"] == "friction.Fc_N" and 15 <= best["value"] <= 30
    assert [c["id"] for c in r["fitted"]] == ["fig7_acf", "fig7_spectrum"]
    assert [c["weight"] for c in r["fitted"]] == [2, 1]
    assert r["predicted"] == []
    with open(out / "calibration.json") as f:
        assert json.load(f) == r
    lines = (out / "evaluations.csv").read_text().splitlines()
    assert len(lines) == 11 and lines[0].startswith("evaluation,friction.Fc_N,objective")
    # A second call replays the journal: the same result, no new evaluation.
    assert pc.calibrate(str(spec), str(out), threads=2, resume=True) == r
    assert len((out / "journal.csv").read_text().splitlines()) == 11


def test_calibrate_refuses_bad_input(tmp_path):
    spec = tmp_path / "spec.toml"
    spec.write_text(SPEC.replace('source = "measured for 32-40 mm seals (docs/notes/virtual_rig.md)"\n', ""))
    with pytest.raises(ValueError, match=r"spec\.toml:3:7: free\.key \(friction\.Fc_N\): needs source"):
        pc.calibrate(str(spec), str(tmp_path / "out"))
    with pytest.raises(ValueError, match="threads"):
        pc.calibrate(str(spec), str(tmp_path / "out"), threads=-1)
    assert not os.path.exists(tmp_path / "out")
