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
            Card("Exercises", (
                "Each question shows a polygon and its triangle T.",
                "Answer before the countdown ends; the answer is checked by the geometry code."),
                 Figure("frame", "counterexample")),
            Quiz(count=3, seed=2022),
            Hunted(NEAREST_TO_C, "Found by the computer", "From B, claim the candidate nearest to C",
                   figure=Figure("rule", heuristic=NEAREST_TO_C)),
        )
