"""The reference triangulation: shapely's constrained Delaunay, mapped back to vertex indices.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (2, 0), (2, 2), (0, 2)])
>>> constrained_delaunay(p)
[(0, 1, 2), (0, 2, 3)]
"""

from __future__ import annotations

import shapely

from geometry.polygon import Polygon
from geometry.predicates import orient


def constrained_delaunay(polygon: Polygon) -> list[tuple[int, int, int]]:
    """Triangles as counter-clockwise index triples, sorted, in this polygon's indexing.

    GEOS keeps every input vertex (collinear ones too) and adds none, so each
    triangle corner is an exact copy of one of our vertices.
    """
    index = {p: i for i, p in enumerate(polygon.points)}
    result = shapely.constrained_delaunay_triangles(shapely.Polygon(polygon.points))
    triangles = []
    for tri in shapely.get_parts(result):
        corners = [index[(float(x), float(y))] for x, y in tri.exterior.coords[:3]]
        triangles.append(_ccw_rotation(polygon, corners))
    return sorted(triangles)


def _ccw_rotation(polygon: Polygon, corners: list[int]) -> tuple[int, int, int]:
    """Counter-clockwise order starting at the smallest index (a canonical form)."""
    a, b, c = corners
    if orient(polygon.points[a], polygon.points[b], polygon.points[c]) < 0:
        b, c = c, b
    k = min(range(3), key=lambda i: (a, b, c)[i])
    tri = (a, b, c)
    return tri[k:] + tri[:k]
