"""The corrected heuristics, each succeeding where its wrong version fails (thesis ch. 2.1.2).

Run: ``manim -pql scenes/corrections.py TranslationCorrect`` (or ``ScalingCorrect``,
``RotationCorrect``, ``ScalingWalled``); ``TREX_POLYGON=<file or sample>`` picks the polygon.
"""

from metaphors.scene import TraceScene
from story.registry import entry


class TranslationCorrect(TraceScene):
    algorithm = "translation-correct"
    polygon = "counterexample"
    title = entry("translation-correct").title


class ScalingCorrect(TraceScene):
    algorithm = "scaling-correct"
    polygon = "counterexample"
    title = entry("scaling-correct").title


class RotationCorrect(TraceScene):
    algorithm = "rotation-correct"
    polygon = "counterexample"
    title = entry("rotation-correct").title


class ScalingWalled(TraceScene):
    algorithm = "scaling-walled"
    polygon = "counterexample"
    title = entry("scaling-walled").title
