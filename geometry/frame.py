"""The frame of the triangle heuristics: B, T = ABC, the candidates; and the claim type.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
>>> t = triangle_at(p, leftmost_vertex(p))
>>> t.trace_key, [v.label for v in candidates_in_triangle(p, t)]
('T(ABC)', ['D', 'E'])
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import tracing
from geometry.polygon import Polygon, Vertex
from geometry.predicates import in_triangle


@dataclass(frozen=True)
class Diagonal:
    """A claimed diagonal between two vertices (traceable as e.g. ``BD``)."""

    u: Vertex
    v: Vertex

    @property
    def name(self) -> str:
        return f"{self.u.label}{self.v.label}"

    @property
    def pair(self) -> tuple[int, int]:
        return (self.u.index, self.v.index)

    @property
    def trace_key(self) -> str:
        return f"{self.u.trace_key}{self.v.trace_key}"  # the name, as the board labels them

    def trace_state(self) -> dict[str, Any]:
        return {
            "kind": "segment",
            "points": [list(self.u.point), list(self.v.point)],
            "labels": [self.u.trace_key, self.v.trace_key],
            "indices": [self.u.index, self.v.index],
        }


@dataclass(frozen=True)
class Triangle:
    """The frame triangle T = ABC at a convex vertex B."""

    a: Vertex
    b: Vertex
    c: Vertex

    @property
    def trace_key(self) -> str:
        return f"T({self.a.trace_key}{self.b.trace_key}{self.c.trace_key})"

    def trace_state(self) -> dict[str, Any]:
        return {
            "kind": "polygon",
            "points": [list(v.point) for v in (self.a, self.b, self.c)],
            "labels": [v.trace_key for v in (self.a, self.b, self.c)],
        }


@tracing.traced
def leftmost_vertex(polygon: Polygon) -> Vertex:
    """B: the left-most vertex, the lowest on ties — always strictly convex."""
    return polygon.vertex(polygon.leftmost())


@tracing.traced
def triangle_at(polygon: Polygon, b: Vertex) -> Triangle:
    """T = ABC: B with its two neighbours (A before it, C after it, counter-clockwise)."""
    return Triangle(polygon.vertex(polygon.prev(b.index)), b, polygon.vertex(polygon.next(b.index)))


@tracing.traced
def candidates_in_triangle(polygon: Polygon, t: Triangle) -> list[Vertex]:
    """The vertices other than A, B, C lying in the closed triangle T, counter-clockwise from C."""
    corners = (t.a.point, t.b.point, t.c.point)
    xs, ys = [p[0] for p in corners], [p[1] for p in corners]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    out = []
    for k in range(2, polygon.n - 1):
        i = (t.b.index + k) % polygon.n
        x, y = polygon.points[i]
        # outside T's bounding box is outside T (exact: comparisons of the same floats)
        if x0 <= x <= x1 and y0 <= y <= y1 and in_triangle((x, y), *corners):
            out.append(polygon.vertex(i))
    return out


@tracing.traced(produces=True)
def claim(u: Vertex, v: Vertex) -> Diagonal:
    """The heuristic's answer, entered into the log as a segment so a scene can draw it."""
    return Diagonal(u, v)
