"""The corrected heuristics, each succeeding where its wrong version fails (thesis ch. 2.1.2).

Run: ``manim -pql scenes/corrections.py TranslationCorrect`` (or ``ScalingCorrect``,
``RotationCorrect``, ``ScalingWalled``); ``TREX_POLYGON=<file or sample>`` picks the polygon.
"""

from metaphors.scene import TraceScene


class TranslationCorrect(TraceScene):
    algorithm = "translation-correct"
    polygon = "counterexample"
    title = "Correct translation: a line parallel to AC swept from B"


class ScalingCorrect(TraceScene):
    algorithm = "scaling-correct"
    polygon = "counterexample"
    title = "Correct scaling: water rises from AC; the last dry candidate"


class RotationCorrect(TraceScene):
    algorithm = "rotation-correct"
    polygon = "counterexample"
    title = "Correct rotation: the clock moves to C, set to B"


class ScalingWalled(TraceScene):
    algorithm = "scaling-walled"
    polygon = "counterexample"
    title = "Scaling with walls: water that cannot pass the edges"
