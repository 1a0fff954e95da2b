"""Every triangulation algorithm by name, run and verified exactly: :func:`triangulate`.

The registry imports each algorithm's module; none of them imports this one
(their result type is in :mod:`geometry.results`), so there is no cycle.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
>>> ALGORITHMS
('divide-and-conquer', 'ear-clipping-naive', 'ear-clipping', 'prune-and-search', 'monotone', 'cdt')
>>> {name: triangulate(p, name).triangles == [(0, 1, 4), (1, 2, 4), (2, 3, 4)] for name in RUNNERS}
... # doctest: +NORMALIZE_WHITESPACE
{'ear-clipping-naive': True, 'ear-clipping': True, 'prune-and-search': True, 'monotone': True,
 'cdt': True}
>>> triangulate(p, "divide-and-conquer", "scaling").failure.why
'B–D crosses edge E–A at (2.86087, 6.36087)'
"""

from __future__ import annotations

from collections.abc import Callable

from geometry.cdt import cdt
from geometry.check import verify_triangulation
from geometry.ears import ear_clipping, ear_clipping_naive
from geometry.lennes import divide_and_conquer
from geometry.monotone import monotone
from geometry.polygon import Polygon
from geometry.prune_search import prune_and_search
from geometry.results import Triangulation
from geometry.user_heuristics import UserHeuristic, is_user_spec, load_user_heuristic

#: The algorithms that take only the polygon (divide and conquer also takes a heuristic).
RUNNERS: dict[str, Callable[[Polygon], Triangulation]] = {
    "ear-clipping-naive": ear_clipping_naive,
    "ear-clipping": ear_clipping,
    "prune-and-search": prune_and_search,
    "monotone": monotone,
    "cdt": cdt,
}

#: Every algorithm :func:`triangulate` knows, in the order the command line lists them.
ALGORITHMS = ("divide-and-conquer", *RUNNERS)


def triangulate(polygon: Polygon, algorithm: str,
                heuristic: str | UserHeuristic | None = None) -> Triangulation:
    """Run a triangulation algorithm by name and verify its answer exactly.

    Parameters
    ----------
    polygon : Polygon
        The polygon to triangulate.
    algorithm : str
        One of :data:`ALGORITHMS`.
    heuristic : str or UserHeuristic, optional
        Divide and conquer's diagonal rule (gravity when None): a built-in's name, or a
        heuristic of one's own (``file.py:function`` or loaded), called through
        :mod:`geometry.user_heuristics` (its one-line errors and time limit apply); the other
        algorithms take none and ignore it.

    Returns
    -------
    Triangulation
        The algorithm's answer; not ``valid`` (with the reason in ``failure``)
        when it stopped early or its triangles fail :func:`verify_triangulation`.
    """
    if algorithm == "divide-and-conquer":
        result = divide_and_conquer(polygon, diagonal_rule(heuristic))
    elif algorithm in RUNNERS:
        result = RUNNERS[algorithm](polygon)
    else:
        raise KeyError(f"unknown algorithm {algorithm!r}; expected one of {', '.join(ALGORITHMS)}")
    if result.valid:
        verdict = verify_triangulation(polygon, result.triangles)
        if not verdict:
            return Triangulation(result.triangles, False, failure=verdict, steps=result.steps)
    return result


def diagonal_rule(heuristic: str | UserHeuristic | None):
    """What divide and conquer calls on each piece: a built-in's name (gravity for None), or
    the traced run of a heuristic of one's own (loaded now if given as ``file.py:function``)."""
    if heuristic is None:
        return "gravity"
    if isinstance(heuristic, UserHeuristic):
        return heuristic.function
    if is_user_spec(heuristic):
        return load_user_heuristic(heuristic).function
    return heuristic
