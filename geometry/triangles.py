"""The common ending of every triangulation algorithm: triangles in canonical form.

Each algorithm finds its triangles in its own order; the result lists them as
divide-and-conquer does: counter-clockwise index triples, each rotated to
start at its smallest index, sorted. (The order in which they were found is in
the trace log.)

>>> finished([(4, 0, 1), (2, 3, 4), (1, 2, 4)], steps=3).triangles
[(0, 1, 4), (1, 2, 4), (2, 3, 4)]
"""

from __future__ import annotations

from collections.abc import Iterable

from geometry.polygon import Vertex
from geometry.triangulate import Triangle, Triangulation

Corners = tuple[Vertex, Vertex, Vertex]


def canonical(tri: Triangle) -> Triangle:
    """The same counter-clockwise triple, rotated to start at its smallest index.

    >>> canonical((5, 2, 7))
    (2, 7, 5)
    """
    a, b, c = tri
    if a < b and a < c:
        return (a, b, c)
    if b < c:
        return (b, c, a)
    return (c, a, b)


def indices(corners: Corners) -> Triangle:
    """The index triple of a triangle given by its corner vertices."""
    a, b, c = corners
    return (a.index, b.index, c.index)


def finished(triangles: Iterable[Triangle], steps: int = 0, **extra) -> Triangulation:
    """A complete (``valid``) triangulation from counter-clockwise triples."""
    return Triangulation(sorted(canonical(t) for t in triangles), True, steps=steps, extra=extra)
