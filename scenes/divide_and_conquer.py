"""Lennes' divide and conquer (1911) with the gravity heuristic: find a diagonal, split along
it, go on with both halves until only triangles are left.

Run: ``manim -pql scenes/divide_and_conquer.py`` (``TREX_POLYGON=<file or sample>`` picks the
polygon, ``TREX_LOG=<saved log>`` replays a saved run). Full detail for the first two claims,
then faster, each diagonal under a caption of its own.
"""

from metaphors.scene import TraceScene
from story.storyboard import Pacing


class DivideAndConquer(TraceScene):
    algorithm = "divide-and-conquer"
    heuristic = "gravity"
    polygon = "lecture"
    title = "Divide and conquer: split along diagonals found by Gravity"
    #: each fast diagonal under a caption of its own, saying what it shows
    pacing = Pacing(full=2, fast=0.35, told=True)
