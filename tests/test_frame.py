"""The frame's candidates: every vertex other than A, B, C in the closed triangle T, exactly
(the bounding-box shortcut drops none, on vertices on T's edges and corners too)."""

from __future__ import annotations

from hypothesis import given, settings

from geometry.frame import candidates_in_triangle, leftmost_vertex, triangle_at
from geometry.polygon import Polygon
from geometry.predicates import in_triangle
from tests.strategies import generated_polygons


def brute_force(polygon: Polygon) -> list[str]:
    t = triangle_at(polygon, leftmost_vertex(polygon))
    corners = (t.a.point, t.b.point, t.c.point)
    order = [(t.b.index + k) % polygon.n for k in range(2, polygon.n - 1)]
    return [polygon.labels[i] for i in order if in_triangle(polygon.points[i], *corners)]


@settings(max_examples=200, deadline=None)
@given(generated_polygons())
def test_candidates_are_every_vertex_in_t(polygon):
    t = triangle_at(polygon, leftmost_vertex(polygon))
    assert [v.label for v in candidates_in_triangle(polygon, t)] == brute_force(polygon)


def test_a_vertex_on_ts_edge_is_a_candidate():
    # (4, 1) lies on AC, the edge of T opposite B, at the edge of T's bounding box too
    polygon = Polygon.from_points([(0, 0), (4, -2), (4, 1), (4, 4)])
    t = triangle_at(polygon, leftmost_vertex(polygon))
    assert [v.point for v in candidates_in_triangle(polygon, t)] == [(4.0, 1.0)]
