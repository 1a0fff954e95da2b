"""The lecture's chapters: found, picked, named, and checked before anything renders
(``trex lecture``, ``trex slides lecture``).

The chapters are the scene files ``scenes/chapters/ch<k>_<slug>.py``, each named by its
class's ``slug`` (``--chapters`` picks some of them by slug, or names scenes to play as
chapters instead).

With ``--polygon``, a lecture chapter is checked by what it plays: each of its segments that
runs on the lecture's polygon (a ``Run`` or ``Compare`` whose polygon is None) is computed
once on it, as :class:`metaphors.lecture.LectureScene` would, without drawing
(:func:`polygon_checks`); a scene played as a chapter runs its ``algorithm`` once
(:func:`trex.render_command.run_once`). The polygon is read once, by the command. A polygon a
chapter rejects is bad input (one line, status 2); a chapter that does not load is
:class:`ChapterFailed` (status 1, :func:`chapter_failed`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, NoReturn

import click

from geometry.io import AnyPolygon
from story.scene_kinds import ChapterScene, TaughtChapter
from trex.inputs import error_line, fail
from trex.render_command import (
    EXIT_FAILED,
    RUN_ERRORS,
    SCENES_DIR,
    load_scene_class,
    resolve_scene,
    run_once,
    scene_run,
)

__all__ = ["CHAPTERS_DIR", "REPO", "Chapter", "ChapterFailed", "chapter_failed",
           "chapter_label", "chapter_stem", "check_chapters", "lecture_chapters",
           "lecture_segments", "pick_chapters", "polygon_checks", "scene_path", "teacher_notes",
           "teacher_notes_markdown"]

REPO = SCENES_DIR.parent
CHAPTERS_DIR = SCENES_DIR / "chapters"


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


def chapter_failed(message: str, status: int = EXIT_FAILED) -> NoReturn:
    """``error: MESSAGE`` and exit status 1 (a chapter, or the list of them, failed), or
    ``status``."""
    click.echo(f"error: {message}", err=True)
    raise click.exceptions.Exit(status)


def lecture_chapters() -> tuple[Chapter, ...]:
    """The lecture's chapters: the scene files ``scenes/chapters/ch<k>_<slug>.py``, in the
    order of ``k``, each named by its class's ``slug`` and titled by its ``chapter_title``
    (``"3. Gravity"``: the part after the number). Loading them imports manim, so only when
    asked for. Raises ValueError for a chapter's class that is no chapter, or whose slug is
    not the one its file's name says (the class is the source; the name follows it)."""
    found = []
    for path in CHAPTERS_DIR.glob("ch*_*.py"):
        digits, _, named = path.stem[2:].partition("_")
        if digits.isdigit():
            found.append((int(digits), named.replace("_", "-"), path))
    chapters = []
    for number, named, path in sorted(found):
        cls = load_scene_class(path, None)
        if not (isinstance(cls, ChapterScene) and cls.slug):
            raise ValueError(f"{path.name}: {cls.__name__} is no chapter: it needs a "
                             "chapter_title and a slug")
        if cls.slug != named:
            raise ValueError(f"{path.name}: {cls.__name__}'s slug is '{cls.slug}'; name the "
                             f"file ch{number}_{cls.slug.replace('-', '_')}.py")
        title = cls.chapter_title.partition(". ")
        chapters.append(Chapter(number, cls.slug, title[2] or title[0],
                                str(path.relative_to(REPO)), cls.__name__))
    return tuple(chapters)


def pick_chapters(spec: str, chapters: Sequence[Chapter] | None) -> list[Chapter]:
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


def scene_path(chapter: Chapter) -> Path:
    """A chapter's scene file (relative paths are from the repository root)."""
    path = Path(chapter.scene_file)
    return path if path.is_absolute() else REPO / path


def chapter_stem(chapter: Chapter) -> str:
    """``01-overview``: the chapter's files in ``chapters/``.

    >>> chapter_stem(Chapter(3, "gravity", "Gravity", "scenes/gravity.py", None))
    '03-gravity'
    """
    return f"{chapter.number:02d}-{chapter.slug}"


def chapter_label(k: int, n: int, chapter: Chapter) -> str:
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


def polygon_checks(segments: Sequence, polygon: str, polygon_read: AnyPolygon | None = None,
                   ) -> list[tuple[str, tuple, Callable[[], object]]]:
    """``(what, key, check)`` for each segment that plays the lecture's polygon: ``check()``
    computes what the chapter would show — a Run's log, a Compare's two triangulations — by
    the chapter's own calls, on ``polygon`` (the one the chapter is handed; ``polygon_read``: it
    read already, which a Run then does not read again). Equal keys are the same
    computation."""
    from geometry.cdt import constrained_delaunay
    from geometry.triangulate import triangulate
    from metaphors import lecture
    from metaphors.lecture import Compare, Run

    def run(segment: Run):
        return replace(segment.spec(polygon), polygon_read=polygon_read).log()

    def compare(segment: Compare):
        polygon_read = lecture.read_polygon(polygon)
        return triangulate(polygon_read, segment.ours), constrained_delaunay(polygon_read)

    checks: list[tuple[str, tuple[Any, ...], Callable[..., object]]] = []  # (called with none)
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


def check_chapters(chapters: Sequence[Chapter], polygon: str | None,
                   polygon_read: AnyPolygon | None = None) -> None:
    """Load every chapter's scene class and, with a polygon (``polygon_read``: it read already by
    the command), compute on it what the chapter plays on it (:func:`polygon_checks`; a
    scene that is not a lecture chapter: its ``algorithm``, once), drawing nothing.

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
            _check_polygon(cls, (polygon, polygon_read), chapter_label(k, len(chapters), chapter),
                           done)


def _check_polygon(cls: type, given: tuple[str, AnyPolygon | None], label: str, done: set) -> None:
    """One chapter's part of :func:`check_chapters` (``given``: the polygon, and it read);
    ``done`` holds the keys already run."""
    polygon, polygon_read = given
    try:
        segments = lecture_segments(cls)
    except Exception as exc:  # the chapter's own list is broken: it would not render either
        raise ChapterFailed(f"{label}: cannot list its segments: {type(exc).__name__}: "
                            f"{error_line(exc)}") from None
    if segments is None:  # a scene played as a chapter (none, if it plays its own polygons)
        spec = scene_run(cls, polygon, polygon_read)
        try:
            if spec is not None:
                run_once(spec)
        except RUN_ERRORS as exc:
            fail(f"{polygon}: {error_line(exc)}")
        return
    for what, key, check in polygon_checks(segments, polygon, polygon_read):
        if key in done:
            continue
        try:
            check()
        except RUN_ERRORS as exc:
            fail(f"{polygon}: {label}: {what}: {error_line(exc)}")
        done.add(key)


def teacher_notes(chapter: Chapter) -> tuple:
    """The chapter's notes for its teacher (cards: ``title``, ``lines``); none for a scene
    played as a chapter."""
    cls = load_scene_class(REPO / chapter.scene_file, chapter.scene_class)
    return tuple(cls.teacher_notes) if isinstance(cls, TaughtChapter) else ()


def teacher_notes_markdown(chapters: Sequence[Chapter]) -> str:
    """``teacher-notes.md``: per chapter that has them, its notes (Forišek–Steinová's
    experience of teaching it), which the students' video leaves out.

    >>> print(teacher_notes_markdown([c for c in lecture_chapters() if c.slug == "heuristics"])
    ...       .splitlines()[0])
    # Teacher notes
    """
    parts = []
    for chapter in chapters:
        notes = teacher_notes(chapter)
        if notes:
            parts.append(f"## {chapter.number}. {chapter.title}\n")
            for note in notes:
                parts.append(f"### {note.title}\n")
                parts.extend(f"- {line}" for line in note.lines)
                parts.append("")
    if not parts:
        parts = ["No chapter of this lecture has notes."]
    return "# Teacher notes\n\nFor whoever teaches the lecture; the video leaves them out.\n\n" \
        + "\n".join(parts).rstrip() + "\n"
