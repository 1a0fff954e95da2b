"""Ear clipping (Meisters 1975): slice a triangle off at an ear, repeat — the fruit, traced.

A vertex v is an *ear* when it is strictly convex and the closed triangle
prev–v–next holds no other vertex; then prev–next is an inner diagonal and the
triangle can be sliced off. Every simple polygon with more than three vertices
has two ears (Meisters' two-ears theorem), also when some vertices are
straight: the leaves of any triangulation are ears. A straight vertex is
never an ear (its triangle has no area), so every slice has positive area and
every vertex ends up in a triangle.

Two versions:

* :func:`ear_clipping_naive` — Meisters' greedy search: test the vertices in
  order against every other vertex, clip the first ear, start again. O(n³).
* :func:`ear_clipping` — the ear status of each vertex is kept; a clip changes
  only its two neighbours, so only they are tested again. A test looks only at
  the reflex and straight vertices (see :mod:`geometry.ring`). The scan goes
  on from the clip, where the changed vertices are. O(n²), usually far less.

Traced steps: ``is_ear(v) → bool`` and ``clip_ear(a, b, c) → [a, b, c]``, the
slice with its three corners as vertex references (ear ``b`` between ``a`` and ``c``).

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
>>> ear_clipping(p).triangles
((0, 1, 4), (1, 2, 4), (2, 3, 4))
>>> ear_clipping_naive(p).triangles
((0, 1, 4), (1, 2, 4), (2, 3, 4))
"""

from __future__ import annotations

from typing import cast

import numpy as np

import tracing
from geometry.batch import PointTable
from geometry.bridges import bridge_holes
from geometry.holes import PolygonWithHoles
from geometry.polygon import Polygon, Vertex
from geometry.predicates import orient
from geometry.results import Corners, Triangulation, finished, indices
from geometry.ring import Ring

# --- the naive search (Meisters) ----------------------------------------------------------------


class Remaining:
    """The vertices not yet clipped, in order: a list, and the same as an array for NumPy."""

    def __init__(self, polygon: Polygon) -> None:
        self.table = PointTable(polygon.points)
        self.order = list(range(polygon.n))
        self.ids = np.arange(polygon.n)

    def corners(self, k: int) -> tuple[int, int, int]:
        """The triangle at the k-th remaining vertex: (before, it, after)."""
        order = self.order
        return order[k - 1], order[k], order[(k + 1) % len(order)]

    def remove(self, k: int) -> None:
        del self.order[k]
        self.ids = np.delete(self.ids, k)


@tracing.traced(name="is_ear", exclude_args=("remaining", "k"))
def is_ear_naive(remaining: Remaining, k: int, v: Vertex) -> bool:
    """The definition, checked against every remaining vertex: O(n)."""
    a, b, c = (remaining.table.points[i] for i in remaining.corners(k))
    if orient(a, b, c) <= 0:
        return False
    m = len(remaining.order)
    corners = {(k - 1) % m, k, (k + 1) % m}
    return not remaining.table.any_in_triangle(a, b, c, remaining.ids, skip=corners)


@tracing.traced(name="clip_ear", exclude_args=("remaining", "k"))
def clip_ear_naive(remaining: Remaining, k: int, a: Vertex, b: Vertex, c: Vertex) -> Corners:
    """Slice off the triangle abc at ear b."""
    remaining.remove(k)
    return (a, b, c)


@tracing.traced(name="ear-clipping-naive")
def ear_clipping_naive(polygon: Polygon) -> Triangulation:
    """Meisters: find the first ear from the start, clip it, start again."""
    remaining, vertex = Remaining(polygon), _vertices(polygon)
    triangles, tests = [], 0
    while len(remaining.order) > 3:
        for k in range(len(remaining.order)):
            tests += 1
            if is_ear_naive(remaining, k, vertex[remaining.order[k]]):
                a, b, c = remaining.corners(k)
                triangles.append(indices(clip_ear_naive(remaining, k, vertex[a], vertex[b], vertex[c])))
                break
        else:
            raise AssertionError("no ear: the polygon is not simple")  # two-ears theorem
    triangles.append(cast("tuple[int, int, int]", tuple(remaining.order)))  # the last three
    return finished(triangles, steps=len(triangles), ear_tests=tests)


# --- the incremental version --------------------------------------------------------------------


@tracing.traced(exclude_args=("ring",))
def is_ear(ring: Ring, v: Vertex) -> bool:
    """Strictly convex, and no reflex or straight vertex in the closed triangle."""
    ring.ear_tests += 1
    i = v.index
    if ring.turn[i] <= 0:
        return False
    return ring.obstacles.first_in(ring.prev[i], i, ring.next[i]) is None


@tracing.traced(exclude_args=("ring",))
def clip_ear(ring: Ring, a: Vertex, b: Vertex, c: Vertex) -> Corners:
    """Slice off the triangle abc at ear b; a and c must be tested again."""
    ring.remove(b.index)
    return (a, b, c)


@tracing.traced(name="ear-clipping")
def ear_clipping(polygon: Polygon | PolygonWithHoles) -> Triangulation:
    """Walk round the polygon clipping ears; only the neighbours of a clip are re-tested.

    A polygon with holes is first made one weakly simple ring by bridges
    (:func:`geometry.bridges.bridge_holes`); its slots then play the vertices.
    """
    if isinstance(polygon, PolygonWithHoles) and polygon.hole_count:  # a Polygon has none
        return _ear_clipping_bridged(polygon)
    ring, vertex = Ring(polygon), _vertices(polygon)
    return _clip_all(ring, vertex)


def _ear_clipping_bridged(polygon: PolygonWithHoles) -> Triangulation:
    bridged = bridge_holes(polygon)
    ring = Ring.linked(bridged.points, bridged.prev, bridged.next, bridged.turn)
    # a slot plays a vertex: its index is the slot, its point the vertex's, its label too
    # (primed for a bridge end's second copy)
    vertex = [Vertex(s, bridged.label(s), polygon.points[v]) for s, v in enumerate(bridged.vertex_of)]
    with tracing.alive(bridged):  # the fruit with its keyhole cuts, while it is sliced
        result = _clip_all(ring, vertex)
    slot = bridged.vertex_of
    return finished([(slot[a], slot[b], slot[c]) for a, b, c in result.triangles],
                    steps=result.steps, ear_tests=result.extra["ear_tests"],
                    bridges=len(bridged.bridges), bridge_searches=bridged.fallbacks)


def _clip_all(ring: Ring, vertex: list[Vertex]) -> Triangulation:
    triangles, v, passed = [], 0, 0
    while ring.size > 3:
        if ring.ear[v] is None:
            ring.ear[v] = is_ear(ring, vertex[v])
        if ring.ear[v]:
            a, c = ring.prev[v], ring.next[v]
            triangles.append(indices(clip_ear(ring, vertex[a], vertex[v], vertex[c])))
            v, passed = c, 0  # go on from the cut: c and a are the only vertices that changed
        else:
            v, passed = ring.next[v], passed + 1
            if passed > ring.size:
                raise AssertionError("no ear: the polygon is not simple")  # two-ears theorem
    triangles.append((ring.prev[v], v, ring.next[v]))
    return finished(triangles, steps=len(triangles), ear_tests=ring.ear_tests)


def _vertices(polygon: Polygon | PolygonWithHoles) -> list[Vertex]:
    return [polygon.vertex(i) for i in range(polygon.n)]
