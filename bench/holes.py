"""Polygons with holes: ear clipping with bridges and monotone beside mapbox_earcut and GEOS.

Inputs: the earcut fixtures with holes that are valid polygons with holes
(earcut's ``water*`` fixtures are not: each has a pinch, a spike or a hole
touching the outer ring, which this project refuses, so they cannot be
timed here), and generated Swiss cheese (:func:`geometry.hole_samples.swiss_cheese`)
with 10,000 vertices and 100 holes. Each time is the median of ``--repeats``
runs or more (see :func:`bench.algorithms.measure`), untraced, on a polygon
validated beforehand; earcut gets the same rings as a flat array, GEOS the
same polygon. Ratios are to earcut.

Then validation alone (``PolygonWithHoles.from_rings``) of cheese with
10,000 vertices and 100 holes and with 100,000 vertices and 1,000 holes.

Writes ``docs/benchmarks-holes.md``; ``make bench`` runs this after ``bench.algorithms``.
Run from the repository root: ``python -m bench.holes [--repeats 5]``.
"""

from __future__ import annotations

import os
import platform
import sys
import time
from collections.abc import Callable
from pathlib import Path

import mapbox_earcut
import numpy as np
import shapely

try:
    import geometry  # noqa: F401
except ModuleNotFoundError:  # run as ``python bench/holes.py``: add the repo root
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from bench.algorithms import Timing, measure, timing_arguments
from geometry.cdt import shapely_polygon
from geometry.hole_samples import swiss_cheese
from geometry.holes import PolygonWithHoles
from geometry.io import read_rings
from geometry.triangulate import RUNNERS

ROOT = Path(__file__).resolve().parents[1]
FIXTURES = ("dude", "earcut", "eberly-6", "issue34", "issue35", "issue52")
CHEESE = (10_000, 100)
VALIDATION = ((10_000, 100), (100_000, 1_000))
EARCUT, GEOS = "mapbox_earcut (C++)", "shapely CDT (GEOS)"
CONTENDERS = ("ear-clipping", "monotone", "cdt", EARCUT, GEOS)


def inputs() -> dict[str, PolygonWithHoles]:
    shapes = {name: PolygonWithHoles.from_rings(read_rings(ROOT / "tests" / "data" / "earcut"
                                                           / f"{name}.json")) for name in FIXTURES}
    vertices, holes = CHEESE
    shapes[f"cheese {vertices:,} / {holes} holes"] = PolygonWithHoles.from_rings(
        swiss_cheese(vertices, holes, seed=0))
    return shapes


def runner(name: str, shape: PolygonWithHoles) -> Callable[[], object]:
    if name == EARCUT:
        arr = np.asarray(shape.points, dtype=np.float64)
        ends = np.asarray(shape.starts[1:], dtype=np.uint32)
        return lambda: mapbox_earcut.triangulate_float64(arr, ends)
    if name == GEOS:
        polygon = shapely_polygon(shape)
        return lambda: shapely.constrained_delaunay_triangles(polygon)
    return lambda: RUNNERS[name](shape)


def run(repeats: int, budget: float) -> tuple[dict, dict]:
    table: dict[tuple[str, str], Timing] = {}
    for label, shape in inputs().items():
        for name in CONTENDERS:
            table[(label, name)] = measure(runner(name, shape), repeats, budget)
            print(f"{name:22} {label:28} n={shape.n:>6,} h={shape.hole_count:>4}  "
                  f"{table[(label, name)].seconds * 1e3:9.2f} ms", flush=True)
    validation = {}
    for vertices, holes in VALIDATION:
        rings = swiss_cheese(vertices, holes, seed=0)
        start = time.perf_counter()
        PolygonWithHoles.from_rings(rings)
        validation[(vertices, holes)] = time.perf_counter() - start
        print(f"validate cheese {vertices:,} vertices, {holes:,} holes: "
              f"{validation[(vertices, holes)]:.2f} s", flush=True)
    return table, validation


def markdown(table: dict, validation: dict, repeats: int) -> str:
    labels = list(dict.fromkeys(label for label, _ in table))
    lines = [
        "# Benchmarks: polygons with holes", "",
        "Written by `python -m bench.holes` (`make bench` runs it after `bench.algorithms`).",
        f"Untraced wall time, median of {repeats} runs or more; Python "
        f"{platform.python_version()}, {os.cpu_count()} CPUs, load {os.getloadavg()[0]:.1f}.",
        "earcut's `water*` fixtures are not here: each has a pinch, a spike or a hole touching",
        "the outer ring, which this project refuses as invalid input.", "",
        "| polygon | n | holes | " + " | ".join(CONTENDERS) + " | ear ÷ earcut | monotone ÷ earcut |",
        "|---|---:|---:|" + "---:|" * (len(CONTENDERS) + 2),
    ]
    shapes = inputs()
    for label in labels:
        cells = [f"{table[(label, c)].seconds * 1e3:.2f} ms" for c in CONTENDERS]
        earcut = table[(label, EARCUT)].seconds
        ratios = [table[(label, c)].seconds / earcut for c in ("ear-clipping", "monotone")]
        lines.append(f"| {label} | {shapes[label].n:,} | {shapes[label].hole_count} | "
                     + " | ".join(cells) + " | " + " | ".join(f"{r:,.0f}×" for r in ratios) + " |")
    lines += ["", "Validation (`PolygonWithHoles.from_rings`: every ring simple, rings apart, holes",
              "inside and not nested, all exact):", "",
              "| vertices | holes | seconds |", "|---:|---:|---:|"]
    lines += [f"| {v:,} | {h:,} | {s:.2f} |" for (v, h), s in validation.items()]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> None:
    args = timing_arguments(__doc__, argv)
    table, validation = run(args.repeats, args.budget)
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "benchmarks-holes.md").write_text(markdown(table, validation, args.repeats))
    worst = max(table[(label, "ear-clipping")].seconds / table[(label, EARCUT)].seconds
                for label, _ in table)
    print(f"slowest ratio of ear clipping with bridges to earcut: {worst:.0f}x")


if __name__ == "__main__":
    main()
