"""Holes joined to the outer ring by bridges (Eberly, *Triangulation by Ear Clipping*, 2002).

The holes are taken in order of their right-most vertex P, right-most first.
A ray from P to the right meets the ring built so far first at a point I. If I
is a vertex, P sees it. Otherwise let M be the end of the edge hit with the
larger x: P sees M unless a reflex (or straight) vertex lies in the triangle
P, I, M, and then it sees the one of those whose direction from P is nearest
the ray's (the nearest on ties). The hole is spliced in along the bridge
P–M, walked both ways: ``… M, P, (the hole), P′, M′, …``. The result is one weakly
simple ring, with two more vertices per hole (the bridge's ends again, their labels
primed), traced as the polygon ``keyhole``: the fruit with its keyhole cuts.

Every decision is an exact sign: which side of the ray, of the edge hit and
of P–M a vertex lies on, and which of two directions turns first. Points
equal to M (M's copies, once M has a bridge) are told apart by the wedge of
the ring at each copy, which must hold P. Each bridge found is checked
exactly before it is used (no vertex on it, no edge crossing it, P in M's
wedge); should one fail, the nearest visible vertex is searched for instead,
so a bridge is never wrong (``BridgedRing.fallbacks`` counts those).

Slots name the places of the weakly simple ring: slot i < n is vertex i,
slot n + 2k and n + 2k + 1 the second copies of P and M of the k-th bridge.

>>> from geometry.holes import PolygonWithHoles
>>> p = PolygonWithHoles.from_rings([[(0, 0), (6, 0), (6, 6), (0, 6)], [(2, 2), (2, 4), (4, 4), (4, 2)]])
>>> ring = bridge_holes(p)
>>> [p.labels[ring.vertex_of[s]] for s in ring.walk()]
['A', 'B', 'C', 'D', 'c₁', 'd₁', 'a₁', 'b₁', 'c₁', 'D']
>>> ring.bridges  # P = c₁ (4, 4); the ray meets C–D at (6, 4); M = D
[(6, 3)]
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

import tracing
from geometry.holes import PolygonWithHoles
from geometry.polygon import Vertex
from geometry.predicates import Contact, Point, on_segment, orient, segment_contact


class BridgedRing:
    """The weakly simple ring of slots: links, the vertex in each slot, and each slot's turn."""

    def __init__(self, polygon: PolygonWithHoles) -> None:
        n, holes = polygon.n, polygon.hole_count
        outer = polygon.starts[1]
        size = n + 2 * holes
        self.polygon = polygon
        self.vertex_of = list(range(n)) + [0] * (2 * holes)
        self.points: list[Point] = list(polygon.points) + [(0.0, 0.0)] * (2 * holes)
        self.next = [*range(1, outer), 0] + [0] * (size - outer)
        self.prev = [outer - 1, *range(outer - 1)] + [0] * (size - outer)
        self.turn = [int(t) for t in polygon.turns] + [0] * (2 * holes)
        self.xy = np.zeros((size, 2))  # the points and links again, for NumPy
        self.xy[:n] = np.asarray(polygon.points, dtype=float)
        self.next_np = np.asarray(self.next)
        self.live = np.zeros(size, dtype=bool)
        self.live[:outer] = True
        self.size = outer
        self.copies = [0] * size  # slot's copy number: 0 the vertex itself, 1 its first copy …
        self.bridges: list[tuple[int, int]] = []  # (hole vertex P, vertex M), vertex indices
        self.fallbacks = 0

    def label(self, s: int) -> str:
        """The label of slot s: its vertex's, primed for each further copy (``D′``, ``D″`` …)."""
        return self.polygon.labels[self.vertex_of[s]] + _primes(self.copies[s])

    @property
    def trace_key(self) -> str:
        return "keyhole"

    def trace_state(self) -> dict[str, Any]:
        """The weakly simple ring as a polygon: its slots' points and labels, in ring order."""
        order = self.walk()
        return {"kind": "polygon", "points": [list(self.points[s]) for s in order],
                "labels": [self.label(s) for s in order]}

    def walk(self, start: int = 0) -> list[int]:
        """The slots in ring order from ``start``."""
        out, s = [start], self.next[start]
        while s != start:
            out.append(s)
            s = self.next[s]
        return out

    def splice(self, m: int, p: int) -> None:
        """Join the hole of vertex p (not yet in the ring) at slot m: ``m, p … p', m'``."""
        polygon, k = self.polygon, len(self.bridges)
        p2, m2 = polygon.n + 2 * k, polygon.n + 2 * k + 1
        hole = polygon.ring(polygon.ring_of(p))
        for v in hole:
            self.next[v], self.prev[v] = polygon.next(v), polygon.prev(v)
        last, after = polygon.prev(p), self.next[m]
        self.vertex_of[p2], self.vertex_of[m2] = p, self.vertex_of[m]
        self.copies[p2] = 1
        self.copies[m2] = 1 + sum(1 for s in range(polygon.n, p2) if self.vertex_of[s] == self.vertex_of[m])
        self.points[p2], self.points[m2] = self.points[p], self.points[m]
        self.xy[p2], self.xy[m2] = self.xy[p], self.xy[m]
        self.next[m], self.prev[p] = p, m
        self.next[last], self.prev[p2] = p2, last
        self.next[p2], self.prev[m2] = m2, p2
        self.next[m2], self.prev[after] = after, m2
        for v in (*hole, last, p2, m2, m):
            self.next_np[v] = self.next[v]
        self.live[list(hole)] = True
        self.live[[p2, m2]] = True
        self.size += len(hole) + 2
        for s in (m, p, p2, m2):
            self.turn[s] = orient(self.points[self.prev[s]], self.points[s], self.points[self.next[s]])
        self.bridges.append((p, self.vertex_of[m]))

    def sees_into(self, s: int, q: Point) -> bool:
        """Whether the ray from slot s towards q starts into the region (s's wedge holds it)."""
        pv, u, w = self.points[s], self.points[self.prev[s]], self.points[self.next[s]]
        if self.turn[s] > 0:
            return orient(pv, w, q) > 0 and orient(pv, u, q) < 0
        return orient(pv, w, q) > 0 or orient(pv, u, q) < 0


def _primes(k: int) -> str:
    """``′``, ``″``, ``‴``, then ``′⁴`` … for the k-th copy (none for 0)."""
    return ("", "′", "″", "‴")[k] if k < 4 else f"′{str(k).translate(_SUPERSCRIPTS)}"


_SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def _rightmost(polygon: PolygonWithHoles, hole: int) -> int:
    """The hole's right-most vertex, the highest on ties."""
    return max(polygon.ring(hole), key=lambda i: polygon.points[i])


def hole_order(polygon: PolygonWithHoles) -> list[int]:
    """Holes by their right-most vertex, right-most first (then by hole number)."""
    key = {h: polygon.points[_rightmost(polygon, h)] for h in range(1, polygon.hole_count + 1)}
    return sorted(key, key=lambda h: (-key[h][0], -key[h][1], h))


def bridge_holes(polygon: PolygonWithHoles) -> BridgedRing:
    """Join every hole of ``polygon`` (a :class:`~geometry.holes.PolygonWithHoles`) by a bridge."""
    ring = BridgedRing(polygon)
    for hole in hole_order(polygon):
        p = _rightmost(polygon, hole)
        m = _visible_slot(ring, polygon.points[p])
        join_hole(ring, polygon.vertex(p), polygon.vertex(ring.vertex_of[m]), m)
    return ring


@tracing.traced(exclude_args=("ring", "slot"))
def join_hole(ring: BridgedRing, p: Vertex, m: Vertex, slot: int) -> tuple[Vertex, Vertex]:
    """Cut the keyhole: the bridge P–M joins P's hole to the ring at M."""
    ring.splice(slot, p.index)
    return (p, m)


# --- finding M ------------------------------------------------------------------------------


def _visible_slot(ring: BridgedRing, p: Point) -> int:
    """A slot of the ring that P sees, with P in its wedge: Eberly's, checked, else searched."""
    slots = np.flatnonzero(ring.live)
    pts = ring.xy[slots]
    nxt = ring.next_np[slots]
    m = _eberly_slot(ring, p, slots, pts, nxt)
    if m is not None and _bridge_ok(ring, p, m, slots, pts, nxt):
        return m
    ring.fallbacks += 1
    return _nearest_visible(ring, p, slots, pts, nxt)


def _copy_seeing(ring: BridgedRing, point: Point, p: Point, slots: np.ndarray, pts: np.ndarray) -> int | None:
    """The slot at ``point`` whose wedge holds P (a point has several slots once bridged)."""
    same = slots[(pts[:, 0] == point[0]) & (pts[:, 1] == point[1])]
    for s in same.tolist():
        if ring.sees_into(s, p):
            return int(s)
    return None


#: the least slack: below it (subnormal coordinates) a float is off by whole units
_ULP0 = 4 * 5e-324


def _ray_hit(ring: BridgedRing, p: Point, slots: np.ndarray, pts: np.ndarray, nxt_pts: np.ndarray) -> tuple[Fraction, int | None, int | None]:
    """The first point the ray from P to the right meets: (x, vertex slot or None, edge slot or None)."""
    px, py = p
    ay, by = pts[:, 1], nxt_pts[:, 1]
    best: tuple[Fraction, int, int | None, int | None] | None = None
    # vertices on the ray
    on = np.flatnonzero((ay == py) & (pts[:, 0] > px))
    for k in on.tolist():
        key = (Fraction(pts[k, 0]), 0, int(slots[k]), None)
        best = key if best is None or key[:2] < best[:2] else best
    # edges crossing the ray's line strictly between their ends, right of P
    cross = np.flatnonzero((ay > py) != (by > py))
    cross = cross[(ay[cross] != py) & (by[cross] != py)]
    if len(cross):
        with np.errstate(all="ignore"):
            a, b = pts[cross], nxt_pts[cross]
            # the ratio first, in (0, 1): no product of two tiny (or huge) numbers
            xs = a[:, 0] + (py - a[:, 1]) / (b[:, 1] - a[:, 1]) * (b[:, 0] - a[:, 0])
            # the float x is off by a few ulps of the coordinates it is made of, not of x
            # itself (an edge from -1e9 to 1e9 crossing near 0): each exact x is within
            # ``slack`` of its float; the exact test below decides
            slack = 1e-12 * (np.abs(a).max(axis=1) + np.abs(b).max(axis=1) + abs(py)) + _ULP0
            # beyond float range (b - a overflows, and the estimate with it): the exact test
            # decides
            lost = ~(np.isfinite(b - a).all(axis=1) & np.isfinite(xs) & np.isfinite(slack))
        right = lost | (xs + slack >= px)
        cross, xs, slack, lost = cross[right], xs[right], slack[right], lost[right]
        if len(cross):
            bound = (xs + slack)[~lost].min() if (~lost).any() else np.inf
            near = cross[lost | (xs - slack <= bound)]
            for k in near.tolist():
                x = _exact_x(tuple(pts[k]), tuple(nxt_pts[k]), py)
                if x > px and (best is None or (x, 1) < best[:2]):
                    best = (x, 1, None, int(slots[k]))
    if best is None:
        raise AssertionError("the ray from a hole meets no edge: the hole is not inside")
    return best[0], best[2], best[3]


def _exact_x(a: tuple[float, ...], b: tuple[float, ...], y: float) -> Fraction:
    ax, ay, bx, by = (Fraction(float(v)) for v in (*a, *b))
    return ax + (Fraction(y) - ay) * (bx - ax) / (by - ay)


def _eberly_slot(ring: BridgedRing, p: Point, slots: np.ndarray, pts: np.ndarray, nxt: np.ndarray) -> int | None:
    nxt_pts = ring.xy[nxt]
    _, vertex, edge = _ray_hit(ring, p, slots, pts, nxt_pts)
    if vertex is not None:
        return _copy_seeing(ring, ring.points[vertex], p, slots, pts)
    assert edge is not None  # the ray meets a vertex or an edge (_ray_hit raises otherwise)
    u, w = ring.points[edge], ring.points[ring.next[edge]]
    m, other = (u, w) if u[0] > w[0] or (u[0] == w[0] and u > w) else (w, u)
    best = m
    for s in _blocking(ring, p, m, other, (u, w), slots, pts):
        q = ring.points[s]
        if best == m:
            best = q
            continue
        turn = orient(p, best, q) * (1 if m[1] > p[1] else -1)
        if turn < 0 or (turn == 0 and _closer(p, q, best)):
            best = q
    return _copy_seeing(ring, best, p, slots, pts)


def _closer(p: Point, q: Point, r: Point) -> bool:
    dq = (Fraction(q[0]) - Fraction(p[0])) ** 2 + (Fraction(q[1]) - Fraction(p[1])) ** 2
    dr = (Fraction(r[0]) - Fraction(p[0])) ** 2 + (Fraction(r[1]) - Fraction(p[1])) ** 2
    return dq < dr


def _blocking(
    ring: BridgedRing, p: Point, m: Point, other: Point, edge: tuple[Point, Point], slots: np.ndarray, pts: np.ndarray
) -> list[int]:
    """Reflex and straight slots in the closed triangle P, I, M (M's own point left out)."""
    lo_x, hi_x = p[0], max(m[0], other[0])
    lo_y, hi_y = (p[1], m[1]) if m[1] > p[1] else (m[1], p[1])
    box = (pts[:, 0] > lo_x) & (pts[:, 0] <= hi_x) & (pts[:, 1] >= lo_y) & (pts[:, 1] <= hi_y)
    out = []
    above = m[1] > p[1]
    side_edge = orient(edge[0], edge[1], p)
    side_pm = orient(p, m, other)
    for s in slots[box].tolist():
        q = ring.points[s]
        if ring.turn[s] > 0 or q == m or (q[1] > p[1]) != above or q[1] == p[1]:
            continue
        if orient(edge[0], edge[1], q) * side_edge >= 0 and orient(p, m, q) * side_pm >= 0:
            out.append(s)
    return out


# --- checking a bridge, and the search when a check fails ------------------------------------


def _bridge_ok(ring: BridgedRing, p: Point, m: int, slots: np.ndarray, pts: np.ndarray, nxt: np.ndarray) -> bool:
    """Exactly: no vertex on the open segment P–M, no edge crossing it, P in M's wedge."""
    q = ring.points[m]
    if not ring.sees_into(m, p):
        return False
    lo = np.minimum(p, q)
    hi = np.maximum(p, q)
    nxt_pts = ring.xy[nxt]
    box_v = np.all((pts >= lo) & (pts <= hi), axis=1)
    for k in np.flatnonzero(box_v).tolist():
        r = (float(pts[k, 0]), float(pts[k, 1]))
        if r != q and r != p and on_segment(r, p, q):
            return False
    e_lo, e_hi = np.minimum(pts, nxt_pts), np.maximum(pts, nxt_pts)
    box_e = np.all((e_hi >= lo) & (e_lo <= hi), axis=1)
    for k in np.flatnonzero(box_e).tolist():
        a, b = (float(pts[k, 0]), float(pts[k, 1])), (float(nxt_pts[k, 0]), float(nxt_pts[k, 1]))
        if segment_contact(p, q, a, b) is Contact.PROPER:
            return False
    return True


def _nearest_visible(ring: BridgedRing, p: Point, slots: np.ndarray, pts: np.ndarray, nxt: np.ndarray) -> int:
    right = np.flatnonzero(pts[:, 0] > p[0])
    dist = (pts[right, 0] - p[0]) ** 2 + (pts[right, 1] - p[1]) ** 2
    for k in right[np.argsort(dist, kind="stable")].tolist():
        s = int(slots[k])
        if _bridge_ok(ring, p, s, slots, pts, nxt):
            return s
    raise AssertionError("no vertex visible from a hole: the polygon is not valid")
