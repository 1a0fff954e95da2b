"""Hunting counterexamples: search small polygons for one on which a heuristic's claim is not
an inner diagonal, then shrink it.

A hand-written search, not hypothesis: the budget counts polygons (so the result depends on
the seed and the budget only, never on the clock), the generators are geometric (they build
the thesis's frame first, where the failures live), and the shrinker speaks of polygons
(drop a vertex, move a coordinate to a small integer, keep the polygon simple and the claim
wrong), which a shrinker of random choices cannot know.

The search
    Polygon number ``t`` (``t = 0, 1, …`` up to the budget) is drawn from its own
    ``random.Random(f"{seed}:{t}")``. Sizes go in rounds, fewest vertices first: round ``r``
    tries :data:`BATCH` polygons of each size from 4 to ``min(4 + r, max_vertices)``. Most
    polygons are built around the frame: B left-most at x = 0, A above and C below to its
    right, the other vertices on a small integer grid, most of them inside the triangle ABC
    (candidates) and the rest outside it (walls), joined in a random order; the others are
    the project's random 2-opt and orthogonal polygons. Each is judged exactly by
    :func:`geometry.check.is_inner_diagonal`.
The shrinker
    Drops vertices while the polygon stays valid and the claim wrong; then moves the
    coordinates to small integers (snapped to a grid, translated to the origin, each one
    towards 0), and drops vertices again, until nothing changes. The result is minimal:
    dropping any one vertex makes the polygon invalid or the claim right.

No manim here.

>>> result = hunt("scaling", budget=400, seed=0)
>>> result.found, result.polygon.n <= 5
(True, True)
>>> hunt("gravity", budget=50, seed=0).found
False
"""

from __future__ import annotations

import random
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field

from geometry.check import CheckResult, is_inner_diagonal
from geometry.errors import GeometryError
from geometry.frame import Diagonal
from geometry.polygon import Polygon
from geometry.predicates import Point, orient
from geometry.samples import make_sample
from usercode.errors import UserHeuristicError, UserHeuristicExit
from usercode.heuristic import UserHeuristic, run_heuristic

__all__ = [
    "BATCH",
    "Failure",
    "Hunt",
    "Shrunk",
    "candidates",
    "fails",
    "hunt",
    "in_general_position",
    "is_minimal",
    "reason",
    "shrink",
]

#: Polygons of each size per round of the search.
BATCH = 16
#: The frame's grid: coordinates 0 … GRID (a fine grid makes the thin triangles and narrow
#: walls failures need; the shrinker brings the coordinates down).
GRID = 30
#: How often a draw may come out invalid before the generator gives up on that polygon.
_ATTEMPTS = 40

Heuristic = str | UserHeuristic


@dataclass(frozen=True)
class Hunt:
    """What a hunt found.

    ``polygon`` (shrunk), ``diagonal`` (its indices into ``polygon.points``) and ``verdict``
    are None when nothing was found; so are ``diagonal`` and ``verdict`` when the finding is an
    ``error`` of a function of one's own (its one-line message: it raised, answered nonsense
    or ran out of time on ``polygon``). ``tried`` counts the polygons searched (not those the
    shrinker tried: ``checks``); ``skipped`` the draws of the budget that made no polygon (a
    generator gave up: large random simple polygons are hard to draw), so that ``tried +
    skipped`` is the budget when nothing was found; ``first`` is the size of the polygon found
    before shrinking; ``stopped``: the shrinking stopped early (too many of its trials ran out
    of time).
    """

    heuristic: str
    found: bool
    tried: int
    max_vertices: int
    seconds: float
    polygon: Polygon | None = None
    diagonal: tuple[int, int] | None = None
    verdict: CheckResult | None = None
    first: int | None = None
    checks: int = 0
    sizes: Mapping[int, int] = field(default_factory=dict)
    skipped: int = 0
    error: str | None = None
    stopped: bool = False

    @property
    def claim_name(self) -> str | None:
        if self.polygon is None or self.diagonal is None:
            return None
        return "".join(self.polygon.labels[i] for i in self.diagonal)


# --- judging ---------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Failure:
    """How a heuristic fails on a polygon: a claim that is not an inner diagonal (``claim`` and
    ``verdict``), or an error of a function of one's own (``error``: it raised, answered
    something that is not two vertices, or did not finish within the time limit)."""

    polygon: Polygon
    claim: Diagonal | None = None
    verdict: CheckResult | None = None
    error: UserHeuristicError | None = None

    @property
    def way(self) -> str:
        """What a shrunk polygon must still do: ``wrong claim``, or the error's
        :attr:`~usercode.errors.UserHeuristicError.way` (``timeout`` …)."""
        return "wrong claim" if self.error is None else self.error.way


def in_general_position(points: Sequence[Point]) -> bool:
    """Whether no three of the points lie on one line (decided exactly).

    >>> in_general_position([(0, 0), (2, 0), (1, 1), (0, 3)])
    True
    >>> in_general_position([(0, 0), (1, 1), (2, 2)])
    False
    """
    n = len(points)
    return all(orient(points[i], points[j], points[k]) != 0
               for i in range(n) for j in range(i + 1, n) for k in range(j + 1, n))


def fails(points: Sequence[Point], heuristic: Heuristic, way: str | None = None, *,
          general: bool = False) -> Failure | None:
    """How the heuristic fails when ``points`` make a valid polygon of at least four vertices
    on which its claim is not an inner diagonal, or on which a function of one's own fails
    (raises, answers nonsense, runs out of time); None otherwise. With ``way``, only a
    failure of that :attr:`Failure.way` counts. With ``general``, only a polygon in general
    position (:func:`in_general_position`) on which a wrong claim crosses an edge counts:
    one a class can see fail (not a claim that only passes through a vertex).

    A function of one's own that tries to end the program
    (:class:`~usercode.errors.UserHeuristicExit`) raises here, as does a built-in
    heuristic that refuses a polygon (ValueError)."""
    if len(points) < 4:
        return None
    try:
        polygon = Polygon.from_points(list(points))
    except GeometryError:
        return None
    if polygon.n != len(points):  # cleaning dropped a repeated point: not this polygon
        return None
    if general and not in_general_position(polygon.points):
        return None
    try:
        claim = run_heuristic(polygon, heuristic)
    except UserHeuristicExit:
        raise
    except UserHeuristicError as exc:
        found: Failure | None = Failure(polygon, error=exc)
    else:
        verdict = is_inner_diagonal(polygon, *claim.pair)
        seen = not general or verdict.code == "crosses"
        found = None if verdict.ok or not seen else Failure(polygon, claim, verdict)
    return found if found is not None and way in (None, found.way) else None


# --- generating --------------------------------------------------------------------------------------


def _frame_polygon(n: int, rng: random.Random, inside_share: float = 0.85) -> list[Point] | None:
    """B = (0, y) left-most, A above and C below to its right, n - 3 more grid points (a share
    ``inside_share`` of them in the closed triangle ABC), joined A, B, C, then the rest in a random order; None if no valid one came."""
    for _ in range(_ATTEMPTS):
        b = (0, rng.randint(0, GRID))
        a = (rng.randint(1, GRID), rng.randint(0, GRID))
        c = (rng.randint(1, GRID), rng.randint(0, GRID))
        if orient(a, b, c) <= 0:
            continue
        box = (max(a[0], c[0]), min(a[1], b[1], c[1]), max(a[1], b[1], c[1]))
        taken = {a, b, c}
        rest: list[Point] = []
        for _ in range(n - 3):
            want_inside = rng.random() < inside_share
            for _ in range(_ATTEMPTS):
                if want_inside:
                    p = (rng.randint(1, box[0]), rng.randint(box[1], box[2]))
                    if not _in_closed(a, b, c, p):
                        continue
                else:
                    p = (rng.randint(1, GRID), rng.randint(0, GRID))
                if p not in taken:
                    break
            else:
                break
            taken.add(p)
            rest.append(p)
        if len(rest) != n - 3:
            continue
        for _ in range(8):
            rng.shuffle(rest)
            points = [a, b, c, *rest]
            if not _maybe_simple(points):
                continue
            try:
                Polygon.from_points(points)
            except GeometryError:
                continue
            return points
    return None


def _cross(o: Point, p: Point, q: Point) -> float:
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])


def _in_closed(a: Point, b: Point, c: Point, p: Point) -> bool:
    """Whether integer point p lies in the closed ccw triangle abc (integer arithmetic)."""
    return _cross(a, b, p) >= 0 and _cross(b, c, p) >= 0 and _cross(c, a, p) >= 0


def _meet(p: Point, q: Point, r: Point, s: Point) -> bool:
    """Whether the closed integer segments pq and rs have a point in common."""
    d1, d2, d3, d4 = _cross(p, q, r), _cross(p, q, s), _cross(r, s, p), _cross(r, s, q)
    if ((d1 > 0) != (d2 > 0) or d1 == 0 or d2 == 0) and ((d3 > 0) != (d4 > 0) or d3 == 0
                                                          or d4 == 0):
        if d1 == d2 == 0:  # collinear: do the boxes overlap?
            return (min(p[0], q[0]) <= max(r[0], s[0]) and min(r[0], s[0]) <= max(p[0], q[0])
                    and min(p[1], q[1]) <= max(r[1], s[1])
                    and min(r[1], s[1]) <= max(p[1], q[1]))
        return True
    return False


def _maybe_simple(points: list[Point]) -> bool:
    """A quick filter before the real check: False when two edges that share no vertex meet
    (then the ring is surely not simple)."""
    n = len(points)
    edges = [(points[k], points[(k + 1) % n]) for k in range(n)]
    for i in range(n):
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue
            if _meet(*edges[i], *edges[j]):
                return False
    return True


def _sample(name: str) -> Callable[[int, random.Random], list[Point] | None]:
    def make(n: int, rng: random.Random) -> list[Point] | None:
        try:
            return make_sample(name, n, rng.randrange(2**31))
        except GeometryError:
            return None
    return make


#: The generators and their weights.
GENERATORS: tuple[tuple[str, Callable[[int, random.Random], list[Point] | None], float], ...] = (
    ("frame", _frame_polygon, 0.8),
    ("2-opt", _sample("random-2opt"), 0.12),
    ("orthogonal", _sample("random-orthogonal"), 0.08),
)


def _sizes(max_vertices: int) -> Iterator[int]:
    """4; 4, 5; 4, 5, 6; … each :data:`BATCH` times, capped at ``max_vertices``: forever."""
    r = 0
    while True:
        for n in range(4, min(4 + r, max_vertices) + 1):
            for _ in range(BATCH):
                yield n
        r += 1


def candidates(
    budget: int, seed: int = 0, max_vertices: int = 8
) -> Iterator[tuple[int, int, list[Point] | None]]:
    """The search's polygons, in order: ``(t, points)`` for ``t`` in ``range(budget)``
    (points None when a generator gave up), each from its own ``Random(f"{seed}:{t}")``."""
    names = [g for _, g, _ in GENERATORS]
    weights = [w for _, _, w in GENERATORS]
    for t, n in zip(range(budget), _sizes(max(4, max_vertices)), strict=False):
        rng = random.Random(f"{seed}:{t}")
        make = rng.choices(names, weights)[0]
        yield t, n, make(n, rng)


# --- shrinking -----------------------------------------------------------------------------------------

#: Trials that may run out of time while one polygon is shrunk (each costs the whole limit):
#: then the shrinker stops with the smallest polygon so far.
MAX_SHRINK_TIMEOUTS = 8


class _Enough(Exception):
    """Too many trials ran out of time: stop shrinking."""


class _Trials:
    """The shrinker's trials: each judged as failing the same way as the first (``way``), or
    not; counted (``checks``), and stopped by :class:`_Enough` after
    :data:`MAX_SHRINK_TIMEOUTS` that ran out of time."""

    def __init__(self, heuristic: Heuristic, first: Failure, general: bool = False) -> None:
        self.heuristic, self.way, self.general = heuristic, first.way, general
        self.best = first  # the last failure found: the polygon the shrinker holds
        self.checks = self.timeouts = 0

    def fails(self, points: Sequence[Point]) -> Failure | None:
        self.checks += 1
        found = fails(points, self.heuristic, general=self.general)
        if found is not None and found.way == "timeout":
            self.timeouts += 1
            if self.timeouts > MAX_SHRINK_TIMEOUTS:
                raise _Enough
        if found is None or found.way != self.way:
            return None
        self.best = found
        return found


def _drop_vertices(points: list[Point], trials: _Trials) -> list[Point]:
    changed = True
    while changed:
        changed = False
        for k in range(len(points)):
            found = trials.fails(points[:k] + points[k + 1:])
            if found is not None:
                points = list(found.polygon.points)
                changed = True
                break
    return points


def _snap(points: list[Point], trials: _Trials) -> list[Point]:
    """Integer coordinates: snapped to a grid (floats), translated to the origin."""
    if not all(float(x).is_integer() and float(y).is_integer() for x, y in points):
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        span = max(max(xs) - min(xs), max(ys) - min(ys)) or 1
        for g in (4, 6, 8, 10, 12, 16, 20, 30, 50, 100, 1000):
            found = trials.fails([(round((x - min(xs)) * g / span),
                                   round((y - min(ys)) * g / span)) for x, y in points])
            if found is not None:
                points = list(found.polygon.points)
                break
        else:
            return points
    points = [(int(x), int(y)) for x, y in points]
    mx, my = min(p[0] for p in points), min(p[1] for p in points)
    found = trials.fails([(x - mx, y - my) for x, y in points])
    return list(found.polygon.points) if found is not None else points


def _towards_zero(v: int) -> list[int]:
    out = [0, v // 2 if v > 0 else -((-v) // 2), v - 1 if v > 0 else v + 1]
    seen: list[int] = []
    for w in out:
        if w != v and abs(w) < abs(v) and w not in seen:
            seen.append(w)
    return seen


def _scale_down(points: list[Point], trials: _Trials) -> list[Point]:
    """The whole polygon scaled by 1/2, 2/3, 3/4 or 4/5 (rounded) while it still fails."""
    if not all(float(x).is_integer() and float(y).is_integer() for x, y in points):
        return points
    changed = True
    while changed:
        changed = False
        for num, den in ((1, 2), (2, 3), (3, 4), (4, 5)):
            trial = [(round(x * num / den), round(y * num / den)) for x, y in points]
            found = trials.fails(trial)
            if found is not None and found.polygon.points != tuple(points):
                points = [(int(x), int(y)) for x, y in found.polygon.points]
                changed = True
                break
    return points


def _move_coordinates(points: list[Point], trials: _Trials) -> list[Point]:
    if not all(float(x).is_integer() and float(y).is_integer() for x, y in points):
        return points
    changed = True
    rounds = 0
    while changed and rounds < 200:
        changed = False
        rounds += 1
        for k in range(len(points)):
            for axis in (0, 1):
                for w in _towards_zero(int(points[k][axis])):
                    moved = list(points[k])
                    moved[axis] = w
                    trial = [*points[:k], (int(moved[0]), int(moved[1])), *points[k + 1:]]
                    found = trials.fails(trial)
                    if found is not None:
                        points = [(int(x), int(y)) for x, y in found.polygon.points]
                        changed = True
                        break
                if changed:
                    break
            if changed:
                break
    return points


def shrink(points: Sequence[Point], heuristic: Heuristic,
           found: Failure | None = None, *, general: bool = False) -> Shrunk:
    """Shrink a failing polygon (see the module docs) while it fails the same way (a wrong
    claim; or the same error of a function of one's own: :attr:`Failure.way`): the minimal
    failure, how many checks it took, and whether it stopped early (too many trials ran out
    of time: :data:`MAX_SHRINK_TIMEOUTS`). ``found``: how ``points`` fail, if known (a
    polygon that runs out of time is not run again).

    Raises ValueError if ``points`` is not a failing polygon to begin with.
    """
    found = found if found is not None else fails(points, heuristic, general=general)
    if found is None:
        raise ValueError("not a counterexample: nothing to shrink")
    trials = _Trials(heuristic, found, general)
    current = list(found.polygon.points)
    stopped = False
    try:
        while True:
            before = current
            for step in (_drop_vertices, _snap, _scale_down, _move_coordinates):
                current = step(current, trials)
            if current == before:
                break
    except _Enough:  # the last failure found is a step further than ``current``
        stopped = True
    return Shrunk(trials.best, trials.checks, stopped)


@dataclass(frozen=True)
class Shrunk:
    """What :func:`shrink` made: the minimal ``failure``, the ``checks`` it took, and whether
    it ``stopped`` early because too many trials ran out of time."""

    failure: Failure
    checks: int
    stopped: bool = False


def is_minimal(polygon: Polygon, heuristic: Heuristic, way: str = "wrong claim", *,
               general: bool = False) -> bool:
    """Whether dropping any one vertex makes the polygon invalid or stops it failing ``way``
    (in general position, crossing an edge, with ``general``)."""
    pts = list(polygon.points)
    return all(fails(pts[:k] + pts[k + 1:], heuristic, way, general=general) is None
               for k in range(len(pts)))


# --- the hunt --------------------------------------------------------------------------------------------


def _name(heuristic: Heuristic) -> str:
    return heuristic.spec if isinstance(heuristic, UserHeuristic) else heuristic


def hunt(heuristic: Heuristic, *, budget: int = 5000, seed: int = 0, max_vertices: int = 8,
         progress: Callable[[int], None] | None = None, general: bool = False) -> Hunt:
    """Search up to ``budget`` polygons of 4 … ``max_vertices`` vertices for one on which the
    heuristic fails (its claim is not an inner diagonal, or a function of one's own raises,
    answers nonsense or runs out of time); shrink the first found.

    ``progress(k)`` is told of every ``k`` polygons drawn. The result depends on the
    heuristic, the budget, the seed and ``max_vertices`` only (``seconds`` aside; and which
    polygons run out of time, for a function that does). A function of one's own that tries
    to end the program raises :class:`~usercode.errors.UserHeuristicExit`.
    ``general``: only polygons in general position whose wrong claim crosses an edge count,
    and the shrinker keeps them so (:func:`fails`; the lecture shows such a one).
    """
    start = time.perf_counter()
    tried = skipped = 0
    sizes: dict[int, int] = {}
    for _t, n, points in candidates(budget, seed, max_vertices):
        if progress is not None:
            progress(1)
        if points is None:
            skipped += 1
            continue
        tried += 1
        sizes[n] = sizes.get(n, 0) + 1
        found = fails(points, heuristic, general=general)
        if found is not None:
            shrunk = shrink(points, heuristic, found, general=general)
            failure = shrunk.failure
            return Hunt(_name(heuristic), True, tried, max_vertices,
                        time.perf_counter() - start, failure.polygon,
                        failure.claim.pair if failure.claim is not None else None,
                        failure.verdict, first=found.polygon.n, checks=shrunk.checks,
                        sizes=sizes, skipped=skipped,
                        error=str(failure.error) if failure.error is not None else None,
                        stopped=shrunk.stopped)
    return Hunt(_name(heuristic), False, tried, max_vertices, time.perf_counter() - start,
                sizes=sizes, skipped=skipped)


# --- in words --------------------------------------------------------------------------------------------


def _coordinate(x: float) -> str:
    return f"{x:.2f}".rstrip("0").rstrip(".") if not float(x).is_integer() else str(int(x))


def _point(p: Point) -> str:
    return f"({_coordinate(float(p[0]))}, {_coordinate(float(p[1]))})"


def reason(result: Hunt) -> str:
    """Why the claim is wrong, as a clause: ``crosses edge E–A at (2.86, 6.36)``."""
    polygon, verdict = result.polygon, result.verdict
    assert polygon is not None and verdict is not None and result.diagonal is not None
    i, j = result.diagonal
    why = verdict.why or "is not an inner diagonal"
    for seg in (f"{polygon.labels[i]}–{polygon.labels[j]}", f"{polygon.labels[i]}"):
        if why.startswith(seg + " "):
            why = why[len(seg) + 1:]
            break
    if verdict.point is not None and " at (" in why:
        why = why[: why.rindex(" at (")] + f" at {_point(verdict.point)}"
    if verdict.code == "through-vertex" and verdict.point is not None:
        head = why[: why.rindex(" (")] if " (" in why else why
        why = f"{head} {_point(verdict.point)}"
    return why


def verdict_line(result: Hunt) -> str:
    """``scaling is wrong: on this 5-vertex polygon it claims BD, which crosses edge E–A at
    (2.86, 6.36)``; ``mine.py:f fails on this 4-vertex polygon: f raised …`` for an error of
    a function of one's own; or ``no counterexample in 2,000 polygons of up to 8 vertices in
    1.2 s`` (and how many draws of the budget made no polygon, if any did)."""
    if not result.found:
        polygons = "1 polygon" if result.tried == 1 else f"{result.tried:,} polygons"
        return (f"no counterexample in {polygons} of up to {result.max_vertices} vertices in "
                f"{result.seconds:.1f} s{skipped_note(result)}")
    assert result.polygon is not None
    if result.error is not None:
        return (f"{result.heuristic} fails on this {result.polygon.n}-vertex polygon: "
                f"{result.error}")
    return (f"{result.heuristic} is wrong: on this {result.polygon.n}-vertex polygon it claims "
            f"{result.claim_name}, which {reason(result)}")


def skipped_note(result: Hunt) -> str:
    """Why fewer polygons were tried than the budget allowed, if they were: `` (78 of the 1,000
    draws made no simple polygon)``; empty otherwise.

    >>> skipped_note(Hunt("gravity", False, 922, 20, 1.0, skipped=78))
    ' (78 of the 1,000 draws made no simple polygon)'
    >>> verdict_line(Hunt("gravity", False, 1, 8, 0.01))
    'no counterexample in 1 polygon of up to 8 vertices in 0.0 s'
    """
    if not result.skipped:
        return ""
    drawn = result.tried + result.skipped
    return f" ({result.skipped:,} of the {drawn:,} draws made no simple polygon)"


def polygon_lines(polygon: Polygon) -> list[str]:
    """``A (1, 4)`` for each vertex, counter-clockwise."""
    return [f"  {label} {_point(p)}" for label, p in zip(polygon.labels, polygon.points,
                                                        strict=True)]
