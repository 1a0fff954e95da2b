"""Every metaphor module, and what it reads and performs.

A metaphor module declares ``READS`` (traced name → :data:`~story.storyboard.Reading`: the
beats of that step) and ``PERFORMS`` (beat kind → :data:`~metaphors.performing.Performer`:
``(board, beat)``, the animations that play it; see :mod:`metaphors.performing`). The
registry names each algorithm's metaphor (:attr:`story.registry.Entry.metaphor`, the
module's name in this package), so a new
metaphor is one module plus its registry entry; the frame every run shares (``basics``) and
a heuristic of one's own (``generic``) are always read. A beat with no performer plays as
its caption only.

>>> [m.__name__ for m in MODULES]  # doctest: +NORMALIZE_WHITESPACE
['metaphors.basics', 'metaphors.water', 'metaphors.clock', 'metaphors.sweep',
 'metaphors.gravity', 'metaphors.pieces', 'metaphors.fruit', 'metaphors.monotone',
 'metaphors.generic']
"""

from __future__ import annotations

import importlib
from collections.abc import Iterable, Mapping
from types import MappingProxyType, ModuleType
from typing import TypeVar

from metaphors import basics, generic
from metaphors.board import Board
from metaphors.performing import Performances
from story.beats import Beat
from story.registry import REGISTRY
from story.storyboard import Pacing, Reading, storyboard
from tracing import Log


def _registered() -> tuple[ModuleType, ...]:
    """The modules of the registry's metaphors, in the registry's order."""
    names = dict.fromkeys(e.metaphor for e in REGISTRY.values() if e.metaphor)
    return tuple(importlib.import_module(f"{__package__}.{name}") for name in names)


#: the metaphor modules: the frame every run shares first, a heuristic of one's own last
MODULES = (basics, *_registered(), generic)


K = TypeVar("K")
V = TypeVar("V")


def _merged(tables: Iterable[Mapping[K, V]]) -> Mapping[K, V]:
    """One table of many; a key declared twice is an error (named by ``str``: a beat kind is
    a class, which does not sort).

    >>> _merged([{"a": 1}, {"b": 2}])
    mappingproxy({'a': 1, 'b': 2})
    >>> from story.beats import Note
    >>> _merged([{Note: 1}, {Note: 2}])
    Traceback (most recent call last):
    ValueError: declared twice: ["<class 'story.beats.Note'>"]
    """
    merged: dict[K, V] = {}
    for table in tables:
        if twice := merged.keys() & table.keys():
            raise ValueError(f"declared twice: {sorted(map(str, twice))}")
        merged.update(table)
    return MappingProxyType(merged)


READS: Mapping[str, Reading] = _merged(m.READS for m in MODULES)
PERFORMS: Performances = _merged(m.PERFORMS for m in MODULES)


def beats(log: Log, pacing: Pacing | None = None, shown_code: str | None = None, *,
          black_box: bool = False) -> list[Beat]:
    """The beats of a log, every metaphor's steps read (``black_box``: divide and
    conquer's heuristic unseen, :func:`story.storyboard.storyboard`)."""
    return storyboard(log, pacing, shown_code, readings=READS, black_box=black_box)


def perform(board: Board, beat: Beat) -> None:
    """Play one beat on the board."""
    PERFORMS.get(type(beat), basics.note)(board, beat)
