"""The README's usage lines parse: every 'build/bin/gesmi ...' line names a command (and
subcommand) that exists, and every option it shows is one that command's --help lists."""
import os
import re
import subprocess

from conftest import GESMI

README = os.path.join(os.path.dirname(__file__), "..", "..", "README.md")


def usage_lines():
    text = open(README, encoding="utf-8").read()
    block = text.split("## Usage", 1)[1].split("\n## ", 1)[0]
    lines = [line.split("#", 1)[0].strip() for line in block.splitlines()]
    return [line for line in lines if line.startswith("build/bin/gesmi ")]


def help_of(*words):
    r = subprocess.run([GESMI, *words, "--help"], capture_output=True, text=True)
    assert r.returncode == 0, f"gesmi {' '.join(words)} --help: {r.stderr}"
    return r.stdout


def test_the_readme_shows_usage_lines():
    assert len(usage_lines()) >= 12


def test_every_readme_usage_line_parses():
    for line in usage_lines():
        words = line.split()[1:]
        command = words[0]
        if command.startswith("-"):  # gesmi --help
            assert command in help_of(), line
            continue
        text = help_of(command)
        # A subcommand: the next word when the command's usage names words after it.
        usage = text.splitlines()[0]
        if len(words) > 1 and re.match(rf"usage: gesmi {command} [a-z]", usage):
            subs = words[1].split("|")
            for sub in subs:
                assert sub in usage, f"{line}: no subcommand {sub}"
                text = help_of(command, sub) if len(subs) == 1 else text
        for option in re.findall(r"(?<![\w-])(--[a-z][a-z0-9-]*)", line):
            assert re.search(rf"(^|\s|\[ ){re.escape(option)}(?![\w-])", text, flags=re.M), f"{line}: {option} not in the help"
