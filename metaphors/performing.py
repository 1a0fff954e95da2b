"""The metaphor API, typed: what a metaphor module declares (:mod:`metaphors.catalog` merges
them).

- ``READS: Mapping[str, Reading]``: traced name → reading, the beats of that step
  (:data:`story.storyboard.Reading`: ``(walk, call, ret)`` → beats);
- ``PERFORMS: Performances``: beat kind → :data:`Performer`, the animations that play a beat
  of that kind on the :class:`~metaphors.board.Board`. The table is built with
  :func:`performs` from :func:`act` pairs, so the type checker sees that each performer takes
  the beat kind it is filed under (``act(Water, flood)`` is an error).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import Any, TypeAlias, TypeVar

from metaphors.board import Board
from story.beats import Beat

B = TypeVar("B", bound=Beat)

#: A performer: plays one beat (of its kind ``B``) on the board.
Performer: TypeAlias = Callable[[Board, B], None]

#: An entry of a ``PERFORMS`` table: a beat kind and its performer (:func:`act`).
Act: TypeAlias = tuple[type[Beat], Performer[Any]]

#: A ``PERFORMS`` table: beat kind → its performer (looked up by the beat's own type).
Performances: TypeAlias = Mapping[type[Beat], Performer[Any]]


def act(kind: type[B], performer: Performer[B]) -> Act:
    """The entry ``kind → performer`` of a ``PERFORMS`` table; the performer must take beats
    of ``kind`` (checked where it is written, before the kind is erased)."""
    return kind, performer


def performs(*acts: Act) -> Performances:
    """A ``PERFORMS`` table of :func:`act` entries (each kind once).

    >>> from story.beats import Note
    >>> table = performs(act(Note, lambda board, beat: None))
    >>> list(table)
    [<class 'story.beats.Note'>]
    >>> performs(act(Note, print), act(Note, print))
    Traceback (most recent call last):
    ValueError: Note performed twice
    """
    table: dict[type[Beat], Performer[Any]] = {}
    for kind, performer in acts:
        if kind in table:
            raise ValueError(f"{kind.__name__} performed twice")
        table[kind] = performer
    return MappingProxyType(table)
