"""Lecture chapter 5: Faster algorithms.

Run: ``manim -pql scenes/chapters/ch5_faster.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import LectureScene


class Faster(LectureScene):
    chapter_title = "5. Faster algorithms"
    slug = "faster"
