"""The counterexample: one 5-vertex polygon defeats all three wrong rules, and its mirror image
defeats the clock turned the other way (thesis ch. 2.1, Fig. 2.1); each correction holds on
the same polygon.

Each wrong rule is followed by the correction that mends it, on the same picture: the rule
fails, then its correction goes on from there (the polygon is not drawn again).

Run: ``manim -pql scenes/counterexample.py`` (the runs name their own polygons; ``TREX_LOG``
may list one saved log per run, joined with ``:``).
"""

from metaphors.scene import SequenceScene


class Counterexample(SequenceScene):
    title = "The counterexample"
    # each run titled with the thesis's name for its heuristic (story.registry.SPOKEN), then
    # what it does: the words taught are the words shown
    runs = (
        ("scaling", "counterexample", "Scaling: water spilled at B, the nearest candidate"),
        ("scaling-correct", "counterexample", "Correct Scaling: water rising from AC"),
        ("rotation", "counterexample", "Rotation: a clock at B, set to A"),
        ("rotation-correct", "counterexample", "Correct Rotation: the clock at C, set to B"),
        ("translation", "counterexample", "Translation: a vertical line swept from B"),
        ("translation-correct", "counterexample", "Correct Translation: the line parallel to AC"),
        ("rotation-ccw", "counterexample-twin", "Rotation the other way: the clock at B, set to C"),
        ("rotation-correct", "counterexample-twin", "Correct Rotation on the mirror image"),
    )
    # the point first, said once, as the polygon is drawn
    pictures = (
        ("polygon", "One {n}-vertex polygon defeats all three wrong rules; its mirror image "
                    "defeats the clock turned the other way"),
        ("mirror image", "Its mirror image, upside down: A and C, D and E swap names"),
    )
    ending = "Each wrong rule failed, and its correction held on the same polygon"
