"""``trex diagonal``, ``trex triangulate`` and ``trex log``: run algorithms, print or save.

JSON output indexes the input's own vertex order (``vertices`` lists the polygon's points
in that order, every one kept; with holes, the rings one after another, outer first);
human output uses the polygon's labels. ``trex triangulate`` takes polygons with holes
for the algorithms that can (:data:`geometry.triangulate.HOLE_ALGORITHMS`); the
others refuse them in one line. None of these commands imports manim.
"""

from __future__ import annotations

import json
from pathlib import Path

import click

from geometry.check import is_inner_diagonal
from geometry.errors import GeometryError
from geometry.io import Shape, write_atomic
from geometry.polygon import Polygon
from geometry.triangulate import triangulate
from geometry.user_heuristics import (
    UserHeuristic,
    UserHeuristicError,
    is_user_spec,
    load_user_heuristic,
    run_heuristic,
)
from story.registry import heuristics, names, triangulations
from trex.inputs import (
    EXIT_INVALID,
    call_timeout_option,
    fail,
    load_or_exit,
    load_run,
    output_or_exit,
    report_error,
    try_load,
)

HEURISTIC = click.Choice(list(heuristics()))


class HeuristicOrFile(click.ParamType):
    """A built-in heuristic's name (click's Choice error for an unknown one), or
    ``path/to/file.py:function``: a heuristic of one's own, loaded here so a bad spec is one
    line before any polygon is read."""

    name = "heuristic"

    def get_metavar(self, param, ctx=None) -> str:
        return "[" + "|".join(heuristics()) + "|FILE.py:FUNCTION]"

    def convert(self, value, param, ctx):
        if isinstance(value, UserHeuristic):
            return value
        if is_user_spec(value):
            try:
                return load_user_heuristic(value)
            except UserHeuristicError as exc:
                self.fail(str(exc), param, ctx)
        try:
            return HEURISTIC.convert(value, param, ctx)
        except click.BadParameter as exc:
            self.fail(f"{exc.message.rstrip('.')}, or FILE.py:FUNCTION of your own", param, ctx)
ALGORITHM = click.Choice(list(triangulations()))


def _vertices(polygon: Shape) -> list[list[float]]:
    return [list(p) for p in polygon.input_points()]


def _to_input(polygon: Shape, indices) -> list[int]:
    return [polygon.source[i] for i in indices]


def diagonal_record(arg: str, polygon: Polygon, heuristic: str | UserHeuristic) -> dict:
    """The claim of a heuristic (a name, or one's own) and its exact verdict, in input indices."""
    claim = run_heuristic(polygon, heuristic)
    verdict = is_inner_diagonal(polygon, *claim.pair)
    return {
        "polygon": arg,
        "vertices": _vertices(polygon),
        "diagonal": _to_input(polygon, claim.pair),
        "inner": verdict.ok,
        "why": verdict.why,
        "labels": [claim.u.label, claim.v.label],
    }


def triangulation_record(arg: str, polygon: Shape, algorithm: str,
                         heuristic: str | UserHeuristic) -> dict:
    """The triangles of an algorithm and the exact verdict on them, in input indices.

    With holes, ``vertices`` are the rings' (cleaned) vertices concatenated in input
    order, outer ring first, and there are ``n + 2h - 2`` triangles.
    """
    result = triangulate(polygon, algorithm, heuristic)
    return {
        "polygon": arg,
        "vertices": _vertices(polygon),
        "triangles": [_to_input(polygon, t) for t in result.triangles],
        "valid": result.valid,
        "why": result.failure.why if result.failure is not None else None,
    }


def _run_each(polygons, make, show_human, as_json: bool, *, holes: bool = False) -> None:
    """Load each polygon, build its record, print it; exit 2 if any input was bad."""
    bad = False
    for arg in polygons:
        polygon = try_load(arg, holes=holes)
        if polygon is None:
            bad = True
            continue
        try:
            record = make(arg, polygon)
        except (ValueError, GeometryError) as exc:  # no diagonal; holes refused; GEOS fails
            report_error(arg, exc)
            bad = True
            continue
        if as_json:
            record.pop("labels", None)
            click.echo(json.dumps(record, separators=(",", ":"), ensure_ascii=False))
        else:
            click.echo(show_human(record))
    if bad:
        raise click.exceptions.Exit(EXIT_INVALID)


@click.command()
@click.argument("polygons", nargs=-1, required=True, metavar="POLYGON...")
@click.option("--heuristic", type=HeuristicOrFile(), required=True,
              help="Which inner-diagonal heuristic: a name, or FILE.py:FUNCTION of your own.")
@click.option("--json", "as_json", is_flag=True, help="One JSON object per line.")
@call_timeout_option
def diagonal(polygons: tuple[str, ...], heuristic: str | UserHeuristic, as_json: bool) -> None:
    """Claim an inner diagonal of each POLYGON with a heuristic, and check the claim exactly."""

    def human(r: dict) -> str:
        name = "".join(r["labels"])
        verdict = "inner diagonal" if r["inner"] else f"NOT an inner diagonal: {r['why']}"
        return f"{r['polygon']}: {heuristic} claims {name} (input vertices {r['diagonal'][0]} and {r['diagonal'][1]}): {verdict}"

    _run_each(polygons, lambda arg, p: diagonal_record(arg, p, heuristic), human, as_json)


@click.command(name="triangulate")
@click.argument("polygons", nargs=-1, required=True, metavar="POLYGON...")
@click.option("--algorithm", type=ALGORITHM, default="divide-and-conquer", show_default=True)
@click.option("--heuristic", type=HeuristicOrFile(), default="gravity", show_default=True,
              help="For divide-and-conquer: how each diagonal is found (a name, or "
                   "FILE.py:FUNCTION of your own: it runs until its first wrong claim).")
@click.option("--json", "as_json", is_flag=True, help="One JSON object per line.")
@call_timeout_option
def triangulate_command(polygons: tuple[str, ...], algorithm: str,
                        heuristic: str | UserHeuristic, as_json: bool) -> None:
    """Triangulate each POLYGON and verify the triangles exactly."""

    def human(r: dict) -> str:
        n = len(r["triangles"])
        count = f"{n} triangle{'' if n == 1 else 's'}"
        if r["valid"]:
            return f"{r['polygon']}: {algorithm}: {count}, valid"
        return f"{r['polygon']}: {algorithm}: stopped after {count}: {r['why']}"

    _run_each(polygons, lambda arg, p: triangulation_record(arg, p, algorithm, heuristic),
              human, as_json, holes=True)


@click.command(name="log")
@click.argument("algorithm", type=click.Choice(list(names())))
@click.argument("polygon")
@click.option("--heuristic", type=HeuristicOrFile(), default="gravity", show_default=True,
              help="For divide-and-conquer: how each diagonal is found, a name or "
                   "FILE.py:FUNCTION of your own.")
@click.option("-o", "--output", required=True, metavar="FILE.json", help="Where to write the log.")
def log_command(algorithm: str, polygon: str, heuristic: str | UserHeuristic,
                output: str) -> None:
    """Run ALGORITHM (a heuristic or a triangulation) on POLYGON and write its log as JSON."""
    from story.spec import RunSpec  # geometry and tracing only: no manim

    output_or_exit(output)  # before any work: one line, exit 2
    named = heuristic.spec if isinstance(heuristic, UserHeuristic) else heuristic
    spec = RunSpec(algorithm, polygon, heuristic=named if algorithm in triangulations() else None)
    spec = load_run(spec, load_or_exit(polygon, holes=True))  # a scene's rule: holes if it can
    try:  # the very log a scene records for this run, so that it replays the same video
        log = spec.log()
    except (ValueError, GeometryError) as exc:  # no diagonal; GEOS fails
        fail(f"{polygon}: {exc}")
    try:
        write_atomic(Path(output), log.to_json())
    except OSError as exc:
        fail(f"{output}: cannot write: {exc.strerror or exc}")
    click.echo(f"{output}: {len(log.events)} events")


COMMANDS = (diagonal, triangulate_command, log_command)
