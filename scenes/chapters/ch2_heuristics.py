"""Lecture chapter 2: Inner diagonals: water, clock, sweep.

Run: ``manim -pql scenes/chapters/ch2_heuristics.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import LectureScene


class Heuristics(LectureScene):
    chapter_title = "2. Inner diagonals: water, clock, sweep"
    slug = "heuristics"
