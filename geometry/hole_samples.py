"""Generated polygons with holes, for tests and benchmarks: a round slice of Swiss cheese.

The outer ring is star-shaped about the origin (radii in [0.9, 1], angles in
order), so it is simple; each hole is star-shaped about the centre of its own
cell of a grid inside the square [-0.6, 0.6]² and stays within 0.4 of the
cell's width of that centre, so holes lie apart and inside. Holes are given
counter-clockwise, as many files give them (the reader turns them clockwise).

>>> [len(ring) for ring in HOLE_SAMPLES["keyhole"]]
[8, 3, 4]
>>> rings = swiss_cheese(40, 4, seed=1)
>>> [len(r) for r in rings]
[20, 5, 5, 5, 5]
>>> swiss_cheese(40, 4, seed=1) == rings
True
"""

from __future__ import annotations

import math
from types import MappingProxyType

import numpy as np

from geometry.predicates import Point

#: Fixed polygons with holes, by name (``trex check keyhole``): ``keyhole``, the explainer's
#: fruit with two holes (a triangle and a quadrilateral, their bridges sharing a vertex),
#: in general position: no three of its vertices, the holes' counted, on one line (issue 22
#: item 3). Its a₁ stood at (2, 3), on one line with E and c₁ and with d₂ and c₂, and its a₂
#: at (5.5, 6.5), halfway from F to A; each moved by a quarter, a step floats hold exactly
#: (the exact predicates judge the points as written, not a decimal's nearest float).
HOLE_SAMPLES: MappingProxyType[str, tuple[tuple[Point, ...], ...]] = MappingProxyType({
    "keyhole": (
        ((0, 0), (6, -1), (10, 1), (11, 5), (9, 9), (4, 10), (0, 8), (-1, 4)),
        ((2, 2.75), (4, 2.5), (3.5, 5)),
        ((6, 4), (8, 4.5), (7.5, 7), (5.5, 6.25)),
    ),
})


def _star(center: Point, radius: tuple[float, float], k: int, rng: np.random.Generator) -> list[Point]:
    """k points round ``center`` at increasing angles, radii between radius[0] and radius[1].

    The radius is a few random waves plus a little noise, so the edges stay short
    however many points there are (and the ring has reflex vertices).
    """
    jitter = rng.uniform(-0.3, 0.3, k) * (2 * math.pi / k)
    angles = (np.arange(k) * 2 * math.pi / k + jitter + rng.uniform(0, 2 * math.pi)) % (2 * math.pi)
    angles.sort()
    low, high = radius
    waves = sum(rng.uniform(0, 1) * np.cos(f * angles + rng.uniform(0, 2 * math.pi))
                for f in rng.integers(2, 12, 3))
    noise = rng.uniform(-1, 1, k) * min(0.2, 20 / k)
    wobble = (waves + noise) / (3 + min(0.2, 20 / k))  # within [-1, 1]
    radii = (low + high) / 2 + (high - low) / 2 * wobble
    return [(float(center[0] + r * math.cos(a)), float(center[1] + r * math.sin(a)))
            for a, r in zip(angles, radii, strict=True)]


def swiss_cheese(vertices: int, holes: int, seed: int = 0) -> list[list[Point]]:
    """About ``vertices`` vertices: half on the outer ring, half shared by ``holes`` holes.

    Parameters
    ----------
    vertices : int
        Total vertices wanted (each hole gets at least 3, the outer ring at least 8).
    holes : int
        Number of holes.
    seed : int
        Seed of the generator; the same seed gives the same rings.

    Returns
    -------
    list of rings
        The outer ring, then the holes, each a list of (x, y).
    """
    rng = np.random.default_rng(seed)
    per_hole = max(3, vertices // (2 * holes)) if holes else 0
    outer = _star((0.0, 0.0), (0.9, 1.0), max(8, vertices - per_hole * holes), rng)
    side = math.ceil(math.sqrt(holes)) if holes else 1
    cell = 1.2 / side
    rings = [outer]
    for k in range(holes):
        row, col = divmod(k, side)
        center = (-0.6 + (col + 0.5) * cell, -0.6 + (row + 0.5) * cell)
        rings.append(_star(center, (0.2 * cell, 0.4 * cell), per_hole, rng))
    return rings
