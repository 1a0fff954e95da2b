"""The plane sweep (geometry.sweep) against a brute-force test of every pair of edges.

"Agrees" means: both find no contact, or both find one; the sweep's pair may
differ from the brute force's, so it is checked on its own (non-adjacent edges
that really meet). Rings come from the fixture files, from small integer grids
(crossings, touchings, collinear overlaps, vertical edges, equal coordinates
abound), from the random generators with one vertex moved onto another edge or
onto its line, and from scaled copies of those (1e-200 … 1e200).
"""

from __future__ import annotations

from pathlib import Path
from unittest.mock import patch

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import geometry.sweep as sweep
import geometry.validate as validate
from geometry.errors import GeometryError, SelfIntersectionError
from geometry.io import read_rings
from geometry.predicates import Contact, Point, segment_contact
from geometry.samples import make_sample
from geometry.sweep import ChunkedList, first_contact
from tests.strategies import GENERATORS

DATA = Path(__file__).parent / "data"
FIXTURES = sorted((DATA / "bad").iterdir()) + sorted((DATA / "earcut").glob("*.json"))


def clean(raw) -> list[Point]:
    """Floats; the closing point and consecutive repeats dropped, as clean_points does."""
    kept: list[Point] = []
    for x, y in raw:
        p = (float(x), float(y))
        if not kept or kept[-1] != p:
            kept.append(p)
    while len(kept) > 1 and kept[-1] == kept[0]:
        kept.pop()
    return kept


def edge(ring: list[Point], i: int) -> tuple[Point, Point]:
    return ring[i], ring[(i + 1) % len(ring)]


def meet(ring: list[Point], i: int, j: int) -> bool:
    return segment_contact(*edge(ring, i), *edge(ring, j)) is not Contact.NONE


def non_adjacent(i: int, j: int, n: int) -> bool:
    return (i - j) % n not in (0, 1, n - 1)


def brute_force(ring: list[Point]) -> list[tuple[int, int]]:
    """Every pair i < j of non-adjacent edges that meet, by testing all pairs.

    Pairs whose bounding boxes are apart are skipped first (float comparisons of
    coordinates are exact, so this loses nothing) to keep 4,000-vertex fixtures fast.
    """
    n = len(ring)
    arr = np.asarray(ring, dtype=float)
    a, b = arr, np.roll(arr, -1, 0)
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    boxes_meet = np.all((lo[:, None] <= hi[None, :]) & (lo[None, :] <= hi[:, None]), axis=2)
    i, j = np.nonzero(np.triu(boxes_meet, 1))
    return [
        (int(p), int(q))
        for p, q in zip(i, j, strict=True)
        if non_adjacent(p, q, n) and meet(ring, int(p), int(q))
    ]


def assert_agrees(ring: list[Point]) -> tuple[int, int] | None:
    found = first_contact(ring)
    expected = brute_force(ring)
    assert (found is None) == (not expected), (found, expected[:3], ring)
    if found is not None:
        i, j = found
        assert 0 <= i < j < len(ring) and non_adjacent(i, j, len(ring)), found
        assert meet(ring, i, j), (found, ring)
    return found


# --- fixtures -------------------------------------------------------------------------------


def fixture_rings(path: Path) -> list[list[Point]]:
    try:
        rings = read_rings(path)
    except GeometryError:  # not a readable polygon file
        return []
    out = []
    for raw in rings:
        try:
            ring = clean(raw)
        except (TypeError, ValueError, OverflowError):  # not a ring of finite numbers
            continue
        if len(ring) >= 3 and all(np.isfinite(ring).ravel()):
            out.append(ring)
    return out


@pytest.mark.parametrize("path", FIXTURES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_fixtures_agree(path):
    for ring in fixture_rings(path):  # the outer ring, then each hole
        assert_agrees(ring)


def test_fixtures_cover_both_verdicts():
    outer = [rings[0] for rings in map(fixture_rings, FIXTURES) if rings]
    verdicts = [first_contact(ring) is None for ring in outer]
    assert len(outer) >= 60 and verdicts.count(True) >= 40 and verdicts.count(False) >= 8


# --- strategies -----------------------------------------------------------------------------


@st.composite
def grid_rings(draw) -> list[Point]:
    """4 to 12 points on a small integer grid, consecutive points distinct."""
    size = draw(st.integers(1, 6))
    coordinate = st.integers(0, size).map(float)
    points = draw(st.lists(st.tuples(coordinate, coordinate), min_size=4, max_size=12))
    ring = clean(points)
    if len(ring) < 3:
        ring = [(0.0, 0.0), (float(size), 0.0), (0.0, float(size))]
    return ring


def lattice(points, scale: int) -> list[tuple[int, int]]:
    """Points scaled to a grid of about 40·scale units and rounded (exact arithmetic after)."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    span = max(max(xs) - min(xs), max(ys) - min(ys)) or 1
    return [(round((x - min(xs)) * 40 / span) * scale, round((y - min(ys)) * 40 / span) * scale)
            for x, y in points]  # fmt: skip


@st.composite
def moved_vertex_rings(draw) -> list[Point]:
    """A generated simple polygon, on a lattice, with one vertex moved onto another edge.

    The new place is a lattice point of another edge (end points included: a
    pinch) or of its line beyond the edge; on a coarse lattice rounding alone
    may already have made the ring touch itself.
    """
    name = draw(st.sampled_from(GENERATORS))
    n = draw(st.integers(max(6, 12 if "comb" in name else 6), 40))
    points = lattice(make_sample(name, n, draw(st.integers(0, 10**6))), draw(st.integers(1, 3)))
    v = draw(st.integers(0, n - 1))
    e = draw(st.integers(0, n - 1))
    (ax, ay), (bx, by) = points[e], points[(e + 1) % n]
    dx, dy = bx - ax, by - ay
    steps = max(np.gcd(abs(dx), abs(dy)), 1)
    k = draw(st.integers(-2, steps + 2))
    points[v] = (ax + k * dx // steps, ay + k * dy // steps)
    ring = clean(points)
    return ring if len(ring) >= 3 else [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]


@st.composite
def float_rings(draw) -> list[Point]:
    """A generated simple polygon in floats, left as is or with a vertex put on another's place."""
    name = draw(st.sampled_from(GENERATORS))
    n = draw(st.integers(12 if "comb" in name else 6, 60))
    points = [(float(x), float(y)) for x, y in make_sample(name, n, draw(st.integers(0, 10**6)))]
    if draw(st.booleans()):
        v, w = draw(st.integers(0, n - 1)), draw(st.integers(0, n - 1))
        points[v] = points[w]
    return clean(points)


@st.composite
def scaled_rings(draw) -> list[Point]:
    """A grid or moved-vertex ring scaled by 10**k, k in [-200, 200], maybe shifted."""
    ring = draw(st.one_of(grid_rings(), moved_vertex_rings()))
    scale = 10.0 ** draw(st.integers(-200, 200))
    shift = draw(st.sampled_from([0.0, 1.0, -3.5]) | st.floats(-1e10, 1e10)) * scale
    scaled = clean([(x * scale + shift, y * scale - shift) for x, y in ring])
    return scaled if len(scaled) >= 3 else [(0.0, 0.0), (scale, 0.0), (0.0, scale)]


# --- agreement ------------------------------------------------------------------------------


@settings(max_examples=1000)
@given(grid_rings())
def test_grid_rings_agree(ring):
    assert_agrees(ring)


@settings(max_examples=500)
@given(moved_vertex_rings())
def test_moved_vertex_rings_agree(ring):
    assert_agrees(ring)


@settings(max_examples=300)
@given(st.one_of(grid_rings(), moved_vertex_rings()), st.integers(1, 3))
def test_tiny_chunks_agree(ring, load):
    """Chunks of 2 to 6 edges: neighbours and removals across chunk boundaries."""
    with patch.object(sweep, "_LOAD", load):
        assert_agrees(ring)


@settings(max_examples=200)
@given(float_rings())
def test_float_rings_agree(ring):
    assert_agrees(ring)


@settings(max_examples=300)
@given(scaled_rings())
def test_scaled_rings_agree(ring):
    assert_agrees(ring)


@pytest.mark.filterwarnings("ignore::hypothesis.errors.NonInteractiveExampleWarning")
def test_strategies_make_both_verdicts():
    """The generated rings are not all simple, nor all self-touching."""
    for strategy in (grid_rings(), moved_vertex_rings(), float_rings(), scaled_rings()):
        verdicts = [first_contact(strategy.example()) is None for _ in range(60)]
        assert 3 <= verdicts.count(True) <= 57, strategy


# --- special cases --------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("ring", "expected"),
    [
        ([(0, 0), (1, 0), (1, 1)], None),  # a triangle: no pair is non-adjacent
        ([(0, 0), (2, 0), (2, 2), (0, 2)], None),
        ([(0, 0), (2, 2), (2, 0), (0, 2)], (0, 2)),  # bow tie
        ([(0, 0), (0, 4), (1, 4), (1, 2), (0, 2), (-1, 1)], (0, 4)),  # vertex on a vertical edge
        ([(0, 0), (0, 4), (1, 4), (0, 2), (-1, 1)], (0, 3)),
        ([(0, 0), (3, 0), (1, 0), (1, 1)], (0, 2)),  # fold-back, both edges leaving (0, 0)…
        ([(1, 1), (0, 0), (3, 0), (1, 0)], (1, 3)),  # …and both edges arriving at (3, 0)
        ([(0, 0), (4, 0), (4, 1), (3, 0), (1, 0), (0, 1)], (0, 4)),  # overlap; (1, 0) first
        ([(0, 0), (4, 0), (4, 1), (3, 0), (1, 0), (1, -1), (0, -1)], (0, 4)),  # same, vertical
        ([(0, 0), (2, 0), (2, 2), (0, 2), (0, 1), (2, 1)], (1, 5)),  # vertex on a vertical edge
        ([(0, 0), (2, 0), (2, 2), (0, 2), (0, 1), (1, 1), (1, 3), (-1, 3)], (2, 5)),  # crossing
    ],
)
def test_small_cases(ring, expected):
    ring = [(float(x), float(y)) for x, y in ring]
    assert assert_agrees(ring) == expected


def test_zero_length_edge_is_refused():
    with pytest.raises(ValueError, match="length zero"):
        first_contact([(0.0, 0.0), (1.0, 0.0), (1.0, 0.0), (0.0, 1.0)])


@pytest.mark.parametrize("name", ["star", "spiral", "comb"])
def test_large_deterministic_samples(name):
    ring = make_sample(name, 5000)
    assert first_contact(ring) is None
    moved = list(ring)
    moved[2500] = moved[10]  # a pinch far from the first vertices
    found = first_contact(moved)
    assert found is not None and meet(moved, *found)


def test_nearly_parallel_long_edges():
    """Two long edges 1 ulp apart at one end: exact signs, not float noise."""
    tiny = 2.0**-52
    ring = [(0.0, 0.0), (1e6, 1.0), (1e6, 1.0 + 1e6 * tiny), (0.0, tiny), (-1.0, 5.0)]
    assert assert_agrees(ring) is None
    ring[3] = (0.0, -tiny)  # now edge 2 crosses edge 0
    assert assert_agrees(ring) == (0, 2)


# --- the status list ------------------------------------------------------------------------


@settings(max_examples=200)
@given(st.lists(st.tuples(st.booleans(), st.integers(0, 50)), max_size=200), st.integers(1, 4))
def test_chunked_list_matches_a_sorted_list(operations, load):
    items, model = ChunkedList(load=load), []
    for is_insert, value in operations:
        pos = items.bisect(lambda x, v=value: x < v)
        assert items.before(pos) == max((x for x in model if x < value), default=None)
        if is_insert:
            items.insert(pos, [value])
            model.append(value)
            model.sort()
        elif items.at(pos) == value:
            assert items.pop(pos) == value
            model.remove(value)
        else:
            assert value not in model
        assert list(items) == model and len(items) == len(model)
        assert all(0 < len(chunk) <= 2 * load for chunk in items.chunks)


# --- check_simple: both paths ---------------------------------------------------------------


def check_message(ring: list[Point], *, sweep: bool) -> str | None:
    """check_simple's message (None if simple), forced onto the sweep or the pair path."""
    with patch.object(validate, "_PAIRS_PER_EDGE", -1 if sweep else 10**9):
        try:
            validate.check_simple(ring, str)
        except SelfIntersectionError as exc:
            return str(exc)
    return None


@settings(max_examples=300)
@given(st.one_of(grid_rings(), moved_vertex_rings()))
def test_check_simple_paths_agree(ring):
    """Same verdict on both paths; same message when only one pair of edges meets."""
    pairs = check_message(ring, sweep=False)
    swept = check_message(ring, sweep=True)
    assert (pairs is None) == (swept is None)
    if len(brute_force(ring)) == 1:
        assert pairs == swept


def test_check_simple_sweeps_a_large_star():
    ring = make_sample("star", 20_000)
    assert validate._candidate_pairs(np.asarray(ring, dtype=float), 16 * len(ring)) is None
    validate.check_simple(ring, str)
    moved = list(ring)
    moved[7] = ((ring[1000][0] + ring[1001][0]) / 2, (ring[1000][1] + ring[1001][1]) / 2)
    with pytest.raises(SelfIntersectionError, match=r"cross at|touches edge|overlap"):
        validate.check_simple(moved, str)


@pytest.mark.parametrize(("name", "n"), [("random-star", 300), ("random-2opt", 200), ("comb", 400)])
def test_candidate_pairs_in_chunks_match_one_query(name, n):
    arr = np.asarray(make_sample(name, n, 1), dtype=float)
    chunked = validate._candidate_pairs(arr, budget=n * n)
    edges = validate.shapely.linestrings(np.stack([arr, np.roll(arr, -1, 0)], axis=1))
    i, j = validate.shapely.STRtree(edges).query(edges)
    keep = (i < j) & (j != i + 1) & ~((i == 0) & (j == n - 1))
    assert set(map(tuple, chunked.tolist())) == set(
        zip(i[keep].tolist(), j[keep].tolist(), strict=True)
    )
