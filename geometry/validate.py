"""Turning raw point lists into a clean ring, and proving the ring simple.

Cleaning names the first defect it meets in one short line (see
:mod:`geometry.errors`). The simplicity test first looks for pinches (a point
twice) and fold-backs (zero-width spikes), then for two edges that meet, on one
of two paths:

* **Candidate pairs** (most polygons): shapely's STRtree lists the pairs of
  edges whose bounding boxes meet (comparisons of floats are exact, so no pair
  is missed), a vectorised float filter with a rigorous error bound discards the
  pairs that are certainly apart, and the exact predicates decide the rest. It is
  fast when the boxes are small (a 100,000-vertex spiral or comb has almost no
  pairs), and it reports the defect with the smallest edge indices.
* **Plane sweep** (:func:`geometry.sweep.first_contact`): many long, nearly
  parallel edges (a star) make the pairs quadratic in number, tens of millions at
  20,000 vertices and more than memory holds at 100,000. So the tree is queried
  a chunk of edges at a time (edges in a fixed pseudo-random order, chunks
  doubling, so the running count estimates the total early); once the count
  passes ``_PAIRS_PER_EDGE`` pairs per edge it stops and the Shamos–Hoey sweep,
  O(n log n) whatever the shape, takes over. It reports the first contact the
  sweep meets (near the left-most one), not the one with the smallest indices.

Both paths decide each sign with the exact predicates and word their defects
alike (:func:`_contact_error`).

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

from geometry import predicates
from geometry.errors import (
    CoordinateError,
    DegenerateError,
    SelfIntersectionError,
    TooFewPointsError,
)
from geometry.predicates import (  # the float filters' bounds
    ORIENT_BOUND,
    TINY,
    Contact,
    Point,
    intersection_point,
    on_segment,
    orient,
    segment_contact,
)
from geometry.sweep import first_contact

# Candidate pairs per edge beyond which the plane sweep is cheaper than deciding each pair.
_PAIRS_PER_EDGE = 16
# Edges in the first STRtree query (later ones grow while the pairs stay few).
_FIRST_CHUNK = 64


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
    kept = [points[i] for i in kept_indices(points)]
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


def kept_indices(points: Sequence[Point]) -> list[int]:
    """The input positions :func:`clean_points` keeps: a closing point and consecutive
    repeats are dropped (the first of a run is kept). The studio maps labels back with it.

    >>> kept_indices([(0, 0), (0, 0), (1, 0), (0, 1), (0, 0)])
    [0, 2, 3]
    """
    kept: list[int] = []
    for i, p in enumerate(points):
        if not kept or points[kept[-1]] != p:
            kept.append(i)
    while len(kept) > 1 and points[kept[-1]] == points[kept[0]]:
        kept.pop()
    return kept


def orient_array(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Orientation signs for rows of (n, 2) arrays; exact (uncertain rows go exact).

    >>> orient_array(np.array([[0., 0.]]), np.array([[1., 0.]]), np.array([[0., 1.]]))
    array([1])
    """
    if predicates.counts_open:
        predicates.count_sign_tests(len(c))  # one per row
    with np.errstate(all="ignore"):
        left = (a[:, 0] - c[:, 0]) * (b[:, 1] - c[:, 1])
        right = (a[:, 1] - c[:, 1]) * (b[:, 0] - c[:, 0])
        det = left - right
        bound = ORIENT_BOUND * (np.abs(left) + np.abs(right)) + TINY
        signs = np.where(det > bound, 1, np.where(-det > bound, -1, 0))
        unsure = ~((det > bound) | (-det > bound))
    rare = np.flatnonzero(unsure)
    if len(rare):
        with predicates.inside_a_test():  # each one of the rows counted above
            for k in rare:  # plain floats: numpy scalars would warn on overflow
                signs[k] = orient(*((float(m[k][0]), float(m[k][1])) for m in (a, b, c)))
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
    spikes), crossings, touchings and overlaps are each named. When edges meet in
    several places, the candidate-pair path reports the pair with the smallest
    edge indices, the sweep (many long edges) the first contact it meets.
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


def _candidate_pairs(arr: np.ndarray, budget: int) -> np.ndarray | None:
    """Pairs (i, j), i < j, of non-adjacent edges whose bounding boxes meet.

    None as soon as there are more than ``budget``. The tree is queried for
    chunks of edges in a fixed pseudo-random order, so the pairs seen so far per
    edge estimate the rest; each chunk is at most twice the one before and
    expected to bring at most ``budget`` pairs. A polygon with quadratically many
    pairs thus stops after a few small queries, holding O(budget) pairs.
    """
    n = len(arr)
    edges = shapely.linestrings(np.stack([arr, np.roll(arr, -1, 0)], axis=1))
    tree = shapely.STRtree(edges)
    order = np.random.default_rng(0).permutation(n)
    found, count, seen, start, size = [], 0, 0, 0, _FIRST_CHUNK
    while start < n:
        chunk = order[start : start + size]
        k, j = tree.query(edges[chunk])
        i = chunk[k]
        keep = (i < j) & (j != i + 1) & ~((i == 0) & (j == n - 1))
        found.append(np.stack([i[keep], j[keep]], axis=1))
        count += len(found[-1])
        if count > budget:
            return None
        start, seen = start + len(chunk), seen + len(k)
        size = min(2 * size, max(_FIRST_CHUNK, budget * start // max(seen, 1)))
    return np.concatenate(found)


def _certainly_apart(arr: np.ndarray, pairs: np.ndarray) -> np.ndarray:
    """Mask of pairs whose segments are certainly disjoint (float filter, exact signs)."""
    n = len(arr)
    a, b = arr[pairs[:, 0]], arr[(pairs[:, 0] + 1) % n]
    c, d = arr[pairs[:, 1]], arr[(pairs[:, 1] + 1) % n]
    same_side_cd = orient_array(a, b, c) * orient_array(a, b, d) > 0
    same_side_ab = orient_array(c, d, a) * orient_array(c, d, b) > 0
    apart: np.ndarray = same_side_cd | same_side_ab
    return apart


def _check_edge_pairs(points: list[Point], label: Callable[[int], str]) -> None:
    arr = np.asarray(points, dtype=float)
    n = len(arr)
    pairs = _candidate_pairs(arr, _PAIRS_PER_EDGE * n)
    if pairs is None:  # too many pairs to decide one by one: sweep instead
        found = first_contact(points)
        if found is not None:
            i, j = found
            raise _contact_error(points, i, j, _contact(points, i, j), label)
        return
    if len(pairs) == 0:
        return
    pairs = pairs[~_certainly_apart(arr, pairs)]
    order: np.ndarray | list[int] = np.lexsort((pairs[:, 1], pairs[:, 0])) if len(pairs) else []
    for k in order:
        i, j = int(pairs[k, 0]), int(pairs[k, 1])
        contact = _contact(points, i, j)
        if contact is not Contact.NONE:
            raise _contact_error(points, i, j, contact, label)


def _contact(points: list[Point], i: int, j: int) -> Contact:
    """How ring edges i and j meet."""
    n = len(points)
    return segment_contact(points[i], points[(i + 1) % n], points[j], points[(j + 1) % n])


def _contact_error(
    points: list[Point], i: int, j: int, contact: Contact, label: Callable[[int], str]
) -> SelfIntersectionError:
    """The error naming how edges i < j meet (``contact`` is not NONE)."""
    n = len(points)
    name1 = f"{label(i)}–{label((i + 1) % n)}"
    name2 = f"{label(j)}–{label((j + 1) % n)}"
    if contact is Contact.PROPER:
        a, b, c, d = points[i], points[(i + 1) % n], points[j], points[(j + 1) % n]
        where = fmt_point(intersection_point(a, b, c, d))
        return SelfIntersectionError(f"edges {name1} and {name2} cross at {where}")
    if contact is Contact.OVERLAP:
        a, b, c, d = points[i], points[(i + 1) % n], points[j], points[(j + 1) % n]
        start, end = overlap_ends(a, b, c, d)
        return SelfIntersectionError(f"edges {name1} and {name2} overlap from "
                                     f"{fmt_point(start)} to {fmt_point(end)}")
    return SelfIntersectionError(_touch_message(points, i, j, label))


def overlap_ends(a: Point, b: Point, c: Point, d: Point) -> tuple[Point, Point]:
    """The ends of the stretch two collinear overlapping segments ab and cd share.

    >>> overlap_ends((0, 0), (4, 0), (6, 0), (2, 0))
    ((2, 0), (4, 0))
    """
    shared = sorted({x for x in (a, b) if on_segment(x, c, d)}
                    | {x for x in (c, d) if on_segment(x, a, b)})
    return shared[0], shared[-1]


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
