"""Monotone partition and stack triangulation (Garey, Johnson, Preparata, Tarjan 1978), traced.

As in de Berg et al., *Computational Geometry*, ch. 3. A horizontal line
sweeps down over the vertices. Each vertex is classified by its neighbours:

* **start**: both neighbours lower, interior angle < π;  **split**: both lower, > π;
* **end**: both neighbours higher, angle < π;  **merge**: both higher, > π;
* **regular**: one higher, one lower (every straight vertex is regular).

Split and merge vertices are where the polygon fails to be y-monotone (a
horizontal line meets a y-monotone polygon in one segment, or not at all).
Every edge crossing the line with the inside on its right has a *helper*: the
lowest vertex above the line whose horizontal segment to the edge lies inside
P (de Berg et al.'s definition: the lowest vertex yet that sees the edge
straight to its left). A split vertex is joined to the helper of the edge
directly left of it; a merge vertex becomes a helper and is joined to the next
vertex that replaces it. The diagonals cut the polygon
into y-monotone pieces (:mod:`geometry.monotone_pieces`), and each piece is
triangulated greedily with a stack in one more sweep. O(n log n).

"Higher" is lexicographic (larger y, then smaller x), so equal y
coordinates need no special case, and every side test is exact.

Traced steps: ``classify_vertex`` (the sweep line reaches the vertex: the
storyboard draws it there), ``handle_start`` … ``handle_regular``, ``add_diagonal``,
``set_helper`` (a vertex becomes the helper of the edge directly left of it: the
storyboard draws the horizontal segment between them), ``monotone_pieces``,
``triangulate_monotone_piece``.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
>>> [classify_vertex(Sweep(p), p.vertex(i)) for i in range(p.n)]
['start', 'regular', 'end', 'start', 'merge']
>>> make_monotone(p)  # the merge vertex E is joined to B, the next vertex below it
[(1, 4)]
>>> monotone(p).triangles
((0, 1, 4), (1, 2, 4), (2, 3, 4))
"""

from __future__ import annotations

import numpy as np

import tracing
from geometry.holes import PolygonWithHoles
from geometry.monotone_pieces import monotone_pieces, triangulate_monotone_piece
from geometry.polygon import Polygon, Vertex
from geometry.results import Triangulation, finished
from geometry.sweep_status import SweepStatus


class Sweep:
    """What the sweep knows: the order of the vertices, their kinds, the status, the diagonals."""

    def __init__(self, polygon: Polygon | PolygonWithHoles) -> None:
        self.polygon = polygon
        arr = np.asarray(polygon.points, dtype=float)
        self.order = np.lexsort((arr[:, 0], -arr[:, 1])).tolist()  # highest first
        self.rank = [0] * polygon.n
        for r, v in enumerate(self.order):
            self.rank[v] = r
        self.turns = polygon.turns.tolist()
        self.next, self.prev = polygon.next_array, polygon.prev_array
        self.kind = [""] * polygon.n
        self.status = SweepStatus(polygon.points, self.next)
        self.diagonals: list[tuple[int, int]] = []


@tracing.traced(exclude_args=("sweep",))
def classify_vertex(sweep: Sweep, v: Vertex) -> str:
    """The line reaches v: start, split, end, merge or regular, from its neighbours' heights."""
    i, rank = v.index, sweep.rank
    before_lower, after_lower = rank[sweep.prev[i]] > rank[i], rank[sweep.next[i]] > rank[i]
    convex = sweep.turns[i] > 0
    if before_lower and after_lower:
        kind = "start" if convex else "split"
    elif not before_lower and not after_lower:
        kind = "end" if convex else "merge"
    else:
        kind = "regular"
    sweep.kind[i] = kind
    return kind


@tracing.traced(exclude_args=("sweep",))
def add_diagonal(sweep: Sweep, u: Vertex, w: Vertex) -> tuple[int, int]:
    """Join u to the helper w: one more cut towards monotone pieces."""
    sweep.diagonals.append((u.index, w.index))
    return (u.index, w.index)


@tracing.traced(exclude_args=("sweep",))
def set_helper(sweep: Sweep, v: Vertex, top: Vertex, bottom: Vertex) -> None:
    """v becomes the helper of edge top–bottom, the edge directly left of it: the lowest
    vertex yet whose horizontal segment to the edge lies inside P."""
    sweep.status.helper[top.index] = v.index


def _helps(sweep: Sweep, v: Vertex, e: int) -> None:
    """v becomes the helper of edge e (from vertex e down to the next), traced with its ends."""
    polygon = sweep.polygon
    set_helper(sweep, v, polygon.vertex(e), polygon.vertex(sweep.next[e]))


def _finish_edge(sweep: Sweep, v: Vertex, e: int) -> None:
    """Edge e ends or gets a new helper at v: a merge-vertex helper is joined to v first."""
    helper = sweep.status.helper[e]
    if sweep.kind[helper] == "merge":
        add_diagonal(sweep, v, sweep.polygon.vertex(helper))


def _end_edge_above(sweep: Sweep, v: Vertex) -> int:
    """The edge from v's predecessor ends at v; where v is in the status."""
    e = sweep.prev[v.index]
    at = sweep.status.find(v.index, own=e)
    _finish_edge(sweep, v, e)
    sweep.status.remove(at, e)
    return at


def _help_edge_left(sweep: Sweep, v: Vertex, at: int) -> None:
    """v, found at ``at``, becomes the helper of the edge directly left of it."""
    left = sweep.status.left(at)
    _finish_edge(sweep, v, left)
    _helps(sweep, v, left)


@tracing.traced(exclude_args=("sweep",))
def handle_start(sweep: Sweep, v: Vertex) -> None:
    sweep.status.insert(sweep.status.find(v.index), v.index, helper=v.index)


@tracing.traced(exclude_args=("sweep",))
def handle_end(sweep: Sweep, v: Vertex) -> None:
    _end_edge_above(sweep, v)


@tracing.traced(exclude_args=("sweep",))
def handle_split(sweep: Sweep, v: Vertex) -> None:
    at = sweep.status.find(v.index)
    left = sweep.status.left(at)
    add_diagonal(sweep, v, sweep.polygon.vertex(sweep.status.helper[left]))
    _helps(sweep, v, left)
    sweep.status.insert(at, v.index, helper=v.index)


@tracing.traced(exclude_args=("sweep",))
def handle_merge(sweep: Sweep, v: Vertex) -> None:
    _help_edge_left(sweep, v, _end_edge_above(sweep, v))


@tracing.traced(exclude_args=("sweep",))
def handle_regular(sweep: Sweep, v: Vertex) -> None:
    i = v.index
    e = sweep.prev[i]
    if sweep.rank[e] < sweep.rank[i]:  # coming down a left side: inside on the right
        at = sweep.status.find(i, own=e)
        _finish_edge(sweep, v, e)
        sweep.status.replace(at, e, i, helper=i)
    else:
        _help_edge_left(sweep, v, sweep.status.find(i))


HANDLERS = {
    "start": handle_start,
    "end": handle_end,
    "split": handle_split,
    "merge": handle_merge,
    "regular": handle_regular,
}


@tracing.traced
def make_monotone(polygon: Polygon | PolygonWithHoles) -> list[tuple[int, int]]:
    """The sweep: diagonals that cut the polygon into y-monotone pieces."""
    sweep = Sweep(polygon)
    for i in sweep.order:
        v = polygon.vertex(i)
        HANDLERS[classify_vertex(sweep, v)](sweep, v)
    return sweep.diagonals


@tracing.traced(name="monotone")
def monotone(polygon: Polygon | PolygonWithHoles) -> Triangulation:
    """Cut into y-monotone pieces, then triangulate each piece with a stack.

    Holes need nothing more: kept clockwise, each hole's top vertex is a split
    vertex and its bottom one a merge vertex, so the diagonals join every hole
    to the rest and each piece is a y-monotone polygon without holes.
    """
    diagonals = make_monotone(polygon)
    triangles = []
    for piece in monotone_pieces(polygon, diagonals):
        with tracing.alive(piece):  # drawn while the stack triangulates it
            triangles.extend(triangulate_monotone_piece(polygon, piece))
    return finished(triangles, steps=len(diagonals), diagonals=len(diagonals))
