"""One polygon and its mirror image defeat every wrong heuristic; the corrections do not fail.

Run: ``manim -pql scenes/counterexample.py`` (the runs name their own polygons; ``TREX_LOG``
may list one saved log per run, joined with ``:``).
"""

from metaphors.scene import SequenceScene


class Counterexample(SequenceScene):
    title = "The counterexample"
    # each run titled with the thesis's name for its heuristic (story.registry.SPOKEN), then
    # what it does: the words taught are the words shown
    runs = (
        ("scaling", "counterexample", "Scaling fails: the nearest candidate"),
        ("rotation", "counterexample", "Rotation fails: the clock set to A"),
        ("translation", "counterexample", "Translation fails: the vertical sweep"),
        ("rotation-ccw", "counterexample-twin", "Rotation the other way fails on the mirror image"),
        ("translation-correct", "counterexample", "Correct Translation works: parallel to AC"),
        ("scaling-correct", "counterexample", "Correct Scaling works: water rising from AC"),
        ("rotation-correct", "counterexample", "Correct Rotation works: the clock at C"),
        ("rotation-correct", "counterexample-twin", "Correct Rotation works on the mirror image too"),
    )
