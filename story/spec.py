"""A run as a value: what a scene plays, handed to it rather than read from the environment.

A :class:`RunSpec` names an algorithm (a registry name, or ``file.py:function`` for a
heuristic of one's own), the polygon it runs on (a file or a sample name), divide and
conquer's heuristic, and optionally a saved log to replay instead of running live.
:meth:`RunSpec.log` produces the log a scene plays; the scene cannot tell a live run from
a saved one. ``trex`` and the tests build specs and hand them to scenes; under plain
``manim scenes/x.py`` a scene builds its own from ``TREX_POLYGON`` and ``TREX_LOG``
(:mod:`story.environment`, the one module that reads the environment).

>>> spec = RunSpec("scaling", "counterexample")
>>> spec.log().meta["algorithm"], spec.log().meta["polygon"]
('scaling', 'counterexample')
>>> spec.on("counterexample-twin")
RunSpec(algorithm='scaling', polygon='counterexample-twin', heuristic=None, saved=None)
>>> spec.replaying("run.json").saved
'run.json'

A polygon is read once, by one rule (:func:`story.runs.read_for`: holes only for the
algorithms that take them): :meth:`RunSpec.read` keeps the polygon read (``polygon_read``) in the
spec, and a scene handed that spec plays it without reading the file again. ``trex`` reads
and checks the polygon that way before anything renders, then hands the scene the spec.

>>> spec.on("keyhole").read()
Traceback (most recent call last):
...
geometry.errors.HolesNotSupportedError: scaling needs a simple polygon and this one has 2 holes; ear-clipping, monotone and cdt triangulate polygons with holes
>>> RunSpec("monotone", "keyhole").read().polygon_read.hole_count
2
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass, field, replace

import tracing
from geometry.io import AnyPolygon, read_any_polygon
from story.runs import fit_for, run_logged, saved_log

__all__ = ["RunSpec"]


@dataclass(frozen=True)
class RunSpec:
    """One run: what to run on what, or the saved log that replays it.

    Attributes
    ----------
    algorithm : str
        A heuristic or triangulation (:mod:`story.registry`), or ``file.py:function``.
    polygon : str
        A polygon file or sample name. Not read when ``saved`` is given (the log has its own).
    heuristic : str or None
        Divide and conquer's heuristic (None: gravity); other algorithms take none.
    saved : str or None
        The path of a saved log (``trex log`` writes them) to replay instead of running.
    polygon_read : Polygon, PolygonWithHoles or None
        ``polygon`` as read and checked (:meth:`read`); None: not read yet, the run reads it.
        Not compared: it is what ``polygon`` names.

    More options (pacing, the panel's) are to come as further keyword fields with defaults.
    """

    algorithm: str
    polygon: str
    _: KW_ONLY
    heuristic: str | None = None
    saved: str | None = None
    polygon_read: AnyPolygon | None = field(default=None, repr=False, compare=False)

    def log(self) -> tracing.Log:
        """The log of this run: the saved one if given, else a live run (on ``polygon_read`` when the
        polygon was read already)."""
        if self.saved:
            return saved_log(self.saved)
        return run_logged(self.algorithm, self.polygon, self.heuristic, self.polygon_read)

    def read(self, polygon_read: AnyPolygon | None = None) -> RunSpec:
        """This run with its polygon read: ``polygon_read`` (``polygon`` read already, as ``trex``
        reads every polygon argument) or read now, and checked by the one rule
        (:func:`story.runs.fit_for`). A replay reads nothing: it comes back as it is.
        Raises :class:`geometry.errors.GeometryError` (or OSError, ValueError) in one line."""
        if self.saved:
            return self
        polygon_read = read_any_polygon(self.polygon) if polygon_read is None else polygon_read
        return replace(self, polygon_read=fit_for(self.algorithm, polygon_read))

    def on(self, polygon: str) -> RunSpec:
        """The same run, live on another polygon (a saved log no longer applies)."""
        return replace(self, polygon=polygon, saved=None, polygon_read=None)

    def replaying(self, saved: str) -> RunSpec:
        """The same run, replayed from the saved log at ``saved``."""
        return replace(self, saved=saved, polygon_read=None)
