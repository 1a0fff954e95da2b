"""Exact checks: is a segment an inner diagonal, is a set of triangles a triangulation.

Each check returns a :class:`CheckResult` that is truthy when the answer is yes
and otherwise says why not, in words and as data (``code``, the edge crossed,
the point of crossing, the vertex hit), so a scene can draw the reason.

Examples
--------
>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
>>> bool(is_inner_diagonal(p, 1, 4))
True
>>> is_inner_diagonal(p, 1, 3).why
'B–D crosses edge E–A at (2.86087, 6.36087)'
>>> verify_triangulation(p, [(1, 2, 4), (2, 3, 4), (4, 0, 1)]).ok
True
>>> verify_triangulation(p, [(1, 2, 4), (2, 3, 4)]).why
'wrong number of triangles: 2 for 5 vertices (expected 3)'
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from geometry.holes import PolygonWithHoles
from geometry.polygon import Polygon
from geometry.predicates import (
    Contact,
    Point,
    intersection_point,
    on_segment,
    orient,
    segment_contact,
    squared_distance,
)
from geometry.validate import fmt_point


@dataclass(frozen=True)
class CheckResult:
    """The answer of a check: ``ok``, and when not ok, why.

    ``code`` is one of: ``adjacent``, ``same-vertex``, ``crosses``,
    ``through-vertex``, ``outside``, ``count``, ``bad-index``, ``degenerate``,
    ``overlap``, ``uncovered``. ``edge`` is the polygon edge crossed (vertex
    indices), ``point`` where, ``vertex`` the vertex hit.
    """

    ok: bool
    why: str | None = None
    code: str | None = None
    edge: tuple[int, int] | None = None
    point: Point | None = None
    vertex: int | None = None
    triangle: tuple[int, int, int] | None = None

    def __bool__(self) -> bool:
        return self.ok

    def to_dict(self) -> dict[str, Any]:
        """Plain JSON data."""
        return {
            "ok": self.ok,
            "why": self.why,
            "code": self.code,
            "edge": list(self.edge) if self.edge else None,
            "point": list(self.point) if self.point else None,
            "vertex": self.vertex,
            "triangle": list(self.triangle) if self.triangle else None,
        }


YES = CheckResult(True)


def _name(p: Polygon | PolygonWithHoles, *idx: int) -> str:
    return "–".join(p.labels[i] for i in idx)


def _strictly_inside_cone(p: Polygon, v: int, target: Point) -> bool:
    """Whether the ray from vertex v towards target starts into the polygon's interior."""
    u, w = p.points[p.prev(v)], p.points[p.next(v)]
    pv = p.points[v]
    if p.turn(v) > 0:
        return orient(pv, w, target) > 0 and orient(pv, u, target) < 0
    return orient(pv, w, target) > 0 or orient(pv, u, target) < 0


def is_inner_diagonal(polygon: Polygon, i: int, j: int) -> CheckResult:
    """Whether the segment between vertices i and j lies inside the polygon.

    Reasons, checked in this order: same vertex, adjacent vertices, passes
    through a vertex (the one nearest i), crosses an edge (the crossing
    nearest i), runs outside near an endpoint.
    """
    n = polygon.n
    if i == j:
        return CheckResult(False, f"{_name(polygon, i)} is one vertex", "same-vertex", vertex=i)
    if j in (polygon.next(i), polygon.prev(i)):
        return CheckResult(False, f"{_name(polygon, i, j)} is an edge (adjacent vertices)", "adjacent")
    a, b = polygon.points[i], polygon.points[j]
    seg = _name(polygon, i, j)
    hits = [k for k in range(n) if k not in (i, j) and on_segment(polygon.points[k], a, b)]
    if hits:
        k = min(hits, key=lambda k: squared_distance(a, polygon.points[k]))
        where = fmt_point(polygon.points[k])
        return CheckResult(
            False, f"{seg} passes through vertex {polygon.labels[k]} {where}",
            "through-vertex", vertex=k, point=polygon.points[k],
        )
    crossing = _first_crossing(polygon, i, j)
    if crossing is not None:
        return crossing
    for v, t in ((i, b), (j, a)):
        if not _strictly_inside_cone(polygon, v, t):
            return CheckResult(
                False, f"{seg} runs outside the polygon near vertex {polygon.labels[v]}",
                "outside", vertex=v,
            )
    return YES


def _first_crossing(polygon: Polygon, i: int, j: int) -> CheckResult | None:
    a, b = polygon.points[i], polygon.points[j]
    best: tuple[Fraction, int, Point] | None = None
    for k, m in polygon.edges():
        if i in (k, m) or j in (k, m):
            continue
        c, d = polygon.points[k], polygon.points[m]
        if segment_contact(a, b, c, d) is not Contact.PROPER:
            continue  # touching at a vertex was reported as passing through it
        x = intersection_point(a, b, c, d)
        dist = squared_distance(a, x)
        if best is None or dist < best[0]:
            best = (dist, k, x)
    if best is None:
        return None
    _, k, x = best
    m = polygon.next(k)
    return CheckResult(
        False, f"{_name(polygon, i, j)} crosses edge {_name(polygon, k, m)} at {fmt_point(x)}",
        "crosses", edge=(k, m), point=x,
    )


def verify_triangulation(polygon: Polygon | PolygonWithHoles, triangles: Iterable[Sequence[int]]) -> CheckResult:
    """Whether the triangles (vertex-index triples) triangulate the polygon, exactly.

    Certificate: every triangle is non-degenerate and counter-clockwise once
    its corners are ordered, and the directed edges of all triangles cancel
    pairwise (u→v against v→u) down to exactly the polygon's directed edges.
    Then the sum of the triangles' indicator functions equals the winding
    number of the boundary, 1 inside and 0 outside: the triangles cover the
    polygon with disjoint interiors. No floating point is involved.

    A :class:`geometry.holes.PolygonWithHoles` is checked the same way: its holes
    run clockwise, so the winding number is 0 inside them, and a triangulation
    has ``n + 2h - 2`` triangles (Euler's formula for h holes).
    """
    tris = [tuple(t) for t in triangles]
    n, holes = polygon.n, polygon.hole_count
    expected = n + 2 * holes - 2
    if len(tris) != expected:
        rings = f" and {holes} hole{'s' if holes > 1 else ''}" if holes else ""
        return CheckResult(
            False,
            f"wrong number of triangles: {len(tris)} for {n} vertices{rings} (expected {expected})",
            "count",
        )
    directed: Counter[tuple[int, int]] = Counter()
    for tri in tris:
        problem = _triangle_problem(polygon, tri)
        if problem is not None:
            return problem
        a, b, c = tri if polygon_turn(polygon, tri) > 0 else (tri[0], tri[2], tri[1])
        directed.update(((a, b), (b, c), (c, a)))
    return _edge_balance(polygon, directed)


def polygon_turn(polygon: Polygon | PolygonWithHoles, tri: Sequence[int]) -> int:
    """Orientation of a triangle given by vertex indices."""
    return orient(*(polygon.points[k] for k in tri))


def _triangle_problem(polygon: Polygon | PolygonWithHoles, tri: tuple[int, ...]) -> CheckResult | None:
    if len(tri) != 3 or not all(isinstance(k, int) and 0 <= k < polygon.n for k in tri):
        return CheckResult(False, f"triangle {list(tri)} does not name three vertices", "bad-index")
    if len(set(tri)) < 3 or polygon_turn(polygon, tri) == 0:
        return CheckResult(
            False, f"triangle {_name(polygon, *tri)} is degenerate (zero area)", "degenerate",
            triangle=(tri[0], tri[1], tri[2]),
        )
    return None


def _edge_balance(polygon: Polygon | PolygonWithHoles, directed: Counter[tuple[int, int]]) -> CheckResult:
    """Check the cancellation certificate edge by edge (each unordered edge once)."""
    boundary = set(polygon.edges())
    pairs = {(min(e), max(e)) for e in directed} | {(min(e), max(e)) for e in boundary}
    for u, v in sorted(pairs):
        if (v, u) in boundary:
            u, v = v, u  # orient boundary edges counter-clockwise: interior on the left
        ahead, back = directed.get((u, v), 0), directed.get((v, u), 0)
        name = _name(polygon, u, v)
        if (u, v) in boundary:
            if back:
                return CheckResult(
                    False, f"a triangle lies outside the polygon beyond edge {name}",
                    "outside", edge=(u, v),
                )
            if ahead != 1:
                return _cover_verdict(ahead, name, (u, v), "polygon edge ")
        elif ahead != 1 or back != 1:
            return _cover_verdict(max(ahead, back) if ahead + back > 1 else 0, name, (u, v))
    return YES


def _cover_verdict(count: int, name: str, edge: tuple[int, int], kind: str = "") -> CheckResult:
    if count > 1:
        return CheckResult(False, f"triangles overlap along {kind}{name}", "overlap", edge=edge)
    return CheckResult(
        False, f"area not covered beside {kind}{name}: it has a triangle on one side only"
        if not kind else f"area not covered: {kind}{name} has no triangle",
        "uncovered", edge=edge,
    )
