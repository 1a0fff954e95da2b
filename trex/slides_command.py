"""``trex slides``: a presenter's page playing one step per key press, offline.

``trex slides SCENE [--polygon P | --log FILE] [--panel …] [-q l|m|h|k] -o DIR`` renders
SCENE once (``trex render``'s machinery) and cuts its video at the step marks noted while
it rendered (:mod:`metaphors.steps`, :mod:`trex.clips`): DIR gets ``index.html``
(:mod:`trex.slides_page`), ``clips/NNN.mp4`` (one per step) and ``handout.pdf``
(:mod:`trex.handout`). SCENE and its run are checked as for ``trex player``
(:mod:`trex.scene_inputs`).

``trex slides lecture [-j N] [--chapters …] [--polygon P] [--lecture LDIR] -o DIR`` does
the same for the lecture, one source per chapter. A chapter rendered already by
``trex lecture`` into LDIR (default ``media/lecture``) is reused when its step marks say it
was made with the same settings and code (:func:`trex.chapter_command.render_settings`);
the others are rendered as ``trex lecture`` renders them, ``-j`` at a time.

DIR is built beside itself and renamed into place; an existing DIR is replaced only if it
is empty or earlier slides (it holds ``.trex-slides``). Bad input is one line and exit 2
before anything renders; a failure or Ctrl-C leaves DIR as it was.
"""

from __future__ import annotations

import shutil
import time
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, cast

import click

from geometry.io import AnyPolygon
from story.pseudocode import PANELS
from story.scene_kinds import SeveralRuns, plays_several
from trex.inputs import call_timeout_option, error_line, fail, load_or_exit
from trex.output_dir import build_guarded, built_beside, check_output

if TYPE_CHECKING:  # manim's, imported when a scene is loaded
    from metaphors.scene import TraceScene
    from trex.scene_inputs import Chosen

MARKER = ".trex-slides"
LECTURE = "lecture"


def _size(folder: Path) -> int:
    return sum(p.stat().st_size for p in folder.rglob("*") if p.is_file())


def _report(slides: list, folder: Path, began: float) -> None:
    click.echo(f"slides: {len(slides)} steps, {_size(folder) / 1e6:.1f} MB, "
               f"in {time.monotonic() - began:.1f} s")


@click.command()
@click.argument("scene")
@click.option("--polygon", metavar="POLYGON",
              help="Polygon file or sample (default: TREX_POLYGON, else the scene's).")
@click.option("--log", "saved", metavar="FILE.json",
              help="Play a saved log (`trex log` writes them) instead of running live.")
@click.option("-q", "--quality", type=click.Choice(["l", "m", "h", "k"]), default="l",
              show_default=True, help="l 480p15, m 720p30, h 1080p60, k 2160p60.")
@click.option("--panel", type=click.Choice(PANELS), default=None,
              help="What the panel shows: the pseudocode (the scenes' default) or the source.")
@click.option("-o", "--output", "output", required=True, metavar="DIR",
              help="Directory to write index.html, clips/ and handout.pdf into.")
@click.option("-j", "--jobs", type=click.IntRange(min=1), default=None,
              help="lecture only: chapters rendered at once (default 1).")
@click.option("--chapters", "only", metavar="NAME,...",
              help="lecture only: these chapters (slugs), or scenes played as chapters.")
@click.option("--lecture", "lecture_dir", metavar="LDIR", default=None,
              help="lecture only: where `trex lecture` rendered its chapters, to reuse "
                   "(default media/lecture).")
@call_timeout_option
def slides(scene: str, polygon: str | None, saved: str | None, quality: str,
           panel: str | None, output: str, jobs: int | None, only: str | None,
           lecture_dir: str | None) -> None:
    """Write presenter slides of SCENE (as for `trex render`), or of the whole lecture
    (SCENE `lecture`): DIR/index.html, one clip per step, handout.pdf.

    Open DIR/index.html: → Space PageDown play the next step, ← PageUp back, Home End,
    a number and Enter, F full screen, S speaker window (or index.html?notes).
    """
    if scene == LECTURE:
        if saved is not None:
            fail("--log: the lecture plays many runs; give --polygon for its chapters")
        polygon_read = load_or_exit(polygon) if polygon is not None else None  # read once
        _lecture(Path(output), quality, jobs or 1, polygon, panel, only,
                 Path(lecture_dir) if lecture_dir else None, polygon_read=polygon_read)
        return
    for name, given in (("-j", jobs), ("--chapters", only), ("--lecture", lecture_dir)):
        if given is not None:
            fail(f"{name}: only for `trex slides lecture`")
    from trex.scene_inputs import choose

    chosen = choose(scene, polygon, saved, "slides", several_runs=True)
    target = Path(output)
    try:
        check_output(target, MARKER, "earlier slides")
    except ValueError as exc:
        fail(f"{output}: {exc}")
    played, subtitle = _played(chosen, scene)
    played = played.with_panel(panel) if panel else played
    began = time.monotonic()
    shown = build_guarded(scene, output, "slides",
                          lambda: _scene_slides(played, quality, subtitle, target))
    _report(shown, target, began)
    click.echo(str(target / "index.html"))


def _played(chosen: Chosen, scene: str) -> tuple[type[TraceScene], str]:
    """The scene class handed what it plays, and the line saying what that is: its one run
    (as the player's), or all its runs, each on its own polygon."""
    from trex.scene_inputs import run_of

    if not plays_several(chosen.cls):
        spec, _, subtitle = run_of(chosen)
        return chosen.cls.with_spec(spec), subtitle
    runs = cast(SeveralRuns, chosen.cls).runs  # plays_several said so
    if chosen.saved is not None:
        fail(f"{chosen.saved_as}: {scene} plays {len(runs)} runs, each on its own polygon; a "
             "saved log is one run")
    if chosen.polygon is not None:
        click.echo(f"warning: {scene}: plays its own polygons; --polygon is ignored", err=True)
    return chosen.cls.handed(), f"{len(runs)} runs, each on its own polygon"


def _scene_slides(cls: type[TraceScene], quality: str, subtitle: str, target: Path) -> list:
    from trex.assemble import probe
    from trex.clips import read_marks
    from trex.render_command import QUALITIES, render_into
    from trex.slides_build import Source, build_slides

    with built_beside(target, MARKER, "trex slides") as built:
        video = built / "render" / "scene.mp4"
        video.parent.mkdir()
        render_into(cls, video, "mp4", QUALITIES[quality], progress=False, srt=False,
                    marks_made_by={"scene": cls.__name__, "quality": quality})
        found = probe(video)
        shown = build_slides(built, [Source(video, read_marks(video))], cls.title, subtitle,
                             (found.width, found.height))
        shutil.rmtree(video.parent)  # the clips hold every frame of it
    return shown


# --- the lecture -------------------------------------------------------------------------------


def _lecture(target: Path, quality: str, jobs: int, polygon: str | None, panel: str | None,
             only: str | None, lecture_dir: Path | None, *, polygon_read: AnyPolygon | None = None,
             ) -> None:
    from trex import chapters as ch
    from trex.lecture_join import DEFAULT_DIR

    try:
        chapters: Sequence[ch.Chapter] = ch.lecture_chapters()
    except Exception as exc:  # the chapter list itself is broken
        ch.chapter_failed(f"lecture chapters: {type(exc).__name__}: {error_line(exc)}")
    if only is not None:
        try:
            chapters = ch.pick_chapters(only, chapters)
        except ValueError as exc:
            fail(f"--chapters {only}: {exc}")
    if not chapters:
        ch.chapter_failed("the lecture has no chapters")
    try:
        check_output(target, MARKER, "earlier slides")
    except ValueError as exc:
        fail(f"{target}: {exc}")
    try:
        ch.check_chapters(chapters, polygon, polygon_read)
    except ch.ChapterFailed as exc:
        ch.chapter_failed(str(exc))
    began = time.monotonic()
    where = lecture_dir if lecture_dir is not None else DEFAULT_DIR
    shown = build_guarded(LECTURE, str(target), "slides",
                          lambda: _lecture_slides(chapters, target, quality, jobs, polygon,
                                                  panel, where))
    _report(shown, target, began)
    click.echo(str(target / "index.html"))


def reusable(video: Path, settings: dict):
    """The step marks of a chapter render at ``video`` if it was made with ``settings`` and
    its video has the frames they mark (None: render it again)."""
    from trex.clips import frame_count, read_marks, step_ranges

    try:
        marks = read_marks(video)
        if marks.made_by != settings:
            return None
        if marks.steps:
            step_ranges(marks, frame_count(video))
    except (OSError, ValueError, KeyError, TypeError):  # missing, unreadable, not fitting
        return None
    return marks


def _source(video: Path, marks, chapter):
    """A chapter's video as a source of slides: a scene that marks no steps (not one of
    this project's) is one step, captioned with the chapter's title."""
    from dataclasses import replace

    from story.step_marks import StepMark
    from trex.chapters import teacher_notes
    from trex.slides_build import Source

    title = f"{chapter.number}. {chapter.title}"
    if not marks.steps:
        marks = replace(marks, steps=(StepMark(0, title, None, "chapter"),))
    notes = tuple(f"{note.title}: {line}" for note in teacher_notes(chapter)
                  for line in note.lines)
    return Source(video, marks, title, notes)


def _lecture_slides(chapters, target: Path, quality: str, jobs: int, polygon: str | None,
                    panel: str | None, lecture_dir: Path) -> list:
    from trex import chapter_pool
    from trex.assemble import probe
    from trex.chapter_command import render_settings
    from trex.chapters import chapter_label, chapter_stem, scene_path
    from trex.clips import read_marks
    from trex.lecture_join import CHAPTER_DIR
    from trex.slides_build import build_slides

    with built_beside(target, MARKER, "trex slides") as built:
        sources: list = [None] * len(chapters)
        missing = []
        for k, chapter in enumerate(chapters):
            video = lecture_dir / CHAPTER_DIR / f"{chapter_stem(chapter)}.mp4"
            settings = render_settings(str(scene_path(chapter)), chapter.scene_class,
                                       quality, polygon, panel)
            marks = reusable(video, settings)
            if marks is None:
                missing.append(k)
            else:
                sources[k] = _source(video, marks, chapter)
                click.echo(f"{chapter_label(k, len(chapters), chapter)}: reused {video}")
        renders, logs = built / "render", built / "logs"
        renders.mkdir()
        logs.mkdir()

        def done(k, chapter, video, seconds):
            click.echo(f"{chapter_label(missing[k], len(chapters), chapter)}: "
                       f"{float(video.duration):.1f} s of video in {seconds:.1f} s")

        picked = [chapters[k] for k in missing]
        videos = chapter_pool.render_chapters(picked, renders, logs, quality,
                                              min(jobs, len(picked)), polygon, done,
                                              panel) if picked else []
        for k, video in zip(missing, videos, strict=True):
            sources[k] = _source(video.path, read_marks(video.path), chapters[k])
        found = probe(sources[0].video)
        shown = build_slides(built, sources, "Triangulation Explained: the lecture",
                             f"{len(chapters)} chapters",
                             (found.width, found.height))
        shutil.rmtree(renders)
        shutil.rmtree(logs)
    return shown


COMMANDS = (slides,)
__all__ = ["COMMANDS", "MARKER", "reusable", "slides"]
