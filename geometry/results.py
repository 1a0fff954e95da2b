"""What a triangulation algorithm returns: triangles in canonical form, or why it stopped.

Each algorithm finds its triangles in its own order; the result lists them all
the same way: counter-clockwise index triples, each rotated to start at its
smallest index (:func:`canonical`), sorted. (The order in which they were
found is in the trace log.) This module imports no algorithm, so every
algorithm and the dispatcher :mod:`geometry.triangulate` can import it.

>>> finished([(4, 0, 1), (2, 3, 4), (1, 2, 4)], steps=3).triangles
((0, 1, 4), (1, 2, 4), (2, 3, 4))
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

from geometry.check import CheckResult
from geometry.polygon import Vertex

TriangleIndices = tuple[int, int, int]
"""Vertex indices of one triangle, counter-clockwise."""

Corners = tuple[Vertex, Vertex, Vertex]
"""One triangle as its corner vertices, counter-clockwise (what a traced clip returns)."""


@dataclass(frozen=True)
class Triangulation:
    """Triangles as counter-clockwise index triples of the polygon triangulated.

    ``valid`` is False when the algorithm stopped early; then ``failure`` says why
    (in the indices of the whole polygon) and ``claim`` is the bad diagonal.
    ``steps`` counts the algorithm's main steps; ``extra`` holds its own counters.
    """

    triangles: tuple[TriangleIndices, ...]
    valid: bool
    failure: CheckResult | None = None
    claim: tuple[int, int] | None = None
    steps: int = 0
    extra: Mapping[str, int] = field(default_factory=dict)


def canonical(tri: TriangleIndices) -> TriangleIndices:
    """The same counter-clockwise triple, rotated to start at its smallest index.

    The one canonical form of a triangle in this package: results list only these.

    >>> canonical((5, 2, 7))
    (2, 7, 5)
    >>> canonical((7, 5, 2))
    (2, 7, 5)
    """
    a, b, c = tri
    if a < b and a < c:
        return (a, b, c)
    if b < c:
        return (b, c, a)
    return (c, a, b)


def indices(corners: Corners) -> TriangleIndices:
    """The index triple of a triangle given by its corner vertices.

    >>> a, b, c = Vertex(2, "C", (1.0, 0.0)), Vertex(0, "A", (0.0, 1.0)), Vertex(1, "B", (0.0, 0.0))
    >>> indices((a, b, c))
    (2, 0, 1)
    """
    a, b, c = corners
    return (a.index, b.index, c.index)


def finished(triangles: Iterable[TriangleIndices], steps: int = 0, **extra: int) -> Triangulation:
    """A complete (``valid``) triangulation from counter-clockwise triples, in canonical form."""
    return Triangulation(tuple(sorted(canonical(t) for t in triangles)), True, steps=steps, extra=extra)
