"""Heuristics pick exactly what their rule says; the correct ones always claim inner diagonals."""

from fractions import Fraction

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import tracing
from geometry.check import is_inner_diagonal
from geometry.diagonals import HEURISTICS, find_diagonal
from geometry.errors import PolygonError
from geometry.polygon import Polygon
from geometry.predicates import in_triangle, orient, orient_det
from geometry.samples import make_sample
from story.registry import correct, heuristics
from tests.strategies import generated_polygons

CORRECT = correct()


def sq(p, q):
    return (Fraction(p[0]) - Fraction(q[0])) ** 2 + (Fraction(p[1]) - Fraction(q[1])) ** 2


def brute_force(p: Polygon, name: str) -> tuple[int, int]:
    """An independent statement of each rule, by minima over exact keys (no shared ranking code)."""
    b = min(range(p.n), key=lambda i: p.points[i])
    a, c = (b - 1) % p.n, (b + 1) % p.n
    pa, pb, pc = p.points[a], p.points[b], p.points[c]
    cands = [k for k in range(p.n) if k not in (a, b, c) and in_triangle(p.points[k], pa, pb, pc)]
    if not cands:
        return (a, c)  # the frame's rule, for every triangle heuristic
    if name == "scaling-walled":
        seen = [k for k in range(p.n) if k not in (a, b, c) and is_inner_diagonal(p, b, k)]
        return (b, _first(p, seen, b, lambda k: sq(pb, p.points[k])))
    if name == "scaling":
        return (b, _first(p, cands, b, lambda k: sq(pb, p.points[k])))
    if name == "translation":
        return (b, _first(p, cands, b, lambda k: p.points[k][0]))
    if name in ("translation-correct", "scaling-correct"):
        return (b, _first(p, cands, b, lambda k: -abs(orient_det(pa, pc, p.points[k]))))
    if name == "rotation":  # clockwise from BA: nothing may lie strictly clockwise-before it
        return (b, _first_hit(p, cands, b, -1))
    if name == "rotation-ccw":
        return (b, _first_hit(p, cands, b, +1))
    if name == "rotation-correct":
        return (b, _first_hit(p, cands, c, orient(pc, pb, pa)))
    raise KeyError(name)


def _first(p, cands, b, key):
    """Minimum of key; ties: nearest to B, then counter-clockwise order after B."""
    return min(cands, key=lambda k: (key(k), sq(p.points[b], p.points[k]), (k - b) % p.n))


def _first_hit(p, cands, centre, turn):
    """The candidate no other candidate precedes when turning in direction `turn` around centre."""
    o = p.points[centre]
    pts = p.points
    first = [x for x in cands if all(orient(o, pts[x], pts[y]) * turn >= 0 for y in cands)]
    b = min(range(p.n), key=lambda i: p.points[i])
    return min(first, key=lambda k: (sq(p.points[b], p.points[k]), (k - b) % p.n))


@settings(max_examples=400)
@given(generated_polygons())
def test_rules_match_brute_force(p):
    for name in (n for n in heuristics() if n != "gravity"):  # the rules of the frame ABC
        assert set(find_diagonal(p, name).pair) == set(brute_force(p, name)), name


@settings(max_examples=2000)
@given(generated_polygons())
def test_correct_heuristics_claim_inner_diagonals(p):
    for name in CORRECT:
        claim = find_diagonal(p, name)
        assert is_inner_diagonal(p, *claim.pair), (name, claim.name)


@pytest.mark.parametrize(
    ("sample", "wrong"),
    [("counterexample", ["scaling", "rotation", "translation"]),
     ("counterexample-twin", ["rotation-ccw"])],
)
def test_counterexample_pair_defeats_the_wrong_heuristics(sample, wrong):
    p = Polygon.from_points(make_sample(sample))
    for name in wrong:
        verdict = is_inner_diagonal(p, *find_diagonal(p, name).pair)
        assert verdict.code == "crosses", name
    for name in CORRECT:
        assert is_inner_diagonal(p, *find_diagonal(p, name).pair), name


def test_counterexample_claims_and_crossed_edge():
    p = Polygon.from_points(make_sample("counterexample"))
    assert find_diagonal(p, "scaling").name == "BD"
    verdict = is_inner_diagonal(p, *find_diagonal(p, "scaling").pair)
    assert [p.labels[k] for k in verdict.edge] == ["E", "A"]
    assert find_diagonal(p, "translation-correct").name == "BE"


def test_convex_polygon_gravity_falls_back_and_says_so():
    p = Polygon.from_points([(0, 0), (2, 0), (3, 2), (1, 3), (-1, 2)])
    with tracing.record() as log:
        claim = find_diagonal(p, "gravity")
    notes = log.find(kind="note")
    assert [n.name for n in notes] == ["no-reflex-vertex"]
    assert notes[0].args["diagonal"] == [claim.u.label, claim.v.label]
    assert is_inner_diagonal(p, *claim.pair)


def test_gravity_tilts_when_an_edge_is_perpendicular():
    # The drop from the notch lands on the horizontal bottom edge.
    p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
    with tracing.record() as log:
        claim = find_diagonal(p, "gravity")
    (ret,) = [e for e in log.events if e.kind == "return" and e.name == "gravity_direction"]
    assert ret.result["tilt"] == pytest.approx(2.0**-10)
    assert is_inner_diagonal(p, *claim.pair)


def test_triangle_has_no_diagonal():
    p = Polygon.from_points([(0, 0), (1, 0), (0, 1)])
    for name in HEURISTICS:
        with pytest.raises(ValueError, match="no diagonal"):
            find_diagonal(p, name)


def test_unknown_heuristic():
    p = Polygon.from_points(make_sample("counterexample"))
    with pytest.raises(KeyError, match="expected one of"):
        find_diagonal(p, "magic")


def test_trace_names_a_scene_can_map():
    p = Polygon.from_points(make_sample("counterexample"))
    expected = {
        "scaling": "nearest_to", "rotation": "first_hit_rotating",
        "translation": "first_hit_sweeping", "scaling-correct": "last_dry",
        "scaling-walled": "nearest_visible", "gravity": "band_snag",
    }
    for name, step in expected.items():
        with tracing.record() as log:
            find_diagonal(p, name)
        assert step in {e.name for e in log.events if e.kind == "call"}, name
        assert log.events[-1].kind == "exit"  # the polygon leaves last


def test_logs_are_deterministic():
    p = Polygon.from_points(make_sample("random-2opt", 20, 7))
    texts = set()
    for _ in range(2):
        for name in HEURISTICS:
            with tracing.record(heuristic=name) as log:
                find_diagonal(p, name)
            texts.add((name, log.to_json()))
    assert len(texts) == len(HEURISTICS)


@pytest.mark.parametrize("scale", [1e-200, 1e-9, 1.0, 1e9, 1e200])
def test_huge_and_tiny_coordinates(scale):
    pts = [(x * scale, y * scale) for x, y in make_sample("counterexample")]
    p = Polygon.from_points(pts)
    for name in CORRECT:
        assert is_inner_diagonal(p, *find_diagonal(p, name).pair), (name, scale)
    assert not is_inner_diagonal(p, *find_diagonal(p, "scaling").pair)


def test_the_convex_fallback_names_the_pieces_own_vertices():
    """Issue 22: a caption speaks of the picture's own vertices. A convex piece of divide and
    conquer keeps its polygon's labels: its left-most vertex is not called B."""
    whole = Polygon.from_points([(0, 0), (2, 0), (3, 2), (1, 3), (-1, 2), (-3, 1)])
    assert whole.labels[1] == "B" and whole.points[1] == (-3.0, 1.0)
    piece = whole.sub_polygon([0, 2, 3, 4, 5])  # B left out: A = (-1, 2) is left-most
    with tracing.record() as log:
        claim = find_diagonal(piece, "gravity")
    (note,) = log.find(kind="note")
    b = piece.labels[min(range(piece.n), key=lambda k: piece.points[k])]
    assert b != "B" and note.args["reason"].endswith(
        f"so claim {claim.u.label}{claim.v.label}, cutting off the left-most {b}"), \
        note.args["reason"]


# --- two of the thesis's teaching points, said in chapter 2, checked ----------------------------

_QUADRILATERALS = st.lists(st.tuples(st.integers(-40, 40), st.integers(-40, 40)),
                           min_size=4, max_size=4, unique=True)


@settings(max_examples=300)
@given(_QUADRILATERALS)
def test_no_quadrilateral_defeats_any_heuristic(raw):
    """Chapter 2 says the counterexample's five vertices are the fewest: with four, T holds
    one candidate at most, and B's diagonal to it is inner. So every rule, the wrong ones
    too, claims an inner diagonal of every quadrilateral (collinear ones included)."""
    try:
        p = Polygon.from_points(raw)
    except PolygonError:
        assume(False)
    assume(p.n == 4)
    for name in heuristics():
        claim = find_diagonal(p, name)
        assert is_inner_diagonal(p, *claim.pair), (name, claim.name)


@settings(max_examples=200)
@given(generated_polygons())
def test_correct_scaling_and_correct_translation_pick_the_same_vertex(p):
    """Chapter 2 says so: the water rising from AC goes over the candidates nearest AC first,
    and the line parallel to AC, from B, touches the farthest from AC first: the last dry
    candidate is the first touched."""
    assert find_diagonal(p, "scaling-correct").pair == find_diagonal(p, "translation-correct").pair
