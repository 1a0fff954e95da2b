"""A clock at B, its hand set to A: the first candidate the hand passes — and why it can be wrong.

Run: ``manim -pql scenes/rotation.py Rotation`` (or ``RotationCcw``, the clock turning the other
way from C on the mirrored counterexample); ``TREX_POLYGON=<file or sample>`` picks the polygon.
"""

from metaphors.scene import TraceScene


class Rotation(TraceScene):
    algorithm = "rotation"
    polygon = "counterexample"
    title = "Rotation: a clock at B, set to A, stops at the first candidate"


class RotationCcw(TraceScene):
    algorithm = "rotation-ccw"
    polygon = "counterexample-twin"
    title = "Rotation the other way: the clock at B set to C"
