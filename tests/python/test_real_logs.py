"""Real-log import, end to end: `gesmi export --format logger` folders read back with
their own import command, navigation logs in other layouts built here from a simulated
mission's HDF5 arrays (never from gesmi's output) and read through column maps, NMEA
fixes checked with pynmea2 and against hand-written sentences, and the one-line errors
of bad inputs (exit 2, nothing written).

Expected values come from the simulated mission (h5py) and from independent
computations here: times are built as whole tenths after an epoch at a whole second,
so the times the import reads are known exactly and the truth files can carry them."""
import csv
import datetime
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import types

import h5py
import numpy as np
import pynmea2
import pytest

import gesmi
from conftest import GESMI, run_gesmi

UTC = datetime.timezone.utc
DEFAULT_EPOCH = datetime.datetime(2026, 5, 14, 8, 0, 0, tzinfo=UTC)  # the export's default t = 0
MIDNIGHT_EPOCH = datetime.datetime(2026, 5, 14, 23, 55, 0, tzinfo=UTC)  # a log that crosses midnight
KNOT = 1852.0 / 3600.0  # m/s
FIELDS = ("roll", "pitch", "heading", "vx", "vy", "vz", "altitude", "depth")


def gesmi_path():
    """The gesmi command as an absolute path (the import command runs from inside its folder)."""
    if os.sep in GESMI:
        return os.path.abspath(GESMI)
    return shutil.which(GESMI) or GESMI


def unix(dt):
    return int(dt.timestamp())


def iso_z(dt):
    return dt.astimezone(UTC).strftime("%Y-%m-%dT%H:%M:%SZ")


def nmea_checksum(body):
    """XOR of the characters between '$' and '*' (NMEA 0183), written here independently."""
    total = 0
    for c in body:
        total ^= ord(c)
    return "%02X" % total


def sentence(body):
    return "$" + body + "*" + nmea_checksum(body)


def nmea_angle(degrees, degree_digits, positive, negative):
    minutes = abs(degrees) * 60.0
    whole = int(minutes // 60)
    rest = minutes - 60 * whole
    return "%0*d%010.7f,%s" % (degree_digits, whole, rest, negative if degrees < 0 else positive)


def gga(dt, lat, lon, quality=1):
    return sentence("GPGGA,%s,%s,%s,%d,08,0.9,0.0,M,47.0,M,," % (
        dt.strftime("%H%M%S.") + "%03d" % (dt.microsecond // 1000), nmea_angle(lat, 2, "N", "S"),
        nmea_angle(lon, 3, "E", "W"), quality))


def rmc(dt, lat, lon):
    return sentence("GPRMC,%s,A,%s,%s,0.0,0.0,%s,,,A" % (
        dt.strftime("%H%M%S.") + "%03d" % (dt.microsecond // 1000), nmea_angle(lat, 2, "N", "S"),
        nmea_angle(lon, 3, "E", "W"), dt.strftime("%d%m%y")))


def seconds_text(seconds):
    """A duration as the notes write it: to the millisecond, without trailing zeros."""
    return ("%.3f" % seconds).rstrip("0").rstrip(".")


def summary_line(stdout):
    lines = [line for line in stdout.splitlines() if line.startswith("wrote ")]
    assert len(lines) == 1, stdout
    return lines[0]


def contains_truth(mission, solution):
    """The fraction of samples whose true position lies in the tube, on all three axes."""
    truth = np.stack([mission.truth_x, mission.truth_y, mission.truth_z], axis=1)
    inside = np.ones(len(mission), dtype=bool)
    for axis, tube in enumerate((solution.north, solution.east, solution.down)):
        inside &= (tube[:, 0] <= truth[:, axis]) & (truth[:, axis] <= tube[:, 1])
    return inside.mean()


def check_solution(out_h5, sim, grid):
    """The imported mission at `grid` (indices of the simulated samples) solves to a tube
    that holds the simulator's truth everywhere, and boxes that hold its mines."""
    m = gesmi.read_mission(out_h5)
    assert len(m) == len(grid)
    # The truth the import carries is the simulator's at the grid rows (one per sample).
    np.testing.assert_array_equal(m.truth_x, sim.position[grid, 0])
    np.testing.assert_array_equal(m.truth_y, sim.position[grid, 1])
    np.testing.assert_array_equal(m.truth_z, sim.position[grid, 2])
    s = gesmi.solve(m)
    assert contains_truth(m, s) == 1.0
    assert m.mine_count == len(sim.mines)
    truth_mines = np.asarray(m.truth_mines).reshape(-1, 3)
    np.testing.assert_array_equal(truth_mines, sim.mines)
    for k in range(m.mine_count):
        box = s.mines[k]
        assert np.all((box[:, 0] <= sim.mines[k]) & (sim.mines[k] <= box[:, 1])), (k, box, sim.mines[k])
    for k in set(sim.mark_mine.tolist()):
        if k >= 0:
            assert np.all(np.isfinite(s.mines[k])), (k, s.mines[k])  # a marked mine is located
    return m, s


# ----------------------------------------------------------------------------------------
# The simulated mission, its logger exports


def simulate(tmp_path_factory, errors):
    path = str(tmp_path_factory.mktemp("sim") / "m.h5")
    r = run_gesmi("simulate", "--seed", "11", "--duration", "600", "--errors", errors, "-o", path)
    assert r.returncode == 0, r.stderr
    with h5py.File(path, "r") as f:
        s = types.SimpleNamespace(
            path=path,
            time=f["/nav/time"][()],
            attitude=f["/nav/attitude"][()],
            velocity=f["/nav/velocity"][()],
            altitude=f["/nav/altitude"][()],
            depth=f["/nav/depth"][()],
            gps_time=f["/gps/time"][()],
            gps_lonlat=f["/gps/lonlat"][()],
            mark_time=f["/marks/time"][()],
            mark_mine=f["/marks/mine"][()],
            mark_range=f["/marks/range"][()],
            mark_side=f["/marks/side"][()],
            position=f["/truth/position"][()],
            mines=f["/truth/mines"][()],
            origin=(float(f.attrs["origin_latitude"]), float(f.attrs["origin_longitude"])),
            model={k: (v.decode() if isinstance(v, bytes) else v) for k, v in f["/model"].attrs.items()},
        )
    n = len(s.time)
    assert n == 6001
    # Samples at 10 Hz: row k is k tenths of a second after t = 0 (the logs below rely on it).
    np.testing.assert_allclose(s.time, np.arange(n) / 10.0, rtol=0, atol=1e-9)
    assert len(s.gps_time) >= 2 and len(s.mark_time) >= 1 and len(s.mines) == 6
    # The heading crosses north: a log writing it in [0, 360) wraps between readings.
    assert s.attitude[:, 2].min() < 0.0 < s.attitude[:, 2].max()
    return s


@pytest.fixture(scope="session")
def sim(tmp_path_factory):
    """A ten-minute simulated mission, sensor errors drawn uniformly within the bounds."""
    return simulate(tmp_path_factory, "uniform")


@pytest.fixture(scope="session", params=["uniform", "worst-case"])
def any_sim(request, sim, tmp_path_factory):
    """The mission above, and the same one with every error at the end of its bound."""
    return sim if request.param == "uniform" else simulate(tmp_path_factory, "worst-case")


def export_logger(sim, folder, *extra):
    r = run_gesmi("export", sim.path, "--format", "logger", "-o", str(folder), *extra)
    assert r.returncode == 0, r.stderr
    return str(folder)


@pytest.fixture(scope="session")
def logger(sim, tmp_path_factory):
    """The export with a 30 s DVL gap and the depth every 10 rows (default epoch)."""
    return export_logger(sim, tmp_path_factory.mktemp("logger") / "out", "--dvl-gap", "200:230", "--depth-every", "10")


@pytest.fixture(scope="session")
def midnight_logger(sim, tmp_path_factory):
    """The export of a log that starts at 23:55 UTC and ends after midnight."""
    return export_logger(sim, tmp_path_factory.mktemp("midnight") / "out", "--epoch", iso_z(MIDNIGHT_EPOCH))


@pytest.fixture(scope="session")
def reimported(logger, tmp_path_factory):
    """The logger folder imported with its own import-command.txt, run from inside it."""
    folder = str(tmp_path_factory.mktemp("reimport") / "folder")
    shutil.copytree(logger, folder)
    with open(os.path.join(folder, "import-command.txt")) as f:
        command = shlex.split(f.read())
    assert command[:3] == ["gesmi", "import", "nav"]
    r = subprocess.run([gesmi_path(), *command[1:]], capture_output=True, text=True, cwd=folder)
    out = os.path.join(folder, command[command.index("-o") + 1])
    return types.SimpleNamespace(result=r, folder=folder, out=out, command=command)


def read_semicolon_log(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f, delimiter=";"))
    return rows[0], rows[1:]


def iso_seconds_after(text, epoch_seconds):
    """An ISO 8601 UTC time with a decimal fraction, in seconds after a whole epoch second,
    as the import computes it: whole seconds + the nearest double to the fraction."""
    assert text.endswith("Z"), text
    whole, _, fraction = text[:-1].partition(".")
    dt = datetime.datetime.strptime(whole, "%Y-%m-%dT%H:%M:%S").replace(tzinfo=UTC)
    return float(unix(dt) - epoch_seconds) + (float("0." + fraction) if fraction else 0.0)


def logger_dvl_rows(sim, dvl_every=2, gap=None):
    """The DVL rows of a logger export, from the simulated times."""
    n = len(sim.time)
    return [k for k in range(n)
            if (k % dvl_every == 0 or k == n - 1) and not (gap and gap[0] <= sim.time[k] <= gap[1])]


def expected_logger_grid(sim, dvl_every=2, gap=None, depth_every=10, max_gap=60.0):
    """The mission's samples from a logger export (every row has the attitude, the depth
    every `depth_every` rows): the DVL rows, and before the first and after the last of
    them every other row within the usable span (docs/formats.md, "Multi-rate rows and
    gaps"). The simulated fixes are on rows: they add no sample."""
    n = len(sim.time)
    dvl = logger_dvl_rows(sim, dvl_every, gap)
    depth = [k for k in range(n) if k % depth_every == 0]
    first = max(sim.time[0], sim.time[depth[0]]) - max_gap
    last = min(sim.time[-1], sim.time[depth[-1]]) + max_gap
    return sorted(set(dvl) | {k for k in range(n) if (k < dvl[0] or k > dvl[-1]) and first <= sim.time[k] <= last})


# ----------------------------------------------------------------------------------------
# The grid and the import's notes, computed here from a log's readings (docs/formats.md,
# "Multi-rate rows and gaps", "NMEA 0183 fixes"; io/imports/nav_grid.h)

ENCLOSED = ("roll", "pitch", "heading", "depth")  # the channels a usable fix needs a reading of nearby
# The import's lines, in its order: the channel (vx for the DVL's three), how and by which model key.
FILL_ORDER = (("vx", "bridged", "surface_max_speed"), ("roll", "enclosed", "max_attitude_rate"),
              ("pitch", "enclosed", "max_attitude_rate"), ("heading", "enclosed", "max_attitude_rate"),
              ("altitude", "enclosed", "max_altitude_rate"), ("depth", "enclosed", "max_depth_rate"))
LOGGER_COLUMNS = {"roll": "roll_deg", "pitch": "pitch_deg", "heading": "hdg_deg", "vx": "dvl_x", "vy": "dvl_y",
                  "vz": "dvl_z", "altitude": "alt_m", "depth": "depth_m"}
NO_READING = ("", "nan", "NaN")


def log_readings(rows, row_time, has):
    """A log as the import reads it: `rows` the file's rows (line = index + 2), `row_time`
    the time of each, `has(i, channel)` whether row i has a reading of the channel.
    Returns the row count, the times and lines of the rows with some reading, and each
    channel's reading times."""
    present = [i for i in range(rows) if any(has(i, c) for c in FIELDS)]
    return types.SimpleNamespace(
        rows=rows, row_time=[row_time[i] for i in present], row_line=[i + 2 for i in present],
        readings={c: [row_time[i] for i in range(rows) if has(i, c)] for c in FIELDS})


def read_logger_readings(path, epoch_seconds):
    """log_readings() of a logger export's log.csv, its times read as the import reads them."""
    header, rows = read_semicolon_log(path)
    col = {name: i for i, name in enumerate(header)}
    times = [iso_seconds_after(row[col["timestamp"]], epoch_seconds) for row in rows]
    return log_readings(len(rows), times, lambda i, c: rows[i][col[LOGGER_COLUMNS[c]]] not in NO_READING)


def usable_span(log, max_gap=60.0):
    """The times a fix can be used at: within max_gap of a reading of every attitude and
    depth channel (the DVL and the altitude are bridged or enclosed without it)."""
    return (max(log.readings[c][0] for c in ENCLOSED) - max_gap,
            min(log.readings[c][-1] for c in ENCLOSED) + max_gap)


def expected_grid(log, fix_times=(), max_gap=60.0):
    """The mission's sample times: the DVL's readings, and before the first and after the
    last of them the other rows with a reading and the fixes' times beyond every row,
    within the usable span. Returns them, and the fixes used."""
    first, last = usable_span(log, max_gap)
    used = [t for t in fix_times if first <= t <= last]
    dvl = log.readings["vx"]
    extra = [t for t in log.row_time if (t < dvl[0] or t > dvl[-1]) and first <= t <= last]
    extra += [t for t in used if t < log.row_time[0] or t > log.row_time[-1]]
    return sorted(set(dvl) | set(extra)), used


def expected_grid_note(log, grid):
    """'grid: the D rows with a DVL reading, of M[, and B samples before and after them];
    longest step X s (lines a-b | from T1 s to T2 s, a fix's time)'."""
    line = {}
    for t, n in zip(log.row_time, log.row_line):
        line.setdefault(t, n)
    steps = np.diff(grid)
    at = int(np.argmax(steps))  # the first of the longest
    a, b = grid[at], grid[at + 1]
    where = ("lines %d-%d" % (line[a], line[b]) if a in line and b in line
             else "from %s s to %s s, a fix's time" % (seconds_text(a), seconds_text(b)))
    dvl = len(log.readings["vx"])
    more = ", and %d samples before and after them" % (len(grid) - dvl) if len(grid) > dvl else ""
    return "grid: the %d rows with a DVL reading, of %d%s; longest step %s s (%s)" % (
        dvl, log.rows, more, seconds_text(steps[at]), where)


def expected_fill(log, grid):
    """Per channel (FILL_ORDER), the grid samples without a reading of it: before its
    first reading, between its readings, after its last; with those readings' times."""
    out = []
    for channel, how, key in FILL_ORDER:
        times = log.readings[channel]
        own = set(times)
        missing = [t for t in grid if t not in own]
        out.append(types.SimpleNamespace(
            channel=channel, how=how, key=key, first=times[0], last=times[-1],
            before=sum(1 for t in missing if t < times[0]), after=sum(1 for t in missing if t > times[-1]),
            between=sum(1 for t in missing if times[0] < t < times[-1])))
    return out


def expected_fill_lines(log, grid):
    """The import's line for each channel it bridged or enclosed at some grid sample."""
    lines = []
    for f in expected_fill(log, grid):
        parts = []
        if f.before:
            parts.append("%d before its first reading (%s s)" % (f.before, seconds_text(f.first)))
        if f.between:
            parts.append("%d between its readings" % f.between)
        if f.after:
            parts.append("%d after its last reading (%s s)" % (f.after, seconds_text(f.last)))
        if parts:
            lines.append("%s: %s by %s at %d samples without a reading: %s" % (
                "vx, vy, vz" if f.channel == "vx" else f.channel, f.how, f.key, f.before + f.between + f.after,
                ", ".join(parts)))
    return lines


def check_nav_notes(stdout, source, log, grid):
    """The import's notes about the navigation log `source`: the grid, then one line per
    channel it filled, nothing else."""
    notes = [line[len(source) + 2:] for line in stdout.splitlines() if line.startswith(source + ": ")]
    assert notes == [expected_grid_note(log, grid)] + expected_fill_lines(log, grid), stdout


# ----------------------------------------------------------------------------------------
# 1. The logger export and its own import command


def test_logger_log_csv_holds_the_mission_at_its_rates(sim, logger):
    header, rows = read_semicolon_log(os.path.join(logger, "log.csv"))
    assert header == ["timestamp", "hdg_deg", "depth_m", "status", "dvl_x", "dvl_y", "dvl_z",
                      "pitch_deg", "alt_m", "roll_deg", "water_temp"]
    assert len(rows) == len(sim.time)
    col = {name: i for i, name in enumerate(header)}
    epoch = unix(DEFAULT_EPOCH)
    grid = set(logger_dvl_rows(sim, 2, (200.0, 230.0)))
    for k, row in enumerate(rows):
        assert len(row) == len(header)
        assert re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{6}Z", row[col["timestamp"]]), row[0]
        assert abs(iso_seconds_after(row[col["timestamp"]], epoch) - sim.time[k]) <= 1e-6
        roll, pitch, heading = sim.attitude[k]
        assert float(row[col["roll_deg"]]) == pytest.approx(math.degrees(roll), rel=1e-12, abs=1e-12)
        assert float(row[col["pitch_deg"]]) == pytest.approx(math.degrees(pitch), rel=1e-12, abs=1e-12)
        assert float(row[col["hdg_deg"]]) == pytest.approx(math.degrees(heading), rel=1e-12, abs=1e-12)
        if k % 10 == 0:
            assert float(row[col["depth_m"]]) == sim.depth[k]
        else:
            assert row[col["depth_m"]] == ""
        in_gap = 200.0 <= sim.time[k] <= 230.0
        dvl = [row[col[c]] for c in ("dvl_x", "dvl_y", "dvl_z")]
        if in_gap:
            assert dvl == ["NaN"] * 3, (k, dvl)
            assert row[col["alt_m"]] == ""
        elif k in grid:
            assert [float(v) for v in dvl] == sim.velocity[k].tolist()
            assert float(row[col["alt_m"]]) == sim.altitude[k]
        else:
            assert dvl == [""] * 3 and row[col["alt_m"]] == ""


def test_logger_export_reimports_with_its_own_command_and_holds_the_truth(sim, logger, reimported):
    r = reimported.result
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    # The DVL rows of log.csv, counted here. The first and the last row have a DVL reading
    # (the gap is inside) and the fixes are on rows: the imported mission's samples.
    header, rows = read_semicolon_log(os.path.join(logger, "log.csv"))
    dvl_x = header.index("dvl_x")
    dvl_rows = [row for row in rows if row[dvl_x] not in NO_READING]
    assert rows[0][dvl_x] not in NO_READING and rows[-1][dvl_x] not in NO_READING
    assert len(dvl_rows) == len(logger_dvl_rows(sim, 2, (200.0, 230.0)))
    grid = expected_logger_grid(sim, 2, (200.0, 230.0))
    assert grid == logger_dvl_rows(sim, 2, (200.0, 230.0))
    m = gesmi.read_mission(reimported.out)
    assert len(m) == len(dvl_rows)
    # The grid: the DVL rows' times after the whole second of the first row, read here.
    epoch = unix(DEFAULT_EPOCH)
    expected_time = [iso_seconds_after(row[0], epoch) for row in dvl_rows]
    np.testing.assert_array_equal(m.time, np.array(expected_time))
    # The notes: the epoch of t = 0, the grid, the depth enclosed between its readings.
    summary = summary_line(r.stdout)
    assert summary.endswith("t = 0 at " + iso_z(DEFAULT_EPOCH)), summary
    assert "%d samples" % len(grid) in summary
    assert "%d GPS fixes" % len(sim.gps_time) in summary
    assert "%d marks" % len(sim.mark_time) in summary
    assert re.search(r"grid: the %d rows with a DVL reading, of %d;" % (len(grid), len(sim.time)), r.stdout), r.stdout
    longest = max(b - a for a, b in zip(expected_time, expected_time[1:]))
    assert 30.0 < longest < 31.0
    assert "longest step %s s" % seconds_text(longest) in r.stdout, r.stdout
    depth_on_grid = sum(1 for k in grid if k % 10 == 0)
    assert ("log.csv: depth: enclosed by max_depth_rate at %d samples without a reading: %d between its readings\n"
            % ((len(grid) - depth_on_grid,) * 2)) in r.stdout, r.stdout
    log = read_logger_readings(os.path.join(logger, "log.csv"), epoch)
    assert expected_grid(log, list(sim.gps_time))[0] == expected_time
    check_nav_notes(r.stdout, "log.csv", log, expected_time)
    # The export's truth is on every row of the log; the import took the grid's rows.
    with open(os.path.join(logger, "truth.csv")) as f:
        truth_rows = list(csv.reader(f))
    assert truth_rows[0] == ["time", "north", "east", "down"] and len(truth_rows) == len(rows) + 1
    assert len(log.row_time) == len(rows)  # every row has a reading (the attitude)
    np.testing.assert_array_equal([float(row[0]) for row in truth_rows[1:]], log.row_time)
    assert re.search(r"\b%d GGA fixes taken; skipped: 0 sentences with a bad checksum, 0 GGA without a fix"
                     % len(sim.gps_time), r.stdout), r.stdout
    # GPS and marks carried through the NMEA and ISO 8601 files.
    np.testing.assert_allclose(m.gps_time, sim.gps_time, rtol=0, atol=1e-3)
    np.testing.assert_allclose(m.gps_longitude, sim.gps_lonlat[:, 0], rtol=0, atol=1e-7)
    np.testing.assert_allclose(m.gps_latitude, sim.gps_lonlat[:, 1], rtol=0, atol=1e-7)
    order = np.argsort(m.mark_time)
    expected_order = np.argsort(sim.mark_time)
    np.testing.assert_allclose(np.asarray(m.mark_time)[order], sim.mark_time[expected_order], rtol=0, atol=1e-6)
    np.testing.assert_array_equal(np.asarray(m.mark_mine)[order], sim.mark_mine[expected_order])
    np.testing.assert_array_equal(np.asarray(m.mark_range)[order], sim.mark_range[expected_order])
    np.testing.assert_array_equal(np.asarray(m.mark_side)[order], sim.mark_side[expected_order])
    # The tube holds the truth at every sample, the boxes the mines.
    check_solution(reimported.out, sim, grid)


def test_logger_export_of_a_log_across_midnight(sim, midnight_logger, tmp_path):
    folder = str(tmp_path / "folder")
    shutil.copytree(midnight_logger, folder)
    with open(os.path.join(folder, "import-command.txt")) as f:
        command = shlex.split(f.read())
    r = subprocess.run([gesmi_path(), *command[1:]], capture_output=True, text=True, cwd=folder)
    assert r.returncode == 0, r.stderr
    assert summary_line(r.stdout).endswith("t = 0 at " + iso_z(MIDNIGHT_EPOCH))
    m = gesmi.read_mission(os.path.join(folder, command[command.index("-o") + 1]))
    # The fix after midnight is dated on the next day by its RMC: at its own time.
    np.testing.assert_allclose(m.gps_time, sim.gps_time, rtol=0, atol=1e-3)
    check_solution(os.path.join(folder, command[command.index("-o") + 1]), sim, expected_logger_grid(sim, 2))


def test_the_epoch_is_stored_and_passed_on_by_the_csv_export(reimported, tmp_path):
    assert reimported.result.returncode == 0, reimported.result.stderr
    with h5py.File(reimported.out, "r") as f:
        stored = f.attrs["epoch_utc"]
    assert (stored.decode() if isinstance(stored, bytes) else stored) == iso_z(DEFAULT_EPOCH)
    folder = str(tmp_path / "csv")
    r = run_gesmi("export", reimported.out, "-o", folder)
    assert r.returncode == 0, r.stderr
    with open(os.path.join(folder, "import-command.txt")) as f:
        command = shlex.split(f.read())
    r = subprocess.run([gesmi_path(), *command[1:]], capture_output=True, text=True, cwd=folder)
    assert r.returncode == 0, r.stderr
    assert summary_line(r.stdout).endswith("t = 0 at " + iso_z(DEFAULT_EPOCH))
    first, again = gesmi.read_mission(reimported.out), gesmi.read_mission(os.path.join(folder, "mission.h5"))
    np.testing.assert_array_equal(again.time, first.time)
    np.testing.assert_array_equal(again.gps_time, first.gps_time)


@pytest.mark.parametrize("options", [
    ("--dvl-gap", "0:10"),  # no DVL at the start: the rows before its first reading are samples, the DVL bridged
    ("--dvl-gap", "590:600"),  # nor at the end: the rows after its last one, and the last fix, too
    ("--dvl-every", "7", "--depth-every", "13"),  # the last row keeps its DVL reading
], ids=["gap_at_start", "gap_at_end", "every_7th"])
def test_logger_export_options_reimport(sim, tmp_path, options):
    folder = export_logger(sim, tmp_path / "out", *options)
    with open(os.path.join(folder, "import-command.txt")) as f:
        command = shlex.split(f.read())
    r = subprocess.run([gesmi_path(), *command[1:]], capture_output=True, text=True, cwd=folder)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""  # no fix left unused
    every = int(options[1]) if options[0] == "--dvl-every" else 2
    gap = tuple(float(x) for x in options[1].split(":")) if options[0] == "--dvl-gap" else None
    depth_every = int(options[3]) if "--depth-every" in options else 10
    grid = expected_logger_grid(sim, every, gap, depth_every)
    # The log as written, read here: the grid, the fixes it can use, the notes.
    log = read_logger_readings(os.path.join(folder, "log.csv"), unix(DEFAULT_EPOCH))
    times, used = expected_grid(log, list(sim.gps_time))
    np.testing.assert_allclose(times, sim.time[grid], rtol=0, atol=1e-6)
    first, last = usable_span(log)
    usable = sum(1 for t in sim.gps_time if first <= t <= last)
    assert usable == len(used) == len(sim.gps_time)  # the fixes at 0 and 600 s, even where the DVL is silent
    assert nmea_counts(r.stdout) == (usable, 0, 0, len(sim.gps_time) - usable)
    check_nav_notes(r.stdout, "log.csv", log, times)
    assert summary_line(r.stdout).endswith("t = 0 at " + iso_z(DEFAULT_EPOCH))
    out = os.path.join(folder, command[command.index("-o") + 1])
    m, _ = check_solution(out, sim, grid)
    np.testing.assert_array_equal(m.time, times)
    np.testing.assert_allclose(m.gps_time, sim.gps_time, rtol=0, atol=1e-3)
    # Where the DVL has no reading it is bridged: 0 +- surface_max_speed on each component,
    # and every DVL row then carries its own bound (dvl_relative |v| + dvl_absolute).
    dvl_times = set(log.readings["vx"])
    bridged = np.array([t not in dvl_times for t in times])
    assert bridged.any() == (gap is not None)
    fill = expected_fill(log, times)[0]  # the DVL's
    assert fill.channel == "vx" and fill.between == 0 and fill.before + fill.after == int(bridged.sum())
    with h5py.File(out, "r") as f:
        velocity = f["/nav/velocity"][()]
        model = f["/model"].attrs
        for axis, name in enumerate(("vx", "vy", "vz")):
            path = "/nav/half_widths/" + name
            if not bridged.any():
                assert path not in f
                continue
            hw = f[path][()]
            assert np.all(velocity[bridged, axis] == 0.0) and np.all(hw[bridged] == model["surface_max_speed"])
            own = model["dvl_relative"] * np.abs(velocity[~bridged, axis]) + model["dvl_absolute"]
            assert np.all(hw[~bridged] >= own) and np.all(hw[~bridged] <= own * (1 + 1e-12))
            attrs = f[path].attrs
            assert (attrs["filled_by"].decode() if isinstance(attrs["filled_by"], bytes) else attrs["filled_by"]) \
                == "surface_max_speed"
            assert (int(attrs["samples_before_first_reading"]), int(attrs["samples_between_readings"]),
                    int(attrs["samples_after_last_reading"])) == (fill.before, 0, fill.after)


# ----------------------------------------------------------------------------------------
# 2. Logs in other layouts, built here from the HDF5 arrays


def write_model_yaml(sim, path):
    with open(path, "w") as f:
        for key, value in sim.model.items():
            f.write("%s: %s\n" % (key, value if isinstance(value, str) else repr(float(value))))


class LogLayout:
    """A navigation log built from the simulated arrays, and its column map.

    `time_format`: seconds (the simulated times as written), epoch (Unix seconds) or
    iso (with `offset` appended, or none and `map_timezone` in the map). Absolute times
    are whole tenths after `epoch` (a whole second), so the import reads
    k // 10 + 0.(k % 10) for row k."""

    def __init__(self, sim, *, rows=None, delimiter=",", map_delimiter=None, time_format="seconds",
                 epoch=DEFAULT_EPOCH, offset="Z", map_timezone=None, angle_unit="rad", speed_unit="m/s",
                 dvl=None, attitude=None, depth=None, altitude=None, names=None, order=None, extra=None,
                 absent="", shuffle_seed=None, heading_0_360=False):
        n = len(sim.time)
        self.sim = sim
        self.rows = list(range(n)) if rows is None else list(rows)
        self.delimiter = delimiter
        self.map_delimiter = map_delimiter
        self.time_format = time_format
        self.epoch = epoch
        self.offset = offset
        self.map_timezone = map_timezone
        self.angle_unit = angle_unit
        self.speed_unit = speed_unit
        everywhere = lambda k: True
        self.dvl = dvl or everywhere
        self.attitude = attitude or everywhere
        self.depth = depth or everywhere
        self.altitude = altitude or self.dvl
        self.names = {"time": "time", **{f: f for f in FIELDS}, **(names or {})}
        self.extra = extra or {}
        columns = ["time", *FIELDS, *self.extra]
        if order is not None:
            columns = list(order)
        elif shuffle_seed is not None:
            np.random.default_rng(shuffle_seed).shuffle(columns)
        self.columns = columns
        self.absent = absent
        self.heading_0_360 = heading_0_360
        self.map_lines = {}

    # Values as written and as read ------------------------------------------------
    def time_text(self, k):
        if self.time_format == "seconds":
            return repr(float(self.sim.time[k]))
        whole, tenth = divmod(k, 10)
        if self.time_format == "epoch":
            return "%d.%d" % (unix(self.epoch) + whole, tenth)
        offset = datetime.timedelta(0)
        if self.offset not in ("Z", ""):
            sign = 1 if self.offset[0] == "+" else -1
            hours, minutes = self.offset[1:].split(":")
            offset = sign * datetime.timedelta(hours=int(hours), minutes=int(minutes))
        elif self.offset == "" and self.map_timezone not in (None, "UTC"):
            sign = 1 if self.map_timezone[0] == "+" else -1
            hours, minutes = self.map_timezone[1:].split(":")
            offset = sign * datetime.timedelta(hours=int(hours), minutes=int(minutes))
        local = (self.epoch + datetime.timedelta(seconds=whole) + offset).replace(tzinfo=None)
        return local.strftime("%Y-%m-%dT%H:%M:%S") + ".%d" % tenth + self.offset

    def read_time(self, k):
        """The time the import reads for row k, in seconds after its epoch."""
        if self.time_format == "seconds":
            return float(self.sim.time[k])
        whole, tenth = divmod(k, 10)
        return float(whole - self.rows[0] // 10) + float("0.%d" % tenth)

    def angle(self, x):
        return repr(math.degrees(x)) if self.angle_unit == "deg" else repr(float(x))

    def heading(self, x):
        if not self.heading_0_360:
            return self.angle(x)
        return repr(math.degrees(x) % 360.0) if self.angle_unit == "deg" else repr(float(x) % (2 * math.pi))

    def speed(self, v):
        return repr(v / KNOT) if self.speed_unit == "knots" else repr(float(v))

    def values(self, k):
        s = self.sim
        roll, pitch, heading = s.attitude[k]
        vx, vy, vz = s.velocity[k]
        a, d, v = self.attitude(k), self.depth(k), self.dvl(k)
        out = {
            "time": self.time_text(k),
            "roll": self.angle(roll) if a else self.absent,
            "pitch": self.angle(pitch) if a else self.absent,
            "heading": self.heading(heading) if a else self.absent,
            "vx": self.speed(vx) if v else self.absent,
            "vy": self.speed(vy) if v else self.absent,
            "vz": self.speed(vz) if v else self.absent,
            "altitude": repr(float(s.altitude[k])) if self.altitude(k) else self.absent,
            "depth": repr(float(s.depth[k])) if d else self.absent,
        }
        for name, text in self.extra.items():
            out[name] = text(k) if callable(text) else text
        return out

    def log_readings(self):
        """The log as the import reads it (log_readings()), computed from the layout."""
        has = {"roll": self.attitude, "pitch": self.attitude, "heading": self.attitude, "vx": self.dvl,
               "vy": self.dvl, "vz": self.dvl, "altitude": self.altitude, "depth": self.depth}
        return log_readings(len(self.rows), [self.read_time(k) for k in self.rows],
                            lambda i, c: bool(has[c](self.rows[i])))

    def fix_times(self):
        """The simulated fixes the import can use, within the usable span of the log. The
        fixes are written in the simulation's seconds: t = 0 must be its first second."""
        assert self.rows[0] < 10
        first, last = usable_span(self.log_readings())
        return [float(t) for t in self.sim.gps_time if first <= t <= last]

    def samples(self):
        """The mission's samples: (time as the import reads it, simulated sample)."""
        if not hasattr(self, "_samples"):
            times, used = expected_grid(self.log_readings(), self.fix_times())
            sample = {self.read_time(k): k for k in self.rows}
            for t in used:
                k = int(round(t * 10))
                assert abs(self.sim.time[k] - t) < 1e-9  # a fix at a simulated sample's time
                sample.setdefault(t, k)
            self._samples = [(t, sample[t]) for t in times]
        return self._samples

    @property
    def grid(self):
        """The simulated samples at the mission's samples."""
        return [k for _, k in self.samples()]

    @property
    def grid_times(self):
        return [t for t, _ in self.samples()]

    # Files -------------------------------------------------------------------------
    def header(self):
        return [self.names.get(c, c) for c in self.columns]

    def write_log(self, path, edit=None):
        lines = [self.delimiter.join(self.header())]
        for k in self.rows:
            values = self.values(k)
            if edit:
                edit(k, values)
            lines.append(self.delimiter.join(values[c] for c in self.columns))
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")

    def map_text(self, max_gap=None, drop_unit=None, unit_override=None, column_override=None):
        lines = ["# column map written by test_real_logs.py"]
        if self.map_delimiter is not None:
            lines.append("delimiter: %s" % self.map_delimiter)
        fmt = {"seconds": "seconds", "epoch": "epoch", "iso": "iso8601"}[self.time_format]
        tz = ", timezone: \"%s\"" % self.map_timezone if self.map_timezone else ""
        lines.append("time: {column: %s, format: %s%s}" % (self.names["time"], fmt, tz))
        units = {"roll": self.angle_unit, "pitch": self.angle_unit, "heading": self.angle_unit,
                 "vx": self.speed_unit, "vy": self.speed_unit, "vz": self.speed_unit, "altitude": "m", "depth": "m"}
        units.update(unit_override or {})
        for field in FIELDS:
            column = (column_override or {}).get(field, self.names[field])
            unit = "" if field == drop_unit else ", unit: %s" % units[field]
            self.map_lines[field] = len(lines) + 1
            lines.append("%s: {column: %s%s}" % (field, column, unit))
        if max_gap is not None:
            lines.append("max_gap: %s" % max_gap)
        return "\n".join(lines) + "\n"

    def write_map(self, path, **kwargs):
        with open(path, "w") as f:
            f.write(self.map_text(**kwargs))

    def write_truth(self, path):
        """The truth on every row of the log and at the samples between none (a fix's
        time outside the rows), as a logger export writes it: the import takes the
        samples' rows."""
        rows = {self.read_time(k): k for k in self.rows}
        rows.update(self.samples())
        with open(path, "w") as f:
            f.write("time,north,east,down\n")
            for t in sorted(rows):
                f.write("%r,%r,%r,%r\n" % (t, *(float(x) for x in self.sim.position[rows[t]])))

    def write_aux(self, folder):
        """gps.csv (the fixes the import can use), marks.csv (seconds after t = 0, within
        the mission), truth_mines.csv and model.yaml."""
        s = self.sim
        t0, t1 = self.grid_times[0], self.grid_times[-1]
        paths = {name: os.path.join(folder, name) for name in ("gps.csv", "marks.csv", "truth_mines.csv", "model.yaml")}
        used = set(self.fix_times())
        with open(paths["gps.csv"], "w") as f:
            f.write("time,longitude,latitude\n")
            for t, (lon, lat) in zip(s.gps_time, s.gps_lonlat):
                if float(t) in used:
                    f.write("%r,%r,%r\n" % (float(t), float(lon), float(lat)))
        with open(paths["marks.csv"], "w") as f:
            f.write("time,mine,range,side\n")
            for t, mine, rng, side in zip(s.mark_time, s.mark_mine, s.mark_range, s.mark_side):
                if not t0 <= t <= t1:
                    continue
                f.write("%r,%s,%r,%s\n" % (float(t), "?" if mine < 0 else int(mine), float(rng),
                                           "starboard" if side > 0 else "port"))
        with open(paths["truth_mines.csv"], "w") as f:
            f.write("mine,north,east,down\n")
            for i, (n_, e_, d_) in enumerate(s.mines):
                f.write("%d,%r,%r,%r\n" % (i, float(n_), float(e_), float(d_)))
        write_model_yaml(s, paths["model.yaml"])
        return paths


def import_layout(layout, folder, *extra_args, map_kwargs=None):
    folder = str(folder)
    log, map_, truth = (os.path.join(folder, n) for n in ("log.txt", "map.yaml", "truth.csv"))
    layout.write_log(log)
    layout.write_map(map_, **(map_kwargs or {}))
    layout.write_truth(truth)
    aux = layout.write_aux(folder)
    out = os.path.join(folder, "mission.h5")
    r = run_gesmi("import", "nav", log, "--map", map_, "--gps", aux["gps.csv"], "--marks", aux["marks.csv"],
                  "--config", aux["model.yaml"], "--origin", "%r,%r" % layout.sim.origin, "--mines",
                  str(len(layout.sim.mines)), "--truth", truth, "--truth-mines", aux["truth_mines.csv"], "-o", out,
                  *extra_args)
    return r, out


LAYOUTS = {
    # (a) comma CSV, Unix epoch seconds, degrees, columns shuffled, extra text columns.
    "comma_epoch_degrees_shuffled": dict(
        delimiter=",", map_delimiter='","', time_format="epoch", angle_unit="deg", shuffle_seed=7,
        names={"time": "unix_time", "roll": "Roll(deg)", "pitch": "Pitch(deg)", "heading": "Heading(deg)",
               "vx": "u", "vy": "v", "vz": "w", "altitude": "Alt", "depth": "Depth"},
        extra={"vehicle": "AUV-3 survey", "mode": lambda k: "TRACK" if k % 50 else "FIX", "seq": lambda k: str(k)},
        dvl=lambda k: k % 2 == 0, depth=lambda k: k % 5 == 0),
    # (b) tab-separated, ISO 8601 local times with a +02:00 offset.
    # The first row 0.7 s after a whole second: t = 0 is that second, the time of the
    # first fix, and the first DVL reading 0.8 s after it: the mission starts at the fix.
    "tab_iso_plus_two_hours": dict(
        delimiter="\t", map_delimiter="tab", time_format="iso", offset="+02:00", angle_unit="deg",
        names={"time": "Local time"}, extra={"note": "-"}, dvl=lambda k: k % 2 == 0, rows=range(7, 6001)),
    # (b'') a negative offset; the local date changes at 00:00-05:30 during the log.
    "comma_iso_minus_0530_local_midnight": dict(
        delimiter=",", time_format="iso", offset="-05:30", angle_unit="deg",
        epoch=datetime.datetime(2026, 5, 15, 5, 25, 0, tzinfo=UTC), dvl=lambda k: k % 2 == 0),
    # (b') the same offset given by the map for times written without a zone.
    "tab_iso_zone_from_map": dict(
        delimiter="\t", map_delimiter='"\\t"', time_format="iso", offset="", map_timezone="+02:00",
        angle_unit="rad", dvl=lambda k: k % 2 == 0),
    # (c) whitespace-separated (detected), seconds, radians, speeds in knots, nan = absent.
    "whitespace_seconds_radians_knots": dict(
        delimiter="   ", time_format="seconds", angle_unit="rad", speed_unit="knots", absent="nan",
        dvl=lambda k: k % 2 == 0, depth=lambda k: k % 4 == 0),
    # (d) DVL every 3rd row, attitude only on the rows without DVL, depth every 20 rows.
    "multirate_attitude_off_grid": dict(
        delimiter=";", time_format="epoch", angle_unit="deg",
        dvl=lambda k: k % 3 == 0, attitude=lambda k: k % 3 != 0, depth=lambda k: k % 20 == 0),
    # (d') the same with the heading written in [0, 360) degrees: it wraps at north.
    "multirate_heading_0_360": dict(
        delimiter=";", time_format="epoch", angle_unit="deg", heading_0_360=True,
        dvl=lambda k: k % 3 == 0, attitude=lambda k: k % 3 != 0, depth=lambda k: k % 20 == 0),
    # (e) a 30 s DVL gap (altitude with it), ISO 8601 UTC.
    "dvl_gap_30s": dict(
        delimiter=",", time_format="iso", offset="Z", angle_unit="deg",
        dvl=lambda k: k % 2 == 0 and not (2000 <= k <= 2300), depth=lambda k: k % 10 == 0),
}


@pytest.mark.parametrize("name", sorted(LAYOUTS))
def test_own_log_layouts_import_and_hold_the_truth(any_sim, tmp_path, name):
    sim = any_sim
    layout = LogLayout(sim, **LAYOUTS[name])
    r, out = import_layout(layout, tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    grid = layout.grid
    m = gesmi.read_mission(out)
    assert len(m) == len(grid)
    np.testing.assert_array_equal(m.time, np.array(layout.grid_times))
    summary = summary_line(r.stdout)
    if layout.time_format == "seconds":
        assert "t = 0 at" not in summary
    else:
        assert summary.endswith("t = 0 at " + iso_z(layout.epoch)), summary
    dvl = [k for k in layout.rows if layout.dvl(k)]
    assert re.search(r"grid: the %d rows with a DVL reading, of %d[;,]" % (len(dvl), len(layout.rows)), r.stdout), r.stdout
    # The grid, and one line per channel with grid samples without their own reading:
    # before its first reading, between its readings, after its last.
    log = layout.log_readings()
    check_nav_notes(r.stdout, str(tmp_path / "log.txt"), log, layout.grid_times)
    if name == "tab_iso_plus_two_hours":
        # The log starts 0.7 s after the whole second of t = 0, with the fix at 0 s: the
        # mission starts at that fix, row 7 (no DVL) is a sample, the DVL bridged on both.
        assert layout.grid_times[:3] == [0.0, 0.7, 0.8] and grid[:3] == [0, 7, 8]
        assert "longest step 0.7 s (from 0 s to 0.7 s, a fix's time)" in r.stdout, r.stdout
        assert "vx, vy, vz: bridged by surface_max_speed at 2 samples without a reading: 2 before its first " \
               "reading (0.8 s)" in r.stdout, r.stdout
        assert "roll: enclosed by max_attitude_rate at 1 samples without a reading: 1 before its first " \
               "reading (0.7 s)" in r.stdout, r.stdout
        np.testing.assert_allclose(m.gps_time, sim.gps_time, rtol=0, atol=1e-9)
    else:
        assert grid == dvl  # the first and last rows have a DVL reading, the fixes are on rows
    if name == "dvl_gap_30s":
        times = [layout.read_time(k) for k in grid]
        steps = np.diff(times)
        at = int(np.argmax(steps))
        assert (grid[at], grid[at + 1]) == (1998, 2302)  # the rows around the gap
        assert "longest step %s s (lines %d-%d)" % (seconds_text(steps[at]), grid[at] + 2, grid[at + 1] + 2) in r.stdout, r.stdout
    check_solution(out, sim, grid)


def test_knots_and_degrees_are_converted_to_si(sim, logger, tmp_path):
    """The imported readings are the simulated ones, within the conversion's rounding; a
    log in seconds placed by --epoch takes the NMEA fixes within max_gap of its readings
    and names the others in a warning."""
    layout = LogLayout(sim, rows=range(0, 1201), angle_unit="deg", speed_unit="knots", dvl=lambda k: k % 2 == 0)
    log, map_, truth = (str(tmp_path / n) for n in ("log.csv", "map.yaml", "truth.csv"))
    layout.write_log(log)
    layout.write_map(map_)
    layout.write_truth(truth)
    out = str(tmp_path / "out.h5")
    r = run_gesmi("import", "nav", log, "--map", map_, "--epoch", iso_z(DEFAULT_EPOCH),
                  "--gps", os.path.join(logger, "gps.nmea"), "--truth", truth, "-o", out)
    assert r.returncode == 0, r.stderr
    # The fixes within max_gap (60 s) of the attitude's and the depth's readings are used,
    # the others named in a warning (their GGA: line 2 i + 2 of the exported gps.nmea).
    first, last = usable_span(layout.log_readings())
    assert (first, last) == pytest.approx((-60.0, 180.0), abs=1e-9)
    inside = [t for t in sim.gps_time if first <= t <= last]
    assert nmea_counts(r.stdout) == (len(inside), 0, 0, len(sim.gps_time) - len(inside))
    warnings = ["%s:%d: warning: the fix at %s s is not used: no attitude or depth reading within max_gap (60 s) of it"
                % (os.path.join(logger, "gps.nmea"), 2 * i + 2, seconds_text(t))
                for i, t in enumerate(sim.gps_time) if not first <= t <= last]
    assert len(warnings) == len(sim.gps_time) - len(inside) >= 1
    assert [line.split(",")[0] for line in r.stderr.splitlines()] == warnings, r.stderr
    m = gesmi.read_mission(out)
    grid = layout.grid
    assert grid == [k for k in layout.rows if k % 2 == 0]  # the fix kept is on the first row
    np.testing.assert_allclose(m.roll, sim.attitude[grid, 0], rtol=1e-14, atol=1e-18)
    np.testing.assert_allclose(m.heading, sim.attitude[grid, 2], rtol=1e-14, atol=1e-18)
    np.testing.assert_allclose(m.vx, sim.velocity[grid, 0], rtol=1e-14, atol=1e-18)
    np.testing.assert_allclose(m.vy, sim.velocity[grid, 1], rtol=1e-14, atol=1e-18)
    np.testing.assert_allclose(m.gps_time, inside, rtol=0, atol=1e-3)
    # The first fix is the origin when --origin is not given.
    assert m.origin[0] == pytest.approx(sim.gps_lonlat[0, 1], abs=1e-7)
    assert m.origin[1] == pytest.approx(sim.gps_lonlat[0, 0], abs=1e-7)
    # --epoch names t = 0 of a log in seconds.
    assert summary_line(r.stdout).endswith("t = 0 at 2026-05-14T08:00:00Z")


# ----------------------------------------------------------------------------------------
# 3. NMEA


def test_exported_nmea_reads_with_pynmea2(sim, midnight_logger):
    with open(os.path.join(midnight_logger, "gps.nmea"), newline="") as f:
        text = f.read()
    lines = [line for line in text.split("\r\n") if line]
    assert len(lines) == 2 * len(sim.gps_time)
    parsed = [pynmea2.parse(line, check=True) for line in lines]  # raises on a bad checksum
    for line in lines:
        body, star, checksum = line[1:].rpartition("*")
        assert star and checksum == nmea_checksum(body)
    rmcs = [p for p in parsed if isinstance(p, pynmea2.types.talker.RMC)]
    ggas = [p for p in parsed if isinstance(p, pynmea2.types.talker.GGA)]
    assert len(rmcs) == len(ggas) == len(sim.gps_time)
    for i, (r, g) in enumerate(zip(rmcs, ggas)):
        assert int(g.gps_qual) >= 1
        assert abs(g.latitude - sim.gps_lonlat[i, 1]) <= 1e-7
        assert abs(g.longitude - sim.gps_lonlat[i, 0]) <= 1e-7
        assert abs(r.latitude - sim.gps_lonlat[i, 1]) <= 1e-7
        assert abs(r.longitude - sim.gps_lonlat[i, 0]) <= 1e-7
        assert r.timestamp == g.timestamp
        when = datetime.datetime.combine(r.datestamp, g.timestamp).replace(tzinfo=UTC)
        assert abs((when - MIDNIGHT_EPOCH).total_seconds() - sim.gps_time[i]) <= 1e-3
    # The last fix is after midnight: its RMC carries the next day.
    assert rmcs[0].datestamp == MIDNIGHT_EPOCH.date()
    assert rmcs[-1].datestamp == MIDNIGHT_EPOCH.date() + datetime.timedelta(days=1)


def nmea_import(logger, tmp_path, lines, *extra):
    """The logger's log.csv and map with `lines` as the GPS file."""
    nmea = str(tmp_path / "fixes.nmea")
    with open(nmea, "w", newline="") as f:
        f.write("".join(line + "\r\n" for line in lines))
    out = str(tmp_path / "out.h5")
    r = run_gesmi("import", "nav", os.path.join(logger, "log.csv"), "--map", os.path.join(logger, "map.yaml"),
                  "--gps", nmea, *extra, "-o", out)
    return r, out, nmea


def nmea_counts(stdout):
    match = re.search(r"(\d+) GGA fixes taken; skipped: (\d+) sentences with a bad checksum, (\d+) GGA without a fix, "
                      r"(\d+) fixes not usable \(below\)", stdout)
    assert match, stdout
    return tuple(int(x) for x in match.groups())


def fix_positions(sim, count):
    lon0, lat0 = sim.gps_lonlat[0]
    return [(lat0 + 1e-4 * i, lon0 - 2e-4 * i) for i in range(count)]


def test_nmea_bad_checksum_and_no_fix_are_skipped_and_counted(sim, logger, tmp_path):
    positions = fix_positions(sim, 4)
    times = [DEFAULT_EPOCH + datetime.timedelta(seconds=s) for s in (0.5, 100.25, 300, 500.75)]
    lines = []
    for t, (lat, lon) in zip(times, positions):
        lines += [rmc(t, lat, lon), gga(t, lat, lon)]
    # The second GGA's latitude altered after its checksum was computed.
    good = lines[3]
    corrupted = good.replace(",N,", ",S,", 1)
    assert corrupted != good and pynmea2.NMEASentence.checksum(corrupted.split("*")[0][1:]) != int(good[-2:], 16)
    lines[3] = corrupted
    # The third GGA without a fix (quality 0), its checksum right.
    lines[5] = gga(times[2], *positions[2], quality=0)
    pynmea2.parse(lines[5], check=True)
    with pytest.raises(pynmea2.ChecksumError):
        pynmea2.parse(lines[3], check=True)
    r, out, _ = nmea_import(logger, tmp_path, lines, "--origin", "%r,%r" % sim.origin)
    assert r.returncode == 0, r.stderr
    assert nmea_counts(r.stdout) == (2, 1, 1, 0)
    m = gesmi.read_mission(out)
    np.testing.assert_allclose(m.gps_time, [0.5, 500.75], rtol=0, atol=1e-9)
    np.testing.assert_allclose(m.gps_latitude, [positions[0][0], positions[3][0]], rtol=0, atol=1e-8)
    np.testing.assert_allclose(m.gps_longitude, [positions[0][1], positions[3][1]], rtol=0, atol=1e-8)


def test_nmea_without_rmc_needs_date(sim, logger, tmp_path):
    positions = fix_positions(sim, 3)
    seconds = (10.0, 250.5, 590.0)
    lines = [gga(DEFAULT_EPOCH + datetime.timedelta(seconds=s), lat, lon) for s, (lat, lon) in zip(seconds, positions)]
    r, out, nmea = nmea_import(logger, tmp_path, lines, "--origin", "%r,%r" % sim.origin)
    assert r.returncode == 2
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert nmea in r.stderr and "--date" in r.stderr and "RMC" in r.stderr
    assert not os.path.exists(out)
    r, out, _ = nmea_import(logger, tmp_path, lines, "--origin", "%r,%r" % sim.origin,
                            "--date", DEFAULT_EPOCH.strftime("%Y-%m-%d"))
    assert r.returncode == 0, r.stderr
    assert nmea_counts(r.stdout) == (3, 0, 0, 0)
    m = gesmi.read_mission(out)
    np.testing.assert_allclose(m.gps_time, seconds, rtol=0, atol=1e-9)


def test_nmea_midnight_crossing_takes_the_next_day(sim, midnight_logger, tmp_path):
    lat, lon = fix_positions(sim, 1)[0]
    before = MIDNIGHT_EPOCH + datetime.timedelta(seconds=240.5)  # 23:59:00.5 on the 14th
    after = MIDNIGHT_EPOCH + datetime.timedelta(seconds=330.25)  # 00:00:30.25 on the 15th
    assert before.date() != after.date()
    # RMC dated before midnight, then a GGA after it with no new RMC.
    lines = [rmc(before, lat, lon), gga(before, lat, lon), gga(after, lat + 1e-4, lon)]
    r, out, _ = nmea_import(midnight_logger, tmp_path, lines, "--origin", "%r,%r" % sim.origin)
    assert r.returncode == 0, r.stderr
    assert nmea_counts(r.stdout) == (2, 0, 0, 0)
    m = gesmi.read_mission(out)
    np.testing.assert_allclose(m.gps_time, [240.5, 330.25], rtol=0, atol=1e-9)
    # A GGA before midnight whose only RMC comes after it (dated the next day): its own day.
    (tmp_path / "rmc_after").mkdir()
    lines_after = [gga(before, lat, lon), rmc(after, lat + 1e-4, lon), gga(after, lat + 1e-4, lon)]
    r, out, _ = nmea_import(midnight_logger, tmp_path / "rmc_after", lines_after, "--origin", "%r,%r" % sim.origin)
    assert r.returncode == 0, r.stderr
    np.testing.assert_allclose(gesmi.read_mission(out).gps_time, [240.5, 330.25], rtol=0, atol=1e-9)
    # GGA only, --date the day of the first fix: the time of day falling back is the next day.
    (tmp_path / "gga").mkdir()
    r, out, _ = nmea_import(midnight_logger, tmp_path / "gga", lines[1:], "--origin", "%r,%r" % sim.origin,
                            "--date", before.strftime("%Y-%m-%d"))
    assert r.returncode == 0, r.stderr
    m = gesmi.read_mission(out)
    np.testing.assert_allclose(m.gps_time, [240.5, 330.25], rtol=0, atol=1e-9)


def test_nmea_fixes_outside_the_navigation_are_skipped_and_counted(sim, logger, reimported, tmp_path):
    """With the logger's map, a fix is used when every attitude and depth channel has a
    reading within max_gap (60 s) of it: the mission reaches the fixes before and after
    the log, and a fix farther out is skipped, counted and named in a warning. With the
    exact-header navigation CSV, the mission reaches the fixes up to 60 s before its first
    or after its last row the same way."""
    positions = fix_positions(sim, 5)
    seconds = (-60.0, -0.5, 42.0, 600.5, 3600.0)  # the log spans 0 .. 600 s
    lines = []
    for s, (lat, lon) in zip(seconds, positions):
        t = DEFAULT_EPOCH + datetime.timedelta(seconds=s)
        lines += [rmc(t, lat, lon), gga(t, lat, lon)]
    gga_of = {s: lines[2 * i + 1] for i, s in enumerate(seconds)}
    lines.insert(0, sentence("GPGSA,A,3,04,05,,09,12,,,24,,,,,2.5,1.3,2.1"))
    # The fix at 42 s again from a second receiver (GN talker): a repeat, not a second fix.
    lines.insert(7, "$GN" + lines[6][3:lines[6].rindex("*")] + "*" + nmea_checksum("GN" + lines[6][3:lines[6].rindex("*")]))
    assert pynmea2.parse(lines[7], check=True).talker == "GN"
    line_of = {s: lines.index(gga_of[s]) + 1 for s in seconds}  # each fix's GGA in the file
    r, out, nmea = nmea_import(logger, tmp_path, lines, "--origin", "%r,%r" % sim.origin)
    assert r.returncode == 0, r.stderr
    log_csv, map_ = os.path.join(logger, "log.csv"), os.path.join(logger, "map.yaml")
    log = read_logger_readings(log_csv, unix(DEFAULT_EPOCH))
    first, last = usable_span(log)
    assert (first, last) == (-60.0, 660.0)  # attitude and depth read from 0 to 600 s
    used = [s for s in seconds if first <= s <= last]
    unused = [s for s in seconds if s not in used]
    assert used == [-60.0, -0.5, 42.0, 600.5] and unused == [3600.0]
    assert nmea_counts(r.stdout) == (len(used), 0, 0, len(unused))
    assert "%d fixes not usable (below), 1 repeated; 1 other sentences ignored" % len(unused) in r.stdout, r.stdout
    warnings = r.stderr.splitlines()
    assert len(warnings) == len(unused), r.stderr
    for warning, s in zip(warnings, unused):
        assert warning.startswith("%s:%d: warning: the fix at %s s is not used: no attitude or depth reading within "
                                  "max_gap (60 s) of it," % (nmea, line_of[s], seconds_text(s))), r.stderr
        assert "max_gap in %s" % map_ in warning, warning
    m = gesmi.read_mission(out)
    np.testing.assert_allclose(m.gps_time, used, rtol=0, atol=1e-9)
    np.testing.assert_allclose(m.gps_latitude, [positions[seconds.index(s)][0] for s in used], rtol=0, atol=1e-8)
    # The grid: the DVL rows and the times of the fixes before and after every row (the
    # log's first and last rows have a DVL reading).
    times, _ = expected_grid(log, used)
    assert times[:2] == [-60.0, -0.5] and times[-1] == 600.5 and len(times) == len(log.readings["vx"]) + 3
    np.testing.assert_array_equal(m.time, times)
    check_nav_notes(r.stdout, log_csv, log, times)
    assert "longest step 59.5 s (from -60 s to -0.5 s, a fix's time)" in r.stdout, r.stdout
    assert "%d samples over %g s, %d GPS fixes" % (len(times), times[-1] - times[0], len(used)) in summary_line(r.stdout)
    # --json: the unused fixes, and what the import filled, channel by channel.
    r = run_gesmi("import", "nav", log_csv, "--map", map_, "--gps", nmea, "--origin", "%r,%r" % sim.origin,
                  "-o", str(tmp_path / "json.h5"), "--json")
    assert r.returncode == 0, r.stderr
    report = json.loads(r.stdout)
    assert [(u["where"], u["time_s"]) for u in report["unused_fixes"]] == [
        ("%s:%d" % (nmea, line_of[s]), s) for s in unused]
    filled = {f["channel"]: f for f in report["mission"]["filled"]}
    expected = {}
    for f in expected_fill(log, times):
        for channel in (("vx", "vy", "vz") if f.channel == "vx" else (f.channel,)):
            expected[channel] = dict(channel=channel, key=f.key, before_first_reading=f.before,
                                     between_readings=f.between, after_last_reading=f.after,
                                     first_reading_s=f.first, last_reading_s=f.last)
    assert filled == expected
    assert (filled["vx"]["before_first_reading"], filled["vx"]["after_last_reading"]) == (2, 1)
    # The exact-header navigation CSV (gesmi's export of the imported logger mission, 0 ..
    # 600 s): the fixes up to 60 s before or after its rows extend the grid; the one
    # farther out is named.
    assert reimported.result.returncode == 0, reimported.result.stderr
    folder = str(tmp_path / "csv")
    assert run_gesmi("export", reimported.out, "-o", folder).returncode == 0
    nav = os.path.join(folder, "nav.csv")
    with open(nav) as f:
        nav_times = [float(row[0]) for row in list(csv.reader(f))[1:]]
    within = [s for s in seconds if nav_times[0] - 60.0 <= s <= nav_times[-1] + 60.0]
    assert within == used
    r = run_gesmi("import", "nav", nav, "--gps", nmea, "--epoch", iso_z(DEFAULT_EPOCH), "--origin", "%r,%r" % sim.origin,
                  "-o", str(tmp_path / "csv.h5"))
    assert r.returncode == 0, r.stderr
    assert nmea_counts(r.stdout) == (len(within), 0, 0, len(seconds) - len(within))
    warnings = r.stderr.splitlines()
    assert [w.split(": warning: ")[0] for w in warnings] == [
        "%s:%d" % (nmea, line_of[s]) for s in seconds if s not in within], r.stderr
    assert all("more than 60 s before the first or after the last row of %s" % nav in w for w in warnings), r.stderr
    m = gesmi.read_mission(str(tmp_path / "csv.h5"))
    outside = [s for s in within if s < nav_times[0] or s > nav_times[-1]]
    np.testing.assert_array_equal(m.time, sorted(nav_times + outside))
    np.testing.assert_allclose(m.gps_time, within, rtol=0, atol=1e-9)
    assert "vx, vy, vz: bridged by surface_max_speed at 3 samples without a reading: 2 before its first reading" in r.stdout
    # The same fixes as gesmi's GPS CSV: the same mission, the same warning.
    gps_csv = str(tmp_path / "gps.csv")
    with open(gps_csv, "w") as f:
        f.write("time,longitude,latitude\n")
        for s, (lat, lon) in zip(seconds, positions):
            f.write("%r,%r,%r\n" % (s, lon, lat))
    r = run_gesmi("import", "nav", nav, "--gps", gps_csv, "--origin", "%r,%r" % sim.origin, "-o", str(tmp_path / "csv2.h5"))
    assert r.returncode == 0, r.stderr
    assert [w.split(": warning: ")[0] for w in r.stderr.splitlines()] == [
        "%s:%d" % (gps_csv, 2 + seconds.index(s)) for s in seconds if s not in within], r.stderr
    m2 = gesmi.read_mission(str(tmp_path / "csv2.h5"))
    np.testing.assert_array_equal(m2.time, m.time)
    np.testing.assert_allclose(m2.gps_time, within, rtol=0, atol=1e-9)


# ----------------------------------------------------------------------------------------
# 4. Bad inputs: exit 2, one line naming the file and the reason, nothing written


def short_layout(sim, **kwargs):
    """A two-minute ISO 8601 log in degrees, DVL every 2nd row."""
    options = dict(rows=range(0, 1201), delimiter=",", time_format="iso", offset="Z", angle_unit="deg",
                   dvl=lambda k: k % 2 == 0)
    options.update(kwargs)
    return LogLayout(sim, **options)


def run_bad(layout, folder, *, edit=None, map_kwargs=None, existing_output=False):
    """Imports a log that must be refused: exit 2, one line on stderr, no output (or an
    existing one untouched). Returns the message and the log's and map's paths."""
    folder = str(folder)
    log, map_ = os.path.join(folder, "log.csv"), os.path.join(folder, "map.yaml")
    layout.write_log(log, edit)
    layout.write_map(map_, **(map_kwargs or {}))
    out = os.path.join(folder, "out.h5")
    if existing_output:
        with open(out, "wb") as f:
            f.write(b"not touched")
    r = run_gesmi("import", "nav", log, "--map", map_, "--origin", "%r,%r" % layout.sim.origin, "-o", out)
    assert r.returncode == 2, (r.returncode, r.stdout, r.stderr)
    message = r.stderr.strip()
    assert len(message.splitlines()) == 1, r.stderr
    assert r.stdout == ""
    if existing_output:
        with open(out, "rb") as f:
            assert f.read() == b"not touched"
    else:
        assert not os.path.exists(out)
    return message, log, map_


def test_the_short_log_imports(sim, tmp_path):
    """The base of the error cases below is itself a good log."""
    layout = short_layout(sim)
    log, map_ = str(tmp_path / "log.csv"), str(tmp_path / "map.yaml")
    layout.write_log(log)
    layout.write_map(map_)
    out = str(tmp_path / "out.h5")
    r = run_gesmi("import", "nav", log, "--map", map_, "--origin", "%r,%r" % sim.origin, "-o", out)
    assert r.returncode == 0, r.stderr
    assert len(gesmi.read_mission(out)) == 601


@pytest.mark.parametrize("bad", ["2026-13-01T00:00:00Z", "yesterday", "2026-05-14T08:00:61Z", "2026-05-14 08:00"])
def test_bad_time_in_the_log(sim, tmp_path, bad):
    row = 37

    def edit(k, values):
        if k == row:
            values["time"] = bad

    message, log, _ = run_bad(short_layout(sim), tmp_path, edit=edit)
    assert "%s:%d: time: " % (log, row + 2) in message, message
    assert repr(bad).strip("'") in message


def test_unknown_unit_in_the_map(sim, tmp_path):
    layout = short_layout(sim)
    message, _, map_ = run_bad(layout, tmp_path, map_kwargs={"unit_override": {"pitch": "grad"}})
    assert "%s:%d: pitch" % (map_, layout.map_lines["pitch"]) in message, message
    assert "grad" in message and "deg" in message and "rad" in message


def test_map_names_a_column_the_file_lacks(sim, tmp_path):
    layout = short_layout(sim)
    message, log, map_ = run_bad(layout, tmp_path, map_kwargs={"column_override": {"depth": "baro_depth"}})
    assert log in message and "baro_depth" in message, message
    assert "%s:%d" % (map_, layout.map_lines["depth"]) in message, message


def test_dvl_gap_beyond_max_gap(sim, tmp_path):
    gap_layout = short_layout(sim, dvl=lambda k: k % 2 == 0 and not (400 <= k <= 700))
    message, log, map_ = run_bad(gap_layout, tmp_path, map_kwargs={"max_gap": 20})
    assert "%s:%d: vx: " % (log, 702 + 2) in message, message  # the reading after the gap
    assert "max_gap" in message and map_ in message, message
    assert "20 s" in message and "%s s" % seconds_text(70.2 - 39.8) in message, message
    # The same log within the default 60 s limit imports.
    (tmp_path / "ok").mkdir()
    log_ok, map_ok = str(tmp_path / "ok" / "log.csv"), str(tmp_path / "ok" / "map.yaml")
    gap_layout.write_log(log_ok)
    gap_layout.write_map(map_ok)
    out = str(tmp_path / "ok" / "out.h5")
    r = run_gesmi("import", "nav", log_ok, "--map", map_ok, "--origin", "%r,%r" % sim.origin, "-o", out)
    assert r.returncode == 0, r.stderr


def test_depth_silent_beyond_max_gap(sim, tmp_path):
    message, log, _ = run_bad(short_layout(sim, depth=lambda k: k in (0, 500, 1200)), tmp_path,
                              map_kwargs={"max_gap": 45})
    assert "%s:%d: depth: " % (log, 500 + 2) in message and "max_gap" in message, message
    assert "50 s" in message and "45 s" in message, message


def test_a_dvl_reading_without_all_three_components(sim, tmp_path):
    row = 88

    def edit(k, values):
        if k == row:
            values["vy"] = ""

    message, log, _ = run_bad(short_layout(sim), tmp_path, edit=edit)
    assert "%s:%d: vy: " % (log, row + 2) in message and "vx, vy and vz" in message, message


def test_time_going_back(sim, tmp_path):
    row = 250

    def edit(k, values):
        if k == row:
            values["time"] = "2026-05-14T07:59:59.000Z"

    message, log, _ = run_bad(short_layout(sim), tmp_path, edit=edit)
    assert "%s:%d: time: " % (log, row + 2) in message and "back in time" in message, message


def test_nmea_fixes_need_a_navigation_with_utc_times(sim, logger, tmp_path):
    layout = short_layout(sim, time_format="seconds")
    log, map_ = str(tmp_path / "log.csv"), str(tmp_path / "map.yaml")
    layout.write_log(log)
    layout.write_map(map_)
    nmea, out = os.path.join(logger, "gps.nmea"), str(tmp_path / "out.h5")
    r = run_gesmi("import", "nav", log, "--map", map_, "--gps", nmea, "-o", out)
    assert r.returncode == 2, r.stdout
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert nmea in r.stderr and "--epoch" in r.stderr, r.stderr
    assert not os.path.exists(out)


def test_a_channel_with_no_reading(sim, tmp_path):
    message, log, _ = run_bad(short_layout(sim, altitude=lambda k: False), tmp_path)
    assert log in message and "altitude" in message and "no reading" in message, message


def test_iso_time_without_zone_and_without_map_timezone(sim, tmp_path):
    message, log, _ = run_bad(short_layout(sim, offset=""), tmp_path)
    assert "%s:2: time: " % log in message, message
    assert "zone" in message


def test_missing_unit_for_an_angle(sim, tmp_path):
    layout = short_layout(sim)
    message, _, map_ = run_bad(layout, tmp_path, map_kwargs={"drop_unit": "heading"})
    assert "%s:%d: heading" % (map_, layout.map_lines["heading"]) in message, message
    assert "unit" in message


def test_roll_in_degrees_declared_as_radians(sim, tmp_path):
    row = 123

    def edit(k, values):
        if k == row:
            values["roll"] = "5.0"  # a 5 degree roll, read as 5 rad

    layout = short_layout(sim, angle_unit="rad")
    message, log, _ = run_bad(layout, tmp_path, edit=edit, existing_output=True)
    assert "%s:%d: roll: " % (log, row + 2) in message, message
    assert "90" in message and "degrees" in message


def test_nmea_sentence_with_a_bad_field(sim, logger, tmp_path):
    t = DEFAULT_EPOCH + datetime.timedelta(seconds=5)
    lat, lon = sim.gps_lonlat[0][1], sim.gps_lonlat[0][0]
    good = gga(t, lat, lon)
    bad = sentence(good[1:good.rindex("*")].replace(",N,", ",Q,", 1))
    lines = [rmc(t, lat, lon), good, bad]
    r, out, nmea = nmea_import(logger, tmp_path, lines, "--origin", "%r,%r" % sim.origin)
    assert r.returncode == 2, r.stdout
    assert len(r.stderr.strip().splitlines()) == 1
    assert "%s:3: GPGGA field 3" % nmea in r.stderr, r.stderr
    assert not os.path.exists(out)


def test_marks_with_absolute_times_need_the_missions_epoch(sim, logger, reimported, tmp_path):
    marks, marks_map = os.path.join(logger, "marks.csv"), os.path.join(logger, "marks_map.yaml")
    out = str(tmp_path / "marked.h5")
    # The simulated mission has no epoch: absolute times cannot be placed.
    r = run_gesmi("import", "marks", marks, "--into", sim.path, "--map", marks_map, "-o", out)
    assert r.returncode == 2, r.stdout
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "%s:2: utc: " % marks in r.stderr and "epoch" in r.stderr, r.stderr
    assert not os.path.exists(out)
    # The re-imported logger mission has one (2026-05-14T08:00:00Z): they land at their times.
    assert reimported.result.returncode == 0, reimported.result.stderr
    r = run_gesmi("import", "marks", marks, "--into", reimported.out, "--map", marks_map, "-o", out)
    assert r.returncode == 0, r.stderr
    m = gesmi.read_mission(out)
    order, expected = np.argsort(m.mark_time), np.argsort(sim.mark_time)
    np.testing.assert_allclose(np.asarray(m.mark_time)[order], sim.mark_time[expected], rtol=0, atol=1e-6)
    np.testing.assert_array_equal(np.asarray(m.mark_mine)[order], sim.mark_mine[expected])


# ----------------------------------------------------------------------------------------
# Found while writing these tests, and fixed


def test_export_epoch_with_a_fraction_is_refused_or_kept(sim, tmp_path):
    folder = str(tmp_path / "out")
    r = run_gesmi("export", sim.path, "--format", "logger", "--epoch", "2026-05-14T08:00:00.5Z", "-o", folder)
    if r.returncode == 0:
        _, rows = read_semicolon_log(os.path.join(folder, "log.csv"))
        assert rows[0][0] == "2026-05-14T08:00:00.500000Z"
    else:
        assert r.returncode == 2 and "--epoch" in r.stderr
        assert not os.path.exists(folder) or os.listdir(folder) == []


def test_marks_epoch_error_suggests_an_option_the_command_has(sim, logger, tmp_path):
    marks, marks_map = os.path.join(logger, "marks.csv"), os.path.join(logger, "marks_map.yaml")
    out = str(tmp_path / "marked.h5")
    r = run_gesmi("import", "marks", marks, "--into", sim.path, "--map", marks_map, "-o", out)
    assert r.returncode == 2
    help_text = run_gesmi("import", "marks", "--help").stdout
    for option in re.findall(r"(--[a-z][a-z-]*)", r.stderr):
        assert option in help_text, (option, r.stderr)
