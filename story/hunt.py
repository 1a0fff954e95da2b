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
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from geometry.check import Verdict, is_inner_diagonal
from geometry.errors import GeometryError
from geometry.frame import Diagonal
from geometry.polygon import Polygon
from geometry.predicates import Point, orient
from geometry.samples import make_sample
from geometry.user_heuristics import UserHeuristic, run_heuristic

__all__ = ["BATCH", "Hunt", "candidates", "fails", "hunt", "is_minimal", "reason", "shrink"]

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
    are None when nothing was found. ``tried`` counts the polygons searched (not those the
    shrinker tried: ``checks``); ``first`` is the size of the polygon found before shrinking.
    """

    heuristic: str
    found: bool
    tried: int
    max_vertices: int
    seconds: float
    polygon: Polygon | None = None
    diagonal: tuple[int, int] | None = None
    verdict: Verdict | None = None
    first: int | None = None
    checks: int = 0
    sizes: dict[int, int] = field(default_factory=dict)

    @property
    def claim_name(self) -> str | None:
        if self.polygon is None or self.diagonal is None:
            return None
        return "".join(self.polygon.labels[i] for i in self.diagonal)


# --- judging ---------------------------------------------------------------------------------------


def fails(points: Sequence[Point], heuristic: Heuristic) -> tuple[Polygon, Diagonal, Verdict] | None:
    """The polygon, claim and verdict when ``points`` make a valid polygon of at least four
    vertices on which the heuristic's claim is not an inner diagonal; None otherwise.

    A heuristic that raises (a user's: :class:`~geometry.user_heuristics.UserHeuristicError`)
    raises here too."""
    if len(points) < 4:
        return None
    try:
        polygon = Polygon.from_points(list(points))
    except GeometryError:
        return None
    if polygon.n != len(points):  # cleaning dropped a repeated point: not this polygon
        return None
    claim = run_heuristic(polygon, heuristic)
    verdict = is_inner_diagonal(polygon, *claim.pair)
    return None if verdict.ok else (polygon, claim, verdict)


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


def _cross(o: Point, p: Point, q: Point):
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


def _sizes(max_vertices: int):
    """4; 4, 5; 4, 5, 6; … each :data:`BATCH` times, capped at ``max_vertices``: forever."""
    r = 0
    while True:
        for n in range(4, min(4 + r, max_vertices) + 1):
            for _ in range(BATCH):
                yield n
        r += 1


def candidates(budget: int, seed: int = 0, max_vertices: int = 8):
    """The search's polygons, in order: ``(t, points)`` for ``t`` in ``range(budget)``
    (points None when a generator gave up), each from its own ``Random(f"{seed}:{t}")``."""
    names = [g for _, g, _ in GENERATORS]
    weights = [w for _, _, w in GENERATORS]
    for t, n in zip(range(budget), _sizes(max(4, max_vertices)), strict=False):
        rng = random.Random(f"{seed}:{t}")
        make = rng.choices(names, weights)[0]
        yield t, n, make(n, rng)


# --- shrinking -----------------------------------------------------------------------------------------


def _drop_vertices(points: list[Point], heuristic: Heuristic, count: list[int]) -> list[Point]:
    changed = True
    while changed:
        changed = False
        for k in range(len(points)):
            trial = points[:k] + points[k + 1:]
            count[0] += 1
            found = fails(trial, heuristic)
            if found is not None:
                points = list(found[0].points)
                changed = True
                break
    return points


def _snap(points: list[Point], heuristic: Heuristic, count: list[int]) -> list[Point]:
    """Integer coordinates: snapped to a grid (floats), translated to the origin."""
    if not all(float(x).is_integer() and float(y).is_integer() for x, y in points):
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        span = max(max(xs) - min(xs), max(ys) - min(ys)) or 1
        for g in (4, 6, 8, 10, 12, 16, 20, 30, 50, 100, 1000):
            trial = [(round((x - min(xs)) * g / span), round((y - min(ys)) * g / span))
                     for x, y in points]
            count[0] += 1
            found = fails(trial, heuristic)
            if found is not None:
                points = list(found[0].points)
                break
        else:
            return points
    points = [(int(x), int(y)) for x, y in points]
    mx, my = min(p[0] for p in points), min(p[1] for p in points)
    trial = [(x - mx, y - my) for x, y in points]
    count[0] += 1
    found = fails(trial, heuristic)
    return list(found[0].points) if found is not None else points


def _towards_zero(v: int) -> list[int]:
    out = [0, v // 2 if v > 0 else -((-v) // 2), v - 1 if v > 0 else v + 1]
    seen: list[int] = []
    for w in out:
        if w != v and abs(w) < abs(v) and w not in seen:
            seen.append(w)
    return seen


def _scale_down(points: list[Point], heuristic: Heuristic, count: list[int]) -> list[Point]:
    """The whole polygon scaled by 1/2, 2/3, 3/4 or 4/5 (rounded) while it still fails."""
    if not all(float(x).is_integer() and float(y).is_integer() for x, y in points):
        return points
    changed = True
    while changed:
        changed = False
        for num, den in ((1, 2), (2, 3), (3, 4), (4, 5)):
            trial = [(round(x * num / den), round(y * num / den)) for x, y in points]
            count[0] += 1
            found = fails(trial, heuristic)
            if found is not None and found[0].points != tuple(points):
                points = [(int(x), int(y)) for x, y in found[0].points]
                changed = True
                break
    return points


def _move_coordinates(points: list[Point], heuristic: Heuristic, count: list[int]) -> list[Point]:
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
                    count[0] += 1
                    found = fails(trial, heuristic)
                    if found is not None:
                        points = [(int(x), int(y)) for x, y in found[0].points]
                        changed = True
                        break
                if changed:
                    break
            if changed:
                break
    return points


def shrink(points: Sequence[Point], heuristic: Heuristic,
           count: list[int] | None = None) -> tuple[Polygon, Diagonal, Verdict]:
    """Shrink a failing polygon (see the module docs): the minimal polygon, claim and verdict.

    Raises ValueError if ``points`` is not a failing polygon to begin with.
    """
    count = count if count is not None else [0]
    found = fails(points, heuristic)
    if found is None:
        raise ValueError("not a counterexample: nothing to shrink")
    current = list(found[0].points)
    while True:
        before = current
        current = _drop_vertices(current, heuristic, count)
        current = _snap(current, heuristic, count)
        current = _scale_down(current, heuristic, count)
        current = _move_coordinates(current, heuristic, count)
        if current == before:
            break
    result = fails(current, heuristic)
    assert result is not None
    return result


def is_minimal(polygon: Polygon, heuristic: Heuristic) -> bool:
    """Whether dropping any one vertex makes the polygon invalid or the claim right."""
    pts = list(polygon.points)
    return all(fails(pts[:k] + pts[k + 1:], heuristic) is None for k in range(len(pts)))


# --- the hunt --------------------------------------------------------------------------------------------


def _name(heuristic: Heuristic) -> str:
    return heuristic.spec if isinstance(heuristic, UserHeuristic) else heuristic


def hunt(heuristic: Heuristic, *, budget: int = 5000, seed: int = 0, max_vertices: int = 8,
         progress: Callable[[int], None] | None = None) -> Hunt:
    """Search up to ``budget`` polygons of 4 … ``max_vertices`` vertices for one on which the
    heuristic's claim is not an inner diagonal; shrink the first found.

    ``progress(k)`` is told of every ``k`` polygons tried. The result depends on the
    heuristic, the budget, the seed and ``max_vertices`` only (``seconds`` aside).
    """
    start = time.perf_counter()
    tried = 0
    sizes: dict[int, int] = {}
    for _t, n, points in candidates(budget, seed, max_vertices):
        if progress is not None:
            progress(1)
        if points is None:
            continue
        tried += 1
        sizes[n] = sizes.get(n, 0) + 1
        found = fails(points, heuristic)
        if found is not None:
            count = [0]
            polygon, claim, verdict = shrink(points, heuristic, count)
            return Hunt(_name(heuristic), True, tried, max_vertices,
                        time.perf_counter() - start, polygon, claim.pair, verdict,
                        first=found[0].n, checks=count[0], sizes=sizes)
    return Hunt(_name(heuristic), False, tried, max_vertices, time.perf_counter() - start,
                sizes=sizes)


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
    (2.86, 6.36)``, or ``no counterexample in 2,000 polygons of up to 8 vertices in 1.2 s``."""
    if not result.found:
        return (f"no counterexample in {result.tried:,} polygons of up to "
                f"{result.max_vertices} vertices in {result.seconds:.1f} s")
    assert result.polygon is not None
    return (f"{result.heuristic} is wrong: on this {result.polygon.n}-vertex polygon it claims "
            f"{result.claim_name}, which {reason(result)}")


def polygon_lines(polygon: Polygon) -> list[str]:
    """``A (1, 4)`` for each vertex, counter-clockwise."""
    return [f"  {label} {_point(p)}" for label, p in zip(polygon.labels, polygon.points,
                                                        strict=True)]
