"""What a sign test costs, before and after the predicates learnt to count themselves.

Since :func:`geometry.predicates.counting_sign_tests`, every exact predicate, batch and the
monotone sweep's bisection first reads one global (``counts_open``) to know whether a count
is open anywhere. This bench says what that costs: each predicate's time per call, and a
few whole runs, measured in today's tree and in the tree of ``--baseline`` (by default the
commit before the counting moved into the predicates), side by side with their ratio.

Each side runs in a child process of its own (``geometry`` and ``tracing`` of the baseline
unpacked with ``git archive``), ``--rounds`` times, the two sides taking turns so that a
busy machine slows both alike; a workload's time is its best (least disturbed) over all
rounds. Today's side also times its predicates with a count open (the cost of a measured
run, which the chapter's plot pays once).

The last line printed is ``sign tests after/before: geometric mean N.NNx, worst N.NNx (NAME)``.

Run from the repository root: ``python -m bench.predicates [--rounds 5] [--baseline REV]``.
"""

from __future__ import annotations

import argparse
import contextlib
import functools
import json
import math
import os
import random
import subprocess
import sys
import tarfile
import tempfile
import time
from collections.abc import Callable, Iterator
from io import BytesIO
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
#: the packages a baseline tree needs (geometry imports tracing, nothing else of ours)
PACKAGES = ("geometry", "tracing")
#: calls per timing of one predicate, and timings per round (the best is kept)
CALLS, TIMINGS = 2000, 5


def _points(k: int, seed: int) -> list[tuple[float, float]]:
    draw = random.Random(seed)
    return [(draw.uniform(-10, 10), draw.uniform(-10, 10)) for _ in range(k)]


def _per_call(call: Callable[[], object], calls: int) -> float:
    """Nanoseconds per call of ``call`` (which itself makes ``calls`` calls), best timing."""
    best = math.inf
    for _ in range(TIMINGS):
        start = time.process_time()  # CPU time: less disturbed by a busy machine
        call()
        best = min(best, time.process_time() - start)
    return best / calls * 1e9


def _workloads() -> dict[str, tuple[Callable[[], object], int]]:
    """Each workload and how many predicate calls (or runs) one go of it makes. Only names
    that both trees have: the predicates, the batches, the sweep status and the runners."""
    import numpy as np

    from geometry import batch, predicates, validate
    from geometry.polygon import Polygon
    from geometry.samples import make_sample
    from geometry.sweep_status import SweepStatus
    from geometry.triangulate import RUNNERS

    pts = _points(4 * CALLS, 1)
    triples = [(pts[i], pts[i + 1], pts[i + 2]) for i in range(0, 3 * CALLS, 3)]
    quads = [(pts[i], pts[i + 1], pts[i + 2], pts[i + 3]) for i in range(0, 4 * CALLS, 4)]
    grid = [((float(a[0] // 1), float(a[1] // 1)), (float(b[0] // 1), float(b[1] // 1)),
             (float(c[0] // 1), float(c[1] // 1))) for a, b, c in triples]
    orient, dot_sign, cross_sign = predicates.orient, predicates.dot_sign, predicates.cross_sign
    compare_distance = predicates.compare_distance
    compare_line_distance = predicates.compare_line_distance
    compare_angle, in_triangle = predicates.compare_angle, predicates.in_triangle
    xs8, ys8 = np.array([p[0] for p in pts[:8]]), np.array([p[1] for p in pts[:8]])
    many = np.array(pts[:1000])
    rolled = np.roll(many, 1, axis=0)
    a, b = (-1.0, -2.0), (3.0, 1.5)
    # a sweep status of 64 vertical edges, asked where 64 points between them lie
    ladder = [(float(i), y) for i in range(64) for y in (1.0, -1.0)] + [
        (i + 0.5, 0.0) for i in range(64)]
    status = SweepStatus(ladder, [k + 1 if k < 128 and k % 2 == 0 else k for k in
                                  range(len(ladder))])
    status.edges = list(range(0, 128, 2))
    queries = list(range(128, 192))
    # samples, not random-2opt polygons: those take seconds to make at these sizes
    runs = {(name, shape): Polygon.from_points(make_sample(shape, n)) for name, shape, n in
            (("monotone", "star", 2000), ("ear-clipping", "spiral", 1000),
             ("prune-and-search", "star", 300))}
    return {
        "orient": (lambda: [orient(*t) for t in triples], CALLS),
        "orient, small integers": (lambda: [orient(*t) for t in grid], CALLS),
        "dot_sign": (lambda: [dot_sign(*t) for t in triples], CALLS),
        "cross_sign": (lambda: [cross_sign(*t) for t in triples], CALLS),
        "compare_distance": (lambda: [compare_distance(*t) for t in triples], CALLS),
        # these two are always exact (rationals): a few calls are enough
        "compare_line_distance": (lambda: [compare_line_distance(*q) for q in quads[:200]], 200),
        "compare_angle": (lambda: [compare_angle(*q) for q in quads[:200]], 200),
        "in_triangle": (lambda: [in_triangle(*q) for q in quads], CALLS),
        "orient_many, 8 points": (lambda: [batch.orient_many(a, b, xs8, ys8)
                                           for _ in range(CALLS)], CALLS),
        "orient_many, 1000 points": (lambda: [batch.orient_many(a, b, many[:, 0], many[:, 1])
                                              for _ in range(200)], 200),
        "dot_sign_many, 1000 points": (lambda: [batch.dot_sign_many(a, many, many[::-1])
                                                for _ in range(200)], 200),
        "orient_array, 1000 rows": (lambda: [validate.orient_array(many, many[::-1], rolled)
                                             for _ in range(200)], 200),
        "SweepStatus.find, 64 edges": (lambda: [status.find(v) for v in queries * 30],
                                       len(queries) * 30),
        **{f"{name} run, {shape} {p.n}": (functools.partial(_fresh_run, RUNNERS[name], p), 1)
           for (name, shape), p in runs.items()},
    }


def _fresh_run(run: Callable[[Any], object], polygon: Any) -> object:
    return run(polygon.sub_polygon(range(polygon.n)))  # nothing cached: its turns too


def measure() -> dict[str, float]:
    """This tree's times (ns per call), and today's with a count open too."""
    from geometry import predicates

    assert Path(predicates.__file__).is_relative_to(Path.cwd()), "the wrong tree's geometry"
    times: dict[str, float] = {}
    for name, (call, calls) in _workloads().items():
        times[name] = _per_call(call, calls)
        counting = getattr(predicates, "counting_sign_tests", None)
        if counting is not None:
            with counting():
                times[f"{name} [counting]"] = _per_call(call, calls)
    return times


@contextlib.contextmanager
def baseline_tree(rev: str) -> Iterator[Path]:
    """The baseline's packages unpacked in a temporary directory."""
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", "--format=tar", rev,
                              *PACKAGES], check=True, capture_output=True).stdout
    with tempfile.TemporaryDirectory(prefix="bench-predicates-") as tmp:
        with tarfile.open(fileobj=BytesIO(archive)) as tar:
            tar.extractall(tmp, filter="data")
        yield Path(tmp)


def default_baseline() -> str:
    """The commit before the one that made the predicates count themselves."""
    found = subprocess.run(
        ["git", "-C", str(ROOT), "log", "--reverse", "--format=%H", "-S", "counts_open",
         "--", "geometry/predicates.py"], check=True, capture_output=True, text=True)
    first = found.stdout.split()
    if not first:
        raise SystemExit("no commit adds counts_open to geometry/predicates.py: "
                         "give --baseline REV")
    return f"{first[0]}^"


def _child(tree: Path | None) -> dict[str, float]:
    """One side's times, measured in a process of its own (its ``geometry`` first)."""
    first = tree or ROOT  # -m puts the working directory first on the path: its geometry
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(first), str(ROOT)])}
    done = subprocess.run([sys.executable, "-m", "bench.predicates", "--measure"],
                          env=env, capture_output=True, text=True, cwd=first)
    if done.returncode:
        raise SystemExit(f"the measuring child ({first}) failed:\n{done.stderr}")
    out = done.stdout
    times: dict[str, float] = json.loads(out)
    return times


def _best(rounds: list[dict[str, float]]) -> dict[str, float]:
    return {name: min(r[name] for r in rounds) for name in rounds[0]}


def _print(before: dict[str, float], after: dict[str, float], rev: str) -> None:
    print(f"sign tests: best of the rounds, ns per call (a run: ms); before = {rev}")
    print(f"{'workload':32} {'before':>10} {'after':>10} {'ratio':>7} {'counting':>10}")
    ratios: dict[str, float] = {}
    for name, old in before.items():
        new, counted = after[name], after.get(f"{name} [counting]", math.nan)
        ratios[name] = new / old
        scale = 1e-6 if " run, " in name else 1.0  # a whole run in ms
        print(f"{name:32} {old * scale:10.1f} {new * scale:10.1f} {new / old:6.2f}x "
              f"{counted * scale:10.1f}")
    worst = max(ratios, key=lambda k: ratios[k])
    mean = math.exp(sum(math.log(r) for r in ratios.values()) / len(ratios))
    print(f"sign tests after/before: geometric mean {mean:.2f}x, worst {ratios[worst]:.2f}x "
          f"({worst})")


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--baseline", help="the git revision to compare with")
    parser.add_argument("--measure", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.measure:  # a child: this tree's times, as JSON
        print(json.dumps(measure()))
        return
    rev = args.baseline or default_baseline()
    befores: list[dict[str, float]] = []
    afters: list[dict[str, float]] = []
    with baseline_tree(rev) as tree:
        for k in range(args.rounds):  # taking turns: first one side, then the other
            sides: list[tuple[Path | None, list[dict[str, float]]]] = [
                (tree, befores), (None, afters)]
            for side, into in sides if k % 2 == 0 else sides[::-1]:
                into.append(_child(side))
    _print(_best(befores), _best(afters), rev)


if __name__ == "__main__":
    main()


__all__ = ["main", "measure"]
