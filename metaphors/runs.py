"""Run an algorithm on a polygon under a recording: the computation that sits beside a scene.

No manim here. A scene asks for a log; it gets one from a live run or from a saved JSON file,
and cannot tell the difference.

>>> log = run_logged("scaling", "counterexample")
>>> log.meta["algorithm"], log.meta["shown"]
('scaling', 'scaling')
"""

from __future__ import annotations

import os

import tracing
from geometry.diagonals import HEURISTICS, find_diagonal
from geometry.io import read_polygon
from geometry.triangulate import triangulate

#: Which traced function's source the panel shows for each algorithm.
SHOWN = {"gravity": "gravity_at", "divide-and-conquer": "divide_and_conquer"}


def run_logged(algorithm: str, polygon: str, heuristic: str | None = None) -> tracing.Log:
    """Run a heuristic (by name) or a triangulation algorithm on a polygon file or sample."""
    p = read_polygon(polygon)
    shown = SHOWN.get(algorithm, algorithm)
    meta = {"algorithm": algorithm, "polygon": polygon, "shown": shown}
    if heuristic:
        meta["heuristic"] = heuristic
    with tracing.record(**meta) as log:
        if algorithm in HEURISTICS:
            find_diagonal(p, algorithm)
        else:
            with tracing.alive(p):
                triangulate(p, algorithm, heuristic)
    return log


def scene_log(algorithm: str, default_polygon: str, heuristic: str | None = None) -> tracing.Log:
    """The log a scene plays: ``TREX_LOG`` (a saved JSON log) wins, else a live run on
    ``TREX_POLYGON`` (a file or sample name), else on the scene's default polygon."""
    saved = os.environ.get("TREX_LOG")
    if saved:
        return tracing.Log.load(saved)
    return run_logged(algorithm, os.environ.get("TREX_POLYGON", default_polygon), heuristic)
