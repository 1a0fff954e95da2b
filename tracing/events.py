"""The log: :class:`Event` records and the :class:`Log` that holds them.

A log is plain data. It is written and read as JSON with the versioned schema
``"trex-log/1"`` (see ``docs/log-format.md``), and it can say which drawable objects
were alive at any step (:meth:`Log.state_at`).
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any, cast

from tracing.encoding import JSON
from tracing.replay import LiveStates

__all__ = ["EVENT_KINDS", "SCHEMA", "Event", "Log", "new_event"]

#: The schema written into, and required from, every JSON log.
SCHEMA = "trex-log/1"

#: Every value :attr:`Event.kind` can take.
EVENT_KINDS = ("call", "return", "enter", "change", "exit", "note")

_ALWAYS_WRITTEN = ("seq", "kind", "name", "depth")


@dataclass(frozen=True, slots=True)
class Event:
    """One step of a recorded run.

    Attributes
    ----------
    seq : int
        Position in the log: 0, 1, 2, …
    kind : str
        ``"call"``, ``"return"``, ``"enter"``, ``"change"``, ``"exit"`` or ``"note"``.
    name : str
        Function name (call/return), object kind such as ``"circle"``
        (enter/change/exit) or note kind (note).
    target : str or None
        Key of the object the event is about, or of ``self`` for a method call.
    args : dict or None
        Encoded arguments in signature order (call) or the note's data (note).
    result : Any
        Encoded return value (return only); ``{"raised": "ValueError"}`` for an exception.
    state : dict or None
        The object's drawable state (enter/change).
    line : int or None
        Source line in the algorithm where the event happened.
    depth : int
        Number of calls open around the event (top-level calls have depth 0).
    call : int or None
        ``seq`` of the matching call (call/return) or of the innermost open call.

    Examples
    --------
    >>> Event(0, "call", "nearest_to", None, {"b": {"ref": "B"}}, line=12, call=0)
    ... # doctest: +NORMALIZE_WHITESPACE
    Event(seq=0, kind='call', name='nearest_to', target=None, args={'b': {'ref': 'B'}},
          result=None, state=None, line=12, depth=0, call=0)
    """

    seq: int
    kind: str
    name: str
    target: str | None = None
    args: Mapping[str, JSON] | None = None
    result: JSON = None
    state: Mapping[str, JSON] | None = None
    line: int | None = None
    depth: int = 0
    call: int | None = None

    def to_dict(self) -> dict[str, Any]:
        """Return the event as a JSON object; fields that are ``None`` are left out.

        Examples
        --------
        >>> Event(3, "exit", "circle", "W(B)", line=40, depth=1, call=2).to_dict()
        {'seq': 3, 'kind': 'exit', 'name': 'circle', 'target': 'W(B)', 'line': 40, \
'depth': 1, 'call': 2}
        """
        out = {}
        for name in _FIELD_NAMES:
            value = getattr(self, name)
            if value is not None or name in _ALWAYS_WRITTEN:
                out[name] = value
        return out

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> Event:
        """Build an event from :meth:`to_dict` output; missing fields are ``None``.

        Examples
        --------
        >>> Event.from_dict({"seq": 0, "kind": "note", "name": "fallback", "depth": 0})
        ... # doctest: +NORMALIZE_WHITESPACE
        Event(seq=0, kind='note', name='fallback', target=None, args=None, result=None,
              state=None, line=None, depth=0, call=None)
        """
        if not isinstance(data, dict):
            raise ValueError(f"an event must be a JSON object, not {data!r}")
        unknown = sorted(set(data) - set(_FIELD_NAMES))
        if unknown:
            raise ValueError(f"unknown event field(s) {unknown} in {data!r}")
        missing = [name for name in ("seq", "kind", "name") if name not in data]
        if missing:
            raise ValueError(f"event {data!r} lacks field(s) {missing}")
        if data["kind"] not in EVENT_KINDS:
            raise ValueError(f"unknown event kind {data['kind']!r}")
        return cls(**data)


_FIELD_NAMES = tuple(spec.name for spec in fields(Event))


class _EventDraft:
    """Mutable twin of :class:`Event` with the same slots; becomes an Event when filled.

    A frozen dataclass's ``__init__`` calls ``object.__setattr__`` once per field
    (about 1 µs for ten fields); filling a plain slotted object and switching its
    class to ``Event`` (same slot layout) costs a quarter of that. Only the recorder's
    hot path uses it, through ``new_event``.

    Examples
    --------
    >>> event = new_event(0, "note", "x", None, None, None, None, 3, 0, None)
    >>> type(event).__name__, event == Event(0, "note", "x", line=3)
    ('Event', True)
    """

    __slots__ = _FIELD_NAMES

    def __init__(
        self,
        seq: int,
        kind: str,
        name: str,
        target: str | None,
        args: dict[str, Any] | None,
        result: Any,
        state: dict[str, Any] | None,
        line: int | None,
        depth: int,
        call: int | None,
    ) -> None:
        self.seq, self.kind, self.name, self.target, self.args = seq, kind, name, target, args
        self.result, self.state, self.line, self.depth, self.call = result, state, line, depth, call
        self.__class__ = Event  # type: ignore[assignment]  # on purpose: the same slots, and an Event from here on


#: Build an :class:`Event` fast from all ten fields, given positionally.
new_event = cast("Callable[..., Event]", _EventDraft)  # its __init__ turns it into an Event


@dataclass
class Log:
    """A recorded run: metadata and the list of events in order.

    Treat ``events`` as append-only; :meth:`state_at` caches checkpoints of its prefix.

    Examples
    --------
    >>> log = Log({"algorithm": "demo"}, [
    ...     Event(0, "enter", "point", "A", state={"kind": "point", "at": [0, 0]}, line=3),
    ...     Event(1, "exit", "point", "A", line=4),
    ... ])
    >>> log.to_json()
    '{"schema":"trex-log/1","meta":{"algorithm":"demo"},"events":[{"seq":0,"kind":"enter",\
"name":"point","target":"A","state":{"kind":"point","at":[0,0]},"line":3,"depth":0},\
{"seq":1,"kind":"exit","name":"point","target":"A","line":4,"depth":0}]}'
    >>> Log.from_json(log.to_json()) == log
    True
    """

    meta: dict[str, JSON] = field(default_factory=dict)
    events: list[Event] = field(default_factory=list)
    _live: LiveStates | None = field(default=None, init=False, repr=False, compare=False)

    def to_json(self, indent: int | None = None) -> str:
        """Serialise the log as JSON, keys in written order (byte-identical for equal logs).

        Parameters
        ----------
        indent : int or None
            Pretty-print with this indent; ``None`` gives the compact form.

        Examples
        --------
        >>> print(Log({"n": 1}).to_json(indent=1))
        {
         "schema": "trex-log/1",
         "meta": {
          "n": 1
         },
         "events": []
        }
        """
        document = {
            "schema": SCHEMA,
            "meta": self.meta,
            "events": [event.to_dict() for event in self.events],
        }
        separators = (",", ":") if indent is None else (",", ": ")
        # Keys keep the order the code wrote them in (deterministic): sorting them would
        # reorder a call's arguments, and a replayed log would show a different call line.
        return json.dumps(
            document,
            indent=indent,
            separators=separators,
            allow_nan=False,
            ensure_ascii=False,
        )

    @classmethod
    def from_json(cls, text: str) -> Log:
        """Read a log written by :meth:`to_json`.

        Raises
        ------
        ValueError
            If the text is not a ``"trex-log/1"`` log.

        Examples
        --------
        >>> Log.from_json('{"schema": "trex-log/1", "meta": {}, "events": []}')
        Log(meta={}, events=[])
        >>> Log.from_json('{"schema": "trex-log/0", "meta": {}, "events": []}')
        Traceback (most recent call last):
        ...
        ValueError: unsupported log schema 'trex-log/0'; expected 'trex-log/1'
        """
        document = json.loads(text)
        schema = document.get("schema") if isinstance(document, dict) else None
        if schema != SCHEMA:
            raise ValueError(f"unsupported log schema {schema!r}; expected {SCHEMA!r}")
        meta, items = document.get("meta", {}), document.get("events", [])
        if not isinstance(meta, dict) or not isinstance(items, list):
            raise ValueError("a log's meta must be an object and its events a list")
        return cls(meta, [Event.from_dict(item) for item in items])

    def save(self, path: str | Path, indent: int | None = None) -> None:
        """Write :meth:`to_json` to ``path`` as UTF-8.

        Examples
        --------
        >>> import pathlib, tempfile
        >>> path = pathlib.Path(tempfile.mkdtemp()) / "run.json"
        >>> Log({"algorithm": "demo"}).save(path)
        >>> Log.load(path).meta
        {'algorithm': 'demo'}
        """
        Path(path).write_text(self.to_json(indent) + "\n", encoding="utf-8")

    @classmethod
    def load(cls, path: str | Path) -> Log:
        """Read a log saved by :meth:`save`."""
        return cls.from_json(Path(path).read_text(encoding="utf-8"))

    def state_at(self, step: int) -> dict[str, dict[str, Any]]:
        """Return every live object's latest state after events ``0..step``.

        Parameters
        ----------
        step : int
            Index of the last event applied; ``-1`` means before the first event.

        Returns
        -------
        dict of str to dict
            Object key → state, in the order the objects entered. Treat the states
            as read-only: they are shared with the events.

        Examples
        --------
        >>> log = Log({}, [
        ...     Event(0, "enter", "circle", "W", state={"kind": "circle", "radius": 0}),
        ...     Event(1, "change", "circle", "W", state={"kind": "circle", "radius": 2}),
        ...     Event(2, "exit", "circle", "W"),
        ... ])
        >>> [log.state_at(step) for step in (-1, 0, 1, 2)]
        [{}, {'W': {'kind': 'circle', 'radius': 0}}, {'W': {'kind': 'circle', 'radius': 2}}, {}]
        """
        if self._live is None or not self._live.covers(self.events):
            self._live = LiveStates(self.events)
        return self._live.at(step)

    def calls(self) -> list[tuple[Event, Event | None]]:
        """Return every call event paired with its return event (``None`` if still open).

        Examples
        --------
        >>> log = Log({}, [
        ...     Event(0, "call", "f", call=0),
        ...     Event(1, "return", "f", result=2, call=0),
        ... ])
        >>> [(c.seq, r.result) for c, r in log.calls()]
        [(0, 2)]
        """
        returns = {event.call: event for event in self.events if event.kind == "return"}
        return [(event, returns.get(event.seq)) for event in self.events if event.kind == "call"]

    def find(
        self, kind: str | None = None, name: str | None = None, target: str | None = None
    ) -> list[Event]:
        """Return the events matching every criterion that is not ``None``.

        Examples
        --------
        >>> log = Log({}, [Event(0, "call", "f", call=0), Event(1, "return", "f", call=0)])
        >>> [e.seq for e in log.find(kind="return")], [e.seq for e in log.find(name="g")]
        ([1], [])
        """
        return [
            event
            for event in self.events
            if (kind is None or event.kind == kind)
            and (name is None or event.name == name)
            and (target is None or event.target == target)
        ]
