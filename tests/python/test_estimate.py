"""gesmi.estimate (tools/python/bind_estimate.cpp) on seed 004's Example 2. Expected
values come from the model: the outlier sets that a brute-force grid established
(docs/setinversion.md, section 5), and phi written again in numpy
(seed004_example2.py), never from the program's own output."""
import json
import os

import numpy as np
import pytest

import gesmi
from conftest import run_gesmi
from seed004_example2 import EXAMPLE2, FRAME, SECTION5, grid, grid_sets, members, phi_codes


@pytest.fixture(scope="module")
def example2():
    return gesmi.estimate(EXAMPLE2)


def proved_sets(result):
    proved = {}
    for h in result["hypotheses"]:
        if h["proved"]:
            proved.setdefault(h["q"], set()).add(tuple(h["outliers"]))
    return proved


def code_of(outliers):
    return sum(1 << (d - 1) for d in outliers)


def inside(boxes, p1, p2):
    """Which of the points (1-D arrays) lie in some box of a (B, 2, 2) array."""
    hit = np.zeros(np.shape(p1), dtype=bool)
    for start in range(0, len(boxes), 1024):
        b = boxes[start:start + 1024, :, :, None]
        hit |= ((b[:, 0, 0] <= p1) & (p1 <= b[:, 0, 1]) & (b[:, 1, 0] <= p2) & (p2 <= b[:, 1, 1])).any(axis=0)
    return hit


def test_proves_exactly_the_sets_of_section_5_numbered_as_in_the_file(example2):
    assert SECTION5 == {q: s for q, s in grid_sets().items() if s}  # the grid still says so
    assert proved_sets(example2) == SECTION5
    assert [level["q"] for level in example2["levels"]] == list(range(7))
    assert [level["proved_nonempty"] for level in example2["levels"]] == [q in SECTION5 for q in range(7)]
    assert example2["q_star"] == 1  # seed 004's conclusion: one outlier, datum 5
    for h in example2["hypotheses"]:
        assert len(h["outliers"]) == h["q"] and all(1 <= d <= 6 for d in h["outliers"])


def test_inner_boxes_hold_only_their_set_and_the_boxes_enclose_the_grid(example2):
    p1, p2, codes = grid(301, 300)
    for h in example2["hypotheses"]:
        mine = codes == code_of(h["outliers"])
        # Every grid point whose phi is this set lies in the set's boxes.
        assert np.all(inside(np.concatenate([h["inner"], h["boundary"]]), p1[mine], p2[mine])), h["outliers"]
        # Points sampled in the inner boxes (corners and centre) all have exactly this phi.
        b, f = h["inner"], np.array([0.0, 0.5, 1.0])
        xs = (b[:, 0, 0, None] + (b[:, 0, 1] - b[:, 0, 0])[:, None] * f)[:, :, None]
        ys = (b[:, 1, 0, None] + (b[:, 1, 1] - b[:, 1, 0])[:, None] * f)[:, None, :]
        assert np.all(phi_codes(xs, ys) == code_of(h["outliers"])), h["outliers"]
        (lo1, hi1), (lo2, hi2) = h["hull"]
        if mine.any():
            assert lo1 <= p1[mine].min() and p1[mine].max() <= hi1 and lo2 <= p2[mine].min() and p2[mine].max() <= hi2
        assert FRAME[0][0] <= lo1 <= hi1 <= FRAME[0][1] and FRAME[1][0] <= lo2 <= hi2 <= FRAME[1][1]
        assert 0 <= h["inner_volume"] <= h["outer_volume"]
        assert h["inner"].shape[1:] == (2, 2) and h["boundary"].shape[1:] == (2, 2)


def test_area_of_datum_5s_set_is_bracketed_by_inner_and_outer_volumes(example2):
    # The grid's area of P_{5} (points at cell centres of a 2000 x 2000 grid).
    n = 2000
    c1 = FRAME[0][0] + (np.arange(n) + 0.5) * (FRAME[0][1] - FRAME[0][0]) / n
    c2 = FRAME[1][0] + (np.arange(n) + 0.5) * (FRAME[1][1] - FRAME[1][0]) / n
    p1, p2 = np.meshgrid(c1, c2, indexing="ij")
    area = np.count_nonzero(phi_codes(p1, p2) == code_of([5])) * 10.0 * 3.0 / n ** 2
    (h,) = [h for h in example2["hypotheses"] if h["outliers"] == [5]]
    assert h["inner_volume"] < area < h["outer_volume"]


def test_matches_the_commands_summary_json(example2, tmp_path):
    out = str(tmp_path / "e")
    r = run_gesmi("estimate", EXAMPLE2, "-o", out, "--quiet")
    assert r.returncode == 0, r.stderr
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    assert [h["outliers"] for h in s["hypotheses"]] == [h["outliers"] for h in example2["hypotheses"]]
    assert [h["inner_boxes"] for h in s["hypotheses"]] == [len(h["inner"]) for h in example2["hypotheses"]]
    assert s["q_star"] == example2["q_star"]
    assert not example2["box_limit_hit"] and not example2["time_limit_hit"]
    assert example2["boxes_examined"] == sum(level["boxes_examined"] for level in example2["levels"])


def scenario_with_solver(tmp_path, solver):
    with open(EXAMPLE2) as f:
        text = f.read()
    assert "solver: {epsilon: 0.005}" in text
    path = tmp_path / "scenario.yaml"
    path.write_text(text.replace("solver: {epsilon: 0.005}", solver))
    return str(path)


def test_a_box_limit_is_reported_and_every_level_still_encloses_its_sets(tmp_path):
    r = gesmi.estimate(scenario_with_solver(tmp_path, "solver: {epsilon: 0.005, max_boxes: 2000}"))
    assert r["box_limit_hit"] and not r["time_limit_hit"]
    assert r["levels"][-1]["box_limit_hit"]
    p1, p2, codes = grid(201, 200)
    for level in r["levels"]:
        q = level["q"]
        sets = [h for h in r["hypotheses"] if h["q"] == q]
        for code in np.unique(codes):
            if len(members(code)) != q:
                continue
            boxes = [np.concatenate([h["inner"], h["boundary"]]) for h in sets if tuple(h["outliers"]) == members(code)]
            boxes.append(level["unresolved"])
            points = codes == code
            assert np.all(inside(np.concatenate(boxes), p1[points], p2[points])), (q, members(code))


def test_bad_scenario_raises_format_error_with_the_commands_line(tmp_path):
    path = scenario_with_solver(tmp_path, "solver: {epsilon: 1e-17}")
    with pytest.raises(gesmi.FormatError) as e:
        gesmi.estimate(path)
    message = str(e.value)
    assert message.startswith(path + ":") and "solver.epsilon: 1e-17 is finer than doubles can split" in message
    # Twice the spacing of doubles at the prior's largest magnitude, 8.
    assert float(message.rsplit("at least ", 1)[1]) == 2 * np.spacing(8.0)
    r = run_gesmi("estimate", path, "-o", str(tmp_path / "out"))
    assert r.returncode == 2 and r.stderr.strip() == "gesmi estimate: " + message
