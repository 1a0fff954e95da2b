"""``trex player``: a self-contained offline HTML page stepping through a run, beat by beat.

``trex player SCENE [--polygon P | --log FILE] -o DIR`` writes ``DIR/index.html`` and
``DIR/steps/*.png`` (one picture per beat, see :mod:`trex.player_steps`). SCENE is what
``trex render`` takes: a name from ``scenes/`` (``gravity``, ``rotation:RotationCcw``), a scene
file, or a heuristic of one's own (``file.py:function``). The scene's algorithm, heuristic,
default polygon, title, theme and pacing are its class attributes; a scene that plays several
runs is refused.

The run played is the one ``trex render SCENE`` would play (a :class:`story.spec.RunSpec`):
``--log FILE`` (a saved log, as ``trex log`` writes) or ``--polygon`` if given, else
``TREX_LOG``, else a live run on ``TREX_POLYGON`` or the scene's default polygon (read by
:mod:`story.environment`). A saved log must be of the algorithm (and heuristic) the scene
plays.

Checked before anything is drawn, each as one line and exit status 2: the polygon or saved
log (a missing file, not a trex log, a log of another algorithm than the scene's), the scene,
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
from geometry.user_heuristics import is_user_spec
from story.pseudocode import PANELS
from trex.inputs import error_line, fail, load_or_exit

MARKER = ".trex-player"
EXIT_FAILED = 1


def load_scene(scene: str) -> type:
    """The TraceScene subclass SCENE names (imports manim). Raises ValueError (one line)."""
    if ".py:" in scene:
        from metaphors.scene import scene_for_heuristic

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


def read_log(path: str):
    """The saved log at ``path`` (a :class:`tracing.Log` of one run). Raises ValueError (one
    line) for a file that cannot be read or is not a trex log of a run."""
    from story.runs import saved_log

    try:
        log = saved_log(path)
    except OSError as exc:
        raise ValueError(f"cannot read: {exc.strerror or error_line(exc)}") from None
    except (ValueError, KeyError, TypeError, RecursionError) as exc:  # JSON, UTF-8, schema
        raise ValueError(f"not a trex log: {error_line(exc)}") from None
    algorithm = log.meta.get("algorithm")
    if not isinstance(algorithm, str) or not algorithm:
        raise ValueError("not the log of a run: its meta names no algorithm")
    return log


def _same_algorithm(plays: str, logged: str) -> bool:
    """A heuristic of one's own is the same when its function is (the path may be spelled
    differently)."""
    if plays == logged:
        return True
    return (is_user_spec(plays) and is_user_spec(logged)
            and plays.rpartition(":")[2] == logged.rpartition(":")[2])


def check_log(cls: type, log, scene: str | None = None) -> None:
    """A saved log must be a run of what the scene (named ``scene``) plays and give steps
    that start with the polygon. Raises ValueError (one line)."""
    from metaphors.catalog import beats as storyboard

    logged, plays, name = log.meta["algorithm"], cls.algorithm, scene or cls.__name__
    if not _same_algorithm(plays, logged):
        raise ValueError(f"is a log of {logged}, but {name} plays {plays}")
    ran_with, wants = log.meta.get("heuristic"), getattr(cls, "heuristic", None)
    if ran_with and wants and ran_with != wants:
        raise ValueError(f"is a log of {logged} with {ran_with}, but {name} plays "
                         f"{plays} with {wants}")
    try:
        beats = storyboard(log)
    except Exception as exc:  # a malformed event: whatever it breaks, the log is at fault
        raise ValueError(f"cannot be played: {type(exc).__name__}: {error_line(exc)}") from None
    if not beats or not {"points", "labels"} <= set(beats[0].data):
        raise ValueError("cannot be played: it does not start with the polygon")


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
@click.option("--polygon", metavar="POLYGON",
              help="Polygon file or sample (default: TREX_POLYGON, else the scene's).")
@click.option("--log", "saved", metavar="FILE.json",
              help="Play a saved log (`trex log` writes them) instead of running live; "
                   "as TREX_LOG for scenes, which is read when neither option is given.")
@click.option("-o", "--output", "output", required=True, metavar="DIR",
              help="Directory to write index.html and steps/ into.")
@click.option("--panel", type=click.Choice(PANELS), default=None,
              help="What the panel shows: the pseudocode (the scenes' default; the source "
                   "when the run has none) or the real source.")
def player(scene: str, polygon: str | None, saved: str | None, output: str,
           panel: str | None) -> None:
    """Write an offline HTML page that steps through SCENE's run, one picture per step.

    SCENE as for `trex render` (gravity, rotation:RotationCcw, my_scene.py:Class, or
    file.py:function for a heuristic of your own). Open DIR/index.html; ← → step, Home End
    jump. Prints the page's path.
    """
    if polygon is not None and saved is not None:
        fail("--polygon and --log: give one of them (a saved log has its own polygon)")
    saved_as = saved
    if polygon is None and saved is None:  # as scenes do: TREX_LOG, else TREX_POLYGON
        from story.environment import LOG, POLYGON, environment_values

        values = environment_values()
        if LOG in values:
            saved, saved_as = values[LOG], f"{LOG}={values[LOG]}"
        else:
            polygon = values.get(POLYGON)
    log = None
    if saved is not None:  # bad input: one line, exit 2, before anything is drawn
        try:
            log = read_log(saved)
        except ValueError as exc:
            fail(f"{saved_as}: {exc}")
    elif polygon is not None:
        load_or_exit(polygon)
    try:
        cls = load_scene(scene)
    except ValueError as exc:
        fail(f"{scene}: {exc}")
    if log is not None:
        try:
            check_log(cls, log, scene)
        except ValueError as exc:
            fail(f"{saved_as}: {exc}")
    target = Path(output)
    try:
        check_output(target)
    except ValueError as exc:
        fail(f"{output}: {exc}")
    spec = cls.default_spec()
    if log is None:
        spec = spec.on(polygon) if polygon is not None else spec
        try:
            log = spec.log()
        except (GeometryError, ValueError, KeyError) as exc:
            fail(f"{spec.polygon}: {error_line(exc)}")
        subtitle = f"{log.meta.get('algorithm')} on {spec.polygon}"
    else:
        spec = spec.replaying(saved)
        subtitle = (f"{log.meta.get('algorithm')} on {log.meta.get('polygon', '?')}, "
                    f"saved in {Path(saved).name}")
    from trex.render_command import EXIT_SIGNAL, Interrupted, interrupts_raise

    with interrupts_raise() as signals:
        try:
            played = cls.with_spec(spec)
            page = _build(played.with_panel(panel) if panel else played, log, subtitle, target)
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


def _build(cls: type, log, subtitle: str, target: Path) -> Path:
    from trex.player_steps import render_steps, write_player

    built = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".player",
                                  dir=target.parent))
    try:
        steps = render_steps(cls, log, built)
        write_player(built, steps, cls.title, subtitle)
        (built / MARKER).write_text("written by trex player\n", encoding="utf-8")
        built.chmod(0o755)  # mkdtemp makes it private
        move_into_place(built, target)
    finally:
        shutil.rmtree(built, ignore_errors=True)
    return target / "index.html"


COMMANDS = (player,)
__all__ = ["COMMANDS", "player"]
