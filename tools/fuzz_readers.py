#!/usr/bin/python3
"""Seeded mutation fuzzer of every reader of the `gesmi` command (docs/testing.md).

    tools/fuzz_readers.py --gesmi build/bin/gesmi --seed 1 --cases 200 [--keep-failures DIR]
    tools/fuzz_readers.py --gesmi build/bin/gesmi --replay tests/data/fuzz

Makes small valid seed inputs with the binary, then for each reader mutates its input
(text edits for CSV, YAML and GESMI text logs; structural h5py edits for mission and
result files; odd values for command-line numbers), runs the command with a timeout in
a fresh folder and classifies the outcome (tools/fuzz/outcome.py). Prints per-reader
counts and the failures by class; exits 1 when any case failed. The cases depend only on
--seed (each case has its own random generator), so a run is reproducible whatever
--jobs is.
"""

import argparse
import collections
import concurrent.futures
import json
import os
import random
import resource
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from fuzz import hdf5_mutations, outcome, targets, text_mutations  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def describe(spec):
    """A short one-line text of a mutation spec (bytes shown escaped and cut)."""
    parts = []
    for key, value in spec.items():
        if isinstance(value, (bytes, str)):
            text = repr(value)
            value = text if len(text) <= 40 else text[:37] + "..."
        elif isinstance(value, list) and len(value) > 4:
            value = "[%s, ... %d items]" % (value[0], len(value))
        parts.append("%s=%s" % (key, value))
    return " ".join(parts)


def operations(case):
    """The mutations of a case, e.g. 'attr_array+dset_values' (how failures are grouped)."""
    return "+".join(sorted({s["op"] for s in case.specs if s["op"] != "seed"}))


def jsonable(spec):
    return {k: (v.decode("latin-1") if isinstance(v, bytes) else v) for k, v in spec.items()}


class Case:
    """One generated case: where its input is, the command, what its message must name."""

    def __init__(self, reader, index):
        self.reader = reader
        self.index = index
        self.args = []
        self.specs = []
        self.must_name = [reader.input_name] if reader.input_name else []
        self.outputs = []
        self.folder = None


def substitute(args, case_folder, input_name, seeds):
    out = []
    for a in args:
        if a == "@":
            out.append(input_name)
        elif isinstance(a, str) and a.startswith("$"):
            out.append(seeds[a[1:]])
        else:
            out.append(a)
    return out


def mutation_count(rng, most):
    """1 mutation mostly, sometimes 2 or 3 stacked (at most `most`)."""
    return min(rng.choices([1, 2, 3], [7, 2, 1])[0], most)


# Inputs that are not regular files, one case in 20: every reader must refuse them before
# reading (a FIFO without a writer blocks whoever opens it; /dev/zero and /dev/urandom
# never end).
SPECIAL_INPUTS = ("fifo", "dev-zero", "dev-urandom", "dev-null", "folder")
SPECIAL_SHARE = 0.05


def make_special(path, kind):
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "folder":
        os.mkdir(path)
    else:
        os.symlink("/dev/" + kind[len("dev-"):], path)


def make_case(reader, index, seed, seeds, inventories, work, options):
    """Creates the case folder with its mutated input; returns the Case."""
    rng = random.Random("%s/%s/%d" % (seed, reader.name, index))
    case = Case(reader, index)
    command_index = index % len(reader.commands)
    command = reader.commands[command_index]
    case.outputs = reader.outputs[command_index] if reader.outputs else []
    case.folder = os.path.join(work, "%s-%d" % (reader.name.replace(":", "-"), index))
    os.makedirs(case.folder)
    if reader.kind == "cli":
        slots = [i for i, a in enumerate(command) if a.startswith("{")]
        slot = rng.choice(slots)
        args = [a[1:-1] if a.startswith("{") else a for a in command]
        value = args[slot].encode()
        if rng.random() < 0.5:
            value = rng.choice(text_mutations.ODD_VALUES)
            case.specs = [{"op": "value", "value": value}]
        else:
            spec = text_mutations.pick(rng, value, "csv", options.exclude_ops)
            case.specs = [spec]
            value = text_mutations.apply(spec, value)
        args[slot] = value.replace(b"\x00", b"")[:100000]  # argv cannot hold NUL nor 128 KiB in one argument
        # A value starting with '-' is taken for an option by the parser, which names it.
        case.must_name = [args[slot - 1] if args[slot - 1].startswith("--") else "INDEX", "unrecognised option"]
        case.args = substitute(args, case.folder, "", seeds)
        return case
    target = os.path.join(case.folder, reader.input_name)
    if rng.random() < SPECIAL_SHARE:
        case.specs = [{"op": "special", "kind": rng.choice(SPECIAL_INPUTS)}]
        make_special(target, case.specs[0]["kind"])
        case.args = substitute(command, case.folder, reader.input_name, seeds)
        return case
    seed_name = rng.choice(reader.seeds)
    if reader.kind == "hdf5":
        shutil.copy(seeds[seed_name], target)
        for _ in range(mutation_count(rng, options.mutations)):
            spec = hdf5_mutations.pick(rng, inventories[seed_name], options.raw_hdf5, options.exclude_ops)
            try:
                hdf5_mutations.apply(spec, target)
            except Exception as e:  # an earlier mutation removed what this one edits
                spec = dict(spec, skipped=type(e).__name__)
            case.specs.append(spec)
    else:
        with open(seeds[seed_name], "rb") as f:
            data = f.read()
        for _ in range(mutation_count(rng, options.mutations)):
            spec = text_mutations.pick(rng, data, reader.kind, options.exclude_ops)
            data = text_mutations.apply(spec, data)
            case.specs.append(spec)
        with open(target, "wb") as f:
            f.write(data)
    case.specs.insert(0, {"op": "seed", "file": seed_name})
    case.args = substitute(command, case.folder, reader.input_name, seeds)
    return case


def run_case(case, gesmi, timeout, inputs):
    """Runs the case; returns (exit code, stderr, failure classes)."""
    result = outcome.run([gesmi] + case.args, case.folder, timeout)
    left = sorted(set(os.listdir(case.folder)) - set(inputs))
    present = all(os.path.exists(os.path.join(case.folder, o)) for o in case.outputs)
    failures = outcome.classify(result, left, case.must_name, present)
    # Every dataset of a result is digested: whatever a command reads of it, an edit is refused.
    edited = any(s.get("op") == "dset_values" and s.get("changed") and "skipped" not in s for s in case.specs)
    if case.reader.name.startswith("result:") and result.code == 0 and edited:
        failures.append("edit-accepted")
    return result, failures, left


def keep_failure(case, result, failures, left, keep_dir, seed):
    folder = os.path.join(keep_dir, failures[0], os.path.basename(case.folder))
    os.makedirs(folder, exist_ok=True)
    kept_input = os.path.join(case.folder, case.reader.input_name)
    if case.reader.input_name and os.path.isfile(kept_input) and not os.path.islink(kept_input):  # (not a special input)
        shutil.copy(kept_input, folder)
    with open(os.path.join(folder, "case.json"), "w") as f:
        json.dump({"reader": case.reader.name, "seed": seed, "case": case.index,
                   "args": [a.decode("latin-1") if isinstance(a, bytes) else a for a in case.args],
                   "mutations": [jsonable(s) for s in case.specs], "exit_code": result.code,
                   "timed_out": result.timed_out, "stderr": result.stderr[:4000].decode("latin-1"),
                   "failures": failures, "left_behind": left}, f, indent=1)


def listing(folder):
    return sorted(os.path.join(root, name) for root, dirs, files in os.walk(folder) for name in dirs + files)


def sanitized(binary):
    """A binary built with AddressSanitizer (tools/sanitizers/check): it reserves
    terabytes of address space for its shadow memory, so it cannot run under RLIMIT_AS."""
    with open(binary, "rb") as f:
        return b"__asan_init" in f.read()


def limit_resources(memory_mb, binary):
    """Children inherit these: no core files in the case folders, bounded memory (a
    reader that trusts a declared 10^12-row dataset must fail, not swap the machine).
    Under ASan the bound is its allocator's instead of the address space's."""
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    if memory_mb <= 0:
        return
    if sanitized(binary):
        options = os.environ.get("ASAN_OPTIONS", "")
        os.environ["ASAN_OPTIONS"] = (options + ":" if options else "") + \
            "max_allocation_size_mb=%d:allocator_may_return_null=1" % memory_mb
    else:
        resource.setrlimit(resource.RLIMIT_AS, (memory_mb << 20, memory_mb << 20))


def fuzz(args):
    readers = [targets.find(n) for n in args.readers] if args.readers else targets.READERS
    work = tempfile.mkdtemp(prefix="gesmi-fuzz-")
    started = time.monotonic()
    try:
        seeds = targets.make_seeds(args.gesmi, REPO, os.path.join(work, "seeds"))
        inventories = {name: hdf5_mutations.inventory(path) for name, path in seeds.items() if name.endswith(".h5")}
        seed_listing = listing(os.path.join(work, "seeds"))
        cases_dir = os.path.join(work, "cases")
        limit_resources(args.memory_mb, args.gesmi)
        counts = collections.OrderedDict((r.name, collections.Counter()) for r in readers)
        by_class = collections.defaultdict(list)
        accepted = []
        kept = collections.Counter()

        def one(reader, index):
            case = make_case(reader, index, args.seed, seeds, inventories, cases_dir, args)
            result, failures, left = run_case(case, args.gesmi, args.timeout, [reader.input_name])
            return case, result, failures, left

        jobs = [(r, i) for i in range(args.cases) for r in readers]
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for case, result, failures, left in pool.map(lambda job: one(*job), jobs):
                c = counts[case.reader.name]
                c["cases"] += 1
                if failures:
                    c["failed"] += 1
                    for f in failures:
                        c[f] += 1
                        by_class[f].append((case, result))
                    key = (failures[0], case.reader.name, operations(case))
                    if args.keep_failures and kept[key] < args.keep_per_class:
                        kept[key] += 1
                        keep_failure(case, result, failures, left, args.keep_failures, args.seed)
                else:
                    c["exit%d" % result.code] += 1
                    if result.code == 0 and args.accepted:
                        accepted.append(case)
                shutil.rmtree(case.folder, ignore_errors=True)
        if listing(os.path.join(work, "seeds")) != seed_listing:
            print("warning: a command wrote into the seed folder", file=sys.stderr)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    report(args, counts, by_class, time.monotonic() - started)
    if args.accepted:
        report_accepted(accepted)
    return 1 if by_class else 0


def report(args, counts, by_class, seconds):
    total = sum(c["cases"] for c in counts.values())
    print("gesmi reader fuzz: seed %s, %d cases per reader, %d cases, %.1f s, binary %s" %
          (args.seed, args.cases, total, seconds, args.gesmi))
    print("%-20s %6s %6s %6s %6s %7s  failure classes" % ("reader", "cases", "exit0", "exit2", "exit3", "failed"))
    for name, c in counts.items():
        classes = ", ".join("%s %d" % (k, c[k]) for k in outcome.FAILURE_CLASSES if c[k])
        print("%-20s %6d %6d %6d %6d %7d  %s" % (name, c["cases"], c["exit0"], c["exit2"], c["exit3"], c["failed"], classes))
    if not by_class:
        print("no failure")
        return
    print("\nfailures by class (a case may fall in several):")
    for cls in outcome.FAILURE_CLASSES:
        items = by_class.get(cls)
        if not items:
            continue
        print("\n%s: %d cases (%s)" % (cls, len(items), outcome.FAILURE_CLASSES[cls]))
        groups = collections.Counter((case.reader.name, operations(case)) for case, _ in items)
        for (reader, op), n in sorted(groups.items(), key=lambda kv: (-kv[1], kv[0])):
            case, result = next((c, r) for c, r in items if c.reader.name == reader and operations(c) == op)
            message = result.stderr.decode("utf-8", "backslashreplace").strip()
            message = message.replace("\n", "\\n")
            if len(message) > 160:
                message = message[:157] + "..."
            print("  %4d  %-18s %-24s e.g. case %d (%s), exit %s: %s" %
                  (n, reader, op, case.index, "; ".join(describe(s) for s in case.specs[1:]) or case.args,
                   "timeout" if result.timed_out else result.code, message))


def report_accepted(cases):
    """Which mutated inputs were accepted (exit 0): where a reader may ignore bad input."""
    print("\naccepted mutated inputs (exit 0), by reader and mutation:")
    groups = collections.defaultdict(list)
    for case in cases:
        groups[(case.reader.name, operations(case))].append(case)
    for (reader, op), items in sorted(groups.items()):
        print("  %4d  %-18s %-24s e.g. %s" % (len(items), reader, op,
                                            "; ".join(describe(s) for s in items[0].specs if s["op"] != "seed") or items[0].args))


def replay(args):
    """Runs the saved cases of each folder (tests/data/fuzz/*/case.json) with the
    stricter expectations they state: the exit code, and texts the message must name.

    case.json: "title"; "args" ("@" the input, "$name" a seed file; "arg_encoding":
    "latin-1" for arguments holding bytes that are not UTF-8); "input", the file of
    the folder given as "@", or "generate": {"seed": name, "mutations": [specs]} to
    make it from a seed with tools/fuzz/hdf5_mutations.py, or "special": one of
    SPECIAL_INPUTS in its place; "exit" (default 2);
    "names", texts the message must contain; "outputs", what an exit 3 writes."""
    work = tempfile.mkdtemp(prefix="gesmi-fuzz-replay-")
    failed = 0
    try:
        seeds = targets.make_seeds(args.gesmi, REPO, os.path.join(work, "seeds"))
        limit_resources(args.memory_mb, args.gesmi)
        folders = []
        for root in args.replay:
            folders += sorted(os.path.join(root, d) for d in os.listdir(root) if os.path.isfile(os.path.join(root, d, "case.json")))
        for folder in folders:
            with open(os.path.join(folder, "case.json")) as f:
                spec = json.load(f)
            case_folder = os.path.join(work, os.path.basename(folder))
            os.makedirs(case_folder)
            input_name = spec.get("input", "")
            if "generate" in spec:  # an HDF5 seed edited by the listed mutations
                gen = spec["generate"]
                shutil.copy(seeds[gen["seed"]], os.path.join(case_folder, input_name))
                for m in gen["mutations"]:
                    hdf5_mutations.apply(m, os.path.join(case_folder, input_name))
            elif "special" in spec:  # not a regular file (SPECIAL_INPUTS)
                make_special(os.path.join(case_folder, input_name), spec["special"])
            elif input_name:
                shutil.copy(os.path.join(folder, input_name), case_folder)
            case = Case(targets.Reader(spec["title"], "replay", [], [], input_name), 0)
            case.folder = case_folder
            command = spec["args"]
            if spec.get("arg_encoding"):  # arguments holding bytes that are not UTF-8
                command = [a.encode(spec["arg_encoding"]) for a in command]
                command = [a.decode() if a.startswith(b"$") or a == b"@" else a for a in command]
            case.args = substitute(command, case_folder, input_name, seeds)
            case.must_name = [input_name] if input_name else []
            case.outputs = spec.get("outputs", [])
            result, failures, left = run_case(case, args.gesmi, args.timeout, [input_name] if input_name else [])
            expected = spec.get("exit", 2)
            if result.code != expected and not failures:
                failures.append("exit %s, expected %d" % (result.code, expected))
            message = result.stderr.decode("utf-8", "backslashreplace")
            for text in spec.get("names", []):
                if text not in message:
                    failures.append("message does not name %r" % text)
            status = "FAIL" if failures else "ok"
            print("%-4s %s: exit %s: %s" % (status, os.path.basename(folder), result.code, message.strip()[:200]))
            for f in failures:
                print("     " + f)
            failed += bool(failures)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("%d of %d cases failed" % (failed, len(folders)))
    return 1 if failed else 0


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--gesmi", default=os.path.join(REPO, "build/bin/gesmi"), help="binary under test")
    p.add_argument("--seed", default="1", help="random seed of the run")
    p.add_argument("--cases", type=int, default=100, help="cases per reader")
    p.add_argument("--readers", nargs="*", choices=targets.reader_names(), help="only these readers")
    p.add_argument("--timeout", type=float, default=10.0, help="seconds per case before it counts as a hang")
    p.add_argument("--jobs", type=int, default=2, help="cases run at once")
    p.add_argument("--memory-mb", type=int, default=4096, help="address-space limit of each case (0: none)")
    p.add_argument("--keep-failures", metavar="DIR", help="copy failing inputs and their case.json here")
    p.add_argument("--keep-per-class", type=int, default=3, help="kept per (class, reader, mutation)")
    p.add_argument("--mutations", type=int, default=3, help="most mutations stacked in one case (1 to 3)")
    p.add_argument("--exclude-ops", nargs="*", default=[], metavar="OP",
                   help="never pick these mutations (e.g. to look past a known failure)")
    p.add_argument("--accepted", action="store_true", help="also list the mutations that exited 0")
    p.add_argument("--raw-hdf5", action="store_true",
                   help="also flip raw bytes inside HDF5 files (may crash libhdf5 itself; not in CI)")
    p.add_argument("--replay", nargs="+", metavar="DIR", help="run the saved cases under these folders instead")
    args = p.parse_args()
    args.gesmi = os.path.abspath(args.gesmi)
    if args.keep_failures:
        args.keep_failures = os.path.abspath(args.keep_failures)
    return replay(args) if args.replay else fuzz(args)


if __name__ == "__main__":
    sys.exit(main())
