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
from typing import TYPE_CHECKING, NoReturn

import click

from geometry.errors import GeometryError
from geometry.io import AnyPolygon, check_format, read_any_polygon, read_polygon
from trex.exit_status import INVALID as EXIT_INVALID
from usercode.limits import DEFAULT_CALL_TIMEOUT, call_timeout, set_call_timeout

if TYPE_CHECKING:
    from story.spec import RunSpec

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


def report_warnings(arg: str, polygon: AnyPolygon) -> None:
    for message in polygon.warnings:
        click.echo(f"warning: {arg}: {message}", err=True)


def fail(message: str) -> NoReturn:
    """Print ``error: <message>`` and exit with status 2."""
    click.echo(f"error: {message}", err=True)
    raise click.exceptions.Exit(EXIT_INVALID)


def try_load(arg: str, *, holes: bool = False) -> AnyPolygon | None:
    """The polygon of ``arg`` with its warnings reported, or None after reporting the error.

    With ``holes``, a polygon with holes is returned as a
    :class:`geometry.holes.PolygonWithHoles`; without, it is refused in one line.
    """
    try:
        polygon = read_any_polygon(arg) if holes else read_polygon(arg)
    except READ_ERRORS as exc:
        report_error(arg, exc)
        return None
    report_warnings(arg, polygon)
    return polygon


def load_or_exit(arg: str, *, holes: bool = False) -> AnyPolygon:
    """The polygon of ``arg`` (with holes, if ``holes``); on failure report it and exit with
    status 2."""
    polygon = try_load(arg, holes=holes)
    if polygon is None:
        raise click.exceptions.Exit(EXIT_INVALID)
    return polygon


def load_run(spec: RunSpec, polygon_read: AnyPolygon | None = None) -> RunSpec:
    """The :class:`story.spec.RunSpec` ``spec`` with its polygon read once and checked by the
    one rule a run's polygon obeys (:meth:`story.spec.RunSpec.read`: holes only for the
    algorithms that take them); a scene handed it reads no file. ``polygon_read`` is the polygon
    read already (a command reads its ``--polygon`` before manim is imported), else it is
    read here, warnings reported. A bad polygon is one line and exit 2; a replay comes back
    as it is."""
    if spec.saved:
        return spec
    if polygon_read is None:
        polygon_read = load_or_exit(spec.polygon, holes=True)
    try:
        return spec.read(polygon_read)
    except READ_ERRORS as exc:
        fail(f"{spec.polygon}: {error_line(exc)}")


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


def check_output_file(path: str, *, polygon: bool = False) -> Path:
    """``path`` as a file a command may write when its work is done, checked before the work:
    not a directory, in an existing directory that can be written to, and with ``polygon``,
    an extension naming a polygon format (:func:`geometry.io.check_format`). Raises
    ValueError with a one-line reason (the caller names the path).

    >>> check_output_file("/no/such/dir/ce.json")
    Traceback (most recent call last):
    ...
    ValueError: no such directory: /no/such/dir
    """
    target = Path(path)
    if not path:
        raise ValueError("empty path; give a file path")
    if target.is_dir():
        raise ValueError("is a directory; give a file path")
    if polygon:
        try:
            check_format(target)
        except GeometryError as exc:
            raise ValueError(error_line(exc)) from None
    parent = target.parent
    if not parent.exists():
        raise ValueError(f"no such directory: {parent}")
    if not parent.is_dir():
        raise ValueError(f"not a directory: {parent}")
    if not os.access(parent, os.W_OK):
        raise ValueError(f"cannot write to directory {parent}")
    return target


def output_or_exit(path: str, *, polygon: bool = False) -> Path:
    """:func:`check_output_file`, or one line naming ``path`` and exit 2."""
    try:
        return check_output_file(path, polygon=polygon)
    except ValueError as exc:
        fail(f"{path or repr(path)}: {exc}")


def make_parent(path: Path) -> None:
    """Create ``path``'s directory if need be and check that it can be written to (an
    output is first written beside itself). Raises ValueError with a one-line reason."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"cannot create its directory: {exc.strerror or exc}") from None
    if not os.access(path.parent, os.W_OK):
        raise ValueError(f"cannot write to directory {path.parent}")
