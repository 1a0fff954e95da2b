"""Exact geometric predicates on float (or int) coordinates.

Every decision that depends on a sign goes through this module. Each predicate
first tries a float evaluation guarded by a rigorous error bound and falls back
to exact rational arithmetic (:class:`fractions.Fraction`, exact for every
finite float) when the float result cannot be trusted.

Examples
--------
>>> orient((0, 0), (1, 0), (0, 1))
1
>>> orient((0.5, 0.5), (12, 12), (24, 24))
0
>>> in_triangle((0, 0), (0, 0), (2, 0), (0, 2))
True
>>> in_triangle((0, 0), (0, 0), (2, 0), (0, 2), closed=False)
False
"""

from __future__ import annotations

import contextlib
import math
import sys
import threading
from collections.abc import Callable, Iterator
from contextvars import ContextVar
from enum import Enum
from fractions import Fraction

Point = tuple[float, float]

EPS = sys.float_info.epsilon / 2  # unit round-off, 2**-53
# Shewchuk's bound for the 2-D orientation determinant.
ORIENT_BOUND = (3.0 + 16.0 * EPS) * EPS
# Below this magnitude products may have underflowed: trust nothing, go exact.
TINY = 2.0**-900
# Integers below this give exact float products and determinants in orient().
SMALL_INTEGER = 2.0**25
# Relative bound for sums of a few products (distances).
_LOOSE_BOUND = 1e-12
# Bound for d·(q − p) in floats, relative to |dx·gx| + |dy·gy|: three roundings, with room.
DOT_BOUND = 4.0 * EPS


class SignTests:
    """The sign tests decided in one context while :func:`counting_sign_tests` is open.

    A sign test is one exact orientation or comparison: :func:`orient`, :func:`dot_sign`
    (and :func:`cross_sign`, which is one), :func:`compare_distance`,
    :func:`compare_line_distance` and :func:`compare_angle`; a test asked of many points
    (:mod:`geometry.batch`, :func:`geometry.validate.orient_array`) is one per point, and the
    monotone sweep's bisection (:meth:`geometry.sweep_status.SweepStatus.find`) one per step.
    A test inside a test already counted (a batch's exact fall-back) is not counted again.
    """

    __slots__ = ("depth", "total")

    def __init__(self) -> None:
        self.total = 0
        self.depth = 0  # > 0 inside a test already counted


#: the count of the context a test runs in (None: not counting). Per context, so a thread
#: (or task) counts only its own tests, whatever runs beside it.
_COUNTED: ContextVar[SignTests | None] = ContextVar("sign_tests", default=None)
#: How many counts are open, in any thread: read before the context variable, so that when
#: nothing counts (every run but a measurement) a predicate pays one global lookup.
#: Read only outside this module.
counts_open = 0
_opening = threading.Lock()  # counts_open += 1 is not atomic between threads


@contextlib.contextmanager
def counting_sign_tests() -> Iterator[SignTests]:
    """Count the sign tests decided in this context (thread or task) while it is open.

    >>> with counting_sign_tests() as tests:
    ...     _ = orient((0, 0), (1, 0), (0, 1)), cross_sign((1, 0), (0, 0), (0, 1))
    >>> tests.total
    2

    Counts do not nest into each other: an inner count has the tests made while it is open,
    its outer count the others.
    """
    global counts_open
    tests = SignTests()
    token = _COUNTED.set(tests)
    with _opening:
        counts_open += 1
    try:
        yield tests
    finally:
        with _opening:
            counts_open -= 1
        _COUNTED.reset(token)


def count_sign_tests(tests: int) -> None:
    """Count ``tests`` sign tests decided here, if this context is counting (and is not
    inside a test already counted). Callers outside check :data:`counts_open` first."""
    counted = _COUNTED.get()
    if counted is not None and not counted.depth:
        counted.total += tests


@contextlib.contextmanager
def inside_a_test() -> Iterator[None]:
    """The tests made inside it are part of one already counted (a batch's exact fall-back
    for one of its points): not counted again."""
    counted = _COUNTED.get()
    if counted is None:
        yield
        return
    counted.depth += 1
    try:
        yield
    finally:
        counted.depth -= 1


def _sign(x: float | Fraction) -> int:
    return (x > 0) - (x < 0)


def orient_det(a: Point, b: Point, c: Point) -> Fraction:
    """Exact value of the orientation determinant (twice the signed area of abc).

    >>> orient_det((0, 0), (2, 0), (0, 1))
    Fraction(2, 1)
    """
    ax, ay = Fraction(a[0]), Fraction(a[1])
    return (Fraction(b[0]) - ax) * (Fraction(c[1]) - ay) - (Fraction(b[1]) - ay) * (
        Fraction(c[0]) - ax
    )


def orient(a: Point, b: Point, c: Point) -> int:
    """Sign of the turn a → b → c: 1 left (counter-clockwise), -1 right, 0 collinear.

    Exact for every finite float input: a filtered float evaluation, then
    exact rational arithmetic when the float sign is not certain.

    >>> orient((0, 0), (1, 1e-17), (2, 0))
    -1
    """
    if counts_open:
        count_sign_tests(1)
    left = (a[0] - c[0]) * (b[1] - c[1])
    right = (a[1] - c[1]) * (b[0] - c[0])
    det = left - right
    bound = ORIENT_BOUND * (abs(left) + abs(right)) + TINY
    if det > bound:
        return 1
    if -det > bound:
        return -1
    if _small_integer(a) and _small_integer(b) and _small_integer(c):
        return (det > 0) - (det < 0)  # exact: integers below 2**25 give an exact determinant
    return _sign(orient_det(a, b, c))


def _small_integer(p: Point) -> bool:
    x, y = p
    return (-SMALL_INTEGER < x < SMALL_INTEGER and -SMALL_INTEGER < y < SMALL_INTEGER
            and x == int(x) and y == int(y))


def _exact_sign_of_difference(x: float, y: float, exact: Callable[[], int]) -> int:
    """Sign of x - y for float approximations x, y of sums of a few products."""
    diff = x - y
    bound = _LOOSE_BOUND * (abs(x) + abs(y)) + TINY
    if diff > bound:
        return 1
    if -diff > bound:
        return -1
    return exact()


def dot_sign(d: Point, p: Point, q: Point) -> int:
    """Sign of d · (q − p), exactly: whether q lies ahead of p along d (1), level with it (0)
    or behind it (−1).

    A filtered float evaluation, then rational arithmetic when its sign is not certain.

    >>> dot_sign((0, -1), (0, 0), (3, -2))  # with gravity down, q is lower than p
    1
    >>> dot_sign((1, 1), (0, 0), (1, -1))
    0
    >>> dot_sign((1.0, 1e-300), (0.5, 0.0), (0.5, -1e-20))  # below float range: exact
    -1
    """
    if counts_open:
        count_sign_tests(1)
    dx, dy = q[0] - p[0], q[1] - p[1]
    value = dx * d[0] + dy * d[1]
    bound = DOT_BOUND * (abs(dx * d[0]) + abs(dy * d[1])) + TINY
    if value > bound:
        return 1
    if -value > bound:
        return -1
    exact = (Fraction(q[0]) - Fraction(p[0])) * Fraction(d[0]) + (
        Fraction(q[1]) - Fraction(p[1])
    ) * Fraction(d[1])
    return _sign(exact)


def cross_sign(d: Point, p: Point, q: Point) -> int:
    """Sign of d × (q − p), exactly: 1 when q lies left of the line through p along d,
    −1 right, 0 on it (like ``orient(p, p + d, q)``, without rounding ``p + d``).

    >>> cross_sign((0, -1), (0, 0), (-1, -5)), cross_sign((0, -1), (0, 0), (2, 1))
    (-1, 1)
    >>> cross_sign((1, 2), (1, 1), (2, 3))
    0
    """
    return -dot_sign((d[1], -d[0]), p, q)  # d × w = −(d turned right) · w


def ray_parameter(p: Point, d: Point, q: Point) -> Fraction:
    """The t of q's foot on the line p + t·d, exactly: (q − p)·d / |d|².

    >>> ray_parameter((0, 0), (2, 0), (3, 5))
    Fraction(3, 2)
    """
    dx, dy = Fraction(d[0]), Fraction(d[1])
    return ((Fraction(q[0]) - Fraction(p[0])) * dx + (Fraction(q[1]) - Fraction(p[1])) * dy) / (
        dx * dx + dy * dy
    )


def ray_meets_line(
    p: Point, d: Point, a: Point, b: Point
) -> tuple[Fraction, tuple[Fraction, Fraction]]:
    """Where the line p + t·d meets the line ab (not parallel to d): (t, point), exactly.

    >>> ray_meets_line((0, 0), (0, -1), (-1, -2), (1, -4))
    (Fraction(3, 1), (Fraction(0, 1), Fraction(-3, 1)))
    """
    px, py = Fraction(p[0]), Fraction(p[1])
    dx, dy = Fraction(d[0]), Fraction(d[1])
    ax, ay = Fraction(a[0]), Fraction(a[1])
    ex, ey = Fraction(b[0]) - ax, Fraction(b[1]) - ay
    t = ((ax - px) * ey - (ay - py) * ex) / (dx * ey - dy * ex)
    return t, (px + t * dx, py + t * dy)


def squared_distance(p: Point, q: Point) -> Fraction:
    """Exact squared distance between p and q."""
    dx = Fraction(p[0]) - Fraction(q[0])
    dy = Fraction(p[1]) - Fraction(q[1])
    return dx * dx + dy * dy


def compare_distance(origin: Point, p: Point, q: Point) -> int:
    """Sign of |origin p| − |origin q|, exactly.

    >>> compare_distance((0, 0), (3, 4), (5, 0))
    0
    >>> compare_distance((0, 0), (1, 0), (0, 2))
    -1
    """
    if counts_open:
        count_sign_tests(1)
    px, py, qx, qy = p[0] - origin[0], p[1] - origin[1], q[0] - origin[0], q[1] - origin[1]
    dp, dq = px * px + py * py, qx * qx + qy * qy  # inf on overflow, then exact
    return _exact_sign_of_difference(
        dp, dq, lambda: _sign(squared_distance(origin, p) - squared_distance(origin, q))
    )


def compare_line_distance(a: Point, b: Point, p: Point, q: Point) -> int:
    """Sign of dist(p, line ab) − dist(q, line ab), exactly.

    >>> compare_line_distance((0, 0), (1, 0), (5, 2), (-7, -2))
    0
    >>> compare_line_distance((0, 0), (1, 0), (5, 1), (0, 3))
    -1
    """
    if counts_open:
        count_sign_tests(1)
    dp = abs(orient_det(a, b, p))
    dq = abs(orient_det(a, b, q))
    return _sign(dp - dq)


def _cos_key(apex: Point, ref: Point, p: Point) -> Fraction:
    """sign(cos θ)·cos²θ·|ref−apex|², θ = angle ref–apex–p; monotone decreasing in θ ∈ [0, π]."""
    ux, uy = Fraction(ref[0]) - Fraction(apex[0]), Fraction(ref[1]) - Fraction(apex[1])
    vx, vy = Fraction(p[0]) - Fraction(apex[0]), Fraction(p[1]) - Fraction(apex[1])
    dot = ux * vx + uy * vy
    return _sign(dot) * dot * dot / (vx * vx + vy * vy)


def compare_angle(apex: Point, ref: Point, p: Point, q: Point) -> int:
    """Sign of angle(ref, apex, p) − angle(ref, apex, q), both unsigned in [0, π].

    Exact: compares cosines without square roots or ``acos``.

    >>> compare_angle((0, 0), (1, 0), (1, 1), (0, 1))
    -1
    >>> compare_angle((0, 0), (1, 0), (2, 2), (1, 1))
    0
    """
    if counts_open:
        count_sign_tests(1)
    if p == apex or q == apex:
        raise ValueError("angle at apex is undefined for a point equal to the apex")
    # Larger cosine means smaller angle.
    return _sign(_cos_key(apex, ref, q) - _cos_key(apex, ref, p))


def in_triangle(p: Point, a: Point, b: Point, c: Point, *, closed: bool = True) -> bool:
    """Whether p lies in triangle abc (either orientation); closed includes the boundary.

    >>> in_triangle((1, 0), (0, 0), (2, 0), (0, 2))
    True
    """
    turn = orient(a, b, c)
    if turn == 0:
        raise ValueError("triangle is degenerate")
    s1 = orient(a, b, p) * turn
    s2 = orient(b, c, p) * turn
    s3 = orient(c, a, p) * turn
    if closed:
        return s1 >= 0 and s2 >= 0 and s3 >= 0
    return s1 > 0 and s2 > 0 and s3 > 0


def _between(p: Point, a: Point, b: Point) -> bool:
    """For p collinear with ab: whether p lies in the closed box of ab."""
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(
        a[1], b[1]
    )


def on_segment(p: Point, a: Point, b: Point) -> bool:
    """Whether p lies on the closed segment ab.

    >>> on_segment((1, 1), (0, 0), (3, 3))
    True
    >>> on_segment((4, 4), (0, 0), (3, 3))
    False
    """
    return orient(a, b, p) == 0 and _between(p, a, b)


class Contact(Enum):
    """How two closed segments meet."""

    NONE = "none"
    PROPER = "proper"  # interiors cross at one point
    TOUCH = "touch"  # they meet at a point that is an endpoint of at least one
    OVERLAP = "overlap"  # collinear and sharing more than one point


def segment_contact(a: Point, b: Point, c: Point, d: Point) -> Contact:
    """Classify how segments ab and cd meet, exactly.

    >>> segment_contact((0, 0), (2, 2), (0, 2), (2, 0))
    <Contact.PROPER: 'proper'>
    >>> segment_contact((0, 0), (2, 0), (2, 0), (3, 5))
    <Contact.TOUCH: 'touch'>
    >>> segment_contact((0, 0), (2, 0), (1, 0), (3, 0))
    <Contact.OVERLAP: 'overlap'>
    >>> segment_contact((0, 0), (1, 0), (2, 0), (3, 0))
    <Contact.NONE: 'none'>
    """
    o1, o2 = orient(a, b, c), orient(a, b, d)
    o3, o4 = orient(c, d, a), orient(c, d, b)
    if o1 == o2 == 0:
        return _collinear_contact(a, b, c, d)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return Contact.PROPER
    touching = (
        (o1 == 0 and _between(c, a, b))
        or (o2 == 0 and _between(d, a, b))
        or (o3 == 0 and _between(a, c, d))
        or (o4 == 0 and _between(b, c, d))
    )
    return Contact.TOUCH if touching else Contact.NONE


def _collinear_contact(a: Point, b: Point, c: Point, d: Point) -> Contact:
    # Project on the dominant axis; float comparisons of coordinates are exact.
    axis = 0 if a[0] != b[0] or c[0] != d[0] else 1
    lo1, hi1 = sorted((a[axis], b[axis]))
    lo2, hi2 = sorted((c[axis], d[axis]))
    lo, hi = max(lo1, lo2), min(hi1, hi2)
    if lo > hi:
        return Contact.NONE
    return Contact.TOUCH if lo == hi else Contact.OVERLAP


def intersection_point(a: Point, b: Point, c: Point, d: Point) -> Point:
    """Intersection of the lines ab and cd, computed exactly and then rounded to floats.

    >>> intersection_point((0, 0), (2, 2), (0, 2), (2, 0))
    (1.0, 1.0)
    """
    d1 = orient_det(c, d, a)
    d2 = orient_det(c, d, b)
    if d1 == d2:
        raise ValueError("lines are parallel")
    t = d1 / (d1 - d2)
    ax, ay = Fraction(a[0]), Fraction(a[1])
    x = ax + t * (Fraction(b[0]) - ax)
    y = ay + t * (Fraction(b[1]) - ay)
    return (float(x), float(y))


def signed_area2(points: list[Point] | tuple[Point, ...]) -> Fraction:
    """Exact twice-signed area of a closed ring (positive when counter-clockwise).

    >>> signed_area2([(0, 0), (1, 0), (0, 1)])
    Fraction(1, 1)
    >>> signed_area2([(1e9, 1e9), (1e9 + 3, 1e9), (1e9, 1e9 + 4)])  # no cancellation lost
    Fraction(12, 1)
    >>> signed_area2([(Fraction(1, 3), 0), (1, 0), (0, 1)])
    Fraction(2, 3)
    """
    # Every coordinate is a ratio of integers (a float's denominator a power of two): over
    # their common denominator the shoelace is integer arithmetic, exact and far faster than
    # summing Fractions (seconds at 100,000 vertices), also beyond a float's range.
    ratios = [c.as_integer_ratio() for point in points for c in point]
    if not ratios:
        return Fraction(0)
    scale = math.lcm(*(den for _, den in ratios))
    ints = [num * (scale // den) for num, den in ratios]
    xs, ys = ints[0::2], ints[1::2]
    n = len(xs)
    twice = sum(xs[i] * ys[(i + 1) % n] - xs[(i + 1) % n] * ys[i] for i in range(n))
    return Fraction(twice, scale * scale)
