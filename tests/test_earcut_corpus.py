"""The earcut fixtures (mapbox/earcut, ISC licence, copied into tests/data/earcut).

Each file is a list of rings: the outer ring, then holes. The table below is the
verdict on each outer ring alone (closing point and consecutive repeats
dropped), written out once and checked by eye against the files, plus the
number of holes. Shapely's validity check on the same outer ring is asserted to
agree with every verdict, as an independent witness.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import shapely

from geometry.errors import HolesNotSupportedError, SelfIntersectionError, TooFewPointsError
from geometry.io import read_polygon, read_rings

EARCUT = Path(__file__).parent / "data" / "earcut"
OK = None
CROSS, FEW = SelfIntersectionError, TooFewPointsError

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
    holes, verdict = TABLE[name]
    assert len(read_rings(fixture(name))) == holes + 1
    if holes:
        plural = "s" if holes > 1 else ""
        with pytest.raises(HolesNotSupportedError, match=f"polygon has {holes} hole{plural};"):
            read_polygon(fixture(name))
    elif verdict is OK:
        read_polygon(fixture(name))
    else:
        with pytest.raises(verdict[0]):
            read_polygon(fixture(name))


@pytest.mark.parametrize("name", sorted(TABLE))
def test_shapely_agrees(name):
    outer = json.loads(fixture(name).read_text())[0]
    reason = shapely.is_valid_reason(shapely.Polygon(outer))
    assert (reason == "Valid Geometry") == (TABLE[name][1] is OK), reason


@pytest.mark.parametrize("name", sorted(NOT_POLYGONS))
def test_not_polygons(name):
    pytest.skip(f"{name}.json: {NOT_POLYGONS[name]}")
