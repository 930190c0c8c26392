"""cmake --install: the gesmi command and the Python module land under the prefix and
work from there (the build folder is the one holding GESMI_BIN, build/bin/gesmi)."""
import glob
import os
import subprocess
import sys

from conftest import GESMI


def test_install_puts_the_command_and_the_module_under_the_prefix(tmp_path):
    build = os.path.dirname(os.path.dirname(os.path.abspath(GESMI)))
    prefix = tmp_path / "prefix"
    r = subprocess.run(["cmake", "--install", build, "--prefix", str(prefix)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    version = subprocess.run([str(prefix / "bin" / "gesmi"), "--version"], capture_output=True, text=True)
    assert version.returncode == 0
    assert version.stdout == subprocess.run([GESMI, "--version"], capture_output=True, text=True).stdout
    sites = glob.glob(str(prefix / "lib" / "python3.*" / "dist-packages"))
    assert len(sites) == 1, sites
    env = dict(os.environ, PYTHONPATH=sites[0])
    imported = subprocess.run([sys.executable, "-c", "import gesmi; print(gesmi.__file__)"], capture_output=True,
                              text=True, env=env)
    assert imported.returncode == 0, imported.stderr
    assert imported.stdout.startswith(sites[0])
