"""Structural mutations of HDF5 inputs (mission and result files), made with h5py.

`inventory(path)` lists a seed file's groups, datasets and attributes; `pick(rng, inv,
raw)` chooses one mutation as a plain dict (the "spec"), and `apply(spec, path)` edits a
copy of the seed in place. The mutations keep the file a valid HDF5 file (only its
content is wrong) except `truncate`, and `raw_flip` which flips bytes anywhere in the
file: those may break libhdf5 itself, so they are only picked when `raw` is true (not in
the CI run; see docs/testing.md).
"""

import os

import h5py
import numpy as np

HUGE_ROWS = 10 ** 12

FLOAT_VALUES = [float("nan"), float("inf"), float("-inf"), 1e308, -1e308, 0.0, -1.0, 1e-320, 1e15, 0.5]
INT_VALUES = [-1, -2, 999, 2 ** 31 - 1, -2 ** 31, 64, 65, 0, 2, 7]
ATTR_NUMBERS = [float("nan"), float("inf"), float("-inf"), 0, -1, 1e300, 2 ** 31 - 1, 2 ** 31, -2 ** 31,
                2 ** 62, 65, 1e-320, 0.5, 90.5, -200.0]
ATTR_STRINGS = ["", "garbage", "x" * 100000, "bad\x07\nvalue\x1b[0m", b"\xff\xfe\xfd", "gesmi-mission", "gesmi-result",
                "inconsistent", "port", "both", "0123456789abcdef", "zzzzzzzzzzzzzzzz"]
RETYPES = ["str_number", "str_text", "int", "float", "bool", "enum", "vlen_str", "empty_str", "int8", "uint64",
           "float32", "empty_array", "null"]
DSET_TYPES = ["int32", "int64", "uint8", "float32", "float16", "bool", "enum", "fixed_str", "vlen_str", "compound"]


def inventory(path):
    """Sorted lists of the file's groups, datasets (path, shape, kind) and attributes."""
    groups, datasets, attrs = ["/"], [], []
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            p = "/" + name
            if isinstance(obj, h5py.Dataset):
                datasets.append((p, tuple(obj.shape), obj.dtype.kind))
            else:
                groups.append(p)
        f.visititems(visit)
        for obj in groups + [d[0] for d in datasets]:
            for name in f[obj].attrs:
                value = f[obj].attrs[name]
                kind = "str" if isinstance(value, (bytes, str)) else ("int" if np.issubdtype(np.asarray(value).dtype, np.integer)
                                                                  else "float")
                attrs.append((obj, name, kind))
    return {"groups": sorted(groups), "datasets": sorted(datasets), "attrs": sorted(attrs), "size": os.path.getsize(path)}


def _other_shapes(rng, shape):
    rows = shape[0] if shape else 1
    choices = [(), (rows, 1) if len(shape) == 1 else (rows * shape[1],), (rows, 2, 2), (max(rows - 1, 0),) + shape[1:],
               (rows + 1,) + shape[1:], (0,) + shape[1:], (1,) + shape[1:]]
    if len(shape) == 2:
        choices += [(rows, max(shape[1] - 1, 0)), (rows, shape[1] + 1), (rows, 0), (shape[1], rows)]
    return list(rng.choice(choices))


def pick(rng, inv, raw=False, exclude=()):
    """A mutation spec for a copy of the inventoried file (never an op in exclude)."""
    ops = ["attr_array", "attr_retype", "attr_value", "attr_delete", "obj_delete", "dset_to_group", "group_to_dset",
           "dset_reshape", "dset_huge", "dset_retype", "dset_values", "link", "add_junk", "truncate"]
    weights = [3, 4, 4, 2, 3, 2, 2, 4, 2, 3, 8, 1, 0.5, 1]
    if raw:
        ops.append("raw_flip")
        weights.append(6)
    weights = [0 if o in exclude else w for o, w in zip(ops, weights)]
    op = rng.choices(ops, weights)[0]
    spec = {"op": op}
    datasets, groups, attrs = inv["datasets"], inv["groups"], inv["attrs"]
    if op.startswith("attr_"):
        obj, name, kind = rng.choice(attrs)
        spec.update(obj=obj, name=name)
        if op == "attr_array":
            spec["n"] = rng.choice([2, 1000])
        elif op == "attr_retype":
            spec["to"] = rng.choice(RETYPES)
        elif op == "attr_value":
            spec["value"] = rng.choice(ATTR_STRINGS if kind == "str" else ATTR_NUMBERS)
            if isinstance(spec["value"], bytes):
                spec["value"] = spec["value"].decode("latin-1")
                spec["raw_bytes"] = True
    elif op == "obj_delete":
        spec["path"] = rng.choice([d[0] for d in datasets] + groups[1:])
    elif op == "dset_to_group":
        spec["path"] = rng.choice(datasets)[0]
        spec["with_child"] = rng.random() < 0.5
    elif op == "group_to_dset":
        spec["path"] = rng.choice(groups[1:])
        spec["shape"] = rng.choice([[], [3], [2, 2], [6001, 3]])
    elif op == "dset_reshape":
        path, shape, _ = rng.choice(datasets)
        spec.update(path=path, shape=_other_shapes(rng, shape))
    elif op == "dset_huge":
        path, shape, _ = rng.choice(datasets)
        spec.update(path=path, shape=[HUGE_ROWS] + list(shape[1:]) if rng.random() < 0.8 else [shape[0] if shape else 1, 10 ** 9],
                    chunked=rng.random() < 0.5)
    elif op == "dset_retype":
        spec.update(path=rng.choice(datasets)[0], to=rng.choice(DSET_TYPES))
    elif op == "dset_values":
        path, shape, kind = rng.choice(datasets)
        rows = shape[0] if shape else 1
        edits = ["set", "set", "shift"]
        if rows >= 2:
            edits += ["swap", "reverse", "constant"]
        if path.endswith("time"):
            edits += ["swap", "constant", "reverse", "set"]
        if path.endswith("/lower") or path.endswith("/upper"):
            edits += ["bounds_cross", "bounds_cross"]
        spec.update(path=path, edit=rng.choice(edits), row=rng.randrange(max(rows, 1)),
                    other=rng.randrange(max(rows, 1)),
                    value=rng.choice(INT_VALUES if kind in "iub" else FLOAT_VALUES))
    elif op == "link":
        spec["path"] = rng.choice([d[0] for d in datasets] + groups[1:])
        spec["kind"] = rng.choice(["soft_dangling", "soft_other", "external", "soft_loop"])
        spec["target"] = rng.choice([d[0] for d in datasets] + groups)
    elif op == "add_junk":
        spec["path"] = rng.choice(groups)
        spec["kind"] = rng.choice(["dataset", "group", "attr"])
    elif op == "truncate":
        spec["fraction"] = rng.choice([0.0, rng.random(), rng.random(), 0.999])
    elif op == "raw_flip":
        # Half of the flips hit the first 8 KiB, where the superblock and most object
        # headers are; the rest anywhere (mostly raw data).
        size = inv["size"]
        spec["offsets"] = [rng.randrange(min(size, 8192)) if rng.random() < 0.5 else rng.randrange(size)
                           for _ in range(rng.choice([1, 2, 4, 16]))]
        spec["xor"] = rng.choice([1, 4, 16, 128, 255])
    return spec


def _attr_data(to, old):
    old = np.asarray(old)
    if to == "str_number":
        return np.bytes_(str(old.item() if old.size == 1 and old.dtype.kind != "S" else "6")), None
    if to == "str_text":
        return "not a number", None
    if to == "int":
        return np.int64(7), None
    if to == "float":
        return np.float64(6.5), None
    if to == "bool":
        return np.bool_(True), None
    if to == "enum":
        return 1, h5py.enum_dtype({"A": 0, "B": 1}, basetype="i1")
    if to == "vlen_str":
        return "gesmi-mission", h5py.string_dtype()
    if to == "empty_str":
        return np.bytes_(b""), None
    if to == "int8":
        return np.int8(-3), None
    if to == "uint64":
        return np.uint64(2 ** 63), None
    if to == "float32":
        return np.float32(0.25), None
    if to == "empty_array":
        return np.zeros((0,), dtype="f8"), None
    if to == "null":
        return h5py.Empty("f8"), None
    raise ValueError(to)


def _retyped(data, to):
    data = np.asarray(data)
    if to in ("int32", "int64", "uint8", "float32", "float16"):
        with np.errstate(all="ignore"):
            return np.nan_to_num(data).astype(to) if to[0] in "iu" else data.astype(to), None
    if to == "bool":
        return data != 0, None
    if to == "enum":
        return (np.nan_to_num(data) != 0).astype("i1"), h5py.enum_dtype({"NO": 0, "YES": 1}, basetype="i1")
    if to == "fixed_str":
        return np.array([b"%g" % x for x in data.ravel()]).reshape(data.shape), None
    if to == "vlen_str":
        return np.array(["%g" % x for x in data.ravel()], dtype=object).reshape(data.shape), h5py.string_dtype()
    if to == "compound":
        out = np.zeros(data.shape, dtype=[("a", "f8"), ("b", "i4")])
        out["a"] = data
        return out, None
    raise ValueError(to)


def _edit_values(data, spec):
    data = np.array(data)
    if data.ndim == 0:
        return np.asarray(spec["value"]).astype(data.dtype)
    flat = data.reshape(data.shape[0], -1) if data.shape[0] else data
    r, o, v = spec["row"], spec["other"], spec["value"]
    edit = spec["edit"]
    if data.shape[0] == 0:
        return data
    with np.errstate(all="ignore"):
        if edit == "set":
            flat[r, 0 if flat.ndim > 1 else ...] = v if data.dtype.kind == "f" else int(np.clip(v, -2 ** 31, 2 ** 31 - 1))
        elif edit == "shift":
            flat[...] = flat + (v if data.dtype.kind == "f" else 1)
        elif edit == "swap":
            flat[[r, o]] = flat[[o, r]]
        elif edit == "reverse":
            flat[...] = flat[::-1].copy()
        elif edit == "constant":
            flat[...] = flat[r]
        elif edit == "bounds_cross":
            flat[r] = flat[r] + (1e3 if spec["path"].endswith("lower") else -1e3)
    return data


def apply(spec, path):
    """Edits the file at path (a copy of the seed) as the spec says."""
    op = spec["op"]
    if op == "truncate":
        os.truncate(path, int(os.path.getsize(path) * spec["fraction"]))
        return
    if op == "raw_flip":
        with open(path, "r+b") as f:
            for offset in spec["offsets"]:
                f.seek(offset)
                b = f.read(1)
                f.seek(offset)
                f.write(bytes([b[0] ^ spec["xor"]]) if b else b"")
        return
    with h5py.File(path, "r+") as f:
        if op.startswith("attr_"):
            attrs = f[spec["obj"]].attrs
            old = attrs[spec["name"]]
            if op == "attr_delete":
                del attrs[spec["name"]]
            elif op == "attr_array":
                value = np.asarray(old)
                attrs[spec["name"]] = np.repeat(value.reshape(1), spec["n"]) if value.dtype.kind != "O" else [value.item()] * spec["n"]
            elif op == "attr_retype":
                data, dtype = _attr_data(spec["to"], old)
                del attrs[spec["name"]]
                attrs.create(spec["name"], data, dtype=dtype)
            elif op == "attr_value":
                value = spec["value"]
                if isinstance(value, str):
                    value = np.bytes_(value.encode("latin-1" if spec.get("raw_bytes") else "utf-8"))
                elif isinstance(old, (np.integer, int)) and float(value).is_integer() and abs(value) < 2 ** 63:
                    value = np.int64(value)
                else:
                    value = np.float64(value)
                del attrs[spec["name"]]
                attrs[spec["name"]] = value
        elif op == "obj_delete":
            del f[spec["path"]]
        elif op == "dset_to_group":
            del f[spec["path"]]
            g = f.create_group(spec["path"])
            if spec["with_child"]:
                g.create_dataset("lower", data=np.zeros(3))
        elif op == "group_to_dset":
            del f[spec["path"]]
            shape = tuple(spec["shape"])
            f.create_dataset(spec["path"], data=np.ones(shape) if shape else np.float64(1.0))
        elif op == "dset_reshape":
            old = f[spec["path"]][()]
            del f[spec["path"]]
            shape = tuple(spec["shape"])
            size = int(np.prod(shape)) if shape else 1
            flat = np.asarray(old).ravel()
            data = np.resize(flat, size) if flat.size else np.zeros(size, dtype=np.asarray(old).dtype)
            f.create_dataset(spec["path"], data=data.reshape(shape) if shape else data[0])
        elif op == "dset_huge":
            dtype = f[spec["path"]].dtype
            del f[spec["path"]]
            shape = tuple(spec["shape"])
            chunks = tuple([1024] + list(shape[1:])) if spec["chunked"] and shape[-1] < 10 ** 6 else None
            f.create_dataset(spec["path"], shape=shape, dtype=dtype, chunks=chunks)
        elif op == "dset_retype":
            old = f[spec["path"]][()]
            del f[spec["path"]]
            data, dtype = _retyped(old, spec["to"])
            f.create_dataset(spec["path"], data=data, dtype=dtype)
        elif op == "dset_values":
            d = f[spec["path"]]
            old = np.asarray(d[()])
            new = np.asarray(_edit_values(old, spec), dtype=old.dtype)
            d[...] = new
            spec["changed"] = old.tobytes() != new.tobytes()  # (a swap of equal rows changes nothing)
        elif op == "link":
            del f[spec["path"]]
            kind = spec["kind"]
            if kind == "soft_dangling":
                f[spec["path"]] = h5py.SoftLink("/does/not/exist")
            elif kind == "soft_other":
                f[spec["path"]] = h5py.SoftLink(spec["target"])
            elif kind == "soft_loop":
                f[spec["path"]] = h5py.SoftLink(spec["path"])
            else:
                f[spec["path"]] = h5py.ExternalLink("missing-file.h5", spec["target"])
        elif op == "add_junk":
            g = f[spec["path"]]
            if spec["kind"] == "dataset":
                g.create_dataset("zz_unknown", data=np.arange(5.0))
            elif spec["kind"] == "group":
                g.create_group("zz_unknown")
            else:
                g.attrs["zz_unknown"] = 1
        else:
            raise ValueError("unknown HDF5 mutation " + op)
