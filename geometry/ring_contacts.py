"""How the rings of a polygon with holes lie: apart, each hole inside the outer ring, none nested.

Each ring is simple already. What is left to prove, exactly:

1. **No two rings meet.** shapely's STRtree lists the pairs of edges of
   different rings whose bounding boxes meet (float comparisons of
   coordinates are exact, so none is missed); a float filter with a rigorous
   bound drops the pairs certainly apart (:func:`geometry.validate.orient_array`)
   and :func:`geometry.predicates.segment_contact` decides the rest.
2. **Every hole lies inside the outer ring, and in no other hole.** With no
   contacts, one vertex of a ring decides where the whole ring lies: a ray from
   it to the right crosses a ring an odd number of times exactly when the vertex
   is inside it (edges counted half-open in y, the side of each decided by an
   exact orientation). The tree lists the edges the rays can meet.

The first defect found is named, in this order: contacts (the outer ring's
first, then between holes, by hole number), holes outside, holes nested.

>>> from geometry.holes import PolygonWithHoles as P
>>> square = [(0, 0), (10, 0), (10, 10), (0, 10)]
>>> P.from_rings([square, [(8, 2), (12, 4), (8, 6)]])
Traceback (most recent call last):
...
geometry.errors.HoleError: hole 1 crosses the outer ring at (10, 5)
>>> P.from_rings([square, [(0, 5), (2, 4), (2, 6)]])
Traceback (most recent call last):
...
geometry.errors.HoleError: hole 1 touches the outer ring at (0, 5)
>>> P.from_rings([square, [(1, 1), (5, 1), (5, 5), (1, 5)], [(2, 2), (3, 2), (3, 3)]])
Traceback (most recent call last):
...
geometry.errors.HoleError: hole 2 lies inside hole 1
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

import numpy as np
import shapely

from geometry.errors import HoleError
from geometry.predicates import Contact, Point, intersection_point, on_segment, segment_contact
from geometry.validate import fmt_point, orient_array


class Rings(Protocol):
    """What the checks read of a :class:`geometry.holes.PolygonWithHoles` (which imports this)."""

    @property
    def points(self) -> Sequence[Point]: ...
    @property
    def starts(self) -> Sequence[int]: ...
    @property
    def next_array(self) -> list[int]: ...
    @property
    def ring_ids(self) -> np.ndarray: ...
    @property
    def hole_count(self) -> int: ...


def check_rings(polygon: Rings) -> None:
    """Raise :class:`HoleError` unless the rings of ``polygon`` lie apart, holes inside, none nested.

    ``polygon`` is a :class:`geometry.holes.PolygonWithHoles` whose rings are each simple.
    """
    points = polygon.points
    _check_repeats(points, polygon.starts)
    arr = np.asarray(points, dtype=float)
    ends = np.asarray(polygon.next_array)
    rings = polygon.ring_ids
    tree = shapely.STRtree(shapely.linestrings(np.stack([arr, arr[ends]], axis=1)))
    _check_contacts(points, arr, ends, rings, tree)
    _check_containment(polygon, arr, ends, rings, tree)


def _check_repeats(points: Sequence[Point], starts: Sequence[int]) -> None:
    """A ring given twice (the same vertices, in either direction) is said so, not as the
    rings touching at its first vertex.

    >>> _check_repeats([(0, 0), (9, 0), (0, 9), (1, 1), (2, 1), (1, 2), (1, 2), (2, 1), (1, 1)],
    ...                [0, 3, 6, 9])
    Traceback (most recent call last):
    ...
    geometry.errors.HoleError: holes 1 and 2 are the same ring twice
    """
    seen: dict[frozenset[Point], int] = {}
    for ring in range(len(starts) - 1):
        key = frozenset(points[starts[ring]:starts[ring + 1]])
        first = seen.setdefault(key, ring)
        if first != ring:
            raise HoleError(f"hole {ring} is the outer ring again" if first == 0
                            else f"holes {first} and {ring} are the same ring twice")


def _check_contacts(
    points: Sequence[Point], arr: np.ndarray, ends: np.ndarray, rings: np.ndarray, tree: shapely.STRtree
) -> None:
    i, j = tree.query(tree.geometries)
    keep = rings[i] < rings[j]
    i, j = i[keep], j[keep]
    a, b, c, d = arr[i], arr[ends[i]], arr[j], arr[ends[j]]
    apart = (orient_array(a, b, c) * orient_array(a, b, d) > 0) | (
        orient_array(c, d, a) * orient_array(c, d, b) > 0
    )
    i, j = i[~apart], j[~apart]
    for k in np.lexsort((j, i, rings[j], rings[i])):
        e, f = int(i[k]), int(j[k])
        p, q, r, s = points[e], points[ends[e]], points[f], points[ends[f]]
        contact = segment_contact(p, q, r, s)
        if contact is not Contact.NONE:
            raise HoleError(_contact_message(int(rings[e]), int(rings[f]), contact, (p, q, r, s)))


def _contact_message(first: int, second: int, contact: Contact, seg: tuple[Point, ...]) -> str:
    p, q, r, s = seg
    if contact is Contact.PROPER:
        if first == 0:
            return f"hole {second} crosses the outer ring at {fmt_point(intersection_point(p, q, r, s))}"
        where = fmt_point(intersection_point(p, q, r, s))
        return f"holes {first} and {second} overlap: their edges cross at {where}"
    where = fmt_point(_touch_point(p, q, r, s))
    if first == 0:
        return f"hole {second} touches the outer ring at {where}"
    return f"holes {first} and {second} touch at {where}"


def _touch_point(p: Point, q: Point, r: Point, s: Point) -> Point:
    """A point two segments share when they touch or overlap: an end of one on the other."""
    for x, (u, v) in ((r, (p, q)), (s, (p, q)), (p, (r, s)), (q, (r, s))):
        if on_segment(x, u, v):
            return x
    raise AssertionError("touching segments share no end point")


def _check_containment(
    polygon: Rings, arr: np.ndarray, ends: np.ndarray, rings: np.ndarray, tree: shapely.STRtree
) -> None:
    holes = polygon.hole_count
    if holes == 0:
        return
    inside = _ring_parity(arr, ends, rings, tree, np.asarray(polygon.starts[1:-1]), holes + 1)
    for hole in range(1, holes + 1):
        if not inside[hole - 1, 0]:
            raise HoleError(f"hole {hole} lies outside the polygon")
    for hole in range(1, holes + 1):
        around = np.flatnonzero(inside[hole - 1, 1:])
        if len(around):
            raise HoleError(f"hole {hole} lies inside hole {int(around[0]) + 1}")


def _ring_parity(arr: np.ndarray, ends: np.ndarray, rings: np.ndarray, tree: shapely.STRtree,
                 probes: np.ndarray, ring_count: int) -> np.ndarray:
    """Whether each probe vertex lies inside each ring (its own ring: False), by ray parity."""
    q = arr[probes]
    far = max(float(arr[:, 0].max()), float(np.nextafter(arr[:, 0].max(), np.inf)))
    rays = shapely.linestrings(np.stack([q, np.column_stack([np.full(len(q), far), q[:, 1]])], 1))
    r, e = tree.query(rays)
    keep = rings[e] != rings[probes[r]]
    r, e = r[keep], e[keep]
    lo, hi = arr[e], arr[ends[e]]
    qy = q[r, 1]
    straddle = (lo[:, 1] > qy) != (hi[:, 1] > qy)
    r, e, lo, hi = r[straddle], e[straddle], lo[straddle], hi[straddle]
    up = lo[:, 1] < hi[:, 1]
    low = np.where(up[:, None], lo, hi)
    high = np.where(up[:, None], hi, lo)
    right = orient_array(low, high, q[r]) > 0  # the probe is left of the upward edge
    counts = np.zeros((len(probes), ring_count), dtype=np.int64)
    np.add.at(counts, (r[right], rings[e[right]]), 1)
    odd: np.ndarray = counts % 2 == 1
    return odd
