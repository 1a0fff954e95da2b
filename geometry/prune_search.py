"""Ear finding by prune and search (ElGindy, Everett, Toussaint 1993; thesis 2.2.2), traced.

A *good sub-polygon* G of P is a part of P cut off by one inner diagonal, its
*cutting edge*: a run U_0 … U_{k-1} of consecutive vertices of P closed by
the cutting edge U_{k-1}U_0 (P itself is good, with no cutting edge).
FindAnEar on G:

1. test the middle vertex V = U_{⌊k/2⌋}; if it is an ear of G, it is an ear of
   P (the rest of P lies beyond the cutting edge, which V is not on);
2. otherwise find an inner diagonal V–W of G: at a strictly convex V whose
   triangle holds vertices, the correct sweep (:func:`sweep_at`: W farthest
   from the neighbours' line); at a reflex or straight V, gravity
   (:func:`gravity_at`);
3. V–W cuts G in two. The part without G's cutting edge — U_j … U_i or
   U_i … U_j, whichever does not wrap round — is good, with at most
   ⌊k/2⌋ + 1 vertices. Go on there.

A round costs O(k) and halves k, so one ear costs O(n): :func:`find_an_ear`.

The triangulation :func:`prune_and_search` clips the ears it finds. After an
ear of G is clipped, what is left of G is still a good sub-polygon of what is
left of P (same cutting edge), so the search goes on in G rather than from
the whole polygon again; once G is down to its cutting edge, the good
sub-polygon around it goes on. At most n searches of O(n) each: O(n²).

Traced: the good sub-polygons are drawable objects (key ``G(first…last)``,
state: the polygon and its cutting edge) that enter when cut off and exit
when done, shrinking (``change``) at every clip; steps ``is_ear``,
``sweep_at`` / ``gravity_at``, ``good_subpolygon``, ``find_an_ear`` and
``clip_ear``.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
>>> find_an_ear(p).label  # C is not an ear (E is in BCD); the sweep cuts off C–D–E
'D'
>>> prune_and_search(p).triangles
((0, 1, 4), (1, 2, 4), (2, 3, 4))
"""

from __future__ import annotations

from typing import Any

import numpy as np

import tracing
from geometry.batch import PointTable
from geometry.diagonals import Diagonal, gravity_at, sweep_at
from geometry.polygon import Polygon, Vertex
from geometry.predicates import orient
from geometry.results import Corners, TriangleIndices, Triangulation, finished, indices


class ShrinkingPolygon:
    """P while its ears are clipped: the vertex indices left, in ccw order, and all points."""

    def __init__(self, polygon: Polygon) -> None:
        self.polygon = polygon
        self.order = np.arange(polygon.n)
        self.table = PointTable(polygon.points)


class GoodSubpolygon:
    """Positions start … start+size−1 of the remaining polygon, closed by a cutting edge.

    Every vertex clipped later lies strictly inside the run of each good
    sub-polygon still open, so a clip only shortens them: their first and
    last vertices (and so their keys) never change.
    """

    def __init__(
        self, remaining: ShrinkingPolygon, start: int, size: int, parent: GoodSubpolygon | None
    ) -> None:
        self.remaining, self.start, self.size, self.parent = remaining, start, size, parent
        labels = remaining.polygon.labels
        order = remaining.order
        self.trace_key = f"G({labels[order[start]]}…{labels[order[start + size - 1]]})"

    @classmethod
    def whole(cls, remaining: ShrinkingPolygon) -> GoodSubpolygon:
        """P itself: good, with no cutting edge."""
        return cls(remaining, 0, len(remaining.order), None)

    @property
    def has_cut(self) -> bool:
        return self.parent is not None

    def indices(self) -> np.ndarray:
        return self.remaining.order[self.start : self.start + self.size]

    def middle(self) -> int:
        """Position of U_⌊k/2⌋ in the remaining polygon."""
        return self.start + self.size // 2

    def vertex_at(self, position: int) -> Vertex:
        return self.remaining.polygon.vertex(int(self.remaining.order[position]))

    def as_polygon(self) -> Polygon:
        """G on its own (labels of P kept), for the diagonal finders."""
        return self.remaining.polygon.sub_polygon(self.indices().tolist())

    def trace_state(self) -> dict[str, Any]:
        p = self.remaining.polygon
        ids = self.indices().tolist()
        cut = [p.labels[ids[-1]], p.labels[ids[0]]] if self.has_cut else None
        return {
            "kind": "polygon",
            "points": [list(p.points[i]) for i in ids],
            "labels": [p.labels[i] for i in ids],
            "cut": cut,
        }


@tracing.traced(name="is_ear")  # the log names every ear test is_ear (as in ears.py)
def is_middle_ear(g: GoodSubpolygon, v: Vertex) -> bool:
    """Whether the middle vertex v is an ear: strictly convex, its closed triangle empty of G."""
    m, order = g.middle(), g.remaining.order
    points = g.remaining.polygon.points
    a, b, c = points[order[m - 1]], points[order[m]], points[order[m + 1]]
    if orient(a, b, c) <= 0:
        return False
    k = m - g.start
    corners = (k - 1, k, k + 1)  # positions in G of v and its neighbours
    return not g.remaining.table.any_in_triangle(a, b, c, g.indices(), skip=corners)


@tracing.traced
def diagonal_at(g: GoodSubpolygon, v: Vertex) -> Diagonal:
    """An inner diagonal of G from its middle vertex v, which is not an ear."""
    sub, k = g.as_polygon(), g.size // 2
    if sub.turns[k] > 0:
        diagonal = sweep_at(sub, sub.vertex(k))
        if diagonal is None:
            raise AssertionError("a convex vertex that is not an ear has candidates")
        return diagonal
    return gravity_at(sub, sub.vertex(k))


@tracing.traced
def good_subpolygon(g: GoodSubpolygon, diagonal: Diagonal) -> GoodSubpolygon:
    """The part of G beyond the diagonal that does not hold G's cutting edge."""
    i, j = sorted(diagonal.pair)  # positions within G; the run i … j does not wrap round
    return GoodSubpolygon(g.remaining, g.start + i, j - i + 1, g)


@tracing.traced(name="clip_ear")  # as in ears.py
def clip_middle_ear(g: GoodSubpolygon, v: Vertex) -> Corners:
    """Slice off the ear v (the middle of G); every good sub-polygon around it shrinks."""
    m, remaining = g.middle(), g.remaining
    corners = (g.vertex_at(m - 1), v, g.vertex_at(m + 1))
    remaining.order = np.delete(remaining.order, m)
    around: GoodSubpolygon | None = g
    while around is not None:
        around.size -= 1
        tracing.change(around)
        around = around.parent
    return corners


@tracing.traced(name="find_an_ear")
def find_an_ear(polygon: Polygon) -> Vertex:
    """FindAnEar on the whole polygon: an ear in O(n)."""
    return _search(GoodSubpolygon.whole(ShrinkingPolygon(polygon)))


def _search(g: GoodSubpolygon) -> Vertex:
    with tracing.alive(g):
        v = g.vertex_at(g.middle())
        if is_middle_ear(g, v):
            return v
        diagonal = diagonal_at(g, v)
        with tracing.alive(diagonal):
            return _search(good_subpolygon(g, diagonal))


@tracing.traced(name="prune-and-search")
def prune_and_search(polygon: Polygon) -> Triangulation:
    """Clip the ears FindAnEar finds, searching on in the good sub-polygon of the last one."""
    remaining = ShrinkingPolygon(polygon)
    triangles: list[TriangleIndices] = []
    _clip_ears_in(GoodSubpolygon.whole(remaining), triangles)
    a, b, c = (int(k) for k in remaining.order)
    triangles.append((a, b, c))
    return finished(triangles, steps=len(triangles))


def _clip_ears_in(g: GoodSubpolygon, triangles: list[TriangleIndices]) -> None:
    """FindAnEar in G and clip, until G is down to its cutting edge (P: to a triangle)."""
    floor = 2 if g.has_cut else 3
    with tracing.alive(g):
        while g.size > floor:
            v = g.vertex_at(g.middle())
            if is_middle_ear(g, v):
                triangles.append(indices(clip_middle_ear(g, v)))
            else:
                diagonal = diagonal_at(g, v)
                with tracing.alive(diagonal):
                    _clip_ears_in(good_subpolygon(g, diagonal), triangles)
