"""Turning raw point lists into a clean ring, and proving the ring simple.

Cleaning names the first defect it meets in one short line (see
:mod:`geometry.errors`). The simplicity test is O(n log n): shapely's STRtree
finds the pairs of edges whose bounding boxes meet (comparisons of floats are
exact, so no pair is missed), a vectorised float filter with a rigorous error
bound discards the pairs that are certainly apart, and the exact predicates
decide the rest.

>>> clean_points([[0, 0], [4, 0], [4, 0], [0, 3], [0, 0]])
([(0.0, 0.0), (4.0, 0.0), (0.0, 3.0)], ['dropped 1 repeated consecutive point'])
>>> clean_points([[0, 0], [1, float("nan")], [0, 1]])
Traceback (most recent call last):
...
geometry.errors.CoordinateError: coordinate y of point 1 is NaN
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from numbers import Real

import numpy as np
import shapely

from geometry.errors import (
    CoordinateError,
    DegenerateError,
    SelfIntersectionError,
    TooFewPointsError,
)
from geometry.predicates import (
    Contact,
    Point,
    intersection_point,
    on_segment,
    orient,
    segment_contact,
)

_EPS = 2.0**-53
_ORIENT_BOUND = (3.0 + 16.0 * _EPS) * _EPS
_TINY = 2.0**-900


def fmt(x: float) -> str:
    """Short, stable text for a coordinate: ``2``, ``1.5``, ``1e+300``."""
    return f"{x:.6g}"


def fmt_point(p: Point) -> str:
    """``(2, 1.5)``."""
    return f"({fmt(p[0])}, {fmt(p[1])})"


def _coordinate(value: object, axis: str, index: int) -> float:
    if isinstance(value, bool) or not isinstance(value, Real):
        raise CoordinateError(f"coordinate {axis} of point {index} is not a number: {value!r}")
    x = float(value)
    if math.isnan(x):
        raise CoordinateError(f"coordinate {axis} of point {index} is NaN")
    if math.isinf(x):
        raise CoordinateError(f"coordinate {axis} of point {index} is {'+' if x > 0 else '-'}inf")
    return x


def _point(raw: object, index: int) -> Point:
    if isinstance(raw, str | bytes) or not isinstance(raw, Sequence):
        raise CoordinateError(f"point {index} is not a pair of numbers: {raw!r}")
    if len(raw) != 2:
        raise CoordinateError(f"point {index} has {len(raw)} coordinates; expected 2")
    return (_coordinate(raw[0], "x", index), _coordinate(raw[1], "y", index))


def clean_points(raw: object) -> tuple[list[Point], list[str]]:
    """Check each point, drop a closing point and consecutive repeats.

    Returns the points (floats, input order) and warnings about what was dropped.
    """
    if isinstance(raw, str | bytes | dict) or not isinstance(raw, Sequence):
        raise CoordinateError("expected a list of [x, y] points")
    points = [_point(p, i) for i, p in enumerate(raw)]
    kept: list[Point] = []
    for p in points:
        if not kept or kept[-1] != p:
            kept.append(p)
    while len(kept) > 1 and kept[-1] == kept[0]:
        kept.pop()
    warnings = []
    repeats = len(points) - len(kept) - (len(points) > 1 and points[-1] == points[0])
    if repeats > 0:
        warnings.append(
            f"dropped {repeats} repeated consecutive point{'s' if repeats > 1 else ''}"
        )
    if len(kept) < 3:
        raise TooFewPointsError(
            f"polygon has {len(kept)} distinct point{'s' if len(kept) != 1 else ''}; "
            "at least 3 are needed"
        )
    return kept, warnings


def orient_array(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Orientation signs for rows of (n, 2) arrays; exact (uncertain rows go exact).

    >>> orient_array(np.array([[0., 0.]]), np.array([[1., 0.]]), np.array([[0., 1.]]))
    array([1])
    """
    with np.errstate(all="ignore"):
        left = (a[:, 0] - c[:, 0]) * (b[:, 1] - c[:, 1])
        right = (a[:, 1] - c[:, 1]) * (b[:, 0] - c[:, 0])
        det = left - right
        bound = _ORIENT_BOUND * (np.abs(left) + np.abs(right)) + _TINY
        signs = np.where(det > bound, 1, np.where(-det > bound, -1, 0))
        unsure = ~((det > bound) | (-det > bound))
    for k in np.flatnonzero(unsure):  # plain floats: numpy scalars would warn on overflow
        signs[k] = orient(*(tuple(map(float, m[k])) for m in (a, b, c)))
    return signs


def check_not_collinear(points: list[Point]) -> None:
    """Raise :class:`DegenerateError` when every point lies on one line."""
    arr = np.asarray(points, dtype=float)
    n = len(arr)
    signs = orient_array(np.repeat(arr[:1], n, 0), np.repeat(arr[1:2], n, 0), arr)
    if not signs.any():
        raise DegenerateError(f"all {n} points are collinear (zero area)")


def check_simple(points: list[Point], label: Callable[[int], str]) -> None:
    """Raise :class:`SelfIntersectionError` unless the ring is simple.

    ``label(i)`` names input point i in messages. Pinches, fold-backs (zero-width
    spikes), crossings, touchings and overlaps are each named; when there are
    several defects the one with the smallest edge indices is reported.
    """
    _check_repeated_vertices(points)
    _check_fold_backs(points, label)
    _check_edge_pairs(points, label)


def _check_repeated_vertices(points: list[Point]) -> None:
    seen: dict[Point, int] = {}
    for i, p in enumerate(points):
        if p in seen:
            raise SelfIntersectionError(f"vertex {fmt_point(p)} appears twice (pinch)")
        seen[p] = i


def _check_fold_backs(points: list[Point], label: Callable[[int], str]) -> None:
    arr = np.asarray(points, dtype=float)
    prev, nxt = np.roll(arr, 1, 0), np.roll(arr, -1, 0)
    collinear = np.flatnonzero(orient_array(prev, arr, nxt) == 0)
    for i in collinear:
        u, v, w = points[i - 1], points[i], points[(i + 1) % len(points)]
        if on_segment(u, v, w) or on_segment(w, v, u):
            raise SelfIntersectionError(
                f"zero-width spike at vertex {label(int(i))} {fmt_point(v)}: "
                "its two edges fold back onto each other"
            )


def _candidate_pairs(arr: np.ndarray) -> np.ndarray:
    """Pairs (i, j), i < j, of non-adjacent edges whose bounding boxes meet."""
    n = len(arr)
    edges = shapely.linestrings(np.stack([arr, np.roll(arr, -1, 0)], axis=1))
    pairs = shapely.STRtree(edges).query(edges)
    i, j = pairs
    keep = (i < j) & (j != i + 1) & ~((i == 0) & (j == n - 1))
    return np.stack([i[keep], j[keep]], axis=1)


def _certainly_apart(arr: np.ndarray, pairs: np.ndarray) -> np.ndarray:
    """Mask of pairs whose segments are certainly disjoint (float filter, exact signs)."""
    n = len(arr)
    a, b = arr[pairs[:, 0]], arr[(pairs[:, 0] + 1) % n]
    c, d = arr[pairs[:, 1]], arr[(pairs[:, 1] + 1) % n]
    same_side_cd = orient_array(a, b, c) * orient_array(a, b, d) > 0
    same_side_ab = orient_array(c, d, a) * orient_array(c, d, b) > 0
    return same_side_cd | same_side_ab


def _check_edge_pairs(points: list[Point], label: Callable[[int], str]) -> None:
    arr = np.asarray(points, dtype=float)
    n = len(arr)
    pairs = _candidate_pairs(arr)
    if len(pairs) == 0:
        return
    pairs = pairs[~_certainly_apart(arr, pairs)]
    order = np.lexsort((pairs[:, 1], pairs[:, 0])) if len(pairs) else []
    for k in order:
        i, j = int(pairs[k, 0]), int(pairs[k, 1])
        a, b = points[i], points[(i + 1) % n]
        c, d = points[j], points[(j + 1) % n]
        contact = segment_contact(a, b, c, d)
        if contact is Contact.NONE:
            continue
        name1 = f"{label(i)}–{label((i + 1) % n)}"
        name2 = f"{label(j)}–{label((j + 1) % n)}"
        if contact is Contact.PROPER:
            where = fmt_point(intersection_point(a, b, c, d))
            raise SelfIntersectionError(f"edges {name1} and {name2} cross at {where}")
        if contact is Contact.OVERLAP:
            raise SelfIntersectionError(f"edges {name1} and {name2} overlap")
        raise SelfIntersectionError(_touch_message(points, i, j, label))


def _touch_message(points: list[Point], i: int, j: int, label: Callable[[int], str]) -> str:
    n = len(points)
    for v, (e0, e1) in ((i, (j, j + 1)), (i + 1, (j, j + 1)), (j, (i, i + 1)), (j + 1, (i, i + 1))):
        v, e0, e1 = v % n, e0 % n, e1 % n
        if on_segment(points[v], points[e0], points[e1]):
            return (
                f"vertex {label(v)} {fmt_point(points[v])} touches edge "
                f"{label(e0)}–{label(e1)}"
            )
    raise AssertionError("touching segments share no endpoint")  # unreachable by Contact.TOUCH
