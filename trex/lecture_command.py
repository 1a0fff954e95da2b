"""``trex lecture``: every chapter rendered, in parallel, then joined into one lecture.

The chapters are the scene files ``scenes/chapters/ch<k>_<slug>.py`` (``--chapters`` picks
some of them by slug, or names scenes to play as chapters instead). Each chapter renders in a process of its own,
``python -m trex.lecture_command`` (:func:`render_chapter`: ``render_into`` of
``trex render``, so each has its own temporary media directory), at most ``-j`` at a time.
When all are done, :mod:`trex.assemble` joins them: one mp4 (packets remuxed, not
encoded again), one .srt, ``chapters.json`` and ``chapters.md``; the chapter mp4s are kept
in ``chapters/``.

Everything is built in a temporary directory beside DIR and moved into place at the end,
with SIGINT and SIGTERM held for the moves. Ctrl-C, SIGTERM or a failing chapter stop the
other renders and leave DIR as it was. Bad input (the polygon, or a polygon a chapter's
algorithm rejects, an output that is not a directory) is one line and status 2 before any
rendering; a chapter that fails to render is one line naming it and status 1.

With ``--polygon``, a lecture chapter is checked by what it plays: each of its segments that
runs on the lecture's polygon (a ``Run`` or ``Compare`` whose polygon is None) is computed
once on it, as :class:`metaphors.lecture.LectureScene` would, without drawing
(:func:`polygon_checks`); a scene played as a chapter dry-runs its ``algorithm``. The
polygon reaches each chapter's process as an argument, and the chapter's scene is handed it
(:func:`trex.render_command.scene_input`); without ``--polygon`` a chapter plays what
``manim`` would play (the environment the process inherits). ``--panel`` reaches it the
same way: what every chapter's panel shows (default: each scene's own, the pseudocode).
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import NoReturn

import click

from geometry.errors import GeometryError
from geometry.user_heuristics import UserHeuristicError, call_timeout, set_call_timeout
from story.environment import call_timeout_from_environment, child_environment
from story.pseudocode import PANELS
from story.scene_kinds import ChapterScene, plays_several
from trex.inputs import (
    EXIT_INVALID,
    call_timeout_option,
    error_line,
    fail,
    first_line,
    load_or_exit,
    make_parent,
)
from trex.render_command import (
    EXIT_FAILED,
    EXIT_SIGNAL,
    QUALITIES,
    SCENES_DIR,
    Interrupted,
    _signals_held,
    dry_run,
    interrupts_raise,
    load_scene_class,
    render_into,
    resolve_scene,
    scene_input,
)

REPO = SCENES_DIR.parent
CHAPTERS_DIR = SCENES_DIR / "chapters"
DEFAULT_DIR = Path("media") / "lecture"
VIDEO, SUBTITLES, LIST_JSON, LIST_MD, CHAPTER_DIR = (
    "lecture.mp4", "lecture.srt", "chapters.json", "chapters.md", "chapters")
OUTPUTS = (CHAPTER_DIR, VIDEO, SUBTITLES, LIST_JSON, LIST_MD)  # what DIR receives
POLL = 0.05  # seconds between looks at the running renders
STOP_WAIT = 20.0  # seconds a stopped render may take to clean up before it is killed


@dataclass(frozen=True)
class Chapter:
    """A chapter: its place in the lecture, its slug and title, its scene file and class
    (None: the file's first)."""

    number: int
    slug: str
    title: str
    scene_file: str
    scene_class: str | None




class ChapterFailed(Exception):
    """A chapter could not be rendered (its one-line reason is the message); ``status``: the
    command's exit status for it (2 when a function of one's own failed in it, else 1)."""

    def __init__(self, message: str, status: int = EXIT_FAILED) -> None:
        super().__init__(message)
        self.status = status


def lecture_chapters() -> tuple[Chapter, ...]:
    """The lecture's chapters: the scene files ``scenes/chapters/ch<k>_<slug>.py``, in the
    order of ``k``, each titled by its class's ``chapter_title`` (``"3. Gravity"``: the part
    after the number). Loading them imports manim, so only when asked for."""
    found = []
    for path in CHAPTERS_DIR.glob("ch*_*.py"):
        number, _, slug = path.stem[2:].partition("_")
        if number.isdigit():
            found.append((int(number), slug.replace("_", "-"), path))
    chapters = []
    for number, slug, path in sorted(found):
        cls = load_scene_class(path, None)
        title = str(cls.chapter_title if isinstance(cls, ChapterScene) else slug).partition(". ")
        chapters.append(Chapter(number, slug, title[2] or title[0], str(path.relative_to(REPO)),
                                cls.__name__))
    return tuple(chapters)


def pick_chapters(spec: str, chapters: Sequence | None) -> list:
    """Chapters named in ``spec`` (comma-separated): a slug of ``chapters``, else a scene
    (``scaling``, ``rotation:RotationCcw``, ``my.py:Mine``) played as a chapter numbered by
    its place. Raises ValueError with a one-line reason.

    >>> [(c.number, c.slug, c.scene_class) for c in pick_chapters("scaling,rotation:RotationCcw",
    ...                                                           None)]
    [(1, 'scaling', None), (2, 'rotation-RotationCcw', 'RotationCcw')]
    """
    by_slug = {c.slug: c for c in chapters or ()}
    picked = []
    for k, item in enumerate((s.strip() for s in spec.split(",")), 1):
        if not item:
            raise ValueError("empty chapter name")
        if item in by_slug:
            picked.append(by_slug[item])
            continue
        path, class_name = resolve_scene(item)
        slug = path.stem if class_name is None else f"{path.stem}-{class_name}"
        title = path.stem.replace("_", " ").capitalize()
        title = title if class_name is None else f"{title} ({class_name})"
        picked.append(Chapter(k, slug.replace("_", "-"), title, str(path), class_name))
    return picked


def scene_path(chapter) -> Path:
    """A chapter's scene file (relative paths are from the repository root)."""
    path = Path(chapter.scene_file)
    return path if path.is_absolute() else REPO / path


def chapter_stem(chapter) -> str:
    """``01-overview``: the chapter's files in ``chapters/``.

    >>> chapter_stem(Chapter(3, "gravity", "Gravity", "scenes/gravity.py", None))
    '03-gravity'
    """
    return f"{chapter.number:02d}-{chapter.slug}"


def chapter_label(k: int, n: int, chapter) -> str:
    """``chapter 3/7 gravity``: how messages name chapter ``k`` (from 0) of ``n``."""
    return f"chapter {k + 1}/{n} {chapter.slug}"


# --- checks before rendering ------------------------------------------------------------------------


def lecture_segments(cls: type) -> tuple | None:
    """The segments a lecture chapter's class plays (None: not a lecture chapter). Listed
    without building the scene: ``chapter_segments`` needs only the class's attributes."""
    from metaphors.lecture import LectureScene

    if not (isinstance(cls, type) and issubclass(cls, LectureScene)):
        return None
    return tuple(cls.__new__(cls).chapter_segments())


def polygon_checks(segments: Sequence,
                   polygon: str) -> list[tuple[str, tuple, Callable[[], object]]]:
    """``(what, key, check)`` for each segment that plays the lecture's polygon: ``check()``
    computes what the chapter would show — a Run's log, a Compare's two triangulations — by
    the chapter's own calls, on ``polygon`` (the one the chapter is handed). Equal keys are
    the same computation."""
    from geometry.cdt import constrained_delaunay
    from geometry.triangulate import triangulate
    from metaphors import lecture
    from metaphors.lecture import Compare, Run

    def run(segment: Run):
        return segment.spec(polygon).log()

    def compare(segment: Compare):
        shape = lecture.read_polygon(polygon)
        return triangulate(shape, segment.ours), constrained_delaunay(shape)

    checks = []
    for segment in segments:
        if isinstance(segment, Run) and segment.polygon is None:
            what = segment.algorithm + (f" with {segment.heuristic}" if segment.heuristic
                                        else "")
            checks.append((what, ("run", segment.algorithm, segment.heuristic),
                           lambda segment=segment: run(segment)))
        elif isinstance(segment, Compare) and segment.polygon is None:
            checks.append((f"{segment.ours} beside constrained Delaunay",
                           ("compare", segment.ours), lambda segment=segment: compare(segment)))
    return checks


def check_chapters(chapters: Sequence, polygon: str | None) -> None:
    """Load every chapter's scene class and, with a polygon, compute on it what the chapter
    plays on it (:func:`polygon_checks`; a scene that is not a lecture chapter: its
    ``algorithm``, once), drawing nothing.

    A scene that does not load raises :class:`ChapterFailed`; a polygon a chapter's run
    rejects exits with status 2 (bad input).
    """
    stems = [chapter_stem(c) for c in chapters]
    if len(set(stems)) != len(stems):
        raise ChapterFailed(f"chapters repeat: {', '.join(stems)}")
    done: set = set()  # computations already checked (chapters share runs)
    for k, chapter in enumerate(chapters):
        path = scene_path(chapter)
        try:
            if not path.is_file():
                raise ValueError(f"no such scene file: {chapter.scene_file}")
            cls = load_scene_class(path, chapter.scene_class or None)
        except ValueError as exc:
            raise ChapterFailed(f"{chapter_label(k, len(chapters), chapter)}: {exc}") from None
        if polygon is not None:
            _check_polygon(cls, polygon, chapter_label(k, len(chapters), chapter), done)


def _check_polygon(cls: type, polygon: str, label: str, done: set) -> None:
    """One chapter's part of :func:`check_chapters`; ``done`` holds the keys already run."""
    try:
        segments = lecture_segments(cls)
    except Exception as exc:  # the chapter's own list is broken: it would not render either
        raise ChapterFailed(f"{label}: cannot list its segments: {type(exc).__name__}: "
                            f"{error_line(exc)}") from None
    if segments is None:
        if not plays_several(cls):
            try:
                dry_run(cls, polygon)
            except (GeometryError, ValueError, KeyError) as exc:
                fail(f"{polygon}: {error_line(exc)}")
        return
    for what, key, check in polygon_checks(segments, polygon):
        if key in done:
            continue
        try:
            check()
        except (GeometryError, ValueError, KeyError) as exc:
            fail(f"{polygon}: {label}: {what}: {error_line(exc)}")
        done.add(key)


def check_output_dir(out_dir: Path) -> None:
    """DIR must be a directory (or not exist yet) whose entries we write are of the right
    kind; its parent is created. Raises ValueError with a one-line reason."""
    if out_dir.exists() and not out_dir.is_dir():
        raise ValueError("exists and is not a directory")
    for name in OUTPUTS:
        target = out_dir / name
        if target.exists() and target.is_dir() != (name == CHAPTER_DIR):
            kind = "not a directory" if name == CHAPTER_DIR else "a directory"
            raise ValueError(f"{name} in it is {kind}")
    make_parent(out_dir)
    if out_dir.is_dir() and not os.access(out_dir, os.W_OK):
        raise ValueError("cannot write there")


# --- rendering the chapters in processes of their own ------------------------------------------------


@dataclass
class _Render:
    k: int
    chapter: object
    process: subprocess.Popen
    log: Path
    output: Path
    began: float


def _start(k: int, chapter, folder: Path, logs: Path, quality: str,
           polygon: str | None, panel: str | None = None) -> _Render:
    output = folder / f"{chapter_stem(chapter)}.mp4"
    log = logs / f"{chapter_stem(chapter)}.log"
    command = [sys.executable, "-m", "trex.lecture_command", str(scene_path(chapter)),
               chapter.scene_class or "", str(output), quality, polygon or "", panel or ""]
    # this command's --call-timeout, for the functions of one's own the chapter runs
    env = child_environment(call_timeout())
    with open(log, "wb") as sink:
        # its own session: Ctrl-C at the terminal reaches only us, and we stop it
        process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=sink,
                                   stderr=subprocess.STDOUT, start_new_session=True, env=env)
    return _Render(k, chapter, process, log, output, time.monotonic())


def _reason(render: _Render, code: int) -> str:
    try:
        lines = render.log.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        lines = []
    said = next((first_line(line) for line in reversed(lines) if line.strip()), "")
    if said.startswith("error: "):
        said = said[len("error: "):]
    if code < 0:
        killed = f"render process killed by {signal.Signals(-code).name}"
        return f"{killed}: {said}" if said else killed
    return said or f"render process exited with status {code}"


def _stop(renders: Sequence[_Render]) -> None:
    """Stop running renders (SIGTERM: each removes its own temporary files), then wait."""
    for render in renders:
        if render.process.poll() is None:
            render.process.terminate()
    deadline = time.monotonic() + STOP_WAIT
    for render in renders:
        try:
            render.process.wait(max(0.0, deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            render.process.kill()
            render.process.wait()


def render_chapters(chapters: Sequence, folder: Path, logs: Path, quality: str, jobs: int,
                    polygon: str | None,
                    done: Callable[[int, object, object, float], None] | None = None,
                    panel: str | None = None) -> list:
    """Render every chapter to ``folder/NN-slug.mp4`` (+ .srt), ``jobs`` at a time, their
    panels showing ``panel`` (None: each scene's own).

    Returns the chapters' :class:`trex.assemble.Video` in chapter order; calls
    ``done(k, chapter, video, seconds)`` as each one finishes. The first failure stops the
    others and raises :class:`ChapterFailed`; so does an exception (an interrupt) here.
    """
    from trex.assemble import probe

    pending = list(enumerate(chapters))
    running: list[_Render] = []
    videos: list = [None] * len(chapters)
    try:
        while pending or running:
            while pending and len(running) < jobs:
                k, chapter = pending.pop(0)
                running.append(_start(k, chapter, folder, logs, quality, polygon, panel))
            time.sleep(POLL)
            for render in list(running):
                code = render.process.poll()
                if code is None:
                    continue
                running.remove(render)
                label = chapter_label(render.k, len(chapters), render.chapter)
                if code != 0:
                    raise ChapterFailed(f"{label}: {_reason(render, code)}",
                                        EXIT_INVALID if code == EXIT_INVALID else EXIT_FAILED)
                try:
                    video = probe(render.output)
                except (OSError, ValueError, RuntimeError) as exc:  # av errors are OSErrors
                    raise ChapterFailed(f"{label}: unreadable video: {error_line(exc)}") from None
                videos[render.k] = video
                if done is not None:
                    done(render.k, render.chapter, video, time.monotonic() - render.began)
    finally:
        _stop(running)
    return videos


# --- assembling and moving into place ------------------------------------------------------------


def assemble(chapters: Sequence, videos: Sequence, stage: Path) -> str | None:
    """Write the lecture's files into ``stage`` (which holds ``chapters/``); returns why the
    video had to be encoded again (None: remuxed)."""
    from trex import assemble as joiner

    reason = joiner.join_videos(videos, stage / VIDEO)
    starts = joiner.starts_of(videos)
    texts = []
    for video in videos:
        srt_file = video.path.with_suffix(".srt")
        texts.append(srt_file.read_text(encoding="utf-8") if srt_file.is_file() else None)
    durations = [v.duration for v in videos]
    (stage / SUBTITLES).write_text(joiner.join_subtitles(texts, starts, durations),
                                   encoding="utf-8")
    files = [f"{CHAPTER_DIR}/{v.path.name}" for v in videos]
    entries = joiner.chapter_entries(chapters, videos, files)
    (stage / LIST_JSON).write_text(joiner.chapters_json(entries), encoding="utf-8")
    (stage / LIST_MD).write_text(joiner.chapters_markdown(entries, VIDEO), encoding="utf-8")
    return reason


def move_into_place(stage: Path, out_dir: Path, trash: Path) -> None:
    """Put the staged lecture at ``out_dir``: the whole directory when there is none yet,
    else its entries one by one (an old ``chapters/`` goes to ``trash``); other files in
    ``out_dir`` stay. Call with signals held."""
    if not out_dir.exists():
        os.rename(stage, out_dir)
        return
    for name in OUTPUTS:
        target = out_dir / name
        if name == CHAPTER_DIR and target.exists():
            os.rename(target, trash / name)
        os.replace(stage / name, target)


def build_lecture(chapters: Sequence, out_dir: Path, quality: str, jobs: int,
                  polygon: str | None, signals=None,
                  echo: Callable[[str], None] = click.echo,
                  panel: str | None = None) -> tuple[Path, float]:
    """Render and join ``chapters`` into ``out_dir`` (their panels showing ``panel``; None:
    each scene's own); returns the lecture mp4 and its length in seconds. Raises :class:`ChapterFailed`, or :class:`Interrupted` on a signal (with
    ``signals`` from ``interrupts_raise``); then nothing at ``out_dir`` has changed."""
    where = out_dir.resolve()  # "." has no name and is its own parent
    temp = Path(tempfile.mkdtemp(prefix=f".{where.name}.", suffix=".lecture",
                                 dir=where.parent))
    try:
        stage, logs, trash = temp / "lecture", temp / "logs", temp / "trash"
        for folder in (stage / CHAPTER_DIR, logs, trash):
            folder.mkdir(parents=True)

        def done(k, chapter, video, seconds):
            echo(f"{chapter_label(k, len(chapters), chapter)}: {float(video.duration):.1f} s of video "
                 f"in {seconds:.1f} s")

        videos = render_chapters(chapters, stage / CHAPTER_DIR, logs, quality,
                                 max(1, min(jobs, len(chapters))), polygon, done, panel)
        for chapter, video in zip(chapters, videos, strict=True):
            if video.audio:
                click.echo(f"warning: {chapter.slug}: has sound; the lecture keeps its video only",
                           err=True)
        reason = assemble(chapters, videos, stage)
        if reason is not None:
            click.echo(f"note: the lecture was encoded again (no remux): {reason}", err=True)
        with _signals_held():
            if signals is not None:
                signals.check()
            move_into_place(stage, out_dir, trash)
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
    if polygon is not None:
        load_or_exit(polygon)  # bad input: one line, exit 2, before anything else
    run_lecture(None, Path(out_dir), quality, jobs, polygon, only, panel)


def run_lecture(chapters: Sequence | None, out_dir: Path, quality: str = "l", jobs: int = 1,
                polygon: str | None = None, only: str | None = None,
                panel: str | None = None) -> Path:
    """The command after its polygon check: ``chapters`` None = the lecture's own."""
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
    try:
        check_output_dir(out_dir)
    except ValueError as exc:
        fail(f"{out_dir}: {exc}")
    began = time.monotonic()
    with interrupts_raise() as signals:
        try:
            check_chapters(chapters, polygon)
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


def chapter_failed(message: str, status: int = EXIT_FAILED) -> NoReturn:
    """``error: MESSAGE`` and exit status 1 (a chapter, or the list of them, failed), or
    ``status``."""
    click.echo(f"error: {message}", err=True)
    raise click.exceptions.Exit(status)


# --- one chapter, in its own process ------------------------------------------------------------

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
                    polygon: str | None, panel: str | None) -> dict:
    """What a chapter's frames depend on, as its step marks record it (``made_by``):
    ``trex slides lecture`` reuses a chapter render whose settings are these."""
    from story.environment import environment_values

    return {"scene_file": str(Path(scene_file).resolve()), "class": class_name or None,
            "quality": quality, "polygon": polygon or None, "panel": panel or None,
            "environment": environment_values(), "source": source_fingerprint()}



def render_chapter(scene_file: str, class_name: str | None, output: str, quality: str,
                   polygon: str | None = None, panel: str | None = None) -> int:
    """Render one scene to ``output`` (mp4 + .srt + .steps.json, its step marks) with
    ``render_into``, handed ``polygon``
    (None or empty: what ``manim`` would give it), its panel showing ``panel`` (None or
    empty: the scene's own); the exit status.

    Failures are one line on stderr; SIGTERM/SIGINT stop it with nothing left behind. A
    function of one's own it runs has the time limit of ``TREX_CALL_TIMEOUT`` (the
    lecture's ``--call-timeout``), else the default.
    """
    try:
        seconds = call_timeout_from_environment()
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_INVALID
    if seconds is not None:
        set_call_timeout(seconds)
    with interrupts_raise() as signals:
        try:
            try:
                cls = load_scene_class(Path(scene_file), class_name or None)
                settings = render_settings(scene_file, class_name, quality, polygon, panel)
                render_into(scene_input(cls, polygon or None, panel or None), Path(output),
                            "mp4", QUALITIES[quality], progress=False, signals=signals,
                            steps=settings)
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


COMMANDS = (lecture,)
__all__ = ["COMMANDS", "build_lecture", "lecture", "render_chapter", "run_lecture"]

if __name__ == "__main__":
    sys.exit(render_chapter(*sys.argv[1:7]))
