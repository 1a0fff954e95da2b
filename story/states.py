"""The shape states a metaphor's step shows: typed records, one per kind of tool.

A metaphor's reading (:mod:`metaphors.water`, :mod:`metaphors.clock` …) turns what the log
says about a heuristic's step into these records; its performer draws them, and the
analysis (:mod:`story.analysis`) turns the one at the pick into a motion. Each record is
frozen and holds plain coordinates (polygon units) as the log gives them.

The moving tools, each from its start (``reached`` None) through each candidate it reaches:

- :class:`Disk`: the water spilled at B, a disk growing about ``center``;
- :class:`Hand`: the clock hand at ``origin``, set to ``heading`` and turned by ``angle``;
- :class:`Line`: the line through ``through`` along ``direction``, moved by ``offset``;
- :class:`Tide`: the water rising from the ``shore`` AC towards B to the ``level``.

Gravity's ball and band are not such tools: :class:`BallDrop` (where the ball falls from and
hits), :class:`BallSlide` (where it slides to) and :class:`RubberBand` (the band's corners,
bent at the vertex it snags) — a different thing from the water's :class:`Tide`.

>>> start = Disk(center=(1.0, 4.5), radius=0.0)
>>> wet = Disk(center=(1.0, 4.5), radius=2.83, reached="D")
>>> Moving.pick_of((start, wet), "D")
Disk(center=(1.0, 4.5), radius=2.83, reached='D', walled=False)
>>> RubberBand(corners=((0.0, 0.0), (4.0, 4.0), (4.0, 8.0))).snagged
True
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from typing import Self, TypeVar

from story.beats import Beat
from story.beats import Point as Point  # re-exported: the metaphors' records use it
from story.beats import point as point

# --- the moving tools -----------------------------------------------------------------------------


@dataclass(frozen=True, kw_only=True)
class Disk:
    """The water's disk about ``center`` of ``radius``; ``walled``: it respects the walls."""

    center: Point
    radius: float
    reached: str | None = None
    walled: bool = False


@dataclass(frozen=True, kw_only=True)
class Hand:
    """The clock hand at ``origin``, set to ``heading`` degrees, turned by ``angle`` degrees
    (unsigned: it turns the way towards the candidates)."""

    origin: Point
    heading: float
    angle: float
    reached: str | None = None


@dataclass(frozen=True, kw_only=True)
class Line:
    """The sweeping line through ``through`` along ``direction``, moved by ``offset``."""

    through: Point
    direction: Point
    offset: float
    reached: str | None = None


@dataclass(frozen=True, kw_only=True)
class Tide:
    """The water rising from the ``shore`` (A, C) towards B (``towards``) to ``level``."""

    shore: tuple[Point, Point]
    towards: Point
    level: float
    reached: str | None = None


#: what a moving tool's state may be
Tool = Disk | Hand | Line | Tide
T = TypeVar("T", bound=Tool)


def hits(states: Iterable[T], until: str | None = None) -> list[tuple[T, str]]:
    """Each state that reached a candidate, with that candidate, in order (the start, which
    reached none, is left out); with ``until``, none after the one that reached it: a tool
    stops at its pick, its decisive moment (the water went on to ring E after wetting D,
    a candidate that decides nothing: chapter 2).

    >>> start = Hand(origin=(0.0, 0.0), heading=90.0, angle=0.0)
    >>> d = Hand(origin=(0.0, 0.0), heading=90.0, angle=35.0, reached="D")
    >>> e = Hand(origin=(0.0, 0.0), heading=90.0, angle=50.0, reached="E")
    >>> [label for _, label in hits([start, d, e])]
    ['D', 'E']
    >>> [label for _, label in hits([start, d, e], until="D")]
    ['D']
    """
    found: list[tuple[T, str]] = []
    for state in states:
        if state.reached is not None:
            found.append((state, state.reached))
            if state.reached == until:
                break
    return found


@dataclass(frozen=True, kw_only=True)
class Moving(Beat):
    """A step whose tool moves: its ``states`` from the start through each candidate it
    reaches, and the picked vertex (``result``, as the call line shows it)."""

    states: tuple[Tool, ...]
    result: str

    @staticmethod
    def pick_of(states: Sequence[Tool], result: str) -> Tool | None:
        """The state at the pick (None: the tool reached no candidate)."""
        return next((s for s in states if s.reached == result), None)

    def at_pick(self) -> Tool | None:
        return self.pick_of(self.states, self.result)

    def before_pick(self) -> Self:
        """This beat as it plays until its tool reaches the pick: the pick still one of T's
        candidates, neutral, amber only as the tool gets there (chapter 2's working runs lit
        it amber as the tool set out, a second before it arrived).

        >>> beat = Moving(caption="", seq=0, states=(), result="E",
        ...               roles={"B": "called", "E": "argument", "F": "candidate"})
        >>> dict(beat.before_pick().roles)
        {'B': 'called', 'E': 'candidate', 'F': 'candidate'}
        """
        if self.roles.get(self.result) != "argument":
            return self
        return replace(self, roles={**self.roles, self.result: "candidate"})


# --- gravity's ball and band ---------------------------------------------------------------------


@dataclass(frozen=True, kw_only=True)
class BallDrop:
    """The ball falls from ``vertex`` (the reflex vertex V) and hits the boundary at ``hit``."""

    vertex: str
    hit: Point


@dataclass(frozen=True, kw_only=True)
class BallSlide:
    """The ball slides down the edge it hit, from where it hit (``hit``, None: not known) to
    the vertex at ``to``."""

    to: Point
    hit: Point | None = None


@dataclass(frozen=True, kw_only=True)
class RubberBand:
    """The rubber band's corners: ``(V, X)`` straight, ``(V, Y, X)`` bent at the snagged Y."""

    corners: tuple[Point, ...]

    @property
    def snagged(self) -> bool:
        return len(self.corners) == 3
