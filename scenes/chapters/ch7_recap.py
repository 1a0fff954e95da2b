"""Lecture chapter 7: Recap.

Run: ``manim -pql scenes/chapters/ch7_recap.py``; the whole lecture: ``trex lecture``.
"""

from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from metaphors.figures import Figure
from metaphors.lecture import Card, LectureScene
from story.registry import spoken
from story.words import why_not_inner

#: the rules the lecture showed failing and holding, on the thesis's 5-vertex polygon
FAILING = ("scaling", "rotation", "translation")
HOLDING = ("scaling-correct", "rotation-correct", "translation-correct")
POLYGON = "counterexample"


def _claim(heuristic: str) -> tuple[str, str]:
    """The rule's claim on the counterexample, and why it is not inner ('' if it is)."""
    polygon = read_polygon(POLYGON)
    claim = find_diagonal(polygon, heuristic)
    verdict = is_inner_diagonal(polygon, *claim.pair)
    return claim.name, "" if verdict.ok else why_not_inner(verdict, polygon.labels, claim.name)


def _names(heuristics: tuple[str, ...], first: bool = False) -> str:
    said = [spoken(h, first=first) for h in heuristics]
    return ", ".join(said[:-1]) + " and " + said[-1]


class Recap(LectureScene):
    chapter_title = "7. Recap"
    slug = "recap"

    def chapter_segments(self) -> tuple:
        wrong_claim, why = _claim(FAILING[0])
        right_claim, _ = _claim(HOLDING[0])
        gravity_claim, gravity_why = _claim("gravity")  # drawn in the figure beside theirs
        assert not gravity_why, "Gravity fails on the counterexample"
        assert all(_claim(h)[0] == wrong_claim for h in FAILING), "the failing rules differ"
        assert all(_claim(h) == (right_claim, "") for h in HOLDING), "the holding rules differ"
        return (
            Card("Recap: the rules that fail", (
                f"{_names(FAILING, first=True)} all claim {wrong_claim}, which is not inner.",
                f"{why}: one polygon of five vertices defeats all three.",
                "Their motion leaves P before it reaches the vertex it picks."),
                Figure("claims", POLYGON, heuristics=()),
                line_figures=(Figure("claims", POLYGON, heuristics=FAILING),)),
            Card("Recap: the rules that hold", (
                f"{_names(HOLDING)} claim {right_claim}, inside P.",
                "Their motion stays inside T until it meets the first candidate.",
                f"Gravity claims {gravity_claim}: its ball and band never leave P."),
                # P alone, then each claim with the line that says it, one at a time: BE
                # and EC both hug B–C and would read as one path
                Figure("claims", POLYGON, heuristics=()),
                line_figures=(Figure("claims", POLYGON, heuristics=HOLDING), None,
                              Figure("claims", POLYGON, heuristics=("gravity",)))),
            Card("Recap: the algorithms", (
                # each named as its picture's legend names it (one name for one method)
                f"{spoken('divide-and-conquer', start=True)}: O(n) per diagonal, "
                "n − 3 diagonals: O(n²).",
                f"{spoken('ear-clipping', start=True)}, each vertex's ear status kept: O(n²).",
                f"{spoken('monotone', start=True)}, each piece cut with a stack: O(n log n). "
                "Chazelle: O(n), not practical."),
                Figure("three-triangulations")),
        )
