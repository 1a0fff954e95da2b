"""Every triangulation algorithm by name, run and verified exactly: :func:`triangulate`.

The registry imports each algorithm's module; none of them imports this one
(their result type is in :mod:`geometry.results`), so there is no cycle.

>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
>>> ALGORITHMS
('divide-and-conquer', 'ear-clipping-naive', 'ear-clipping', 'prune-and-search', 'monotone', 'cdt')
>>> {name: triangulate(p, name).triangles == ((0, 1, 4), (1, 2, 4), (2, 3, 4)) for name in RUNNERS}
... # doctest: +NORMALIZE_WHITESPACE
{'ear-clipping-naive': True, 'ear-clipping': True, 'prune-and-search': True, 'monotone': True,
 'cdt': True}
>>> triangulate(p, "divide-and-conquer", "scaling").failure.why
'B–D crosses edge E–A at (2.86087, 6.36087)'
"""

from __future__ import annotations

from collections.abc import Callable
from typing import cast

from geometry.cdt import cdt
from geometry.check import verify_triangulation
from geometry.ears import ear_clipping, ear_clipping_naive
from geometry.errors import HolesNotSupportedError
from geometry.frame import Diagonal
from geometry.holes import PolygonWithHoles
from geometry.lennes import divide_and_conquer
from geometry.monotone import monotone
from geometry.polygon import Polygon
from geometry.prune_search import prune_and_search
from geometry.results import Triangulation

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

#: The algorithms that triangulate a polygon with holes (the others need a simple polygon).
HOLE_ALGORITHMS = ("ear-clipping", "monotone", "cdt")


def refuse_holes(polygon: Polygon | PolygonWithHoles, algorithm: str) -> None:
    """Raise :class:`HolesNotSupportedError` when ``algorithm`` cannot take the polygon's holes.

    >>> from geometry.holes import PolygonWithHoles
    >>> p = PolygonWithHoles.from_rings([[(0, 0), (6, 0), (6, 6), (0, 6)], [(2, 2), (4, 2), (3, 4)]])
    >>> refuse_holes(p, "prune-and-search")
    Traceback (most recent call last):
    ...
    geometry.errors.HolesNotSupportedError: prune-and-search needs a simple polygon and this one has 1 hole; ear-clipping, monotone and cdt triangulate polygons with holes
    """
    holes = polygon.hole_count
    if holes and algorithm not in HOLE_ALGORITHMS:
        can = ", ".join(HOLE_ALGORITHMS[:-1]) + f" and {HOLE_ALGORITHMS[-1]}"
        raise HolesNotSupportedError(
            f"{algorithm} needs a simple polygon and this one has {holes} hole"
            f"{'s' if holes > 1 else ''}; {can} triangulate polygons with holes"
        )


def triangulate(polygon: Polygon | PolygonWithHoles, algorithm: str,
                heuristic: str | Callable[[Polygon], Diagonal] | None = None) -> Triangulation:
    """Run a triangulation algorithm by name and verify its answer exactly.

    Parameters
    ----------
    polygon : Polygon or PolygonWithHoles
        The polygon to triangulate; one with holes only by :data:`HOLE_ALGORITHMS`.
    algorithm : str
        One of :data:`ALGORITHMS`.
    heuristic : str or callable, optional
        Divide and conquer's diagonal rule (gravity when None): a built-in's name, or a
        function ``piece -> Diagonal``; a heuristic of one's own is handed as
        :func:`usercode.heuristic.diagonal_rule` makes it (its traced run, its one-line errors
        and time limit its own). The other algorithms take none and ignore it.

    Raises
    ------
    HolesNotSupportedError
        When the polygon has holes and the algorithm needs a simple polygon.

    Returns
    -------
    Triangulation
        The algorithm's answer; not ``valid`` (with the reason in ``failure``)
        when it stopped early or its triangles fail :func:`verify_triangulation`.
    """
    if algorithm in ALGORITHMS:
        refuse_holes(polygon, algorithm)
    if algorithm == "divide-and-conquer":
        # refuse_holes let through no holes: a hole-free PolygonWithHoles does as a Polygon
        result = divide_and_conquer(cast(Polygon, polygon), diagonal_rule(heuristic))
    elif algorithm in RUNNERS:
        result = RUNNERS[algorithm](cast(Polygon, polygon))  # as above, or a hole algorithm
    else:
        raise KeyError(f"unknown algorithm {algorithm!r}; expected one of {', '.join(ALGORITHMS)}")
    if result.valid:
        verdict = verify_triangulation(polygon, result.triangles)
        if not verdict:
            return Triangulation(result.triangles, False, failure=verdict, steps=result.steps)
    return result


def diagonal_rule(
    heuristic: str | Callable[[Polygon], Diagonal] | None,
) -> str | Callable[[Polygon], Diagonal]:
    """What divide and conquer calls on each piece: ``heuristic``, gravity for None."""
    return "gravity" if heuristic is None else heuristic
