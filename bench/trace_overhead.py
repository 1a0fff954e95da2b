"""What the tracing decorators cost on a realistic traced geometric workload.

The workload is written once, with decorators, as the project's algorithms are. It
runs three ways, interleaved, ``--repeats`` times each (median reported):

(a) plain: every traced function in the workload's module swapped for its
    ``__wrapped__`` original (:func:`untraced`), i.e. undecorated code;
(b) off: decorated, no recording open;
(c) on: decorated, inside ``tracing.record()``.

The last line printed is ``trace overhead: off 1.0Nx, on N.NNx, NNN bytes/event``
with off = (b)/(a), on = (c)/(a) and bytes/event = ``len(log.to_json()) / len(events)``.

The default workload is the project's real divide-and-conquer triangulation (gravity
heuristic) of a seeded random 1,000-vertex star polygon; the traced functions of its
modules (and the ``HEURISTICS`` table) are unwrapped for the plain baseline. The traced
picks inside the heuristics are closures and stay traced even in (a), so (a) is a shade
slow and the ratios a shade low. ``--workload clip_ears`` measures the bench's own
self-contained ear clipping instead.

Run from the repository root: ``python -m bench.trace_overhead [--n 1000] [--repeats 5]``.
"""

from __future__ import annotations

import argparse
import contextlib
import gc
import inspect
import math
import random
import statistics
import sys
import time
from collections.abc import Callable, Iterable, Iterator, MutableMapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

try:
    import tracing
except ModuleNotFoundError:  # run as ``python bench/trace_overhead.py``: add the repo root
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    import tracing

Point = tuple[float, float]
TriangleIndices = tuple[int, int, int]


# --- the workload: incremental ear clipping -------------------------------------------


def star_polygon(n: int, seed: int = 2022) -> list[Point]:
    """A simple, counter-clockwise polygon: ``n`` random radii at sorted random angles.

    Examples
    --------
    >>> star_polygon(4, seed=1)[0]
    (44.64333785688646, 50.231994949372854)
    """
    rng = random.Random(seed)
    angles = sorted(rng.uniform(0.0, 2.0 * math.pi) for _ in range(n))
    radii = [rng.uniform(35.0, 100.0) for _ in range(n)]
    return [(r * math.cos(a), r * math.sin(a)) for a, r in zip(angles, radii, strict=True)]


def turn(a: Point, b: Point, c: Point) -> float:
    """Twice the signed area of abc: positive for a left (counter-clockwise) turn."""
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def in_triangle(p: Point, a: Point, b: Point, c: Point) -> bool:
    """Whether p lies in the closed counter-clockwise triangle abc."""
    return turn(a, b, p) >= 0 and turn(b, c, p) >= 0 and turn(c, a, p) >= 0


@tracing.traced(exclude_args=("points", "reflex"))
def is_ear(prev: int, vertex: int, nxt: int, points: list[Point], reflex: set[int]) -> bool:
    """Whether the triangle prev-vertex-nxt is an ear: convex and no reflex vertex inside."""
    a, b, c = points[prev], points[vertex], points[nxt]
    if turn(a, b, c) <= 0:
        return False
    return not any(in_triangle(points[r], a, b, c) for r in reflex if r not in (prev, vertex, nxt))


def clip_ears(points: list[Point]) -> list[TriangleIndices]:
    """Triangulate a simple counter-clockwise polygon by clipping ears (O(n²) on stars)."""
    n = len(points)
    prev = [(i - 1) % n for i in range(n)]
    nxt = [(i + 1) % n for i in range(n)]
    reflex = {i for i in range(n) if turn(points[prev[i]], points[i], points[nxt[i]]) <= 0}
    triangles: list[TriangleIndices] = []
    vertex, remaining, misses = 0, n, 0
    while remaining > 3:
        a, c = prev[vertex], nxt[vertex]
        if not is_ear(a, vertex, c, points, reflex):
            vertex, misses = c, misses + 1
            if misses > remaining:
                raise ValueError("no ear found: the polygon is not simple")
            continue
        corners = [points[a], points[vertex], points[c]]
        with tracing.Shape(f"T{len(triangles)}", "polygon", points=corners):
            triangles.append((a, vertex, c))
        nxt[a], prev[c] = c, a
        remaining, misses = remaining - 1, 0
        for v in (a, c):
            if v in reflex and turn(points[prev[v]], points[v], points[nxt[v]]) > 0:
                reflex.discard(v)
        vertex = a
    triangles.append((prev[vertex], vertex, nxt[vertex]))
    return triangles


# --- measuring ----------------------------------------------------------------------


@dataclass
class Overhead:
    """Median seconds of the three modes and the size of the recorded log."""

    plain: float
    off: float
    on: float
    events: int
    json_bytes: int

    @property
    def off_ratio(self) -> float:
        return self.off / self.plain

    @property
    def on_ratio(self) -> float:
        return self.on / self.plain

    @property
    def bytes_per_event(self) -> float:
        return self.json_bytes / max(self.events, 1)


def _unwrapped_member(member: Any) -> Any:
    """The undecorated version of a traced function or static/class method, else None."""
    if isinstance(member, staticmethod | classmethod):
        inner = _unwrapped_member(member.__func__)
        return None if inner is None else type(member)(inner)
    return member.__wrapped__ if hasattr(member, "__trace_spec__") else None


def _swaps(namespace: MutableMapping[str, Any]) -> Iterator[tuple[Any, str, Any]]:
    """(owner, name, undecorated) for every traced function and method in a namespace."""
    for name, value in list(namespace.items()):
        plain = _unwrapped_member(value)
        if plain is not None:
            yield namespace, name, plain
        elif isinstance(value, type):
            for attr, member in list(vars(value).items()):
                plain = _unwrapped_member(member)
                if plain is not None:
                    yield value, attr, plain


@contextlib.contextmanager
def untraced(namespaces: Iterable[MutableMapping[str, Any]]) -> Iterator[None]:
    """Temporarily replace every traced function (and method) by its ``__wrapped__``."""
    undo = []
    for namespace in namespaces:
        for owner, name, plain in _swaps(namespace):
            undo.append((owner, name, _get(owner, name)))
            _set(owner, name, plain)
    try:
        yield
    finally:
        for owner, name, original in reversed(undo):
            _set(owner, name, original)


def _get(owner: Any, name: str) -> Any:
    return owner[name] if isinstance(owner, dict) else vars(owner)[name]


def _set(owner: Any, name: str, value: Any) -> None:
    if isinstance(owner, dict):
        owner[name] = value
    else:
        setattr(owner, name, value)


def _seconds(run: Callable[[], Any]) -> tuple[float, Any]:
    """Time one run after a full garbage collection (so none is left over from before)."""
    gc.collect()
    start = time.perf_counter()
    result = run()
    return time.perf_counter() - start, result


def _run_mode(
    mode: str,
    workload: Callable[[Any], Any],
    data: Any,
    spaces: list[MutableMapping[str, Any]],
    meta: dict[str, Any],
) -> tuple[float, Any, tracing.Log | None]:
    """Run the workload once in ``mode``; return (seconds, result, log or None)."""
    if mode == "plain":
        with untraced(spaces):
            seconds, result = _seconds(lambda: getattr(workload, "__wrapped__", workload)(data))
        return seconds, result, None
    if mode == "off":
        return (*_seconds(lambda: workload(data)), None)
    with tracing.record(**meta) as log:
        seconds, result = _seconds(lambda: workload(data))
    return seconds, result, log


def measure(
    workload: Callable[[Any], Any],
    data: Any,
    *,
    repeats: int = 5,
    namespaces: Iterable[MutableMapping[str, Any]] | None = None,
    meta: dict[str, Any] | None = None,
) -> Overhead:
    """Time ``workload(data)`` plain, traced with recording off, and traced with it on.

    The modes take turns, in a rotating order, so drift in the machine's speed hits
    them alike; each run starts after a full garbage collection.

    Parameters
    ----------
    workload : callable
        The algorithm, written with ``@tracing.traced`` etc.; called as ``workload(data)``.
    data : Any
        Its input (not modified by a correct workload).
    repeats : int
        Runs per mode (≥ 5 for a meaningful median).
    namespaces : iterable of dict, optional
        Module namespaces whose traced functions are unwrapped for the plain baseline;
        defaults to the workload's own module.
    meta : dict, optional
        Metadata for the recording.
    """
    own_module = inspect.unwrap(workload).__globals__
    spaces = list(namespaces) if namespaces is not None else [own_module]
    modes = ["plain", "off", "on"]
    times: dict[str, list[float]] = {mode: [] for mode in modes}
    results, events, json_bytes = [], 0, 0
    for turn_index in range(repeats):
        for mode in modes[turn_index % 3 :] + modes[: turn_index % 3]:
            seconds, result, log = _run_mode(mode, workload, data, spaces, meta or {})
            times[mode].append(seconds)
            results.append(result)
            if log is not None:
                events, json_bytes = len(log.events), len(log.to_json())
            del log
    if any(result != results[0] for result in results):
        raise AssertionError("the workload gave different results in different modes")
    medians = {mode: statistics.median(values) for mode, values in times.items()}
    return Overhead(**medians, events=events, json_bytes=json_bytes)


def per_call_costs(repeats: int = 50_000) -> tuple[float, float, float]:
    """Nanoseconds per call of a trivial one-argument function: plain, off, on."""

    @tracing.traced
    def identity(x: int) -> int:
        return x

    def loop(function: Callable[[int], int]) -> float:
        start = time.perf_counter()
        for i in range(repeats):
            function(i)
        return (time.perf_counter() - start) / repeats * 1e9

    plain, off = loop(identity.__wrapped__), loop(identity)
    with tracing.record():
        on = loop(identity)
    return plain, off, on


def real_workload(n: int, seed: int, heuristic: str):
    """The project's divide-and-conquer on a random star polygon, and the namespaces to unwrap."""
    from geometry import diagonals, frame, gravity, lennes
    from geometry.polygon import Polygon
    from geometry.samples import make_sample

    polygon = Polygon.from_points(make_sample("random-star", n, seed))

    def workload(p: Polygon) -> list[TriangleIndices]:
        return lennes.divide_and_conquer(p, heuristic).triangles

    spaces = [vars(m) for m in (diagonals, frame, gravity, lennes)] + [diagonals.HEURISTICS]
    return workload, polygon, spaces


def main(argv: list[str] | None = None) -> None:
    """Measure a workload (the real divide-and-conquer by default) and print the report."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1000, help="polygon vertices")
    parser.add_argument("--seed", type=int, default=2022)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--workload", default="divide-and-conquer",
                        choices=["divide-and-conquer", "clip_ears"])
    parser.add_argument("--heuristic", default="gravity")
    options = parser.parse_args(argv)
    if options.workload == "clip_ears":
        workload, data, spaces = clip_ears, star_polygon(options.n, options.seed), None
        what = "clip_ears (the bench's own)"
    else:
        workload, data, spaces = real_workload(options.n, options.seed, options.heuristic)
        what = f"divide_and_conquer({options.heuristic})"
    meta = {"algorithm": options.workload, "polygon": f"star-{options.n}-{options.seed}"}
    result = measure(workload, data, repeats=options.repeats, namespaces=spaces, meta=meta)
    calls = per_call_costs()
    print(f"workload: {what} on a {options.n}-vertex random star polygon (seed {options.seed}), "
          f"median of {options.repeats} runs")  # fmt: skip
    print(f"  (a) plain              {result.plain * 1e3:9.1f} ms")
    print(f"  (b) traced, not recording {result.off * 1e3:6.1f} ms  {result.off_ratio:5.2f}x")
    print(f"  (c) traced, recording  {result.on * 1e3:9.1f} ms  {result.on_ratio:5.2f}x")
    print(f"log: {result.events} events, {result.json_bytes} bytes of JSON")
    print("per call of a trivial traced function: plain {:.0f} ns, off {:.0f} ns, on {:.0f} ns"
          .format(*calls))  # fmt: skip
    print(
        f"trace overhead: off {result.off_ratio:.2f}x, on {result.on_ratio:.2f}x, "
        f"{result.bytes_per_event:.0f} bytes/event"
    )


if __name__ == "__main__":
    main()
