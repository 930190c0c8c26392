"""Fixtures for the tests of the gesmi Python module: the module built into
build/python (PYTHONPATH set by CTest), the gesmi command for comparisons, and a
short simulated mission written by that command."""
import os
import subprocess

import pytest

GESMI = os.environ.get("GESMI_BIN", "gesmi")


def run_gesmi(*args):
    return subprocess.run([GESMI, *args], capture_output=True, text=True)


@pytest.fixture(scope="session")
def mission_file(tmp_path_factory):
    path = str(tmp_path_factory.mktemp("mission") / "m.h5")
    r = run_gesmi("simulate", "--seed", "5", "--duration", "900", "--missed", "0.3", "-o", path)
    assert r.returncode == 0, r.stderr
    return path
