"""The status of the monotone partition's sweep: edges crossing the sweep line, left to right.

The line moves down. The edges kept are those with the polygon's inside on
their right, which for a counter-clockwise polygon are exactly the edges that
run downwards: edge k goes from vertex k (higher) to vertex k+1 (lower). (A
polygon with holes keeps its holes clockwise, so the same holds for their
edges; edge k then ends at ``nxt[k]``, the next vertex round its ring.)
"Higher" is lexicographic — larger y, or equal y and smaller x — as if the
picture were turned by an infinitesimal angle, so no edge is horizontal and no
two vertices are level. That turn keeps every orientation, so the order needs
no coordinates at the sweep line: edge k lies left of a point p exactly when
``orient(v_k, v_k+1, p) > 0``. A sorted list searched by bisection with that
exact test is the balanced tree of the textbook (insertions and deletions
shift the list in C, which is cheap at these sizes). Each vertex needs one
search: :meth:`find` gives its place, and the edge ending there, the edge
starting there and the edge directly left of it are all next to that place.

>>> s = SweepStatus([(0, 0), (4, 0), (4, 4), (0, 4)])
>>> s.insert(s.find(3), 3, helper=3)  # edge (0, 4)–(0, 0), the left side
>>> at = s.find(2)  # vertex (4, 4): one edge lies left of it
>>> at, s.left(at), s.helper[3]
(1, 3, 3)
"""

from __future__ import annotations

from collections.abc import Sequence

from geometry import predicates
from geometry.predicates import ORIENT_BOUND, TINY, Point, orient  # the float filters' bounds


class SweepStatus:
    """Downward edges crossing the sweep line, left to right, each with its helper vertex."""

    def __init__(self, points: Sequence[Point], nxt: Sequence[int] | None = None) -> None:
        self.points = points
        self.n = len(points)
        # edge k ends at nxt[k]: k + 1 round one ring, or round each ring of a polygon with holes
        self.nxt = list(nxt) if nxt is not None else [*range(1, self.n), 0]
        self.xs = [p[0] for p in points]
        self.ys = [p[1] for p in points]
        self.edges: list[int] = []
        self.helper: dict[int, int] = {}

    def find(self, v: int, own: int = -1) -> int:
        """Where vertex v is: how many edges lie strictly left of it (its own edge ``own`` not)."""
        xs, ys, edges, nxt = self.xs, self.ys, self.edges, self.nxt
        px, py = xs[v], ys[v]
        lo, hi = 0, len(edges)
        while lo < hi:
            mid = (lo + hi) // 2
            k = edges[mid]
            if k == own:
                hi = mid
                continue
            after = nxt[k]
            # orient(v_k, v_k+1, p) > 0, with the float filter of geometry.predicates
            # inlined: this test is the inner loop of the whole sweep.
            left = (xs[k] - px) * (ys[after] - py)
            right = (ys[k] - py) * (xs[after] - px)
            det, bound = left - right, ORIENT_BOUND * (abs(left) + abs(right)) + TINY
            # (``not det < -bound``, not ``det >= -bound``: an overflow's nan or inf goes to
            # the exact test too)
            if det > bound or (not det < -bound and self._exactly_left(k, after, v)):
                lo = mid + 1
            else:
                hi = mid
        if predicates.counts_open:  # counted after, so the inner loop pays nothing
            predicates.count_sign_tests(self.tests_made(own, lo))
        return lo

    def tests_made(self, own: int, found: int) -> int:
        """The sign tests :meth:`find` made to return ``found``: its bisection replayed
        (each test went right exactly when its middle lay left of the place found)."""
        edges, lo, hi, steps = self.edges, 0, len(self.edges), 0
        while lo < hi:
            mid = (lo + hi) // 2
            if edges[mid] == own:  # its own edge: passed without a test
                hi = mid
                continue
            steps += 1
            lo, hi = (mid + 1, hi) if mid < found else (lo, mid)
        return steps

    def _exactly_left(self, k: int, after: int, v: int) -> bool:
        points = self.points
        with predicates.inside_a_test():  # one of find's steps, counted with them
            return orient(points[k], points[after], points[v]) > 0

    def insert(self, at: int, k: int, helper: int) -> None:
        """Edge k starts at the vertex the line has reached, found at ``at``."""
        self.edges.insert(at, k)
        self.helper[k] = helper

    def remove(self, at: int, k: int) -> None:
        """Edge k, found at ``at``, ends at the vertex the line has reached."""
        if self.edges[at] != k:
            raise AssertionError("sweep status out of order")  # a simple polygon never gets here
        del self.edges[at]
        del self.helper[k]

    def replace(self, at: int, k: int, new: int, helper: int) -> None:
        """Edge k ends where edge ``new`` starts: the new one takes its place in the order."""
        self.remove(at, k)
        self.insert(at, new, helper)

    def left(self, at: int) -> int:
        """The edge directly left of a vertex found at ``at``."""
        if at == 0:
            raise AssertionError("no edge left of a vertex inside the sweep")
        return self.edges[at - 1]
