#!/usr/bin/python3
"""Tube and mine-box widths of the step models on reference-like missions
(docs/model.md, "Boxes over a step"): for each simulated mission, the widest and
median horizontal tube width and the widest mine box, per step model and max_jerk.

    PYTHONPATH=build/python tools/bench/step_model_widths.py [--seeds 1 2 3]
"""
import argparse
import statistics

import numpy as np

import gesmi


def widths(solution):
    north, east = solution.north, solution.east
    w = np.maximum(north[:, 1] - north[:, 0], east[:, 1] - east[:, 0])
    mines = solution.mines
    mine = max(max(m[0][1] - m[0][0], m[1][1] - m[1][0]) for m in mines) if len(mines) else float("nan")
    return float(np.max(w)), float(statistics.median(w)), float(mine)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--errors", nargs="+", default=["uniform", "worst-case", "at-samples"])
    parser.add_argument("--jerks", type=float, nargs="+", default=[0.1, 0.3, 1.0, 3.0])
    args = parser.parse_args()
    print("| errors | seed | step model | J (m/s³) | tube widest (m) | tube median (m) | widest mine box (m) | consistent |")
    print("|---|---:|---|---:|---:|---:|---:|---|")
    for errors in args.errors:
        for seed in args.seeds:
            m = gesmi.simulate(seed=seed, errors=errors)
            runs = [("rate-hull", 1.0), ("sample", 1.0)] + [("trapezoid", j) for j in args.jerks]
            for model, jerk in runs:
                m.model["step_model"] = model
                m.model["max_jerk"] = jerk
                s = gesmi.solve(m, diagnose=False, waterfall=False)
                widest, median, mine = widths(s)
                jerk_text = f"{jerk:g}" if model == "trapezoid" else "–"
                print(f"| {errors} | {seed} | {model} | {jerk_text} | {widest:.1f} | {median:.1f} | {mine:.1f} | "
                      f"{'yes' if s.consistent else 'NO'} |")


if __name__ == "__main__":
    main()
