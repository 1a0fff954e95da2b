"""Holes: a keyhole cut from each hole to the rind, then the fruit sliced round it; and the
monotone sweep over the same polygon, whose holes need no cut at all.

Run: ``manim -pql scenes/holes.py`` (``KeyholeEars`` first, then ``HolesSweep``);
``TREX_POLYGON=<file with holes>`` picks another polygon.
"""

from metaphors.layout import Box
from metaphors.scene import TraceScene
from story.storyboard import Pacing


class KeyholeEars(TraceScene):
    """Ear clipping with holes (Eberly 2002): each hole, right-most first, is joined to the
    rind by a keyhole cut; the fruit, now one ring, is sliced ear by ear."""

    algorithm = "ear-clipping"
    polygon = "keyhole"
    title = "Holes: cut a keyhole, then slice the fruit"
    metaphor_box = Box(-3.45, 0.8, 5.6, 3.9)  # room for the plate and the counter below
    pacing = Pacing(full=3, fast=0.4)


class HolesSweep(TraceScene):
    """The monotone sweep over the same polygon: a hole's top vertex is a split vertex, its
    bottom a merge vertex; their diagonals join the holes to the rest."""

    algorithm = "monotone"
    polygon = "keyhole"
    title = "Holes in the sweep: split and merge vertices"
