"""A heuristic the lecture does not cover: from B, the candidate nearest to C.

``trex hunt examples/nearest_to_c.py:nearest_to_c`` finds a polygon where it fails; the
lecture's exercises chapter hunts for one at build time (seed 0) and plays it.
"""

import math

import tracing
from geometry.frame import candidates_in_triangle, leftmost_vertex, triangle_at


@tracing.traced
def distance_to_c(c, d):
    """How far candidate D is from C."""
    return math.dist(c.point, d.point)


def nearest_to_c(polygon):
    """Claim BD for the candidate D nearest to C.

    Pseudocode:
        B = the left-most vertex; T = ABC   [leftmost_vertex, triangle_at]
        candidates: the vertices inside T   [candidates_in_triangle]
        none: claim AC                      [claim]
        D = the candidate nearest to C      [distance_to_c]
        claim BD                            [claim]
    """
    b = leftmost_vertex(polygon)
    t = triangle_at(polygon, b)
    with tracing.alive(t):
        candidates = candidates_in_triangle(polygon, t)
        if not candidates:
            return t.a, t.c
        return b, min(candidates, key=lambda d: distance_to_c(t.c, d))
