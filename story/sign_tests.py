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

The predicates count themselves while a count is open in the thread (or task) that calls
them (:func:`count_sign_tests`), the algorithms unchanged: a count is of the run itself,
with no recording open and no verification after.
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
from collections.abc import Callable
from typing import Any

from geometry import predicates
from geometry.io import read_polygon
from geometry.lennes import divide_and_conquer
from geometry.polygon import Polygon
from geometry.results import Triangulation
from geometry.samples import is_seeded
from geometry.triangulate import RUNNERS

#: the runs a plot measures: random simple polygons ``random-2opt:n:SEED``, these seeds (a
#: seeded family; a family by size alone, such as ``half-disc``, is one polygon a size)
SEEDS = (1, 2, 3)
#: the algorithms that can be measured, as :func:`geometry.triangulate.triangulate` names
#: them (divide and conquer with Gravity, as the lecture runs it)
ALGORITHMS: dict[str, Callable[[Polygon], Triangulation]] = {
    "divide-and-conquer": lambda p: divide_and_conquer(p, "gravity"),
    **{name: RUNNERS[name] for name in ("ear-clipping-naive", "ear-clipping",
                                        "prune-and-search", "monotone")},
}


def count_sign_tests(run: Callable[[], Any]) -> int:
    """How many sign tests ``run()`` decides (its result is dropped), in this thread only:
    the predicates count themselves (:func:`geometry.predicates.counting_sign_tests`)."""
    with predicates.counting_sign_tests() as tests:
        run()
    return tests.total


@functools.cache  # the same runs for every build of the chapter in one process
def measured(algorithm: str, n: int, shape: str = "random-2opt") -> int:
    """The sign tests ``algorithm`` decides on polygons of ``n`` vertices of the sample
    family ``shape``: random ones (``random-2opt:n:SEED``, :data:`SEEDS`) on average,
    rounded; a family by size alone (``half-disc:n``), its one polygon.

    >>> measured("ear-clipping", 40, "half-disc") > 4 * measured("ear-clipping", 20, "half-disc") / 2
    True
    """
    run = ALGORITHMS[algorithm]
    counts = []
    for seed in (SEEDS if is_seeded(shape) else (0,)):
        read = _polygon(shape, n, seed)
        fresh = read.sub_polygon(range(read.n))  # nothing cached: its turns are tests too
        counts.append(count_sign_tests(functools.partial(run, fresh)))
    return round(sum(counts) / len(counts))


@functools.cache  # made once for all the algorithms measured on it
def _polygon(shape: str, n: int, seed: int) -> Polygon:
    return read_polygon(f"{shape}:{n}:{seed}" if is_seeded(shape) else f"{shape}:{n}")


__all__ = ["ALGORITHMS", "SEEDS", "count_sign_tests", "measured"]
