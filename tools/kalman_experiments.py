#!/usr/bin/python3
"""The experiments of docs/comparison.md: gesmi's interval solver against the Kalman smoother.

usage: tools/kalman_experiments.py OUTDIR [--gesmi BIN] [--duration T] [--only a,b,c,d,e]

Simulates missions with `gesmi simulate`, runs `gesmi solve` and `gesmi kalman` (plain and,
when the binary has it, `--biases`) on each, compares them with tools/compare_kalman.py,
and writes OUTDIR/<experiment>.md (an interval table and a Kalman table per experiment),
OUTDIR/summary.json (every figure, exit code and timing) and each comparison's report
and figures under OUTDIR/<experiment>/<run>/.

Experiments:
  a  uniform errors inside the bounds (seed 1)
  b  worst-case errors, a bias at 99 % of each bound (seeds 1 and 2)
  c  every sensor bound divided by 2 and by 3, given to both methods (worst-case and
     uniform data, seed 1): the interval solver either proves the data inconsistent
     (exit 3) or answers; the smoother is judged by its containment and chi-square test
  d  one outlier mark (--outliers 1, seed 1): the smoother's leave-one-out tests against
     the interval diagnosis, and `gesmi solve --max-outliers 1` and `2`
  e  drifting errors (--errors drifting, seeds 1 and 2): inside the bounds, but not the
     constant bias the bias-aware smoother assumes

Timings are of the whole processes: wall time, and CPU time (user + system) of the
child from resource.getrusage(RUSAGE_CHILDREN) before and after it.
Exit code 2 with one line on bad input; 1 with one line when a command fails unexpectedly.
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import time

import h5py

HERE = os.path.dirname(os.path.abspath(__file__))
COMPARE = os.path.join(HERE, "compare_kalman.py")
# The sensor error bounds (docs/formats.md); not the motion model (max_* rates and jerk),
# the mine depth band (a terrain prior) or the sonar's range limit.
SENSOR_BOUNDS = ["dvl_relative", "dvl_absolute", "roll", "pitch", "heading", "depth_absolute", "depth_relative", "altitude",
                 "gps_lon_deg", "gps_lat_deg", "gps_metres", "mark_range", "along_track_tolerance"]


def one_line(text):
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


def fail(message, code=2):
    print("kalman_experiments: " + one_line(message), file=sys.stderr)
    sys.exit(code)


def slug(text):
    """A file name from a label: letters, digits, '_' and '-'."""
    return "_".join("".join(c if c.isalnum() or c == "-" else " " for c in text).split()).strip("-_")


def timed(command, expected=(0,)):
    """Runs a command; returns (exit code, stdout, stderr, wall s, CPU s of the child)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    r = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if r.returncode not in expected:
        last = (r.stderr.strip().splitlines() or ["(no message)"])[-1]
        fail(f"{' '.join(command)}: exit {r.returncode}: {last}", 1)
    return r.returncode, r.stdout, r.stderr, wall, cpu


class Runner:
    def __init__(self, out, gesmi, duration):
        self.out, self.gesmi, self.duration = out, gesmi, duration
        help_text = subprocess.run([gesmi, "kalman", "--help"], capture_output=True, text=True).stdout
        self.has_biases = "--biases" in help_text
        self.missions = {}

    def mission(self, seed, errors, outliers=0):
        key = f"seed{seed}_{errors}" + (f"_outliers{outliers}" if outliers else "")
        if key not in self.missions:
            path = os.path.join(self.out, "missions", key + ".h5")
            os.makedirs(os.path.dirname(path), exist_ok=True)
            command = [self.gesmi, "simulate", "--seed", str(seed), "--errors", errors, "--duration", str(self.duration),
                       "-o", path]
            if outliers:
                command += ["--outliers", str(outliers)]
            timed(command)
            self.missions[key] = path
        return self.missions[key]

    def divided_config(self, mission, divisor):
        """A YAML --config with every sensor bound of the mission's model divided."""
        path = os.path.join(self.out, "configs", f"{os.path.basename(mission)[:-3]}_bounds_div{divisor}.yaml")
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with h5py.File(mission, "r") as f:
            model = dict(f["model"].attrs)
        with open(path, "w") as f:
            f.write(f"# every sensor bound of {os.path.basename(mission)} divided by {divisor}\n")
            for key in SENSOR_BOUNDS:
                f.write(f"{key}: {float(model[key]) / divisor!r}\n")
        return path

    def solve(self, mission, name, extra=()):
        path = os.path.join(self.out, "results", name + ".h5")
        os.makedirs(os.path.dirname(path), exist_ok=True)
        code, _, err, wall, cpu = timed([self.gesmi, "solve", mission, "-o", path, *extra], expected=(0, 3))
        return {"file": path, "options": " ".join(extra), "exit": code, "stderr": err.strip(), "wall_s": wall,
                "cpu_s": cpu}

    def kalman(self, mission, name, biases, extra=()):
        if biases and not self.has_biases:
            return None
        path = os.path.join(self.out, "kalman", name + ("_biases" if biases else "") + ".h5")
        os.makedirs(os.path.dirname(path), exist_ok=True)
        command = [self.gesmi, "kalman", mission, "-o", path, *extra] + (["--biases"] if biases else [])
        code, _, err, wall, cpu = timed(command)
        return {"file": path, "biases": biases, "options": " ".join(extra), "exit": code, "stderr": err.strip(),
                "wall_s": wall, "cpu_s": cpu}

    def compare(self, mission, result, kalman, folder):
        folder = os.path.join(self.out, folder)
        json_path = os.path.join(folder, "compare.json")
        timed([sys.executable, COMPARE, mission, result["file"], kalman["file"], "-o", folder, "--json", json_path,
               "--show-inconsistent"])
        with open(json_path) as f:
            return json.load(f)

    def case(self, experiment, label, mission, bounds="declared", config=None, solves=(("plain", ()),)):
        """One data set: every solve variant against the plain smoother, and the smoothers
        (plain, bias-aware) against the first solve."""
        name = slug(f"{experiment} {label} {bounds.replace('/', 'div')}")
        extra = ("--config", config) if config else ()
        rows = {"label": label, "bounds": bounds, "mission": mission, "config": config, "solves": [], "kalmans": []}
        kalmans = [k for k in (self.kalman(mission, name, False, extra), self.kalman(mission, name, True, extra)) if k]
        for solve_label, options in solves:
            s = self.solve(mission, slug(f"{name} {solve_label}"), (*extra, *options))
            s["label"] = solve_label
            s["compare"] = self.compare(mission, s, kalmans[0], os.path.join(experiment, slug(f"{name} {solve_label}")))
            rows["solves"].append(s)
        first = rows["solves"][0]
        for k in kalmans:
            k["label"] = "bias-aware (--biases)" if k["biases"] else "plain"
            k["compare"] = (first["compare"] if not k["biases"] else self.compare(
                mission, first, k, os.path.join(experiment, slug(f"{name} biases"))))
            rows["kalmans"].append(k)
        if not self.has_biases:
            rows["kalmans"].append({"label": "bias-aware (--biases)", "unavailable": True})
        return rows


# ---- Tables.
def pct(x):
    return "–" if x is None else f"{100 * x:.1f} %"


def num(x, digits=1):
    return "–" if x is None else f"{x:.{digits}f}"


def interval_cells(s):
    c = s["compare"]
    i = c["interval"]
    if i["status"] != "consistent":
        return [f"inconsistent (exit {s['exit']}): {one_line(i['inconsistency'] or '')}", "", "", "", "", ""]
    h, v = i["trajectory"]["horizontal"], i["trajectory"]["vertical"]
    width = f"{num(h['width_max'])} / {num(h['width_mean'])}"
    if h.get("unbounded_steps"):
        width += f" (unbounded at {h['unbounded_steps']} steps)"
    mines = [m for m in i["mines"]]
    bounded = [m for m in mines if m["bounded"]]
    # Over the bounded boxes: an unbounded box (a mine never marked) holds the truth trivially.
    in_3d = sum(1 for m in bounded if m.get("truth_inside_3d"))
    in_plane = sum(1 for m in bounded if m.get("truth_inside_plane"))
    widest = max((m["width_plane"] for m in bounded), default=None)
    status = f"consistent (exit {s['exit']})"
    if i.get("minimal_outliers"):
        status += f", {int(i['minimal_outliers'])} outlier(s) tolerated" + (
            ": removed by every hypothesis " + ", ".join(f"{a} {b}" for a, b in i["removed_by_every_hypothesis"])
            if i["removed_by_every_hypothesis"] else "")
    return [status, width, f"{pct(h.get('truth_inside'))} / {pct(v.get('truth_inside'))}",
            f"{num(h.get('centre_error_max'))} / {num(h.get('centre_error_mean'))}",
            f"{in_3d} / {in_plane} of {len(bounded)} bounded", num(widest) + (
                f" ({len(mines) - len(bounded)} unbounded)" if len(bounded) < len(mines) else "")]


def kalman_cells(k, interval_consistent):
    if k.get("unavailable"):
        return ["not available in this gesmi binary"] + [""] * 8
    c = k["compare"]["kalman"]
    h, v = c["trajectory"]["horizontal"], c["trajectory"]["vertical"]
    estimated = [m for m in c["mines"] if m["finite"] and "inside_3d" in m]
    in_3d = sum(1 for m in estimated if m["inside_3d"])
    in_plane = sum(1 for m in estimated if m["inside_plane"])
    chi2 = c.get("chi2")
    chi2_cell = "not recorded" if chi2 is None else (
        f"{num(chi2['chi2_per_dof'], 3)} [{num(chi2['chi2_band_low'], 3)}, {num(chi2['chi2_band_high'], 3)}] "
        + ("consistent" if chi2["consistent"] else "**inconsistent**"))
    flagged = "not recorded" if c["flagged"] is None else (", ".join(f"{a} {b}" for a, b in c["flagged"]) or "none")
    tube = (f"{pct(h['mean_in_tube'])} / {pct(v['mean_in_tube'])}" if interval_consistent else "no interval answer")
    passes = f"{c['iterations']}" + ("" if c["converged"] else
                                      " (stalled at the rounding floor)" if c.get("stalled") else " (not converged)")
    return [passes, f"{num(h['width_6sigma_mean'])}",
            f"{pct(h.get('truth_inside_3sigma'))} / {pct(v.get('truth_inside_3sigma'))}",
            f"{num(h.get('error_max'))} / {num(h.get('error_mean'))}",
            f"{in_3d} / {in_plane} of {len(estimated)} estimated", tube, chi2_cell, flagged]


def write_tables(out, key, title, cases):
    lines = [f"# {title}", "",
             "Interval solver (`gesmi solve`). Widths are the larger horizontal side of the box; \"truth in tube\" "
             "counts steps (horizontal = north and east in the box, vertical = down); mines counted in the box in 3-D "
             "and in the plane.", "",
             "| data | bounds | solve | result | horizontal width max / mean (m) | truth in tube: horizontal / vertical "
             "| box-centre error, horizontal max / mean (m) | mines: truth in box 3-D / plane | widest mine box, plane (m) "
             "| process wall / CPU (s) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for c in cases:
        for s in c["solves"]:
            lines.append(f"| {c['label']} | {c['bounds']} | {s['label']} | " + " | ".join(interval_cells(s))
                         + f" | {s['wall_s']:.2f} / {s['cpu_s']:.2f} |")
    lines += ["", "Kalman smoother (`gesmi kalman`). \"6σ\" is six standard deviations of the larger horizontal "
              "axis (mean over steps); \"truth in 3σ\" is per axis (horizontal: north and east both within 3σ of "
              "their axis); mines by the Mahalanobis test at 99.73 % (chi-square 3 dof in 3-D, 2 dof in the plane) "
              "over the mines it estimated; \"mean in tube\" is the truth-free check, the fraction of steps whose "
              "Kalman mean lies in the interval tube.", "",
              "| data | bounds | smoother | passes | 6σ horizontal, mean (m) | truth in 3σ: horizontal / vertical "
              "| mean error, horizontal max / mean (m) | mines: truth in 99.73 % 3-D / plane | mean in tube: "
              "horizontal / vertical | χ²/dof [95 % band] | flagged inputs | process wall / CPU (s) |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in cases:
        consistent = c["solves"][0]["compare"]["interval"]["status"] == "consistent"
        for k in c["kalmans"]:
            timing = "" if k.get("unavailable") else f"{k['wall_s']:.2f} / {k['cpu_s']:.2f}"
            lines.append(f"| {c['label']} | {c['bounds']} | {k['label']} | " + " | ".join(kalman_cells(k, consistent))
                         + f" | {timing} |")
    with open(os.path.join(out, key + ".md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir")
    parser.add_argument("--gesmi", default=os.environ.get("GESMI_BIN", os.path.join(HERE, "..", "build", "bin", "gesmi")))
    parser.add_argument("--duration", type=float, default=5999.4, help="mission length (s); the reference is 5999.4")
    parser.add_argument("--only", default="a,b,c,d,e", help="experiments to run, e.g. a,d")
    args = parser.parse_args()
    if not os.access(args.gesmi, os.X_OK):
        fail(f"{args.gesmi}: not an executable gesmi (give --gesmi or GESMI_BIN)")
    wanted = set(args.only.split(","))
    if not wanted <= set("abcde"):
        fail(f"--only: unknown experiments {','.join(sorted(wanted - set('abcde')))} (a to e)")
    os.makedirs(args.outdir, exist_ok=True)
    r = Runner(args.outdir, args.gesmi, args.duration)
    summary = {"gesmi": os.path.abspath(args.gesmi), "duration_s": args.duration, "kalman_biases_available": r.has_biases,
               "divided_bounds": SENSOR_BOUNDS, "experiments": {}}

    def record(key, title, cases):
        write_tables(args.outdir, key, title, cases)
        summary["experiments"][key] = {"title": title, "cases": cases}
        print(f"kalman_experiments: wrote {os.path.join(args.outdir, key + '.md')}", file=sys.stderr)

    if "a" in wanted:
        record("a_uniform", "(a) Uniform errors inside the bounds",
               [r.case("a", "uniform seed 1", r.mission(1, "uniform"))])
    if "b" in wanted:
        record("b_worst_case", "(b) Worst-case errors: a bias at 99 % of each bound",
               [r.case("b", f"worst-case seed {seed}", r.mission(seed, "worst-case")) for seed in (1, 2)])
    if "c" in wanted:
        cases = []
        for errors in ("worst-case", "uniform"):
            mission = r.mission(1, errors)
            for divisor in (2, 3):
                cases.append(r.case("c", f"{errors} seed 1", mission, bounds=f"all / {divisor}",
                                    config=r.divided_config(mission, divisor)))
        record("c_bounds_divided", "(c) Every sensor bound divided by 2 and by 3, given to both methods", cases)
    if "d" in wanted:
        record("d_outlier", "(d) One outlier mark (--outliers 1)",
               [r.case("d", "uniform seed 1 outliers 1", r.mission(1, "uniform", outliers=1),
                       solves=(("plain", ()), ("--max-outliers 1", ("--max-outliers", "1")),
                               ("--max-outliers 2", ("--max-outliers", "2"))))])
    if "e" in wanted:
        record("e_drifting", "(e) Drifting errors: a slow sinusoid inside each bound",
               [r.case("e", f"drifting seed {seed}", r.mission(seed, "drifting")) for seed in (1, 2)])
    with open(os.path.join(args.outdir, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
