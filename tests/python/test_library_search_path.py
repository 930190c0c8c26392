"""The gesmi command and the Python module load their shared libraries from the
system's folders only, never from the folder they run in: a folder holding files named
like the C library (a download, an attacker's) neither breaks nor hijacks them."""
import os
import subprocess
import sys

from conftest import GESMI

LIBRARIES = ("libc.so.6", "libm.so.6", "libmvec.so.1", "libhdf5_serial.so.103", "libstdc++.so.6")


def folder_of_impostors(path):
    # Where the loader looks below a search folder: the folder itself and its
    # glibc-hwcaps subfolders.
    for sub in ("", "glibc-hwcaps/x86-64-v2", "glibc-hwcaps/x86-64-v3", "glibc-hwcaps/x86-64-v4"):
        os.makedirs(path / sub, exist_ok=True)
        for name in LIBRARIES:
            (path / sub / name).write_bytes(b"not a library\n")
    return str(path)


def test_the_command_ignores_libraries_in_the_current_folder(tmp_path):
    r = subprocess.run([GESMI, "--version"], cwd=folder_of_impostors(tmp_path), capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("gesmi ")


def test_the_module_ignores_libraries_in_the_current_folder(tmp_path):
    module_folder = os.path.dirname(__import__("gesmi").__file__)
    env = dict(os.environ, PYTHONPATH=module_folder)
    r = subprocess.run([sys.executable, "-c", "import gesmi; print(gesmi.__name__)"],
                       cwd=folder_of_impostors(tmp_path), env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "gesmi"
