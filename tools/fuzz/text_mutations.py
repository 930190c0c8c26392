"""Mutations of text inputs (CSV, YAML, GESMI text logs), as bytes.

Each mutation is chosen by `pick(rng, data, kind)` as a plain dict (the "spec": the
operation's name and every parameter it needs) and applied by `apply(spec, data)`, so a
case is reproducible from its spec alone and can be written to a report.
"""

import re

# Values that replace a field: overflow, underflow, non-finite, malformed numbers,
# words, control characters and encoding junk.
ODD_VALUES = [
    b"1e308", b"1e309", b"-1e309", b"1e-400", b"4.9e-324", b"nan", b"NaN", b"-nan", b"inf", b"-inf",
    b"infinity", b"9" * 400, b"-" + b"9" * 40, b"0x1p3", b"1,5", b"", b"?", b"\x00", b"1e", b".", b"+-1",
    b"--1", b"1..2", b"true", b"~", b"'1'", b'"1"', b"\xd9\xa1\xd9\xa2", b"1\x07", b"\x1b[31mred",
    b"a\nb", b"\r", b"\t", b"\xff\xfe", b"2147483648", b"-2147483649", b"9223372036854775808", b"-1",
    b"0", b"1e-320", b"x" * 5000,
]

CONTROL_CHARS = [b"\x00", b"\x07", b"\x08", b"\x1b", b"\r", b"\x0b", b"\x0c", b"\x7f", b"\t", b"\x01"]

ENCODING_JUNK = [b"\xff\xfe", b"\xef\xbb\xbf", b"\xc3\x28", b"\xed\xa0\x80", b"\xf8\x88\x80\x80\x80",
                 b"\xe2\x80\xae", b"\x00\x00", b"\xc0\xaf"]

INSERTED_LINES = [b"", b",,,,", b"...", b"---", b"#", b" ", b"\t", b"\x00\x01\x02", b"\xff" * 8,
                  b",".join([b"1"] * 10000), b"1 " * 5000]

# YAML structure edits (the sensor model and scenario readers).
YAML_VALUES = [b"{a: 1}", b"[1, 2]", b"[]", b"{}", b"~", b"null", b'""', b"!!binary aGVsbG8=", b"&x 1",
               b"*undefined", b"!!str 1", b"!custom 3", b"|\n  1", b">-", b"[[[]]]", b"? a", b"!!float",
               b"0x10", b"0o17", b".inf", b"-.inf", b".nan", b"1_000", b"+12e3", b"yes", b"true"]
YAML_KEYS = [b"{a: 1}", b"[1, 2]", b"? [a, b]\n", b"~", b"1", b"true", b'""', b"<<", b"&k key", b"!!int key"]
YAML_PREFIXES = [b"...\n", b",,,,\n", b"---\n---\n", b"~\n---\n", b"--- ~\n", b"--- !!null\n", b"%YAML 1.2\n---\n",
                 b"--- []\n---\n", b"# only a comment\n...\n"]
YAML_SUFFIXES = [b"---\nfoo: 1\n", b"---\n", b"...\n---\n[1, 2]\n", b"\n...\n", b"---\n- 1\n"]


def _lines(data):
    return data.split(b"\n")


def _join(lines):
    return b"\n".join(lines)


def _pick_line(rng, lines):
    # Half of the edits land on the first lines (headers, first document keys).
    if rng.random() < 0.5:
        return rng.randrange(min(len(lines), 4))
    return rng.randrange(len(lines))


def _tokens(line):
    """(start, end) of each field: runs of characters other than separators."""
    return [(m.start(), m.end()) for m in re.finditer(rb"[^,\s:\[\]{}]+", line)]


def _yaml_key_lines(lines):
    return [i for i, l in enumerate(lines) if re.match(rb"^\s*-?\s*[A-Za-z_][A-Za-z0-9_]*\s*:", l)]


def pick(rng, data, kind, exclude=()):
    """A mutation spec for `data`; kind is 'csv', 'yaml' or 'txt' (never an op in exclude)."""
    lines = _lines(data)
    ops = ["byte_flip", "insert_line", "delete_line", "duplicate_line", "swap_lines", "duplicate_field",
           "delete_field", "control_char", "replace_token", "long_line", "truncate", "encoding_junk",
           "line_endings", "empty_file"]
    weights = [3, 3, 3, 2, 1, 3, 3, 3, 8, 1, 2, 2, 1, 0.3]
    if kind == "yaml":
        ops += ["yaml_prefix", "yaml_suffix", "yaml_doc_end", "yaml_duplicate_key", "yaml_key_collection",
                "yaml_value", "yaml_deep_nesting", "yaml_tabs", "yaml_alias"]
        weights += [3, 3, 2, 4, 3, 6, 2, 1, 1]
    weights = [0 if o in exclude else w for o, w in zip(ops, weights)]
    op = rng.choices(ops, weights)[0]
    spec = {"op": op}
    n = len(data)
    if op == "byte_flip":
        spec["at"] = [rng.randrange(max(n, 1)) for _ in range(rng.choice([1, 1, 2, 8]))]
        spec["xor"] = rng.choice([1, 2, 4, 8, 16, 32, 64, 128, 255])
    elif op == "insert_line":
        spec["at"] = _pick_line(rng, lines)
        spec["text"] = rng.choice(INSERTED_LINES + [lines[rng.randrange(len(lines))]])
    elif op in ("delete_line", "duplicate_line"):
        spec["at"] = _pick_line(rng, lines)
    elif op == "swap_lines":
        spec["at"] = [_pick_line(rng, lines), _pick_line(rng, lines)]
    elif op in ("duplicate_field", "delete_field", "replace_token"):
        spec["line"] = _pick_line(rng, lines)
        spec["token"] = rng.randrange(16)
        if op == "replace_token":
            spec["value"] = rng.choice(ODD_VALUES + (YAML_VALUES if kind == "yaml" else []))
    elif op == "control_char":
        spec["at"] = rng.randrange(n + 1)
        spec["char"] = rng.choice(CONTROL_CHARS)
    elif op == "long_line":
        spec["line"] = _pick_line(rng, lines)
        spec["text"] = rng.choice([b"x", b"9", b",", b" ", b"1,"]) * rng.choice([1000, 100000])
    elif op == "truncate":
        spec["at"] = rng.randrange(n + 1)
    elif op == "encoding_junk":
        spec["at"] = rng.choice([0, rng.randrange(n + 1)])
        spec["junk"] = rng.choice(ENCODING_JUNK + [b"utf-16"])
    elif op == "line_endings":
        spec["ending"] = rng.choice([b"\r\n", b"\r", b"\n\n", b"\x85", b"\xe2\x80\xa8"])
    elif op == "yaml_prefix":
        spec["text"] = rng.choice(YAML_PREFIXES)
    elif op == "yaml_suffix":
        spec["text"] = rng.choice(YAML_SUFFIXES)
    elif op == "yaml_doc_end":
        spec["at"] = rng.randrange(len(lines))
        spec["text"] = rng.choice([b"...", b"---", b"--- ~"])
    elif op == "yaml_duplicate_key":
        keys = _yaml_key_lines(lines) or [0]
        spec["line"] = rng.choice(keys)
        spec["value"] = rng.choice([None, b"7", b"-1", b"starboard", b"{a: 1}"])
    elif op == "yaml_key_collection":
        keys = _yaml_key_lines(lines) or [0]
        spec["line"] = rng.choice(keys)
        spec["key"] = rng.choice(YAML_KEYS)
    elif op == "yaml_value":
        keys = _yaml_key_lines(lines) or [0]
        spec["line"] = rng.choice(keys)
        spec["token"] = rng.randrange(8)
        spec["value"] = rng.choice(YAML_VALUES)
    elif op == "yaml_deep_nesting":
        keys = _yaml_key_lines(lines) or [0]
        spec["line"] = rng.choice(keys)
        spec["depth"] = rng.choice([100, 1000, 10000, 100000])
        spec["style"] = rng.choice(["flow_seq", "flow_map", "block"])
    elif op == "yaml_tabs":
        spec["line"] = _pick_line(rng, lines)
    elif op == "yaml_alias":
        keys = _yaml_key_lines(lines) or [0]
        spec["line"] = rng.choice(keys)
        spec["levels"] = rng.choice([3, 9])
    return spec


def _replace_token(line, index, value):
    tokens = _tokens(line)
    if not tokens:
        return line + value
    start, end = tokens[index % len(tokens)]
    return line[:start] + value + line[end:]


def _nested(depth, style):
    if style == "flow_seq":
        return b"[" * depth + b"1" + b"]" * depth
    if style == "flow_map":
        return b"{a: " * depth + b"1" + b"}" * depth
    return b"\n" + b"".join(b"  " * (i + 1) + b"k:\n" for i in range(min(depth, 3000))) + b"  " * 3001 + b"1"


def apply(spec, data):
    """The mutated bytes."""
    op = spec["op"]
    lines = _lines(data)
    if op == "byte_flip":
        b = bytearray(data)
        for at in spec["at"]:
            if at < len(b):
                b[at] ^= spec["xor"]
        return bytes(b)
    if op == "insert_line":
        lines.insert(spec["at"], spec["text"])
        return _join(lines)
    if op == "delete_line":
        del lines[spec["at"]]
        return _join(lines)
    if op == "duplicate_line":
        lines.insert(spec["at"], lines[spec["at"]])
        return _join(lines)
    if op == "swap_lines":
        a, b = spec["at"]
        lines[a], lines[b] = lines[b], lines[a]
        return _join(lines)
    if op in ("duplicate_field", "delete_field", "replace_token"):
        line = lines[spec["line"]]
        tokens = _tokens(line)
        if not tokens:
            lines[spec["line"]] = line + b",1" if op == "duplicate_field" else line
            return _join(lines)
        start, end = tokens[spec["token"] % len(tokens)]
        if op == "duplicate_field":
            sep = b"," if b"," in line else b" "
            lines[spec["line"]] = line[:end] + sep + line[start:end] + line[end:]
        elif op == "delete_field":
            cut_end = end + 1 if end < len(line) else end
            lines[spec["line"]] = line[:start] + line[cut_end:]
        else:
            lines[spec["line"]] = line[:start] + spec["value"] + line[end:]
        return _join(lines)
    if op == "control_char":
        return data[:spec["at"]] + spec["char"] + data[spec["at"]:]
    if op == "long_line":
        lines[spec["line"]] = lines[spec["line"]] + spec["text"]
        return _join(lines)
    if op == "truncate":
        return data[:spec["at"]]
    if op == "encoding_junk":
        if spec["junk"] == b"utf-16":
            return b"\xff\xfe" + data.decode("latin-1").encode("utf-16-le")
        return data[:spec["at"]] + spec["junk"] + data[spec["at"]:]
    if op == "line_endings":
        return data.replace(b"\n", spec["ending"])
    if op == "empty_file":
        return b""
    if op == "yaml_prefix":
        return spec["text"] + data
    if op == "yaml_suffix":
        return data + (b"" if data.endswith(b"\n") else b"\n") + spec["text"]
    if op == "yaml_doc_end":
        lines.insert(spec["at"], spec["text"])
        return _join(lines)
    if op == "yaml_duplicate_key":
        line = lines[spec["line"]]
        if spec["value"] is not None and b":" in line:
            indent_key = line.split(b":", 1)[0]
            line = indent_key + b": " + spec["value"]
        lines.insert(spec["line"] + 1, line)
        return _join(lines)
    if op == "yaml_key_collection":
        line = lines[spec["line"]]
        m = re.match(rb"^(\s*-?\s*)([A-Za-z_][A-Za-z0-9_]*)(\s*:.*)$", line)
        if m:
            lines[spec["line"]] = m.group(1) + spec["key"] + m.group(3)
        return _join(lines)
    if op == "yaml_value":
        line = lines[spec["line"]]
        key, _, value = line.partition(b":")
        lines[spec["line"]] = key + b": " + (_replace_token(value, spec["token"], spec["value"]) if value.strip()
                                            else spec["value"])
        return _join(lines)
    if op == "yaml_deep_nesting":
        line = lines[spec["line"]]
        key = line.split(b":", 1)[0]
        lines[spec["line"]] = key + b": " + _nested(spec["depth"], spec["style"])
        return _join(lines)
    if op == "yaml_tabs":
        line = lines[spec["line"]]
        stripped = line.lstrip(b" ")
        lines[spec["line"]] = b"\t" * max(1, len(line) - len(stripped)) + stripped
        return _join(lines)
    if op == "yaml_alias":
        # A "billion laughs" chain of aliases as the value of a known key.
        chain = [b"a0: &a0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]"]
        for i in range(1, spec["levels"] + 1):
            chain.append(b"a%d: &a%d [" % (i, i) + b", ".join([b"*a%d" % (i - 1)] * 10) + b"]")
        line = lines[spec["line"]]
        key = line.split(b":", 1)[0]
        lines[spec["line"]] = key + b": {" + b", ".join(chain) + b"}"
        return _join(lines)
    raise ValueError("unknown text mutation " + op)
