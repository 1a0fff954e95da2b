"""Polygons with holes: reading, orientation, labels, and the three algorithms that take them.

Every triangulation is checked by ``verify_triangulation``'s exact certificate
(``triangulate`` does that; the tests also call it directly), on every valid
earcut fixture with holes, on hand-made degenerate bridges and on random
cheese from hypothesis.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import shapely
from click.testing import CliRunner
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from geometry.bridges import bridge_holes, hole_order
from geometry.check import verify_triangulation
from geometry.errors import HoleError, HolesNotSupportedError, PolygonError
from geometry.hole_samples import swiss_cheese
from geometry.holes import PolygonWithHoles, hole_label
from geometry.io import read_any_polygon
from geometry.predicates import orient
from geometry.triangulate import ALGORITHMS, HOLE_ALGORITHMS, triangulate
from tests.strategies import generated_polygons
from tests.test_earcut_corpus import OK, TABLE, WHOLE, fixture
from trex.cli import main

DATA = Path(__file__).parent / "data"
SQUARE = [(0, 0), (10, 0), (10, 10), (0, 10)]
VALID_WITH_HOLES = sorted(n for n, v in WHOLE.items() if v is OK and TABLE[n][0])


def triangulated(shape: PolygonWithHoles, algorithm: str):
    result = triangulate(shape, algorithm)
    assert result.valid, (algorithm, result.failure)
    assert len(result.triangles) == shape.n + 2 * shape.hole_count - 2
    assert verify_triangulation(shape, result.triangles)
    return result


# --- reading, orientation, labels -------------------------------------------------------------


def test_orientation_is_normalised_and_labels_read_well():
    # outer clockwise, hole counter-clockwise in the input
    shape = PolygonWithHoles.from_rings([SQUARE[::-1], [(2, 2), (4, 2), (4, 4), (2, 4)]])
    assert shape.input_clockwise
    outer, hole = shape.ring(0), shape.ring(1)
    assert all(shape.turn(i) > 0 for i in outer)  # convex corners of the region
    assert all(shape.turn(i) < 0 for i in hole)  # a convex hole bulges into the region
    assert [shape.labels[i] for i in hole] == ["a₁", "b₁", "c₁", "d₁"]
    assert shape.points[hole[0]] == (2.0, 2.0)  # a: the hole's left-most (lowest) vertex
    assert orient(*(shape.points[i] for i in list(hole)[:3])) < 0  # stored clockwise
    assert shape.area == 96.0


def test_labels_past_26_and_many_holes():
    assert hole_label(3, 0) == "a₃" and hole_label(10, 27) == "b1₁₀"
    shape = PolygonWithHoles.from_rings(swiss_cheese(400, 12, seed=3))
    assert len(set(shape.labels)) == shape.n


def test_source_indexes_the_rings_concatenated():
    rings = [SQUARE, [(2, 2), (2, 4), (4, 4), (4, 2)], [(6, 6), (8, 6), (8, 8)]]
    shape = PolygonWithHoles.from_rings(rings)
    flat = [(float(x), float(y)) for ring in rings for x, y in ring]
    assert shape.input_points() == flat
    assert sorted(shape.source) == list(range(shape.n))


@pytest.mark.parametrize("name", ["two-holes.json", "hole.wkt"])
def test_files_with_holes(name):
    shape = read_any_polygon(DATA / "holes" / name)
    assert shape.hole_count == {"two-holes.json": 2, "hole.wkt": 1}[name]


def test_geojson_feature_with_interior_rings(tmp_path):
    doc = {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [
        [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]], [[2, 2], [2, 4], [4, 4], [2, 2]],
        [[6, 6], [8, 6], [8, 8], [6, 6]]]}}
    path = tmp_path / "p.geojson"
    path.write_text(json.dumps(doc))
    shape = read_any_polygon(path)
    assert (shape.n, shape.hole_count) == (10, 2)
    assert triangulated(shape, "ear-clipping").triangles


@pytest.mark.parametrize(("rings", "message"), [
    ([SQUARE, [(8, 2), (12, 4), (8, 6)]], "hole 1 crosses the outer ring at (10, 5)"),
    ([SQUARE, [(1, 1), (2, 1), (2, 2)], [(0, 5), (2, 4), (2, 6)]],
     "hole 2 touches the outer ring at (0, 5)"),
    ([SQUARE, [(1, 1), (5, 1), (5, 5)], [(7, 7), (8, 7), (8, 8)], [(5, 2), (6, 2), (6, 3)]],
     "holes 1 and 3 touch at (5, 2)"),
    ([SQUARE, [(1, 1), (5, 1), (5, 5)], [(7, 7), (8, 7), (8, 8)], [(3, 0.5), (6, 1.5), (3.5, 2.5)]],
     "holes 1 and 3 overlap: their edges cross at (5, 1.9)"),
    ([SQUARE, [(1, 1), (5, 1), (5, 5)], [(1, 1), (5, 1), (5, 5)]],
     "holes 1 and 2 are the same ring twice"),
    ([SQUARE, [(1, 1), (5, 1), (5, 5)], [(5, 5), (5, 1), (1, 1)]],
     "holes 1 and 2 are the same ring twice"),  # also the other way round
    ([SQUARE, [(1, 1), (5, 1), (5, 5)], [(1, 1), (5, 1), (5, 4)]], "holes 1 and 2 touch at (1, 1)"),
    ([SQUARE, list(reversed(SQUARE))], "hole 1 is the outer ring again"),
    ([SQUARE, [(1, 1), (6, 1), (6, 6), (1, 6)], [(2, 2), (3, 2), (3, 3)]], "hole 2 lies inside hole 1"),
    ([SQUARE, [(2, 2), (3, 2), (3, 3)], [(1, 1), (6, 1), (6, 6), (1, 6)]], "hole 1 lies inside hole 2"),
    ([SQUARE, [(11, 1), (12, 1), (12, 2)]], "hole 1 lies outside the polygon"),
    ([SQUARE, [(-5, -5), (15, -5), (15, 15), (-5, 15)]], "hole 1 lies outside the polygon"),
    ([SQUARE, SQUARE], "hole 1 is the outer ring again"),
    ([SQUARE, [(1, 1), (1, 1), (2, 2)]], "hole 1: polygon has 2 distinct points"),
    ([SQUARE, [(1, 1), (2, 2), (3, 3)]], "hole 1: all 3 points are collinear"),
    ([SQUARE, [(1, 1), (1 + 1e-9, 1), (1, 2)], [(5, 5), (10 - 1e-12, 5), (5, 6)]], None),
])
def test_ring_defects_are_one_line(rings, message):
    if message is None:  # a hole 1e-12 from the wall is still apart from it: valid
        shape = PolygonWithHoles.from_rings(rings)
        for algorithm in HOLE_ALGORITHMS:
            triangulated(shape, algorithm)
        return
    with pytest.raises(PolygonError) as info:
        PolygonWithHoles.from_rings(rings)
    assert message in str(info.value)
    assert "\n" not in str(info.value)


def test_validating_many_holes_is_exact_about_a_near_touch():
    # the hole's vertex is one float step inside the wall: apart; on the wall: touching
    inside = 10 - 2**-49
    PolygonWithHoles.from_rings([SQUARE, [(5, 5), (inside, 5), (5, 6)]])
    with pytest.raises(HoleError, match=r"hole 1 touches the outer ring at \(10, 5\)"):
        PolygonWithHoles.from_rings([SQUARE, [(5, 5), (10, 5), (5, 6)]])


# --- the earcut fixtures ----------------------------------------------------------------------


@pytest.mark.parametrize("algorithm", HOLE_ALGORITHMS)
@pytest.mark.parametrize("name", VALID_WITH_HOLES)
def test_every_valid_earcut_fixture_with_holes(name, algorithm):
    triangulated(read_any_polygon(fixture(name)), algorithm)


@pytest.mark.parametrize("name", VALID_WITH_HOLES)
def test_bridges_found_by_eberly_need_no_search(name):
    ring = bridge_holes(read_any_polygon(fixture(name)))
    assert len(ring.bridges) == TABLE[name][0]
    assert ring.fallbacks == 0
    assert len(ring.walk()) == ring.size == len(ring.points)


# --- degenerate bridges -----------------------------------------------------------------------


def cases():
    notch = [(0, 0), (10, 0), (10, 10), (8, 5), (10, 10.5), (0, 10.5)]  # reflex vertex on the ray
    return {
        # the ray from (5, 5) passes exactly through the reflex vertex (8, 5)
        "ray through a vertex": [notch, [(4, 4), (5, 5), (4, 6)]],
        # reflex vertices (7, 6) and (9, 7) lie on one line through P = (5, 5): the nearer wins
        "collinear candidates": [
            [(0, 0), (10, 0), (10, 9), (9, 7), (10, 9.5), (7, 6), (10, 10), (0, 10)],
            [(3, 4), (5, 5), (3, 6)]],
        # P is 1e-6 from the wall
        "hole 1e-6 from the wall": [SQUARE, [(5, 4), (10 - 1e-6, 5), (5, 6)]],
        # two holes share the right wall's top corner as M (its copies then tell them apart)
        "shared M": [SQUARE, [(8, 6), (9, 7), (8, 8)], [(8, 2), (9, 3), (8, 4)]],
        # holes in a row on one line: each ray hits the next hole's left-most vertex
        "holes in a row": [SQUARE, *[[(x - 0.5, 5), (x, 4.5), (x + 0.5, 5), (x, 5.5)] for x in (2, 4, 6, 8)]],
        # a hole whose right side is vertical: two right-most vertices
        "vertical right side": [SQUARE, [(3, 3), (6, 3), (6, 6), (3, 6)], [(7, 2), (8, 2), (8, 8)]],
        # the wall hit is vertical too, and collinear straight vertices on it
        "straight vertices on the wall": [
            [(0, 0), (10, 0), (10, 2), (10, 5), (10, 8), (10, 10), (0, 10)], [(2, 2), (6, 5), (2, 8)]],
        # P a few ulps left of an edge from (-1e9, -1e9) to (1e9, 1e9): the ray's float x
        # there is off by 1e-7, more than P's distance to the edge
        "an ulp from a long edge": [
            [(-999999810.161296, -1000000438.7730701), (1000000021.0346731, 1000000627.5265886),
             (-3e9, 1e9)],
            [(1.271242540482291, -0.2887449228429917), (11.271242540482291, 0.2112550771570083),
             (1.271242540482291, 0.7112550771570083)]],
        # huge and tiny coordinates; slanted walls too (the ray's x must not underflow)
        **{f"slanted at {scale:g}": [[(x * scale, y * scale) for x, y in ring] for ring in (
            [(0, 0), (8, 0), (12, 10), (0, 10)], [(4, 4), (9, 5), (4, 6)])]
           for scale in (1e-300, 1e-200, 1e200, 1e300)},
        "huge": [[(x * 1e150, y * 1e150) for x, y in SQUARE], [(2e150, 2e150), (4e150, 2e150), (3e150, 4e150)]],
        "tiny": [[(x * 1e-150, y * 1e-150) for x, y in SQUARE], [(2e-150, 2e-150), (4e-150, 2e-150), (3e-150, 4e-150)]],
    }  # fmt: skip


@pytest.mark.filterwarnings("ignore:.*encountered in constrained_delaunay:RuntimeWarning")  # GEOS, 1e150
@pytest.mark.parametrize("algorithm", HOLE_ALGORITHMS)
@pytest.mark.parametrize("case", sorted(cases()))
def test_degenerate_bridges(case, algorithm):
    shape = PolygonWithHoles.from_rings(cases()[case])
    triangulated(shape, algorithm)
    if algorithm == "ear-clipping":
        assert bridge_holes(shape).fallbacks == 0


@pytest.mark.parametrize("algorithm", HOLE_ALGORITHMS)
def test_walls_wider_than_the_float_range(algorithm):
    """Coordinates at ±1.7e308: an edge's width overflows to inf (its ray crossing cannot be
    estimated in floats; the exact test still finds it)."""
    ring, hole = [(0, 0), (8, 0), (12, 10), (0, 10)], [(4, 4), (9, 5), (4, 6)]
    shape = PolygonWithHoles.from_rings([[((x - 6) * 2.8e307, (y - 5) * 2.8e307) for x, y in r]
                                         for r in (ring, hole)])
    triangulated(shape, algorithm)
    assert bridge_holes(shape).fallbacks == 0
    # a spike from the floor nearly to the roof between the hole and the far wall: its
    # float estimate is far off (its height overflows), the wall's is right
    big = 1.7e308
    spiked = PolygonWithHoles.from_rings([
        [(-big, -big), (0.0, -big), (1e307, 1.6e308), (2e307, -big), (big, -big), (big, big),
         (-big, big)],
        [(-3e307, -1e307), (-1e307, 0.0), (-3e307, 1e307)]])
    triangulated(spiked, algorithm)
    assert bridge_holes(spiked).fallbacks == 0


def test_bridge_through_a_vertex_ends_there():
    shape = PolygonWithHoles.from_rings(cases()["ray through a vertex"])
    ((p, m),) = bridge_holes(shape).bridges
    assert (shape.points[p], shape.points[m]) == ((5.0, 5.0), (8.0, 5.0))


def test_bridge_takes_the_nearer_of_collinear_candidates():
    shape = PolygonWithHoles.from_rings(cases()["collinear candidates"])
    ((_, m),) = bridge_holes(shape).bridges
    assert shape.points[m] == (7.0, 6.0)


def test_holes_go_right_most_first():
    shape = PolygonWithHoles.from_rings(cases()["holes in a row"])
    assert hole_order(shape) == [4, 3, 2, 1]
    ring = bridge_holes(shape)
    # each hole's bridge ends at the left-most vertex of the hole to its right; the first
    # ray meets the wall inside an edge, whose upper end (x ties) nothing hides
    ends = [shape.points[m] for _, m in ring.bridges]
    assert ends == [(10.0, 10.0), (7.5, 5.0), (5.5, 5.0), (3.5, 5.0)]


# --- refusals ---------------------------------------------------------------------------------


@pytest.mark.parametrize("algorithm", sorted(set(ALGORITHMS) - set(HOLE_ALGORITHMS)))
def test_simple_polygon_algorithms_refuse_holes(algorithm):
    shape = read_any_polygon(DATA / "holes" / "two-holes.json")
    with pytest.raises(HolesNotSupportedError) as info:
        triangulate(shape, algorithm)
    assert str(info.value) == (
        f"{algorithm} needs a simple polygon and this one has 2 holes; "
        "ear-clipping, monotone and cdt triangulate polygons with holes"
    )


# --- the command line -------------------------------------------------------------------------


def invoke(*args):
    return CliRunner().invoke(main, list(args))


@pytest.mark.parametrize("algorithm", HOLE_ALGORITHMS)
def test_triangulate_json_indexes_the_rings_in_input_order(tmp_path, algorithm):
    rings = [SQUARE[::-1], [(2, 2), (4, 2), (4, 4), (2, 4)], [(6, 6), (6, 8), (8, 8)]]
    path = tmp_path / "p.json"
    path.write_text(json.dumps(rings))
    result = invoke("triangulate", "--algorithm", algorithm, "--json", str(path))
    assert result.exit_code == 0, result.output
    record = json.loads(result.stdout)
    assert record["vertices"] == [[float(x), float(y)] for ring in rings for x, y in ring]
    assert len(record["triangles"]) == 11 + 2 * 2 - 2 and record["valid"]
    # the triangles tile the region: their areas sum to it, and none lies in a hole
    points = record["vertices"]
    polys = [shapely.Polygon([points[k] for k in t]) for t in record["triangles"]]
    assert sum(p.area for p in polys) == pytest.approx(100 - 4 - 2)
    holes = [shapely.Polygon(r) for r in rings[1:]]
    assert all(p.intersection(h).area == 0 for p in polys for h in holes)


def test_triangulate_refuses_holes_in_one_line():
    result = invoke("triangulate", "--algorithm", "prune-and-search", str(DATA / "holes" / "hole.wkt"))
    assert result.exit_code == 2
    assert result.stderr.count("\n") == 1
    assert "prune-and-search needs a simple polygon and this one has 1 hole;" in result.stderr


def test_check_counts_the_holes():
    result = invoke("check", str(DATA / "holes" / "two-holes.json"))
    assert result.exit_code == 0
    assert "valid, 10 vertices, 2 holes (4 on the outer ring, 6 on holes)" in result.stdout


def test_check_names_a_ring_defect():
    result = invoke("check", str(DATA / "bad" / "hole-touches.wkt"))
    assert result.exit_code == 2
    assert result.stderr.endswith(": hole 3 touches the outer ring at (0, 5)\n")


# --- random cheese ----------------------------------------------------------------------------


@st.composite
def cheeses(draw):
    """A random outer ring (every generator of tests/strategies.py, and star-shaped cheese)
    with random small triangles and squares for holes, kept where shapely finds them inside
    and apart (the exact validation then has the last word)."""
    if draw(st.booleans()):
        outer = draw(generated_polygons(max_n=24)).input_points()
    else:
        outer = swiss_cheese(draw(st.integers(8, 60)), 0, seed=draw(st.integers(0, 10**6)))[0]
    region = shapely.Polygon(outer)
    (x0, y0, x1, y1), holes = region.bounds, []
    size = max(x1 - x0, y1 - y0)
    for _ in range(draw(st.integers(1, 8))):
        cx, cy = draw(st.floats(x0, x1)), draw(st.floats(y0, y1))
        r = draw(st.floats(0.005, 0.12)) * size
        square = shapely.affinity.rotate(shapely.Point(cx, cy).buffer(r, quad_segs=1),
                                         draw(st.floats(0, 6.3)), use_radians=True)
        candidate = shapely.Polygon(list(square.exterior.coords)[:-1][: draw(st.sampled_from([3, 4]))])
        if candidate.area > 0 and region.contains(candidate) and all(
                candidate.distance(h) > 0 for h in holes):
            holes.append(candidate)
    assume(holes)
    return [outer, *[list(h.exterior.coords)[:-1] for h in holes]]


@settings(max_examples=80, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(cheeses())
def test_random_holes_triangulate_by_every_hole_algorithm(rings):
    try:
        shape = PolygonWithHoles.from_rings(rings)
    except HoleError:
        assume(False)  # shapely's float distance can say "apart" of rings that touch
    for algorithm in HOLE_ALGORITHMS:
        triangulated(shape, algorithm)


@settings(max_examples=10, deadline=None)
@given(st.integers(20, 400), st.integers(1, 30), st.integers(0, 10**6))
def test_generated_cheese_triangulates(vertices, holes, seed):
    shape = PolygonWithHoles.from_rings(swiss_cheese(vertices, holes, seed))
    assert shape.hole_count == holes
    for algorithm in HOLE_ALGORITHMS:
        triangulated(shape, algorithm)


def test_simple_polygons_are_untouched_by_holes_support():
    shape = read_any_polygon("counterexample")
    assert shape.hole_count == 0 and type(shape).__name__ == "Polygon"
    assert triangulate(shape, "ear-clipping").triangles == ((0, 1, 4), (1, 2, 4), (2, 3, 4))


def test_the_keyhole_sample_is_in_general_position():
    """Issue 22 item 3: no three of the shown sample's vertices on one line, its holes'
    counted (decided exactly). Its a₁ stood on one line with E and c₁ and with d₂ and c₂,
    and its a₂ halfway from F to A."""
    from itertools import combinations

    from story.hunt import in_general_position

    shape = read_any_polygon("keyhole")
    on_a_line = [" ".join(shape.labels[k] for k in three)
                 for three in combinations(range(shape.n), 3)
                 if orient(*(shape.points[k] for k in three)) == 0]
    assert on_a_line == []
    assert in_general_position(shape.points)


# --- the log and the beats of a run with holes ------------------------------------------------


def test_monotone_sweep_meets_each_hole_at_a_split_and_a_merge_vertex():
    from geometry.monotone import Sweep, classify_vertex

    shape = read_any_polygon("keyhole")
    sweep = Sweep(shape)
    kinds = {shape.labels[i]: classify_vertex(sweep, shape.vertex(i)) for i in range(shape.n)}
    for hole in range(1, shape.hole_count + 1):
        ring = list(shape.ring(hole))
        top = max(ring, key=lambda i: (shape.points[i][1], -shape.points[i][0]))
        bottom = min(ring, key=lambda i: (shape.points[i][1], -shape.points[i][0]))
        assert kinds[shape.labels[top]] == "split" and kinds[shape.labels[bottom]] == "merge"


def test_ear_clipping_log_has_keyholes_and_every_slice():
    from metaphors import catalog
    from metaphors.fruit import Keyhole, LastSlice, Slice
    from story.runs import run_logged

    log = run_logged("ear-clipping", "keyhole")
    shape = read_any_polygon("keyhole")
    joins = [e for e in log.events if e.kind == "return" and e.name == "join_hole"]
    assert len(joins) == shape.hole_count
    ring = next(e.state for e in log.events if e.kind == "enter" and e.target == "keyhole")
    assert len(ring["labels"]) == len(set(ring["labels"])) == shape.n + 2 * shape.hole_count
    beats = catalog.beats(log)
    assert [b.hole for b in beats if isinstance(b, Keyhole)] == [2, 1]  # right-most first
    slices = [b for b in beats if isinstance(b, Slice)]
    assert len(slices) == shape.n + 2 * shape.hole_count - 2
    assert isinstance(slices[-1], LastSlice) and slices[-1].rest == ()
    assert log.meta["pseudocode"][0][1] == ["join_hole"]


def test_simple_polygon_log_meta_is_unchanged():
    from story.runs import run_logged

    assert "pseudocode" not in run_logged("ear-clipping", "lecture").meta


def test_trex_log_with_holes(tmp_path):
    out = tmp_path / "run.json"
    assert invoke("log", "ear-clipping", "keyhole", "-o", str(out)).exit_code == 0
    assert '"join_hole"' in out.read_text()
    result = invoke("log", "prune-and-search", "keyhole", "-o", str(out))
    assert result.exit_code == 2
    assert "prune-and-search needs a simple polygon and this one has 2 holes" in result.stderr


def test_huge_and_tiny_coordinates_in_one_polygon_for_geos():
    """1e-150 beside 1e200: scaled for GEOS though not exactly (the points stay apart), and
    the triangles verified on the polygon as given."""
    ring, hole = [(0, 0), (8, 0), (12, 10), (0, 10)], [(4, 4), (9, 5), (4, 6)]
    rings = [[(x * 1e200, y * 1e200) for x, y in r] for r in (ring, hole)]
    rings[0][0] = (1e-150, 0.0)
    triangulated(PolygonWithHoles.from_rings(rings), "cdt")


def test_geos_failing_is_one_line_naming_it(monkeypatch):
    import shapely

    from geometry import cdt
    from geometry.errors import PolygonError

    def fails(_):
        raise shapely.errors.GEOSException("IllegalStateException: Unable to find shell join")

    monkeypatch.setattr(cdt.shapely, "constrained_delaunay_triangles", fails)
    shape = PolygonWithHoles.from_rings(cases()["shared M"])
    with pytest.raises(PolygonError, match=r"^GEOS cannot triangulate this polygon \(coordinates "
                       r"from 2 to 10\): Unable to find shell join$"):
        cdt.constrained_delaunay(shape)


def test_geos_failing_in_the_cli_is_one_line_and_status_2(monkeypatch, tmp_path, capsys):
    import json
    import sys

    import shapely

    from geometry import cdt
    from trex.cli import main

    def fails(_):
        raise shapely.errors.GEOSException("IllegalStateException: Unable to find shell join")

    monkeypatch.setattr(cdt.shapely, "constrained_delaunay_triangles", fails)
    polygon = tmp_path / "p.json"
    polygon.write_text(json.dumps(cases()["shared M"]))
    for command in (["triangulate", str(polygon), "--algorithm", "cdt"],
                    ["log", "cdt", str(polygon), "-o", str(tmp_path / "log.json")]):
        monkeypatch.setattr(sys, "argv", ["trex", *command])
        with pytest.raises(SystemExit) as stopped:
            main()
        assert stopped.value.code == 2
        err = capsys.readouterr().err
        assert err == f"error: {polygon}: GEOS cannot triangulate this polygon (coordinates " \
                      "from 2 to 10): Unable to find shell join\n"
    assert not (tmp_path / "log.json").exists()
