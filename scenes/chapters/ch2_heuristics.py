"""Lecture chapter 2: Inner diagonals: water, clock, sweep.

Run: ``manim -pql scenes/chapters/ch2_heuristics.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.figures import Figure
from metaphors.lecture import Analysis, Card, LectureScene, Run
from story.registry import SPOKEN, entry, spoken
from story.runs import working_example

#: The wrong heuristic of each metaphor: the card of its metaphor, and what its analysis says
#: on the counterexample — as its tool reaches the wrong vertex, and why its correction (the
#: registry's) holds. The family is named after the metaphor.
FAMILIES = (
    ("scaling",
     ("Spill water at B: it spreads as a growing circle.",
      "The first candidate it wets is D, the nearest one."),
     "Red: the water outside P but inside T. It wets {pick} from outside P.",
     "Still dry as {pick} goes under: no vertex, so no wall. {claim} is inside P."),
    ("rotation",
     ("Put a clock at B, set the hand to A and let it turn towards C.",
      "The first candidate the hand passes is D."),
     "Red: the hand outside P. That part passes {pick} first.",
     "From C, the hand meets {pick} before any part of it in T leaves P."),
    ("translation",
     ("Sweep a vertical line from B to the right.",
      "The first candidate it touches is D, the left-most."),
     "Red: the line outside P but inside T. That part touches {pick} first.",
     "Parallel to AC, the line meets {pick} before any part of it in T leaves P."),
)


def family_segments(family: tuple) -> tuple:
    wrong, metaphor, fails, holds = family
    known = entry(wrong)
    if known.correct or known.correction is None:
        raise ValueError(f"{wrong} is no wrong heuristic with a correction")
    # each name said with its picture the first time (its card; the correction's run)
    right, said = known.correction, SPOKEN[wrong]
    return (
        Card(f"{said.name}: {said.picture}", metaphor),
        Run(wrong, working_example(wrong), f"{spoken(wrong)} on a polygon where it happens to "
            "work"),
        Run(wrong, "counterexample", f"{spoken(wrong)} on the counterexample"),
        Analysis(wrong, "counterexample", fails=fails, holds=holds),
        Run(right, "counterexample", f"{spoken(right, first=True)}: the correction"),
    )


class Heuristics(LectureScene):
    chapter_title = "2. Inner diagonals: water, clock, sweep"
    slug = "heuristics"
    teacher_notes = (
        Card("The wrong heuristics first", (
            "Let students propose a way to find D before showing any.",
            "Almost everyone proposes the nearest or the left-most vertex.",
            "The counterexample needs only five vertices: draw it on the board.")),
        Card("Metaphors", (
            "Water, a clock, a sweeping line: each wrong heuristic is a familiar motion.",
            "Ask where the motion leaves the polygon — that is the bug.",
            "The corrections move only inside T, up to the first candidate: inside P.")),
        Card("From metaphor to proof", (
            "Kinesthetic heuristics are fast to invent and easy to get wrong.",
            "Ask for the invariant: what does the water, hand or line never cross?",
            "Then write the proof with that invariant.")),
    )

    def chapter_segments(self) -> tuple:
        frame = Card("The frame every heuristic shares", (
            "B: the left-most vertex (lowest on ties) — always convex: P lies to its right.",
            "A and C: its neighbours; T = triangle ABC.",
            "No other vertex in T: AC is an inner diagonal. Otherwise pick a candidate D: is BD?"),
            Figure("frame"))
        return (frame, *[s for family in FAMILIES for s in family_segments(family)])
