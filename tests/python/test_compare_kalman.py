"""tools/compare_kalman.py against the files: every containment figure of its --json
report recomputed here with numpy from the mission, result and Kalman files; the plane
judgement of a mine agreeing with the ellipse mines.png draws (a mine inside its ellipse
but outside per-axis 3σ is inside); an inconsistent interval result refused (exit 3) or,
with --show-inconsistent, reported by its diagnosis with no interval numbers; a Kalman
file without the consistency tests reported as "not recorded"."""
import importlib.util
import json
import math
import os
import re
import shutil
import subprocess
import sys

import h5py
import numpy as np
import pytest

from conftest import run_gesmi

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
COMPARE = os.path.join(TOOLS, "compare_kalman.py")
P = 0.9973


def chi2_quantile(p, dof):
    """Independent of the tool: the chi-square CDF integrated numerically from its density."""
    x = np.linspace(0.0, 60.0, 600001)
    density = x ** (dof / 2 - 1) * np.exp(-x / 2) / (2 ** (dof / 2) * math.gamma(dof / 2))
    cdf = np.concatenate([[0.0], np.cumsum((density[1:] + density[:-1]) / 2 * np.diff(x))])
    return float(np.interp(p, cdf, x))


Q2, Q3 = chi2_quantile(P, 2), chi2_quantile(P, 3)


def load_tool():
    spec = importlib.util.spec_from_file_location("compare_kalman", COMPARE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def compare(mission, result, kalman, out, *extra):
    json_path = os.path.join(out, "report.json")
    r = subprocess.run([sys.executable, COMPARE, mission, result, kalman, "-o", out, "--json", json_path, *extra],
                       capture_output=True, text=True)
    report = None
    if r.returncode == 0:
        with open(json_path) as f:
            report = json.load(f)
    return r, report


def h5(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: out.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset) else None)
        out["@"] = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()}
    return out


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("compare")
    m, r, k = str(d / "m.h5"), str(d / "r.h5"), str(d / "k.h5")
    assert run_gesmi("simulate", "--seed", "6", "--duration", "1200", "--errors", "worst-case", "-o", m).returncode == 0
    assert run_gesmi("solve", m, "-o", r).returncode == 0
    assert run_gesmi("kalman", m, "-o", k).returncode == 0
    return d, m, r, k


def test_every_containment_figure_recomputed_from_the_files(files):
    d, m, r, k = files
    proc, report = compare(m, r, k, str(d / "report"))
    assert proc.returncode == 0, proc.stderr
    mission, result, kalman = h5(m), h5(r), h5(k)
    truth, lo, hi = mission["truth/position"], result["tube/lower"], result["tube/upper"]
    mean, cov = kalman["kalman/mean"], kalman["kalman/cov"].reshape(-1, 3, 3)
    sigma = np.sqrt(np.einsum("kii->ki", cov))
    for part, axes in [("horizontal", [0, 1]), ("vertical", [2])]:
        itv, kal = report["interval"]["trajectory"][part], report["kalman"]["trajectory"][part]
        inside = np.all((lo[:, axes] <= truth[:, axes]) & (truth[:, axes] <= hi[:, axes]), axis=1)
        assert itv["truth_inside"] == pytest.approx(inside.mean(), abs=1e-12)
        in3 = np.all(np.abs(truth[:, axes] - mean[:, axes]) <= 3 * sigma[:, axes], axis=1)
        assert kal["truth_inside_3sigma"] == pytest.approx(in3.mean(), abs=1e-12)
        tube = np.all((lo[:, axes] <= mean[:, axes]) & (mean[:, axes] <= hi[:, axes]), axis=1)
        assert kal["mean_in_tube"] == pytest.approx(tube.mean(), abs=1e-12)
        err = np.sqrt(np.sum((truth[:, axes] - mean[:, axes]) ** 2, axis=1))
        assert kal["error_max"] == pytest.approx(err.max()) and kal["error_mean"] == pytest.approx(err.mean())
        centre = np.sqrt(np.sum((truth[:, axes] - (lo[:, axes] + hi[:, axes]) / 2) ** 2, axis=1))
        assert itv["centre_error_max"] == pytest.approx(centre.max())
        width = np.max(hi[:, axes] - lo[:, axes], axis=1)
        assert itv["width_max"] == pytest.approx(width.max()) and itv["width_mean"] == pytest.approx(width.mean())
        assert kal["width_6sigma_mean"] == pytest.approx(np.mean(6 * np.max(sigma[:, axes], axis=1)))
    # Worst-case biases: the truth stays in the tube, and the per-axis 3σ corridor misses it.
    assert report["interval"]["trajectory"]["horizontal"]["truth_inside"] == 1.0
    assert report["kalman"]["trajectory"]["horizontal"]["truth_inside_3sigma"] < 0.5

    tm, mlo, mhi = mission["truth/mines"], result["mines/lower"], result["mines/upper"]
    mm, mc = kalman["kalman/mines/mean"], kalman["kalman/mines/cov"].reshape(-1, 3, 3)
    judged = 0
    for i in range(len(tm)):
        box, km = report["interval"]["mines"][i], report["kalman"]["mines"][i]
        inside = (mlo[i] <= tm[i]) & (tm[i] <= mhi[i])
        assert box["truth_inside_3d"] == bool(inside.all()) and box["truth_inside_plane"] == bool(inside[:2].all())
        assert box["bounded"] == bool(np.isfinite(mlo[i]).all() and np.isfinite(mhi[i]).all())
        if not np.isfinite(mm[i]).all():
            assert not km["finite"]
            continue
        e = tm[i] - mm[i]
        d3 = e @ np.linalg.inv(mc[i]) @ e
        d2 = e[:2] @ np.linalg.inv(mc[i][:2, :2]) @ e[:2]
        assert km["mahalanobis2_3d"] == pytest.approx(d3, rel=1e-9)
        assert km["mahalanobis2_plane"] == pytest.approx(d2, rel=1e-9)
        assert km["inside_3d"] == bool(d3 <= Q3) and km["inside_plane"] == bool(d2 <= Q2)
        assert km["inside_per_axis_3sigma"] == bool(np.all(np.abs(e) <= 3 * np.sqrt(np.diag(mc[i]))))
        assert km["error_plane"] == pytest.approx(np.hypot(*e[:2]))
        assert km["mean_in_box_plane"] == bool(np.all((mlo[i][:2] <= mm[i][:2]) & (mm[i][:2] <= mhi[i][:2])))
        judged += 1
    assert judged >= 3
    # gesmi kalman's own figures (in its file) follow the same definitions.
    recorded = kalman["@"]
    for part, name in [("horizontal", "containment_3sigma_horizontal"), ("vertical", "containment_3sigma_vertical")]:
        assert recorded[name] == pytest.approx(report["kalman"]["trajectory"][part]["truth_inside_3sigma"], abs=1e-12)
    finite = [km for km in report["kalman"]["mines"] if km["finite"]]
    assert recorded["containment_mines"] == pytest.approx(np.mean([km["inside_3d"] for km in finite]))
    assert recorded["containment_mines_plane"] == pytest.approx(np.mean([km["inside_plane"] for km in finite]))
    assert report["chi2_quantile_plane"] == pytest.approx(Q2, rel=1e-5)
    assert report["chi2_quantile_3d"] == pytest.approx(Q3, rel=1e-5)
    # The file's timing parts, summed as labelled.
    assert report["timing"]["interval_parts_sum_ms"] == pytest.approx(
        sum(v for key, v in result["@"].items() if key.startswith("timing_") and key.endswith("_ms")))
    text = (d / "report" / "report.md").read_text()
    assert "| trajectory (horizontal) |" in text and "| trajectory (vertical) |" in text
    for name in ("track.png", "mines.png", "widths.png"):
        assert (d / "report" / name).stat().st_size > 0


def test_the_consistency_tests_as_recorded_or_not_recorded(files):
    d, m, r, k = files
    _, report = compare(m, r, k, str(d / "report_tests"))
    kalman = h5(k)
    if "kalman/tests/flagged" not in kalman:  # an older file
        assert report["kalman"]["chi2"] is None and report["kalman"]["flagged"] is None
        assert "not recorded" in (d / "report_tests" / "report.md").read_text()
        return
    flagged = [["fix" if kind == 0 else "mark", int(row)] for kind, row, f in
               zip(kalman["kalman/tests/kind"], kalman["kalman/tests/row"], kalman["kalman/tests/flagged"]) if f]
    assert report["kalman"]["flagged"] == flagged
    assert report["kalman"]["chi2"]["chi2"] == pytest.approx(kalman["@"]["chi2"])
    assert report["kalman"]["chi2"]["consistent"] == bool(kalman["@"]["chi2_consistent"])


def test_bias_estimates_are_reported_when_the_smoother_has_them(files):
    d, m, r, _ = files
    if "--biases" not in run_gesmi("kalman", "--help").stdout:
        pytest.skip("this gesmi kalman has no --biases yet")
    kb = str(d / "kb.h5")
    assert run_gesmi("kalman", m, "-o", kb, "--biases").returncode == 0
    proc, report = compare(m, r, kb, str(d / "report_biases"))
    assert proc.returncode == 0, proc.stderr
    kalman = h5(kb)
    assert report["kalman"]["biases"] is True
    estimates = report["kalman"]["bias_estimates"]
    assert [b["name"] for b in estimates] == kalman["@"]["bias_names"].split(",")
    assert [b["estimate"] for b in estimates] == pytest.approx(list(kalman["kalman/biases/estimate"]))


def test_a_mine_inside_its_drawn_ellipse_is_inside_even_outside_per_axis_3_sigma(files):
    d, m, r, k = files
    tool = load_tool()
    # Synthetic: σ = (1, 2, 0.5) m, the truth 3.2σ north of the mean: outside the per-axis
    # 3σ box, inside the 99.73 % ellipse of the plane (d = 3.2 <= 3.44) and the 3-D region.
    cov = np.diag([1.0, 4.0, 0.25])
    verdict = tool.judge_mine([3.2, 0.0, 0.0], [0.0, 0.0, 0.0], cov)
    assert verdict["inside_plane"] and verdict["inside_3d"] and not verdict["inside_per_axis_3sigma"]
    assert tool.judge_mine([3.5, 0.0, 0.0], [0.0, 0.0, 0.0], cov)["inside_plane"] is False  # d = 3.5 > 3.44
    north, east = tool.ellipse_points(np.zeros(2), cov[:2, :2], Q2)
    assert np.max(north) == pytest.approx(math.sqrt(Q2), rel=1e-4)  # the drawn ellipse reaches 3.44σ north
    # The same through the files: mine 0's Kalman estimate moved so that the truth sits
    # there, the report must say inside in the plane.
    k2 = str(d / "k_moved.h5")
    shutil.copy(k, k2)
    with h5py.File(m, "r") as f:
        truth = f["truth/mines"][0]
    with h5py.File(k2, "r+") as f:
        f["kalman/mines/cov"][0] = cov
        f["kalman/mines/mean"][0] = truth - np.array([3.2, 0.0, 0.0])
    proc, report = compare(m, r, k2, str(d / "report_moved"))
    assert proc.returncode == 0, proc.stderr
    mine = report["kalman"]["mines"][0]
    assert mine["inside_plane"] and mine["inside_3d"] and not mine["inside_per_axis_3sigma"]
    assert mine["mahalanobis2_plane"] == pytest.approx(3.2 ** 2)
    from matplotlib.path import Path
    n, e = tool.ellipse_points(truth[:2] - [3.2, 0.0], cov[:2, :2], Q2)
    assert Path(np.column_stack([n, e])).contains_point(truth[:2])


@pytest.fixture(scope="module")
def inconsistent(tmp_path_factory):
    d = tmp_path_factory.mktemp("inconsistent")
    m, r, k = str(d / "m.h5"), str(d / "r.h5"), str(d / "k.h5")
    assert run_gesmi("simulate", "--seed", "9", "--outliers", "1", "--duration", "2400", "-o", m).returncode == 0
    solve = run_gesmi("solve", m, "-o", r)
    assert solve.returncode == 3, solve.stderr
    assert run_gesmi("kalman", m, "-o", k).returncode == 0
    return d, m, r, k


def test_an_inconsistent_result_is_refused_then_shown_as_such(inconsistent):
    d, m, r, k = inconsistent
    out = str(d / "report")
    proc, _ = compare(m, r, k, out)
    assert proc.returncode == 3
    assert len(proc.stderr.strip().splitlines()) == 1 and "--show-inconsistent" in proc.stderr
    assert not os.path.exists(out)
    proc, report = compare(m, r, k, out, "--show-inconsistent")
    assert proc.returncode == 0, proc.stderr
    with h5py.File(r, "r") as f:
        diagnosis = f.attrs["inconsistency"].decode()
    assert diagnosis
    assert report["interval"]["status"] == "inconsistent" and report["interval"]["inconsistency"] == diagnosis
    assert report["interval"]["trajectory"] is None and report["interval"]["mines"] is None
    assert report["kalman"]["trajectory"]["horizontal"]["mean_in_tube"] is None  # no tube to be inside
    text = (d / "report" / "report.md").read_text()
    assert "INCONSISTENT" in text
    assert f"| interval result | inconsistent (exit 3): {diagnosis} |" in text
    for line in text.splitlines():
        if line.startswith("| trajectory (") or line.startswith("| mine "):
            assert line.split(" | ")[1] == "no answer", line
    # The marks the diagnosis names are listed beside the Kalman's verdict and the truth.
    with h5py.File(m, "r") as f:
        corrupted = [int(j) for j in np.nonzero(f["truth/marks_outlier"][()])[0]]
    assert report["truth_outliers"] == [["mark", j] for j in corrupted]
    assert report["interval"]["named"] == [["mark", j] for j in corrupted]  # seed 9: the diagnosis names it
    for kind, row in report["interval"]["named"]:
        assert re.search(rf"^\| {kind} {row}( \(mine \d+\))? \|.*\| removing it restores consistency \|", text, re.M)


def test_bad_input_exits_2_with_one_line(files, tmp_path):
    d, m, r, k = files
    proc, _ = compare(m, str(tmp_path / "none.h5"), k, str(tmp_path / "out"))
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1
    proc, _ = compare(m, k, r, str(tmp_path / "out"))  # the files swapped
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1
