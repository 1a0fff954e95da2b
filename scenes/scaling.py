"""Water spilled at B: the nearest candidate — and why it can be wrong.

Run: ``manim -pql scenes/scaling.py`` (``TREX_POLYGON=<file or sample>`` picks the polygon).
"""

from metaphors.scene import TraceScene


class Scaling(TraceScene):
    algorithm = "scaling"
    polygon = "counterexample"
    title = "Scaling: water spilled at B wets the nearest candidate"
