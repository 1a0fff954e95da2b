"""The course file: TOML read with :mod:`tomllib` into typed items, every field checked.

No manim here and nothing rendered: a bad file is refused before anything is submitted.
Each problem is a :class:`CourseError` naming the item (``scene 2``, the second
``[[scene]]``) and the field, which ``trex course`` prints as one line with exit status 2.
Relative paths (polygon files, scene files) are read from the course file's folder; a
polygon that is no file there is a sample name (``counterexample``, ``random-star:50:7``).

>>> course = parse_course('''
... [course]
... title = "Autumn"
... [[scene]]
... scene = "gravity"
... polygons = ["counterexample"]
... ''', Path("."))
>>> course.title, course.quality, course.scenes[0].polygons
('Autumn', 'l', ('counterexample',))
>>> parse_course('[[scene]]\\nscene = "gravity"\\nformat = "avi"', Path("."))
Traceback (most recent call last):
...
trex.course.schema.CourseError: scene 1, field format: 'avi' is not one of mp4, gif, png
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, cast, overload

from story.pseudocode import PANELS

QUALITY_KEYS = ("l", "m", "h", "k")  # as trex render -q
FORMATS = ("mp4", "gif", "png")
MAX_STUDENTS = 10_000
MAX_EXERCISES = 99  # as trex exercises --n


class CourseError(ValueError):
    """A course file that cannot be run; the message names the item and the field."""

    def __init__(self, item: str, field: str | None, problem: str) -> None:
        where = item if field is None else f"{item}, field {field}"
        super().__init__(f"{where}: {problem}")
        self.item, self.field = item, field


@dataclass(frozen=True)
class Lecture:
    """A ``[[lecture]]``: its chapters (None: all) on ``polygon`` (None: each its own)."""

    number: int
    quality: str
    polygon: str | None
    panel: str | None
    chapters: tuple[str, ...] | None

    @property
    def name(self) -> str:
        return f"lecture {self.number}"


@dataclass(frozen=True)
class SceneItem:
    """A ``[[scene]]``: one render per polygon (None: the scene's own)."""

    number: int
    scene: str
    polygons: tuple[str | None, ...]
    format: str
    quality: str
    panel: str | None

    @property
    def name(self) -> str:
        return f"scene {self.number}"


@dataclass(frozen=True)
class Slides:
    """A ``[[slides]]``: the presenter's page of a scene, or of the lecture."""

    number: int
    scene: str
    quality: str
    polygon: str | None
    panel: str | None
    chapters: tuple[str, ...] | None = None  # the lecture's slides only (None: all)

    @property
    def name(self) -> str:
        return f"slides {self.number}"


@dataclass(frozen=True)
class Exercises:
    """An ``[[exercises]]``: ``n`` exercises for each of ``students``, student k seeded from
    ``seed`` and k; a video of each student's first polygon when ``video``."""

    number: int
    students: int
    seed: int
    n: int
    video: bool
    quality: str

    @property
    def name(self) -> str:
        return f"exercises {self.number}"


@dataclass(frozen=True)
class Course:
    """A checked course file (``folder``: where its relative paths start)."""

    title: str
    quality: str
    folder: Path
    lectures: tuple[Lecture, ...] = ()
    scenes: tuple[SceneItem, ...] = ()
    slides: tuple[Slides, ...] = ()
    exercises: tuple[Exercises, ...] = ()

    @property
    def items(self) -> tuple:
        return (*self.lectures, *self.scenes, *self.slides, *self.exercises)


# --- reading fields ---------------------------------------------------------------------------------


class _Fields:
    """One table's fields, each taken once and checked; :meth:`done` refuses the rest."""

    def __init__(self, item: str, table: Any, allowed: tuple[str, ...]) -> None:
        if not isinstance(table, dict):
            raise CourseError(item, None, "must be a table")
        self.item, self.table, self.allowed = item, table, allowed
        for key in table:
            if key not in allowed:
                raise CourseError(item, key, f"unknown field; known: {', '.join(allowed)}")

    def get(self, key: str, kind: type | tuple[type, ...], default: Any = None) -> Any:
        value = self.table.get(key, default)
        if value is None or value is default:
            return value
        # a bool is an int in Python, not in a course file
        if not isinstance(value, kind) or (isinstance(value, bool) and kind is int):
            wanted = kind.__name__ if isinstance(kind, type) else "/".join(k.__name__ for k in kind)
            raise CourseError(self.item, key, f"must be {_WORDS.get(wanted, wanted)}, "
                                              f"not {_shown(value)}")
        return value

    @overload
    def text(self, key: str, default: str) -> str: ...
    @overload
    def text(self, key: str, default: None = None) -> str | None: ...

    def text(self, key: str, default: str | None = None) -> str | None:
        value = self.get(key, str, default)
        if value is not None and not value.strip():
            raise CourseError(self.item, key, "is empty")
        return value

    @overload
    def choice(self, key: str, choices: tuple[str, ...], default: str) -> str: ...
    @overload
    def choice(self, key: str, choices: tuple[str, ...], default: None) -> str | None: ...

    def choice(self, key: str, choices: tuple[str, ...], default: str | None) -> str | None:
        value = self.text(key, default)
        if value is not None and value not in choices:
            raise CourseError(self.item, key, f"{value!r} is not one of {', '.join(choices)}")
        return value

    def texts(self, key: str) -> tuple[str, ...] | None:
        values = self.get(key, list)
        if values is None:
            return None
        if not values:
            raise CourseError(self.item, key, "is an empty list")
        for k, value in enumerate(values):
            if not isinstance(value, str) or not value.strip():
                raise CourseError(self.item, f"{key}[{k}]", f"must be a name, not {_shown(value)}")
        return tuple(values)

    def whole(self, key: str, default: int, low: int, high: int) -> int:
        value = self.get(key, int, default)
        if not low <= value <= high:
            raise CourseError(self.item, key, f"must be from {low} to {high}, not {value}")
        return value

    def required(self, key: str) -> None:
        if key not in self.table:
            raise CourseError(self.item, key, "is missing")


_WORDS = {"str": "text", "int": "a whole number", "list": "a list", "bool": "true or false"}


def _shown(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


# --- the items ----------------------------------------------------------------------------------------


def _lecture(number: int, table: Any, quality: str) -> Lecture:
    f = _Fields(f"lecture {number}", table, ("quality", "polygon", "panel", "chapters"))
    return Lecture(number, f.choice("quality", QUALITY_KEYS, quality), f.text("polygon"),
                   f.choice("panel", PANELS, None), f.texts("chapters"))


def _scene(number: int, table: Any, quality: str) -> SceneItem:
    f = _Fields(f"scene {number}", table, ("scene", "polygons", "format", "quality", "panel"))
    f.required("scene")  # so f.text("scene") is a str
    polygons: tuple[str | None, ...] = f.texts("polygons") or (None,)
    return SceneItem(number, cast(str, f.text("scene")), polygons, f.choice("format", FORMATS, "mp4"),
                     f.choice("quality", QUALITY_KEYS, quality), f.choice("panel", PANELS, None))


def _slides(number: int, table: Any, quality: str) -> Slides:
    f = _Fields(f"slides {number}", table, ("scene", "quality", "polygon", "panel", "chapters"))
    f.required("scene")  # so f.text("scene") is a str
    slides = Slides(number, cast(str, f.text("scene")), f.choice("quality", QUALITY_KEYS, quality),
                    f.text("polygon"), f.choice("panel", PANELS, None), f.texts("chapters"))
    if slides.chapters is not None and slides.scene != "lecture":
        raise CourseError(slides.name, "chapters", "only for the lecture's slides "
                                                   '(scene = "lecture")')
    return slides


def _exercises(number: int, table: Any, quality: str) -> Exercises:
    f = _Fields(f"exercises {number}", table, ("students", "seed", "n", "video", "quality"))
    f.required("students")
    return Exercises(number, f.whole("students", 1, 1, MAX_STUDENTS), f.get("seed", int, 0),
                     f.whole("n", 6, 1, MAX_EXERCISES), f.get("video", bool, False),
                     f.choice("quality", QUALITY_KEYS, quality))


KINDS = {"lecture": _lecture, "scene": _scene, "slides": _slides, "exercises": _exercises}


def parse_course(text: str, folder: Path) -> Course:
    """The course in TOML ``text`` whose relative paths start at ``folder``; raises
    :class:`CourseError` for the first problem (names only: whether a scene or polygon
    exists is :mod:`trex.course.tasks`' check)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CourseError("the file", None, f"not TOML: {exc}") from None
    head = _Fields("[course]", data.get("course", {}), ("title", "quality"))
    title = head.text("title", "Course")
    quality = head.choice("quality", QUALITY_KEYS, "l")
    items: dict[str, list] = {kind: [] for kind in KINDS}
    for kind, tables in data.items():
        if kind == "course":
            continue
        if kind not in KINDS:
            raise CourseError(f"[{kind}]", None,
                              f"unknown kind; known: course, {', '.join(KINDS)}")
        if not isinstance(tables, list):
            raise CourseError(f"[{kind}]", None, f"write it [[{kind}]] (one table per item)")
        for number, table in enumerate(tables, 1):
            items[kind].append(KINDS[kind](number, table, quality))
    course = Course(title, quality, folder, tuple(items["lecture"]), tuple(items["scene"]),
                    tuple(items["slides"]), tuple(items["exercises"]))
    if not course.items:
        raise CourseError("the file", None, "has no items: add a [[lecture]], [[scene]], "
                                            "[[slides]] or [[exercises]]")
    return course


def read_course(path: Path) -> Course:
    """The course file at ``path``; raises :class:`CourseError` (also when unreadable)."""
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        problem = exc.strerror if isinstance(exc, OSError) and exc.strerror else str(exc)
        raise CourseError("the file", None, f"cannot read: {problem}") from None
    return parse_course(text, path.resolve().parent)


def polygon_path(course: Course, polygon: str) -> str:
    """A course's polygon as trex reads it: a file beside the course file (absolute), else
    the name as given (a sample, or a file that is missing: reported when read)."""
    beside = course.folder / polygon
    return str(beside) if beside.exists() else polygon
