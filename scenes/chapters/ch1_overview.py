"""Lecture chapter 1: Overview.

The problem, each word drawn as it is said: a diagonal, inner or not (one leaving P across an
edge, one through a vertex); a triangulation (the thesis's Definition 5) and why it has n − 2
triangles, the numbers after the rule; then Lennes' divide and conquer, its diagonal finder a
black box, run once on the lecture's polygon (the cards draw no step the run plays again).

Run: ``manim -pql scenes/chapters/ch1_overview.py``; the whole lecture: ``trex lecture``.
"""

from geometry.io import read_polygon
from metaphors.figures import Figure, overview_examples
from metaphors.lecture import Card, LectureScene, Run
from story.storyboard import Pacing


def diagonal_lines(polygon: str) -> tuple[str, ...]:
    """The definitions card's lines, naming the figure's own diagonals
    (:func:`metaphors.figures.overview_examples`); a line for each kind P has."""
    inner, leaving, edge, through, vertex = overview_examples(polygon)
    if not inner:  # a triangle
        return ("A simple polygon: its edges meet only where neighbours share a vertex.",
                "A diagonal joins two vertices that are not neighbours: a triangle has none.")
    return ("A simple polygon: its edges meet only where neighbours share a vertex.",
            f"A diagonal joins two vertices that are not neighbours, as {inner} does.",
            f"{inner} is an inner diagonal: inside P, touching its boundary only at its ends.",
            *([f"{leaving} is not: it leaves P, crossing edge {edge}."] if leaving else []),
            *([f"Nor is {through}: it passes through vertex {vertex}."] if through else []))


def triangulation_lines(polygon: str) -> tuple[str, ...]:
    """The triangulation card's lines: the thesis's definition, why n − 2 (a cut counts its
    two ends twice; by induction), then this P's numbers, after the rule."""
    n = read_polygon(polygon).n
    inner = overview_examples(polygon)[0]
    why = ((f"Why n − 2? An inner diagonal, as {inner}, cuts P in two: "
            "n₁ + n₂ = n + 2 vertices, its ends in both.",
            "By induction: (n₁ − 2) + (n₂ − 2) = n − 2 triangles, cut by n − 3 diagonals.")
           if inner else ())
    return ("A triangulation of P: triangles with corners at P's vertices, not overlapping, "
            "that make up P.", *why,
            f"Here n = {n}: {n - 2} triangle{'s' * (n > 3)} and {n - 3} diagonal"
            f"{'s' * (n != 4)}.")


class Overview(LectureScene):
    chapter_title = "1. Overview"
    slug = "overview"

    def chapter_segments(self) -> tuple:
        polygon = self.lecture_polygon()
        return (
            Card("Diagonals of a simple polygon", diagonal_lines(polygon),
                 Figure("definitions")),
            Card("Triangulation: n − 2 triangles", triangulation_lines(polygon),
                 Figure("why-n-2")),
            # the proof is the algorithm; the question the rest of the lecture answers comes
            # with the black box the run asks (the card split along DG, then the run did again)
            Card("Lennes, 1911: divide and conquer", (
                "The proof is an algorithm: find an inner diagonal, cut P along it, repeat on "
                "both parts.",
                "n − 3 diagonals, each found in O(n) steps: O(n²) in all.",
                "Everything hinges on one question: how do we find an inner diagonal?"),
                 Figure("question")),
            # the diagonal finder a black box: no heuristic is taught yet (issue 22 item 2);
            # gravity answers it, unseen, as it is correct on every polygon
            Run("divide-and-conquer", None,
                "Lennes' divide and conquer: ask for an inner diagonal, split, repeat",
                heuristic="gravity", black_box=True, pacing=Pacing(full=4, fast=0.35),
                speed=1.0),
        )
