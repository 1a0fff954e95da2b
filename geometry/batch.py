"""Exact predicates for one triangle (or line) against many points at once.

The ear tests of ear clipping and prune-and-search ask the same question of
many points: which of them lie in the closed triangle abc? Here it is asked of
numpy arrays. Each orientation is first evaluated in floats with the same
rigorous error bound as :func:`geometry.predicates.orient`; only the points
whose sign that bound cannot certify are decided exactly, one by one. For a
few points a plain loop is faster: :meth:`PointTable.any_in_triangle` picks.

Examples
--------
>>> xs = np.array([0.5, 3.0, 1.0, 0.0])
>>> ys = np.array([0.5, 3.0, 0.0, 2.0])
>>> orient_many((0, 0), (2, 0), xs, ys)
array([1, 1, 0, 1], dtype=int8)
>>> in_triangle_many((0, 0), (2, 0), (0, 2), xs, ys)
array([ True, False,  True,  True])
"""

from __future__ import annotations

from collections.abc import Collection, Sequence

import numpy as np

from geometry import predicates
from geometry.predicates import (  # the float filters' bounds
    DOT_BOUND,
    ORIENT_BOUND,
    SMALL_INTEGER,
    TINY,
    Point,
    dot_sign,
    orient,
)


def orient_many(a: Point, b: Point, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """``orient(a, b, p)`` for every point p = (xs[k], ys[k]), exactly, as int8 signs."""
    if predicates.counts_open:
        predicates.count_sign_tests(len(xs))  # one per point
    with np.errstate(all="ignore"):
        left = (a[0] - xs) * (b[1] - ys)
        right = (a[1] - ys) * (b[0] - xs)
        det = left - right
        bound = ORIENT_BOUND * (np.abs(left) + np.abs(right)) + TINY
        positive, negative = det > bound, det < -bound
    signs = positive.astype(np.int8) - negative.astype(np.int8)
    unsure = np.flatnonzero(~(positive | negative))
    if len(unsure) == 0:
        return signs
    ux, uy = xs[unsure], ys[unsure]
    # A product is exactly zero when a factor is (float differences vanish only for
    # equal floats): p equal to a or b, or on an axis-parallel line through both.
    zero = ((a[0] == ux) | (b[1] == uy)) & ((a[1] == uy) | (b[0] == ux))
    signs[unsure[zero]] = 0
    unsure = unsure[~zero]
    if len(unsure) == 0:
        return signs
    exact = _small_integers(a, b, xs[unsure], ys[unsure])
    signs[unsure[exact]] = np.sign(det[unsure[exact]])
    with predicates.inside_a_test():  # each one of the points counted above
        for k in unsure[~exact]:  # rare: decide these one by one in rationals
            signs[k] = orient(a, b, (float(xs[k]), float(ys[k])))
    return signs


def dot_sign_many(d: Point, starts: np.ndarray, ends: np.ndarray) -> np.ndarray:
    """``dot_sign(d, p, q)`` for every row p of ``starts`` and q of ``ends``, exactly, as int8.

    >>> starts, ends = np.array([[0.0, 0.0], [1.0, 1.0]]), np.array([[5.0, 0.0], [0.0, 3.0]])
    >>> dot_sign_many((0, 1), starts, ends)
    array([0, 1], dtype=int8)
    """
    if predicates.counts_open:
        predicates.count_sign_tests(len(starts))  # one per point
    with np.errstate(all="ignore"):
        dx, dy = ends[:, 0] - starts[:, 0], ends[:, 1] - starts[:, 1]
        value = dx * d[0] + dy * d[1]
        bound = DOT_BOUND * (np.abs(dx * d[0]) + np.abs(dy * d[1])) + TINY
        positive, negative = value > bound, value < -bound
    signs = positive.astype(np.int8) - negative.astype(np.int8)
    rare = np.flatnonzero(~(positive | negative))
    if len(rare):
        with predicates.inside_a_test():  # each one of the points counted above
            for k in rare:  # decide these one by one
                signs[k] = dot_sign(d, tuple(starts[k].tolist()), tuple(ends[k].tolist()))
    found: np.ndarray = signs
    return found


def in_closed_triangle(p: Point, a: Point, b: Point, c: Point) -> bool:
    """Whether p lies in the closed counter-clockwise triangle abc (one point, exact).

    >>> in_closed_triangle((1, 0), (0, 0), (2, 0), (0, 2))
    True
    """
    return orient(a, b, p) >= 0 and orient(b, c, p) >= 0 and orient(c, a, p) >= 0


#: Up to this many points a plain loop over them beats setting up NumPy arrays.
LOOP_UP_TO = 32


class PointTable:
    """A polygon's points twice over: the tuples for a plain loop, float arrays for NumPy.

    >>> table = PointTable([(0.0, 0.0), (4.0, 0.0), (0.0, 4.0), (1.0, 1.0), (5.0, 5.0)])
    >>> table.any_in_triangle((0, 0), (4, 0), (0, 4), [0, 1, 2, 3, 4], skip=(0, 1, 2))
    True
    >>> table.any_in_triangle((0, 0), (4, 0), (0, 4), [0, 1, 2, 4], skip=(0, 1, 2))
    False
    """

    def __init__(self, points: Sequence[Point]) -> None:
        self.points = points
        arr = np.asarray(points, dtype=float).reshape(-1, 2)
        self.xs, self.ys = arr[:, 0], arr[:, 1]

    def any_in_triangle(
        self,
        a: Point,
        b: Point,
        c: Point,
        ids: Sequence[int] | np.ndarray,
        skip: Collection[int] = (),
    ) -> bool:
        """Whether a point ``ids[j]``, j not in ``skip``, lies in the closed ccw triangle abc.

        Exact either way: a plain loop for up to :data:`LOOP_UP_TO` ids, NumPy beyond.
        ``skip`` holds positions in ``ids`` (the triangle's own corners, say).
        """
        if len(ids) <= LOOP_UP_TO:
            points = self.points
            return any(
                in_closed_triangle(points[i], a, b, c) for j, i in enumerate(ids) if j not in skip
            )
        inside = in_triangle_many(a, b, c, self.xs[ids], self.ys[ids])
        inside[list(skip)] = False
        return bool(inside.any())


def _small_integers(a: Point, b: Point, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """Mask of points for which the float determinant is exact.

    With integer coordinates below 2**25 in magnitude, every difference (< 2**26)
    and product (< 2**52) and their difference (< 2**53) is an exact float. This
    decides the many exact zeros of integer grids (collinear runs) at numpy speed.
    """
    ends = np.array([a[0], a[1], b[0], b[1]], dtype=float)
    if not (np.all(np.abs(ends) < SMALL_INTEGER) and np.all(ends == np.round(ends))):
        return np.zeros(len(xs), dtype=bool)
    small: np.ndarray = (np.abs(xs) < SMALL_INTEGER) & (np.abs(ys) < SMALL_INTEGER) & (
        xs == np.round(xs)
    ) & (ys == np.round(ys))
    return small


def in_triangle_many(
    a: Point, b: Point, c: Point, xs: np.ndarray, ys: np.ndarray
) -> np.ndarray:
    """Mask of the points lying in the closed counter-clockwise triangle abc.

    Points are thinned out edge by edge, so the later edges see only the
    points still in question.
    """
    inside = np.zeros(len(xs), dtype=bool)
    keep = np.flatnonzero(orient_many(a, b, xs, ys) >= 0)
    keep = keep[orient_many(b, c, xs[keep], ys[keep]) >= 0]
    keep = keep[orient_many(c, a, xs[keep], ys[keep]) >= 0]
    inside[keep] = True
    return inside
