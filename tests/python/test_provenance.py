"""Provenance and units in every HDF5 file gesmi writes (mission, result, Kalman,
localization), read with h5py and checked against independent computations: the input
files' SHA-256 by hashlib, the command line as it was typed, the creation time against
the clock, the origin and sensor model against the mission, and a `units` and
`long_name` attribute on every dataset (docs/formats.md, "Provenance and units")."""
import datetime
import hashlib
import os
import subprocess

import h5py
import pytest

from conftest import GESMI, run_gesmi

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def text(value):
    return value.decode() if isinstance(value, bytes) else value


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def check_file(path, args, inputs, trajectory=True):
    with h5py.File(path, "r") as f:
        assert text(f.attrs["command_line"]) == " ".join(["gesmi", *args])
        assert text(f.attrs["gesmi_version"]) in text(f.attrs["source"])
        created = datetime.datetime.strptime(text(f.attrs["created_utc"]), "%Y-%m-%dT%H:%M:%SZ")
        now = datetime.datetime.now(datetime.timezone.utc).replace(tzinfo=None)
        assert abs((now - created).total_seconds()) < 120
        assert text(f.attrs["history"]).endswith(text(f.attrs["command_line"]))
        if trajectory:
            assert text(f.attrs["featureType"]) == "trajectory"
            assert text(f.attrs["datum"]) == "WGS84"
            assert -90 <= f.attrs["origin_latitude"] <= 90
        p = f["/provenance"].attrs
        assert p["input_count"] == len(inputs)
        for i, given in enumerate(inputs):
            assert text(p[f"input_{i}"]) == os.path.abspath(given)
            assert text(p[f"input_{i}_sha256"]) == sha256(given)
        missing = []
        f.visititems(lambda name, obj: missing.append(name) if isinstance(obj, h5py.Dataset) and (
            "units" not in obj.attrs or "long_name" not in obj.attrs) else None)
        assert missing == []


def run(*args):
    r = run_gesmi(*args)
    assert r.returncode == 0, r.stderr
    return list(args)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("provenance")


@pytest.fixture
def files(folder, monkeypatch):
    monkeypatch.chdir(folder)  # relative paths, as a user types them; recorded absolute
    return folder


def test_mission_result_and_kalman_record_their_making(files):
    args = run("simulate", "--seed", "4", "--duration", "900", "-o", "m.h5")
    check_file("m.h5", args, [])
    with h5py.File("m.h5", "r") as f:
        assert text(f["/nav/time"].attrs["units"]) == "s"
        assert text(f["/nav/time"].attrs["standard_name"]) == "time"
        assert text(f["/nav/velocity"].attrs["units"]) == "m s-1, m s-1, m s-1"
        assert "/model" in f
    args = run("solve", "m.h5", "-o", "r.h5")
    check_file("r.h5", args, ["m.h5"])
    with h5py.File("r.h5", "r") as f, h5py.File("m.h5", "r") as m:
        assert f.attrs["origin_latitude"] == m.attrs["origin_latitude"]
        assert f.attrs["origin_longitude"] == m.attrs["origin_longitude"]
        assert dict(f["/model"].attrs) == dict(m["/model"].attrs)
        assert text(f["/tube/lower"].attrs["units"]) == "m, m, m"
    args = run("kalman", "m.h5", "-o", "k.h5")
    check_file("k.h5", args, ["m.h5"])
    with h5py.File("k.h5", "r") as f, h5py.File("m.h5", "r") as m:
        assert dict(f["/model"].attrs) == dict(m["/model"].attrs)
        assert text(f["/kalman/cov"].attrs["units"]) == "m2"


def test_time_units_follow_the_epoch(files):
    run("export", "m.h5", "-o", "csv")
    with open(os.path.join("csv", "import-command.txt")) as f:
        words = f.read().split()[1:]
    words[words.index("-o") + 1] = os.path.abspath("dated.h5")
    r = subprocess.run([GESMI, *words, "--epoch", "2026-05-14T08:00:00Z"], cwd="csv", capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with h5py.File("dated.h5", "r") as f:
        assert text(f["/nav/time"].attrs["units"]) == "seconds since 2026-05-14T08:00:00Z"
        p = f["/provenance"].attrs
        roles = [text(p[f"input_{i}"]) for i in range(p["input_count"])]
    assert os.path.abspath(os.path.join("csv", "nav.csv")) in roles
    args = run("solve", "dated.h5", "-o", "dated_result.h5")
    with h5py.File("dated_result.h5", "r") as f:
        assert text(f["/time"].attrs["units"]) == "seconds since 2026-05-14T08:00:00Z"


def test_localization_file_records_its_making_and_data(files):
    scenario = os.path.join(SOURCE, "missions", "localization", "triangle_two_hypotheses.yaml")
    args = run("localize", scenario, "-o", "loc")
    check_file(os.path.join("loc", "paving.h5"), args, [scenario], trajectory=False)
    with h5py.File(os.path.join("loc", "paving.h5"), "r") as f:
        assert f["/data/range"].shape[0] + f["/data/bearing"].shape[0] == f["/components/outliers"].shape[1]
