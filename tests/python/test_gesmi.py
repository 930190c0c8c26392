"""The gesmi Python module against the gesmi command: the same result files bit for
bit, the same one-line errors, and an operator loop (add a mark, warm solve)."""
import math
import os

import h5py
import numpy as np
import pytest

import gesmi
from conftest import run_gesmi


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: out.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset) else None)
        # Timings and how the file was made (command line, creation time) differ by run.
        attrs = {k: v for k, v in f.attrs.items()
                 if not k.startswith("timing_") and k not in ("command_line", "created_utc", "history")}
    return out, attrs


def test_a_solve_from_python_equals_the_command_bit_for_bit(mission_file, tmp_path):
    cli = str(tmp_path / "cli.h5")
    assert run_gesmi("solve", mission_file, "-o", cli).returncode == 0
    m = gesmi.read_mission(mission_file)
    s = gesmi.solve(m)
    py = str(tmp_path / "py.h5")
    written = gesmi.write_result(s, m, py, "m.h5")
    assert written == [py]
    everything = gesmi.write_result(s, m, str(tmp_path / "all.h5"), "m.h5", png=True, geojson=True, mines_csv=True)
    assert [os.path.basename(p) for p in everything] == ["all.h5", "all.mines.csv", "all.geojson", "all.envelope.png"]
    assert all(os.path.getsize(p) > 0 for p in everything)
    a, a_attrs = datasets(cli)
    b, b_attrs = datasets(py)
    assert a.keys() == b.keys()
    for name in a:
        assert a[name].dtype == b[name].dtype, name
        assert a[name].tobytes() == b[name].tobytes(), name  # NaN-safe, bit for bit
    assert a_attrs.keys() == b_attrs.keys()
    for key in a_attrs:
        assert a_attrs[key] == b_attrs[key], key


def test_bad_input_raises_a_value_error_with_the_commands_message(tmp_path):
    missing = str(tmp_path / "none.h5")
    r = run_gesmi("solve", missing, "-o", str(tmp_path / "r.h5"))
    assert r.returncode == 2
    with pytest.raises(gesmi.FormatError) as error:
        gesmi.read_mission(missing)
    assert isinstance(error.value, ValueError)
    assert r.stderr.strip() == "gesmi solve: " + str(error.value)
    assert "\n" not in str(error.value)


def test_the_arrays_are_numpy_views_and_the_model_a_mapping(mission_file):
    m = gesmi.read_mission(mission_file)
    assert np.shares_memory(m.time, m.time)  # both views of the same C++ array
    assert m.time.shape == (len(m),)
    assert m.model["heading"] == pytest.approx(5.27e-3)
    assert "sonar_side" in m.model and m.model["sonar_side"] == "starboard"
    assert len(dict(m.model.items())) == len(m.model)
    with pytest.raises(gesmi.FormatError):
        m.model["heading"] = -1.0  # refused, as in a YAML file
    with pytest.raises(KeyError):
        m.model["speed_of_sound"]
    s = gesmi.solve(m)
    north = s.north
    assert north.shape == (len(m), 2) and np.shares_memory(north, s.north)
    assert np.all(north[:, 0] <= north[:, 1])
    truth = np.stack([m.truth_x, m.truth_y, m.truth_z], axis=1)
    for axis, tube in enumerate((s.north, s.east, s.down)):
        assert np.all((tube[:, 0] <= truth[:, axis]) & (truth[:, axis] <= tube[:, 1]))
    assert s.mines.shape == (m.mine_count, 3, 2)


def test_an_operator_loop_adds_a_mark_and_reruns_warm(mission_file, tmp_path):
    m = gesmi.read_mission(mission_file)
    first = gesmi.solve(m)
    assert first.consistent
    # A missed detection, as the operator would mark it: the simulator's truth knows it.
    with h5py.File(mission_file, "r") as f:
        missed = f["/truth/missed_marks"][()]
    assert len(missed) > 0
    time, mine, true_range = missed[0]
    with pytest.raises(gesmi.FormatError):
        m.add_mark(time=1e9, range=true_range)  # outside the mission: refused, table unchanged
    rows = m.mark_count()
    m.add_mark(time=time, range=true_range, mine=int(mine))
    assert m.mark_count() == rows + 1
    warm = gesmi.solve(m, warm_from=first)
    assert warm.report["mode"] == "warm" and warm.consistent
    cold = gesmi.solve(m)
    # Constraints only remove solutions: the warm rerun is inside the first solve and
    # agrees with a cold solve within the solver's tolerance.
    assert np.all(warm.north[:, 0] >= first.north[:, 0]) and np.all(warm.north[:, 1] <= first.north[:, 1])
    assert np.max(np.abs(warm.north - cold.north)) < 1e-3
    # The same rerun from the file the command writes.
    path = str(tmp_path / "first.h5")
    gesmi.write_result(first, gesmi.read_mission(mission_file), path)
    from_file = gesmi.read_warm_start(path, m)
    assert gesmi.solve(m, warm_from=from_file).report["mode"] == "warm"


def test_outliers_diagnosis_kalman_and_localize(tmp_path):
    m = gesmi.simulate(seed=31, duration=3000, outliers=1)
    s = gesmi.solve(m)
    assert not s.consistent
    assert s.report["explained_by"], s.report["message"]
    assert s.report["inconsistency"]["kind"] in ("evolution", "fix", "detection")
    tolerant = gesmi.solve(m, max_outliers=1, trust_gps=True)
    assert tolerant.consistent and tolerant.report["minimal_outliers"] == 1
    assert tolerant.report["mode"] == "outliers"
    conditional = gesmi.solve(m, minimal_outliers=1, trust_gps=True)
    assert conditional.report["mode"] == "minimal-outliers"
    k = gesmi.kalman(gesmi.simulate(seed=2, duration=600))
    assert k.mean.shape[1] == 3 and k.covariance.shape[1:] == (3, 3)
    assert all(math.isfinite(x) for x in k.mean[:, 0])


def test_bias_noise_missions():
    m = gesmi.simulate(seed=2, duration=300, errors="bias-noise", bias_share=1.0, drift="flip")
    error = np.asarray(m.depth) - np.asarray(m.truth_z)
    assert len(error) == 3001
    r = m.model["depth_relative"]
    bound = (m.model["depth_absolute"] + r * np.abs(np.asarray(m.truth_z))) / (1 + r)
    assert np.all(np.abs(error) <= 0.99 * bound + 1e-12)
    # A whole bias that flips at the middle: the error is the same affine function of
    # the depth before, and its opposite after.
    z = np.asarray(m.truth_z)
    before, after = np.asarray(m.time) < 150, np.asarray(m.time) >= 150
    fit = np.polyfit(z[before], error[before], 1)
    assert np.allclose(error[after], -np.polyval(fit, z[after]), atol=1e-9)
    with pytest.raises(gesmi.FormatError, match="bias_share and drift go with"):
        gesmi.simulate(duration=300, bias_share=0.5)
    with pytest.raises(gesmi.FormatError, match="drift: expected none, ramp or flip"):
        gesmi.simulate(duration=300, errors="bias-noise", drift="sine")


def test_the_inputs_nothing_else_checks_are_named():
    m = gesmi.simulate(seed=27, duration=1800, outliers=1)
    counts = {}
    for j, mine in enumerate(m.mark_mine):
        counts.setdefault(int(mine), []).append(j)
    single = sorted(mine for mine, rows in counts.items() if len(rows) == 1)
    assert single
    u = gesmi.solve(m).unchecked
    assert u["mines"] == single
    assert u["marks"] == [counts[mine][0] for mine in single]
    assert u["gps_fixes"] == []


def test_kalman_checks_and_biases():
    # The outlier mission's corrupted mark is flagged, with the other mark of the same mine
    # only (two marks of one mine that disagree: leaving either out explains the other);
    # the bias-aware variant reports its nine biases, each sigma within its prior's.
    m = gesmi.simulate(seed=31, duration=3000, outliers=1)
    k = gesmi.kalman(m)
    flagged = [t for t in k.tests if t["flagged"]]
    corrupted = list(m.truth_marks_outlier).index(1)
    assert corrupted in [t["row"] for t in flagged if t["kind"] == "mark"]
    assert {m.mark_mine[t["row"]] for t in flagged if t["kind"] == "mark"} == {m.mark_mine[corrupted]}
    assert all(t["kind"] == "mark" for t in flagged)
    c = k.consistency
    assert c["band_low"] < 1.0 < c["band_high"] and c["dof"] > 0
    assert c["consistent"] == (c["band_low"] <= c["chi2_per_dof"] <= c["band_high"])
    assert not k.biases and k.bias_estimates == []
    b = gesmi.kalman(gesmi.simulate(seed=2, duration=600), biases=True)
    names = [x["name"] for x in b.bias_estimates]
    assert names[0] == "heading" and names[-1] == "depth_offset" and len(names) == 9
    assert all(0.0 < x["sigma"] <= x["prior_sigma"] * (1 + 1e-6) for x in b.bias_estimates)  # (the chain's rounding)


def test_kalman_stops_at_the_rounding_floor():
    # A tolerance of 0 is never met: the passes stop when the steps stall within 1 % of a
    # standard deviation (stalled), or, with stall_fraction=0, at the cap.
    m = gesmi.simulate(seed=2, duration=600)
    k = gesmi.kalman(m, tolerance=0.0)
    assert k.stalled and not k.converged and k.iterations < 20
    assert 0.0 < k.last_step_sigmas <= 0.01
    capped = gesmi.kalman(m, tolerance=0.0, stall_fraction=0.0, max_iterations=6)
    assert not capped.stalled and not capped.converged and capped.iterations == 6
    with pytest.raises(gesmi.FormatError):
        gesmi.kalman(m, stall_fraction=1.0)


def test_kalman_starts_from_a_coarse_chain_or_the_dead_reckoning(tmp_path):
    # Both starts end within the tolerance (1 mm) of each other; the coarse one needs
    # fewer full linearisations here, and the command's file records which was used.
    m = gesmi.simulate(seed=2, duration=1200)
    coarse = gesmi.kalman(m)
    dead_reckoning = gesmi.kalman(m, start="dead-reckoning")
    assert coarse.converged and dead_reckoning.converged
    assert coarse.coarse_iterations > 0 and dead_reckoning.coarse_iterations == 0
    assert coarse.iterations < dead_reckoning.iterations
    assert np.max(np.abs(coarse.mean - dead_reckoning.mean)) <= 1e-3
    with pytest.raises(gesmi.FormatError):
        gesmi.kalman(m, start="truth")
    mission, out = str(tmp_path / "m.h5"), str(tmp_path / "k.h5")
    assert run_gesmi("simulate", "--seed", "2", "--duration", "1200", "-o", mission).returncode == 0
    r = run_gesmi("kalman", mission, "-o", out, "--start", "dead-reckoning")
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        start = f.attrs["start"]  # (a fixed-length string: bytes to h5py)
        assert (start.decode() if isinstance(start, bytes) else start) == "dead-reckoning"
        assert f.attrs["coarse_iterations"] == 0


def test_localize_a_scenario():
    scenario = os.path.join(os.path.dirname(__file__), "..", "..", "missions", "localization", "triangle_two_hypotheses.yaml")
    r = gesmi.localize(scenario)
    assert r["found"]
    assert r["inner"].shape[1:] == (3, 2)
    assert len(r["hypotheses"]) == 2  # the scenario's two symmetric poses
    with pytest.raises(gesmi.FormatError):
        gesmi.localize(scenario + ".missing")
