"""Pacing: full detail for the first claims, then faster, so that a 20-vertex divide and conquer
(18 triangles, 17 claims) stays under about three minutes of video (every caption held until read). Measured on the scene built
in dry run (:func:`trex.scene_graph.build`), as long as its video at ``-ql``: each play
lasts a whole number of frames (15 per second), the last one begun counted whole."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from story.storyboard import Pacing
from trex.render_command import load_scene_class
from trex.scene_graph import build

SCENE_FILE = Path(__file__).resolve().parents[1] / "scenes" / "divide_and_conquer.py"


def divide_and_conquer():
    return load_scene_class(SCENE_FILE, "DivideAndConquer")


def _video_seconds(scene_class, polygon: str, fps: int = 15) -> float:
    _, plays = build(scene_class.handed(polygon))
    return sum(math.ceil(play.run_time * fps - 1e-9) for play in plays) / fps


@pytest.mark.parametrize("polygon", [
    "random-orthogonal:20:0",  # the longest of the generators' first 20-gons (97 s)
    pytest.param("random-star:20:1", marks=pytest.mark.slow),
])
def test_twenty_vertex_triangulation_stays_under_three_minutes(polygon):
    """Divide and conquer on 20 vertices (18 triangles, 17 claims) plays in under 3 minutes:
    full detail for the first claims, then faster (the scene's ``Pacing``)."""
    scene_class = divide_and_conquer()
    seconds = _video_seconds(scene_class, polygon)
    assert 30 < seconds < 180, f"{polygon}: {seconds:.1f} s of video"


@pytest.mark.slow
def test_pacing_is_what_keeps_it_short():
    scene_class = divide_and_conquer()

    class Unpaced(scene_class):
        pacing = Pacing(full=100, fast=1.0)

    polygon = "random-orthogonal:20:0"
    assert _video_seconds(Unpaced, polygon) > 1.5 * _video_seconds(scene_class, polygon)
