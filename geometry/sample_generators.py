"""The shapes behind :mod:`geometry.samples`: families by size, random ones by seed.

Each function returns exactly ``n`` points that form a valid simple polygon. The
constructions keep margins far above float rounding: integer coordinates
(combs, orthogonal polygons) are exact, and the curved ones (stars, spirals, half discs)
keep every vertex in its own angular slot with chords well clear of the
neighbouring turn. Float coordinates are rounded to 6 decimals, which moves a
point by at most 1e-6, far inside those margins.

>>> star(4)
[(0.0, 10.0), (-4.0, 0.0), (-0.0, -10.0), (4.0, -0.0)]
>>> comb(12)[:6]
[(0, 0), (10, 0), (10, 10), (8, 10), (8, 2), (6, 2)]
"""

from __future__ import annotations

import math
import random

import numpy as np
import shapely

from geometry.errors import PolygonError
from geometry.polygon import Polygon
from geometry.predicates import Point
from geometry.validate import orient_array

_DECIMALS = 6


def _polar(radius: float, angle: float) -> Point:
    return (round(radius * math.cos(angle), _DECIMALS), round(radius * math.sin(angle), _DECIMALS))


# --- stars -------------------------------------------------------------------


def star(n: int) -> list[Point]:
    """Star with radii alternating 10 and 4 at equal angles (n ≥ 3); n = 10 has five points."""
    radii = (10.0, 4.0)
    return [_polar(radii[k % 2], math.pi / 2 + 2 * math.pi * k / n) for k in range(n)]


def random_star(n: int, rng: random.Random) -> list[Point]:
    """Star-shaped around the origin: vertex k keeps to the middle 40 % of slot k.

    Consecutive angles then differ by less than 2π·1.4/n < π (n ≥ 3), so the
    origin sees every edge and the ring is simple.
    """
    turn = rng.uniform(0, 2 * math.pi)
    points = []
    for k in range(n):
        angle = turn + 2 * math.pi * (k + 0.3 + 0.4 * rng.random()) / n
        points.append(_polar(10 * rng.uniform(0.3, 1.0), angle))
    return points


# --- spirals -----------------------------------------------------------------


def _spiral_turns(chain: int, width: float, gap: float, start: float, stretch: float) -> float:
    """Most turns (a multiple of 1/4, at most 20) keeping every chord clear.

    A chord between consecutive vertices cuts inside its arc by the sagitta
    r·(1 − cos(step/2)); it must stay below a quarter of the narrower of the
    band (``width``) and the gap between turns (``gap``). ``stretch`` bounds how
    much jitter lengthens one angular step.
    """
    best = 0.25
    for quarter in range(1, 81):
        turns = quarter / 4
        step = stretch * 2 * math.pi * turns / (chain - 1)
        reach = start + 2 * math.pi * turns + width / 2
        if reach * (1 - math.cos(step / 2)) > min(width, gap) / 4:
            break
        best = turns
    return best


def _spiral_band(
    n: int, turns: float, width: float, start: float, jitter: tuple[random.Random, float] | None
) -> list[Point]:
    """Outer chain outwards, inner chain back: a band of ``width`` along r = start + θ."""
    outer, inner = (n + 1) // 2, n // 2
    total = 2 * math.pi * turns
    points = []
    for count, side, reverse in ((outer, 1, False), (inner, -1, True)):
        for k in range(count):
            t = (count - 1 - k) if reverse else k
            angle, radial = total * t / (count - 1), 0.0
            if jitter is not None and 0 < t < count - 1:
                rng, amount = jitter
                angle += total / (count - 1) * rng.uniform(-0.25, 0.25)
                radial = rng.uniform(-amount, amount)
            points.append(_polar(start + angle + side * width / 2 + radial, angle))
    return points


def spiral(n: int) -> list[Point]:
    """Archimedean spiral band, n ≥ 6, up to 20 turns; band and gap both π wide."""
    width, start = math.pi, 2 * math.pi
    turns = _spiral_turns(n // 2, width, 2 * math.pi - width, start, 1.0)
    return _spiral_band(n, turns, width, start, None)


def random_spiral(n: int, rng: random.Random) -> list[Point]:
    """Spiral band of random width and length with jittered vertices, n ≥ 6, either hand."""
    width = rng.uniform(0.35, 0.65) * 2 * math.pi
    narrow = min(width, 2 * math.pi - width)
    start = rng.uniform(1.5, 3.0) * math.pi
    # Jitter stretches a step by at most 1.5 and moves a vertex radially by narrow/16,
    # so chords stay within narrow/4 + 2·narrow/16 < narrow of their neighbours.
    most = _spiral_turns(n // 2, width, 2 * math.pi - width, start, 1.5)
    turns = most * rng.uniform(0.6, 1.0)
    points = _spiral_band(n, turns, width, start, (rng, narrow / 16))
    return [(-x, y) for x, y in points] if rng.random() < 0.5 else points


# --- combs -------------------------------------------------------------------


def _comb(bar: int, teeth: list[tuple[int, int, int, int]]) -> list[Point]:
    """Comb on a bar of height ``bar``; teeth (left, right, height, tip) left to right.

    A tooth with ``tip`` > 0 gets a pointed top at its middle, ``tip`` above it.
    """
    points: list[Point] = [(0, 0), (teeth[-1][1], 0)]
    for t in range(len(teeth) - 1, -1, -1):
        left, right, height, tip = teeth[t]
        points.append((right, height))
        if tip:
            points.append(((left + right) // 2, height + tip))
        points.append((left, height))
        if t > 0:
            points += [(left, bar), (teeth[t - 1][1], bar)]
    return points


def comb(n: int) -> list[Point]:
    """Comb of n // 4 teeth (n ≥ 12), width and gap 2, height 10; n % 4 teeth get a tip."""
    count, tips = divmod(n, 4)
    return _comb(2, [(4 * t, 4 * t + 2, 10, int(t < tips)) for t in range(count)])


def random_comb(n: int, rng: random.Random) -> list[Point]:
    """Comb with random tooth widths, gaps, heights and tips (n ≥ 12), integer coordinates."""
    count, extra = divmod(n, 4)
    bar = rng.randint(1, 3)
    tipped = set(rng.sample(range(count), extra))
    teeth, x = [], 0
    for t in range(count):
        width = 2 * rng.randint(1, 3)  # even, so a tip sits on an integer
        tip = rng.randint(1, 3) if t in tipped else 0
        teeth.append((x, x + width, bar + rng.randint(2, 12), tip))
        x += width + 2 * rng.randint(1, 3)
    return _comb(bar, teeth)


# --- half discs --------------------------------------------------------------

#: how far the half disc's straight side bends in at its middle, a share of the radius: ear
#: clipping's count still grows fourfold when n doubles (2 % did too, but drawn in a legend
#: the side looked straight)
_DENT = 0.3


def half_disc(n: int) -> list[Point]:
    """A half disc of radius 10, its straight side dented in (n ≥ 4): n // 2 + 1 vertices on
    the arc, counter-clockwise from the bottom, the rest on the straight side, which bends
    in by 30 % of the radius at its middle (a dent the eye sees), so that they are reflex
    (from about 10,000 vertices, rounding straightens some near its ends). Ear clipping's
    worst case: its ears are cut along the arc, and the box of every ear it tests holds a
    share of the dented side, each vertex of which it must test."""
    arc = n // 2 + 1
    side = n - arc
    points = [_polar(10.0, -math.pi / 2 + math.pi * k / (arc - 1)) for k in range(arc)]
    for k in range(1, side + 1):
        t = k / (side + 1)
        points.append((round(10 * _DENT * math.sin(math.pi * t), _DECIMALS),
                       round(10 * (1 - 2 * t), _DECIMALS)))
    return points


# --- the fixed two-ears polygon ----------------------------------------------


def two_ears(bends: int = 4) -> list[Point]:
    """A zig-zag strip with pointed ends: its only ears are the two tips.

    Every other convex vertex has the opposite chain's reflex vertex inside its
    triangle; the tips stick out far enough (2 beyond a strip 2 thick, zig-zag
    6 high) for the vertices next to them to see the other chain too.
    """
    lower = [(4 * k, 6 * (k % 2)) for k in range(bends + 1)]
    upper = [(x, y + 2) for x, y in reversed(lower)]
    right_tip = (4 * bends + 2, lower[-1][1] + 1)
    return [*lower, right_tip, *upper, (-2, 1)]


# --- random 2-opt ------------------------------------------------------------


def _crossings(arr: np.ndarray) -> np.ndarray | None:
    """Pairs (i, j), i < j, of edges that cross properly; None on any touching contact."""
    n = len(arr)
    ends = np.roll(arr, -1, 0)
    edges = shapely.linestrings(np.stack([arr, ends], axis=1))
    i, j = shapely.STRtree(edges).query(edges)
    keep = (i < j) & (j != i + 1) & ~((i == 0) & (j == n - 1))
    i, j = i[keep], j[keep]
    s1 = orient_array(arr[i], ends[i], arr[j]) * orient_array(arr[i], ends[i], ends[j])
    s2 = orient_array(arr[j], ends[j], arr[i]) * orient_array(arr[j], ends[j], ends[i])
    if np.any((s1 <= 0) & (s2 <= 0) & ((s1 == 0) | (s2 == 0))):
        return None  # collinear or touching: a measure-zero draw, the caller redraws
    proper = (s1 < 0) & (s2 < 0)
    return np.stack([i[proper], j[proper]], axis=1)


def _disjoint_moves(pairs: np.ndarray, n: int) -> list[tuple[int, int]]:
    """Shortest-first crossing pairs whose reversals touch disjoint index ranges."""
    spans = pairs[:, 1] - pairs[:, 0]
    taken = np.zeros(n + 1, dtype=bool)
    moves = []
    for k in np.argsort(spans, kind="stable")[: 4 * n]:
        i, j = int(pairs[k, 0]), int(pairs[k, 1])
        if not taken[i : j + 2].any():
            taken[i : j + 2] = True
            moves.append((i, j))
    return moves


def _untangle(arr: np.ndarray) -> np.ndarray | None:
    """2-opt: reverse the path between crossing edges until none cross.

    Each reversal shortens the ring, so this ends; None if a draw is degenerate.
    """
    while True:
        pairs = _crossings(arr)
        if pairs is None:
            return None
        if len(pairs) == 0:
            return arr
        for i, j in _disjoint_moves(pairs, len(arr)):
            arr[i + 1 : j + 1] = arr[i + 1 : j + 1][::-1].copy()


def _is_simple(points: list[Point]) -> bool:
    try:
        Polygon.from_points(points)
    except PolygonError:
        return False
    return True


def random_2opt(n: int, rng: random.Random) -> list[Point]:
    """Random points in a 100 × 100 square joined in random order, then untangled by 2-opt."""
    while True:
        raw = [(round(rng.uniform(0, 100), 3), round(rng.uniform(0, 100), 3)) for _ in range(n)]
        ring = _untangle(np.array(raw, dtype=float))
        if ring is not None:
            points = [(float(x), float(y)) for x, y in ring]
            if _is_simple(points):
                return points


# --- random orthogonal -------------------------------------------------------

_RING8 = ((0, 1), (1, 1), (1, 0), (1, -1), (0, -1), (-1, -1), (-1, 0), (-1, 1))
_SIDES = ((0, 1), (1, 0), (0, -1), (-1, 0))
Cell = tuple[int, int]


def _can_add(cells: set[Cell], c: Cell) -> bool:
    """Whether adding cell c keeps the boundary one simple ring (no hole, no pinch).

    True when the occupied cells around c form one run in the cyclic 8-ring and
    that run holds a side neighbour (the digital-topology "simple point" test).
    """
    occupied = [(c[0] + dx, c[1] + dy) in cells for dx, dy in _RING8]
    runs = sum(1 for k in range(8) if occupied[k] and not occupied[k - 1])
    return runs == 1 and any(occupied[0::2])


def _is_corner(cells: set[Cell], x: int, y: int) -> bool:
    """A lattice vertex is a corner when 1 or 3 of its 4 cells are occupied."""
    count = sum((x - dx, y - dy) in cells for dx in (0, 1) for dy in (0, 1))
    return count in (1, 3)


def _corner_delta(cells: set[Cell], c: Cell) -> int:
    vertices = [(c[0] + dx, c[1] + dy) for dx in (0, 1) for dy in (0, 1)]
    before = sum(_is_corner(cells, x, y) for x, y in vertices)
    cells.add(c)
    after = sum(_is_corner(cells, x, y) for x, y in vertices)
    cells.discard(c)
    return after - before


def _grow(target: int, rng: random.Random) -> set[Cell]:
    """A random polyomino with a simple boundary and at most ``target`` corners."""
    cells, corners = {(0, 0)}, 4
    frontier = [(dx, dy) for dx, dy in _SIDES]
    while frontier and corners < target - 1:
        k = rng.randrange(len(frontier))
        frontier[k], frontier[-1] = frontier[-1], frontier[k]
        c = frontier.pop()
        if c in cells or not _can_add(cells, c):
            continue
        delta = _corner_delta(cells, c)
        if corners + delta > target:
            continue
        cells.add(c)
        corners += delta
        frontier += [(c[0] + dx, c[1] + dy) for dx, dy in _SIDES]
    return cells


def _boundary(cells: set[Cell]) -> list[Cell]:
    """Lattice points along the boundary, counter-clockwise (interior on the left)."""
    step: dict[Cell, Cell] = {}
    for x, y in sorted(cells):
        if (x, y - 1) not in cells:
            step[(x, y)] = (x + 1, y)
        if (x + 1, y) not in cells:
            step[(x + 1, y)] = (x + 1, y + 1)
        if (x, y + 1) not in cells:
            step[(x + 1, y + 1)] = (x, y + 1)
        if (x - 1, y) not in cells:
            step[(x, y + 1)] = (x, y)
    start = min(step)
    ring, v = [start], step[start]
    while v != start:
        ring.append(v)
        v = step[v]
    return ring


def random_orthogonal(n: int, rng: random.Random) -> list[Point]:
    """Orthogonal polygon on an integer grid (n ≥ 4), about a quarter of its vertices collinear."""
    cells = _grow(max(4, n - rng.randint(n // 8, n // 4)), rng)
    ring = _boundary(cells)
    corners = [_is_corner(cells, x, y) for x, y in ring]
    pad = n - sum(corners)
    scale = max(1, math.ceil((pad + sum(corners)) / len(ring)))
    # At ``scale`` every unit edge holds scale − 1 extra lattice points to pick from.
    fine: list[tuple[Point, bool]] = []
    for k, (x, y) in enumerate(ring):
        nx, ny = ring[(k + 1) % len(ring)]
        fine.append(((scale * x, scale * y), corners[k]))
        fine += [
            ((scale * x + s * (nx - x), scale * y + s * (ny - y)), False) for s in range(1, scale)
        ]
    spare = [k for k, (_, corner) in enumerate(fine) if not corner]
    keep = set(rng.sample(spare, pad)) | {k for k, (_, corner) in enumerate(fine) if corner}
    points = [fine[k][0] for k in sorted(keep)]
    shift = rng.randrange(n)
    points = points[shift:] + points[:shift]
    return points[::-1] if rng.random() < 0.5 else points
