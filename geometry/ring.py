"""The shrinking polygon of ear clipping, and the vertices that can spoil an ear.

:class:`Ring` is the polygon as a doubly linked ring of vertex indices with
the current turn at each vertex; clipping an ear unlinks one vertex and
changes the turns of its two neighbours only.

:class:`Obstacles` holds the vertices that can spoil an ear: the reflex and
the straight ones. If a closed ear triangle prev–v–next (v strictly convex)
holds any other vertex, it holds one of these: the vertex in it farthest from
the line prev–next has both of its edges going back towards that line, so its
interior angle is at least π. A clip only ever shrinks the angles at the two
neighbours, so vertices leave this set and never join it. They are kept
sorted by x and by y; a triangle looks only at those inside its bounding box
along the narrower of the two axes (float comparisons of coordinates are
exact, so nothing inside is missed), and decides them with exact predicates.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
>>> ring = Ring(p)
>>> [p.labels[k] for k in ring.obstacles.members()]
['E']
>>> ring.obstacles.first_in(0, 1, 2), ring.obstacles.first_in(2, 3, 4)
(4, None)
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right
from collections.abc import Sequence

import numpy as np

from geometry.batch import in_closed_triangle, in_triangle_many
from geometry.holes import PolygonWithHoles
from geometry.polygon import Polygon
from geometry.predicates import Point, orient

# Below this many candidates a plain loop beats setting up numpy.
_VECTOR_FROM = 48


class Ring:
    """A polygon being clipped: links, current turns, obstacles and cached ear status."""

    def __init__(self, polygon: Polygon | PolygonWithHoles) -> None:
        n = polygon.n
        self._link(polygon.points, [n - 1, *range(n - 1)], [*range(1, n), 0],
                   [int(t) for t in polygon.turns], n)

    @classmethod
    def linked(cls, points: list[Point], prev: list[int], nxt: list[int], turn: list[int]) -> Ring:
        """A ring given by its links: a polygon whose holes are bridged (weakly simple).

        Every slot must be in the ring; slots may share a point (a bridge's ends).
        """
        ring = cls.__new__(cls)
        ring._link(points, list(prev), list(nxt), list(turn), len(points))
        return ring

    def _link(self, points: Sequence[Point], prev: list[int], nxt: list[int], turn: list[int], size: int) -> None:
        n = len(points)
        self.points = points
        self.prev, self.next, self.turn = prev, nxt, turn
        self.size = size
        self.ear: list[bool | None] = [None] * n  # None: not known since the last change
        self.ear_tests = 0
        self.obstacles = Obstacles(self.points, [i for i in range(n) if self.turn[i] <= 0])

    def remove(self, v: int) -> None:
        """Unlink v; its neighbours get new turns and must be tested again."""
        p, q = self.prev[v], self.next[v]
        self.next[p], self.prev[q] = q, p
        self.size -= 1
        for u in (p, q):
            self.turn[u] = orient(self.points[self.prev[u]], self.points[u], self.points[self.next[u]])
            self.ear[u] = None
            if self.turn[u] > 0:
                self.obstacles.discard(u)

    def indices(self, start: int = 0) -> list[int]:
        """The vertices still in the ring, counter-clockwise from start."""
        out, v = [start], self.next[start]
        while v != start:
            out.append(v)
            v = self.next[v]
        return out


class Obstacles:
    """Reflex and straight vertices of a shrinking polygon, searchable by bounding box."""

    def __init__(self, points: Sequence[Point], members: list[int]) -> None:
        n = len(points)
        self.points = points
        self.alive = [False] * n
        self.alive_mask = np.zeros(n, dtype=bool)
        for i in members:
            self.alive[i] = True
        self.alive_mask[members] = True
        self.count = len(members)
        arr = np.asarray(points, dtype=float).reshape(-1, 2)
        self.coords = (arr[:, 0], arr[:, 1])
        self.coord_lists = (arr[:, 0].tolist(), arr[:, 1].tolist())
        self.axes = [_Axis(arr[:, axis], members) for axis in (0, 1)]

    def members(self) -> list[int]:
        return [i for i, a in enumerate(self.alive) if a]

    def discard(self, i: int) -> None:
        if self.alive[i]:
            self.alive[i] = False
            self.alive_mask[i] = False
            self.count -= 1

    def first_in(self, a: int, b: int, c: int) -> int | None:
        """An obstacle other than a, b, c in the closed ccw triangle abc, or None.

        An obstacle at a corner's very point (a bridge's end again, in a polygon
        whose holes are bridged) does not count: its edges run outside the
        triangle, or along its sides, or to a vertex inside it that counts.
        """
        if self.count == 0:
            return None
        pa, pb, pc = self.points[a], self.points[b], self.points[c]
        box = [(min(p[k] for p in (pa, pb, pc)), max(p[k] for p in (pa, pb, pc))) for k in (0, 1)]
        ranges = [axis.range(*box[k]) for k, axis in enumerate(self.axes)]
        k = 0 if ranges[0][1] - ranges[0][0] <= ranges[1][1] - ranges[1][0] else 1
        lo, hi = ranges[k]
        candidates = self._in_box(k, lo, hi, box[1 - k])
        if len(candidates) >= _VECTOR_FROM:  # a big triangle: decide them all at once
            idx = np.asarray(candidates)
            inside = in_triangle_many(pa, pb, pc, self.coords[0][idx], self.coords[1][idx])
            hits = idx[inside & (idx != a) & (idx != b) & (idx != c)]
            corners = (pa, pb, pc)
            return next((int(i) for i in hits if self.points[i] not in corners), None)
        for i in candidates:
            if i != a and i != b and i != c and in_closed_triangle(self.points[i], pa, pb, pc) \
                    and self.points[i] not in (pa, pb, pc):
                return i
        return None

    def _in_box(self, k: int, lo: int, hi: int, across: tuple[float, float]) -> list[int]:
        """Alive obstacles in slots lo..hi of axis k whose other coordinate is in `across`."""
        low, high = across
        if hi - lo < _VECTOR_FROM:
            alive, order, other = self.alive, self.axes[k].order, self.coord_lists[1 - k]
            return [i for i in order[lo:hi] if alive[i] and low <= other[i] <= high]
        idx = self.axes[k].order_array[lo:hi]
        vals = self.coords[1 - k][idx]
        keep = self.alive_mask[idx] & (vals >= low) & (vals <= high)
        kept: list[int] = idx[keep].tolist()
        return kept


class _Axis:
    """Obstacles sorted along one axis (static: dead ones are skipped, not removed)."""

    def __init__(self, values: np.ndarray, members: list[int]) -> None:
        members_arr = np.asarray(members, dtype=np.int64)
        order = members_arr[np.argsort(values[members_arr], kind="stable")]
        self.order_array = order
        self.order = order.tolist()
        self.keys = values[order].tolist()

    def range(self, low: float, high: float) -> tuple[int, int]:
        return bisect_left(self.keys, low), bisect_right(self.keys, high)

