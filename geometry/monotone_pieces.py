"""The second half of the monotone algorithm: the pieces, and a stack to triangulate each.

:func:`monotone_pieces` walks the faces of the polygon cut by its diagonals:
around each vertex the edges and diagonals are sorted counter-clockwise (an
exact angular order), and a face is followed by always taking, at the end of
a half-edge a→b, the edge out of b that comes next clockwise from b→a.

:func:`triangulate_monotone_piece` is the greedy stack triangulation of a
y-monotone polygon (de Berg et al., ch. 3.3): merge its two chains top to
bottom; a vertex on the other chain than the stack's top sees every stacked
vertex (cut them all off, top first); a vertex on the same chain cuts off
triangles while the stack's top is strictly convex, then waits. Straight angles are not convex,
so no triangle has zero area.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
>>> [piece.ids for piece in monotone_pieces(p, [(1, 4)])]
[(0, 1, 4), (1, 2, 3, 4)]
>>> triangulate_monotone_piece(p, monotone_pieces(p, [(1, 4)])[1])
[(4, 1, 2), (3, 4, 2)]
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cmp_to_key
from typing import Any

import numpy as np

import tracing
from geometry.holes import PolygonWithHoles
from geometry.polygon import Polygon
from geometry.predicates import Point, orient
from geometry.results import TriangleIndices


@dataclass(frozen=True)
class MonotonePiece:
    """A y-monotone piece: polygon vertex indices, counter-clockwise (key ``M1``, ``M2`` …)."""

    polygon: Polygon | PolygonWithHoles
    ids: tuple[int, ...]
    number: int

    @property
    def trace_key(self) -> str:
        return f"M{self.number}"

    def trace_state(self) -> dict[str, Any]:
        p = self.polygon
        return {
            "kind": "polygon",
            "points": [list(p.points[i]) for i in self.ids],
            "labels": [p.labels[i] for i in self.ids],
        }


@tracing.traced(exclude_args=("diagonals",))
def monotone_pieces(polygon: Polygon | PolygonWithHoles, diagonals: list[tuple[int, int]]) -> list[MonotonePiece]:
    """The faces of the polygon cut along the diagonals, each counter-clockwise."""
    n, nxt = polygon.n, polygon.next_array
    around = _fans(polygon, diagonals)
    seen_edge = bytearray(n)
    seen_diagonal: set[tuple[int, int]] = set()
    starts = [(i, nxt[i]) for i in range(n)]
    starts += [pair for u, w in diagonals for pair in ((u, w), (w, u))]
    pieces: list[MonotonePiece] = []
    for a, b in starts:
        if (b == nxt[a] and seen_edge[a]) or (a, b) in seen_diagonal:
            continue
        ids = []
        start = (a, b)
        while True:
            ids.append(a)
            if b == nxt[a]:
                seen_edge[a] = 1
            else:
                seen_diagonal.add((a, b))
            fan = around.get(b)
            c = nxt[b] if fan is None else fan[fan.index(a) - 1]
            a, b = b, c
            if (a, b) == start:
                break
        pieces.append(MonotonePiece(polygon, tuple(ids), len(pieces) + 1))
    return pieces


def _fans(polygon: Polygon | PolygonWithHoles, diagonals: list[tuple[int, int]]) -> dict[int, list[int]]:
    """For each vertex with diagonals: its neighbours counter-clockwise, from next to prev."""
    points, nxt_of, prv_of = polygon.points, polygon.next_array, polygon.prev_array
    partners: dict[int, list[int]] = {}
    for u, w in diagonals:
        partners.setdefault(u, []).append(w)
        partners.setdefault(w, []).append(u)
    fans = {}
    for v, others in partners.items():
        nxt, prv = nxt_of[v], prv_of[v]
        pv, ref = points[v], points[nxt]

        def half(p: int, pv: Point = pv, ref: Point = ref) -> int:  # 0: within π counter-clockwise of v→next
            return 0 if orient(pv, ref, points[p]) > 0 else 1

        def compare(p: int, q: int, pv: Point = pv, half: Callable[[int], int] = half) -> int:
            return (half(p) - half(q)) or -orient(pv, points[p], points[q])

        fans[v] = [nxt, *sorted(others, key=cmp_to_key(compare)), prv]
    return fans


@tracing.traced
def triangulate_monotone_piece(polygon: Polygon | PolygonWithHoles, piece: MonotonePiece) -> list[TriangleIndices]:
    """The stack triangulation of one y-monotone piece, counter-clockwise triples.

    The stack holds the chain of vertices that wait to be triangulated; every change to it
    is a traced step (:func:`push`, :func:`cut_off`), so the log shows the chain grow and
    shrink, each triangle as it is cut off.
    """
    ids = piece.ids
    if len(ids) == 3:
        return [ids]
    points = polygon.points
    order, on_left = _merged_chains(polygon, ids)
    triangles: list[TriangleIndices] = []
    stack: list[int] = []
    push(stack, order[0])
    push(stack, order[1])
    for u in order[2:-1]:
        if on_left[u] != on_left[stack[-1]]:  # the other chain: u sees every waiting vertex
            top = stack[-1]
            while len(stack) > 1:
                triangles.append(cut_off(points, stack, u))
            stack = [top]  # the last one popped (the bottom) needs no triangle
        else:  # the same chain: cut off while the top is strictly convex, then wait
            while len(stack) > 1 and _cuts_off(points, stack[-2], stack[-1], u, on_left[u]):
                triangles.append(cut_off(points, stack, u))
        push(stack, u)
    while len(stack) > 1:  # the lowest vertex sees every waiting one
        triangles.append(cut_off(points, stack, order[-1]))
    return triangles


@tracing.traced
def push(stack: list[int], u: int) -> None:
    """u waits on the stack (the call's ``stack`` is the chain before it)."""
    stack.append(u)


@tracing.traced(exclude_args=("points",))
def cut_off(points: Sequence[Point], stack: list[int], u: int) -> TriangleIndices:
    """u sees the vertex below the stack's top: the triangle (below, top, u) is cut off and
    the top leaves the stack (the call's ``stack`` is the chain before)."""
    top = stack.pop()
    return _ccw(points, stack[-1], top, u)


def _merged_chains(polygon: Polygon | PolygonWithHoles, ids: tuple[int, ...]) -> tuple[list[int], dict[int, bool]]:
    """The piece's vertices from highest to lowest, and which lie on its left chain."""
    pts = np.asarray([polygon.points[i] for i in ids], dtype=float)
    by_height = np.lexsort((pts[:, 0], -pts[:, 1])).tolist()  # highest first, as in the sweep
    top, bottom = by_height[0], by_height[-1]
    k = len(ids)
    on_left = {ids[i]: False for i in range(k)}
    i = top
    while i != bottom:  # counter-clockwise from the top runs down the left chain
        on_left[ids[i]] = True
        i = (i + 1) % k
    return [ids[i] for i in by_height], on_left


def _cuts_off(points: Sequence[Point], s: int, last: int, u: int, left: bool) -> bool:
    """Whether u sees s past last: last is strictly convex on u's chain."""
    turn = orient(points[s], points[last], points[u])
    return turn > 0 if left else turn < 0


def _ccw(points: Sequence[Point], a: int, b: int, c: int) -> TriangleIndices:
    turn = orient(points[a], points[b], points[c])
    if turn == 0:
        raise AssertionError("a monotone piece produced a zero-area triangle")
    return (a, b, c) if turn > 0 else (a, c, b)
