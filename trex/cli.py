"""The ``trex`` command group.

Every command reports bad input as one line on stderr and exits with status 2;
usage errors too (click's multi-line usage report is folded into one line).
"""

from __future__ import annotations

import decimal
import sys
from typing import Any, NoReturn

import click

from geometry.errors import GeometryError
from geometry.io import AnyPolygon, to_json, write_polygon
from geometry.polygon import Polygon  # (the doctests' polygons too)
from geometry.samples import make_sample
from trex import exit_status
from trex.course.command import COMMANDS as COURSE_COMMANDS
from trex.exercises_command import COMMANDS as EXERCISE_COMMANDS
from trex.hunt_command import COMMANDS as HUNT_COMMANDS
from trex.inputs import EXIT_INVALID, error_line, fail, first_line, output_or_exit, try_load
from trex.lecture_command import COMMANDS as LECTURE_COMMANDS
from trex.player_command import COMMANDS as PLAYER_COMMANDS
from trex.render_command import COMMANDS as RENDER_COMMANDS
from trex.run_commands import COMMANDS
from trex.slides_command import COMMANDS as SLIDES_COMMANDS
from trex.snapshot_command import COMMANDS as SNAPSHOT_COMMANDS
from trex.studio.command import COMMANDS as STUDIO_COMMANDS

_SHOWN_LABELS = 8


class _OneLineGroup(click.Group):
    """A group whose usage errors print as ``error: <message> (try '… --help')``, and whose
    commands, interrupted by Ctrl-C, say so in one line and exit 130."""

    def invoke(self, ctx: click.Context) -> Any:
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt:  # a real Ctrl-C: a user's own raise is their function's error
            _interrupted(ctx.invoked_subcommand)

    def main(self, *args: Any, standalone_mode: bool = True, **kwargs: Any) -> Any:
        if not standalone_mode:
            return super().main(*args, standalone_mode=False, **kwargs)  # type: ignore[call-overload]  # *args: click's own positional parameters, passed on as they came
        kwargs.setdefault("prog_name", "trex")
        try:
            code = super().main(*args, standalone_mode=False, **kwargs)  # type: ignore[call-overload]  # *args: click's own positional parameters, passed on as they came
        except click.exceptions.NoArgsIsHelpError as exc:
            click.echo(exc.format_message())  # bare `trex`: the help, status 2 as click does
            sys.exit(exc.exit_code)
        except click.UsageError as exc:
            where = exc.ctx.command_path if exc.ctx is not None else "trex"
            message = first_line(exc.format_message())
            click.echo(f"error: {message} (try '{where} --help')", err=True)
            sys.exit(exc.exit_code)
        except click.ClickException as exc:
            click.echo(f"error: {first_line(exc.format_message())}", err=True)
            sys.exit(exc.exit_code)
        except click.Abort:  # Ctrl-C before the command ran (click turned it into Abort)
            _interrupted(None)
        sys.exit(code if isinstance(code, int) else 0)


def _interrupted(command: str | None) -> NoReturn:
    """``error: hunt interrupted`` on stderr (on a line of its own after the terminal's ``^C``)
    and the status of an interrupt."""
    start = "\n" if sys.stderr.isatty() else ""
    click.echo(f"{start}error: {command or 'trex'} interrupted", err=True)
    sys.exit(exit_status.INTERRUPTED)


@click.group(cls=_OneLineGroup, context_settings={"help_option_names": ["-h", "--help"]})
def main() -> None:
    """Triangulation Explained: real runs of triangulation algorithms, as videos.

    A POLYGON is a file (.json, .geojson, .wkt, .dat) or a sample name such as
    counterexample, lecture or random-star:50:7 (NAME[:N[:SEED]]).
    """


def _reflex_text(polygon: AnyPolygon) -> str:
    reflex = polygon.reflex_vertices()
    if not reflex:
        return "0 reflex vertices (convex)"
    labels = [polygon.labels[i] for i in reflex[:_SHOWN_LABELS]]
    if len(reflex) > _SHOWN_LABELS:
        labels.append(f"… {len(reflex) - _SHOWN_LABELS} more")
    noun = "vertex" if len(reflex) == 1 else "vertices"
    return f"{len(reflex)} reflex {noun} ({', '.join(labels)})"


def display_area(polygon: AnyPolygon) -> str:
    """The area to six significant digits, rounded from the exact value, so that an
    area beyond a float's range (coordinates near 1.7e308) is still a number.

    >>> display_area(Polygon.from_points([(0, 0), (1e300, 0), (0, 1e300)]))
    '5e+599'
    """
    area = polygon.area2 / 2  # exact (geometry.predicates.signed_area2)
    try:
        return f"{float(area):.6g}"  # float(Fraction) rounds correctly
    except OverflowError:
        pass
    with decimal.localcontext() as context:
        context.prec = 6
        context.Emax, context.Emin = decimal.MAX_EMAX, decimal.MIN_EMIN
        value = decimal.Decimal(area.numerator) / decimal.Decimal(area.denominator)
    return f"{value.normalize():g}".replace("E", "e")


def _size_text(polygon: AnyPolygon) -> str:
    holes = polygon.hole_count
    if not holes or isinstance(polygon, Polygon):  # a Polygon has no holes
        return f"{polygon.n} vertices"
    outer = polygon.starts[1]
    return (f"{polygon.n} vertices, {holes} hole{'s' if holes > 1 else ''} "
            f"({outer} on the outer ring, {polygon.n - outer} on holes)")


def summary(polygon: AnyPolygon) -> str:
    """One line about a valid polygon, orientation (of the outer ring) as given in the input.

    The number of holes is said when there are any; hole vertices are reflex
    where the hole bulges into the region.

    >>> summary(Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)]))
    'valid, 5 vertices, counter-clockwise, area 12.92, 1 reflex vertex (E)'
    >>> from geometry.holes import PolygonWithHoles
    >>> summary(PolygonWithHoles.from_rings([[(0, 0), (6, 0), (6, 6), (0, 6)],
    ...                                      [(2, 2), (4, 2), (3, 4)]]))
    'valid, 7 vertices, 1 hole (4 on the outer ring, 3 on holes), counter-clockwise, area 34, 3 reflex vertices (a₁, b₁, c₁)'
    """
    orientation = "clockwise" if polygon.input_clockwise else "counter-clockwise"
    return (
        f"valid, {_size_text(polygon)}, {orientation}, "
        f"area {display_area(polygon)}, {_reflex_text(polygon)}"
    )


@main.command()
@click.argument("polygons", nargs=-1, required=True, metavar="POLYGON...")
def check(polygons: tuple[str, ...]) -> None:
    """Validate each POLYGON and print one line about it.

    Exits with status 2 when any POLYGON is invalid.
    """
    invalid = False
    for arg in polygons:
        polygon = try_load(arg, holes=True)
        if polygon is None:
            invalid = True
        else:
            click.echo(f"{arg}: {summary(polygon)}")
    if invalid:
        raise click.exceptions.Exit(EXIT_INVALID)


@main.command()
@click.argument("name")
@click.option("-n", "--n", "n", type=int, help="Number of vertices (families and generators).")
@click.option("--seed", type=int, default=0, show_default=True, help="Seed of the generator.")
@click.option("-o", "--output", metavar="FILE", help="Write here (format by extension).")
def sample(name: str, n: int | None, seed: int, output: str | None) -> None:
    """Write sample NAME as JSON points to stdout, or to FILE (format by extension)."""
    if output is not None:
        output_or_exit(output, polygon=True)  # before any work
    try:
        points = make_sample(name, n, seed)
    except GeometryError as exc:
        fail(error_line(exc))
    if output is None:
        click.echo(to_json(points))
        return
    try:
        write_polygon(points, output)
    except GeometryError as exc:
        fail(f"{output}: {error_line(exc)}")
    except OSError as exc:
        fail(f"{output}: cannot write: {exc.strerror or error_line(exc)}")


for _command in (*COMMANDS, *HUNT_COMMANDS, *RENDER_COMMANDS, *EXERCISE_COMMANDS, *LECTURE_COMMANDS,
                 *PLAYER_COMMANDS, *SLIDES_COMMANDS, *SNAPSHOT_COMMANDS, *STUDIO_COMMANDS,
                 *COURSE_COMMANDS):
    main.add_command(_command)

if __name__ == "__main__":
    main()
