"""Readers, writers and their errors (geometry.io)."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geometry import io
from geometry.errors import (
    CoordinateError,
    DegenerateError,
    HoleError,
    HolesNotSupportedError,
    InputFormatError,
    SelfIntersectionError,
    TooFewPointsError,
)
from geometry.io import (
    polygon_to_json_points,
    read_polygon,
    read_rings,
    to_dat,
    to_geojson,
    to_json,
    to_wkt,
    write_json,
    write_polygon,
)
from geometry.polygon import Polygon
from geometry.samples import make_sample, minimum_n

DATA = Path(__file__).parent / "data"
BAD = DATA / "bad"
HOLES = DATA / "holes"
COUNTER = [(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)]
GENERATORS = ["random-star", "random-2opt", "random-orthogonal", "random-spiral", "random-comb"]

# Every bad input: the error class and a fragment of its one-line message.
BAD_INPUTS = {
    "missing.json": (InputFormatError, "no such file or sample: "),
    "directory.json": (InputFormatError, "is a directory"),
    "empty.json": (InputFormatError, "file is empty"),
    "not-json.json": (InputFormatError, "not valid JSON: Expecting value at line 1 column 1"),
    "truncated.json": (InputFormatError, "truncated JSON: input ends early at line 1 column 28"),
    "not-utf8.json": (InputFormatError, "not UTF-8 text: byte 0xff at offset 25"),
    "not-geojson.json": (InputFormatError, "JSON object has no 'type'"),
    "two-points.json": (TooFewPointsError, "polygon has 2 distinct points; at least 3 are needed"),
    "repeated-points.json": (TooFewPointsError, "polygon has 2 distinct points"),
    "three-coordinates.json": (CoordinateError, "point 0 has 3 coordinates; expected 2"),
    "string-coordinates.json": (CoordinateError, "coordinate x of point 0 is not a number: '0'"),
    "nan.json": (CoordinateError, "coordinate y of point 1 is NaN"),
    "infinity.json": (CoordinateError, "coordinate x of point 1 is +inf"),
    "minus-infinity.json": (CoordinateError, "coordinate y of point 2 is -inf"),
    "huge-number.json": (CoordinateError, "coordinate x of point 1 is +inf"),
    "huge-integer.json": (CoordinateError, "coordinate x of point 1 is +inf"),
    "collinear.json": (DegenerateError, "all 4 points are collinear"),
    "bow-tie.json": (SelfIntersectionError, "edges B–C and D–A cross at (1, 1)"),
    "pinch.json": (SelfIntersectionError, "vertex (1, 1) appears twice (pinch)"),
    "spike.json": (SelfIntersectionError, "zero-width spike at vertex F (2, 7)"),
    "overlapping-edges.json": (SelfIntersectionError,
                                "edges B–C and F–G overlap from (2, 0) to (4, 0)"),
    "hole.geojson": (HoleError, "hole 1 touches the outer ring at (1, 1)"),
    "hole-crosses.json": (HoleError, "hole 1 crosses the outer ring at (10, 5)"),
    "holes-overlap.json": (HoleError, "holes 1 and 3 overlap: their edges cross at (3, 4)"),
    "hole-inside-hole.json": (HoleError, "hole 2 lies inside hole 1"),
    "hole-outside.json": (HoleError, "hole 1 lies outside the polygon"),
    "hole-touches.wkt": (HoleError, "hole 3 touches the outer ring at (0, 5)"),
    "hole-bow-tie.geojson": (SelfIntersectionError, "hole 1: edges d₁–c₁ and b₁–a₁ cross at (3, 3)"),
    "multipolygon.geojson": (
        InputFormatError,
        "GeoJSON MultiPolygon has 2 polygons; expected exactly one",
    ),
    "linestring.geojson": (InputFormatError, "GeoJSON LineString is not supported"),
    "empty-collection.geojson": (InputFormatError, "FeatureCollection has 0 features"),
    "malformed.wkt": (InputFormatError, "malformed WKT: Expected word but encountered end"),
    "multipolygon.wkt": (InputFormatError, "WKT MULTIPOLYGON is not supported"),
    "bad-line.dat": (InputFormatError, "line 3: expected two numbers 'x y', got '4 zero'"),
    "unknown-extension.xyz": (
        InputFormatError,
        "unknown format '.xyz'; expected .json, .geojson, .wkt or .dat",
    ),
}


def write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def same_polygon(a: Polygon, b: Polygon) -> bool:
    return (a.points, a.labels, a.source, a.input_clockwise) == (
        b.points,
        b.labels,
        b.source,
        b.input_clockwise,
    )


def test_every_bad_file_is_in_the_table():
    assert sorted(p.name for p in BAD.iterdir()) == sorted(set(BAD_INPUTS) - {"missing.json"})


@pytest.mark.parametrize("name", sorted(BAD_INPUTS))
def test_bad_input(name):
    error, fragment = BAD_INPUTS[name]
    with pytest.raises(error) as info:
        read_polygon(BAD / name)
    assert fragment in str(info.value)
    assert "\n" not in str(info.value)


# --- the formats ---------------------------------------------------------------


def test_json_points_keep_input_order(tmp_path):
    polygon = read_polygon(write(tmp_path / "p.json", json.dumps(COUNTER)))
    assert polygon.input_points() == [(float(x), float(y)) for x, y in COUNTER]
    assert polygon.labels == ("A", "B", "C", "D", "E")


def test_integer_ring_points_are_accepted(tmp_path):
    # A closed ring of ints, as in the earcut corpus: the closing point goes silently.
    polygon = read_polygon(write(tmp_path / "p.json", "[[[0, 0], [4, 0], [4, 3], [0, 0]]]"))
    assert polygon.input_points() == [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0)]
    assert polygon.warnings == ()


def test_rings_with_holes_can_be_ignored():
    polygon = read_polygon(HOLES / "two-holes.json", ignore_holes=True)
    assert polygon.n == 4
    assert len(read_rings(HOLES / "two-holes.json")) == 3


@pytest.mark.parametrize(("name", "holes"), [("two-holes.json", "2 holes"), ("hole.wkt", "1 hole")])
def test_valid_holes_are_refused_where_a_simple_polygon_is_needed(name, holes):
    with pytest.raises(HolesNotSupportedError, match=f"polygon has {holes}; holes are not supported here"):
        read_polygon(HOLES / name)


@pytest.mark.parametrize(
    "document",
    [
        {"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [0, 3], [0, 0]]]},
        {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [
            [[0, 0], [4, 0], [0, 3], [0, 0]]]}},
        {"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": {
            "type": "Polygon", "coordinates": [[[0, 0], [4, 0], [0, 3], [0, 0]]]}}]},
    ],
)  # fmt: skip
@pytest.mark.parametrize("suffix", [".geojson", ".json"])
def test_geojson_forms(tmp_path, document, suffix):
    polygon = read_polygon(write(tmp_path / f"p{suffix}", json.dumps(document)))
    assert polygon.input_points() == [(0.0, 0.0), (4.0, 0.0), (0.0, 3.0)]


@pytest.mark.parametrize(
    ("document", "fragment"),
    [
        ({"type": "Feature", "geometry": None}, "GeoJSON Feature has no geometry"),
        (
            {"type": "Feature", "geometry": {"type": "Point", "coordinates": [0, 0]}},
            "GeoJSON Point",
        ),
        ({"type": "FeatureCollection", "features": [{}, {}]}, "has 2 features; expected exactly"),
        ({"type": "Polygon", "coordinates": [[0, 0], [1, 0], [0, 1]]}, "must be a list of rings"),
        ({"type": "Polygon"}, "must be a list of rings"),
        ({"type": "FeatureCollection", "features": [[1]]}, "feature is a JSON array"),
    ],
)
def test_geojson_errors(tmp_path, document, fragment):
    with pytest.raises(InputFormatError, match=fragment):
        read_polygon(write(tmp_path / "p.geojson", json.dumps(document)))


def test_geojson_must_be_an_object(tmp_path):
    with pytest.raises(InputFormatError, match="expected a GeoJSON object, got a JSON array"):
        read_polygon(write(tmp_path / "p.geojson", "[[0, 0], [1, 0], [0, 1]]"))


def test_wkt(tmp_path):
    polygon = read_polygon(
        write(tmp_path / "p.wkt", "POLYGON ((1 4.5, 9 2, 3 6.5, 4.6 4.1, 1.6 8, 1 4.5))")
    )
    assert polygon.input_points() == [(float(x), float(y)) for x, y in COUNTER]


@pytest.mark.parametrize(
    ("text", "error", "fragment"),
    [
        ("POLYGON EMPTY", TooFewPointsError, "0 distinct points"),
        ("POLYGON ((0 0, 1 0, 0 1))", InputFormatError, "malformed WKT: "),
        ("LINESTRING (0 0, 1 1)", InputFormatError, "WKT LINESTRING is not supported"),
        ("hello", InputFormatError, "malformed WKT: "),
        ("POLYGON Z ((0 0 1, 1 0 1, 0 1 1, 0 0 1))", CoordinateError, "3 coordinates"),
    ],
)
def test_wkt_errors(tmp_path, text, error, fragment):
    with pytest.raises(error, match=fragment) as info:
        read_polygon(write(tmp_path / "p.wkt", text))
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("suffix", [".dat", ".txt"])
def test_dat(tmp_path, suffix):
    text = "# counterexample\n1 4.5\n\n9, 2\n  3 6.5   # C\n4.6\t4.1\n1.6 8\n"
    polygon = read_polygon(write(tmp_path / f"p{suffix}", text))
    assert polygon.input_points() == [(float(x), float(y)) for x, y in COUNTER]


def test_dat_nan_is_a_coordinate_error(tmp_path):
    with pytest.raises(CoordinateError, match="coordinate x of point 1 is NaN"):
        read_polygon(write(tmp_path / "p.dat", "0 0\nnan 1\n0 1\n"))


def test_json_nested_too_deep(tmp_path):
    with pytest.raises(InputFormatError, match="nested too deeply"):
        read_polygon(write(tmp_path / "p.json", "[" * 100_000 + "]" * 100_000))


def test_byte_order_mark_is_accepted(tmp_path):
    path = tmp_path / "p.json"
    path.write_bytes(b"\xef\xbb\xbf" + json.dumps(COUNTER).encode())
    assert read_polygon(path).n == 5


def test_unreadable_file_is_one_line(tmp_path, monkeypatch):
    path = write(tmp_path / "p.json", "[]")

    def refuse(*_args):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(os, "open", refuse)
    with pytest.raises(InputFormatError, match="cannot read file: Permission denied"):
        read_polygon(path)


def test_sample_names_and_specs():
    assert read_polygon("counterexample").input_points() == [
        (0.4, 2.5), (7.0, 1.0), (4.0, 3.5), (4.4, 2.2), (0.8, 7.0)
    ]
    assert read_polygon("random-orthogonal:30:4").n == 30
    with pytest.raises(InputFormatError, match="needs n ≥ 3"):
        read_polygon("random-star:1")
    with pytest.raises(InputFormatError, match="no such file or sample: nothing-here"):
        read_polygon("nothing-here")


def test_an_existing_path_wins_over_a_sample(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    write(tmp_path / "square", "[[0, 0], [1, 0], [0, 1]]")
    with pytest.raises(InputFormatError, match="unknown format ''"):
        read_polygon("square")


# --- writing -----------------------------------------------------------------

AWKWARD = [(0.1, 0.2), (1 / 3, -1e-7), (123456789.123, 2.5), (1e15, 1e16 + 2), (-0.0, 7)]


def test_json_points_writer():
    assert polygon_to_json_points(Polygon.from_points(COUNTER)) == [[x, y] for x, y in COUNTER]
    assert json.loads(to_json(COUNTER)) == [[x, y] for x, y in COUNTER]


def test_sub_polygon_is_written_counter_clockwise():
    polygon = Polygon.from_points(make_sample("lecture"))
    part = polygon.sub_polygon([0, 1, 2, 5])
    assert polygon_to_json_points(part) == [list(polygon.points[i]) for i in (0, 1, 2, 5)]


@pytest.mark.parametrize("suffix", [".json", ".wkt", ".geojson", ".dat", ".txt"])
@pytest.mark.parametrize("name", ["counterexample", "counterexample-twin", "lecture", "awkward"])
def test_round_trip(tmp_path, suffix, name):
    points = AWKWARD if name == "awkward" else make_sample(name)
    original = Polygon.from_points(points)
    path = tmp_path / f"p{suffix}"
    write_polygon(original, path)
    assert same_polygon(read_polygon(path), original)


@settings(max_examples=40)
@given(
    name=st.sampled_from(GENERATORS),
    extra=st.integers(0, 30),
    seed=st.integers(0, 10**6),
    suffix=st.sampled_from([".json", ".wkt", ".geojson", ".dat"]),
)
def test_round_trip_generated(tmp_path_factory, name, extra, seed, suffix):
    original = Polygon.from_points(make_sample(name, minimum_n(name) + extra, seed))
    path = tmp_path_factory.mktemp("rt") / f"p{suffix}"
    write_polygon(original, path)
    assert same_polygon(read_polygon(path), original)


def test_text_writers():
    assert to_wkt([(0, 0), (1, 0), (0, 1)]) == "POLYGON ((0 0, 1 0, 0 1, 0 0))"
    assert json.loads(to_geojson([(0, 0), (1, 0), (0, 1)]))["type"] == "Polygon"
    assert to_dat([(0, 0), (0.5, 0), (0, 1)]) == "0 0\n0.5 0\n0 1\n"


def test_write_json(tmp_path):
    write_json(COUNTER, tmp_path / "c.json")
    assert json.loads((tmp_path / "c.json").read_text()) == [[x, y] for x, y in COUNTER]


def test_write_unknown_format(tmp_path):
    with pytest.raises(InputFormatError, match=r"unknown format '\.svg'"):
        write_polygon(COUNTER, tmp_path / "c.svg")
    assert list(tmp_path.iterdir()) == []


# --- never half a file ---------------------------------------------------------


@pytest.mark.parametrize("failing", ["write", "fsync", "replace"])
def test_failed_write_leaves_old_file_and_no_temp(tmp_path, monkeypatch, failing):
    target = tmp_path / "c.json"
    target.write_text("old contents")

    def boom(*args, **kwargs):
        raise OSError(28, "No space left on device")

    if failing == "write":
        real_open = open

        class HalfWriter:
            def __init__(self, *a, **k):
                self.handle = real_open(*a, **k)

            def __enter__(self):
                return self

            def __exit__(self, *exc):
                self.handle.close()

            def write(self, text):
                self.handle.write(text[:3])
                boom()

        monkeypatch.setattr(io, "open", HalfWriter, raising=False)
    else:
        monkeypatch.setattr(os, failing, boom)
    with pytest.raises(OSError, match="No space left"):
        write_json(COUNTER, target)
    assert target.read_text() == "old contents"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.json"]


def test_failed_first_write_leaves_nothing(tmp_path, monkeypatch):
    def boom(*args, **kwargs):
        raise OSError(5, "Input/output error")

    monkeypatch.setattr(os, "fsync", boom)
    with pytest.raises(OSError):
        write_polygon(COUNTER, tmp_path / "c.wkt")
    assert list(tmp_path.iterdir()) == []


def test_write_into_missing_directory(tmp_path):
    with pytest.raises(FileNotFoundError):
        write_json(COUNTER, tmp_path / "no" / "c.json")
    assert list(tmp_path.iterdir()) == []


def test_overwrite_keeps_the_mode(tmp_path):
    target = tmp_path / "c.json"
    target.write_text("old")
    target.chmod(0o640)
    write_json(COUNTER, target)
    assert target.stat().st_mode & 0o777 == 0o640
    assert json.loads(target.read_text())[0] == [1, 4.5]
