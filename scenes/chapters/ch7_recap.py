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
#: what each wrong rule's tool is, as its line says it
TOOLS = {"scaling": "the water", "rotation": "the hand", "translation": "the line"}
#: the holding rules' pictures, each with its line, in the order their lines say why: the
#: line parallel to AC, the clock at C, the water rising from AC (farthest from AC: that
#: line's first), gravity
WHY_ORDER = ("translation-correct", "rotation-correct", "scaling-correct", "gravity")


def _claim(heuristic: str) -> tuple[str, str]:
    """The rule's claim on the counterexample, and why it is not inner ('' if it is)."""
    polygon = read_polygon(POLYGON)
    claim = find_diagonal(polygon, heuristic)
    verdict = is_inner_diagonal(polygon, *claim.pair)
    return claim.name, "" if verdict.ok else why_not_inner(verdict, polygon.labels, claim.name)


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
        pick = wrong_claim[1]
        return (
            # each wrong rule with the picture of why, one after another on one polygon drawn
            # large: its tool stopped at its pick, its part outside P red (one shared picture
            # of BD crossing E–A stood for all three, their motion never drawn); then their
            # claim, solid red, across the crossed edge, dashed (the same red line before)
            Card("Recap: the rules that fail", (
                *(f"{spoken(h, first=True)}: {TOOLS[h]} leaves P (red) before it reaches "
                  f"{pick}." for h in FAILING),
                f"All three claim {wrong_claim}. {why}: one polygon of five vertices defeats "
                "all three."),
                Figure("failing-motions", POLYGON, heuristics=FAILING)),
            # the thesis's argument (ch. 2): what a correction sweeps in T stays in P until it
            # meets its pick ("inside T" held for the wrong clock hand too)
            Card("Recap: the rules that hold", (
                f"{spoken('translation-correct')} claims {right_claim}: the line parallel to "
                f"AC meets {right_claim[1]} before any part of it in T leaves P.",
                f"{spoken('rotation-correct')} claims {right_claim}: so does the hand of the "
                "clock at C.",
                f"{spoken('scaling-correct')} claims {right_claim}: {right_claim[1]} is the "
                "candidate farthest from AC, the first that line meets.",
                f"Gravity claims {gravity_claim}: its ball and band never leave P."),
                Figure("holding-motions", POLYGON, heuristics=WHY_ORDER)),
            Card("Recap: the algorithms", (
                # each named as its picture's legend names it (one name for one method), said
                # once, under its picture
                f"{spoken('divide-and-conquer', start=True)}: O(n) per diagonal, "
                "n − 3 diagonals: O(n²).",
                f"{spoken('ear-clipping', start=True)}, each vertex's ear status kept: O(n²).",
                f"{spoken('monotone', start=True)}, each piece cut with a stack: O(n log n). "
                "Chazelle: O(n), not practical."),
                Figure("three-triangulations"), layout="columns"),
        )
