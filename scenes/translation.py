"""A vertical line swept rightwards from B: the left-most candidate — and why it can be wrong.

Run: ``manim -pql scenes/translation.py`` (``TREX_POLYGON=<file or sample>`` picks the polygon).
"""

from metaphors.scene import TraceScene


class Translation(TraceScene):
    algorithm = "translation"
    polygon = "counterexample"
    title = "Translation: a vertical line swept from B"
