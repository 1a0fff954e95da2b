"""Lecture chapter 6: Experience.

Run: ``manim -pql scenes/chapters/ch6_experience.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.lecture import Card, LectureScene


class Experience(LectureScene):
    chapter_title = "6. Experience"
    slug = "experience"

    def chapter_segments(self) -> tuple:
        return (
            Card("Teaching notes: the wrong heuristics first", (
                "Let students propose a way to find D before showing any.",
                "Almost everyone proposes the nearest or the left-most vertex.",
                "The counterexample needs only five vertices: draw it on the board.")),
            Card("Teaching notes: metaphors", (
                "Water, a clock, a sweeping line: each wrong heuristic is a familiar motion.",
                "Ask where the motion leaves the polygon — that is the bug.",
                "The corrections move only inside T, up to the first candidate: inside P.")),
            Card("Teaching notes: from metaphor to proof", (
                "Kinesthetic heuristics are fast to invent and easy to get wrong.",
                "Ask for the invariant: what does the water, hand or line never cross?",
                "Then write the proof with that invariant.")),
        )
