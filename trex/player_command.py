"""``trex player``: a self-contained offline HTML page stepping through a run, beat by beat.

``trex player SCENE [--polygon P] -o DIR`` writes ``DIR/index.html`` and ``DIR/steps/*.png``
(one picture per beat, see :mod:`metaphors.player`). SCENE is what ``trex render`` takes: a
name from ``scenes/`` (``gravity``, ``rotation:RotationCcw``), a scene file, or a heuristic of
one's own (``file.py:function``). The scene's algorithm, heuristic, default polygon, title,
theme and pacing are its class attributes; a scene that plays several runs is refused.

Checked before anything is drawn, each as one line and exit status 2: the polygon, the scene,
the output directory, the run itself. The page is built in a temporary directory beside DIR
and renamed into place; an existing DIR is replaced only if it is empty or an earlier player
(it holds the marker file ``.trex-player``). Failure or Ctrl-C leaves DIR as it was.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import click

from geometry.errors import GeometryError
from trex.inputs import error_line, fail, load_or_exit

MARKER = ".trex-player"
EXIT_FAILED = 1


def load_scene(scene: str) -> type:
    """The TraceScene subclass SCENE names (imports manim). Raises ValueError (one line)."""
    if ".py:" in scene:
        from metaphors.generic import scene_for_heuristic

        cls = scene_for_heuristic(scene)
    else:
        from trex.render_command import load_scene_class, resolve_scene

        cls = load_scene_class(*resolve_scene(scene))
    from metaphors.scene import TraceScene

    if not (isinstance(cls, type) and issubclass(cls, TraceScene)):
        raise ValueError(f"{cls.__name__} does not play an algorithm's log; the player needs "
                         "a TraceScene")
    if getattr(cls, "runs", None):
        raise ValueError(f"{cls.__name__} plays several runs; the player steps through one "
                         "(pick a scene of one algorithm)")
    return cls


def check_output(target: Path) -> None:
    """DIR may be new, empty, or an earlier player; its parent is created. ValueError if not."""
    if target.exists() and not target.is_dir():
        raise ValueError("exists and is not a directory")
    if target.is_dir() and any(target.iterdir()) and not (target / MARKER).is_file():
        raise ValueError("exists and is not an earlier player (no .trex-player in it); "
                         "give a new or empty directory")
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"cannot create its parent: {exc.strerror or exc}") from None
    if not os.access(target.parent, os.W_OK):
        raise ValueError(f"cannot write to directory {target.parent}")


def move_into_place(built: Path, target: Path) -> None:
    """Put the finished directory at ``target``; an earlier player there is removed after."""
    if not target.exists():
        os.replace(built, target)
        return
    old = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".old", dir=target.parent))
    os.replace(target, old / "player")
    try:
        os.replace(built, target)
    except OSError:
        os.replace(old / "player", target)  # put the earlier one back
        raise
    finally:
        shutil.rmtree(old, ignore_errors=True)


@click.command()
@click.argument("scene")
@click.option("--polygon", metavar="POLYGON", help="Polygon file or sample (default: the scene's).")
@click.option("-o", "--output", "output", required=True, metavar="DIR",
              help="Directory to write index.html and steps/ into.")
def player(scene: str, polygon: str | None, output: str) -> None:
    """Write an offline HTML page that steps through SCENE's run, one picture per step.

    SCENE as for `trex render` (gravity, rotation:RotationCcw, my_scene.py:Class, or
    file.py:function for a heuristic of your own). Open DIR/index.html; ← → step, Home End
    jump. Prints the page's path.
    """
    if polygon is not None:
        load_or_exit(polygon)  # bad input: one line, exit 2, before anything is drawn
    try:
        cls = load_scene(scene)
    except ValueError as exc:
        fail(f"{scene}: {exc}")
    target = Path(output)
    try:
        check_output(target)
    except ValueError as exc:
        fail(f"{output}: {exc}")
    polygon = polygon if polygon is not None else cls.polygon
    from metaphors.runs import run_logged

    try:
        log = run_logged(cls.algorithm, polygon, cls.heuristic)
    except (GeometryError, ValueError, KeyError) as exc:
        fail(f"{polygon}: {error_line(exc)}")
    from trex.render_command import EXIT_SIGNAL, Interrupted, interrupts_raise

    with interrupts_raise() as signals:
        try:
            page = _build(cls, log, polygon, target)
            signals.done = True
        except Interrupted as exc:
            click.echo(f"error: {scene}: interrupted; {output} left as it was", err=True)
            raise click.exceptions.Exit(EXIT_SIGNAL + exc.signum) from None
        except (click.exceptions.Exit, KeyboardInterrupt):
            raise
        except Exception as exc:
            click.echo(f"error: {scene}: player failed: {type(exc).__name__}: "
                       f"{error_line(exc)}", err=True)
            raise click.exceptions.Exit(EXIT_FAILED) from None
    click.echo(str(page))


def _build(cls: type, log, polygon: str, target: Path) -> Path:
    from metaphors.player import render_steps, write_player

    built = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".player",
                                  dir=target.parent))
    try:
        steps = render_steps(cls, log, built)
        write_player(built, steps, cls.title, f"{log.meta.get('algorithm')} on {polygon}")
        (built / MARKER).write_text("written by trex player\n", encoding="utf-8")
        built.chmod(0o755)  # mkdtemp makes it private
        move_into_place(built, target)
    finally:
        shutil.rmtree(built, ignore_errors=True)
    return target / "index.html"


COMMANDS = (player,)
__all__ = ["COMMANDS", "player"]
