"""One polygon and its mirror image defeat every wrong heuristic; the corrections do not fail.

Run: ``manim -pql scenes/counterexample.py`` (the runs name their own polygons; ``TREX_LOG``
may list one saved log per run, joined with ``:``).
"""

from metaphors.scene import SequenceScene


class Counterexample(SequenceScene):
    title = "The counterexample"
    runs = (
        ("scaling", "counterexample", "Scaling fails: the nearest candidate"),
        ("rotation", "counterexample", "Rotation fails: the clock set to A"),
        ("translation", "counterexample", "Translation fails: the vertical sweep"),
        ("rotation-ccw", "counterexample-twin", "On the mirror image, the clock set to C fails"),
        ("translation-correct", "counterexample", "Sweeping parallel to AC works"),
        ("scaling-correct", "counterexample", "Water rising from AC works"),
        ("rotation-correct", "counterexample", "The clock at C works"),
        ("rotation-correct", "counterexample-twin", "… and on the mirror image too"),
    )
