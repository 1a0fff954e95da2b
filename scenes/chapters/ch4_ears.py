"""Lecture chapter 4: Ears.

Run: ``manim -pql scenes/chapters/ch4_ears.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import LectureScene


class Ears(LectureScene):
    chapter_title = "4. Ears"
    slug = "ears"
