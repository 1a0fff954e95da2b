"""``trex chapter`` (hidden): one chapter of a lecture, rendered in a process of its own.

:mod:`trex.chapter_pool` starts it, with the command line :func:`chapter_command_line`
builds: named options, not positions. It renders the scene with ``render_into`` of
``trex render`` (its own temporary media directory; the mp4, its .srt and its step marks,
``NAME.steps.json``, whose ``made_by`` is :func:`render_settings`: ``trex slides lecture``
reuses a chapter render made with the same settings and code). Handed ``--polygon``, the
scene plays it (:func:`trex.render_command.scene_input`); without, what ``manim`` would play
(the environment the process inherits). Failures are one line on stderr, status 1;
SIGTERM/SIGINT stop it with nothing left behind, status 128 + the signal.
"""

from __future__ import annotations

import sys
from pathlib import Path

import click

from story.pseudocode import PANELS
from tracing import JSON
from trex.inputs import EXIT_INVALID, call_timeout_option, error_line
from trex.render_command import (
    EXIT_FAILED,
    QUALITIES,
    SCENES_DIR,
    load_scene_class,
    render_into,
    scene_input,
)
from trex.signals import EXIT_SIGNAL, Interrupted, interrupts_raise
from usercode.errors import UserHeuristicError

__all__ = ["SOURCE_DIRS", "chapter", "chapter_command_line", "render_chapter",
           "render_settings", "source_fingerprint"]

REPO = SCENES_DIR.parent
#: the code a chapter's frames come from (its fingerprint tells a render still up to date)
SOURCE_DIRS = ("tracing", "geometry", "story", "rendering", "metaphors", "scenes", "examples",
               "trex")


def source_fingerprint() -> str:
    """sha256 of the project's Python sources and manim's version: a chapter rendered by
    other code has another."""
    import hashlib

    import manim

    digest = hashlib.sha256(manim.__version__.encode())
    for folder in SOURCE_DIRS:
        for path in sorted((REPO / folder).rglob("*.py")):
            digest.update(str(path.relative_to(REPO)).encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()


def render_settings(scene_file: str, class_name: str | None, quality: str,
                    polygon: str | None, panel: str | None) -> dict[str, JSON]:
    """What a chapter's frames depend on, as its step marks record it (``made_by``):
    ``trex slides lecture`` reuses a chapter render whose settings are these."""
    from story.environment import environment_values

    return {"scene_file": str(Path(scene_file).resolve()), "class": class_name or None,
            "quality": quality, "polygon": polygon or None, "panel": panel or None,
            "environment": environment_values(), "source": source_fingerprint()}


def render_chapter(scene_file: str, class_name: str | None, output: str, quality: str,
                   polygon: str | None = None, panel: str | None = None) -> int:
    """Render one scene to ``output`` (mp4 + .srt + .steps.json, its step marks), handed
    ``polygon`` (None or empty: what ``manim`` would give it), its panel showing ``panel``
    (None or empty: the scene's own); the exit status. A function of one's own it runs has
    the time limit set already (``trex chapter --call-timeout``, the lecture's own); when
    one fails, the status is 2."""
    with interrupts_raise() as signals:
        try:
            try:
                cls = load_scene_class(Path(scene_file), class_name or None)
                settings = render_settings(scene_file, class_name, quality, polygon, panel)
                render_into(scene_input(cls, polygon or None, panel or None), Path(output),
                            "mp4", QUALITIES[quality], progress=False, signals=signals,
                            marks_made_by=settings)
            except UserHeuristicError as exc:  # a function of one's own failed: status 2
                signals.check()
                print(f"error: {exc}", file=sys.stderr)
                return EXIT_INVALID
            except Exception as exc:
                signals.check()
                print(f"error: render failed: {type(exc).__name__}: {error_line(exc)}",
                      file=sys.stderr)
                return EXIT_FAILED
        except Interrupted as exc:
            return EXIT_SIGNAL + exc.signum
    return 0


def chapter_command_line(scene_file: Path, class_name: str | None, output: Path, quality: str,
                         polygon: str | None, panel: str | None,
                         call_timeout: float | None = None) -> list[str]:
    """The command that renders one chapter in a process of its own: ``trex chapter`` with
    the options given (``--opt=value``, so that a value starting with ``-`` stays a value),
    and the lecture's limit on functions of one's own (None: none, said as 0).

    >>> chapter_command_line(Path("scenes/gravity.py"), None, Path("c/01-g.mp4"), "l", "star",
    ...                      None, 2.5)[2:]
    ['trex', 'chapter', '--scene-file=scenes/gravity.py', '--output=c/01-g.mp4', '--quality=l', '--polygon=star', '--call-timeout=2.5']
    """
    given = {"scene-file": str(scene_file), "class": class_name, "output": str(output),
             "quality": quality, "polygon": polygon, "panel": panel}
    return [sys.executable, "-m", "trex", "chapter",
            *(f"--{name}={value}" for name, value in given.items() if value),
            f"--call-timeout={call_timeout or 0:g}"]


@click.command(hidden=True)
@click.option("--scene-file", required=True, metavar="FILE.py", help="The chapter's scene file.")
@click.option("--class", "class_name", metavar="NAME", help="Its scene class (default: the first).")
@click.option("--output", required=True, metavar="PATH", help="The chapter's mp4.")
@click.option("--quality", type=click.Choice(list(QUALITIES)), default="l", show_default=True)
@click.option("--polygon", metavar="POLYGON", help="The polygon handed to the scene (checked "
                                                   "by trex lecture already).")
@click.option("--panel", type=click.Choice(PANELS), default=None, help="What its panel shows.")
@call_timeout_option
def chapter(scene_file: str, class_name: str | None, output: str, quality: str,
            polygon: str | None, panel: str | None) -> None:
    """Render one chapter of ``trex lecture`` (its own process; not for use by hand)."""
    raise click.exceptions.Exit(render_chapter(scene_file, class_name, output, quality,
                                               polygon, panel))
