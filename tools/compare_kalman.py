#!/usr/bin/python3
"""Side-by-side comparison of gesmi's interval result and the Kalman smoother.

usage: tools/compare_kalman.py MISSION.h5 RESULT.h5 KALMAN.h5 -o REPORT_DIR [--json FILE] [--show-inconsistent]

Writes into REPORT_DIR: track.png (the interval envelope against the Kalman ±3σ corridor,
north, east and down), mines.png (mine boxes against the Kalman 99.73 % ellipses in the
plane), widths.png (widths over time) and report.md; --json FILE writes the report's
figures for machines (FILE "-": stdout).

What "inside" means (the same in the tables, the JSON and the figures):
- trajectory, Kalman: per axis, |truth - mean| <= 3σ on that axis (σ the square root of
  the covariance's diagonal); horizontal = north and east both, vertical = down. A
  Gaussian puts 99.73 % on each axis.
- mines, Kalman: the Mahalanobis distance d² = eᵀC⁻¹e of the truth, in 3-D (C the 3×3
  covariance) and in the plane (C the north-east 2×2 block), against the chi-square
  quantile of 3 and 2 degrees of freedom at that same probability 0.9973 (d ≤ 3.76 in
  3-D, d ≤ 3.44 in the plane). The figure draws the plane's ellipse d = 3.44, so a truth
  drawn inside its ellipse is tabulated inside in the plane.
- interval: inside the box (bounds included), horizontal = north and east, vertical = down.

Exit code 2 with one line on bad input; 3 with one line for an inconsistent interval
result (its boxes are no answer) unless --show-inconsistent, which reports the Kalman side
and the interval diagnosis ("inconsistent (exit 3): ...") with no interval numbers.
"""
import argparse
import json
import math
import os
import re
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PROBABILITY = 0.9973  # two-sided 3σ of one Gaussian axis, and the Kalman tests' level


def one_line(text):
    """Control characters escaped: every message is one line, whatever a path holds."""
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


def fail(message):
    print("compare_kalman: " + one_line(message), file=sys.stderr)
    sys.exit(2)


def chi2_cdf(x, dof):
    """Chi-square CDF for 1, 2 or 3 degrees of freedom (closed forms; no scipy needed)."""
    if x <= 0:
        return 0.0
    if dof == 1:
        return math.erf(math.sqrt(x / 2))
    if dof == 2:
        return 1 - math.exp(-x / 2)
    if dof == 3:
        return math.erf(math.sqrt(x / 2)) - math.sqrt(2 * x / math.pi) * math.exp(-x / 2)
    raise ValueError("dof must be 1, 2 or 3")


def chi2_quantile(p, dof):
    """The x with chi2_cdf(x, dof) = p, by bisection (the CDF is increasing)."""
    lo, hi = 0.0, 100.0
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if chi2_cdf(mid, dof) < p else (lo, mid)
    return (lo + hi) / 2


def mahalanobis2(error, cov):
    """eᵀC⁻¹e; NaN when the covariance is not finite, inf when it is singular."""
    error, cov = np.asarray(error, float), np.asarray(cov, float)
    if not (np.all(np.isfinite(error)) and np.all(np.isfinite(cov))):
        return float("nan")
    try:
        return float(error @ np.linalg.solve(cov, error))
    except np.linalg.LinAlgError:
        return float("inf")


def ellipse_points(mean, cov, d2, count=200):
    """The boundary eᵀC⁻¹e = d2 around a 2-D mean: e = √d2 · V √Λ u, |u| = 1 (what
    mines.png draws, so that the plane test and the picture agree)."""
    values, vectors = np.linalg.eigh(np.asarray(cov, float))
    angles = np.linspace(0, 2 * np.pi, count)
    e = vectors @ (math.sqrt(d2) * np.sqrt(np.maximum(values, 0))[:, None] * np.stack([np.cos(angles), np.sin(angles)]))
    return mean[0] + e[0], mean[1] + e[1]


def judge_mine(truth, mean, cov, probability=PROBABILITY):
    """The Kalman judgements of one mine: d² in 3-D and in the plane, inside at the
    probability (chi-square 3 and 2 dof), and per-axis 3σ for comparison."""
    e = np.asarray(truth, float) - np.asarray(mean, float)
    cov = np.asarray(cov, float)
    d3, d2 = mahalanobis2(e, cov), mahalanobis2(e[:2], cov[:2, :2])
    sigma = np.sqrt(np.diag(cov))
    return {"mahalanobis2_3d": d3, "mahalanobis2_plane": d2,
            "inside_3d": bool(d3 <= chi2_quantile(probability, 3)),
            "inside_plane": bool(d2 <= chi2_quantile(probability, 2)),
            "inside_per_axis_3sigma": bool(np.all(np.abs(e) <= 3 * sigma))}


def read(path, names):
    try:
        with h5py.File(path, "r") as f:
            out = {}
            for name in names:
                if name.startswith("@"):
                    value = f.attrs.get(name[1:])
                    out[name] = value.decode() if isinstance(value, bytes) else value
                elif name in f:
                    out[name] = f[name][()]
                else:
                    out[name] = None
            out["@@timing"] = {k[len("timing_"):-len("_ms")]: float(v) for k, v in f.attrs.items()
                               if k.startswith("timing_") and k.endswith("_ms")}
            return out
    except OSError as e:
        fail(f"{path}: cannot read ({e})")


def number(value):
    """JSON-safe: NaN and infinities as null (JSON has neither)."""
    if value is None:
        return None
    value = float(value)
    return value if math.isfinite(value) else None


def fmt(value, digits=1):
    if value is None:
        return "–"
    if isinstance(value, float) and math.isnan(value):
        return "–"
    if isinstance(value, float) and math.isinf(value):
        return "unbounded"
    return f"{value:.{digits}f}"


def pct(fraction):
    return "–" if fraction is None else f"{100 * fraction:.1f} %"


def yes(flag):
    return "–" if flag is None else ("yes" if flag else "**no**")


def max_mean(values):
    values = np.asarray(values, float)
    if values.size == 0:
        return None, None
    return float(np.max(values)), float(np.mean(values))


def named_in_diagnosis(text):
    """(kind, row) of the marks and fixes whose removal the diagnosis says restores consistency."""
    found = []
    match = re.search(r"removing (.*?) restores consistency", text or "")
    if match:
        for kind, row in re.findall(r"(mark|GPS fix) (\d+)", match.group(1)):
            found.append(("mark" if kind == "mark" else "fix", int(row)))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mission")
    parser.add_argument("result")
    parser.add_argument("kalman")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--json", metavar="FILE", help="write the report's figures as JSON to FILE (- for stdout)")
    parser.add_argument("--show-inconsistent", action="store_true",
                        help="report an inconsistent interval result as such (its diagnosis, no numbers) beside the Kalman side")
    args = parser.parse_args()

    mission = read(args.mission, ["/truth/position", "/truth/mines", "/truth/marks_outlier", "/truth/gps_outlier",
                                  "/nav/time", "/marks/time", "/marks/mine", "/gps/time"])
    result = read(args.result, ["/time", "/tube/lower", "/tube/upper", "/mines/lower", "/mines/upper", "/marks/outlier",
                                "/gps/outlier", "@status", "@mode", "@inconsistency", "@minimal_outliers", "@sweeps"])
    kalman = read(args.kalman, ["/time", "/kalman/mean", "/kalman/cov", "/kalman/mines/mean", "/kalman/mines/cov",
                                "@iterations", "@converged", "@stalled", "@biases", "@containment_3sigma_horizontal",
                                "@containment_3sigma_vertical", "@containment_mines", "@containment_mines_plane", "@chi2", "@chi2_dof", "@chi2_per_dof",
                                "@chi2_band_low", "@chi2_band_high", "@chi2_band_probability", "@chi2_consistent",
                                "@test_probability",
                                "@flagged_fixes", "@flagged_marks", "/kalman/tests/kind", "/kalman/tests/row",
                                "/kalman/tests/time", "/kalman/tests/chi2", "/kalman/tests/dof", "/kalman/tests/flagged",
                                "/kalman/biases/estimate", "/kalman/biases/sigma", "/kalman/biases/prior_sigma",
                                "@bias_names", "@bias_units"])
    for path, data, key in [(args.result, result, "/tube/lower"), (args.kalman, kalman, "/kalman/mean")]:
        if data[key] is None:
            fail(f"{path}: missing {key}: not a gesmi result / kalman file")
    consistent = result["@status"] == "consistent"
    if not consistent and not args.show_inconsistent:
        print(f"compare_kalman: {one_line(args.result)} is an inconsistent result (the data contradict the bounds, so its boxes "
              "are no answer): see its diagnosis with gesmi solve, or add --show-inconsistent to compare anyway",
              file=sys.stderr)
        sys.exit(3)
    t = result["/time"]
    if kalman["/time"].shape != t.shape or np.any(kalman["/time"] != t):
        fail(f"{args.kalman}: /time differs from {args.result}: not the same mission")
    if mission["/nav/time"] is None or mission["/nav/time"].shape != t.shape or np.any(mission["/nav/time"] != t):
        fail(f"{args.mission}: /nav/time differs from {args.result}: not the same mission")
    os.makedirs(args.output, exist_ok=True)

    lower, upper = result["/tube/lower"], result["/tube/upper"]
    mean, cov = kalman["/kalman/mean"], kalman["/kalman/cov"].reshape(-1, 3, 3)
    sigma = np.sqrt(np.stack([cov[:, i, i] for i in range(3)], axis=1))
    truth = mission["/truth/position"]
    has_truth = truth is not None and truth.shape == mean.shape
    hours = t / 3600.0
    marker = "" if consistent else " (interval result INCONSISTENT: no answer, not drawn)"
    q2, q3 = chi2_quantile(PROBABILITY, 2), chi2_quantile(PROBABILITY, 3)
    diagnosis = "inconsistent (exit 3): " + one_line(result["@inconsistency"] or "no diagnosis recorded")

    # ---- Figures. The interval boxes are drawn only for a consistent result.
    # 1. Along the track: north, east and down against time.
    fig, axes = plt.subplots(3, 1, figsize=(11, 9), sharex=True)
    for axis, name in enumerate(["north", "east", "down"]):
        ax = axes[axis]
        reference = truth[:, axis] if has_truth else mean[:, axis]
        if consistent:
            ax.fill_between(hours, lower[:, axis] - reference, upper[:, axis] - reference, color="0.75",
                            label="interval envelope")
        ax.plot(hours, mean[:, axis] - 3 * sigma[:, axis] - reference, "b-", lw=0.8, label="Kalman ±3σ (this axis)")
        ax.plot(hours, mean[:, axis] + 3 * sigma[:, axis] - reference, "b-", lw=0.8)
        ax.plot(hours, mean[:, axis] - reference, "b--", lw=0.6, label="Kalman mean")
        ax.axhline(0.0, color="k", lw=0.8, label="truth" if has_truth else "Kalman mean")
        ax.set_ylabel(f"{name} - {'truth' if has_truth else 'mean'} (m)")
        ax.legend(loc="upper right", fontsize=8)
    axes[2].set_xlabel("time (h)")
    fig.suptitle("Interval envelope and Kalman ±3σ per axis, relative to the " + ("truth" if has_truth else "Kalman mean")
                 + marker)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "track.png"), dpi=110)
    plt.close(fig)

    # 2. Mines in the plane: boxes against the ellipses of the plane test.
    mine_lower, mine_upper = result["/mines/lower"], result["/mines/upper"]
    mine_mean = kalman["/kalman/mines/mean"]
    mine_cov = kalman["/kalman/mines/cov"].reshape(-1, 3, 3)
    truth_mines = mission["/truth/mines"]
    k = mine_mean.shape[0]
    columns = min(k, 3) if k else 1
    rows = (k + columns - 1) // columns if k else 1
    fig, axes = plt.subplots(rows, columns, figsize=(4 * columns, 4 * rows), squeeze=False)
    for i in range(k):
        ax = axes[i // columns][i % columns]
        if consistent and i < mine_lower.shape[0]:
            lo, hi = mine_lower[i], mine_upper[i]
            if np.all(np.isfinite([lo[0], lo[1], hi[0], hi[1]])):
                ax.add_patch(plt.Rectangle((lo[1], lo[0]), hi[1] - lo[1], hi[0] - lo[0], fill=False, color="k", lw=1.5,
                                           label="interval box"))
        if np.all(np.isfinite(mine_mean[i])) and np.all(np.isfinite(mine_cov[i])):
            north, east = ellipse_points(mine_mean[i][:2], mine_cov[i][:2, :2], q2)
            ax.plot(east, north, "b-",
                    label=f"Kalman {100 * PROBABILITY:.2f} % (d = {math.sqrt(q2):.2f})")
        if truth_mines is not None and i < truth_mines.shape[0]:
            ax.plot(truth_mines[i][1], truth_mines[i][0], "r+", ms=12, label="truth")
        verdicts = []  # the table's judgements of the truth, in the panel's title
        if truth_mines is not None and i < truth_mines.shape[0]:
            if consistent and i < mine_lower.shape[0] and np.all(np.isfinite(mine_lower[i])) and np.all(
                    np.isfinite(mine_upper[i])):
                inside = np.all((mine_lower[i][:2] <= truth_mines[i][:2]) & (truth_mines[i][:2] <= mine_upper[i][:2]))
                verdicts.append("in box" if inside else "OUT of box")
            if np.all(np.isfinite(mine_mean[i])) and np.all(np.isfinite(mine_cov[i])):
                inside = judge_mine(truth_mines[i], mine_mean[i], mine_cov[i])["inside_plane"]
                verdicts.append("in ellipse" if inside else "OUT of ellipse")
            else:
                verdicts.append("no Kalman estimate")
        ax.set_title(f"mine {i}" + (": " + ", ".join(verdicts) if verdicts else ""), fontsize=10)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("east (m)")
        ax.set_ylabel("north (m)")
        ax.legend(fontsize=7)
    for j in range(k, rows * columns):
        axes[j // columns][j % columns].axis("off")
    fig.suptitle("Mines in the plane: interval boxes and Kalman ellipses" + marker, fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "mines.png"), dpi=110)
    plt.close(fig)

    # 3. Widths over time.
    fig, ax = plt.subplots(figsize=(11, 4))
    for axis, name, style in [(0, "north", "-"), (1, "east", "--"), (2, "down", ":")]:
        if consistent:
            ax.plot(hours, upper[:, axis] - lower[:, axis], "k" + style, lw=0.8, label=f"interval width, {name}")
        ax.plot(hours, 6 * sigma[:, axis], "b" + style, lw=0.8, label=f"Kalman 6σ, {name}")
    ax.set_xlabel("time (h)")
    ax.set_ylabel("width (m)")
    ax.set_yscale("log")
    ax.legend(fontsize=8)
    ax.set_title("Widths over time" + marker)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "widths.png"), dpi=110)
    plt.close(fig)

    # ---- Figures of the trajectory.
    horizontal, vertical = slice(0, 2), slice(2, 3)
    in_tube = (lower <= mean) & (mean <= upper)  # truth-free: the Kalman mean in the tube
    kal = {"trajectory": {}, "mines": []}
    itv = {"status": result["@status"], "mode": result["@mode"], "sweeps": number(result["@sweeps"]),
           "minimal_outliers": number(result["@minimal_outliers"]),
           "inconsistency": result["@inconsistency"] or None, "trajectory": None, "mines": None}
    for part, axes_ in [("horizontal", horizontal), ("vertical", vertical)]:
        s6 = 6 * np.max(sigma[:, axes_], axis=1)
        entry = {"width_6sigma_max": number(np.max(s6)), "width_6sigma_mean": number(np.mean(s6)),
                 "mean_in_tube": float(np.mean(np.all(in_tube[:, axes_], axis=1))) if consistent else None}
        if has_truth:
            e = truth[:, axes_] - mean[:, axes_]
            entry["truth_inside_3sigma"] = float(np.mean(np.all(np.abs(e) <= 3 * sigma[:, axes_], axis=1)))
            mx, mn = max_mean(np.linalg.norm(e, axis=1))
            entry["error_max"], entry["error_mean"] = number(mx), number(mn)
        kal["trajectory"][part] = entry
    if consistent:
        itv["trajectory"] = {}
        with np.errstate(invalid="ignore"):  # inf - inf where a hypothesis leaves a step unbounded
            centre = (lower + upper) / 2
        for part, axes_ in [("horizontal", horizontal), ("vertical", vertical)]:
            w = np.max(upper[:, axes_] - lower[:, axes_], axis=1)
            bounded = np.isfinite(w)  # an outlier hypothesis without a fix can leave steps unbounded
            mx, mn = max_mean(w[bounded])
            entry = {"width_max": number(mx), "width_mean": number(mn), "unbounded_steps": int(np.sum(~bounded))}
            if has_truth:
                entry["truth_inside"] = float(np.mean(np.all((lower[:, axes_] <= truth[:, axes_])
                                                             & (truth[:, axes_] <= upper[:, axes_]), axis=1)))
                mx, mn = max_mean(np.linalg.norm(truth[bounded][:, axes_] - centre[bounded][:, axes_], axis=1))
                entry["centre_error_max"], entry["centre_error_mean"] = number(mx), number(mn)
            itv["trajectory"][part] = entry

    # ---- Mines.
    if consistent:
        itv["mines"] = []
    for i in range(k):
        m_truth = truth_mines[i] if truth_mines is not None and i < truth_mines.shape[0] else None
        finite = bool(np.all(np.isfinite(mine_mean[i])) and np.all(np.isfinite(mine_cov[i])))
        entry = {"mine": i, "finite": finite}
        if finite:
            values = np.linalg.eigvalsh(mine_cov[i][:2, :2])
            entry["ellipse_axes"] = [number(2 * math.sqrt(q2 * max(v, 0.0))) for v in values[::-1]]
            entry["width_6sigma_down"] = number(6 * math.sqrt(mine_cov[i][2, 2]))
            if m_truth is not None:
                entry.update(judge_mine(m_truth, mine_mean[i], mine_cov[i]))
                entry["mahalanobis2_3d"] = number(entry["mahalanobis2_3d"])
                entry["mahalanobis2_plane"] = number(entry["mahalanobis2_plane"])
                entry["error_plane"] = float(np.linalg.norm(m_truth[:2] - mine_mean[i][:2]))
                entry["error_down"] = float(abs(m_truth[2] - mine_mean[i][2]))
            if consistent and i < mine_lower.shape[0]:
                inside = (mine_lower[i] <= mine_mean[i]) & (mine_mean[i] <= mine_upper[i])
                entry["mean_in_box_plane"] = bool(np.all(inside[:2]))
                entry["mean_in_box_vertical"] = bool(inside[2])
        kal["mines"].append(entry)
        if consistent and i < mine_lower.shape[0]:
            lo, hi = mine_lower[i], mine_upper[i]
            box = {"mine": i, "bounded": bool(np.all(np.isfinite(lo)) and np.all(np.isfinite(hi))),
                   "width_plane": number(np.max(hi[:2] - lo[:2])), "width_down": number(hi[2] - lo[2])}
            if m_truth is not None:
                inside = (lo <= m_truth) & (m_truth <= hi)
                box["truth_inside_3d"] = bool(np.all(inside))
                box["truth_inside_plane"] = bool(np.all(inside[:2]))
                with np.errstate(invalid="ignore"):
                    box["centre_error_plane"] = number(np.linalg.norm(m_truth[:2] - (lo[:2] + hi[:2]) / 2))
            itv["mines"].append(box)

    # ---- The Kalman consistency tests and the interval diagnosis.
    def attr(name, kind=float):
        value = kalman["@" + name]
        return None if value is None else (number(value) if kind is float else kind(value))

    kal["iterations"], kal["converged"] = attr("iterations", int), attr("converged", bool)
    kal["stalled"] = attr("stalled", bool)  # None in files written before the stall rule
    kal["biases"] = attr("biases", bool)
    if kalman["@chi2"] is not None:
        kal["chi2"] = {name: attr(name) for name in ["chi2", "chi2_dof", "chi2_per_dof", "chi2_band_low", "chi2_band_high",
                                                     "chi2_band_probability"]}
        kal["chi2"]["consistent"] = attr("chi2_consistent", bool)
    else:
        kal["chi2"] = None
    kal["test_probability"] = attr("test_probability")
    # gesmi kalman's own figures, by the same definitions as this report's (NaN: no truth).
    kal["recorded"] = {name: attr("containment_" + name) for name in
                       ["3sigma_horizontal", "3sigma_vertical", "mines", "mines_plane"]}
    tests = None
    if kalman["/kalman/tests/kind"] is not None:
        tests = [{"kind": "fix" if kd == 0 else "mark", "row": int(rw), "time": float(tm), "chi2": number(c2),
                  "dof": int(df), "flagged": bool(fl)}
                 for kd, rw, tm, c2, df, fl in zip(kalman["/kalman/tests/kind"], kalman["/kalman/tests/row"],
                                                   kalman["/kalman/tests/time"], kalman["/kalman/tests/chi2"],
                                                   kalman["/kalman/tests/dof"], kalman["/kalman/tests/flagged"])]
    kal["flagged"] = None if tests is None else [(x["kind"], x["row"]) for x in tests if x["flagged"]]
    if kalman["/kalman/biases/estimate"] is not None:
        names = (kalman["@bias_names"] or "").split(",")
        units = (kalman["@bias_units"] or "").split(",")
        est, sd = kalman["/kalman/biases/estimate"], kalman["/kalman/biases/sigma"]
        prior = kalman["/kalman/biases/prior_sigma"]
        kal["bias_estimates"] = [{"name": names[j] if j < len(names) else f"bias {j}",
                                  "unit": units[j] if j < len(units) else "",
                                  "estimate": number(est[j]), "sigma": number(sd[j]),
                                  "prior_sigma": number(prior[j]) if prior is not None else None}
                                 for j in range(len(est))]
    else:
        kal["bias_estimates"] = None
    # Interval: the marks/fixes the diagnosis names, and those every outlier hypothesis removes.
    itv["named"] = [list(x) for x in named_in_diagnosis(result["@inconsistency"])]
    itv["removed_by_every_hypothesis"] = (
        [["mark", int(j)] for j in np.nonzero(result["/marks/outlier"])[0]] if result["/marks/outlier"] is not None else []) + (
        [["fix", int(j)] for j in np.nonzero(result["/gps/outlier"])[0]] if result["/gps/outlier"] is not None else [])
    truth_outliers = ([("mark", int(j)) for j in np.nonzero(mission["/truth/marks_outlier"])[0]]
                      if mission["/truth/marks_outlier"] is not None else []) + (
        [("fix", int(j)) for j in np.nonzero(mission["/truth/gps_outlier"])[0]]
        if mission["/truth/gps_outlier"] is not None else [])

    timing = {"interval_ms": result["@@timing"], "interval_parts_sum_ms": sum(result["@@timing"].values()),
              "kalman_ms": kalman["@@timing"], "kalman_parts_sum_ms": sum(kalman["@@timing"].values())}
    report = {"mission": args.mission, "result": args.result, "kalman_file": args.kalman, "has_truth": bool(has_truth),
              "probability": PROBABILITY, "chi2_quantile_plane": q2, "chi2_quantile_3d": q3,
              "interval": itv, "kalman": kal, "truth_outliers": [list(x) for x in truth_outliers], "timing": timing}

    # ---- report.md
    lines = ["# gesmi interval result against the Kalman smoother" + marker, "",
             f"- mission: `{args.mission}`" + ("" if has_truth else " (no truth recorded: no containment figures)"),
             "- interval result: " + (f"consistent ({itv['mode']}, {fmt(itv['sweeps'], 0)} sweeps"
                                      + (f", {fmt(itv['minimal_outliers'], 0)} outlier(s) tolerated"
                                         if itv["minimal_outliers"] else "") + ")" if consistent
                                      else "**" + diagnosis + "**"),
             f"- Kalman smoother: {fmt(kal['iterations'], 0) if kal['iterations'] is not None else '?'} linearisations, "
             + ("converged" if kal["converged"] else
                "stopped at the rounding floor (steps stalled within the stall fraction of σ)" if kal["stalled"]
                else "**not converged**")
             + "; bias states: " + ("not recorded" if kal["biases"] is None else ("yes" if kal["biases"] else "no")),
             "- Kalman \"inside 3σ\" on the trajectory: per axis, |truth − mean| ≤ 3σ of that axis (99.73 % per axis "
             "for a Gaussian); horizontal = north and east both. Mines: Mahalanobis d² ≤ the chi-square quantile at "
             f"{100 * PROBABILITY:.2f} %: {q3:.2f} in 3-D (3 dof, d ≤ {math.sqrt(q3):.2f}), {q2:.2f} in the plane "
             f"(2 dof, d ≤ {math.sqrt(q2):.2f}, the ellipse drawn in mines.png).",
             "- Widths: interval, the larger horizontal side of the box and its vertical side; Kalman, 6σ of the larger "
             "horizontal σ and 6σ down. Errors: distance from the truth to the Kalman mean and to the interval box's "
             "centre (in the plane, or down).", "",
             "## Trajectory", "",
             "| | interval width max / mean (m) | Kalman 6σ max / mean (m) | truth in interval | truth in Kalman 3σ "
             "| box-centre error max / mean (m) | Kalman-mean error max / mean (m) | Kalman mean in interval tube |",
             "|---|---|---|---|---|---|---|---|"]
    if not consistent:
        lines.append(f"| interval result | {diagnosis} | | | | | | |")
    for part in ["horizontal", "vertical"]:
        kp = kal["trajectory"][part]
        ip = itv["trajectory"][part] if consistent else None
        no = "no answer"
        lines.append(
            f"| trajectory ({part}) | "
            + ((f"{fmt(ip['width_max'])} / {fmt(ip['width_mean'])}"
                + (f" (unbounded at {ip['unbounded_steps']} steps, left out)" if ip["unbounded_steps"] else ""))
               if ip else no) + " | "
            + f"{fmt(kp['width_6sigma_max'])} / {fmt(kp['width_6sigma_mean'])} | "
            + (pct(ip.get("truth_inside")) if ip else no) + " | " + pct(kp.get("truth_inside_3sigma")) + " | "
            + (f"{fmt(ip.get('centre_error_max'))} / {fmt(ip.get('centre_error_mean'))}" if ip else no) + " | "
            + f"{fmt(kp.get('error_max'))} / {fmt(kp.get('error_mean'))} | "
            + (pct(kp["mean_in_tube"]) if consistent else no) + " |")
    lines += ["", "## Mines", "",
              "| | interval box: plane / down width (m) | truth in box: 3-D / plane | box-centre error, plane (m) "
              f"| Kalman ellipse axes, plane (m) / 6σ down (m) | Mahalanobis d: 3-D / plane | truth in Kalman "
              f"{100 * PROBABILITY:.2f} %: 3-D / plane | Kalman-mean error: plane / down (m) | Kalman mean in box: "
              "plane / down |",
              "|---|---|---|---|---|---|---|---|---|"]
    for i in range(k):
        km = kal["mines"][i]
        bx = itv["mines"][i] if consistent and i < len(itv["mines"]) else None
        no = "no answer"

        def root(d2):
            return None if d2 is None else math.sqrt(d2)

        axes_txt = (" × ".join(fmt(a) for a in km["ellipse_axes"]) + f" / {fmt(km['width_6sigma_down'])}"
                    if km["finite"] else "not estimated")
        lines.append(
            f"| mine {i} | " + ((f"{fmt(bx['width_plane'])} / {fmt(bx['width_down'])}" if bx["bounded"] else "unbounded")
                                 if bx else no) + " | "
            + (f"{yes(bx.get('truth_inside_3d'))} / {yes(bx.get('truth_inside_plane'))}" if bx else no) + " | "
            + (fmt(bx.get("centre_error_plane")) if bx else no) + f" | {axes_txt} | "
            + f"{fmt(root(km.get('mahalanobis2_3d')), 2)} / {fmt(root(km.get('mahalanobis2_plane')), 2)} | "
            + f"{yes(km.get('inside_3d'))} / {yes(km.get('inside_plane'))} | "
            + f"{fmt(km.get('error_plane'))} / {fmt(km.get('error_down'))} | "
            + (f"{yes(km.get('mean_in_box_plane'))} / {yes(km.get('mean_in_box_vertical'))}" if bx else no) + " |")

    lines += ["", "## Consistency tests and diagnosis", ""]
    if kal["chi2"] is None:
        lines.append("- Kalman chi-square test of the whole fit: not recorded in this file.")
    else:
        c = kal["chi2"]
        lines.append(f"- Kalman chi-square of the whole fit: χ² = {fmt(c['chi2'])} for {fmt(c['chi2_dof'], 0)} dof, "
                     f"χ²/dof = {fmt(c['chi2_per_dof'], 3)} against the "
                     f"{fmt(100 * (c['chi2_band_probability'] or 0.95), 0)} % band [{fmt(c['chi2_band_low'], 3)}, "
                     f"{fmt(c['chi2_band_high'], 3)}]: " + ("consistent" if c["consistent"] else "**inconsistent**"))
    if tests is None:
        lines.append("- Kalman leave-one-out tests of the GPS fixes and marks: not recorded in this file.")
    else:
        level = kal["test_probability"]
        testable = sum(1 for x in tests if x["chi2"] is not None)
        lines.append(f"- Kalman leave-one-out tests: {len(tests)} inputs, {testable} testable (not: a mine's only mark), "
                     f"{len(kal['flagged'])} flagged "
                     f"(χ² above its {fmt(100 * level if level else None, 2)} % quantile)")
    rec = kal["recorded"]
    if any(x is not None for x in rec.values()):
        lines.append(f"- `gesmi kalman`'s own figures in the file: truth within 3σ horizontally "
                     f"{pct(rec['3sigma_horizontal'])}, vertically {pct(rec['3sigma_vertical'])}; mines inside their "
                     f"99.73 % region {pct(rec['mines'])} (3-D), {pct(rec['mines_plane'])} (plane)")
    lines.append("- interval: " + (diagnosis if not consistent else f"consistent ({itv['mode']})")
                 + ("; removed by every outlier hypothesis: "
                    + ", ".join(f"{a} {b}" for a, b in itv["removed_by_every_hypothesis"])
                    if itv["removed_by_every_hypothesis"] else ""))
    lines.append("- truth: " + (", ".join(f"{a} {b}" for a, b in truth_outliers) + " corrupted by the simulator"
                                if truth_outliers else "no corrupted input recorded"))
    suspects = sorted(set((kal["flagged"] or []) + [tuple(x) for x in itv["named"]]
                          + [tuple(x) for x in itv["removed_by_every_hypothesis"]] + truth_outliers))
    if suspects:
        by_input = {(x["kind"], x["row"]): x for x in tests or []}
        lines += ["", "| input | time (s) | Kalman leave-one-out χ² (dof) | Kalman | interval | truth |",
                  "|---|---|---|---|---|---|"]
        for kind, row in suspects:
            x = by_input.get((kind, row))
            times = mission["/marks/time"] if kind == "mark" else mission["/gps/time"]
            when = float(times[row]) if times is not None and row < len(times) else None
            kal_cell = "not recorded" if tests is None else (
                "not tested" if x is None else ("**flagged**" if x["flagged"] else "passed"))
            named = (kind, row) in [tuple(n) for n in itv["named"]]
            removed = (kind, row) in [tuple(n) for n in itv["removed_by_every_hypothesis"]]
            itv_cell = ("removing it restores consistency" if named else
                        "removed by every hypothesis" if removed else "–")
            mines_of = mission["/marks/mine"]
            of_mine = (f" (mine {int(mines_of[row])})" if kind == "mark" and mines_of is not None and row < len(mines_of)
                       and mines_of[row] >= 0 else "")
            lines.append(f"| {kind} {row}{of_mine} | {fmt(when)} | "
                         + (f"{fmt(x['chi2'], 1)} ({x['dof']})" if x else "–") + f" | {kal_cell} | {itv_cell} | "
                         + ("corrupted" if (kind, row) in truth_outliers else "–") + " |")
    if kal["bias_estimates"] is not None:
        lines += ["", "Bias estimates of the smoother (estimate ± σ, prior σ):", ""]
        lines += [f"- {b['name']}: {b['estimate']:.3g} ± {b['sigma']:.2g} {b['unit']} (prior "
                  + ("–" if b["prior_sigma"] is None else format(b["prior_sigma"], ".3g")) + ")"
                  for b in kal["bias_estimates"] if b["estimate"] is not None and b["sigma"] is not None]

    def parts(t_):
        return " + ".join(f"{name} {value:.1f}" for name, value in t_.items()) or "none recorded"

    lines += ["", "## Timings recorded in the files", "",
              f"- interval (`gesmi solve`), parts: {parts(timing['interval_ms'])} = {timing['interval_parts_sum_ms']:.1f} ms",
              f"- Kalman (`gesmi kalman`), parts: {parts(timing['kalman_ms'])} = {timing['kalman_parts_sum_ms']:.1f} ms",
              "- These are the stages each command times, not the whole process (start-up and writing the file are "
              "outside them); tools/kalman_experiments.py times the processes.", "",
              "Figures: `track.png`, `mines.png`, `widths.png`.", ""]
    with open(os.path.join(args.output, "report.md"), "w") as f:
        f.write("\n".join(lines))
    if args.json:
        text = json.dumps(report, indent=1, allow_nan=False)
        if args.json == "-":
            print(text)
        else:
            with open(args.json, "w") as f:
                f.write(text + "\n")
    if args.json != "-":
        print("\n".join(lines))


if __name__ == "__main__":
    main()
