"""A polygon with holes: its rings validated, oriented and labelled, as one vertex array.

Vertices are stored ring after ring: the outer ring counter-clockwise (as
:class:`geometry.polygon.Polygon` stores it, labelled A, B, C … with B the
left-most vertex), then each hole **clockwise**, so the region lies on the left
of every edge and a positive turn is a convex corner of the region. Hole k
(numbered from 1 in input order) is labelled a, b, c … with the hole's number
as a subscript — ``a₁ b₁ c₁``, ``a₂ b₂ …``; ``a`` is the hole's left-most vertex
(the lowest on ties) and the letters run clockwise, the order stored. Past 26
vertices of a hole the letters go round again with a count, as on the outer
ring: ``a1₁`` is hole 1's 27th vertex.

``source`` maps each stored vertex to its place in the cleaned input rings
concatenated (outer, then the holes in order): the indexing of ``trex
triangulate --json``.

Examples
--------
>>> p = PolygonWithHoles.from_rings([[(0, 0), (6, 0), (6, 6), (0, 6)], [(2, 2), (2, 4), (4, 4), (4, 2)]])
>>> p.n, p.hole_count, p.labels
(8, 1, ('A', 'B', 'C', 'D', 'a₁', 'b₁', 'c₁', 'd₁'))
>>> p.points[4:], p.source[4:]
(((2.0, 2.0), (2.0, 4.0), (4.0, 4.0), (4.0, 2.0)), (4, 5, 6, 7))
>>> p.next(7), p.prev(4), p.ring_of(5)
(4, 7, 1)
>>> p.area
32.0
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property
from typing import Any

import numpy as np

from geometry.errors import PolygonError
from geometry.polygon import Polygon, Vertex, leftmost_index, orientation_step
from geometry.predicates import Point, signed_area2
from geometry.ring_contacts import check_rings
from geometry.validate import check_not_collinear, check_simple, clean_points, orient_array

_SUBSCRIPTS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def hole_label(hole: int, i: int) -> str:
    """Label of the i-th vertex (clockwise from the left-most) of hole ``hole`` (from 1).

    >>> [hole_label(1, 0), hole_label(2, 1), hole_label(12, 25), hole_label(1, 26)]
    ['a₁', 'b₂', 'z₁₂', 'a1₁']
    """
    letter = chr(ord("a") + i % 26) + (str(i // 26) if i >= 26 else "")
    return letter + str(hole).translate(_SUBSCRIPTS)


def _clockwise_order(points: list[Point]) -> list[int]:
    """Input indices clockwise, starting at the left-most (then lowest) point."""
    n, step = len(points), -orientation_step(points)
    start = leftmost_index(points)
    return [(start + step * k) % n for k in range(n)]


@dataclass(frozen=True)
class _Hole:
    points: tuple[Point, ...]
    labels: tuple[str, ...]
    source: tuple[int, ...]
    input_clockwise: bool
    warnings: tuple[str, ...]


def _hole(raw: object, number: int) -> _Hole:
    """Clean, validate and orient hole ``number``; errors say which hole."""
    try:
        points, warnings = clean_points(raw)
        check_not_collinear(points)
        order = _clockwise_order(points)
        name = {src: hole_label(number, k) for k, src in enumerate(order)}
        check_simple(points, name.__getitem__)
    except PolygonError as exc:
        raise type(exc)(f"hole {number}: {exc}") from None
    return _Hole(
        points=tuple(points[i] for i in order),
        labels=tuple(name[i] for i in order),
        source=tuple(order),
        input_clockwise=orientation_step(points) < 0,
        warnings=tuple(f"hole {number}: {w}" for w in warnings),
    )


@dataclass(frozen=True, eq=False)
class PolygonWithHoles:
    """An outer ring (counter-clockwise) and holes (clockwise) in one vertex array.

    Use :meth:`from_rings` for untrusted input. Ring k occupies
    ``points[starts[k]:starts[k + 1]]``; ring 0 is the outer one.
    """

    points: tuple[Point, ...]
    labels: tuple[str, ...]
    source: tuple[int, ...]
    starts: tuple[int, ...]
    input_clockwise: bool = False
    warnings: tuple[str, ...] = ()

    @classmethod
    def from_rings(cls, rings: Sequence[object]) -> PolygonWithHoles:
        """Validate the outer ring, each hole, then how the rings lie (see :mod:`geometry.ring_contacts`).

        Raises a :class:`geometry.errors.PolygonError` naming the defect and where.
        """
        outer = Polygon.from_points(rings[0] if rings else [])
        holes = [_hole(raw, k) for k, raw in enumerate(rings[1:], start=1)]
        points, labels, source, starts = list(outer.points), list(outer.labels), list(outer.source), [0]
        offset = outer.n
        for hole in holes:
            starts.append(len(points))
            points += hole.points
            labels += hole.labels
            source += [offset + s for s in hole.source]
            offset += len(hole.points)
        starts.append(len(points))
        polygon = cls(
            points=tuple(points), labels=tuple(labels), source=tuple(source),
            starts=tuple(starts), input_clockwise=outer.input_clockwise,
            warnings=outer.warnings + tuple(w for hole in holes for w in hole.warnings),
        )
        check_rings(polygon)
        return polygon

    # --- the rings ---------------------------------------------------------------------------

    @property
    def n(self) -> int:
        return len(self.points)

    def __len__(self) -> int:
        return len(self.points)

    @property
    def hole_count(self) -> int:
        return len(self.starts) - 2

    def ring(self, k: int) -> range:
        """Vertex indices of ring k (0: the outer ring)."""
        return range(self.starts[k], self.starts[k + 1])

    @cached_property
    def ring_ids(self) -> np.ndarray:
        """The ring of every vertex."""
        sizes = np.diff(np.asarray(self.starts))
        return np.repeat(np.arange(len(sizes)), sizes)

    def ring_of(self, i: int) -> int:
        return int(self.ring_ids[i])

    @cached_property
    def _links(self) -> tuple[list[int], list[int]]:
        nxt, prv = list(range(1, self.n + 1)), list(range(-1, self.n - 1))
        for lo, hi in zip(self.starts, self.starts[1:], strict=False):
            nxt[hi - 1], prv[lo] = lo, hi - 1
        return nxt, prv

    def next(self, i: int) -> int:
        return self._links[0][i]

    def prev(self, i: int) -> int:
        return self._links[1][i]

    @property
    def next_array(self) -> list[int]:
        return self._links[0]

    @property
    def prev_array(self) -> list[int]:
        return self._links[1]

    def edges(self) -> Iterator[tuple[int, int]]:
        """Every ring's edges (i, next(i)), the region on their left."""
        nxt = self._links[0]
        return ((i, nxt[i]) for i in range(self.n))

    @cached_property
    def outer(self) -> Polygon:
        """The outer ring alone, as the simple polygon it is."""
        k = self.starts[1]
        return Polygon(self.points[:k], self.labels[:k], self.source[:k], self.input_clockwise)

    # --- vertices, turns, area -----------------------------------------------------------------

    def vertex(self, i: int) -> Vertex:
        return Vertex(i, self.labels[i], self.points[i])

    @cached_property
    def turns(self) -> np.ndarray:
        """Turn at every vertex within its ring: 1 convex, -1 reflex, 0 straight (for the region)."""
        arr = np.asarray(self.points, dtype=float)
        nxt, prv = self._links
        return orient_array(arr[prv], arr, arr[nxt])

    def turn(self, i: int) -> int:
        return int(self.turns[i])

    def reflex_vertices(self) -> list[int]:
        return [int(i) for i in np.flatnonzero(self.turns < 0)]

    @cached_property
    def area2(self) -> Fraction:
        """Exact twice the area: the outer ring's less the holes'."""
        return sum((signed_area2(self.points[r.start:r.stop]) for r in map(self.ring, range(len(self.starts) - 1))),
                   Fraction(0))

    @property
    def area(self) -> float:
        return float(self.area2) / 2

    def leftmost(self) -> int:
        return leftmost_index(self.points[: self.starts[1]])

    def input_points(self) -> list[Point]:
        """The vertices in (cleaned) input order: the rings concatenated."""
        out: list[Point] = [(0.0, 0.0)] * self.n
        for p, src in zip(self.points, self.source, strict=True):
            out[src] = p
        return out

    # --- tracing ------------------------------------------------------------------------------

    @property
    def trace_key(self) -> str:
        holes = self.hole_count
        return f"P({self.outer.trace_key[2:-1]}, {holes} hole{'s' if holes > 1 else ''})"

    def trace_state(self) -> dict[str, Any]:
        rings = [self.ring(k) for k in range(len(self.starts) - 1)]
        return {
            "kind": "polygon",
            "points": [list(self.points[i]) for i in rings[0]],
            "labels": [self.labels[i] for i in rings[0]],
            "holes": [
                {"points": [list(self.points[i]) for i in r], "labels": [self.labels[i] for i in r]}
                for r in rings[1:]
            ],
        }

    def __repr__(self) -> str:
        return f"PolygonWithHoles(n={self.n}, holes={self.hole_count})"
