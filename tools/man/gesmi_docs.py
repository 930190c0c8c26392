#!/usr/bin/python3
"""The gesmi man page and bash completion, generated from the command's own help texts
(one fact in one place), at build time:

    tools/man/gesmi_docs.py man GESMI OUT.1          # through help2man (Debian)
    tools/man/gesmi_docs.py completion GESMI OUT     # a bash completion script

The commands come from 'gesmi --help'; a command whose usage line names words after it
('gesmi marks list|add|remove ...', 'gesmi example paper2d') has subcommands, each with
its own --help."""
import os
import re
import subprocess
import sys
import tempfile


def help_text(gesmi, *words):
    r = subprocess.run([gesmi, *words, "--help"], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"gesmi_docs: {gesmi} {' '.join(words)} --help exited {r.returncode}: {r.stderr.strip()}")
    return r.stdout


def commands(gesmi):
    """(name, summary) of every command, as 'gesmi --help' lists them."""
    listed, found = [], False
    for line in help_text(gesmi).splitlines():
        if line.strip() == "commands:":
            found = True
        elif found and line.startswith("  ") and line.strip():
            name, summary = line.strip().split(None, 1)
            listed.append((name, summary))
        elif found and listed and not line.strip():
            break
    if not listed:
        sys.exit("gesmi_docs: 'gesmi --help' lists no commands")
    return listed


def subcommands(gesmi, command, text):
    """The words the usage line names after the command ('list|add|remove', 'paper2d'),
    or none (placeholders are upper case, options start with '[' or '-')."""
    match = re.match(rf"usage: gesmi {re.escape(command)} ([a-z][a-z0-9-]*(?:\|[a-z0-9-]+)*)(?:\s|$)", text)
    return match.group(1).split("|") if match else []


def helps(gesmi):
    """[(words, summary, help text)] for every command and subcommand."""
    out = []
    for name, summary in commands(gesmi):
        text = help_text(gesmi, name)
        out.append(([name], summary, text))
        for sub in subcommands(gesmi, name, text):
            out.append(([name, sub], summary, help_text(gesmi, name, sub)))
    return out


def options(text):
    """Every long option a help text lists ('  -o [ --output ] arg', '  --png')."""
    return sorted(set(re.findall(r"^\s+(?:-\w \[ )?(--[a-z0-9][a-z0-9-]*)", text, flags=re.M)))


def roff(text):
    """Help text as literal roff lines: backslashes doubled, hyphens kept as hyphens, and
    a line starting with a control character protected."""
    lines = []
    for line in text.splitlines():
        line = line.replace("\\", "\\\\").replace("-", "\\-")
        lines.append("\\&" + line if line.startswith((".", "'")) else line)
    return "\n".join(lines)


def write_man(gesmi, output):
    include = ["[COMMANDS]"]
    for words, summary, text in helps(gesmi):
        include += [f".SS gesmi {' '.join(words)}", summary if len(words) == 1 else "", ".nf", roff(text), ".fi"]
    include += ["[EXIT STATUS]", "0 ok, 2 bad input (one line on stderr naming the file, line or dataset, the field and",
                "the reason; nothing written), 3 inconsistent data.",
                "[SEE ALSO]", "The README and docs/ (formats, model, guarantees, operator, python), installed under",
                "share/doc/gesmi."]
    with tempfile.NamedTemporaryFile("w", suffix=".h2m", delete=False) as f:
        f.write("\n".join(include) + "\n")
        name = f.name
    try:
        subprocess.run(["help2man", "--no-info", "--no-discard-stderr", "--section", "1",
                        "--name", "guaranteed estimation of seamarks with intervals",
                        "--include", name, "--output", output + ".tmp", gesmi], check=True)
        os.replace(output + ".tmp", output)
    finally:
        os.unlink(name)


def write_completion(gesmi, output):
    cases, names = [], []
    by_command = {}
    for words, _, text in helps(gesmi):
        entry = by_command.setdefault(words[0], {"subs": [], "options": set()})
        if len(words) == 2:
            entry["subs"].append(words[1])
        entry["options"].update(options(text))
    for name, entry in by_command.items():
        names.append(name)
        cases.append(f'    {name}) subs="{" ".join(entry["subs"])}"; opts="{" ".join(sorted(entry["options"]))}" ;;')
    script = f"""# bash completion for gesmi, generated from its help texts (tools/man/gesmi_docs.py)
_gesmi() {{
  local cur=${{COMP_WORDS[COMP_CWORD]}} subs="" opts=""
  if [ "$COMP_CWORD" -eq 1 ]; then
    COMPREPLY=($(compgen -W "{" ".join(names)} --help --version" -- "$cur"))
    return
  fi
  case "${{COMP_WORDS[1]}}" in
{chr(10).join(cases)}
  esac
  if [ "$COMP_CWORD" -eq 2 ] && [ -n "$subs" ] && [[ $cur != -* ]]; then
    COMPREPLY=($(compgen -W "$subs" -- "$cur"))
  elif [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "$opts" -- "$cur"))
  else
    mapfile -t COMPREPLY < <(compgen -f -- "$cur")
  fi
}}
complete -o filenames -F _gesmi gesmi
"""
    with open(output + ".tmp", "w") as f:
        f.write(script)
    os.replace(output + ".tmp", output)


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in ("man", "completion"):
        sys.exit("usage: gesmi_docs.py man|completion GESMI OUTPUT")
    _, what, gesmi, output = sys.argv
    (write_man if what == "man" else write_completion)(gesmi, output)


if __name__ == "__main__":
    main()
