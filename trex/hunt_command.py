"""``trex hunt``: search for a counterexample to a heuristic, shrink it, say why it fails.

The search and the shrinker are :mod:`story.hunt` (no manim); this is the command: the
verdict in words and the polygon, or one JSON line; ``-o`` writes the polygon for
``trex render --polygon``. Exit status 1: a counterexample was found; 0: none within the
budget; 2: bad input (an unknown heuristic, a broken file, a function of one's own that
raises, answers nonsense or does not return within ``--call-timeout`` seconds).
"""

from __future__ import annotations

import contextlib
import json
import sys

import click

from geometry.io import polygon_to_json_points, write_polygon
from geometry.user_heuristics import UserHeuristic, UserHeuristicError
from story.hunt import Hunt, hunt, polygon_lines, reason, verdict_line
from trex.inputs import call_timeout_option, error_line, fail
from trex.run_commands import HeuristicOrFile

EXIT_FOUND = 1


def hunt_record(result: Hunt) -> dict:
    """The one JSON line: indices into ``polygon`` as listed (counter-clockwise from A)."""
    found = result.found and result.polygon is not None
    return {
        "heuristic": result.heuristic,
        "found": result.found,
        "polygon": polygon_to_json_points(list(result.polygon.points)) if found else None,
        "diagonal": list(result.diagonal) if found and result.diagonal else None,
        "inner": False if found else None,
        "reason": reason(result) if found else None,
        "tried": result.tried,
        "max_vertices": result.max_vertices,
        "seconds": round(result.seconds, 3),
    }


@click.command(name="hunt")
@click.argument("heuristic", type=HeuristicOrFile())
@click.option("--budget", type=click.IntRange(min=1), default=5000, show_default=True,
              metavar="N", help="How many polygons to try (the result depends on it, not on "
                                "the clock).")
@click.option("--seed", type=int, default=0, show_default=True, help="Seed of the search.")
@click.option("--max-vertices", type=click.IntRange(min=4), default=8, show_default=True,
              metavar="N", help="The largest polygons tried (fewest vertices first).")
@click.option("-o", "--output", metavar="FILE",
              help="Write the counterexample here (format by extension), for trex render "
                   "--polygon.")
@click.option("--json", "as_json", is_flag=True, help="One JSON line.")
@call_timeout_option
def hunt_command(heuristic: str | UserHeuristic, budget: int, seed: int, max_vertices: int,
                 output: str | None, as_json: bool) -> None:
    """Search small polygons for one on which HEURISTIC's claim is not an inner diagonal,
    shrink it to a minimal one and say why the claim is wrong.

    HEURISTIC is a built-in name or FILE.py:FUNCTION of your own. Exit status 1: found;
    0: none within the budget; 2: bad input.
    """
    show_bar = not as_json and sys.stderr.isatty()
    bar_context = (click.progressbar(length=budget, label="hunting", file=sys.stderr)
                   if show_bar else contextlib.nullcontext())
    with bar_context as bar:
        try:
            result = hunt(heuristic, budget=budget, seed=seed, max_vertices=max_vertices,
                          progress=bar.update if bar is not None else None)
        except UserHeuristicError as exc:
            fail(f"{heuristic}: {exc}")
        except ValueError as exc:  # a built-in heuristic that refuses a polygon
            fail(f"{heuristic}: {error_line(exc)}")
    if as_json:
        click.echo(json.dumps(hunt_record(result), separators=(",", ":"), ensure_ascii=False))
    else:
        click.echo(verdict_line(result))
        if result.found and result.polygon is not None:
            click.echo("\n".join(polygon_lines(result.polygon)))
            click.echo(f"(found among {result.tried:,} polygons, on one of {result.first} "
                       f"vertices, shrunk in {result.checks:,} checks, "
                       f"{result.seconds:.2f} s)")
    if result.found and result.polygon is not None:
        if output is not None:
            try:
                write_polygon(list(result.polygon.points), output)
            except (OSError, ValueError) as exc:
                fail(f"{output}: cannot write: {error_line(exc)}")
            if not as_json:
                click.echo(f"wrote {output}")
        raise click.exceptions.Exit(EXIT_FOUND)


COMMANDS = (hunt_command,)
