"""Gravity: a ball on a rubber band finds an inner diagonal — and it is always right.

Run: ``manim -pql scenes/gravity.py`` (``TREX_POLYGON=<file or sample>`` picks the polygon,
``TREX_LOG=<saved log>`` replays a saved run). The default polygon, ``gravity-snag``, makes the
band snag a vertex on the way down.
"""

from metaphors.scene import TraceScene


class Gravity(TraceScene):
    algorithm = "gravity"
    polygon = "gravity-snag"
    title = "Gravity: a ball on a rubber band finds a diagonal"
