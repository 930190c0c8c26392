#!/usr/bin/python3
"""Side-by-side comparison of gesmi's interval result and the Kalman smoother.

usage: tools/compare_kalman.py MISSION.h5 RESULT.h5 KALMAN.h5 -o REPORT_DIR

Writes into REPORT_DIR: track.png (the interval envelope against the 3-sigma corridor
along the track), mines.png (mine boxes against 3-sigma ellipses), widths.png (widths
over time) and report.md (a table per trajectory and mine: interval width, 3-sigma
width, whether the truth is inside each, and the run times). Exit code 2 with one line
on bad input; 3 with one line for an inconsistent interval result (its boxes are no
answer) unless --show-inconsistent, which marks the report and pictures INCONSISTENT.
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def one_line(text):
    """Control characters escaped: every message is one line, whatever a path holds."""
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


def fail(message):
    print("compare_kalman: " + one_line(message), file=sys.stderr)
    sys.exit(2)


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
            return out
    except OSError as e:
        fail(f"{path}: cannot read ({e})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mission")
    parser.add_argument("result")
    parser.add_argument("kalman")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--show-inconsistent", action="store_true",
                        help="compare with an inconsistent interval result anyway (marked INCONSISTENT)")
    args = parser.parse_args()

    mission = read(args.mission, ["/truth/position", "/truth/mines", "/nav/time"])
    result = read(args.result, ["/time", "/tube/lower", "/tube/upper", "/mines/lower", "/mines/upper",
                                "@status", "@timing_propagate_ms", "@timing_build_ms"])
    kalman = read(args.kalman, ["/time", "/kalman/mean", "/kalman/cov", "/kalman/mines/mean",
                                "/kalman/mines/cov", "@timing_smooth_ms"])
    for path, data, key in [(args.result, result, "/tube/lower"), (args.kalman, kalman, "/kalman/mean")]:
        if data[key] is None:
            fail(f"{path}: missing {key}: not a gesmi result / kalman file")
    if result["@status"] != "consistent" and not args.show_inconsistent:
        print(f"compare_kalman: {one_line(args.result)} is an inconsistent result (the data contradict the bounds, so its boxes "
              "are no answer): see its diagnosis with gesmi solve, or add --show-inconsistent to compare anyway",
              file=sys.stderr)
        sys.exit(3)
    marker = "" if result["@status"] == "consistent" else " (INCONSISTENT interval result: no answer)"
    t = result["/time"]
    if kalman["/time"].shape != t.shape or np.any(kalman["/time"] != t):
        fail(f"{args.kalman}: /time differs from {args.result}: not the same mission")
    os.makedirs(args.output, exist_ok=True)

    lower, upper = result["/tube/lower"], result["/tube/upper"]
    mean, cov = kalman["/kalman/mean"], kalman["/kalman/cov"].reshape(-1, 3, 3)
    sigma = np.sqrt(np.stack([cov[:, i, i] for i in range(3)], axis=1))
    truth = mission["/truth/position"]
    has_truth = truth is not None and truth.shape == mean.shape
    hours = t / 3600.0

    # 1. Along the track: north and east against time.
    fig, axes = plt.subplots(2, 1, figsize=(11, 7), sharex=True)
    for axis, name in enumerate(["north", "east"]):
        ax = axes[axis]
        reference = truth[:, axis] if has_truth else mean[:, axis]
        ax.fill_between(hours, lower[:, axis] - reference, upper[:, axis] - reference, color="0.75",
                        label="interval envelope")
        ax.plot(hours, mean[:, axis] - 3 * sigma[:, axis] - reference, "b-", lw=0.8, label="Kalman ±3σ")
        ax.plot(hours, mean[:, axis] + 3 * sigma[:, axis] - reference, "b-", lw=0.8)
        ax.plot(hours, mean[:, axis] - reference, "b--", lw=0.6, label="Kalman mean")
        ax.axhline(0.0, color="k", lw=0.8, label="truth" if has_truth else "Kalman mean")
        ax.set_ylabel(f"{name} - {'truth' if has_truth else 'mean'} (m)")
        ax.legend(loc="upper right", fontsize=8)
    axes[1].set_xlabel("time (h)")
    fig.suptitle("Interval envelope and Kalman 3σ corridor, relative to the " + ("truth" if has_truth else "Kalman mean")
                 + marker)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "track.png"), dpi=110)
    plt.close(fig)

    # 2. Mines: boxes against 3-sigma ellipses, each mine in its own panel.
    mine_lower, mine_upper = result["/mines/lower"], result["/mines/upper"]
    mine_mean, mine_cov = kalman["/kalman/mines/mean"], kalman["/kalman/mines/cov"].reshape(-1, 3, 3)
    truth_mines = mission["/truth/mines"]
    k = mine_lower.shape[0]
    columns = min(k, 3) if k else 1
    rows = (k + columns - 1) // columns if k else 1
    fig, axes = plt.subplots(rows, columns, figsize=(4 * columns, 4 * rows), squeeze=False)
    angles = np.linspace(0, 2 * np.pi, 200)
    for i in range(k):
        ax = axes[i // columns][i % columns]
        lo, hi = mine_lower[i], mine_upper[i]
        if np.all(np.isfinite([lo[0], lo[1], hi[0], hi[1]])):
            ax.add_patch(plt.Rectangle((lo[1], lo[0]), hi[1] - lo[1], hi[0] - lo[0], fill=False, color="k", lw=1.5,
                                       label="interval box"))
        if np.all(np.isfinite(mine_mean[i])):
            c2 = mine_cov[i][:2, :2][::-1, ::-1]  # (east, north)
            values, vectors = np.linalg.eigh(c2)
            ellipse = vectors @ (3 * np.sqrt(np.maximum(values, 0))[:, None] * np.stack([np.cos(angles), np.sin(angles)]))
            ax.plot(mine_mean[i][1] + ellipse[0], mine_mean[i][0] + ellipse[1], "b-", label="Kalman 3σ")
        if truth_mines is not None and i < truth_mines.shape[0]:
            ax.plot(truth_mines[i][1], truth_mines[i][0], "r+", ms=12, label="truth")
        ax.set_title(f"mine {i}")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("east (m)")
        ax.set_ylabel("north (m)")
        ax.legend(fontsize=7)
    for j in range(k, rows * columns):
        axes[j // columns][j % columns].axis("off")
    if marker:
        fig.suptitle("Mine boxes and Kalman 3σ ellipses" + marker)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "mines.png"), dpi=110)
    plt.close(fig)

    # 3. Widths over time.
    fig, ax = plt.subplots(figsize=(11, 4))
    for axis, name, style in [(0, "north", "-"), (1, "east", "--")]:
        ax.plot(hours, upper[:, axis] - lower[:, axis], "k" + style, lw=0.8, label=f"interval width, {name}")
        ax.plot(hours, 6 * sigma[:, axis], "b" + style, lw=0.8, label=f"Kalman 6σ, {name}")
    ax.set_xlabel("time (h)")
    ax.set_ylabel("width (m)")
    ax.set_yscale("log")
    ax.legend(fontsize=8)
    if marker:
        ax.set_title("Widths over time" + marker)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "widths.png"), dpi=110)
    plt.close(fig)

    # 4. The table.
    def inside_interval(values, lo, hi):
        return bool(np.all((lo <= values) & (values <= hi)))

    def inside_sigma(values, m, s):
        return bool(np.all(np.abs(values - m) <= 3 * s))

    lines = ["# gesmi interval result against the Kalman smoother" + marker, "",
             f"- mission: `{args.mission}`; interval status: {result['@status']}",
             f"- run time: interval propagation {result['@timing_propagate_ms']:.1f} ms "
             f"(+ {result['@timing_build_ms']:.1f} ms to build the network); Kalman smoother "
             f"{kalman['@timing_smooth_ms']:.1f} ms", "",
             "| | interval width (max / mean, m) | Kalman 3σ width = 6σ (max / mean, m) | truth in interval | truth in 3σ |",
             "|---|---|---|---|---|"]
    w = np.maximum(upper[:, 0] - lower[:, 0], upper[:, 1] - lower[:, 1])
    s6 = 6 * np.maximum(sigma[:, 0], sigma[:, 1])
    if has_truth:
        in_interval = np.mean(np.all((lower <= truth) & (truth <= upper), axis=1))
        in_sigma = np.mean(np.all(np.abs(truth - mean) <= 3 * sigma, axis=1))
        truth_cells = f"{100 * in_interval:.1f} % of steps | {100 * in_sigma:.1f} % of steps"
    else:
        truth_cells = "– | –"
    lines.append(f"| trajectory (horizontal) | {np.nanmax(w):.1f} / {np.nanmean(w):.1f} | "
                 f"{np.nanmax(s6):.1f} / {np.nanmean(s6):.1f} | {truth_cells} |")
    for i in range(k):
        box = np.max(mine_upper[i][:2] - mine_lower[i][:2])
        sd = 6 * np.sqrt(np.max(np.diag(mine_cov[i])[:2])) if np.all(np.isfinite(mine_mean[i])) else float("nan")
        if truth_mines is not None and i < truth_mines.shape[0]:
            a = "yes" if inside_interval(truth_mines[i], mine_lower[i], mine_upper[i]) else "**no**"
            b = "yes" if inside_sigma(truth_mines[i], mine_mean[i], np.sqrt(np.diag(mine_cov[i]))) else "**no**"
        else:
            a = b = "–"
        lines.append(f"| mine {i} | {box:.1f} | {sd:.1f} | {a} | {b} |")
    lines += ["", "Figures: `track.png`, `mines.png`, `widths.png`.", ""]
    with open(os.path.join(args.output, "report.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
