"""Rebuilding which objects are alive at a step from enter/change/exit deltas.

No snapshot is stored per event. :class:`LiveStates` replays the events and keeps a
checkpoint (a copy of the live set) only after at least ``max(CHECKPOINT_EVERY,
live objects)`` events since the previous one, so checkpoints never hold more
entries in total than there are events: memory stays linear in the log, and a query
replays at most that many events from the nearest checkpoint.
"""

from __future__ import annotations

import bisect
from collections.abc import Mapping, Sequence
from typing import Any, Protocol, cast

from tracing.encoding import JSON

__all__ = ["CHECKPOINT_EVERY", "LiveStates", "apply_event"]

#: Minimum number of events between two checkpoints.
CHECKPOINT_EVERY = 256

States = dict[str, dict[str, Any]]


class Event(Protocol):
    """What replaying needs of a :class:`tracing.events.Event` (which imports this module)."""

    @property
    def kind(self) -> str: ...
    @property
    def target(self) -> str | None: ...
    @property
    def state(self) -> Mapping[str, JSON] | None: ...


def apply_event(live: States, event: Event) -> None:
    """Apply one event to ``live`` (object key → state) in place.

    ``enter`` adds or replaces, ``change`` replaces the state of a live object (a change
    of an object that is not alive is ignored), ``exit`` removes; other kinds do nothing.

    Examples
    --------
    >>> from tracing.events import Event
    >>> live = {}
    >>> apply_event(live, Event(0, "enter", "point", "A", state={"kind": "point"}))
    >>> apply_event(live, Event(1, "change", "point", "B", state={"kind": "point"}))
    >>> live
    {'A': {'kind': 'point'}}
    """
    kind = event.kind
    # enter and change events always have a target and a state (tracing.recorder writes them)
    target, state = cast(str, event.target), cast("dict[str, Any]", event.state)
    if kind == "enter":
        live[target] = state
    elif kind == "change":
        if target in live:
            live[target] = state
    elif kind == "exit":
        live.pop(target, None)


class LiveStates:
    """Checkpointed replay of one event list.

    Parameters
    ----------
    events : sequence of Event
        The log's events; treated as append-only.

    Examples
    --------
    >>> from tracing.events import Event
    >>> events = [Event(i, "enter", "point", f"P{i}", state={"kind": "point"}) for i in range(600)]
    >>> live = LiveStates(events)
    >>> len(live.at(299)), len(live.at(-1)), len(live.at(599))
    (300, 0, 600)
    """

    def __init__(self, events: Sequence[Event]) -> None:
        self._events = events
        self._starts: list[int] = [0]  # checkpoint i = live set before event _starts[i]
        self._snapshots: list[States] = [{}]

    def covers(self, events: Sequence[Event]) -> bool:
        """Return whether this replay was built for ``events`` (the same list object)."""
        return events is self._events and len(events) >= self._starts[-1]

    def at(self, step: int) -> States:
        """Return the live objects after applying events ``0..step`` (``-1``: none)."""
        if not -1 <= step < len(self._events):
            raise IndexError(f"step {step} outside -1..{len(self._events) - 1}")
        self._extend_checkpoints(step)
        index = bisect.bisect_right(self._starts, step + 1) - 1
        live = dict(self._snapshots[index])
        for event in self._events[self._starts[index] : step + 1]:
            apply_event(live, event)
        return live

    def _extend_checkpoints(self, step: int) -> None:
        """Add checkpoints until the last one is close enough to ``step``."""
        position = self._starts[-1]
        gap = max(CHECKPOINT_EVERY, len(self._snapshots[-1]))
        if step + 1 - position < gap:
            return
        live = dict(self._snapshots[-1])
        while step + 1 - position >= gap:
            for event in self._events[position : position + gap]:
                apply_event(live, event)
            position += gap
            self._starts.append(position)
            self._snapshots.append(dict(live))
            gap = max(CHECKPOINT_EVERY, len(live))
