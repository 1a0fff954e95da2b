"""Every metaphor module, and what it reads and performs.

A metaphor module declares ``READS`` (traced name → reading: the beats of that step, see
:mod:`story.storyboard`) and ``PERFORMS`` (beat kind → performer: ``(board, beat)``, the
animations that play it). A new metaphor is one module, named here once. A beat with no
performer plays as its caption only.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from metaphors import basics, clock, fruit, generic, gravity, monotone, pieces, sweep, water
from story.beats import Beat
from story.storyboard import Pacing, Reading, storyboard
from tracing import Log

#: the metaphor modules: the frame every run shares first, a heuristic of one's own last
MODULES = (basics, water, clock, sweep, gravity, pieces, fruit, monotone, generic)


def _merged(tables) -> Mapping:
    merged: dict = {}
    for table in tables:
        if merged.keys() & table.keys():
            raise ValueError(f"declared twice: {sorted(merged.keys() & table.keys())}")
        merged.update(table)
    return MappingProxyType(merged)


READS: Mapping[str, Reading] = _merged(m.READS for m in MODULES)
PERFORMS: Mapping[type[Beat], object] = _merged(m.PERFORMS for m in MODULES)


def beats(log: Log, pacing: Pacing | None = None, shown_code: str | None = None) -> list[Beat]:
    """The beats of a log, every metaphor's steps read."""
    return storyboard(log, pacing, shown_code, readings=READS)


def perform(board, beat: Beat) -> None:
    """Play one beat on the board."""
    PERFORMS.get(type(beat), basics.note)(board, beat)
