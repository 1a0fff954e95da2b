"""Lecture chapter 1: Overview.

Run: ``manim -pql scenes/chapters/ch1_overview.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.figures import Figure
from metaphors.lecture import Card, LectureScene, Run
from story.storyboard import Pacing


class Overview(LectureScene):
    chapter_title = "1. Overview"
    slug = "overview"

    def chapter_segments(self) -> tuple:
        return (
            Card("Triangulating a simple polygon", (
                "A simple polygon: its edges meet only where neighbours share a vertex.",
                "A diagonal joins two vertices that are not neighbours.",
                "An inner diagonal lies inside, touching the boundary only at its two ends.",
                "n vertices: n − 2 triangles and n − 3 diagonals (angles: (n − 2) · 180°)."),
                 Figure("triangulation")),
            Card("Lennes, 1911: divide and conquer", (
                "Find an inner diagonal, split the polygon along it, repeat on both halves.",
                "Each diagonal takes O(n) steps, and n − 3 are needed: O(n²) in all.",
                "Everything hinges on one question: how do we find an inner diagonal?"),
                 Figure("diagonal")),
            # the diagonal finder a black box: no heuristic is taught yet (issue 22 item 2);
            # gravity answers it, unseen, as it is correct on every polygon
            Run("divide-and-conquer", None,
                "Lennes' divide and conquer: ask for an inner diagonal, split, repeat",
                heuristic="gravity", black_box=True, pacing=Pacing(full=4, fast=0.35),
                speed=1.0),
        )
