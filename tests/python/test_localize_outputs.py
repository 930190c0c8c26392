"""The outputs of set-inversion localization and estimation: the Python
binding's outlier fields (agreed outliers and inliers, outlier sets, q_lower, safety),
OUT/summary.json written by `gesmi localize` (data numbered from 1 as in the scenario
file) and by `gesmi estimate` on seed 004's Example 2, checked against a grid."""
import json
import os

import numpy as np
import pytest

import gesmi
from conftest import run_gesmi
from seed004_example2 import EXAMPLE2, grid_sets

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WAREHOUSE = os.path.join(ROOT, "missions", "localization", "warehouse_p04_outliers.yaml")
# The bearings given outlier values when the scenario was simulated
# (`--bearing-outliers 3,8`, its description): every datum is a bearing.
INJECTED = [3, 8]


@pytest.fixture(scope="module")
def warehouse():
    return gesmi.localize(WAREHOUSE, safety=True)


def test_binding_names_the_injected_outliers_and_proves_fewer_impossible(warehouse):
    r = warehouse
    assert r["found"]
    assert r["q"] == 2 and r["q_lower"] == 2  # q* = 2: no pose fits with 0 or 1 outlier
    assert len(r["hypotheses"]) == 1
    h = r["hypotheses"][0]
    assert h["agreed_outliers"] == INJECTED
    assert h["agreed_inliers"] == [i for i in range(13) if i not in INJECTED]
    assert h["outlier_sets"] == [INJECTED] and h["outlier_sets_complete"]
    assert h["outliers_determined"]
    assert [s["outliers"] for s in r["outlier_sets"]] == [INJECTED]


def test_binding_safety_is_one_interval_in_0_1_per_datum(warehouse):
    safety = np.array(warehouse["safety"])
    assert safety.shape == (13, 2)
    assert np.all(safety[:, 0] >= 0) and np.all(safety[:, 1] <= 1) and np.all(safety[:, 0] <= safety[:, 1])


def test_summary_json_numbers_data_from_1_as_in_the_file(tmp_path, warehouse):
    out = str(tmp_path / "w")
    r = run_gesmi("localize", WAREHOUSE, "-o", out, "--safety", "--quiet")
    assert r.returncode == 0, r.stderr
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    assert s["q"] == 2 and s["q_lower"] == 2
    h = s["hypotheses"][0]
    assert h["outliers"] == [i + 1 for i in INJECTED]
    assert h["agreed_inliers"] == [i + 1 for i in warehouse["hypotheses"][0]["agreed_inliers"]]
    assert h["outlier_sets"] == [[i + 1 for i in INJECTED]]
    assert [d["datum"] for d in s["safety"]] == list(range(1, 14))
    lo = [d["safety"][0] for d in s["safety"]]
    assert np.allclose(lo, np.array(warehouse["safety"])[:, 0])


def test_estimate_example2_proves_the_sets_of_the_grid(tmp_path):
    out = str(tmp_path / "e")
    r = run_gesmi("estimate", EXAMPLE2, "-o", out, "--quiet")
    assert r.returncode == 0, r.stderr
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    proved = {}
    for h in s["hypotheses"]:
        assert len(h["outliers"]) == h["q"]
        if h["proved"]:
            proved.setdefault(h["q"], set()).add(tuple(h["outliers"]))
    assert proved == grid_sets()
    assert [level["q"] for level in s["levels"]] == list(range(7))


def test_summary_json_marks_the_no_echo_of_the_doorway(tmp_path):
    # The doorway scenario's second measurement reads `range: none`; the others are echoes.
    doorway = os.path.join(ROOT, "missions", "localization", "no_echo_doorway.yaml")
    with open(doorway) as f:
        lines = [line for line in f if line.startswith("  - {sensor:")]
    expected = [("range: none" in line) for line in lines]
    out = str(tmp_path / "d")
    r = run_gesmi("localize", doorway, "-o", out, "--quiet")
    assert r.returncode == 0, r.stderr
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    assert [d["no_echo"] for d in s["data"]] == expected
    assert expected.count(True) == 1
    assert len(s["hypotheses"]) == 1 and s["hypotheses"][0]["holds_truth"]
