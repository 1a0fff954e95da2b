"""A checked course expanded into tasks: what each renders, into which files, from what.

:func:`plan` checks every item as the command that renders it would (scenes load, each
polygon is read and its run computed once without drawing, as ``trex lecture`` and
``trex render`` do) and raises :class:`trex.course.schema.CourseError` for the first
problem, before anything is submitted. Then each item becomes tasks:

- a lecture: one ``chapter`` task per chapter (``lecture-K/chapters/NN-slug.mp4``, rendered
  as ``trex lecture`` renders one), plus its ``join`` (``lecture-K/lecture.mp4`` …) that
  waits for them;
- a scene: one ``scene`` task per polygon (``scene-<scene>-<polygon>.<ext>``);
- slides: one ``slides`` task (``slides-<scene>/``); those of the lecture wait for a lecture
  item of the same settings and reuse its chapters, as ``trex slides lecture`` does (with
  no such item, chapter tasks of their own first, into ``slides-lecture-chapters/``);
- exercises: one ``student`` task per student (``exercises/student-K/``), student K getting
  what ``trex exercises --n N --seed SEED+K-1`` writes, and ``video.mp4`` when asked.

Each task has a fingerprint: its settings, the bytes of its input files, the code that
renders (:func:`trex.chapter_command.source_fingerprint`) and its dependencies'
fingerprints. Importing this module imports no manim; :func:`plan` does.
"""

from __future__ import annotations

import hashlib
import json
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NotRequired, TypedDict, cast

from geometry.io import AnyPolygon
from story.scene_kinds import Handed, WithPanel, algorithm_of, plays_several
from trex.course.schema import Course, CourseError, Exercises, Lecture, SceneItem, Slides
from trex.course.schema import polygon_path as _polygon_path
from trex.inputs import READ_ERRORS, error_line

LECTURE_SCENE = "lecture"  # [[slides]] scene = "lecture": the lecture's slides
KINDS = ("chapter", "join", "scene", "slides", "student")


class ChapterRecord(TypedDict):
    """A chapter as a task's settings hold it (the fields of :class:`trex.chapters.Chapter`)."""

    number: int
    slug: str
    title: str
    scene_file: str
    scene_class: str | None


class ChapterSettings(TypedDict):
    """A ``chapter`` task: one chapter, rendered as ``trex lecture`` renders it."""

    chapter: ChapterRecord
    quality: str
    polygon: str | None
    panel: str | None


class JoinSettings(TypedDict):
    """A ``join`` task: the lecture's folder and the chapters it joins."""

    folder: str
    chapters: list[ChapterRecord]


class SceneSettings(TypedDict):
    """A ``scene`` task: one scene on one polygon, as ``trex render`` renders it."""

    scene: str
    polygon: str | None
    format: str
    quality: str
    panel: str | None


class SlidesSettings(TypedDict):
    """A ``slides`` task: ``trex slides``' page of a scene, or of the lecture (its chapters
    and the lecture's folder then)."""

    scene: str
    quality: str
    polygon: str | None
    panel: str | None
    chapters: NotRequired[list[ChapterRecord]]
    lecture: NotRequired[str]


class StudentSettings(TypedDict):
    """A ``student`` task: one student's exercise sheets, and a video if asked."""

    n: int
    seed: int
    video: bool
    quality: str


#: what a task's body reads, by the task's kind
Settings = ChapterSettings | JoinSettings | SceneSettings | SlidesSettings | StudentSettings


@dataclass(frozen=True)
class Task:
    """One unit of work: ``files`` (relative to the output directory) it writes, the
    ``settings`` its body reads, the ``deps`` (task ids) it waits for."""

    id: str
    kind: str
    item: str
    files: tuple[str, ...]
    settings: Settings = field(hash=False)
    inputs: tuple[str, ...] = ()
    deps: tuple[str, ...] = ()
    fingerprint: str = ""


def slug(text: str) -> str:
    """A name fit for a file: ``random-star:50:7`` → ``random-star-50-7``.

    >>> slug("rotation:RotationCcw"), slug("my shapes/star.json")
    ('rotation-RotationCcw', 'star')
    """
    text = Path(text).stem if text.endswith((".json", ".geojson", ".wkt", ".dat", ".py")) \
        else text
    return re.sub(r"[^A-Za-z0-9_-]+", "-", text).strip("-") or "x"


def scene_slug(scene: str) -> str:
    """``gravity``, ``rotation-RotationCcw``, ``my_scene-Mine`` (a file's stem)."""
    target, _, name = scene.partition(":")
    stem = Path(target).stem if target.endswith(".py") else target
    return slug(f"{stem}-{name}" if name else stem)


# --- checking what the items name (imports manim) ------------------------------------------------


class _Checked:
    """Runs computed once across the course (``(algorithm, heuristic, polygon)`` keys)."""

    def __init__(self) -> None:
        self.done: set = set()

    def once(self, key: Any, check: Callable[[], object]) -> None:
        if key not in self.done:
            check()
            self.done.add(key)


def _read(item: str, name: str, polygon: str, holes: bool) -> AnyPolygon:
    """The polygon ``polygon`` read (with holes, if ``holes``), once: the checks run on it."""
    from geometry.io import read_any_polygon, read_polygon

    try:
        return (read_any_polygon if holes else read_polygon)(polygon)
    except READ_ERRORS as exc:
        raise CourseError(item, name, f"{polygon}: {error_line(exc)}") from None


def _scene_file(course: Course, scene: str) -> str:
    """A scene argument with a relative file read from the course's folder."""
    target, colon, name = scene.partition(":")
    if target.endswith(".py") and not Path(target).is_absolute():
        target = str(course.folder / target)
    return f"{target}{colon}{name}"


def _scene_class(item: str, scene: str) -> type:
    from trex.render_command import load_scene_class, resolve_scene

    try:
        if ".py:" in scene:
            from metaphors.scene import scene_for_heuristic

            return scene_for_heuristic(scene)
        return load_scene_class(*resolve_scene(scene))
    except ValueError as exc:
        raise CourseError(item, "scene", error_line(exc)) from None


def _run_once(item: str, name: str, cls: type, polygon: str, checked: _Checked) -> None:
    """The scene's run on ``polygon`` computed once, as ``trex render`` runs it before
    rendering (:func:`trex.render_command.run_once`); what it rejects is the item's field
    ``name``'s fault."""
    from geometry.triangulate import HOLE_ALGORITHMS
    from trex.render_command import RUN_ERRORS, run_once, scene_run

    algorithm = algorithm_of(cls)
    spec = scene_run(cls, polygon, _read(item, name, polygon, algorithm in HOLE_ALGORITHMS))
    if spec is None:
        return
    try:
        checked.once(("run", algorithm, spec.heuristic, polygon), lambda: run_once(spec))
    except RUN_ERRORS as exc:
        raise CourseError(item, name, f"{polygon}: {error_line(exc)}") from None


def _chapters(course: Course, item: str, only: tuple[str, ...] | None) -> list:
    from trex import chapters as ch

    try:
        chapters = list(ch.lecture_chapters())
        if only is not None:
            chapters = ch.pick_chapters(",".join(_scene_file(course, c) for c in only),
                                        chapters)
    except Exception as exc:  # a scene that does not load, an unknown name
        raise CourseError(item, "chapters", error_line(exc)) from None
    stems = [ch.chapter_stem(c) for c in chapters]
    if len(set(stems)) != len(stems):
        raise CourseError(item, "chapters", f"chapters repeat: {', '.join(stems)}")
    return chapters


def _check_chapters(item: str, chapters: list, polygon: str | None, checked: _Checked) -> None:
    """What ``trex lecture`` checks (:func:`trex.chapters.check_chapters`), each
    problem named by the item."""
    from trex import chapters as ch
    from trex import render_command as rc

    for k, chapter in enumerate(chapters):
        label = ch.chapter_label(k, len(chapters), chapter)
        try:
            cls = rc.load_scene_class(ch.scene_path(chapter), chapter.scene_class or None)
        except ValueError as exc:
            raise CourseError(item, "chapters", f"{label}: {error_line(exc)}") from None
        if polygon is None:
            continue
        segments = ch.lecture_segments(cls)
        if segments is None:
            if not plays_several(cls):
                _run_once(item, "polygon", cls, polygon, checked)
            continue
        polygon_read = _read(item, "polygon", polygon, False)
        for what, key, check in ch.polygon_checks(segments, polygon, polygon_read):
            try:
                checked.once((key, polygon), check)
            except rc.RUN_ERRORS as exc:
                raise CourseError(item, "polygon",
                                  f"{polygon}: {label}: {what}: {error_line(exc)}") from None


# --- the tasks of each item ------------------------------------------------------------------------


def _chapter_tasks(folder: str, item: str, chapters: list, quality: str, polygon: str | None,
                   panel: str | None) -> list[Task]:
    from trex import chapters as ch
    from trex import lecture_join as lj

    tasks = []
    for chapter in chapters:
        stem = f"{folder}/{lj.CHAPTER_DIR}/{ch.chapter_stem(chapter)}"
        settings: ChapterSettings = {"chapter": _chapter_dict(chapter), "quality": quality,
                                     "polygon": polygon, "panel": panel}
        tasks.append(Task(stem, "chapter", item, (f"{stem}.mp4",), settings, _inputs(polygon)))
    return tasks


def _chapter_of(task: Task) -> ChapterRecord:
    """The chapter a ``chapter`` task renders."""
    return cast(ChapterSettings, task.settings)["chapter"]  # a chapter task's, by its kind


def _chapter_dict(chapter) -> ChapterRecord:
    from trex import chapters as ch

    return {"number": chapter.number, "slug": chapter.slug, "title": chapter.title,
            "scene_file": str(ch.scene_path(chapter)), "scene_class": chapter.scene_class}


def _lecture(course: Course, item: Lecture, checked: _Checked) -> list[Task]:
    from trex import lecture_join as lj

    polygon = _polygon(course, item.polygon)
    chapters = _chapters(course, item.name, item.chapters)
    _check_chapters(item.name, chapters, polygon, checked)
    folder = f"lecture-{item.number}"
    parts = _chapter_tasks(folder, item.name, chapters, item.quality, polygon, item.panel)
    files = tuple(f"{folder}/{name}" for name in (lj.VIDEO, lj.SUBTITLES, lj.LIST_JSON,
                                                   lj.LIST_MD, lj.NOTES))
    join = Task(folder, "join", item.name, files,
                JoinSettings(folder=folder, chapters=[_chapter_of(t) for t in parts]),
                deps=tuple(t.id for t in parts))
    return [*parts, join]


def _scene(course: Course, item: SceneItem, checked: _Checked) -> list[Task]:
    scene = _scene_file(course, item.scene)
    cls = _scene_class(item.name, scene)
    if plays_several(cls) and item.polygons != (None,):
        raise CourseError(item.name, "polygons", f"{item.scene} plays its own polygons; "
                                                 "give none")
    if item.panel is not None and not isinstance(cls, WithPanel):
        raise CourseError(item.name, "panel", f"{item.scene} has no panel")
    tasks = []
    for k, given in enumerate(item.polygons):
        polygon = _polygon(course, given)
        if polygon is not None:
            _run_once(item.name, f"polygons[{k}]", cls, polygon, checked)
        name = f"scene-{scene_slug(item.scene)}{_polygon_part(cls, given)}"
        settings: SceneSettings = {"scene": scene, "polygon": polygon, "format": item.format,
                                   "quality": item.quality, "panel": item.panel}
        tasks.append(Task(name, "scene", item.name, (f"{name}.{item.format}",), settings,
                          _inputs(polygon, scene)))
    return tasks


def _polygon_part(cls: type, given: str | None) -> str:
    """``-star`` for a polygon given, else the scene's own (``-counterexample``); nothing
    for a scene of several runs, or of none."""
    own = cls.polygon if isinstance(cls, Handed) else None
    if given is None and (plays_several(cls) or not isinstance(own, str)):
        return ""
    return f"-{slug(cast(str, given if given is not None else own))}"  # own is a str here


def _slides(course: Course, item: Slides, checked: _Checked,
            lectures: dict[tuple, list[Task]]) -> list[Task]:
    polygon = _polygon(course, item.polygon)
    name = f"slides-{scene_slug(item.scene)}"
    settings: SlidesSettings = {"scene": item.scene, "quality": item.quality,
                                "polygon": polygon, "panel": item.panel}
    if item.scene == LECTURE_SCENE:
        chapters = _chapters(course, item.name, item.chapters)
        _check_chapters(item.name, chapters, polygon, checked)
        parts = lectures.get((item.quality, polygon, item.panel, item.chapters), [])
        own = [] if parts else _chapter_tasks(f"{name}-chapters", item.name, chapters,
                                              item.quality, polygon, item.panel)
        settings["chapters"] = [_chapter_dict(c) for c in chapters]
        settings["lecture"] = (parts or own)[0].id.rpartition("/chapters/")[0]
        return [*own, Task(name, "slides", item.name, (f"{name}/index.html",), settings,
                           _inputs(polygon), tuple(t.id for t in parts or own))]
    scene = _scene_file(course, item.scene)
    settings["scene"] = scene
    from trex.scene_inputs import load_scene

    try:
        cls = load_scene(scene, "slides", several_runs=True)
    except ValueError as exc:
        raise CourseError(item.name, "scene", error_line(exc)) from None
    if polygon is not None and not plays_several(cls):
        _run_once(item.name, "polygon", cls, polygon, checked)
    return [Task(name, "slides", item.name, (f"{name}/index.html",), settings,
                 _inputs(polygon, scene))]


def _students(item: Exercises, first: bool) -> list[Task]:
    folder = "exercises" if first else f"exercises-{item.number}"
    tasks = []
    for k in range(1, item.students + 1):
        name = f"{folder}/student-{k}"
        settings: StudentSettings = {"n": item.n, "seed": item.seed + k - 1,
                                     "video": item.video, "quality": item.quality}
        files = (f"{name}/answers.md", *((f"{name}/video.mp4",) if item.video else ()))
        tasks.append(Task(name, "student", item.name, files, settings))
    return tasks


def _polygon(course: Course, polygon: str | None) -> str | None:
    return None if polygon is None else _polygon_path(course, polygon)


def _inputs(*given: str | None) -> tuple[str, ...]:
    """The files among ``given`` (polygons, scene files) whose bytes a task depends on."""
    files = []
    for value in given:
        if value is None:
            continue
        path = Path(value.partition(".py:")[0] + ".py" if ".py:" in value else value)
        if path.is_file():
            files.append(str(path.resolve()))
    return tuple(files)


# --- the plan -------------------------------------------------------------------------------------


def plan(course: Course, code: str) -> list[Task]:
    """Every task of ``course``, checked, in an order where each follows its dependencies,
    fingerprinted with ``code`` (the renderers' fingerprint). Raises CourseError."""
    checked = _Checked()
    tasks: list[Task] = []
    lectures: dict[tuple, list[Task]] = {}
    for item in course.lectures:
        mine = _lecture(course, item, checked)
        key = (item.quality, _polygon(course, item.polygon), item.panel, item.chapters)
        lectures.setdefault(key, [t for t in mine if t.kind == "chapter"])
        tasks += mine
    for scene in course.scenes:
        tasks += _scene(course, scene, checked)
    for slides in course.slides:
        tasks += _slides(course, slides, checked, lectures)
    for k, exercises in enumerate(course.exercises):
        tasks += _students(exercises, k == 0)
    _refuse_clashes(tasks)
    return fingerprinted(tasks, code)


def _refuse_clashes(tasks: Iterable[Task]) -> None:
    """Two items writing the same file would overwrite each other: refused."""
    owner: dict[str, Task] = {}
    for task in tasks:
        for name in task.files:
            other = owner.setdefault(name, task)
            if other is not task:
                raise CourseError(task.item, None, f"writes {name}, as {other.item} does")


def fingerprinted(tasks: list[Task], code: str) -> list[Task]:
    """The tasks with their fingerprints (dependencies come first in ``tasks``)."""
    done: dict[str, str] = {}
    result = []
    for task in tasks:
        digest = hashlib.sha256()
        record = {"kind": task.kind, "settings": task.settings, "files": task.files,
                  "deps": [done[d] for d in task.deps], "code": code}
        digest.update(json.dumps(record, sort_keys=True).encode())
        for path in task.inputs:
            digest.update(b"\0" + path.encode() + b"\0" + Path(path).read_bytes())
        done[task.id] = digest.hexdigest()
        result.append(Task(task.id, task.kind, task.item, task.files, task.settings,
                           task.inputs, task.deps, done[task.id]))
    return result
