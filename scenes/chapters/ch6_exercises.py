"""Lecture chapter 6: Exercises.

Run: ``manim -pql scenes/chapters/ch6_exercises.py``; the whole lecture: ``trex lecture``.
"""

from pathlib import Path

from metaphors.figures import Figure
from metaphors.lecture import Card, Hunted, LectureScene, Quiz

#: a rule the lecture does not cover, from the examples (a heuristic of one's own)
NEAREST_TO_C = f"{Path(__file__).resolve().parents[2] / 'examples' / 'nearest_to_c.py'}:nearest_to_c"


class Exercises(LectureScene):
    chapter_title = "6. Exercises"
    slug = "exercises"

    def chapter_segments(self) -> tuple:
        return (
            # each line says what the figure draws as it comes in (the figure's "Convex" and
            # "Reflex" stood unspoken of), and what the class does, not how the answer is made;
            # on the lecture's polygon, the frame chapter 2 drew (on the counterexample's
            # thin T, D's label stood across T's side from D)
            Card("Exercises", (
                "Each question shows a polygon, its left-most vertex B, its triangle T = ABC "
                "and each candidate in T.",
                "Answer before the countdown reaches 0; then the answer is drawn on the "
                "picture."),
                 Figure("frame")),
            Quiz(count=3, seed=2022),
            Hunted(NEAREST_TO_C, "Found by the computer", "From B, claim the candidate nearest to C",
                   name="Nearest to C", why="{pick} is nearer to C than {others}",
                   figure=Figure("rule", heuristic=NEAREST_TO_C)),
        )
