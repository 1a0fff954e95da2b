"""``trex diagonal``, ``trex triangulate`` and ``trex log``: run algorithms, print or save.

JSON output indexes the input's own vertex order (``vertices`` lists the polygon's points
in that order, every one kept; with holes, the rings one after another, outer first);
human output uses the polygon's labels. ``trex triangulate`` takes polygons with holes
for the algorithms that can (:data:`geometry.triangulate.HOLE_ALGORITHMS`); the
others refuse them in one line. None of these commands imports manim.
"""

from __future__ import annotations

import difflib
import json
from pathlib import Path

import click

from geometry.check import is_inner_diagonal
from geometry.errors import GeometryError
from geometry.io import AnyPolygon, write_atomic
from geometry.polygon import Polygon
from geometry.triangulate import triangulate
from story.registry import heuristics, names, triangulations
from trex import exit_status
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
from usercode.errors import UserHeuristicError
from usercode.heuristic import UserHeuristic, diagonal_rule, load_user_heuristic, run_heuristic
from usercode.loading import is_user_spec


class BadHeuristic(click.ClickException):
    """A heuristic of one's own that cannot be loaded: its one line as it is (no click
    ``Invalid value for '[scaling|rotation|…]'`` before it), exit status 2."""

    exit_code = EXIT_INVALID


def unknown(kind: str, value: str, known: tuple[str, ...], ctx) -> click.UsageError:
    """The short usage error for a name that is not one of ``known``: ``unknown heuristic
    'gravty'; did you mean 'gravity'?`` (the command's ``--help`` lists them).

    >>> unknown("algorithm", "ear", ("divide-and-conquer", "ear-clipping"), None).message
    "unknown algorithm 'ear'; did you mean 'ear-clipping'?"
    >>> unknown("heuristic", "rot", ("rotation", "rotation-ccw", "scaling"), None).message
    "unknown heuristic 'rot'; did you mean one of rotation, rotation-ccw?"
    """
    close = ([k for k in known if value and k.startswith(value)]
             or difflib.get_close_matches(value, known, n=1))
    hint = (f"; did you mean '{close[0]}'?" if len(close) == 1
            else f"; did you mean one of {', '.join(close)}?" if 1 < len(close) <= 4 else "")
    return click.UsageError(f"unknown {kind} '{value}'{hint}", ctx)


class HeuristicOrFile(click.ParamType):
    """A built-in heuristic's name, or ``path/to/file.py:function``: a heuristic of one's own,
    loaded here so a bad spec is one line before any polygon is read. Either error is one
    short line (:func:`unknown`, :class:`BadHeuristic`)."""

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
                raise BadHeuristic(str(exc)) from None
        if value in heuristics():
            return value
        raise unknown("heuristic", value, heuristics(), ctx)


class ShortChoice(click.Choice):
    """A :class:`click.Choice` whose error is one short line (:func:`unknown`), not the whole
    list of choices twice."""

    def __init__(self, choices, kind: str) -> None:
        super().__init__(choices)
        self.kind = kind

    def convert(self, value, param, ctx):
        if value in self.choices:
            return value
        raise unknown(self.kind, value, tuple(self.choices), ctx)


#: The one algorithm a heuristic is handed to: it finds each piece's diagonal.
TAKES_HEURISTIC = "divide-and-conquer"
ALGORITHM = ShortChoice(list(triangulations()), "algorithm")


def _vertices(polygon: AnyPolygon) -> list[list[float]]:
    return [list(p) for p in polygon.input_points()]


def _to_input(polygon: AnyPolygon, indices) -> list[int]:
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


def triangulation_record(arg: str, polygon: AnyPolygon, algorithm: str,
                         heuristic: str | UserHeuristic) -> dict:
    """The triangles of an algorithm and the exact verdict on them, in input indices.

    With holes, ``vertices`` are the rings' (cleaned) vertices concatenated in input
    order, outer ring first, and there are ``n + 2h - 2`` triangles.
    """
    result = triangulate(polygon, algorithm, diagonal_rule(heuristic))
    return {
        "polygon": arg,
        "vertices": _vertices(polygon),
        "triangles": [_to_input(polygon, t) for t in result.triangles],
        "valid": result.valid,
        "why": result.failure.why if result.failure is not None else None,
    }


def _run_each(polygons, make, show_human, as_json: bool, finding, *,
              holes: bool = False) -> None:
    """Load each polygon, build its record, print it; then exit 2 if any input was bad (or a
    function of one's own failed), else 1 if any record is a ``finding`` (a wrong claim, a
    stopped triangulation), else 0."""
    bad = found = False
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
        found = found or finding(record)
        if as_json:
            record.pop("labels", None)
            click.echo(json.dumps(record, separators=(",", ":"), ensure_ascii=False))
        else:
            click.echo(show_human(record))
    status = exit_status.worst(EXIT_INVALID if bad else exit_status.OK,
                               exit_status.FINDING if found else exit_status.OK)
    if status:
        raise click.exceptions.Exit(status)


def refuse_unused_heuristic(algorithm: str) -> None:
    """``--heuristic`` given to an algorithm that takes none: one line, exit 2 (as ``trex
    render`` refuses it), before any polygon is read. Only divide and conquer takes one."""
    ctx = click.get_current_context()
    given = ctx.get_parameter_source("heuristic") not in (
        click.core.ParameterSource.DEFAULT, None)
    if given and algorithm in triangulations() and algorithm != TAKES_HEURISTIC:
        fail(f"--heuristic: {algorithm} takes no heuristic (only {TAKES_HEURISTIC} does)")


@click.command()
@click.argument("polygons", nargs=-1, required=True, metavar="POLYGON...")
@click.option("--heuristic", type=HeuristicOrFile(), required=True,
              help="Which inner-diagonal heuristic: a name, or FILE.py:FUNCTION of your own.")
@click.option("--json", "as_json", is_flag=True, help="One JSON object per line.")
@call_timeout_option
def diagonal(polygons: tuple[str, ...], heuristic: str | UserHeuristic, as_json: bool) -> None:
    """Claim an inner diagonal of each POLYGON with a heuristic, and check the claim exactly.

    Exit status 1 when a claim is not an inner diagonal, 2 for bad input.
    """

    def human(r: dict) -> str:
        name = "".join(r["labels"])
        verdict = "inner diagonal" if r["inner"] else f"NOT an inner diagonal: {r['why']}"
        return f"{r['polygon']}: {heuristic} claims {name} (input vertices {r['diagonal'][0]} and {r['diagonal'][1]}): {verdict}"

    _run_each(polygons, lambda arg, p: diagonal_record(arg, p, heuristic), human, as_json,
              lambda r: not r["inner"])


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
    """Triangulate each POLYGON and verify the triangles exactly.

    Exit status 1 when a triangulation stopped early (a heuristic's wrong claim), 2 for bad
    input (or ``--heuristic`` for an algorithm that takes none).
    """
    refuse_unused_heuristic(algorithm)

    def human(r: dict) -> str:
        n = len(r["triangles"])
        count = f"{n} triangle" if n == 1 else f"{n} triangles"
        if r["valid"]:
            return f"{r['polygon']}: {algorithm}: {count}, valid"
        return f"{r['polygon']}: {algorithm}: stopped after {count}: {r['why']}"

    _run_each(polygons, lambda arg, p: triangulation_record(arg, p, algorithm, heuristic),
              human, as_json, lambda r: not r["valid"], holes=True)


@click.command(name="log")
@click.argument("algorithm", type=ShortChoice(list(names()), "algorithm"))
@click.argument("polygon")
@click.option("--heuristic", type=HeuristicOrFile(), default="gravity", show_default=True,
              help="For divide-and-conquer: how each diagonal is found, a name or "
                   "FILE.py:FUNCTION of your own.")
@click.option("-o", "--output", required=True, metavar="FILE.json", help="Where to write the log.")
@call_timeout_option
def log_command(algorithm: str, polygon: str, heuristic: str | UserHeuristic,
                output: str) -> None:
    """Run ALGORITHM (a heuristic or a triangulation) on POLYGON and write its log as JSON."""
    from story.spec import RunSpec  # geometry and tracing only: no manim

    refuse_unused_heuristic(algorithm)
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
