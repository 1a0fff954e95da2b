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

from pathlib import Path
from typing import TYPE_CHECKING

import click

from story.pseudocode import PANELS
from trex.inputs import call_timeout_option, fail
from trex.output_dir import EXIT_FAILED, build_guarded, built_beside, check_output
from trex.scene_inputs import check_log, choose, load_scene, read_log, run_of

if TYPE_CHECKING:  # manim's, imported when a scene is loaded
    from metaphors.scene import TraceScene

MARKER = ".trex-player"


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
@call_timeout_option
def player(scene: str, polygon: str | None, saved: str | None, output: str,
           panel: str | None) -> None:
    """Write an offline HTML page that steps through SCENE's run, one picture per step.

    SCENE as for `trex render` (gravity, rotation:RotationCcw, my_scene.py:Class, or
    file.py:function for a heuristic of your own). Open DIR/index.html; ← → step, Home End
    jump. Prints the page's path.
    """
    chosen = choose(scene, polygon, saved)
    target = Path(output)
    try:
        check_output(target, MARKER, "an earlier player")
    except ValueError as exc:
        fail(f"{output}: {exc}")
    spec, log, subtitle = run_of(chosen)
    cls = chosen.cls
    played = cls.with_spec(spec)
    played = played.with_panel(panel) if panel else played
    page = build_guarded(scene, output, "player",
                         lambda: _build(played, log, subtitle, target))
    click.echo(str(page))


def _build(cls: type[TraceScene], log, subtitle: str, target: Path) -> Path:
    from trex.player_steps import render_steps, write_player

    with built_beside(target, MARKER, "trex player") as built:
        steps = render_steps(cls, log, built)
        write_player(built, steps, cls.title, subtitle)
    return target / "index.html"


COMMANDS = (player,)
__all__ = ["COMMANDS", "EXIT_FAILED", "check_log", "load_scene", "player", "read_log"]
