"""Lecture chapter 7: Exercises.

Run: ``manim -pql scenes/chapters/ch7_exercises.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import Card, LectureScene, Quiz


class Exercises(LectureScene):
    chapter_title = "7. Exercises"
    slug = "exercises"

    def chapter_segments(self) -> tuple:
        return (
            Card("Exercises", (
                "Each question shows a polygon and its triangle T.",
                "Answer before the countdown ends; the answer is checked by the geometry code.")),
            Quiz(count=3, seed=2022),
        )
