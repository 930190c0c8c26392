"""The digests of a result file recomputed by an independent reader, from h5py,
Python's xxhash and hashlib, and what docs/formats.md says ("Result file", "The root
digest, for an independent reader"): every dataset digest and the root digest of a
fresh result (format 6, XXH3-128) and of the stored format-5 result (SHA-256)."""
import hashlib
import os
import struct

import h5py
import numpy as np
import pytest
import xxhash

from conftest import run_gesmi

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATASETS = ["/time", "/tube/lower", "/tube/upper", "/increments/lower", "/increments/upper", "/mines/lower",
            "/mines/upper", "/waterfall/step", "/waterfall/mine", "/waterfall/lower", "/waterfall/upper",
            "/marks/candidates", "/marks/outlier", "/marks/time", "/marks/range", "/marks/mine", "/marks/side",
            "/gps/outlier"]
MODEL_KEYS = ("dvl_relative dvl_absolute roll pitch heading depth_absolute depth_relative altitude gps_lon_deg "
              "gps_lat_deg gps_metres mark_range mine_depth_band sonar_max_range along_track_tolerance "
              "max_attitude_rate max_acceleration max_depth_rate max_altitude_rate max_jerk").split()
MODEL_KEYS_7 = MODEL_KEYS + "max_speed surface_layer_depth surface_max_jerk surface_max_speed".split()


def text(value):
    return value.decode() if isinstance(value, bytes) else value


def shortest(x):
    """The shortest decimal that reads back as x, as C++ std::to_chars writes it: repr's
    digits (also the shortest) in the shorter of the fixed and scientific forms, fixed
    on a tie."""
    x = float(x)
    if x == 0.0:
        return "-0" if np.signbit(x) else "0"
    r = repr(abs(x))
    if "e" in r:
        head, _, e = r.partition("e")
        digits, point = head.replace(".", "").rstrip("0"), int(e) + 1
    else:
        whole, _, frac = r.partition(".")
        digits = (whole + frac).lstrip("0").rstrip("0")
        point = len(whole) if whole != "0" else -(len(frac) - len(frac.lstrip("0")))
    if point <= 0:
        fixed = "0." + "0" * (-point) + digits
    elif point >= len(digits):
        fixed = digits + "0" * (point - len(digits))
    else:
        fixed = digits[:point] + "." + digits[point:]
    e = point - 1
    scientific = digits[0] + ("." + digits[1:] if len(digits) > 1 else "") + "e" + ("-" if e < 0 else "+") + f"{abs(e):02d}"
    return ("-" if x < 0 else "") + (fixed if len(fixed) <= len(scientific) else scientific)


def digest(kind):
    return xxhash.xxh3_128() if kind == "xxh128" else hashlib.sha256()


def length_prefixed(data):
    return struct.pack("<Q", len(data)) + data


def dataset_digest(kind, name, values):
    rows = values.shape[0]
    columns = values.shape[1] if values.ndim == 2 else 1
    raw = values.astype("<f8" if values.dtype.kind == "f" else "<i4").tobytes()
    h = digest(kind)
    h.update(length_prefixed(name.encode()) + struct.pack("<QQQ", rows, columns, values.size) + raw)
    return h.hexdigest()


def root_digest(f, kind):
    a = f.attrs
    fields = [("status", text(a["status"])), ("mode", text(a["mode"])), ("inconsistency", text(a["inconsistency"])),
              ("sweeps", str(int(a["sweeps"]))), ("converged", str(int(a["converged"]))),
              ("minimal_outliers", str(int(a["minimal_outliers"]))), ("mine_count", str(int(a["mine_count"])))]
    fields += [(f"{part}_{kind}", text(a[f"{part}_{kind}"])) for part in ("navigation", "bounds", "marks")]
    fields += [("mark_count", str(int(a["mark_count"]))), ("gesmi_version", text(a["gesmi_version"]))]
    if "epoch_utc" in a:
        fields.append(("epoch_utc", text(a["epoch_utc"])))
    fields += [("origin_latitude", shortest(a["origin_latitude"])), ("origin_longitude", shortest(a["origin_longitude"])),
               ("datum", text(a["datum"]))]
    version = int(a["format_version"])
    if version >= 7:
        fields.append(("surface_steps", str(int(a["surface_steps"]))))
        for count, times in (("fallback_steps", "fallback_times"), ("speed_exceeded_samples", "speed_exceeded_times")):
            fields += [(count, str(int(a[count]))), (times, text(a[times]))]
    model = f["/model"].attrs
    fields += [(f"/model/{key}", shortest(model[key])) for key in (MODEL_KEYS_7 if version >= 7 else MODEL_KEYS)]
    fields += [(f"/model/{key}", text(model[key])) for key in ("sonar_side", "step_model")]
    fields += [(name, text(f[name].attrs[kind])) for name in DATASETS]
    h = digest(kind)
    for name, value in fields:
        h.update(length_prefixed(name.encode()) + length_prefixed(value.encode()))
    return h.hexdigest()


def check_digests(path, kind):
    with h5py.File(path, "r") as f:
        for name in DATASETS:
            assert dataset_digest(kind, name, f[name][()]) == text(f[name].attrs[kind]), name
        assert root_digest(f, kind) == text(f.attrs[kind])


def test_shortest_is_cpp_to_chars():
    # What libstdc++'s std::to_chars(first, last, x) wrote for these (GCC 12, Debian 12)
    for x, expected in [(1.0, "1"), (9e-06, "9e-06"), (100000.0, "1e+05"), (123456.0, "123456"), (0.1, "0.1"),
                        (1e-05, "1e-05"), (0.0001, "1e-04"), (0.001, "0.001"), (1.5e300, "1.5e+300"), (-2.5, "-2.5"),
                        (1e16, "1e+16"), (48.3, "48.3"), (-4.25, "-4.25"), (0.2, "0.2"), (2e-05, "2e-05"),
                        (0.05, "0.05")]:
        assert shortest(x) == expected, x


def test_a_fresh_result_has_the_digests_formats_md_describes(mission_file, tmp_path):
    out = str(tmp_path / "r.h5")
    r = run_gesmi("solve", mission_file, "-o", out)
    assert r.returncode == 0, r.stderr
    with h5py.File(out, "r") as f:
        assert int(f.attrs["format_version"]) == 7
    check_digests(out, "xxh128")


def test_the_stored_format_5_result_has_sha256_digests():
    check_digests(os.path.join(SOURCE, "tests", "data", "format5", "result-format5.h5"), "sha256")


def test_an_edited_value_changes_the_recomputed_digest(mission_file, tmp_path):
    # The check above can fail: one changed bit of a tube bound changes its digest.
    out = str(tmp_path / "r.h5")
    assert run_gesmi("solve", mission_file, "-o", out).returncode == 0
    with h5py.File(out, "r+") as f:
        lo = f["/tube/lower"][()]
        lo[10, 0] = np.nextafter(lo[10, 0], -np.inf)
        f["/tube/lower"][...] = lo
    with pytest.raises(AssertionError):
        check_digests(out, "xxh128")
