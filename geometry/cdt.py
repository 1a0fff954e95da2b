"""The reference triangulation: shapely's constrained Delaunay, mapped back to vertex indices.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (2, 0), (2, 2), (0, 2)])
>>> constrained_delaunay(p)
[(0, 1, 2), (0, 2, 3)]
>>> cdt(p).triangles
[(0, 1, 2), (0, 2, 3)]
"""

from __future__ import annotations

import shapely

import tracing
from geometry.polygon import Polygon
from geometry.predicates import orient
from geometry.results import Triangle, Triangulation, canonical, finished


def constrained_delaunay(polygon: Polygon) -> list[Triangle]:
    """Triangles as counter-clockwise index triples, sorted, in this polygon's indexing.

    GEOS keeps every input vertex (collinear ones too) and adds none, so each
    triangle corner is an exact copy of one of our vertices.
    """
    index = {p: i for i, p in enumerate(polygon.points)}
    result = shapely.constrained_delaunay_triangles(shapely.Polygon(polygon.points))
    triangles = []
    for tri in shapely.get_parts(result):
        a, b, c = (index[(float(x), float(y))] for x, y in tri.exterior.coords[:3])
        if orient(polygon.points[a], polygon.points[b], polygon.points[c]) < 0:
            b, c = c, b  # GEOS may give a triangle clockwise
        triangles.append(canonical((a, b, c)))
    return sorted(triangles)


@tracing.traced(name="cdt")
def cdt(polygon: Polygon) -> Triangulation:
    """The reference as a triangulation algorithm: shapely's (GEOS) constrained Delaunay."""
    return finished(constrained_delaunay(polygon))
