"""Lecture chapter 1: Overview.

Run: ``manim -pql scenes/chapters/ch1_overview.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import LectureScene


class Overview(LectureScene):
    chapter_title = "1. Overview"
    slug = "overview"
