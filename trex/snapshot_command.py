"""``trex snapshot``: the scene graph of a scene, written or checked (docs/scene-graph.md).

``trex snapshot SCENE [--polygon P | --log FILE ...] [-o FILE]`` builds SCENE in a dry run
(no video: seconds, not a render) and writes its graph, deterministic JSON, to FILE or
stdout. ``--check FILE`` compares it with a stored graph instead: exit 0 when equal, exit 1
with the differences in words, play by play; ``--update`` then rewrites FILE. The run is the
arguments' alone: ``TREX_POLYGON`` and ``TREX_LOG`` (plain ``manim``'s) are not read, so a
check means the same in any shell.

Exit status: 0 written, or equal (or updated); 1 the graph differs from FILE; 2 nothing to
compare: bad input (one line: the scene, polygon, log or FILE), or the scene failed while it
was built (the error's first line, and where in the scene's file).
"""

from __future__ import annotations

import os
import traceback
from pathlib import Path

import click

from geometry.io import AnyPolygon
from story.scene_kinds import Handed
from trex.inputs import call_timeout_option, error_line, fail, load_or_exit

EXIT_DIFFERS = 1


def _where(exc: BaseException, scene: str) -> str:
    """`` (file.py:12)``: the innermost line of the scene's own file the error passed, if any."""
    file_part = scene.rpartition(":")[0] if ".py:" in scene else scene.partition(":")[0]
    if not file_part.endswith(".py"):
        return ""
    wanted = os.path.realpath(file_part)
    frames = [f for f in traceback.extract_tb(exc.__traceback__)
              if os.path.realpath(f.filename) == wanted]
    return f" ({Path(file_part).name}:{frames[-1].lineno})" if frames else ""


def _build(scene: str, polygon: str | None, logs: tuple[str, ...], polygon_read: AnyPolygon | None = None):
    """The scene's graph, or exit 2 with one line (``polygon_read``: ``polygon`` read already)."""
    from trex.render_command import RUN_ERRORS, run_once
    from trex.snapshot import SnapshotError, build, hand, load_scene, plays_own_polygons

    try:
        cls = load_scene(scene)
    except ValueError as exc:
        fail(f"{scene}: {error_line(exc)}")
    if polygon is not None and plays_own_polygons(cls):
        click.echo(f"warning: {scene}: plays its own polygons; --polygon is ignored", err=True)
        polygon = None
    try:
        handed = hand(cls, polygon, logs, polygon_read)
    except SnapshotError as exc:  # a polygon's or log's fault names it; else the scene's
        named = [p for p in (polygon, *logs) if p is not None and str(exc).startswith(f"{p}:")]
        fail(str(exc) if named else f"{scene}: {exc}")
    spec = handed.spec if isinstance(handed, Handed) else None
    if spec is not None and spec.polygon_read is not None:
        try:
            run_once(spec)
        except RUN_ERRORS as exc:  # an input the algorithm rejects: said as the polygon's fault
            fail(f"{spec.polygon}: {error_line(exc)}")
    try:
        return build(handed)
    except (KeyboardInterrupt, click.exceptions.Exit):
        raise
    except Exception as exc:
        fail(f"{scene}: the scene failed while it was built: {type(exc).__name__}: "
             f"{error_line(exc)}{_where(exc, scene)}")


def _stored(check: str, update: bool):
    """The graph stored in FILE (None: there is none yet and ``--update`` will write it)."""
    from trex.snapshot import SceneGraph, SnapshotError

    if Path(check).is_dir():
        fail(f"{check}: is a directory; give the file of a stored graph")
    try:
        return SceneGraph.read(check)
    except SnapshotError as exc:
        if update:  # whatever is there (nothing, an older schema …) is replaced
            return None
        hint = " (write it with -o, or --update)" if not Path(check).exists() else ""
        fail(f"{check}: {exc}{hint}")


def _writable(path: str) -> None:
    from trex.render_command import prepare_output

    try:
        prepare_output(Path(path))
    except ValueError as exc:
        fail(f"{path}: {exc}")


@click.command()
@click.argument("scene")
@click.option("--polygon", metavar="POLYGON", help="Polygon file or sample (default: the scene's).")
@click.option("--log", "logs", multiple=True, metavar="FILE.json",
              help="Replay a saved log (`trex log … -o FILE.json`) instead of running live; "
                   "once per run for a scene of several runs.")
@click.option("-o", "--output", metavar="FILE", help="Write the graph here (default: stdout).")
@click.option("--check", "check", metavar="FILE",
              help="Compare with the graph stored in FILE: exit 0 if equal, 1 with the "
                   "differences in words.")
@click.option("--update", is_flag=True, help="With --check: rewrite FILE when it differs.")
@call_timeout_option
def snapshot(scene: str, polygon: str | None, logs: tuple[str, ...], output: str | None,
             check: str | None, update: bool) -> None:
    """Write the scene graph of SCENE (JSON; a dry run, no video), or --check it.

    SCENE as for `trex render`: a name from scenes/ (gravity, rotation:RotationCcw), a
    FILE.py[:Class] anywhere (any manim Scene), or FILE.py:function (a heuristic of one's own).
    A plain manim Scene takes no --polygon or --log. Exit 0 written or equal, 1 differs,
    2 bad input or a scene that fails.
    """
    if update and check is None:
        fail("--update rewrites the file of --check: give --check FILE")
    if output is not None and check is not None:
        fail("-o and --check: give one of them (--check FILE --update rewrites FILE)")
    if polygon is not None and logs:
        fail("--polygon and --log: give one of them (a saved log has its own polygon)")
    # one line, exit 2, before manim is even imported (holes: the scene's rule, later)
    polygon_read = load_or_exit(polygon, holes=True) if polygon is not None else None
    target = output if output is not None else check if update else None
    if target is not None:
        _writable(target)
    stored = _stored(check, update) if check is not None else None
    graph = _build(scene, polygon, logs, polygon_read)
    if check is None:
        if output is None:
            click.echo(graph.text)
        else:
            graph.write(output)
            click.echo(output)
        return
    _compare(graph, stored, check, update)


def _compare(graph, stored, check: str, update: bool) -> None:
    from trex.graph_diff import report
    from trex.snapshot import explanation

    plays = f"{len(graph.data['plays'])} plays"
    if stored is not None and stored.data == graph.data:
        click.echo(f"{check}: unchanged ({plays})")
        return
    if stored is None:  # only with --update
        graph.write(check)
        click.echo(f"{check}: written ({plays})")
        return
    message = explanation(report(stored.data, graph.data))
    if update:
        graph.write(check)
        click.echo(f"{check}: updated; {message}")
        return
    click.echo(f"{check}: {message}")
    raise click.exceptions.Exit(EXIT_DIFFERS)


COMMANDS = (snapshot,)
__all__ = ["COMMANDS", "snapshot"]
