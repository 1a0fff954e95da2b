"""is_inner_diagonal and verify_triangulation: exact answers and the reasons they give."""

import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from geometry.cdt import constrained_delaunay
from geometry.check import is_inner_diagonal, verify_triangulation
from geometry.polygon import Polygon
from geometry.predicates import orient

COUNTEREXAMPLE = [(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)]


@pytest.fixture
def counterexample():
    return Polygon.from_points(COUNTEREXAMPLE)


def test_counterexample_diagonals(counterexample):
    p = counterexample  # A(1.6,8) B(1,4.5) C(9,2) D(3,6.5) E(4.6,4.1)
    b, d, e = p.label_of("B"), p.label_of("D"), p.label_of("E")
    verdict = is_inner_diagonal(p, b, d)
    assert not verdict
    assert verdict.code == "crosses"
    assert [p.labels[k] for k in verdict.edge] == ["E", "A"]
    assert is_inner_diagonal(p, b, e)
    assert is_inner_diagonal(p, e, b)
    assert is_inner_diagonal(p, 0, 1).code == "adjacent"
    assert is_inner_diagonal(p, 2, 2).code == "same-vertex"


def test_diagonal_through_a_vertex_and_outside():
    # A square with a collinear midpoint on the bottom edge and a notch on top.
    p = Polygon.from_points([(0, 0), (2, 0), (4, 0), (4, 4), (2, 2), (0, 4)])
    lab = {label: p.label_of(label) for label in p.labels}
    names = {p.points[i]: i for i in range(p.n)}
    bottom_left, bottom_right = names[(0.0, 0.0)], names[(4.0, 0.0)]
    verdict = is_inner_diagonal(p, bottom_left, bottom_right)
    assert verdict.code == "through-vertex"
    assert p.points[verdict.vertex] == (2.0, 0.0)
    top_left, top_right = names[(0.0, 4.0)], names[(4.0, 4.0)]
    outside = is_inner_diagonal(p, top_left, top_right)
    assert outside.code == "outside", outside
    assert is_inner_diagonal(p, names[(2.0, 0.0)], names[(2.0, 2.0)])
    assert lab  # labels exist for every vertex


def test_diagonal_crossing_reports_nearest_crossing():
    # A comb: from the left base corner to the far tooth crosses several teeth.
    pts = [(0, 0), (10, 0), (10, 5), (8, 5), (8, 1), (6, 1), (6, 5), (4, 5), (4, 1), (2, 1),
           (2, 5), (0, 5)]
    p = Polygon.from_points(pts)
    i = p.points.index((0.0, 5.0))
    j = p.points.index((8.0, 1.0))
    verdict = is_inner_diagonal(p, i, j)
    assert verdict.code == "crosses"
    assert {p.points[k] for k in verdict.edge} == {(2.0, 1.0), (2.0, 5.0)}


def test_verify_counterexample(counterexample):
    tris = constrained_delaunay(counterexample)
    assert verify_triangulation(counterexample, tris)
    assert verify_triangulation(counterexample, tris[:-1]).code == "count"
    assert verify_triangulation(counterexample, [*tris[:-1], (0, 0, 1)]).code == "degenerate"
    assert verify_triangulation(counterexample, [*tris[:-1], (0, 1, 9)]).code == "bad-index"


def test_verify_collinear_vertices_kept():
    p = Polygon.from_points([(0, 0), (1, 0), (2, 0), (3, 0), (3, 1), (0, 1)])
    tris = constrained_delaunay(p)
    assert len(tris) == 4
    assert verify_triangulation(p, tris)
    # A fan from a corner over the collinear run uses zero-area triangles.
    corner = p.points.index((0.0, 1.0))
    run = [p.points.index((float(x), 0.0)) for x in range(4)]
    fan = [(corner, run[k], run[k + 1]) for k in range(3)] + [
        (corner, run[3], p.points.index((3.0, 1.0)))
    ]
    assert verify_triangulation(p, fan)
    bad = [(run[0], run[1], run[2]), *fan[1:]]
    assert verify_triangulation(p, bad).code == "degenerate"


@st.composite
def star_polygons(draw, min_n=4, max_n=24):
    """Star-shaped around the origin: distinct angles, sorted, any radii."""
    n = draw(st.integers(min_n, max_n))
    steps = draw(st.lists(st.integers(1, 1000), min_size=n, max_size=n))
    total = sum(steps)
    radii = draw(st.lists(st.integers(1, 50), min_size=n, max_size=n))
    angle, pts = 0.0, []
    for step, r in zip(steps, radii, strict=True):
        angle += 2 * math.pi * step / total
        pts.append((round(r * math.cos(angle), 3), round(r * math.sin(angle), 3)))
    try:
        return Polygon.from_points(pts)
    except Exception:
        assume(False)


SETTINGS = settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.filter_too_much]
)


@SETTINGS
@given(star_polygons())
def test_cdt_of_generated_polygons_verifies(p):
    assert verify_triangulation(p, constrained_delaunay(p))


@SETTINGS
@given(star_polygons(), st.data())
def test_dropping_a_triangle_fails_with_count(p, data):
    tris = constrained_delaunay(p)
    k = data.draw(st.integers(0, len(tris) - 1))
    verdict = verify_triangulation(p, tris[:k] + tris[k + 1 :])
    assert verdict.code == "count"


@SETTINGS
@given(star_polygons(), st.data())
def test_moving_a_corner_fails(p, data):
    tris = constrained_delaunay(p)
    k = data.draw(st.integers(0, len(tris) - 1))
    corner = data.draw(st.integers(0, 2))
    new = data.draw(st.integers(0, p.n - 1))
    assume(new not in tris[k])
    moved = list(tris)
    t = list(moved[k])
    t[corner] = new
    moved[k] = tuple(t)
    verdict = verify_triangulation(p, moved)
    assert not verdict
    assert verdict.code in {"degenerate", "overlap", "outside", "uncovered"}


def _quads(tris):
    """Pairs of triangles sharing an edge, as (k, m, shared edge, far corners)."""
    for k in range(len(tris)):
        for m in range(k + 1, len(tris)):
            shared = set(tris[k]) & set(tris[m])
            if len(shared) == 2:
                (x,) = set(tris[k]) - shared
                (y,) = set(tris[m]) - shared
                yield k, m, sorted(shared), (x, y)


@SETTINGS
@given(star_polygons())
def test_swapping_a_diagonal(p):
    """The flip of a diagonal is valid exactly when its quadrilateral is strictly convex."""
    tris = constrained_delaunay(p)
    for k, m, (u, v), (x, y) in _quads(tris):
        pts = p.points
        convex = orient(pts[x], pts[y], pts[u]) * orient(pts[x], pts[y], pts[v]) < 0 and (
            orient(pts[u], pts[v], pts[x]) * orient(pts[u], pts[v], pts[y]) < 0
        )
        flipped = [t for i, t in enumerate(tris) if i not in (k, m)] + [(x, y, u), (x, y, v)]
        verdict = verify_triangulation(p, flipped)
        assert bool(verdict) == convex, (verdict, (u, v), (x, y))
        if not convex:
            assert verdict.code in {"degenerate", "overlap", "outside", "uncovered"}
