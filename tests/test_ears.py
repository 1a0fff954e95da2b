"""Ear clipping, naive (Meisters, O(n³)) and incremental (O(n²)): valid, traced, ears only.

Shared with the other algorithm tests: the earcut corpus, the named samples, a
strategy of integer polygons with collinear runs, and an ear test by definition
that does not use the algorithms' own code (``is_inner_diagonal``).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import tracing
from geometry.check import is_inner_diagonal, verify_triangulation
from geometry.ears import ear_clipping, ear_clipping_naive
from geometry.errors import GeometryError
from geometry.io import read_polygon
from geometry.polygon import Polygon
from geometry.predicates import orient
from geometry.samples import make_sample
from geometry.triangulate import triangulate
from story.refs import ref, result_refs
from tests.strategies import generated_polygons

EARCUT = Path(__file__).parent / "data" / "earcut"
NAMED = ["counterexample", "counterexample-twin", "square", "triangle", "lecture", "two-ears",
         "star", "spiral", "comb"]


def corpus_polygons() -> list[pytest.param]:
    """Every earcut fixture whose outer ring alone is a valid simple polygon."""
    params = []
    for path in sorted(EARCUT.glob("*.json")):
        try:
            polygon = read_polygon(path, ignore_holes=True)
        except GeometryError:
            continue  # an invalid outer ring (or not a polygon): a bad-input case, not ours
        params.append(pytest.param(polygon, id=path.stem))
    return params


CORPUS = corpus_polygons()


def is_ear_by_definition(p: Polygon, i: int) -> bool:
    """Strictly convex, and prev–next an inner diagonal (exact, from geometry.check)."""
    a, c = p.prev(i), p.next(i)
    if orient(p.points[a], p.points[i], p.points[c]) <= 0:
        return False
    return p.n == 3 or bool(is_inner_diagonal(p, a, c))


@st.composite
def collinear_polygons(draw, max_n: int = 24) -> Polygon:
    """Integer polygons with runs of collinear vertices and many equal x and y.

    An integer polygon (orthogonal, comb, or a 2-opt one on a 1000 grid) is scaled
    by m and some edges get the m − 1 lattice points between their ends: exact
    straight vertices, never a fold.
    """
    name = draw(st.sampled_from(["random-orthogonal", "random-comb", "random-2opt"]))
    low = 12 if name == "random-comb" else 4
    n = draw(st.integers(low, max(low, max_n)))
    points = make_sample(name, n, draw(st.integers(0, 10**6)))
    if name == "random-2opt":
        points = [(round(x * 1000), round(y * 1000)) for x, y in points]
    m = draw(st.integers(2, 4))
    split = draw(st.lists(st.booleans(), min_size=len(points), max_size=len(points)))
    out = []
    for k, (x, y) in enumerate(points):
        nx, ny = points[(k + 1) % len(points)]
        out.append((m * x, m * y))
        if split[k]:
            out += [(m * x + j * (nx - x), m * y + j * (ny - y)) for j in range(1, m)]
    try:
        return Polygon.from_points(out)
    except GeometryError:
        assume(False)
        raise


def assert_valid(polygon: Polygon, result) -> None:
    assert result.valid, result.failure
    assert len(result.triangles) == polygon.n - 2
    verdict = verify_triangulation(polygon, result.triangles)
    assert verdict, verdict.why


def clipped_ears(log: tracing.Log) -> list[list[str]]:
    """The corners (labels) of every clip, in order, from the log."""
    return [result_refs(e) for e in log.find(kind="return", name="clip_ear")]


ALGORITHMS = {"ear-clipping-naive": ear_clipping_naive, "ear-clipping": ear_clipping}


# --- known answers -------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ALGORITHMS)
def test_convex_polygon_is_clipped_vertex_by_vertex(name):
    # A convex octagon: vertex 0 is an ear; after it goes, vertex 1 is, and so on, so the
    # slices fan out from the last vertex H: (H, A, B), (H, B, C), … and finally (F, G, H).
    p = Polygon.from_points([(2, 0), (4, 0), (6, 2), (6, 4), (4, 6), (2, 6), (0, 4), (0, 2)])
    with tracing.record() as log:
        result = ALGORITHMS[name](p)
    assert clipped_ears(log) == [["H", "A", "B"], ["H", "B", "C"], ["H", "C", "D"],
                                 ["H", "D", "E"], ["H", "E", "F"]]
    assert result.triangles == ((0, 1, 7), (1, 2, 7), (2, 3, 7), (3, 4, 7), (4, 5, 7), (5, 6, 7))


def test_naive_tests_from_the_start_after_every_clip():
    # Meisters: after each clip the search starts again at the first vertex left, and every
    # answer agrees with the definition.
    p = Polygon.from_points(make_sample("lecture"))
    with tracing.record() as log:
        ear_clipping_naive(p)
    left = list(range(p.n))
    expect_first = True
    for event in log.events:
        if event.kind == "call" and event.name == "is_ear":
            i = left.index(p.label_of(ref(event, "v")))
            assert (i == 0) == expect_first
            expect_first = False
        elif event.kind == "return" and event.name == "is_ear":
            assert event.result == is_ear_by_definition(p.sub_polygon(left), i)
        elif event.kind == "return" and event.name == "clip_ear":
            left.remove(p.label_of(result_refs(event)[1]))
            expect_first = True
    assert len(left) == 3


def test_incremental_retests_only_the_neighbours_of_a_clip():
    p = Polygon.from_points(make_sample("lecture"))
    with tracing.record() as log:
        result = ear_clipping(p)
    assert_valid(p, result)
    tests = [ref(e, "v") for e in log.find(kind="call", name="is_ear")]
    clips = clipped_ears(log)
    # Every vertex is tested once before its first clip-related change; after that only the
    # two neighbours of each clip can be tested again.
    assert len(tests) <= p.n + 2 * len(clips)
    assert result.extra["ear_tests"] == len(tests)


def square_with_straight_sides() -> Polygon:
    """A 4 × 4 square with three straight vertices on each side (16 vertices)."""
    side = [(k, 0) for k in range(4)]
    return Polygon.from_points(
        side + [(4, k) for k in range(4)] + [(4 - k, 4) for k in range(4)]
        + [(0, 4 - k) for k in range(4)]
    )


@pytest.mark.parametrize("name", ALGORITHMS)
@pytest.mark.parametrize(
    "polygon",
    [square_with_straight_sides(), Polygon.from_points(make_sample("random-orthogonal", 40, 7))],
    ids=["straight-sides", "orthogonal"],
)
def test_every_clip_is_an_ear_of_the_polygon_left(name, polygon):
    # Replayed from the log against the definition: a straight vertex is clipped only once
    # a neighbour's clip has made it strictly convex.
    p = polygon
    with tracing.record() as log:
        assert_valid(p, ALGORITHMS[name](p))
    left = list(range(p.n))
    for a, b, c in clipped_ears(log):
        i = left.index(p.label_of(b))
        current = p.sub_polygon(left)
        assert [current.labels[current.prev(i)], current.labels[current.next(i)]] == [a, c]
        assert is_ear_by_definition(current, i)
        left.pop(i)


def test_few_ear_tests_per_vertex_on_a_spiral():
    p = Polygon.from_points(make_sample("spiral", 2000))
    result = ear_clipping(p)
    assert_valid(p, result)
    assert result.extra["ear_tests"] <= 3 * p.n


def test_dispatch_and_trace_names():
    p = Polygon.from_points(make_sample("counterexample"))
    for name in ALGORITHMS:
        with tracing.record() as log:
            result = triangulate(p, name)
        assert_valid(p, result)
        assert log.find(kind="call", name=name)
        assert len(log.find(kind="call", name="clip_ear")) == p.n - 3


# --- every input --------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ALGORITHMS)
@pytest.mark.parametrize("sample", NAMED)
def test_named_samples(name, sample):
    p = Polygon.from_points(make_sample(sample))
    assert_valid(p, ALGORITHMS[name](p))


@pytest.mark.parametrize("name", ALGORITHMS)
@pytest.mark.parametrize("polygon", CORPUS)
def test_earcut_corpus(name, polygon):
    assert_valid(polygon, triangulate(polygon, name))


@settings(max_examples=2000)
@given(generated_polygons(max_n=30))
def test_generated_polygons(p):
    for algorithm in ALGORITHMS.values():
        assert_valid(p, algorithm(p))


@settings(max_examples=300)
@given(collinear_polygons())
def test_collinear_runs(p):
    for algorithm in ALGORITHMS.values():
        assert_valid(p, algorithm(p))
