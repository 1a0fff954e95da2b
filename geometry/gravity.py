"""Gravity (Forišek–Steinová): a ball on a rubber band finds an inner diagonal, traced.

Pick a reflex vertex V: the first one counter-clockwise from the left-most
vertex B. Gravity points along the inward bisector at V, so both edges at V
go up. If some edge is exactly perpendicular to gravity, gravity is tilted by
the smallest angle ±2^-k rad (k = 10, 11, …; + before −) that leaves no edge
perpendicular and both edges at V still going up. The ball drops from V along
gravity, hits the first edge (or lands on a vertex), slides down the edge to
its lower end X; the band from V to the ball sweeps the triangle V–hit–X and
snags the first vertex Y it meets (smallest angle from the drop line, nearest
to V on ties). The claim is VY, or VX when the band stays straight.

A polygon without reflex vertices is convex. If it has a straight vertex (its
two edges collinear) the ball drops from the first one, gravity along the
inward normal; a strictly convex polygon gets the claim AC around the
left-most vertex B (there every diagonal is inner). A ``no-reflex-vertex``
note says which.

The gravity vector is a float, but once chosen it is used exactly: every
side, order and height comparison below is decided exactly, by the
predicates of :mod:`geometry.predicates` (float filters, then rational
arithmetic), so the claim is always an inner diagonal.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
>>> gravity(p).name
'EC'
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import cmp_to_key
from typing import Any, cast

import numpy as np

import tracing
from geometry.batch import dot_sign_many
from geometry.frame import Diagonal, claim, leftmost_vertex, triangle_at
from geometry.polygon import Polygon, Vertex
from geometry.predicates import (
    Point,
    compare_angle,
    compare_distance,
    cross_sign,
    dot_sign,
    in_triangle,
    ray_meets_line,
    ray_parameter,
)

Exact = tuple[Fraction, Fraction]


@dataclass(frozen=True)
class Gravity:
    """Which way is down, and how the picture turns so that it points down on screen."""

    down: tuple[float, float]
    tilt: float  # radians added to the bisector's direction (0 when none was needed)
    turn_picture: float  # degrees to rotate the polygon so that `down` points down


@dataclass(frozen=True)
class Hit:
    """Where the falling ball first meets the boundary: inside an edge, or on a vertex."""

    point: Exact
    edge: tuple[int, int] | None
    vertex: Vertex | None

    @property
    def at(self) -> tuple[float, float]:
        return (float(self.point[0]), float(self.point[1]))

    @property
    def trace_key(self) -> str:
        return "hit"

    def trace_state(self) -> dict[str, Any]:
        state = {"kind": "point", "at": list(self.at)}
        if self.vertex is not None:  # it landed on a vertex: nothing to slide, no band to bend
            state["vertex"] = self.vertex.label
        return state


@tracing.traced
def reflex_vertex(polygon: Polygon) -> Vertex | None:
    """The first reflex vertex counter-clockwise from the left-most vertex B, or None."""
    return _first_turn(polygon, -1)


@tracing.traced
def straight_vertex(polygon: Polygon) -> Vertex | None:
    """In a polygon with no reflex vertex: the first straight (collinear) vertex from B, or None."""
    return _first_turn(polygon, 0)


def _first_turn(polygon: Polygon, turn: int) -> Vertex | None:
    b = polygon.leftmost()
    for k in range(polygon.n):
        i = (b + k) % polygon.n
        if polygon.turns[i] == turn:
            return polygon.vertex(i)
    return None


@tracing.traced
def gravity_direction(polygon: Polygon, v: Vertex) -> Gravity:
    """Gravity along the inward bisector at V (the inward normal at a straight vertex)."""
    u, w = polygon.points[polygon.prev(v.index)], polygon.points[polygon.next(v.index)]
    if polygon.turns[v.index] < 0:
        e1, e2 = _unit(v.point, u), _unit(v.point, w)
        # The inward bisector −(e1 + e2), written as e2 − e1 turned left (they are parallel for
        # unit vectors): well-conditioned even when the angle is within 1e-12 of straight,
        # where e1 + e2 cancels to rounding noise.
        bisector = (-(e2[1] - e1[1]), e2[0] - e1[0])
        down = _tilted(polygon, v, bisector)
    else:  # straight angle: both edges lie across gravity, there is nothing to tilt
        bisector = down = _unit((0.0, 0.0), (u[1] - w[1], w[0] - u[0]))
    tilt = _wrap(math.atan2(down[1], down[0]) - math.atan2(bisector[1], bisector[0]))
    turn = -90.0 - math.degrees(math.atan2(down[1], down[0]))
    return Gravity(down=down, tilt=tilt, turn_picture=(turn + 180.0) % 360.0 - 180.0)


def _unit(p: Point, q: Point) -> tuple[float, float]:
    dx, dy = q[0] - p[0], q[1] - p[1]
    r = math.hypot(dx, dy)
    return (dx / r, dy / r)


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def _goes_up(polygon: Polygon, v: Vertex, down: Point) -> bool:
    ends = (polygon.points[polygon.prev(v.index)], polygon.points[polygon.next(v.index)])
    return all(dot_sign(down, v.point, q) < 0 for q in ends)


def _perpendicular_edges(polygon: Polygon, down: Point) -> bool:
    arr = np.asarray(polygon.points, dtype=float)
    return not dot_sign_many(down, arr, np.roll(arr, -1, 0)).all()


def _tilted(polygon: Polygon, v: Vertex, down: Point) -> tuple[float, float]:
    if _goes_up(polygon, v, down) and not _perpendicular_edges(polygon, down):
        return down
    for k in range(10, 60):
        for sign in (1.0, -1.0):
            t = sign * 2.0**-k
            c, s = math.cos(t), math.sin(t)
            turned = (c * down[0] - s * down[1], s * down[0] + c * down[1])
            if _goes_up(polygon, v, turned) and not _perpendicular_edges(polygon, turned):
                return turned
    raise AssertionError("no tilt avoids perpendicular edges")  # finitely many edges


@tracing.traced(produces=True)  # the impact point stays marked until the band is done
def drop_ball(polygon: Polygon, v: Vertex, g: Gravity) -> Hit:
    """The ball falls from V along gravity; the first edge (or vertex) it meets."""
    down, p, n = g.down, v.point, polygon.n
    sides = [cross_sign(down, p, q) for q in polygon.points]
    best: tuple[Fraction, Hit] | None = None
    for k in range(n):
        if k == v.index:
            continue
        q = polygon.points[k]
        if sides[k] == 0 and dot_sign(down, p, q) > 0:
            t = ray_parameter(p, down, q)
            best = _nearer(best, t, Hit(_exact(q), None, polygon.vertex(k)))
        m = (k + 1) % n
        if v.index in (k, m) or sides[k] * sides[m] >= 0:
            continue
        t, point = ray_meets_line(p, down, q, polygon.points[m])
        if t > 0:
            best = _nearer(best, t, Hit(point, (k, m), None))
    if best is None:
        raise AssertionError("a ray from inside meets the boundary")
    return best[1]


def _exact(q: Point) -> Exact:
    return (Fraction(q[0]), Fraction(q[1]))


def _nearer(best: tuple[Fraction, Hit] | None, t: Fraction, hit: Hit) -> tuple[Fraction, Hit]:
    return (t, hit) if best is None or t < best[0] else best


@tracing.traced
def slide_to_vertex(polygon: Polygon, hit: Hit, g: Gravity) -> Vertex:
    """The ball slides down the edge it hit to the edge's lower end X."""
    if hit.vertex is not None:
        return hit.vertex
    assert hit.edge is not None  # a hit is on a vertex or inside an edge
    k, m = hit.edge
    lower = m if dot_sign(g.down, polygon.points[k], polygon.points[m]) > 0 else k
    return polygon.vertex(lower)


@tracing.traced(consumes=("hit",))
def band_snag(polygon: Polygon, v: Vertex, hit: Hit, x: Vertex) -> Vertex | None:
    """The band V–ball sweeps the triangle V–hit–X; the first vertex it snags, if any."""
    if hit.vertex is not None:
        return None
    h = cast(Point, hit.point)  # exact Fractions: the predicates compute exactly on them too
    inside = [
        polygon.vertex(k)
        for k in _near_triangle(polygon, v.point, hit.at, x.point)
        if k not in (v.index, x.index) and in_triangle(polygon.points[k], v.point, h, x.point)
    ]
    if not inside:
        return None

    def order(a: Vertex, b: Vertex) -> int:
        return compare_angle(v.point, h, a.point, b.point) or compare_distance(
            v.point, a.point, b.point
        )

    return min(inside, key=cmp_to_key(order))


def _near_triangle(polygon: Polygon, a: Point, b: Point, c: Point) -> list[int]:
    """Vertices in the triangle's bounding box, widened a little (a float pre-filter)."""
    arr = np.asarray(polygon.points, dtype=float)
    corners = np.asarray([a, b, c], dtype=float)
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    pad = 1e-9 * (np.abs(corners).max() + 1.0)
    mask = np.all((arr >= lo - pad) & (arr <= hi + pad), axis=1)
    return [int(k) for k in np.flatnonzero(mask)]


@tracing.traced
def gravity_at(polygon: Polygon, v: Vertex) -> Diagonal:
    """Gravity's diagonal from a given reflex (or straight) vertex V."""
    g = gravity_direction(polygon, v)
    hit = drop_ball(polygon, v, g)
    x = slide_to_vertex(polygon, hit, g)
    y = band_snag(polygon, v, hit, x)
    return claim(v, y if y is not None else x)


@tracing.traced(name="gravity")
def gravity(polygon: Polygon) -> Diagonal:
    """The gravity heuristic on the whole polygon (first reflex vertex from B)."""
    if polygon.n < 4:
        raise ValueError("a triangle has no diagonal")
    # B, traced: the pseudocode's first row names it, and V is "the first reflex vertex after
    # B" (B was never shown nor its row lit: chapter 3)
    b = leftmost_vertex(polygon)
    v = reflex_vertex(polygon)
    if v is None:
        v = straight_vertex(polygon)
        if v is None:
            return _convex_fallback(polygon, b)
        tracing.note(
            "no-reflex-vertex",
            reason=f"No reflex vertex: the ball drops from the straight vertex {v.label}",
            vertex=v.label,
        )
    return gravity_at(polygon, v)


def _convex_fallback(polygon: Polygon, b: Vertex) -> Diagonal:
    """Strictly convex: every diagonal is inner; claim AC around the left-most vertex B."""
    t = triangle_at(polygon, b)
    tracing.note(
        "no-reflex-vertex",
        reason="Strictly convex: every diagonal is inner, so claim "  # the piece's own labels
               f"{t.a.label}{t.c.label}, cutting off the left-most {t.b.label}",
        diagonal=[t.a.label, t.c.label],
    )
    return claim(t.a, t.c)
