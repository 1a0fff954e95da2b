"""Recording a run: the scoped recorder and the explicit event functions.

A recording is opened with ``with record(...) as log``. The open recorder lives in a
:class:`contextvars.ContextVar`, so recordings in different threads or tasks never
mix, and an inner ``record()`` takes the events until it closes. When no recording
is open, every function here is a no-op that costs one ``ContextVar.get``.

Code that calls on someone else's behalf (a wrapper around a user's function) can
read the events so far with :func:`events_so_far` and state the line its events belong to
with ``with at_line(n):``.
"""

from __future__ import annotations

import sys
from contextvars import ContextVar, Token
from typing import Any

from tracing.encoding import Traceable, encode
from tracing.events import Event, Log, new_event

__all__ = [
    "ACTIVE_RECORDER",
    "Recorder",
    "Recording",
    "alive",
    "at_line",
    "caller_line",
    "change",
    "enter",
    "events_so_far",
    "exit",
    "note",
    "record",
]


class Recorder:
    """The mutable side of one open recording: its events and its open calls.

    Parameters
    ----------
    log : Log
        The log whose ``events`` list receives the events.

    Examples
    --------
    >>> rec = Recorder(Log())
    >>> seq = rec.open_call("f", None, {"x": 1}, line=7)
    >>> rec.add("note", "hint", None, line=8, args={"why": "demo"})
    >>> rec.close_call(seq, "f", None, 2, line=7)
    >>> [(e.kind, e.depth, e.call) for e in rec.events]
    [('call', 0, 0), ('note', 1, 0), ('return', 0, 0)]
    """

    __slots__ = ("events", "kinds", "open_calls")

    def __init__(self, log: Log) -> None:
        self.events = log.events
        self.open_calls: list[int] = []
        self.kinds: dict[str, str] = {}  # live object key -> kind, to name its exit

    def open_call(self, name: str, target: str | None, args: dict[str, Any], line: int) -> int:
        """Append a call event and open the call; return its ``seq``."""
        events, open_calls = self.events, self.open_calls
        seq = len(events)
        events.append(
            new_event(seq, "call", name, target, args, None, None, line, len(open_calls), seq)
        )
        open_calls.append(seq)
        return seq

    def close_call(self, seq: int, name: str, target: str | None, result: Any, line: int) -> None:
        """Close the call opened as ``seq`` and append its return event."""
        events, open_calls = self.events, self.open_calls
        if open_calls and open_calls[-1] == seq:
            open_calls.pop()
        elif seq in open_calls:  # defensive: drop inner calls that never closed
            del open_calls[open_calls.index(seq) :]
        events.append(
            new_event(
                len(events), "return", name, target, None, result, None, line, len(open_calls), seq
            )
        )

    def add(
        self,
        kind: str,
        name: str,
        target: str | None,
        line: int,
        args: dict[str, Any] | None = None,
        state: dict[str, Any] | None = None,
    ) -> None:
        """Append an enter/change/exit/note event inside the innermost open call."""
        events, open_calls = self.events, self.open_calls
        innermost = open_calls[-1] if open_calls else None
        events.append(
            new_event(
                len(events), kind, name, target, args, None, state, line, len(open_calls), innermost
            )
        )

    def enter(self, obj: Traceable, line: int) -> None:
        """Record that ``obj`` appears, with its state."""
        state = _state_of(obj)
        name = _kind_of(state)
        self.kinds[obj.trace_key] = name
        self.add("enter", name, obj.trace_key, line, state=state)

    def change(self, obj: Traceable, line: int) -> None:
        """Record the new state of ``obj``."""
        state = _state_of(obj)
        name = _kind_of(state)
        self.kinds[obj.trace_key] = name
        self.add("change", name, obj.trace_key, line, state=state)

    def exit(self, obj: Traceable, line: int) -> None:
        """Record that ``obj`` disappears."""
        name = self.kinds.pop(obj.trace_key, None) or _kind_of(_state_of(obj))
        self.add("exit", name, obj.trace_key, line)


class _StatedLine(Recorder):
    """A recorder sharing ``base``'s events and open calls that writes ``line`` into the
    events at ``base``'s current depth (see :class:`at_line`); deeper events keep theirs.

    Examples
    --------
    >>> base = Recorder(Log())
    >>> stated = _StatedLine(base, 30)
    >>> seq = stated.open_call("claim", None, {}, line=7)
    >>> stated.add("enter", "segment", "BE", line=95)
    >>> stated.close_call(seq, "claim", None, None, line=7)
    >>> [(e.kind, e.line, e.depth) for e in base.events]
    [('call', 30, 0), ('enter', 95, 1), ('return', 30, 0)]
    """

    __slots__ = ("depth", "line")

    def __init__(self, base: Recorder, line: int) -> None:
        self.events, self.open_calls, self.kinds = base.events, base.open_calls, base.kinds
        self.depth = len(base.open_calls)
        self.line = line

    def open_call(self, name: str, target: str | None, args: dict[str, Any], line: int) -> int:
        if len(self.open_calls) == self.depth:
            line = self.line
        return super().open_call(name, target, args, line)

    def close_call(self, seq: int, name: str, target: str | None, result: Any, line: int) -> None:
        if self.events[seq].depth == self.depth:  # a call made in the block
            line = self.line
        super().close_call(seq, name, target, result, line)

    def add(
        self,
        kind: str,
        name: str,
        target: str | None,
        line: int,
        args: dict[str, Any] | None = None,
        state: dict[str, Any] | None = None,
    ) -> None:
        if len(self.open_calls) == self.depth:
            line = self.line
        super().add(kind, name, target, line, args, state)


#: The recorder of the innermost open recording in this context, if any.
ACTIVE_RECORDER: ContextVar[Recorder | None] = ContextVar("tracing_recorder", default=None)


class Recording:
    """Context manager returned by :func:`record`; ``__enter__`` gives the :class:`Log`."""

    __slots__ = ("_token", "_used", "log")

    def __init__(self, meta: dict[str, Any]) -> None:
        self.log = Log(encode(meta))
        self._token: Token[Recorder | None] | None = None
        self._used = False

    def __enter__(self) -> Log:
        if self._used:
            raise RuntimeError("a recording can be opened only once; call record() again")
        self._used = True
        self._token = ACTIVE_RECORDER.set(Recorder(self.log))
        return self.log

    def __exit__(self, *exc_info: object) -> None:
        if self._token is not None:
            ACTIVE_RECORDER.reset(self._token)
            self._token = None


def record(**meta: Any) -> Recording:
    """Open a recording: ``with record(algorithm="scaling") as log: ...``.

    Parameters
    ----------
    **meta
        Plain JSON values describing the run; stored (encoded) as ``log.meta``.

    Examples
    --------
    >>> with record(algorithm="demo", size=(3, 4)) as log:
    ...     note("hello", who="world")
    >>> log.meta, [(e.kind, e.name, e.args) for e in log.events]
    ({'algorithm': 'demo', 'size': [3, 4]}, [('note', 'hello', {'who': 'world'})])
    >>> with record() as outer:
    ...     with record() as inner:
    ...         note("inner")
    ...     note("outer")
    >>> [e.name for e in outer.events], [e.name for e in inner.events]
    (['outer'], ['inner'])
    """
    return Recording(meta)


def events_so_far() -> tuple[Event, ...]:
    """Return the events recorded so far by the innermost open recording.

    A snapshot: a tuple, which later events do not change. Code that runs inside a
    recording it did not open (a wrapper around someone else's function) reads the log
    with it; whoever opened the recording has the :class:`Log` itself.

    Returns
    -------
    tuple of Event
        The events in order (``events_so_far()[i].seq == i``); empty when no recording is open.

    Examples
    --------
    >>> events_so_far()  # no recording open
    ()
    >>> with record() as log:
    ...     note("first")
    ...     seen = events_so_far()
    ...     note("second")
    >>> [e.name for e in seen], len(log.events)
    (['first'], 2)
    """
    recorder = ACTIVE_RECORDER.get()
    return () if recorder is None else tuple(recorder.events)


class at_line:
    """State the source line of the events recorded in the ``with`` block.

    Every event recorded at the depth where the block opens gets ``line`` instead of the
    line it would have: the call and return of a traced function called in the block,
    and an enter/change/exit/note made in the block. Events inside those calls keep their
    own lines. For code that calls on someone else's behalf: a wrapper that makes a call
    for the function it wraps states the line of that function the call belongs to.

    Parameters
    ----------
    line : int or None
        The line to record; ``None`` states nothing (the events keep their lines).

    Examples
    --------
    >>> import tracing
    >>> @tracing.traced
    ... def pick(x):
    ...     note("inside")
    ...     return x
    >>> with record() as log:
    ...     with at_line(40):
    ...         pick(1)
    ...         note("after")
    1
    >>> [(e.kind, e.name, e.line) for e in log.events]
    [('call', 'pick', 40), ('note', 'inside', 3), ('return', 'pick', 40), ('note', 'after', 40)]
    >>> with record() as log, at_line(None):
    ...     note("unstated")
    >>> log.events[0].line
    2
    """

    __slots__ = ("_token", "line")

    def __init__(self, line: int | None) -> None:
        self.line = line
        self._token: Token[Recorder | None] | None = None

    def __enter__(self) -> None:
        recorder = ACTIVE_RECORDER.get()
        if recorder is not None and self.line is not None:
            self._token = ACTIVE_RECORDER.set(_StatedLine(recorder, self.line))

    def __exit__(self, *exc_info: object) -> None:
        if self._token is not None:
            ACTIVE_RECORDER.reset(self._token)
            self._token = None


def caller_line(skip: int = 0) -> int:
    """Return the line of the code that called the function calling ``caller_line``.

    Parameters
    ----------
    skip : int
        Extra frames to go up.

    Examples
    --------
    >>> def where():
    ...     return caller_line()
    >>> where()  # a doctest example is line 1 of its own code
    1
    """
    return sys._getframe(2 + skip).f_lineno


def note(kind: str, /, **data: Any) -> None:
    """Record a narrative event ``kind`` with encoded ``data`` (rare; for the story).

    Examples
    --------
    >>> note("ignored")  # no recording open: nothing happens
    >>> with record() as log:
    ...     note("fallback", reason="convex polygon", diagonal=("A", "C"))
    >>> log.events[0].args
    {'reason': 'convex polygon', 'diagonal': ['A', 'C']}
    """
    recorder = ACTIVE_RECORDER.get()
    if recorder is None:
        return
    recorder.add("note", kind, None, sys._getframe(1).f_lineno, args=encode(data))


def enter(obj: Traceable) -> None:
    """Record that ``obj`` appears on screen, with its current state.

    Examples
    --------
    >>> from tracing.shapes import Shape
    >>> with record() as log:
    ...     enter(Shape("P", "point", at=[1, 2]))
    >>> log.state_at(0)
    {'P': {'kind': 'point', 'at': [1, 2]}}
    """
    recorder = ACTIVE_RECORDER.get()
    if recorder is None:
        return
    recorder.enter(obj, sys._getframe(1).f_lineno)


def change(obj: Traceable) -> None:
    """Record the current state of ``obj`` (which has entered before).

    Examples
    --------
    >>> from tracing.shapes import Shape
    >>> p = Shape("P", "point", at=[1, 2])
    >>> with record() as log:
    ...     enter(p)
    ...     p.fields["at"] = [3, 4]
    ...     change(p)
    >>> log.events[1].kind, log.events[1].state
    ('change', {'kind': 'point', 'at': [3, 4]})
    """
    recorder = ACTIVE_RECORDER.get()
    if recorder is None:
        return
    recorder.change(obj, sys._getframe(1).f_lineno)


def exit(obj: Traceable) -> None:
    """Record that ``obj`` disappears.

    Examples
    --------
    >>> from tracing.shapes import Shape
    >>> p = Shape("P", "point", at=[1, 2])
    >>> with record() as log:
    ...     enter(p)
    ...     exit(p)
    >>> [(e.kind, e.name, e.target) for e in log.events], log.state_at(1)
    ([('enter', 'point', 'P'), ('exit', 'point', 'P')], {})
    """
    recorder = ACTIVE_RECORDER.get()
    if recorder is None:
        return
    recorder.exit(obj, sys._getframe(1).f_lineno)


class alive:
    """Keep ``obj`` on screen for the ``with`` block: enter on entry, exit on leaving.

    Both events carry the line of the ``with`` statement.

    Examples
    --------
    >>> from tracing.shapes import Shape
    >>> with record() as log:
    ...     with alive(Shape("L", "line", through=[[0, 0], [1, 1]])) as line:
    ...         note("inside", key=line.trace_key)
    >>> [e.kind for e in log.events]
    ['enter', 'note', 'exit']
    """

    __slots__ = ("obj",)

    def __init__(self, obj: Traceable) -> None:
        self.obj = obj

    def __enter__(self) -> Any:
        recorder = ACTIVE_RECORDER.get()
        if recorder is not None:
            recorder.enter(self.obj, sys._getframe(1).f_lineno)
        return self.obj

    def __exit__(self, *exc_info: object) -> None:
        recorder = ACTIVE_RECORDER.get()
        if recorder is not None:
            recorder.exit(self.obj, sys._getframe(1).f_lineno)


def _state_of(obj: Traceable) -> dict[str, Any]:
    """Return ``obj.trace_state()`` encoded as plain JSON data."""
    state = obj.trace_state()
    if not isinstance(state, dict):
        raise TypeError(f"{type(obj).__name__}.trace_state() must return a dict")
    encoded: dict[str, Any] = encode(state)  # a dict encodes as a dict
    return encoded


def _kind_of(state: dict[str, Any]) -> str:
    """Return the state's ``"kind"``, or ``"object"`` when it has none."""
    kind = state.get("kind")
    return kind if isinstance(kind, str) else "object"
