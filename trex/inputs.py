"""Polygon arguments shared by every command: load, report, exit with status 2.

A polygon argument is a file path or a sample spec ``NAME[:N[:SEED]]`` (see
:func:`geometry.io.read_polygon`). Every failure becomes one line on stderr,
``error: <arg>: <reason>``, and the command exits with :data:`EXIT_INVALID`;
warnings are ``warning: <arg>: <message>``.

>>> error_line(ValueError("bad\\nsecond line"))
'bad'
>>> error_line(OSError())
'OSError'
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import NoReturn

import click

from geometry.errors import GeometryError
from geometry.io import Shape, read_polygon, read_shape
from geometry.polygon import Polygon
from geometry.user_heuristics import DEFAULT_CALL_TIMEOUT, call_timeout, set_call_timeout
from trex.exit_status import INVALID as EXIT_INVALID

# Reading can also fail outside the GeometryError family (an unexpected OS
# error, a value shapely rejects); those must still end as one line.
READ_ERRORS = (GeometryError, OSError, ValueError, RecursionError, MemoryError)


def first_line(text: str) -> str:
    """The first non-blank line of ``text`` (stripped), or ``""``."""
    lines = text.strip().splitlines()
    return lines[0].strip() if lines else ""


def error_line(exc: BaseException) -> str:
    """The first line of an exception's message (its class name when it has none)."""
    return first_line(str(exc)) or type(exc).__name__


def report_error(arg: str, exc: BaseException) -> None:
    click.echo(f"error: {arg}: {error_line(exc)}", err=True)


def report_warnings(arg: str, polygon: Shape) -> None:
    for message in polygon.warnings:
        click.echo(f"warning: {arg}: {message}", err=True)


def fail(message: str) -> NoReturn:
    """Print ``error: <message>`` and exit with status 2."""
    click.echo(f"error: {message}", err=True)
    raise click.exceptions.Exit(EXIT_INVALID)


def try_load(arg: str, *, holes: bool = False) -> Polygon | None:
    """The polygon of ``arg`` with its warnings reported, or None after reporting the error.

    With ``holes``, a polygon with holes is returned as a
    :class:`geometry.holes.PolygonWithHoles`; without, it is refused in one line.
    """
    try:
        polygon = read_shape(arg) if holes else read_polygon(arg)
    except READ_ERRORS as exc:
        report_error(arg, exc)
        return None
    report_warnings(arg, polygon)
    return polygon


def load_or_exit(arg: str, *, holes: bool = False) -> Polygon:
    """The polygon of ``arg`` (with holes, if ``holes``); on failure report it and exit with
    status 2."""
    polygon = try_load(arg, holes=holes)
    if polygon is None:
        raise click.exceptions.Exit(EXIT_INVALID)
    return polygon


def _set_call_timeout(ctx: click.Context, _param, value: float) -> float:
    """Set the limit for this command, and put the one before back when it ends (a command
    invoked in process, as tests do, leaves no limit behind)."""
    previous = call_timeout()
    set_call_timeout(value)
    ctx.call_on_close(lambda: set_call_timeout(previous))
    return value


#: ``--call-timeout SECONDS``: how long a user's function may run (eager: set before the
#: heuristic's file is loaded, which the limit covers too).
call_timeout_option = click.option(
    "--call-timeout", type=click.FloatRange(min=0), default=DEFAULT_CALL_TIMEOUT,
    show_default=True, is_eager=True, expose_value=False, callback=_set_call_timeout,
    metavar="SECONDS", help="Stop a FILE.py:FUNCTION of your own that runs longer (0: never).")


def make_parent(path: Path) -> None:
    """Create ``path``'s directory if need be and check that it can be written to (an
    output is first written beside itself). Raises ValueError with a one-line reason."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"cannot create its directory: {exc.strerror or exc}") from None
    if not os.access(path.parent, os.W_OK):
        raise ValueError(f"cannot write to directory {path.parent}")
