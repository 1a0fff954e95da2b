"""Lecture chapter 3: Gravity.

Run: ``manim -pql scenes/chapters/ch3_gravity.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import LectureScene


class Gravity(LectureScene):
    chapter_title = "3. Gravity"
    slug = "gravity"
