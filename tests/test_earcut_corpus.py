"""The earcut fixtures (mapbox/earcut, ISC licence, copied into tests/data/earcut).

Each file is a list of rings: the outer ring, then holes. The table below is the
verdict on each outer ring alone (closing point and consecutive repeats
dropped), written out once and checked by eye against the files, plus the
number of holes. Shapely's validity check on the same outer ring is asserted to
agree with every verdict, as an independent witness. A second table is the
verdict on the whole file, holes and all; shapely witnesses each defect of how
the rings lie (the rings named meet at the point named) and each valid file.
The triangulations of the valid files are tested in ``tests/test_holes.py``.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
import shapely

from geometry.errors import HoleError, InputFormatError, SelfIntersectionError, TooFewPointsError
from geometry.io import read_any_polygon, read_polygon, read_rings
from geometry.triangulate import triangulate

EARCUT = Path(__file__).parent / "data" / "earcut"
OK = None
CROSS, FEW, HOLE = SelfIntersectionError, TooFewPointsError, HoleError

# name: (holes, verdict on the outer ring alone: OK or (error class, message fragment))
TABLE = {
    "bad-diagonals": (0, (CROSS, "vertex (368, 4192) appears twice (pinch)")),
    "bad-hole": (3, OK),
    "boxy": (4, OK),
    "building": (0, OK),
    "collinear-diagonal": (0, (CROSS, "vertex (3413, 1869) appears twice (pinch)")),
    "degenerate": (0, (CROSS, "vertex (200, 100) appears twice (pinch)")),
    "dude": (2, OK),
    "earcut": (6, OK),
    "eberly-3": (2, OK),
    "eberly-6": (15, OK),
    "empty-square": (1, OK),
    "filtered-bridge-jhl": (4, OK),
    "hilbert": (0, OK),
    "hole-touching-outer": (1, OK),
    "hourglass": (0, (CROSS, "vertex (7, 15) appears twice (pinch)")),
    "infinite-loop-jhl": (1, OK),
    "issue107": (1, (FEW, "polygon has 2 distinct points; at least 3 are needed")),
    "issue111": (3, (CROSS, "vertex F (800, 4692) touches edge C–D")),
    "issue119": (4, OK),
    "issue131": (2, OK),
    "issue142": (1, OK),
    "issue147": (3, OK),
    "issue149": (1, (CROSS, "vertex (1856, 5520) appears twice (pinch)")),
    "issue16": (1, OK),
    "issue17": (1, OK),
    "issue186": (0, (CROSS, "zero-width spike at vertex B (0, 200)")),
    "issue29": (1, OK),
    "issue34": (7, OK),
    "issue35": (29, OK),
    "issue45": (2, OK),
    "issue52": (5, OK),
    "issue83": (2, OK),
    "outside-ring": (2, OK),
    "rain": (7, OK),
    "self-tangent-1": (2, OK),
    "self-tangent-2": (2, OK),
    "self-tangent-3": (22, OK),
    "self-tangent-4": (272, OK),
    "self-touching": (2, (CROSS, "vertex (160.571, 11.1494) appears twice (pinch)")),
    "shared-points": (0, (CROSS, "vertex (4136, 1016) appears twice (pinch)")),
    "simplified-us-border": (1, (CROSS, "edges D–E and G–H cross at (654.92, 1428.06)")),
    "steiner": (4, OK),
    "touching-holes": (7, OK),
    "touching-holes2": (2, OK),
    "touching-holes3": (26, OK),
    "touching-holes4": (26, OK),
    "touching-holes5": (52, OK),
    "touching-holes6": (168, OK),
    "touching2": (1, OK),
    "touching3": (2, OK),
    "touching4": (4, OK),
    "water-huge": (192, (CROSS, "vertex (4224, -128) appears twice (pinch)")),
    "water-huge2": (442, (CROSS, "vertex (-128, 4224) appears twice (pinch)")),
    "water-huge3": (1443, OK),
    "water": (9, (CROSS, "vertex (4224, 4224) appears twice (pinch)")),
    "water2": (7, (CROSS, "zero-width spike at vertex B (-128, -128)")),
    "water3": (5, OK),
    "water3b": (2, OK),
    "water4": (5, OK),
}  # fmt: skip

# name: verdict on the whole file (outer ring and holes): OK or (error class, message fragment).
# A ring may not touch another (earcut accepts that; this project's rules do not), so only
# ten of the 51 files with holes are valid polygons with holes.
WHOLE = {
    "bad-diagonals": (CROSS, "vertex (368, 4192) appears twice (pinch)"),
    "bad-hole": (CROSS, "hole 1: zero-width spike at vertex i₁ (847, 2827)"),
    "boxy": (HOLE, "hole 2 touches the outer ring at (3432, 2779)"),
    "building": OK,
    "collinear-diagonal": (CROSS, "vertex (3413, 1869) appears twice (pinch)"),
    "degenerate": (CROSS, "vertex (200, 100) appears twice (pinch)"),
    "dude": OK,
    "earcut": OK,
    "eberly-3": (HOLE, "hole 2 touches the outer ring at (1912, 2632)"),
    "eberly-6": OK,
    "empty-square": (HOLE, "hole 1 is the outer ring again"),
    "filtered-bridge-jhl": OK,
    "hilbert": OK,
    "hole-touching-outer": (HOLE, "hole 1 touches the outer ring at (1770, 512)"),
    "hourglass": (CROSS, "vertex (7, 15) appears twice (pinch)"),
    "infinite-loop-jhl": (HOLE, "hole 1 touches the outer ring at (-1, 2)"),
    "issue107": (FEW, "polygon has 2 distinct points"),
    "issue111": (CROSS, "vertex F (800, 4692) touches edge C–D"),
    "issue119": (HOLE, "holes 1 and 4 touch at (7, 15)"),
    "issue131": (HOLE, "hole 1 touches the outer ring at (-2048, -381)"),
    "issue142": (HOLE, "hole 1 touches the outer ring at (-16.3697, 28.342)"),
    "issue147": (HOLE, "holes 1 and 2 touch at (-1235, -1387)"),
    "issue149": (CROSS, "vertex (1856, 5520) appears twice (pinch)"),
    "issue16": OK,
    "issue17": OK,
    "issue186": (CROSS, "zero-width spike at vertex B (0, 200)"),
    "issue29": OK,
    "issue34": OK,
    "issue35": OK,
    "issue45": (HOLE, "hole 1 touches the outer ring at (10, 40)"),
    "issue52": OK,
    "issue83": (FEW, "hole 2: polygon has 1 distinct point"),
    "outside-ring": (HOLE, "hole 1 touches the outer ring at (2181, 1228)"),
    "rain": (HOLE, "hole 6 touches the outer ring at (3755, 1974)"),
    "self-tangent-1": (HOLE, "hole 2 touches the outer ring at (3210, 3334)"),
    "self-tangent-2": (HOLE, "hole 1 touches the outer ring at (2966, 2512)"),
    "self-tangent-3": (HOLE, "hole 1 touches the outer ring at (841, 1568)"),
    "self-tangent-4": (HOLE, "hole 2 touches the outer ring at (245, 4160)"),
    "self-touching": (CROSS, "vertex (160.571, 11.1494) appears twice (pinch)"),
    "shared-points": (CROSS, "vertex (4136, 1016) appears twice (pinch)"),
    "simplified-us-border": (CROSS, "edges D–E and G–H cross at (654.92, 1428.06)"),
    "steiner": (FEW, "hole 1: polygon has 1 distinct point"),
    "touching-holes": (HOLE, "holes 5 and 7 touch at (3719, 2079)"),
    "touching-holes2": (HOLE, "holes 1 and 2 touch at (2, 12)"),
    "touching-holes3": (HOLE, "holes 1 and 2 touch at (2, 12)"),
    "touching-holes4": (HOLE, "holes 1 and 2 touch at (2, 12)"),
    "touching-holes5": (HOLE, "holes 1 and 2 touch at (2, 12)"),
    "touching-holes6": (HOLE, "hole 1 touches the outer ring at (134, 2738)"),
    "touching2": (HOLE, "hole 1 touches the outer ring at (44, 2104)"),
    "touching3": (HOLE, "hole 1 touches the outer ring at (1212, 911)"),
    "touching4": (HOLE, "holes 3 and 4 touch at (1, 4)"),
    "water-huge": (CROSS, "vertex (4224, -128) appears twice (pinch)"),
    "water-huge2": (CROSS, "vertex (-128, 4224) appears twice (pinch)"),
    "water-huge3": (HOLE, "hole 19 touches the outer ring at (1981, 2763)"),
    "water": (CROSS, "vertex (4224, 4224) appears twice (pinch)"),
    "water2": (CROSS, "zero-width spike at vertex B (-128, -128)"),
    "water3": (HOLE, "hole 1 touches the outer ring at (4224, 4060)"),
    "water3b": (HOLE, "hole 1 touches the outer ring at (3688, -128)"),
    "water4": (CROSS, "hole 5: vertex g1₅ (4224, 2415) touches edge b1₅–c1₅"),
}  # fmt: skip

NOT_POLYGONS = {"expected-by-earcut": "earcut's own triangle counts, not a polygon"}


def fixture(name: str) -> Path:
    return EARCUT / f"{name}.json"


def test_table_covers_every_fixture():
    names = {p.stem for p in EARCUT.glob("*.json")}
    assert names == set(TABLE) | set(NOT_POLYGONS)
    assert (EARCUT / "LICENSE").exists()


def test_corpus_readme_counts():
    valid = [name for name, (_, verdict) in TABLE.items() if verdict is OK]
    assert len(TABLE) == 59
    assert len(valid) == 44
    assert sum(1 for holes, _ in TABLE.values() if holes) == 51
    assert sorted(n for n in valid if TABLE[n][0] == 0) == ["building", "hilbert"]


@pytest.mark.parametrize("name", sorted(TABLE))
def test_outer_ring_verdict(name):
    _, verdict = TABLE[name]
    if verdict is OK:
        polygon = read_polygon(fixture(name), ignore_holes=True)
        assert polygon.n >= 3
        return
    error, fragment = verdict
    with pytest.raises(error) as info:
        read_polygon(fixture(name), ignore_holes=True)
    assert fragment in str(info.value)


@pytest.mark.parametrize("name", sorted(TABLE))
def test_whole_file_verdict(name):
    holes, _ = TABLE[name]
    assert len(read_rings(fixture(name))) == holes + 1
    verdict = WHOLE[name]
    if verdict is OK:
        shape = read_any_polygon(fixture(name))
        assert shape.hole_count == holes
        return
    error, fragment = verdict
    with pytest.raises(error) as info:
        read_any_polygon(fixture(name))
    assert fragment in str(info.value)
    assert "\n" not in str(info.value)


def test_whole_file_counts():
    valid = sorted(name for name, verdict in WHOLE.items() if verdict is OK)
    assert set(WHOLE) == set(TABLE)
    assert [name for name in valid if TABLE[name][0]] == [
        "dude", "earcut", "eberly-6", "filtered-bridge-jhl", "issue16", "issue17", "issue29",
        "issue34", "issue35", "issue52",
    ]


@pytest.mark.parametrize("name", sorted(n for n, v in WHOLE.items() if v is not OK and v[0] is HOLE))
def test_shapely_witnesses_each_ring_defect(name):
    """Shapely, independently: the rings the message names meet at the point it names, or the
    hole it names lies outside the outer ring or inside the other hole."""
    rings = [shapely.LinearRing(r) for r in json.loads(fixture(name).read_text())]
    message = WHOLE[name][1]
    numbers = [int(k) for k in re.findall(r"\b(\d+)\b(?![,)])", message.split(" at ")[0])]
    named = [rings[0], rings[numbers[0]]] if "outer" in message else [rings[k] for k in numbers]
    point = re.search(r"at \((.+), (.+)\)", message)
    assert named[0].intersects(named[1])
    if point is not None:
        where = shapely.Point(float(point[1]), float(point[2]))
        assert named[0].distance(where) < 1e-3 and named[1].distance(where) < 1e-3


@pytest.mark.parametrize("name", sorted(n for n, v in WHOLE.items() if v is OK and TABLE[n][0]))
def test_shapely_agrees_valid_rings_lie_apart(name):
    rings = json.loads(fixture(name).read_text())
    outer = shapely.Polygon(rings[0])
    lines = [shapely.LinearRing(r) for r in rings]
    for k, hole in enumerate(rings[1:], start=1):
        assert outer.contains(shapely.Polygon(hole))
        assert not any(lines[k].intersects(lines[j]) for j in range(len(lines)) if j != k)


@pytest.mark.parametrize("name", sorted(TABLE))
def test_shapely_agrees(name):
    outer = json.loads(fixture(name).read_text())[0]
    reason = shapely.is_valid_reason(shapely.Polygon(outer))
    assert (reason == "Valid Geometry") == (TABLE[name][1] is OK), reason


@pytest.mark.parametrize("name", sorted(NOT_POLYGONS))
def test_not_polygons_are_refused_in_one_line(name):
    with pytest.raises(InputFormatError) as info:
        read_any_polygon(fixture(name))
    assert "\n" not in str(info.value)


#: Earcut's own counts for the small valid fixtures; earcut drops a zero-area triangle where
#: a ring has collinear points, so its count is at most n + 2h − 2, ours exactly that.
SMALL_VALID = sorted(n for n, v in WHOLE.items() if v is OK
                     and sum(map(len, json.loads(fixture(n).read_text()))) <= 250)


@pytest.mark.parametrize("name", SMALL_VALID)
def test_our_count_is_n_plus_2h_minus_2_and_never_below_earcuts(name):
    shape = read_any_polygon(fixture(name))
    earcut = json.loads(fixture("expected-by-earcut").read_text())["triangles"][name]
    triangles = triangulate(shape, "ear-clipping").triangles
    assert len(triangles) == shape.n + 2 * shape.hole_count - 2 >= earcut
