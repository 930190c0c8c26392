#!/usr/bin/python3
"""Whole-process cost of the gesmi commands (docs/performance.md, "Current figures"):
each command run as a process, several times, with its CPU time (user + system, from
wait4, and each of the two: on a virtual machine the system time is mostly the host
supplying fresh memory, and varies with what ran before, docs/performance.md; the kernel
splits the two by timer ticks, coarsely for a command of tens of milliseconds), wall
time and peak resident memory; the median of the runs is printed as a
Markdown table. Each command first runs once under /usr/bin/time for its peak; that run
is not counted in the times (time's own start would add a few milliseconds to them). Missions: the reference-like one (59,995 steps) and, with --sizes,
10^6 and 10^7 steps (the survey repeated).

    tools/bench/whole_process.py [--gesmi build/bin/gesmi] [--runs 5] [--sizes ref 1e6 1e7]
                                 [--big-runs 1] [--only solve warm ...] [--skip NAME ...]
                                 [--keep DIR] [--vs OTHER/gesmi] [--pause SECONDS]

The operator iteration is `marks add` + `solve --from` + `waterfall` + `candidates`
after one missed mark is found (the simulator's first missed mark, its true range).

--pause waits before each run, as an operator does between commands: on a virtual
machine the memory a command gets back right after another freed it is cheaper than
after a pause (docs/performance.md, "How to reproduce").

--vs compares two builds on a shared machine, whose speed drifts between minutes: each
command of the two is run in turn (A B A B ..., after one pair not counted), each in its
own folder on the same mission, and the ratio A/B of each pair's CPU time is printed
with the medians (its median, then its range: a wide range says the machine was noisy),
and the ratio of the user times alone, which the host's supply of fresh memory moves less
(at 10^6 and 10^7 steps: the kernel splits a process's CPU time into user and system by
timer ticks, so for a command of tens of milliseconds the split is coarse and that ratio
noisier than the CPU's).
Copy both binaries into one folder first: one run from the build tree it was linked in
started up to a tenth slower than its copy here (docs/performance.md, "How to
reproduce"); the commands a change does not touch should give about 1.
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import h5py

SIZES = {"ref": 5999.4, "1e6": 100000.0, "1e7": 1000000.0}  # simulated seconds at 10 Hz


PAUSE = 0.0  # seconds slept before each timed run (--pause)


def run(command, quiet=True, peak=False):
    """One process: (CPU s, wall s, peak RSS MiB or None, user s, system s); CPU is user
    plus system. Exit codes 0 and 3 count as done.

    With `peak`, the command runs under /usr/bin/time, which forks it and reads its peak:
    a process this script starts directly inherits, through exec, the peak of the Python
    interpreter it was forked from (about 45 MB), which hid every smaller peak. Its times
    are then those of /usr/bin/time and the command together (time's own start costs a
    few milliseconds of CPU), so the times counted come from runs without it."""
    time.sleep(PAUSE)
    with tempfile.NamedTemporaryFile("r", prefix="gesmi-peak-") as peak_file:
        timed = ["/usr/bin/time", "-q", "-f", "%M", "-o", peak_file.name] + command if peak else command
        start = time.perf_counter()
        process = subprocess.Popen(timed, stdout=subprocess.DEVNULL if quiet else None, stderr=subprocess.PIPE)
        _, status, usage = os.wait4(process.pid, 0)
        wall = time.perf_counter() - start
        code = os.waitstatus_to_exitcode(status)
        if code not in (0, 3):
            sys.exit(f"whole_process: {' '.join(command)} exited {code}: {process.stderr.read().decode().strip()}")
        process.stderr.close()
        peak_mib = float(peak_file.read().split()[-1]) / 1024.0 if peak else None
    return usage.ru_utime + usage.ru_stime, wall, peak_mib, usage.ru_utime, usage.ru_stime


def one(command, fresh, peak=False):
    """run(), after removing `fresh` (a folder the command writes, or None)."""
    if fresh:
        shutil.rmtree(fresh, ignore_errors=True)
    return run(command, peak=peak)


def median_of(runs, command, fresh=None):
    """Median CPU and wall over the runs, the peak of one run before them (not counted),
    and the median user and system times."""
    peak = one(command, fresh, peak=True)[2]
    samples = [one(command, fresh) for _ in range(runs)]
    return (statistics.median(s[0] for s in samples), statistics.median(s[1] for s in samples), peak,
            statistics.median(s[3] for s in samples), statistics.median(s[4] for s in samples))


def paired(runs, a, b):
    """A and B in turn, after one pair not counted that measures the peaks. a, b: (argv,
    folder to remove before each run or None). Medians of each, the pairs' CPU ratios A/B,
    and their user-time ratios (for long commands: see the module's docstring)."""
    peaks = (one(*a, peak=True)[2], one(*b, peak=True)[2])
    pairs = [(one(*a), one(*b)) for _ in range(runs)]
    medians = [tuple(statistics.median(p[side][i] for p in pairs) for i in range(2)) + (peaks[side],)
               for side in (0, 1)]
    ratios = [p[0][0] / p[1][0] for p in pairs]
    user_ratios = [p[0][3] / p[1][3] for p in pairs if p[1][3] > 0.0]
    return medians[0], medians[1], ratios, user_ratios


def first_missed_mark(mission):
    with h5py.File(mission, "r") as f:
        t, _, r = f["truth/missed_marks"][0]
    return float(t), float(r)


def commands(gesmi, folder, mission):
    """(name, argv, setup, folder to remove before each run or None), in the order a user
    runs them; setup: the (argv, file it writes) each needs first, run when the file is
    missing (with --only, the commands before it were not run)."""
    result, warm_mission = f"{folder}/r.h5", f"{folder}/m2.h5"
    t, r = first_missed_mark(mission)
    solve = ([gesmi, "solve", mission, "-o", result], result)
    add = ([gesmi, "marks", "add", mission, "--time", repr(t), "--range", repr(r), "-o", warm_mission], warm_mission)
    return [
        ("solve", solve[0], [], None),
        ("solve --png --geojson --mines-csv", [gesmi, "solve", mission, "-o", f"{folder}/all.h5", "--png", "--geojson",
                                               "--mines-csv"], [], None),
        ("marks add", add[0], [], None),
        ("solve --from (one added mark)", [gesmi, "solve", warm_mission, "--from", result, "-o", f"{folder}/w.h5"],
         [solve, add], None),
        ("waterfall", [gesmi, "waterfall", result, "-o", f"{folder}/wf.png"], [solve], None),
        ("candidates", [gesmi, "candidates", result], [solve], None),
        ("export tube-csv", [gesmi, "export", result, "--format", "tube-csv", "-o", f"{folder}/tube.csv"], [solve],
         None),
        ("kalman", [gesmi, "kalman", mission, "-o", f"{folder}/k.h5"], [], None),
        ("export csv", [gesmi, "export", mission, "-o", f"{folder}/csv"], [], f"{folder}/csv"),
    ]


def prepare(setup):
    """Runs the setup commands whose files are missing."""
    for argv, writes in setup:
        if not os.path.exists(writes):
            run(argv)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--gesmi", default="build/bin/gesmi")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--sizes", nargs="+", default=["ref"], choices=list(SIZES))
    parser.add_argument("--only", nargs="+", help="command names to time (prefixes of the table's names)")
    parser.add_argument("--skip", nargs="+", default=[], help="command names not to time (prefixes)")
    parser.add_argument("--keep", help="folder for the files (default: a temporary one, removed)")
    parser.add_argument("--big-runs", type=int, default=1, help="runs (or pairs) at 10^6 and 10^7 steps")
    parser.add_argument("--vs", help="a second gesmi build (B), run in turn with --gesmi (A)")
    parser.add_argument("--pause", type=float, default=0.0,
                        help="seconds to wait before each run, as a user pausing between commands")
    args = parser.parse_args()
    global PAUSE
    PAUSE = args.pause
    gesmi = os.path.abspath(args.gesmi)
    folder = args.keep or tempfile.mkdtemp(prefix="gesmi-whole-")
    os.makedirs(folder, exist_ok=True)
    if args.vs:
        compare(args, gesmi, os.path.abspath(args.vs), folder)
        return
    print("| command | steps | CPU (s) | user (s) | system (s) | wall (s) | peak memory (MiB) | runs |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    try:
        for size in args.sizes:
            mission = f"{folder}/m-{size}.h5"
            simulate = [gesmi, "simulate", "--preset", "redermor", "--seed", "1", "--missed", "0.3", "--duration",
                        repr(SIZES[size]), "-o", mission]
            cpu, wall, peak, user, system = run(simulate, peak=True)
            with h5py.File(mission, "r") as f:
                steps = f["nav/time"].shape[0]
            print(f"| simulate | {steps:,} | {cpu:.3f} | {user:.3f} | {system:.3f} | {wall:.3f} | {peak:.0f} | 1 |",
                  flush=True)
            runs = args.runs if size == "ref" else args.big_runs
            operator = [0.0, 0.0]
            # (a folder per size: a setup file of another size is never taken for this one's)
            os.makedirs(f"{folder}/{size}", exist_ok=True)
            for name, command, setup, fresh in commands(gesmi, f"{folder}/{size}", mission):
                if not wanted(args, name):
                    continue
                prepare(setup)
                cpu, wall, peak, user, system = median_of(runs, command, fresh)
                if name in ("marks add", "solve --from (one added mark)", "waterfall", "candidates"):
                    operator = [operator[0] + cpu, operator[1] + wall]
                print(f"| {name} | {steps:,} | {cpu:.3f} | {user:.3f} | {system:.3f} | {wall:.3f} | {peak:.0f} | {runs} |",
                      flush=True)
            if not args.only:
                print(f"| operator iteration (marks add, solve --from, waterfall, candidates) | {steps:,} | {operator[0]:.3f} "
                      f"| | | {operator[1]:.3f} | | |")
    finally:
        if not args.keep:
            shutil.rmtree(folder, ignore_errors=True)


def wanted(args, name):
    return (not args.only or any(name.startswith(o) for o in args.only)) and not any(
        name.startswith(o) for o in args.skip)


def compare(args, gesmi_a, gesmi_b, folder):
    """--vs: each command of A and B in turn, on the same mission (A simulates it)."""
    print("| command | steps | CPU A (s) | CPU B (s) | A/B CPU: median (range) | wall A (s) | wall B (s) "
          "| A/B user: median (range) | peak A (MiB) | peak B (MiB) | pairs |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    try:
        for size in args.sizes:
            mission = f"{folder}/m-{size}.h5"
            run([gesmi_a, "simulate", "--preset", "redermor", "--seed", "1", "--missed", "0.3", "--duration",
                 repr(SIZES[size]), "-o", mission])
            with h5py.File(mission, "r") as f:
                steps = f["nav/time"].shape[0]
            runs = args.runs if size == "ref" else args.big_runs
            sides = []
            for side, gesmi in (("a", gesmi_a), ("b", gesmi_b)):
                os.makedirs(f"{folder}/{size}/{side}", exist_ok=True)
                sides.append(commands(gesmi, f"{folder}/{size}/{side}", mission))
            for (name, command_a, setup_a, fresh_a), (_, command_b, setup_b, fresh_b) in zip(*sides):
                if not wanted(args, name):
                    continue
                prepare(setup_a)
                prepare(setup_b)
                a, b, ratios, user_ratios = paired(runs, (command_a, fresh_a), (command_b, fresh_b))
                user = (f"{statistics.median(user_ratios):.2f} ({min(user_ratios):.2f}–{max(user_ratios):.2f})"
                        if user_ratios else "")
                print(f"| {name} | {steps:,} | {a[0]:.3f} | {b[0]:.3f} | {statistics.median(ratios):.2f} "
                      f"({min(ratios):.2f}–{max(ratios):.2f}) | {a[1]:.3f} | {b[1]:.3f} | {user} | {a[2]:.1f} "
                      f"| {b[2]:.1f} | {runs} |", flush=True)
    finally:
        if not args.keep:
            shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
