"""``trex lecture``: every chapter rendered, in parallel, then joined into one lecture.

The command's own job is the order of things; each part is a module of its own:

- the chapters found, picked by ``--chapters`` and checked before any rendering
  (:mod:`trex.chapters`);
- each chapter rendered by the hidden ``trex chapter`` in a process of its own
  (:mod:`trex.chapter_command`), at most ``-j`` at a time (:mod:`trex.chapter_pool`);
- the lecture's files joined from them (:mod:`trex.lecture_join`): one mp4, one .srt,
  ``chapters.json`` and ``chapters.md``; the chapter mp4s are kept in ``chapters/``.

Everything is built in a temporary directory beside DIR and moved into place at the end
(:func:`trex.output_dir.move_into_place`), with SIGINT and SIGTERM held for the moves
(:mod:`trex.signals`). Ctrl-C, SIGTERM or a failing chapter stop the other renders and leave
DIR as it was. Bad input (the polygon, or a polygon a chapter's algorithm rejects, an output
that is not a directory) is one line and status 2 before any rendering; a chapter that fails
to render is one line naming it and status 1.

The polygon reaches each chapter's process as an option, and the chapter's scene is handed it
(:func:`trex.render_command.scene_input`); without ``--polygon`` a chapter plays what
``manim`` would play (the environment the process inherits). ``--panel`` reaches it the same
way: what every chapter's panel shows (default: each scene's own, the pseudocode).
"""

from __future__ import annotations

import shutil
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path

import click

from geometry.io import AnyPolygon
from story.pseudocode import PANELS
from trex.chapter_command import chapter
from trex.chapter_pool import render_chapters
from trex.chapters import (
    Chapter,
    ChapterFailed,
    chapter_failed,
    chapter_label,
    check_chapters,
    lecture_chapters,
    pick_chapters,
)
from trex.inputs import call_timeout_option, error_line, fail, load_or_exit
from trex.lecture_join import (
    CHAPTER_DIR,
    DEFAULT_DIR,
    OUTPUTS,
    VIDEO,
    check_output_dir,
    join_lecture,
)
from trex.output_dir import move_into_place
from trex.render_command import QUALITIES
from trex.signals import EXIT_SIGNAL, Interrupted, Signals, interrupts_raise, signals_held

__all__ = ["COMMANDS", "build_lecture", "lecture", "run_lecture"]


def build_lecture(chapters: Sequence[Chapter], out_dir: Path, quality: str, jobs: int,
                  polygon: str | None, signals: Signals | None = None,
                  echo: Callable[[str], None] = click.echo,
                  panel: str | None = None) -> tuple[Path, float]:
    """Render and join ``chapters`` into ``out_dir`` (their panels showing ``panel``; None:
    each scene's own); returns the lecture mp4 and its length in seconds. Raises
    :class:`ChapterFailed`, or :class:`Interrupted` on a signal (with ``signals`` from
    ``interrupts_raise``); then nothing at ``out_dir`` has changed."""
    where = out_dir.resolve()  # "." has no name and is its own parent
    temp = Path(tempfile.mkdtemp(prefix=f".{where.name}.", suffix=".lecture",
                                 dir=where.parent))
    try:
        stage, logs = temp / "lecture", temp / "logs"
        for folder in (stage / CHAPTER_DIR, logs):
            folder.mkdir(parents=True)

        def done(k, chapter, video, seconds):
            echo(f"{chapter_label(k, len(chapters), chapter)}: {float(video.duration):.1f} s "
                 f"of video in {seconds:.1f} s")

        videos = render_chapters(chapters, stage / CHAPTER_DIR, logs, quality,
                                 max(1, min(jobs, len(chapters))), polygon, done, panel)
        for one, video in zip(chapters, videos, strict=True):
            if video.audio:
                click.echo(f"warning: {one.slug}: has sound; the lecture keeps its video only",
                           err=True)
        reason = join_lecture(chapters, videos, stage)
        if reason is not None:
            click.echo(f"note: the lecture was encoded again (no remux): {reason}", err=True)
        with signals_held():
            if signals is not None:
                signals.check()
            move_into_place(stage, out_dir, OUTPUTS)
            if signals is not None:
                signals.done = True
        return out_dir / VIDEO, float(sum(v.duration for v in videos))
    finally:
        shutil.rmtree(temp, ignore_errors=True)


@click.command()
@click.option("-q", "--quality", type=click.Choice(list(QUALITIES)), default="l",
              show_default=True, help="l 480p15, m 720p30, h 1080p60, k 2160p60.")
@click.option("-j", "--jobs", type=click.IntRange(min=1), default=1, show_default=True,
              help="Chapters rendered at once (one process each).")
@click.option("--polygon", metavar="POLYGON",
              help="Polygon file or sample for the chapters (those with fixed polygons ignore it).")
@click.option("-o", "--output", "out_dir", metavar="DIR", default=str(DEFAULT_DIR),
              show_default=True, help="Directory of the lecture.")
@click.option("--chapters", "only", metavar="NAME,...",
              help="Only these chapters (slugs), or scenes played as chapters.")
@click.option("--panel", type=click.Choice(PANELS), default=None,
              help="What the panels show: the pseudocode (the scenes' default; the source "
                   "when a run has none) or the real source.")
@call_timeout_option
def lecture(quality: str, jobs: int, polygon: str | None, out_dir: str,
            only: str | None, panel: str | None) -> None:
    """Render every chapter of the lecture and join them: DIR/lecture.mp4, lecture.srt,
    chapters.json, chapters.md and the chapter videos in DIR/chapters/.

    Prints one line per chapter as it finishes, then the lecture's path. An interrupted or
    failed run leaves DIR as it was.
    """
    # bad input: one line, exit 2, before anything else; read once, the checks' polygon
    polygon_read = load_or_exit(polygon) if polygon is not None else None
    run_lecture(None, Path(out_dir), quality, jobs, polygon, only, panel, polygon_read=polygon_read)


def _chapters(chapters: Sequence[Chapter] | None, only: str | None) -> Sequence[Chapter]:
    """The chapters to render: ``chapters`` (None: the lecture's own), picked by ``only``."""
    if chapters is None:
        try:
            chapters = lecture_chapters()
        except ModuleNotFoundError as exc:
            if only is None or exc.name != "metaphors.lecture":
                chapter_failed(f"lecture chapters: {type(exc).__name__}: {error_line(exc)}")
            chapters = ()  # not written yet: --chapters names scenes
        except Exception as exc:  # the chapter list itself is broken
            chapter_failed(f"lecture chapters: {type(exc).__name__}: {error_line(exc)}")
    if only is not None:
        try:
            chapters = pick_chapters(only, chapters)
        except ValueError as exc:
            fail(f"--chapters {only}: {exc}")
    if not chapters:
        chapter_failed("the lecture has no chapters")
    return chapters


def run_lecture(chapters: Sequence[Chapter] | None, out_dir: Path, quality: str = "l",
                jobs: int = 1, polygon: str | None = None, only: str | None = None,
                panel: str | None = None, *, polygon_read: AnyPolygon | None = None) -> Path:
    """The command after its polygon check: ``chapters`` None = the lecture's own;
    ``polygon_read``: ``polygon`` read already (None: the checks read it)."""
    chapters = _chapters(chapters, only)
    try:
        check_output_dir(out_dir)
    except ValueError as exc:
        fail(f"{out_dir}: {exc}")
    began = time.monotonic()
    with interrupts_raise() as signals:
        try:
            check_chapters(chapters, polygon, polygon_read)
            video, seconds = build_lecture(chapters, out_dir, quality, jobs, polygon, signals,
                                           panel=panel)
        except Interrupted as exc:
            click.echo("error: lecture interrupted; nothing written", err=True)
            raise click.exceptions.Exit(EXIT_SIGNAL + exc.signum) from None
        except ChapterFailed as exc:
            signals.check()
            chapter_failed(str(exc), exc.status)
        except (KeyboardInterrupt, click.exceptions.Exit):
            raise
        except Exception as exc:
            signals.check()  # an interrupt that surfaced as another error is still one
            chapter_failed(f"lecture failed: {type(exc).__name__}: {error_line(exc)}")
    click.echo(f"lecture: {seconds:.1f} s of video, {len(chapters)} chapters, "
               f"in {time.monotonic() - began:.1f} s")
    click.echo(str(video))
    return video


COMMANDS = (lecture, chapter)
