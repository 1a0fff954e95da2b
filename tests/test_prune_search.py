"""Prune and search: good sub-polygons that halve, ears that are ears, a valid triangulation."""

from __future__ import annotations

from itertools import pairwise

import pytest
from hypothesis import given, settings

import tracing
from geometry.check import is_inner_diagonal
from geometry.polygon import Polygon
from geometry.prune_search import find_an_ear, prune_and_search
from geometry.samples import make_sample
from geometry.triangulate import triangulate
from tests.strategies import generated_polygons
from tests.test_ears import (
    CORPUS,
    NAMED,
    assert_valid,
    clipped_ears,
    collinear_polygons,
    is_ear_by_definition,
)

# gravity_at (geometry/gravity.py, not this algorithm) raises "no tilt avoids perpendicular
# edges" at a reflex vertex whose angle is within ~1e-12 of π: its bisector −(e1 + e2) of two
# nearly opposite unit vectors is rounding noise. eberly-6's outer ring has such a vertex.


def good_subpolygons(log: tracing.Log) -> list[dict]:
    """States of the good sub-polygons in the order they entered."""
    return [e.state for e in log.find(kind="enter") if e.target.startswith("G(")]


def check_search(p: Polygon, log: tracing.Log, ear_label: str) -> None:
    """The trace of one FindAnEar: nested, halving good sub-polygons ending at an ear."""
    gs = good_subpolygons(log)
    assert gs[0]["cut"] is None and gs[0]["labels"] == list(p.labels)
    for parent, child in pairwise(gs):
        k = len(parent["labels"])
        assert len(child["labels"]) < k
        assert len(child["labels"]) <= k // 2 + 1
        assert set(child["labels"]) <= set(parent["labels"])
        u, w = (p.label_of(label) for label in child["cut"])
        assert is_inner_diagonal(p, u, w)
    last = gs[-1]["labels"]
    assert last[len(last) // 2] == ear_label
    assert is_ear_by_definition(p, p.label_of(ear_label))


# --- known answers -------------------------------------------------------------------------------


def test_find_an_ear_on_a_notch():
    # Middle vertex C is convex but E lies in BCD: the sweep at C claims C–E; the good
    # sub-polygon C, D, E (cut E–C) has middle D, an ear.
    p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
    with tracing.record() as log:
        ear = find_an_ear(p)
    assert ear.label == "D"
    assert [g["labels"] for g in good_subpolygons(log)] == [list("ABCDE"), list("CDE")]
    assert good_subpolygons(log)[1]["cut"] == ["E", "C"]
    assert [e.name for e in log.find(kind="call") if e.name in ("sweep_at", "gravity_at")] == [
        "sweep_at"]
    assert [e.result for e in log.find(kind="return", name="is_ear")] == [False, True]
    check_search(p, log, ear.label)


def test_reflex_middle_uses_gravity():
    # The lecture polygon's middle vertex G is reflex.
    p = Polygon.from_points(make_sample("lecture"))
    assert p.turns[p.n // 2] < 0
    with tracing.record() as log:
        ear = find_an_ear(p)
    assert log.find(kind="call", name="gravity_at")[0].args["v"] == {"ref": p.labels[p.n // 2]}
    check_search(p, log, ear.label)


@pytest.mark.parametrize("sample", ["spiral", "comb", "star", "lecture", "two-ears"])
def test_good_subpolygons_strictly_shrink(sample):
    p = Polygon.from_points(make_sample(sample))
    with tracing.record() as log:
        ear = find_an_ear(p)
    check_search(p, log, ear.label)


def test_every_clip_is_an_ear_and_good_subpolygons_come_and_go():
    p = Polygon.from_points(make_sample("random-orthogonal", 40, 3))
    with tracing.record() as log:
        result = prune_and_search(p)
    assert_valid(p, result)
    left = list(range(p.n))
    for a, b, c in clipped_ears(log):
        i = left.index(p.label_of(b))
        current = p.sub_polygon(left)
        assert [current.labels[current.prev(i)], current.labels[current.next(i)]] == [a, c]
        assert is_ear_by_definition(current, i)
        left.pop(i)
    entered = [e.target for e in log.find(kind="enter") if e.target.startswith("G(")]
    exited = [e.target for e in log.find(kind="exit") if e.target.startswith("G(")]
    assert sorted(entered) == sorted(exited)
    assert log.state_at(len(log.events) - 1) == {}


# --- every input --------------------------------------------------------------------------------


@pytest.mark.parametrize("sample", NAMED)
def test_named_samples(sample):
    p = Polygon.from_points(make_sample(sample))
    assert_valid(p, prune_and_search(p))
    if p.n > 3:
        assert is_ear_by_definition(p, find_an_ear(p).index)


@pytest.mark.parametrize("polygon", CORPUS)
def test_earcut_corpus(polygon):
    assert_valid(polygon, triangulate(polygon, "prune-and-search"))


@settings(max_examples=2000)
@given(generated_polygons(max_n=30))
def test_generated_polygons(p):
    assert_valid(p, prune_and_search(p))


@settings(max_examples=500)
@given(generated_polygons(max_n=60))
def test_find_an_ear_finds_an_ear(p):
    with tracing.record() as log:
        ear = find_an_ear(p)
    check_search(p, log, ear.label)


@settings(max_examples=300)
@given(collinear_polygons())
def test_collinear_runs(p):
    assert_valid(p, prune_and_search(p))
    assert is_ear_by_definition(p, find_an_ear(p).index)


def test_gravity_at_nearly_straight_reflex_vertices():
    """eberly-6 has reflex vertices within ~1e-12 of straight: −(e1 + e2) cancelled there."""
    import math

    from geometry.check import is_inner_diagonal
    from geometry.gravity import gravity_at
    from geometry.io import polygon_from_rings, read_rings

    p = polygon_from_rings(read_rings("tests/data/earcut/eberly-6.json"), ignore_holes=True)
    nearly = []
    for i in p.reflex_vertices():
        (ux, uy), (vx, vy), (wx, wy) = p.points[i - 1], p.points[i], p.points[(i + 1) % p.n]
        cross = (vx - ux) * (wy - vy) - (vy - uy) * (wx - vx)
        if abs(cross) < 1e-9 * math.dist((ux, uy), (vx, vy)) * math.dist((vx, vy), (wx, wy)):
            nearly.append(i)
    assert nearly
    for i in nearly:
        assert is_inner_diagonal(p, *gravity_at(p, p.vertex(i)).pair)
