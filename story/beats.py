"""Beats: what each moment of a video shows, as typed plain data.

A beat has what every moment has — its caption, the seq of the log event it comes from, the call
line, the line of the shown code lit and the row of the pseudocode lit, the roles of the
objects (called, argument, result, rejected, idle) and its pace — and the fields of its own
kind: a water beat the states of the growing disk, a verdict whether the claim holds and the
edge it crosses. Each kind is a frozen dataclass; ``action`` names the kind (the player, the
snapshots and a scene's paces read it). This module has the kinds every run shares (the
heuristics' frame, the claim and its verdict, notes, and the generic beats of a heuristic of
one's own); a metaphor module declares its own kinds beside the performers that play them.

>>> beat = Pick(caption="B is the left-most vertex", seq=3, vertex="B")
>>> beat.action, beat.to_dict()["data"]
('pick', {'vertex': 'B'})
>>> from dataclasses import replace
>>> replace(beat, pace=0.5).pace
0.5
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, fields
from types import MappingProxyType
from typing import Any, ClassVar, TypeVar, dataclass_transform

from tracing import JSON

#: a point in polygon coordinates, as the log holds it
Point = tuple[float, float]


def point(p: Sequence[float]) -> Point:
    """``p`` (a log's list) as a record's point, its numbers unchanged."""
    x, y = p
    return (x, y)


def points_of(ps: Iterable[Sequence[float]]) -> tuple[Point, ...]:
    """A log's list of points as a record's."""
    return tuple(point(p) for p in ps)


def segment(ps: Sequence[Sequence[float]]) -> tuple[Point, Point]:
    """A log's two end points (a diagonal's, an edge's) as a record's."""
    a, b = ps
    return point(a), point(b)


@dataclass(frozen=True, kw_only=True)
class Hole:
    """A hole of the polygon: its ring's ``points`` (clockwise) and ``labels``."""

    points: tuple[Point, ...]
    labels: tuple[str, ...]

    @classmethod
    def of(cls, hole: dict[str, Any]) -> Hole:
        """The hole as the log holds it (``{"points": …, "labels": …}``)."""
        return cls(points=points_of(hole["points"]), labels=tuple(hole["labels"]))


_NO_ROLES: Mapping[str, str] = MappingProxyType({})

#: the fields every beat has; the others are its kind's ``data``
COMMON = ("caption", "seq", "call", "line", "row", "roles", "pace", "within")


@dataclass(frozen=True, kw_only=True)
class Beat:
    """What every moment has. Subclasses add the fields of their kind."""

    action: ClassVar[str] = "note"
    caption: str
    seq: int
    call: str | None = None
    line: int | None = None
    #: the index of the pseudocode row lit (:func:`story.pseudocode.lit_row`); None: none yet
    row: int | None = None
    #: label or key → role; read-only (a copy of what the beat was made with)
    roles: Mapping[str, str] = field(default_factory=lambda: _NO_ROLES)
    pace: float = 1.0
    #: the labels of the part of P the running heuristic works on when it is not all of P
    #: (divide and conquer's piece; the panel tints it); empty: all of P, or no heuristic
    within: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if not isinstance(self.roles, MappingProxyType):  # a frozen beat's roles stay as made
            object.__setattr__(self, "roles", MappingProxyType(dict(self.roles)))

    @property
    def data(self) -> dict[str, Any]:
        """The fields of this kind of beat, by name."""
        return {f.name: getattr(self, f.name) for f in fields(self) if f.name not in COMMON}

    def to_dict(self) -> dict[str, Any]:
        return {"action": self.action, "caption": self.caption, "seq": self.seq,
                "call": self.call, "line": self.line, "row": self.row, "roles": dict(self.roles),
                "data": self.data, "pace": self.pace, "within": list(self.within)}


B = TypeVar("B", bound=Beat)


@dataclass_transform(frozen_default=True, kw_only_default=True)
def beat_kind(action: str) -> Callable[[type[B]], type[B]]:
    """Declare a kind of beat: a frozen, keyword-only dataclass named ``action``."""

    def declare(cls: type[B]) -> type[B]:
        cls.action = action
        return dataclass(frozen=True, kw_only=True)(cls)

    return declare


# --- the frame every run shares --------------------------------------------------------------


@beat_kind("polygon")
class ShowPolygon(Beat):
    """The polygon appears: its points and labels (the outer ring's), and its holes (none
    for a simple polygon)."""

    points: tuple[Point, ...]
    labels: tuple[str, ...]
    holes: tuple[Hole, ...] = ()


@beat_kind("pick")
class Pick(Beat):
    """A vertex is picked (the left-most one, a reflex one …)."""

    vertex: str


@beat_kind("triangle")
class ShowTriangle(Beat):
    """T = ABC, the triangle of the heuristics' frame."""

    points: tuple[Point, ...]
    labels: tuple[str, ...]


@beat_kind("candidates")
class Candidates(Beat):
    """The vertices inside T."""

    candidates: tuple[str, ...]


@beat_kind("claim")
class Claim(Beat):
    """A heuristic claims the diagonal between two labels."""

    labels: tuple[str, str]
    points: tuple[Point, Point]


@beat_kind("verdict")
class Verdict(Beat):
    """The claim judged exactly: ``ok``, or why not — the crossed ``edge`` and ``point``."""

    ok: bool
    labels: tuple[str, str]
    why: str
    code: str
    point: Point | None = None
    edge: tuple[str, str] | None = None


@beat_kind("find")
class FindDiagonal(Beat):
    """Divide and conquer asks for an inner diagonal of the polygon ``piece`` (a key of
    the log), the heuristic that answers a black box: the overview poses the problem
    before any heuristic is taught, so none of its own steps is shown."""

    piece: str


@beat_kind("note")
class Note(Beat):
    """A caption only; ``details`` are the note's own fields from the log, if any."""

    details: Mapping[str, JSON] = field(default_factory=dict)


# --- a heuristic of one's own -------------------------------------------------------------------


@beat_kind("call")
class Call(Beat):
    """A traced function of the user's returned: its call line and roles say it all."""


@beat_kind("shape")
class ShapeChange(Beat):
    """A shape of the user's appears, changes or goes (``state`` None)."""

    key: str
    event: str
    #: the shape's drawable state as the log holds it (``kind``, ``at`` …; tracing.Shape)
    state: Mapping[str, JSON] | None = None
