"""Lecture chapter 3: Gravity.

Run: ``manim -pql scenes/chapters/ch3_gravity.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import Card, LectureScene, Run


class Gravity(LectureScene):
    chapter_title = "3. Gravity"
    slug = "gravity"

    def chapter_segments(self) -> tuple:
        return (
            Card("Gravity (Forišek and Steinová)", (
                "Hang a ball on a rubber band at a reflex vertex V.",
                "Turn the polygon so that both edges at V point up, and let the ball drop.",
                "It hits an edge and slides down to a vertex X; the band may snag a vertex Y first.")),
            Run("gravity", "gravity-snag", "Gravity: the band snags a vertex"),
            Card("Why the band is always right", (
                "The band stays inside the polygon the whole time:",
                "the first vertex it touches is seen from V through the inside.",
                "So VY — or VX when the band stays straight — is an inner diagonal.")),
            Run("gravity", "counterexample", "Gravity on the counterexample"),
        )
