"""Lecture chapter 2: Inner diagonals: water, clock, sweep.

Run: ``manim -pql scenes/chapters/ch2_heuristics.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import Card, LectureScene, Run
from story.registry import entry
from story.runs import working_example

#: The wrong heuristic of each metaphor, told in three cards: the metaphor, why it fails, and
#: why its correction (the registry's) holds. The family is named after the metaphor.
FAMILIES = (
    ("scaling",
     ("Spill water at B: it spreads as a growing circle.",
      "The first candidate it wets is D, the nearest one."),
     ("The circle grows through the walls of the polygon:",
      "it wets D from outside, before any water could get there from inside.",
      "The edge E–A lies between B and D."),
     ("Go backwards: let water rise from the shore AC towards B.",
      "The last dry candidate is the farthest from AC — always an inner diagonal:",
      "below that level nothing blocks the way from B.")),
    ("rotation",
     ("Put a clock at B, set the hand to A and let it turn towards C.",
      "The first candidate the hand passes is D."),
     ("Part of the hand lies outside the polygon when it passes D:",
      "that outside part hits D first. The hand is not inside T all the time."),
     ("Move the clock to C and set it to B.",
      "Before any part of the hand inside T leaves the polygon, it must pass a vertex:",
      "the first one forms an inner diagonal with B.")),
    ("translation",
     ("Sweep a vertical line from B to the right.",
      "The first candidate it touches is D, the left-most."),
     ("The vertical line leaves the polygon at A's side before it reaches D:",
      "the part outside the polygon touches D first."),
     ("Sweep a line parallel to AC instead.",
      "It reaches A and C at the same moment it leaves T,",
      "so the first vertex it touches is a candidate, seen from inside.")),
)



def family_segments(family: tuple) -> tuple:
    wrong, metaphor, analysis, correction = family
    known = entry(wrong)
    if known.correct or known.correction is None:
        raise ValueError(f"{wrong} is no wrong heuristic with a correction")
    name, right = known.metaphor.capitalize(), known.correction
    return (
        Card(f"{name}: the metaphor", metaphor),
        Run(wrong, working_example(wrong), f"{wrong} on a polygon where it happens to work"),
        Run(wrong, "counterexample", f"{wrong} on the counterexample"),
        Card(f"{name}: why it fails", analysis),
        Run(right, "counterexample", f"{right}: the correction"),
        Card(f"{name}: why the correction holds", correction),
    )


class Heuristics(LectureScene):
    chapter_title = "2. Inner diagonals: water, clock, sweep"
    slug = "heuristics"

    def chapter_segments(self) -> tuple:
        frame = Card("The frame every heuristic shares", (
            "B: the left-most vertex (lowest on ties) — always convex.",
            "A and C: its neighbours; T = triangle ABC.",
            "No other vertex in T: AC is an inner diagonal. Otherwise pick a candidate D: is BD?"))
        return (frame, *[s for family in FAMILIES for s in family_segments(family)])
