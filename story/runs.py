"""Run an algorithm on a polygon under a recording: the computation that sits beside a scene.

No manim here. A scene's log (:meth:`story.spec.RunSpec.log`) is live or saved, alike.

>>> log = run_logged("scaling", "counterexample")
>>> log.meta["algorithm"], log.meta["shown"]
('scaling', 'scaling')
"""

from __future__ import annotations

import inspect
from typing import Any, cast

import tracing
from geometry.holes import PolygonWithHoles
from geometry.io import AnyPolygon, read_any_polygon
from geometry.polygon import Polygon
from geometry.triangulate import refuse_holes, triangulate
from story.pseudocode import from_docstring, to_json
from story.registry import REGISTRY, hole_pseudocode, shown
from story.source import shown_source
from usercode.heuristic import UserHeuristic, diagonal_rule, load_user_heuristic
from usercode.loading import is_user_spec


def fit_for(algorithm: str, polygon_read: AnyPolygon) -> AnyPolygon:
    """``polygon_read`` if ``algorithm`` can run on it: the one rule for a polygon handed to a run.
    Only :data:`geometry.triangulate.HOLE_ALGORITHMS` take holes; the heuristics, the other
    triangulations and a heuristic of one's own refuse them in one line.

    >>> fit_for("scaling", read_any_polygon("keyhole"))
    Traceback (most recent call last):
    ...
    geometry.errors.HolesNotSupportedError: scaling needs a simple polygon and this one has 2 holes; ear-clipping, monotone and cdt triangulate polygons with holes
    >>> fit_for("monotone", read_any_polygon("keyhole")).hole_count
    2
    """
    refuse_holes(polygon_read, algorithm)
    return polygon_read


def read_for(algorithm: str, polygon: str) -> AnyPolygon:
    """The polygon file or sample ``polygon``, read as a run of ``algorithm`` takes it
    (:func:`fit_for`). Raises :class:`geometry.errors.GeometryError` (one line)."""
    return fit_for(algorithm, read_any_polygon(polygon))


def run_logged(algorithm: str, polygon: str, heuristic: str | None = None,
               polygon_read: AnyPolygon | None = None) -> tracing.Log:
    """Run a heuristic (by name, or ``file.py:function`` of one's own) or a triangulation algorithm
    on a polygon file or sample (with holes, for the algorithms that take them). ``polygon_read``, if
    given, is that polygon read already (:func:`read_for`): it is not read again."""
    own = load_user_heuristic(algorithm) if is_user_spec(algorithm) else None  # a bad spec first
    polygon_read = read_for(algorithm, polygon) if polygon_read is None else fit_for(algorithm, polygon_read)
    if own is not None:
        return record_user_run(own, cast(Polygon, polygon_read), polygon)  # fit_for refused holes
    return record_run(algorithm, polygon_read, polygon, heuristic)


def record_run(algorithm: str, p: Polygon | PolygonWithHoles, polygon: str,
               heuristic: str | UserHeuristic | None = None) -> tracing.Log:
    """The log of a named heuristic or triangulation algorithm on the polygon ``p`` (read from
    ``polygon``, the name the log records). ``trex log`` writes exactly this log. Divide and
    conquer's ``heuristic`` may be one's own (``file.py:function``): it is loaded first (a bad
    spec is one line, before anything runs), and the meta names its traced function
    (``heuristic_function``), which the storyboard then treats as a heuristic."""
    meta: dict[str, Any] = {"algorithm": algorithm, "polygon": polygon, "shown": shown(algorithm)}
    if p.hole_count:  # the listing with the holes' rows (a simple polygon's meta is unchanged)
        meta["pseudocode"] = to_json(hole_pseudocode(algorithm))
    if heuristic:
        meta["heuristic"] = heuristic
    if isinstance(heuristic, str) and is_user_spec(heuristic):
        loaded = load_user_heuristic(heuristic)
        meta["heuristic_function"] = loaded.name
        heuristic = loaded
    known = REGISTRY.get(algorithm)
    with tracing.record(**meta) as log, tracing.alive(p):
        if known is None:  # geometry's own one-line KeyError names the algorithms it runs
            triangulate(p, algorithm, diagonal_rule(heuristic))
        elif known.is_heuristic:
            known.function(p)
        else:
            known.function(p, heuristic)
    return log


def saved_log(path: str) -> tracing.Log:
    """A saved log, as a scene plays it. A log written before logs named the function the
    panel shows gets the one a live run names."""
    log = tracing.Log.load(path)
    algorithm = log.meta.get("algorithm")
    if isinstance(algorithm, str) and "shown" not in log.meta and not log.meta.get(
            "user_heuristic"):
        log.meta["shown"] = shown(algorithm)
    return log


def record_user_run(heuristic: UserHeuristic, p: Polygon, polygon: str) -> tracing.Log:
    """The log of a loaded heuristic of one's own on the polygon ``p`` (``polygon``: the name
    the log records for it), as :func:`run_logged` records it: the meta names it
    (``user_heuristic``, which turns on the storyboard's generic beats) and carries its
    source, and the pseudocode of its docstring if it has some
    (:func:`story.pseudocode.from_docstring`), so a saved log shows them too."""
    spec = heuristic.spec
    code = [list(row) for row in shown_source(heuristic.raw)]  # the panel's rows of its source
    meta = {"algorithm": spec, "polygon": polygon, "shown": heuristic.name,
            "user_heuristic": heuristic.name, "code": code}
    rows = from_docstring(inspect.getdoc(heuristic.raw))
    if rows:
        meta["pseudocode"] = to_json(rows)
    with tracing.record(**meta) as log:
        heuristic.run(p)
    return log
