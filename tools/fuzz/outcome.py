"""Runs one case of the binary and classifies what it did against gesmi's promise:

    bad input -> exit 2, ONE line on stderr naming the input, nothing written;
    never a crash, a hang, exit 1 (internal error) or another exit code.

A case is ok when it exits 0; or exits 2 with exactly one line that names the input and
leaves only the inputs in the case folder; or exits 3 (inconsistent data) with its
output written. Anything else is a failure of one or more classes (FAILURE_CLASSES).
"""

import os
import signal
import subprocess

FAILURE_CLASSES = {
    "crash": "killed by a signal or a sanitizer report",
    "hang": "still running at the timeout",
    "exit1": "exit code 1 (internal error)",
    "exit-other": "an exit code other than 0, 1, 2 or 3",
    "exit2-lines": "exit 2 without exactly one line on stderr",
    "exit2-files-left": "exit 2 with a file or folder left in the case folder",
    "exit2-unnamed": "exit 2 whose message does not name the input",
    "exit2-raw-bytes": "exit 2 whose message holds a control character or bytes that are not UTF-8",
    "exit2-overlong": "exit 2 whose message is longer than %d bytes",
    "exit3-no-output": "exit 3 without its output written",
    "temp-left": "a temporary file left behind (any exit code)",
    "edit-accepted": "a result whose values were edited accepted (exit 0): its digests must refuse it",
}

MAX_MESSAGE_BYTES = 500
FAILURE_CLASSES["exit2-overlong"] %= MAX_MESSAGE_BYTES
STDERR_LIMIT = 1 << 20


class RunResult:
    def __init__(self, code, stderr, timed_out):
        self.code = code          # exit code, or -signal
        self.stderr = stderr      # bytes (at most STDERR_LIMIT)
        self.timed_out = timed_out


def run(args, cwd, timeout):
    """Runs args in cwd in its own process group; kills the group at the timeout."""
    p = subprocess.Popen(args, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         start_new_session=True)
    try:
        _, err = p.communicate(timeout=timeout)
        return RunResult(p.returncode, err[:STDERR_LIMIT], False)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        _, err = p.communicate()
        return RunResult(p.returncode, err[:STDERR_LIMIT], True)


def _has_raw_bytes(line):
    if any(b < 0x20 or b == 0x7F for b in line):
        return True
    try:
        line.decode("utf-8")
    except UnicodeDecodeError:
        return True
    return False


def classify(result, left_behind, must_name, outputs_present):
    """The failure classes of a finished case (empty when it kept the promise).

    left_behind: names in the case folder other than the inputs, after the run;
    must_name: texts the exit-2 message must contain one of (the input's name);
    outputs_present: whether what an exit 3 must write exists.
    """
    failures = []
    err = result.stderr
    if any(".tmp" in name for name in left_behind):
        failures.append("temp-left")
    if result.timed_out:
        return ["hang"] + failures
    if result.code < 0 or b"Sanitizer" in err or b"runtime error:" in err:
        return ["crash"] + failures
    if result.code == 1:
        return ["exit1"] + failures
    if result.code == 3:
        return failures if outputs_present else ["exit3-no-output"] + failures
    if result.code == 0:
        return failures
    if result.code != 2:
        return ["exit-other"] + failures
    lines = err.split(b"\n")
    if len(lines) != 2 or lines[1] != b"" or not lines[0]:
        failures.append("exit2-lines")
    if left_behind:
        failures.append("exit2-files-left")
    if must_name and not any(name.encode() in err for name in must_name):
        failures.append("exit2-unnamed")
    if _has_raw_bytes(err.rstrip(b"\n")):
        failures.append("exit2-raw-bytes")
    if len(err) > MAX_MESSAGE_BYTES:
        failures.append("exit2-overlong")
    return failures
