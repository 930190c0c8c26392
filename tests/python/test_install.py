"""cmake --install: the gesmi command, the Python module, the man page, the bash
completion and the docs land under the prefix and work from there (the build folder is
the one holding GESMI_BIN, build/bin/gesmi)."""
import glob
import os
import subprocess
import sys

from conftest import GESMI


import pytest


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    build = os.path.dirname(os.path.dirname(os.path.abspath(GESMI)))
    prefix = tmp_path_factory.mktemp("install") / "prefix"
    r = subprocess.run(["cmake", "--install", build, "--prefix", str(prefix)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return prefix


def listed_commands():
    text = subprocess.run([GESMI, "--help"], capture_output=True, text=True).stdout
    block = text.split("commands:\n", 1)[1].split("\n\n", 1)[0]
    return [line.split()[0] for line in block.splitlines()]


def test_install_puts_the_command_and_the_module_under_the_prefix(prefix):
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


def test_the_man_page_describes_every_command(prefix):
    page = (prefix / "share" / "man" / "man1" / "gesmi.1").read_text()
    version = subprocess.run([GESMI, "--version"], capture_output=True, text=True).stdout.split()[1]
    assert '.TH GESMI "1"' in page
    assert f'"gesmi {version}"' in page
    commands = listed_commands()
    assert len(commands) >= 10
    for command in commands:
        assert f".SS gesmi {command}" in page, command
    for sub in ("marks add", "import nav", "example paper2d"):
        assert f".SS gesmi {sub}" in page, sub
    assert "\\-\\-skip\\-existing" in page  # options as hyphens, not typographic dashes


def complete(prefix, *words):
    """What the installed completion offers for the words, the last one being typed."""
    script = prefix / "share" / "bash-completion" / "completions" / "gesmi"
    quoted = " ".join(f"'{w}'" for w in words)
    r = subprocess.run(["bash", "-c", f"source '{script}'; COMP_WORDS=(gesmi {quoted}); COMP_CWORD={len(words)}; "
                        "_gesmi; printf '%s\\n' \"${COMPREPLY[@]}\""], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return sorted(r.stdout.split())


def test_the_bash_completion_offers_commands_subcommands_and_options(prefix):
    assert complete(prefix, "so") == ["solve"]
    assert complete(prefix, "--ver") == ["--version"]
    assert complete(prefix, "marks", "") == ["add", "list", "remove"]
    assert complete(prefix, "solve", "--max") == ["--max-outliers", "--max-sweeps"]
    assert "--map" in complete(prefix, "import", "nav", "--ma")


def test_the_docs_are_installed(prefix):
    docs = prefix / "share" / "doc" / "gesmi"
    assert (docs / "README.md").is_file()
    for name in ("formats.md", "model.md", "guarantees.md", "python.md"):
        assert (docs / name).is_file(), name
