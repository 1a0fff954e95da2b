"""Lecture chapter 6: Experience.

Run: ``manim -pql scenes/chapters/ch6_experience.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import LectureScene


class Experience(LectureScene):
    chapter_title = "6. Experience"
    slug = "experience"
