"""The reference triangulation: shapely's constrained Delaunay, mapped back to vertex indices.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (2, 0), (2, 2), (0, 2)])
>>> constrained_delaunay(p)
[(0, 1, 2), (0, 2, 3)]
>>> cdt(p).triangles
((0, 1, 2), (0, 2, 3))
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import shapely

import tracing
from geometry.errors import PolygonError
from geometry.holes import PolygonWithHoles
from geometry.polygon import Polygon
from geometry.predicates import Point, orient
from geometry.results import TriangleIndices, Triangulation, canonical, finished


def shapely_polygon(
    polygon: Polygon | PolygonWithHoles, points: Sequence[Point] | None = None
) -> shapely.Polygon:
    """The same polygon (its holes as interior rings) for shapely; ``points``: other
    coordinates for its vertices (scaled ones)."""
    points = polygon.points if points is None else points
    if not isinstance(polygon, PolygonWithHoles) or not polygon.hole_count:  # a Polygon has none
        return shapely.Polygon(points)
    rings = [points[r.start:r.stop] for r in map(polygon.ring, range(polygon.hole_count + 1))]
    return shapely.Polygon(rings[0], rings[1:])


def _scaled_near_one(points: Sequence[Point]) -> list[tuple[float, float]]:
    """The points times the power of two that brings the largest coordinate near 1, when
    they are far from it (GEOS fails on a polygon at 1e±200) and the scaled points stay
    distinct; else the points themselves. A power of two changes no sign of any predicate
    while it scales exactly.

    >>> _scaled_near_one([(0.0, 3e200), (1e200, 0.0)])[0][1] < 4
    True
    >>> _scaled_near_one([(0.5, 2.0)])
    [(0.5, 2.0)]
    """
    biggest = max(abs(c) for point in points for c in point)
    k = math.frexp(biggest)[1] if biggest else 0
    if abs(k) < 64:
        return list(points)
    scaled = [(math.ldexp(x, -k), math.ldexp(y, -k)) for x, y in points]
    # inexact (a tiny coordinate beside a huge one loses bits): still scaled while the points
    # stay apart, since GEOS copies its input's points; the triangles are verified after
    return scaled if len(set(scaled)) == len(scaled) else list(points)


def constrained_delaunay(polygon: Polygon | PolygonWithHoles) -> list[TriangleIndices]:
    """Triangles as counter-clockwise index triples, sorted, in this polygon's indexing.

    GEOS keeps every input vertex (collinear ones too) and adds none, so each
    triangle corner is an exact copy of one of our vertices (the rings of a
    polygon with holes share no point, so the copy names one vertex).
    """
    points = _scaled_near_one(polygon.points)
    index = {p: i for i, p in enumerate(points)}
    try:
        result = shapely.constrained_delaunay_triangles(shapely_polygon(polygon, points))
    except shapely.errors.GEOSException as error:  # GEOS's own limits, on valid input
        low, high = (f(abs(c) for p in polygon.points for c in p if c) for f in (min, max))
        raise PolygonError(f"GEOS cannot triangulate this polygon (coordinates from {low:g} "
                           f"to {high:g}): {str(error).split(': ', 1)[-1]}") from None
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
