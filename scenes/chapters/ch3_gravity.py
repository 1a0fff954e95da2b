"""Lecture chapter 3: Gravity.

Run: ``manim -pql scenes/chapters/ch3_gravity.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.figures import Figure
from metaphors.lecture import Analysis, Card, LectureScene, Run


class Gravity(LectureScene):
    chapter_title = "3. Gravity"
    slug = "gravity"

    def chapter_segments(self) -> tuple:
        return (
            Card("Gravity (Forišek and Steinová)", (
                "Hang a ball on a rubber band at a reflex vertex V.",
                "Turn P so that both edges at V point up and no edge is level; drop the ball.",
                "It hits an edge and slides down to a vertex X; the band may snag a vertex Y.",
                "Claim VY where the band snags, else VX: an inner diagonal either way."),
                 Figure("gravity", "gravity-snag")),
            Run("gravity", "gravity-snag", "Gravity: the band snags a vertex"),
            # on the run's last picture: what the band swept, shaded as it swept, turns green
            Analysis("gravity", "gravity-snag", title="Gravity: why the band is always right",
                     holds="The band sweeps only the inside of P: it touches {pick} from "
                           "inside, so {claim} is inner.", on_run=True),
            Run("gravity", "counterexample", "Gravity on the counterexample"),
        )
