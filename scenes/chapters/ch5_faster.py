"""Lecture chapter 5: Faster algorithms.

Run: ``manim -pql scenes/chapters/ch5_faster.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.figures import Figure
from metaphors.lecture import Card, Compare, LectureScene, Run


class Faster(LectureScene):
    chapter_title = "5. Faster algorithms"
    slug = "faster"

    def chapter_segments(self) -> tuple:
        return (
            Card("Garey, Johnson, Preparata, Tarjan (1978)", (
                "Cut the polygon into y-monotone pieces in O(n log n);",
                "a stack triangulates each piece in linear time: O(n log n) in all.",
                "The sweep shown, with split and merge vertices, is the textbooks' later telling."),
                 Figure("monotone-pieces")),
            Run("monotone", None, "Monotone partition, then the stack", speed=0.7),
            Card("Tarjan and van Wyk (1988), Chazelle (1991)", (
                "O(n log log n) time: Tarjan and van Wyk, with finger trees and Jordan sorting;",
                "Kirkpatrick, Klawe and Tarjan matched it with simple data structures (1990).",
                "Chazelle: O(n), famously hard to implement; no implementation is known to be "
                "practical.",
                "Neither is implemented here: the dashed lines are bounds, not measurements."),
                 Figure("measured")),
            # one sentence a bullet; libraries by their own names (Shapely, Mapbox's earcut)
            Card("Constrained Delaunay", (
                "It keeps the polygon's edges, and each triangle's circumcircle holds no "
                "vertex seen from inside the triangle.",
                "Our reference here: GEOS, through Shapely.",
                "Mapbox's earcut, another library, clips ears instead."),
                 Figure("delaunay-circle")),
            Compare(None),
        )
