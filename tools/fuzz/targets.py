"""The readers of the `gesmi` command under test: their seed inputs and command lines.

Seeds are small valid inputs made once per run with the binary under test (a 600 s
simulated mission, its result, its CSV export and GESMI text log) plus samples of the
repository (missions/). Each reader mutates one input file, named `input` in the case
folder, and runs one of its command lines, chosen by the case number. `@` in an argument
is the mutated file; `$name` is the seed file `name` (read-only, outside the case
folder); every output is written in the case folder.
"""

import os
import re
import shutil
import subprocess

ORIGIN = "48.212920614,-4.458227931"


def _run(gesmi, args, cwd):
    r = subprocess.run([gesmi] + args, cwd=cwd, capture_output=True, timeout=120)
    if r.returncode != 0:
        raise RuntimeError("seed command failed: gesmi %s: %s" % (" ".join(args), r.stderr.decode(errors="replace")))


def _scenario_seed(source, target):
    """A localization or estimation scenario bounded in time and boxes, so that a
    mutated epsilon cannot make a case run for minutes. Its `solver` mapping is in
    block style (localization) or flow style (estimation)."""
    with open(source, "rb") as f:
        text = f.read()
    text, block = re.subn(rb"\nsolver:\n", b"\nsolver:\n  max_seconds: 2\n  max_boxes: 200000\n", text, count=1)
    # Estimation examines boxes for every level: a tenth of the boxes keeps a case as
    # short under the sanitizers as a localization's.
    text, flow = re.subn(rb"\nsolver: \{", b"\nsolver: {max_seconds: 1, max_boxes: 20000, ", text, count=1)
    if block + flow != 1:
        raise RuntimeError("seed scenario %s: no 'solver:' mapping to bound" % source)
    with open(target, "wb") as f:
        f.write(text)


def make_seeds(gesmi, repo, folder):
    """Writes the seed files into folder; returns {name: absolute path}."""
    os.makedirs(folder, exist_ok=True)
    _run(gesmi, ["simulate", "--seed", "2", "--duration", "600", "-o", "mission.h5"], folder)
    _run(gesmi, ["solve", "mission.h5", "-o", "result.h5"], folder)
    _run(gesmi, ["export", "mission.h5", "-o", "csv"], folder)
    _run(gesmi, ["export", "mission.h5", "--format", "gesmi-txt", "-o", "mission.txt"], folder)
    _run(gesmi, ["export", "mission.h5", "--format", "logger", "--dvl-gap", "200:230", "-o", "logger"], folder)
    shutil.copy(os.path.join(repo, "missions/gesmi_txt/redermor_start.txt"), os.path.join(folder, "redermor.txt"))
    # Two marks that fit both missions (the text log is 30 s long).
    with open(os.path.join(folder, "marks10.csv"), "w") as f:
        f.write("time,mine,range,side\n10,?,20,starboard\n12,?,30,port\n")
    _run(gesmi, [a[1:] if a.startswith("$") else a for a in IMPORT_LOGGER[:-1]] + ["logger-mission.h5"], folder)
    _run(gesmi, ["import", "gesmi-txt", "redermor.txt", "--marks", "marks10.csv", "-o", "txt_mission.h5"], folder)
    for name in ("triangle_two_hypotheses", "warehouse_p02", "warehouse_p04_outliers", "no_echo_doorway"):
        _scenario_seed(os.path.join(repo, "missions/localization", name + ".yaml"), os.path.join(folder, name + ".yaml"))
    _scenario_seed(os.path.join(repo, "missions/setinv/seed004_example2.yaml"), os.path.join(folder, "seed004_example2.yaml"))
    with open(os.path.join(folder, "small.yaml"), "w") as f:
        f.write("heading: 0.006  # rad\nsonar_side: starboard\ndvl_relative: 0.005\n")
    seeds = {}
    for root, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(root, name)
            seeds[os.path.relpath(path, folder)] = path
    for stray in [k for k in seeds if k.startswith("result.") and k != "result.h5"]:
        del seeds[stray]
    return seeds


class Reader:
    """One reader: the seeds its input is mutated from, how, and the command lines."""

    def __init__(self, name, kind, seeds, commands, input_name, outputs=()):
        self.name = name
        self.kind = kind              # hdf5, csv, yaml, txt or cli
        self.seeds = seeds            # seed names the input is taken from (cycled)
        self.commands = commands      # argument lists; "@" = the input, "$x" = seed x
        self.input_name = input_name  # file name of the mutated input in the case folder
        self.outputs = outputs        # per command: what an exit 3 must have written


IMPORT_NAV = ["import", "nav", "$csv/nav.csv", "--gps", "$csv/gps.csv", "--marks", "$csv/marks.csv", "--config",
              "$csv/model.yaml", "--origin", ORIGIN, "--mines", "6", "--truth", "$csv/truth.csv", "--truth-mines",
              "$csv/truth_mines.csv", "-o", "out.h5"]


def _import_nav_with(option, value="@"):
    args = list(IMPORT_NAV)
    if option == "nav":
        args[2] = value
    else:
        args[args.index("--" + option) + 1] = value
    return args


IMPORT_LOGGER = ["import", "nav", "$logger/log.csv", "--map", "$logger/map.yaml", "--gps", "$logger/gps.nmea", "--marks",
                 "$logger/marks.csv", "--marks-map", "$logger/marks_map.yaml", "--config", "$logger/model.yaml",
                 "--origin", ORIGIN, "--mines", "6", "-o", "out.h5"]


def _import_logger_with(option):
    args = list(IMPORT_LOGGER)
    args[2 if option == "nav" else args.index("--" + option) + 1] = "@"
    return args


READERS = [
    Reader("mission:solve", "hdf5", ["mission.h5", "txt_mission.h5"],
           [["solve", "@", "-o", "out.h5"]], "mission.h5", [["out.h5"]]),
    Reader("mission:kalman", "hdf5", ["mission.h5", "txt_mission.h5"],
           [["kalman", "@", "-o", "out.h5"]], "mission.h5", [["out.h5"]]),
    Reader("mission:export", "hdf5", ["mission.h5", "txt_mission.h5"],
           [["export", "@", "-o", "out"], ["export", "@", "--format", "gesmi-txt", "-o", "out.txt"]], "mission.h5"),
    Reader("mission:marks", "hdf5", ["mission.h5", "txt_mission.h5"],
           [["marks", "list", "@"], ["marks", "add", "@", "--time", "10", "--range", "20", "-o", "out.h5"],
            ["marks", "remove", "@", "0", "-o", "out.h5"], ["import", "marks", "$marks10.csv", "--into", "@", "-o", "out.h5"]],
           "mission.h5"),
    Reader("result:waterfall", "hdf5", ["result.h5"], [["waterfall", "@", "-o", "out.png"]], "result.h5"),
    Reader("result:candidates", "hdf5", ["result.h5"],
           [["candidates", "@"], ["candidates", "@", "--csv", "out.csv"]], "result.h5"),
    Reader("result:warm-start", "hdf5", ["result.h5"], [["solve", "$mission.h5", "--from", "@", "-o", "out.h5"]],
           "result.h5", [["out.h5"]]),
    Reader("yaml:config", "yaml", ["csv/model.yaml", "small.yaml"],
           [["solve", "$mission.h5", "--config", "@", "-o", "out.h5"],
            ["simulate", "--seed", "3", "--duration", "60", "--config", "@", "-o", "out.h5"],
            ["kalman", "$mission.h5", "--config", "@", "-o", "out.h5"],
            _import_nav_with("config")], "model.yaml", [["out.h5"]] * 4),
    Reader("yaml:scenario", "yaml", ["triangle_two_hypotheses.yaml", "warehouse_p02.yaml", "warehouse_p04_outliers.yaml",
                                     "no_echo_doorway.yaml"],
           [["localize", "@", "-o", "out", "-q"], ["localize", "@", "--simulate", "--seed", "4"]], "scenario.yaml",
           [["out"], []]),
    Reader("yaml:estimation", "yaml", ["seed004_example2.yaml"],
           [["estimate", "@", "-o", "out", "-q"], ["estimate", "@", "-o", "out", "--json"]], "estimation.yaml",
           [["out"], ["out"]]),
    # Without the other CSV files: their cross-checks against the navigation (a GPS fix
    # or a truth row outside a shortened log) name the other file, rightly.
    Reader("csv:nav", "csv", ["csv/nav.csv"],
           [["import", "nav", "@", "--origin", ORIGIN, "-o", "out.h5"],
            ["import", "nav", "@", "--origin", ORIGIN, "--config", "$csv/model.yaml", "--mines", "6", "-o", "out.h5"]],
           "nav.csv", [["out.h5"]] * 2),
    Reader("csv:gps", "csv", ["csv/gps.csv"], [_import_nav_with("gps")], "gps.csv", [["out.h5"]]),
    Reader("csv:marks", "csv", ["csv/marks.csv"],
           [_import_nav_with("marks"), ["import", "marks", "@", "--into", "$mission.h5", "-o", "out.h5"]], "marks.csv",
           [["out.h5"]] * 2),
    Reader("csv:truth", "csv", ["csv/truth.csv"], [_import_nav_with("truth")], "truth.csv", [["out.h5"]]),
    Reader("csv:truth-mines", "csv", ["csv/truth_mines.csv"], [_import_nav_with("truth-mines")], "truth_mines.csv",
           [["out.h5"]]),
    Reader("csv:logger-log", "csv", ["logger/log.csv"],
           [["import", "nav", "@", "--map", "$logger/map.yaml", "--origin", ORIGIN, "-o", "out.h5"]], "log.csv", [["out.h5"]]),
    Reader("yaml:map", "yaml", ["logger/map.yaml", "logger/marks_map.yaml"],
           [_import_logger_with("map"), _import_logger_with("marks-map")], "map.yaml", [["out.h5"]] * 2),
    Reader("txt:nmea", "txt", ["logger/gps.nmea"],
           [_import_logger_with("gps"), _import_logger_with("gps")[:-2] + ["--gps-format", "nmea", "-o", "out.h5"]],
           "gps.nmea", [["out.h5"]] * 2),
    Reader("csv:logger-marks", "csv", ["logger/marks.csv"],
           [_import_logger_with("marks"), ["import", "marks", "@", "--into", "$logger-mission.h5", "--map",
                                           "$logger/marks_map.yaml", "-o", "out.h5"]], "marks.csv", [["out.h5"]] * 2),
    Reader("txt:gesmi", "txt", ["redermor.txt", "redermor.txt", "mission.txt"],
           [["import", "gesmi-txt", "@", "-o", "out.h5"], ["import", "gesmi-txt", "@", "--xy", "truth", "-o", "out.h5"],
            ["import", "gesmi-txt", "@", "--marks", "$marks10.csv", "--mines", "6", "-o", "out.h5"]], "log.txt",
           [["out.h5"]] * 3),
    Reader("cli:args", "cli", [], [
        ["marks", "add", "$mission.h5", "--time", "{100}", "--range", "{20}", "--mine", "{3}", "-o", "out.h5"],
        ["marks", "remove", "$mission.h5", "{0}", "-o", "out.h5"],
        ["solve", "$mission.h5", "--tolerance", "{0.001}", "--mines", "{6}", "--max-outliers", "{0}", "-o", "out.h5"],
        ["import", "nav", "$csv/nav.csv", "--origin", "{%s}" % ORIGIN, "--mines", "{6}", "-o", "out.h5"],
        ["localize", "$triangle_two_hypotheses.yaml", "--simulate", "--seed", "{4}", "--error-fraction", "{0.9}",
         "--range-outliers", "{1,2}"],
        ["waterfall", "$result.h5", "--max-range", "{75}", "-o", "out.png"],
        ["kalman", "$mission.h5", "--noise-factor", "{1}", "-o", "out.h5"],
        ["simulate", "--seed", "{3}", "--duration", "60", "--mines", "{6}", "--missed", "{0.1}", "-o", "out.h5"],
    ], "", [["out.h5"]] * 4 + [[], ["out.png"], ["out.h5"], ["out.h5"]]),
]


def reader_names():
    return [r.name for r in READERS]


def find(name):
    for r in READERS:
        if r.name == name:
            return r
    raise KeyError(name)
