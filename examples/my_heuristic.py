"""A heuristic of my own: from B, take the candidate with the largest angle ABD.

    trex diagonal --heuristic examples/my_heuristic.py:biggest_angle counterexample
    trex render examples/my_heuristic.py:biggest_angle

Right on the counterexample; try it on counterexample-twin too.
"""

import math

import tracing
from geometry.frame import candidates_in_triangle, leftmost_vertex, triangle_at


@tracing.traced
def angle_at_b(b, a, d):
    """The angle ABD in degrees: how far B has to turn from A to look at D."""
    ax, ay = a.point[0] - b.point[0], a.point[1] - b.point[1]
    dx, dy = d.point[0] - b.point[0], d.point[1] - b.point[1]
    return round(abs(math.degrees(math.atan2(ax * dy - ay * dx, ax * dx + ay * dy))), 1)


def biggest_angle(polygon):
    """Claim BD for the candidate D with the largest angle ABD."""
    b = leftmost_vertex(polygon)
    t = triangle_at(polygon, b)
    with tracing.alive(t):
        candidates = candidates_in_triangle(polygon, t)
        if not candidates:
            return t.a, t.c
        best = candidates[0]
        widest = angle_at_b(b, t.a, best)
        with tracing.Shape("best", "segment", points=[b.point, best.point]) as arm:
            for d in candidates[1:]:
                angle = angle_at_b(b, t.a, d)
                if angle > widest:
                    best, widest = d, angle
                    arm.update(points=[b.point, best.point])
        return b, best
