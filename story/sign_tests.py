"""The work of a run measured: how many sign tests it decides (issue 22 item 7).

A sign test is one exact orientation or comparison: :func:`geometry.predicates.orient`,
:func:`~geometry.predicates.dot_sign` (and ``cross_sign``, which is one),
:func:`~geometry.predicates.compare_distance`, ``compare_line_distance`` and
``compare_angle``. A test asked of many points at once counts once per point
(:func:`geometry.batch.orient_many`, :func:`~geometry.batch.dot_sign_many`,
:func:`geometry.validate.orient_array`), and the test the monotone sweep inlines in its
bisection (:meth:`geometry.sweep_status.SweepStatus.find`) once per step of the bisection.
A test inside a test is not counted again (``in_triangle`` is its three or four
orientations; the exact fall-back of a batch is one of the batch's points).

They are counted where the geometry calls them (:func:`count_sign_tests`), the algorithms
unchanged: a count is of the run itself, with no recording open and no verification after.
What a sign test leaves out is said with the plot: coordinate comparisons (sorting, the
bounding boxes that ear clipping and Gravity filter with) are not sign tests.

>>> from geometry.polygon import Polygon
>>> square = Polygon.from_points([(0, 0), (2, 0), (2, 2), (0, 2)])
>>> count_sign_tests(lambda: square.sub_polygon(range(4)).turns)  # one per vertex
4
>>> measured("monotone", 20) == measured("monotone", 20) > 0  # the same every time
True
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Callable
from typing import Any

from geometry import batch, predicates, validate
from geometry.io import read_polygon
from geometry.lennes import divide_and_conquer
from geometry.polygon import Polygon
from geometry.results import Triangulation
from geometry.sweep_status import SweepStatus
from geometry.triangulate import RUNNERS

#: the tests that count one each, and those asked of many points (and which argument
#: holds the points)
_ONE: tuple[Callable[..., Any], ...] = (
    predicates.orient, predicates.dot_sign, predicates.compare_distance,
    predicates.compare_line_distance, predicates.compare_angle)
_MANY: tuple[tuple[Callable[..., Any], int], ...] = (
    (batch.orient_many, 2), (batch.dot_sign_many, 1), (validate.orient_array, 2))

#: the runs a plot measures: random simple polygons ``random-2opt:n:SEED``, these seeds
SEEDS = (1, 2, 3)
#: the algorithms that can be measured, as :func:`geometry.triangulate.triangulate` names
#: them (divide and conquer with Gravity, as the lecture runs it)
ALGORITHMS: dict[str, Callable[[Polygon], Triangulation]] = {
    "divide-and-conquer": lambda p: divide_and_conquer(p, "gravity"),
    **{name: RUNNERS[name] for name in ("ear-clipping-naive", "ear-clipping",
                                        "prune-and-search", "monotone")},
}


def _bisection_steps(status: SweepStatus, own: int, found: int) -> int:
    """The tests :meth:`SweepStatus.find` made to return ``found``: its bisection replayed
    (each test went right exactly when its middle lay left of the place found)."""
    edges, lo, hi, steps = status.edges, 0, len(status.edges), 0
    while lo < hi:
        mid = (lo + hi) // 2
        if edges[mid] == own:  # its own edge: passed without a test
            hi = mid
            continue
        steps += 1
        lo, hi = (mid + 1, hi) if mid < found else (lo, mid)
    return steps


class _Counter:
    """Sign tests counted while it is open; a test inside a test is not counted again."""

    def __init__(self) -> None:
        self.total = self.depth = 0

    def one(self, test: Callable[..., Any]) -> Callable[..., Any]:
        return self.wrapped(test, lambda args: 1)

    def many(self, test: Callable[..., Any], points: int) -> Callable[..., Any]:
        return self.wrapped(test, lambda args: len(args[points]))

    def wrapped(self, test: Callable[..., Any],
                counts: Callable[[tuple[Any, ...]], int]) -> Callable[..., Any]:
        @functools.wraps(test)
        def counted(*args: Any, **kwargs: Any) -> Any:
            if self.depth == 0:
                self.total += counts(args)
            self.depth += 1
            try:
                return test(*args, **kwargs)
            finally:
                self.depth -= 1
        return counted

    def find(self, find: Callable[..., int]) -> Callable[..., int]:
        @functools.wraps(find)
        def counted(status: SweepStatus, v: int, own: int = -1) -> int:
            self.depth += 1  # its exact fall-back is one of its steps
            try:
                found = find(status, v, own)
            finally:
                self.depth -= 1
            if self.depth == 0:
                self.total += _bisection_steps(status, own, found)
            return found
        return counted


def count_sign_tests(run: Callable[[], Any]) -> int:
    """How many sign tests ``run()`` decides (its result is dropped). The tests are counted
    where geometry calls them: every name a ``geometry`` module binds to one of them is
    bound to a counting copy while ``run`` runs, then given back."""
    counter = _Counter()
    copies: dict[int, tuple[Callable[..., Any], Callable[..., Any]]] = {
        id(test): (test, counter.one(test)) for test in _ONE}
    copies.update({id(test): (test, counter.many(test, at)) for test, at in _MANY})
    swapped: list[tuple[object, str, object]] = []
    for name, loaded in list(sys.modules.items()):
        if loaded is None or (name != "geometry" and not name.startswith("geometry.")):
            continue
        module: object = loaded
        for attribute, value in list(vars(module).items()):
            if id(value) in copies and copies[id(value)][0] is value:
                swapped.append((module, attribute, value))
                setattr(module, attribute, copies[id(value)][1])
    find = SweepStatus.find
    SweepStatus.find = counter.find(find)  # type: ignore[method-assign]  # counted, then given back
    try:
        run()
    finally:
        SweepStatus.find = find  # type: ignore[method-assign]  # given back
        for module, attribute, value in swapped:
            setattr(module, attribute, value)
    return counter.total


@functools.cache  # the same runs for every build of the chapter in one process
def measured(algorithm: str, n: int) -> int:
    """The sign tests ``algorithm`` decides on random polygons of ``n`` vertices
    (``random-2opt:n:SEED``, :data:`SEEDS`), on average, rounded."""
    run = ALGORITHMS[algorithm]
    counts = []
    for seed in SEEDS:
        read = _random_polygon(n, seed)
        fresh = read.sub_polygon(range(read.n))  # nothing cached: its turns are tests too
        counts.append(count_sign_tests(functools.partial(run, fresh)))
    return round(sum(counts) / len(counts))


@functools.cache  # made once for all the algorithms measured on it
def _random_polygon(n: int, seed: int) -> Polygon:
    return read_polygon(f"random-2opt:{n}:{seed}")


__all__ = ["ALGORITHMS", "SEEDS", "count_sign_tests", "measured"]
