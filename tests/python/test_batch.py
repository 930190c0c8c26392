"""A campaign through GNU parallel (docs/batch.md): three simulated missions solved as
parallel jobs with a joblog, then the same commands again with --skip-existing, which
redo nothing."""
import csv
import os
import subprocess

import h5py

from conftest import GESMI


def parallel(joblog, *command_and_inputs):
    r = subprocess.run(["parallel", "--will-cite", "--joblog", str(joblog), "-j", "2", *command_and_inputs],
                       capture_output=True, text=True)
    with open(joblog, newline="") as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    return r, rows


def test_a_campaign_runs_under_gnu_parallel_and_reruns_skip_what_exists(tmp_path):
    folder = str(tmp_path)
    r, jobs = parallel(tmp_path / "simulate.log", GESMI, "simulate", "--seed", "{}", "--duration", "300",
                       "-o", folder + "/m{}.h5", "--skip-existing", ":::", "1", "2", "3")
    assert r.returncode == 0, r.stderr
    assert [row["Exitval"] for row in jobs] == ["0", "0", "0"]
    missions = sorted(os.path.join(folder, f"m{i}.h5") for i in (1, 2, 3))
    r, jobs = parallel(tmp_path / "solve.log", GESMI, "solve", "{}", "-o", "{.}.result.h5", "--skip-existing",
                       ":::", *missions)
    assert r.returncode == 0, r.stderr
    assert len(jobs) == 3 and all(row["Exitval"] == "0" for row in jobs), jobs
    results = [m.replace(".h5", ".result.h5") for m in missions]
    stamps = []
    for path in results:
        with h5py.File(path, "r") as f:
            assert f.attrs["format"] in (b"gesmi-result", "gesmi-result")
        stamps.append(os.stat(path).st_mtime_ns)
    # The rerun of the campaign: every result exists, nothing is redone or rewritten.
    r, jobs = parallel(tmp_path / "rerun.log", GESMI, "solve", "{}", "-o", "{.}.result.h5", "--skip-existing",
                       ":::", *missions)
    assert r.returncode == 0, r.stderr
    assert all(row["Exitval"] == "0" for row in jobs), jobs
    assert r.stdout.count("skipped (--skip-existing)") == 3, r.stdout
    assert [os.stat(path).st_mtime_ns for path in results] == stamps
    # A missing result is redone alone.
    os.remove(results[1])
    r, jobs = parallel(tmp_path / "again.log", GESMI, "solve", "{}", "-o", "{.}.result.h5", "--skip-existing",
                       ":::", *missions)
    assert r.returncode == 0, r.stderr
    assert r.stdout.count("skipped (--skip-existing)") == 2, r.stdout
    assert os.path.exists(results[1])
