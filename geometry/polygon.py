"""The validated simple polygon every algorithm works on.

Vertices are stored counter-clockwise. They are labelled A, B, C, … (then A1,
B1, … past 26) along that order, starting so that the left-most vertex (the
lowest one on ties) is **B**: the frame of the thesis's inner-diagonal
heuristics (B left-most, A and C its neighbours) then reads with the polygon's
own labels. ``source`` maps each stored vertex back to its position in the
cleaned input.

Examples
--------
>>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
>>> p.labels
('A', 'B', 'C', 'D', 'E')
>>> p.points[1], p.source[1]
((1.0, 4.5), 0)
>>> p.reflex_vertices()
[4]
>>> Polygon.from_points([(0, 0), (2, 2), (2, 0), (0, 2)])
Traceback (most recent call last):
...
geometry.errors.SelfIntersectionError: edges B–C and D–A cross at (1, 1)
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cached_property
from typing import Any

import numpy as np

from geometry.predicates import Point, orient, signed_area2
from geometry.validate import (
    check_not_collinear,
    check_simple,
    clean_points,
    orient_array,
)


def vertex_label(i: int) -> str:
    """Label of the i-th vertex: A … Z, then A1 … Z1, A2 …

    >>> [vertex_label(i) for i in (0, 25, 26, 53)]
    ['A', 'Z', 'A1', 'B2']
    """
    letter = chr(ord("A") + i % 26)
    return letter if i < 26 else f"{letter}{i // 26}"


def leftmost_index(points: Sequence[Point]) -> int:
    """Index of the left-most point, the lowest one on ties (exact: tuple comparison)."""
    return min(range(len(points)), key=lambda i: (points[i][0], points[i][1]))


def _is_counter_clockwise(points: list[Point]) -> bool:
    # The turn at the left-most (then lowest) vertex of a simple ring is never
    # collinear-with-fold, and is left exactly when the ring is counter-clockwise.
    k = leftmost_index(points)
    turn = orient(points[k - 1], points[k], points[(k + 1) % len(points)])
    if turn != 0:
        return turn > 0
    return signed_area2(points) > 0


def orientation_step(points: list[Point]) -> int:
    """1 when the ring runs counter-clockwise, -1 when clockwise (exact)."""
    return 1 if _is_counter_clockwise(points) else -1


def _ccw_order(points: list[Point]) -> list[int]:
    """Input indices in counter-clockwise order, starting one before the left-most."""
    n = len(points)
    step = orientation_step(points)
    start = leftmost_index(points) - step
    return [(start + step * k) % n for k in range(n)]


@dataclass(frozen=True)
class Vertex:
    """A vertex as the algorithms speak of it: index, label, point (traceable by its label)."""

    index: int
    label: str
    point: Point
    #: the label the log shows, when it is not ``label`` (a vertex of a polygon handed in its
    #: own frame, :meth:`Polygon.own_frame`: the video keeps the labels on the board)
    shown: str | None = field(default=None, repr=False, compare=False)

    @property
    def trace_key(self) -> str:
        return self.shown or self.label

    def trace_state(self) -> dict[str, Any]:
        return {"kind": "point", "at": list(self.point), "label": self.trace_key}


@dataclass(frozen=True, eq=False)
class Polygon:
    """A simple polygon, counter-clockwise, with labelled vertices.

    Use :meth:`from_points` to build one from untrusted input; the constructor
    itself trusts its arguments (algorithms use it for sub-polygons).
    """

    points: tuple[Point, ...]
    labels: tuple[str, ...]
    source: tuple[int, ...]
    input_clockwise: bool = False
    warnings: tuple[str, ...] = ()
    #: the labels the log shows, when they are not ``labels`` (see :meth:`own_frame`)
    shown: tuple[str, ...] | None = field(default=None, repr=False)

    @classmethod
    def from_points(cls, raw: object) -> Polygon:
        """Validate raw points (any orientation) and build the polygon.

        Raises a :class:`geometry.errors.PolygonError` naming the defect.
        """
        points, warnings = clean_points(raw)
        check_not_collinear(points)
        order = _ccw_order(points)
        name = {src: vertex_label(k) for k, src in enumerate(order)}
        check_simple(points, name.__getitem__)
        clockwise = len(points) > 2 and order[1] != (order[0] + 1) % len(points)
        return cls(
            points=tuple(points[i] for i in order),
            labels=tuple(name[i] for i in order),
            source=tuple(order),
            input_clockwise=clockwise,
            warnings=tuple(warnings),
        )

    def sub_polygon(self, indices: Sequence[int]) -> Polygon:
        """The polygon on a subset of vertices (kept in the given ccw order, labels kept).

        ``source`` of the result maps to this polygon's indices' sources, so the
        indices of the root polygon survive any number of splits.
        """
        return Polygon(
            points=tuple(self.points[i] for i in indices),
            labels=tuple(self.labels[i] for i in indices),
            source=tuple(self.source[i] for i in indices),
            input_clockwise=self.input_clockwise,
            shown=tuple(self.shown[i] for i in indices) if self.shown else None,
        )

    def own_frame(self) -> Polygon:
        """This polygon in its own frame, as :meth:`from_points` would store it: from the
        vertex before the left-most, so that the left-most is **B** (index 1), A and C its
        neighbours, the rest labelled in order; ``source`` maps each vertex to its index
        here. A sub-polygon keeps its parent's labels (:meth:`sub_polygon`); a heuristic is
        handed it in this frame. What it traces still shows the labels it had (``shown``),
        as the video draws them. A polygon already in its own frame is returned as it is.

        >>> p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 6), (0, 4)])
        >>> piece = p.sub_polygon([2, 3, 4]).own_frame()
        >>> piece.labels, piece.source, piece.trace_key, piece.vertex(1).trace_key
        (('A', 'B', 'C'), (1, 2, 0), 'P(DEC)', 'E')
        >>> p.own_frame() is p
        True
        """
        n = self.n
        start = (self.leftmost() - 1) % n
        labels = tuple(vertex_label(k) for k in range(n))
        if start == 0 and self.labels == labels:
            return self
        order = tuple((start + k) % n for k in range(n))
        return Polygon(points=tuple(self.points[i] for i in order), labels=labels,
                       source=order, input_clockwise=self.input_clockwise,
                       shown=tuple(self.shown_labels[i] for i in order))

    @property
    def shown_labels(self) -> tuple[str, ...]:
        """The labels the log shows: ``labels``, unless handed in another frame."""
        return self.shown or self.labels

    def vertex(self, i: int) -> Vertex:
        return Vertex(i, self.labels[i], self.points[i], self.shown[i] if self.shown else None)

    @property
    def trace_key(self) -> str:
        """``P(ABCDE)``; long polygons are named by their first and last labels and size."""
        labels = self.shown_labels
        if self.n <= 16:
            return f"P({''.join(labels)})"
        return f"P({''.join(labels[:3])}…{''.join(labels[-3:])}, n={self.n})"

    def trace_state(self) -> dict[str, Any]:
        return {
            "kind": "polygon",
            "points": [list(p) for p in self.points],
            "labels": list(self.shown_labels),
        }

    def __len__(self) -> int:
        return len(self.points)

    @property
    def n(self) -> int:
        return len(self.points)

    @property
    def hole_count(self) -> int:
        """A simple polygon has none (see :class:`geometry.holes.PolygonWithHoles`)."""
        return 0

    def next(self, i: int) -> int:
        return (i + 1) % len(self.points)

    def prev(self, i: int) -> int:
        return (i - 1) % len(self.points)

    @cached_property
    def next_array(self) -> list[int]:
        """``next(i)`` of every vertex, as a list (shared with polygons with holes)."""
        return [*range(1, self.n), 0]

    @cached_property
    def prev_array(self) -> list[int]:
        """``prev(i)`` of every vertex, as a list."""
        return [self.n - 1, *range(self.n - 1)]

    def edges(self) -> Iterator[tuple[int, int]]:
        """Edges as index pairs (i, i+1), counter-clockwise."""
        n = len(self.points)
        return ((i, (i + 1) % n) for i in range(n))

    def label_of(self, label: str) -> int:
        """Index of the vertex with this label."""
        return self.labels.index(label)

    def turn(self, i: int) -> int:
        """1 at a convex vertex, -1 at a reflex one, 0 where the edges are collinear."""
        return orient(self.points[i - 1], self.points[i], self.points[(i + 1) % self.n])

    @cached_property
    def turns(self) -> np.ndarray:
        """:meth:`turn` of every vertex, computed at once."""
        arr = np.asarray(self.points, dtype=float)
        return orient_array(np.roll(arr, 1, 0), arr, np.roll(arr, -1, 0))

    def reflex_vertices(self) -> list[int]:
        return [int(i) for i in np.flatnonzero(self.turns < 0)]

    @cached_property
    def area2(self) -> Fraction:
        """Exact twice the area (positive)."""
        return signed_area2(self.points)

    @property
    def area(self) -> float:
        return float(self.area2) / 2

    def leftmost(self) -> int:
        """The left-most vertex, lowest on ties: convex, the thesis's B."""
        return leftmost_index(self.points)

    def input_points(self) -> list[Point]:
        """The vertices in (cleaned) input order."""
        out: list[Point] = [(0.0, 0.0)] * len(self.points)
        for p, src in zip(self.points, self.source, strict=True):
            out[src] = p
        return out

    def to_input_index(self, i: int) -> int:
        return self.source[i]

    def __repr__(self) -> str:
        return f"Polygon(n={self.n}, labels={''.join(self.labels[:8])}{'…' if self.n > 8 else ''})"
