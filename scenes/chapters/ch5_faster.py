"""Lecture chapter 5: Faster algorithms.

Run: ``manim -pql scenes/chapters/ch5_faster.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import Card, Compare, LectureScene, Run


class Faster(LectureScene):
    chapter_title = "5. Faster algorithms"
    slug = "faster"

    def chapter_segments(self) -> tuple:
        return (
            Card("Garey, Johnson, Preparata, Tarjan (1978)", (
                "Sweep a horizontal line downwards; classify each vertex.",
                "Diagonals at split and merge vertices cut the polygon into y-monotone pieces.",
                "A stack triangulates each piece in linear time: O(n log n) in all.")),
            Run("monotone", None, "Monotone partition, then the stack", speed=0.7),
            Card("Tarjan and van Wyk (1988)", (
                "O(n log log n), with finger trees and Jordan sorting;",
                "Kirkpatrick, Klawe and Tarjan matched it with simple data structures (1990).")),
            Card("Chazelle (1991)", (
                "Linear time: O(n). Correct, celebrated — and famously hard to implement.",
                "No implementation is known to be practical.")),
            Card("Constrained Delaunay", (
                "Delaunay triangulation of the vertices, keeping the polygon's edges:",
                "the reference triangulation libraries use (here: shapely / GEOS).")),
            Compare(None),
        )
