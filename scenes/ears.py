"""Ear clipping as slicing fruit: cut off an ear, put the slice on the plate, repeat.

Run: ``manim -pql scenes/ears.py`` (``TREX_POLYGON=<file or sample>`` picks the polygon).
"""

from metaphors.layout import Box
from metaphors.scene import TraceScene
from story.storyboard import Pacing


class Ears(TraceScene):
    algorithm = "ear-clipping-naive"
    polygon = "lecture"
    title = "Ear clipping: slice the fruit one ear at a time"
    metaphor_box = Box(-3.45, 0.8, 5.6, 3.9)  # room for the plate and the counter below
    pacing = Pacing(full=3, fast=0.4)
