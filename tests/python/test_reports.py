"""The --json report of every command, validated against docs/report.schema.json
(jsonschema) and checked against the files the command wrote: one JSON object on one
line of stdout, inputs and outputs as given, a solve's status, inconsistency and
flagged outliers as its result file records them. gesmi demo --json prints one report
per step, then its own."""
import json
import os
import subprocess

import h5py
import jsonschema
import pytest

from conftest import GESMI, run_gesmi

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
with open(os.path.join(SOURCE, "docs", "report.schema.json")) as f:
    SCHEMA = json.load(f)
VALIDATOR = jsonschema.Draft202012Validator(SCHEMA)


def report(*args, exit_code=0, lines=1):
    r = run_gesmi(*args, "--json")
    assert r.returncode == exit_code, r.stderr
    out = r.stdout.splitlines()
    assert len(out) == lines, r.stdout
    reports = [json.loads(line) for line in out]
    for rep in reports:
        VALIDATOR.validate(rep)
    return reports[-1] if lines == 1 else reports


def attr(path, name):
    with h5py.File(path, "r") as f:
        value = f.attrs[name]
    return value.decode() if isinstance(value, bytes) else value


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("reports")


@pytest.fixture(scope="module")
def inconsistent(folder):
    path = str(folder / "bad.h5")
    rep = report("simulate", "--seed", "9", "--outliers", "1", "--duration", "2400", "-o", path)
    assert rep["outputs"] == [path]
    with h5py.File(path, "r") as f:
        assert rep["mission"]["samples"] == f["/nav/time"].shape[0]
    return path


def test_solve_reports_the_inconsistency_as_the_result_records_it(folder, inconsistent):
    result = str(folder / "bad_result.h5")
    rep = report("solve", inconsistent, "-o", result, exit_code=3)
    assert rep["exit_code"] == 3
    assert rep["inputs"] == [{"role": "mission", "path": inconsistent}]
    assert rep["outputs"] == [result]
    solve = rep["solve"]
    assert solve["status"] == "inconsistent" == attr(result, "status")
    assert solve["inconsistency"]["text"] == attr(result, "inconsistency")
    assert solve["inconsistency"]["kind"] in ("evolution", "fix", "detection")
    assert solve["explained_by"], "the single mark whose removal restores consistency"
    assert set(rep["timings_ms"]) >= {"load", "propagate", "write"}


def test_a_refused_inconsistent_result_still_reports(folder, inconsistent):
    result = str(folder / "refused.h5")
    assert run_gesmi("solve", inconsistent, "-o", result).returncode == 3
    for args in (["candidates", result], ["waterfall", result, "-o", str(folder / "never.png")],
                 ["export", result, "--format", "tube-csv", "-o", str(folder / "never.csv")]):
        rep = report(*args, exit_code=3)
        assert rep["refused"] and rep["status"] == "inconsistent" and rep["outputs"] == []
    assert not os.path.exists(folder / "never.png") and not os.path.exists(folder / "never.csv")


def test_skipped_imports_and_simulated_localization(folder, mission_file):
    csv_folder = str(folder / "skip_csv")
    assert run_gesmi("export", mission_file, "-o", csv_folder).returncode == 0
    target = str(folder / "existing.h5")
    open(target, "w").write("placeholder")
    r = subprocess.run([GESMI, "import", "nav", "nav.csv", "--gps", "gps.csv", "-o", target, "--skip-existing", "--json"],
                       cwd=csv_folder, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    rep = json.loads(r.stdout)
    VALIDATOR.validate(rep)
    assert rep["command"] == "import nav" and rep["skipped"]
    scenario = os.path.join(SOURCE, "missions", "localization", "triangle_two_hypotheses.yaml")
    assert run_gesmi("localize", scenario, "--simulate", "--json").returncode == 2


def test_outlier_solve_lists_the_flagged_marks_of_its_result(folder, inconsistent):
    result = str(folder / "tolerant.h5")
    rep = report("solve", inconsistent, "--max-outliers", "1", "-o", result)
    solve = rep["solve"]
    assert solve["status"] == "consistent"
    assert solve["outliers"]["minimal"] == 1
    with h5py.File(result, "r") as f:
        flagged = [int(j) for j in range(f["/marks/outlier"].shape[0]) if f["/marks/outlier"][j]]
        candidates = f["/marks/candidates"][()]
    assert solve["outliers"]["marks"] == flagged
    for mark in solve["marks"]:
        assert mark["candidates"] == [i for i in range(candidates.shape[1]) if candidates[mark["row"], i]]
    # --stats is the older name of --json
    r = run_gesmi("solve", inconsistent, "--max-outliers", "1", "-o", str(folder / "tolerant2.h5"), "--stats")
    VALIDATOR.validate(json.loads(r.stdout))


def test_every_other_command_reports(folder, mission_file):
    result = str(folder / "r.h5")
    assert report("solve", mission_file, "-o", result)["solve"]["status"] == "consistent"
    rep = report("kalman", mission_file, "-o", str(folder / "k.h5"))
    assert os.path.exists(rep["outputs"][0])
    rep = report("candidates", result, "--csv", str(folder / "w.csv"))
    assert rep["outputs"] == [str(folder / "w.csv")] and rep["status"] == "consistent"
    rep = report("waterfall", result, "-o", str(folder / "w.png"))
    assert rep["outputs"] == [str(folder / "w.png")]
    for fmt in ("tube-csv", "mines-csv", "geojson"):
        out = str(folder / ("e." + fmt))
        rep = report("export", result, "--format", fmt, "-o", out)
        assert rep["format"] == fmt and rep["outputs"] == [out] and os.path.exists(out)
    csv_folder = str(folder / "csv")
    rep = report("export", mission_file, "-o", csv_folder)
    with open(os.path.join(csv_folder, "import-command.txt")) as f:
        import_args = f.read().split()[1:]
    imported = str(folder / "imported.h5")
    import_args[import_args.index("-o") + 1] = imported
    r = subprocess.run([GESMI, *import_args, "--json"], cwd=csv_folder, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    rep = json.loads(r.stdout)
    VALIDATOR.validate(rep)
    assert rep["command"] == "import nav" and {"role": "nav", "path": "nav.csv"} in rep["inputs"]
    rep = report("marks", "list", mission_file)
    count = len(rep["marks"])
    rep = report("marks", "add", mission_file, "--time", "10", "--range", "20", "-o", str(folder / "plus.h5"))
    assert rep["marks"] == count + 1 and rep["added"]["mine"] is None
    rep = report("marks", "remove", str(folder / "plus.h5"), str(count), "-o", str(folder / "minus.h5"))
    assert rep["marks"] == count and rep["removed"]["time"] == 10
    rep = report("example", "paper2d")
    assert rep["sweeps"] > 0 and len(rep["x4"]) == 2
    scenario = os.path.join(SOURCE, "missions", "localization", "triangle_two_hypotheses.yaml")
    rep = report("localize", scenario, "-o", str(folder / "loc"))
    assert rep["localization"]["found"] and len(rep["outputs"]) == 7  # summary.json among them
    example2 = os.path.join(SOURCE, "missions", "setinv", "seed004_example2.yaml")
    rep = report("estimate", example2, "-o", str(folder / "est"))
    assert rep["estimation"]["levels"][1]["q"] == 1 and rep["estimation"]["levels"][1]["proved_nonempty"]
    assert len(rep["outputs"]) == 3 and all(os.path.exists(p) for p in rep["outputs"])
    # A skipped rerun reports what exists instead of what it wrote.
    rep = report("waterfall", result, "-o", str(folder / "w.png"), "--skip-existing")
    assert rep["skipped"] and rep["existing"] == [str(folder / "w.png")] and rep["outputs"] == []


def test_demo_prints_each_steps_report_then_its_own(folder):
    reports = report("demo", "-o", str(folder / "demo"), lines=4)
    assert [r["command"] for r in reports] == ["simulate", "solve", "waterfall", "demo"]
    assert len(reports[-1]["outputs"]) == 6
    for path in reports[-1]["outputs"]:
        assert os.path.exists(path), path
