"""The region visible from a vertex: for drawing water that respects the walls.

A drawing aid, not a decision: which vertex B sees is decided exactly by
:func:`geometry.check.is_inner_diagonal`. The region is traced by rays from the
vertex towards every other vertex and just past it on both sides (±1e-7 rad);
the nearest boundary hit of each ray, in angular order, outlines the region.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
>>> round(visible_region(p, p.label_of("B")).area, 6) == round(p.area, 6)
False
>>> round(visible_region(p, p.label_of("E")).area, 3) == round(p.area, 3)
True
"""

from __future__ import annotations

import math

import shapely

from geometry.polygon import Polygon
from geometry.predicates import Point

_TURN = 1e-7


def visible_region(polygon: Polygon, i: int) -> shapely.Polygon:
    """The part of the polygon seen from vertex i, as a shapely polygon (for drawing)."""
    origin = polygon.points[i]
    boundary = shapely.LinearRing(polygon.points)
    reach = 4 * max(math.dist(origin, q) for q in polygon.points)
    base = _angle(origin, polygon.points[polygon.next(i)])
    hits = []
    for k, q in enumerate(polygon.points):
        if k == i:
            continue
        theta = _angle(origin, q)
        for turn in (-_TURN, 0.0, _TURN):
            hit = _first_hit(boundary, origin, theta + turn, reach)
            if hit is not None:
                hits.append(((theta + turn - base) % (2 * math.pi), hit))
    hits.sort()
    ring = [origin] + [h for _, h in hits]
    region = shapely.Polygon(ring).buffer(0)
    return region.intersection(shapely.Polygon(polygon.points))


def _angle(p: Point, q: Point) -> float:
    return math.atan2(q[1] - p[1], q[0] - p[0])


def _first_hit(
    boundary: shapely.Geometry, origin: Point, theta: float, reach: float
) -> Point | None:
    far = (origin[0] + reach * math.cos(theta), origin[1] + reach * math.sin(theta))
    crossing = boundary.intersection(shapely.LineString([origin, far]))
    points = [p for g in shapely.get_parts(crossing) for p in _coords(g)]
    points = [p for p in points if math.dist(p, origin) > 1e-9 * reach]
    return min(points, key=lambda p: math.dist(p, origin)) if points else None


def _coords(g: shapely.Geometry) -> list[tuple[float, float]]:
    return [(c[0], c[1]) for c in g.coords]
