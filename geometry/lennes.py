"""Triangulation by divide and conquer (Lennes 1911), with any inner-diagonal heuristic, traced.

Find a diagonal, split the polygon along it, go on with both halves until only
triangles are left. Every claim is checked exactly before the split; a wrong
heuristic's first bad claim stops the run and comes back as the failure, with
the edge it crosses. The work list is explicit (no recursion), so spirals of
thousands of vertices cannot exhaust Python's stack, and each split makes
both halves strictly smaller, so it always ends.

Traced, by decorators only: the pieces (key ``P(…)``, state: the polygon and
its vertex ids in the whole) enter when made and exit when split or done; each
finished triangle enters as ``△ABC`` and stays; the heuristic's claim exits
once checked. Steps: the recursion taking up a part a split made
(``next_part``), the base case (``done``), the heuristic's own, then ``split``:
each row of the pseudocode has a step that lights it.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
>>> divide_and_conquer(p, "gravity").triangles
((0, 1, 4), (1, 2, 4), (2, 3, 4))
>>> result = divide_and_conquer(p, "scaling")
>>> result.valid, result.failure.why
(False, 'B–D crosses edge E–A at (2.86087, 6.36087)')
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any, cast

import tracing
from geometry.check import CheckResult, is_inner_diagonal
from geometry.diagonals import HEURISTICS
from geometry.frame import Diagonal
from geometry.polygon import Polygon
from geometry.results import TriangleIndices, Triangulation, canonical


@dataclass(frozen=True)
class Piece:
    """A sub-polygon on its way to triangles, and where its vertices are in the whole polygon."""

    polygon: Polygon
    ids: tuple[int, ...]

    @classmethod
    @tracing.lifetimes(produces=True)
    def whole(cls, polygon: Polygon) -> Piece:
        """The first piece: the whole polygon (it enters the log)."""
        return cls(polygon, tuple(range(polygon.n)))

    @property
    def trace_key(self) -> str:
        return self.polygon.trace_key

    def trace_state(self) -> dict[str, Any]:
        return {**self.polygon.trace_state(), "ids": list(self.ids)}


@dataclass(frozen=True)
class FilledTriangle:
    """A piece of three vertices: a triangle of the answer, drawn filled (key ``△ABC``)."""

    piece: Piece

    @property
    def corners(self) -> TriangleIndices:
        """Its vertex indices in the whole polygon, in canonical form."""
        return canonical(cast(TriangleIndices, self.piece.ids))  # a piece of three vertices

    @property
    def trace_key(self) -> str:
        return f"△{''.join(self.piece.polygon.labels)}"

    def trace_state(self) -> dict[str, Any]:
        p = self.piece.polygon
        return {"kind": "polygon", "points": [list(q) for q in p.points], "labels": list(p.labels)}


@tracing.traced(consumes=("piece",), produces=True, produced_first=True)
def done(piece: Piece) -> FilledTriangle:
    """A triangle: done (the base case, a step of its own: its row is lit as it runs). It is
    drawn filled for good, then the piece goes."""
    return FilledTriangle(piece)


@tracing.traced
def next_part(piece: Piece) -> Piece:
    """The part made by a split that is triangulated the same way next (the recursion, a
    step of its own: its row is lit as the run takes the part up)."""
    return piece


@tracing.lifetimes(consumes=("claim",))
def check_claim(piece: Piece, claim: Diagonal) -> CheckResult:
    """Whether the heuristic's claim is an inner diagonal of the piece, exactly; the claim goes."""
    return is_inner_diagonal(piece.polygon, *claim.pair)


@tracing.traced(consumes=("piece",), produces=True)
def split(piece: Piece, i: int, j: int) -> tuple[Piece, Piece]:
    """Cut a piece along its inner diagonal i–j into the chains i…j and j…i.

    The piece leaves the log and its two halves enter it.
    """
    n = piece.polygon.n
    first = [(i + k) % n for k in range((j - i) % n + 1)]
    second = [(j + k) % n for k in range((i - j) % n + 1)]
    halves = [
        Piece(piece.polygon.sub_polygon(c), tuple(piece.ids[k] for k in c)) for c in (first, second)
    ]
    return halves[0], halves[1]


@tracing.traced(name="divide_and_conquer")
def divide_and_conquer(polygon: Polygon,
                       heuristic: str | Callable[[Polygon], Diagonal]) -> Triangulation:
    """Lennes' triangulation: a triangle is done; otherwise find a diagonal, split, go on.

    ``heuristic`` is a built-in's name, or a function ``piece -> Diagonal`` (a heuristic of
    one's own, :attr:`usercode.heuristic.UserHeuristic.function`, its errors and its
    time limit its own): it runs on each piece until its first wrong claim.
    """
    find = heuristic if callable(heuristic) else HEURISTICS[heuristic]
    todo, triangles, steps = [Piece.whole(polygon)], [], 0
    whole = todo[0].ids
    while todo:
        piece = todo.pop()
        if piece.ids != whole:  # a part a split made: the recursion takes it up
            piece = next_part(piece)
        if piece.polygon.n == 3:
            triangles.append(done(piece).corners)
            continue
        steps += 1
        claim = find(piece.polygon)
        verdict = check_claim(piece, claim)
        if not verdict:
            return _failure(piece, verdict, claim.pair, triangles, steps)
        halves = split(piece, *claim.pair)
        todo.extend(reversed(halves))  # the first half is worked on first
    return Triangulation(tuple(sorted(triangles)), True, steps=steps)


def _failure(
    piece: Piece, verdict: CheckResult, pair: tuple[int, int], triangles: list[TriangleIndices], steps: int
) -> Triangulation:
    """A piece's failed claim, restated in the whole polygon's indices.

    The edge it crosses may be an earlier diagonal (an edge of the piece only).
    """
    ids = piece.ids
    whole = replace(
        verdict,
        edge=(ids[verdict.edge[0]], ids[verdict.edge[1]]) if verdict.edge else None,
        vertex=ids[verdict.vertex] if verdict.vertex is not None else None,
    )
    labels = [piece.polygon.labels[k] for k in pair]
    tracing.note("bad-diagonal", diagonal=labels, why=verdict.why)
    return Triangulation(
        tuple(sorted(triangles)), False, failure=whole, claim=(ids[pair[0]], ids[pair[1]]), steps=steps
    )
