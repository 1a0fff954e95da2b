"""Lecture chapter 7: Exercises.

Run: ``manim -pql scenes/chapters/ch7_exercises.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import LectureScene


class Exercises(LectureScene):
    chapter_title = "7. Exercises"
    slug = "exercises"
