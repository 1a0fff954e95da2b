"""What ``trex`` asks of a scene class, as protocols: checked with ``isinstance``, never by
probing for an attribute's name.

A scene class is one of this project's (:class:`metaphors.scene.TraceScene` and its kin) or
any manim ``Scene`` a user writes. The commands hand the first kind its run as data and
choose its panel; they play the second as it is. Each capability is a
:func:`typing.runtime_checkable` protocol, met by the class object itself (its classmethods
and class attributes), so ``isinstance(cls, Handed)`` says whether ``cls.handed(…)`` may be
called. No manim here: the protocols say what is asked, the scenes say how.

>>> class Plain:  # a user's own Scene: nothing to hand it
...     pass
>>> isinstance(Plain, Handed), plays_several(Plain), algorithm_of(Plain)
(False, False, None)
>>> class OneRun:
...     algorithm, polygon, heuristic, spec = "scaling", "star", None, None
...     @classmethod
...     def default_spec(cls): ...
...     @classmethod
...     def with_spec(cls, spec): ...
...     @classmethod
...     def handed(cls, polygon=None, saved=()): ...
...     @classmethod
...     def from_environment(cls): ...
>>> isinstance(OneRun, Handed), plays_several(OneRun), algorithm_of(OneRun)
(True, False, 'scaling')
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Protocol, runtime_checkable

from story.spec import RunSpec


@runtime_checkable
class OfAlgorithm(Protocol):
    """A scene that plays runs of one algorithm (a heuristic, ``divide-and-conquer``, a
    heuristic of one's own's ``FILE.py:NAME``), with divide and conquer's ``heuristic``."""

    algorithm: str
    heuristic: str | None


@runtime_checkable
class Handed(OfAlgorithm, Protocol):
    """A scene handed its run as data: a subclass carrying a :class:`~story.spec.RunSpec`
    (``spec``), made from its default run (``polygon``), a polygon, a saved log, or what the
    environment says (``TREX_POLYGON``, ``TREX_LOG``: plain ``manim``)."""

    polygon: str
    spec: RunSpec | None

    def default_spec(self) -> RunSpec: ...

    def with_spec(self, spec: RunSpec) -> type: ...

    def handed(self, polygon: str | None = None, saved: Sequence[str] = ()) -> type: ...

    def from_environment(self) -> type: ...


@runtime_checkable
class SeveralRuns(Handed, Protocol):
    """A scene that plays several runs, each on its own polygon (``runs``: algorithm,
    polygon, title), handed one spec per run."""

    runs: tuple[tuple[str, str, str], ...]

    def with_specs(self, specs: Sequence[RunSpec]) -> type: ...


@runtime_checkable
class WithPanel(Protocol):
    """A scene with a panel beside the picture; ``with_panel(p)`` shows ``p`` there (one of
    :data:`story.pseudocode.PANELS`)."""

    panel: str

    def with_panel(self, panel: str) -> type: ...


@runtime_checkable
class WithHeuristic(Protocol):
    """A scene whose run takes a heuristic (divide and conquer): ``with_heuristic(name)``."""

    def with_heuristic(self, heuristic: str) -> type: ...


@runtime_checkable
class ChapterScene(Protocol):
    """A chapter of the lecture: its ``chapter_title`` (``"3. Gravity"``) and its ``slug``
    (``"gravity"``: what ``--chapters`` names it by, and its files' names, ``03-gravity.mp4``;
    ``""``: none, a scene played as a chapter is named by its file)."""

    chapter_title: str
    slug: str


@runtime_checkable
class TaughtChapter(Protocol):
    """A lecture chapter with notes for its teacher: ``teacher_notes``, each with a
    ``title`` and ``lines`` (never played)."""

    chapter_title: str
    teacher_notes: tuple[Any, ...]


def plays_several(cls: object) -> bool:
    """Whether ``cls`` plays several runs (it names their polygons: a given one is not
    played)."""
    return isinstance(cls, SeveralRuns) and bool(cls.runs)


def plays_one(cls: object) -> bool:
    """Whether ``cls`` is handed one run (on a polygon it may be given)."""
    return isinstance(cls, Handed) and not plays_several(cls)


def algorithm_of(cls: object) -> str | None:
    """The algorithm ``cls`` plays (None: a scene that plays none)."""
    if isinstance(cls, OfAlgorithm) and isinstance(cls.algorithm, str):
        return cls.algorithm
    return None


def heuristic_of(cls: object) -> str | None:
    """Divide and conquer's heuristic ``cls`` plays (None: none, or not such a scene)."""
    return cls.heuristic if isinstance(cls, OfAlgorithm) else None
