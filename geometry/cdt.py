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
from geometry.holes import PolygonWithHoles
from geometry.polygon import Polygon
from geometry.predicates import orient
from geometry.results import Triangle, Triangulation, canonical, finished


def shapely_polygon(polygon: Polygon | PolygonWithHoles) -> shapely.Polygon:
    """The same polygon (its holes as interior rings) for shapely."""
    if not polygon.hole_count:
        return shapely.Polygon(polygon.points)
    rings = [polygon.points[r.start:r.stop] for r in map(polygon.ring, range(polygon.hole_count + 1))]
    return shapely.Polygon(rings[0], rings[1:])


def constrained_delaunay(polygon: Polygon | PolygonWithHoles) -> list[Triangle]:
    """Triangles as counter-clockwise index triples, sorted, in this polygon's indexing.

    GEOS keeps every input vertex (collinear ones too) and adds none, so each
    triangle corner is an exact copy of one of our vertices (the rings of a
    polygon with holes share no point, so the copy names one vertex).
    """
    index = {p: i for i, p in enumerate(polygon.points)}
    result = shapely.constrained_delaunay_triangles(shapely_polygon(polygon))
    triangles = []
    for tri in shapely.get_parts(result):
        a, b, c = (index[(float(x), float(y))] for x, y in tri.exterior.coords[:3])
        if orient(polygon.points[a], polygon.points[b], polygon.points[c]) < 0:
            b, c = c, b  # GEOS may give a triangle clockwise
        triangles.append(canonical((a, b, c)))
    return sorted(triangles)


@tracing.traced(name="cdt")
def cdt(polygon: Polygon | PolygonWithHoles) -> Triangulation:
    """The reference as a triangulation algorithm: shapely's (GEOS) constrained Delaunay."""
    return finished(constrained_delaunay(polygon))
