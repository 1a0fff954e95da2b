"""The edges to draw red on an invalid polygon: those that cross, touch or overlap another.

The validator names the first defect it meets in words; the page also wants every edge
involved, as index pairs into the input's own order (the rings concatenated, outer ring
first), even when cleaning would drop repeated points. Shapely's STRtree finds the pairs of
edges that meet; two edges that follow each other on a ring always share their common
vertex, so they count only when they share more (a fold-back).

>>> bow = [[[0, 0], [4, 4], [4, 0], [0, 4]]]
>>> offending_edges(bow)
[[0, 1], [2, 3]]
>>> offending_edges([[[0, 0], [4, 0], [4, 4], [0, 4]]])
[]
"""

from __future__ import annotations

import shapely

MAX_SHOWN = 200
"""At most this many red edges: a scribble has quadratically many contacts."""


def _ring_edges(rings: list[list[list[float]]]) -> list[tuple[int, int, int, int]]:
    """(ring, position on the ring's edge list, start index, end index) of every edge of
    non-zero length, indices into the concatenated input."""
    edges: list[tuple[int, int, int, int]] = []
    offset = 0
    for k, ring in enumerate(rings):
        m = len(ring)
        for i in range(m):
            j = (i + 1) % m
            if ring[i] != ring[j]:
                edges.append((k, len(edges), offset + i, offset + j))
        offset += m
    return edges


def _adjacent(e: tuple[int, int, int, int], f: tuple[int, int, int, int],
              ring_size: dict[int, tuple[int, int]]) -> bool:
    """Whether two edges follow each other on their ring (zero-length edges skipped)."""
    if e[0] != f[0]:
        return False
    first, count = ring_size[e[0]]
    a, b = e[1] - first, f[1] - first
    return (b - a) % count in (1, count - 1)


def offending_edges(rings: list[list[list[float]]]) -> list[list[int]]:
    """Every edge that meets another one where it should not, sorted, as ``[i, j]``."""
    edges = _ring_edges(rings)
    if len(edges) < 2:
        return []
    ring_size: dict[int, tuple[int, int]] = {}
    for e in edges:
        first, count = ring_size.get(e[0], (e[1], 0))
        ring_size[e[0]] = (first, count + 1)
    points = [p for ring in rings for p in ring]
    lines = shapely.linestrings([[points[e[2]], points[e[3]]] for e in edges])
    left, right = shapely.STRtree(lines).query(lines, predicate="intersects")
    bad: set[int] = set()
    for p, q in zip(left.tolist(), right.tolist(), strict=True):
        if p >= q or (p in bad and q in bad):
            continue
        if (_adjacent(edges[p], edges[q], ring_size)
                and shapely.intersection(lines[p], lines[q]).length == 0):
            continue  # just their common vertex
        bad.update((p, q))
    return [[edges[k][2], edges[k][3]] for k in sorted(bad)[:MAX_SHOWN]]
