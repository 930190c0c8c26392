"""The logger sample of missions/logger (a multi-rate log with a 30 s DVL gap, a column
map, NMEA fixes and a mapped mark table) imports with its own documented command and
solves to a tube that holds the simulation's truth on every sample."""
import os
import shlex
import shutil
import subprocess

import numpy as np

import gesmi
from conftest import GESMI

SAMPLE = os.path.join(os.path.dirname(__file__), "..", "..", "missions", "logger")
GESMI_BIN = os.path.abspath(GESMI) if os.sep in GESMI else GESMI  # the tests run it from other folders


def run_import_command(folder):
    """Copies the sample into folder and runs its import-command.txt there."""
    for name in os.listdir(SAMPLE):
        shutil.copy(os.path.join(SAMPLE, name), folder)
    with open(folder / "import-command.txt") as f:
        args = shlex.split(f.read())[1:]
    return subprocess.run([GESMI_BIN, *args], cwd=folder, capture_output=True, text=True)


def import_sample(folder):
    """The sample imported into folder/mission.h5; returns the gesmi binary."""
    r = run_import_command(folder)
    assert r.returncode == 0, r.stderr
    return GESMI_BIN


def test_the_logger_sample_imports_with_its_command_and_holds_the_truth(tmp_path):
    r = run_import_command(tmp_path)
    assert r.returncode == 0, r.stderr
    assert "2 GGA fixes taken" in r.stdout and "t = 0 at 2026-05-14T08:00:00Z" in r.stdout
    # The grid is the rows with a DVL reading, and before the first and after the last of
    # them the other rows and the fixes beyond every row: the sample's first and last rows
    # have a DVL reading and its two fixes are at their times, so the grid is the DVL rows
    # (counted independently in the log), every fix used.
    with open(tmp_path / "log.csv") as f:
        header = f.readline().rstrip("\n").split(";")
        dvl, depth = header.index("dvl_x"), header.index("depth_m")
        rows = [line.rstrip("\n").split(";") for line in f]
    with open(tmp_path / "gps.nmea") as f:
        fix_clock = [line.split(",")[1] for line in f if line.startswith("$GPGGA")]
    assert fix_clock == [rows[i][0][11:19].replace(":", "") + "." + rows[i][0][20:23] for i in (0, -1)]
    assert rows[0][dvl] not in ("", "NaN") and rows[-1][dvl] not in ("", "NaN")
    dvl_rows = [row for row in rows if row[dvl] not in ("", "NaN")]
    m = gesmi.read_mission(str(tmp_path / "mission.h5"))
    assert len(m) == len(dvl_rows) < len(rows)
    assert "0 fixes not usable" in r.stdout and r.stderr == ""
    assert "log.csv: grid: the %d rows with a DVL reading, of %d; longest step" % (len(dvl_rows), len(rows)) in r.stdout
    # The depth at 1 Hz, read on the first and the last row: enclosed between its readings
    # at the DVL rows without one; nothing bridged.
    without_depth = sum(1 for row in dvl_rows if row[depth] == "")
    assert rows[0][depth] != "" and rows[-1][depth] != "" and without_depth > 0
    assert ("log.csv: depth: enclosed by max_depth_rate at %d samples without a reading: %d between its readings\n"
            % (without_depth, without_depth)) in r.stdout, r.stdout
    assert "bridged" not in r.stdout
    s = gesmi.solve(m)
    assert s.consistent
    truth = np.stack([m.truth_x, m.truth_y, m.truth_z], axis=1)
    for axis, tube in enumerate((s.north, s.east, s.down)):
        assert np.all((tube[:, 0] <= truth[:, axis]) & (truth[:, axis] <= tube[:, 1]))
    mines = np.asarray(m.truth_mines).reshape(-1, 3)
    for i in range(m.mine_count):
        for axis in range(3):
            assert s.mines[i, axis, 0] <= mines[i, axis] <= s.mines[i, axis, 1]


def test_results_and_exports_carry_the_logs_epoch(tmp_path):
    import json

    import h5py

    gesmi_bin = import_sample(tmp_path)
    # The first row of log.csv is 2026-05-14T08:00:00.000000Z: t = 0 at that second.
    r = subprocess.run([gesmi_bin, "solve", "mission.h5", "-o", "result.h5", "--geojson"], cwd=tmp_path,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with h5py.File(tmp_path / "mission.h5") as f:
        assert f.attrs["epoch_utc"] in (b"2026-05-14T08:00:00Z", "2026-05-14T08:00:00Z")
    with h5py.File(tmp_path / "result.h5") as f:
        assert f.attrs["epoch_utc"] in (b"2026-05-14T08:00:00Z", "2026-05-14T08:00:00Z")
    r = subprocess.run([gesmi_bin, "kalman", "mission.h5", "-o", "kalman.h5"], cwd=tmp_path, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with h5py.File(tmp_path / "kalman.h5") as f:
        assert f.attrs["epoch_utc"] in (b"2026-05-14T08:00:00Z", "2026-05-14T08:00:00Z")
    with open(tmp_path / "result.geojson") as f:
        envelope = [x for x in json.load(f)["features"] if x["properties"]["kind"] == "envelope"]
    assert envelope[0]["properties"]["epoch_utc"] == "2026-05-14T08:00:00Z"
    # The mission's CSV export passes it on to the import that rebuilds it.
    r = subprocess.run([gesmi_bin, "export", "mission.h5", "-o", "csv"], cwd=tmp_path, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with open(tmp_path / "csv" / "import-command.txt") as f:
        assert "--epoch 2026-05-14T08:00:00Z" in f.read()


def test_config_cannot_silently_miss_bounds_fixed_at_import(tmp_path):
    import h5py

    gesmi_bin = import_sample(tmp_path)
    # The sample's depth is read at 1 Hz: its bounds are per sample, made at import.
    (tmp_path / "deeper.yaml").write_text("depth_absolute: 3\n")
    r = subprocess.run([gesmi_bin, "solve", "mission.h5", "--config", "deeper.yaml", "-o", "r.h5"], cwd=tmp_path,
                       capture_output=True, text=True)
    assert r.returncode == 2 and "depth_absolute" in r.stderr and "import the log again" in r.stderr, r.stderr
    assert not (tmp_path / "r.h5").exists()
    # Its heading is in degrees: a heading bound from --config gets the conversion's margin back.
    (tmp_path / "heading.yaml").write_text("heading: 0.01\n")
    r = subprocess.run([gesmi_bin, "solve", "mission.h5", "--config", "heading.yaml", "-o", "r.h5"], cwd=tmp_path,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with h5py.File(tmp_path / "mission.h5") as f:
        margin = f.attrs["conversion_margin_heading"]
    with h5py.File(tmp_path / "r.h5") as f:
        heading = f["/model"].attrs["heading"]
    assert 0 < margin < 1e-13 and 0.01 < heading <= 0.01 + 2 * margin
    # The sample's 30 s DVL gap: the paper's sample step model cannot cross it.
    (tmp_path / "sample.yaml").write_text("step_model: sample\n")
    r = subprocess.run([gesmi_bin, "solve", "mission.h5", "--config", "sample.yaml", "-o", "r2.h5"], cwd=tmp_path,
                       capture_output=True, text=True)
    assert r.returncode == 2 and "step_model: 'sample' cannot cross" in r.stderr, r.stderr
    assert not (tmp_path / "r2.h5").exists()


def test_a_logger_export_refuses_per_sample_bounds_it_cannot_carry(tmp_path):
    gesmi_bin = import_sample(tmp_path)
    r = subprocess.run([gesmi_bin, "export", "mission.h5", "--format", "logger", "-o", "again"], cwd=tmp_path,
                       capture_output=True, text=True)
    assert r.returncode == 2 and "mission.h5: /nav/half_widths/depth" in r.stderr, r.stderr
    assert not (tmp_path / "again").exists()


def test_the_python_model_mapping_obeys_the_same_rules_as_config(tmp_path):
    gesmi_bin = import_sample(tmp_path)
    m = gesmi.read_mission(str(tmp_path / "mission.h5"))
    depth = m.model["depth_absolute"]
    try:
        m.model["depth_absolute"] = 3.0  # the depth is bounded per sample (read at 1 Hz)
        raise AssertionError("accepted")
    except gesmi.FormatError as e:
        assert "depth_absolute" in str(e)
    assert m.model["depth_absolute"] == depth  # unchanged
    try:
        m.model["step_model"] = "sample"  # the 30 s DVL gap
        raise AssertionError("accepted")
    except gesmi.FormatError as e:
        assert "cannot cross" in str(e)
    m.model["heading"] = 0.01  # in degrees in the log: the margin comes back
    assert 0.01 < m.model["heading"] < 0.01 + 1e-13
    before = gesmi.solve(m).north
    m.model["gps_metres"] = 30.0  # and the fixes' boxes follow at once
    after = gesmi.solve(m).north
    assert np.all(after[:, 0] <= before[:, 0]) and np.any(after[:, 1] - after[:, 0] > before[:, 1] - before[:, 0] + 1.0)
