"""The shared logger: record real runs of algorithms as JSON-serialisable event logs.

Standard library only. Open a recording with :func:`record`; decorate the algorithm's
functions with :func:`traced` and classes with :func:`traced_class`; make the objects
to draw :class:`Traceable` (or use :class:`Shape`) and mark their lifetimes with
:func:`enter` / :func:`change` / :func:`exit` or ``with``. With no recording open,
all of it is a cheap no-op. :func:`events_so_far` reads the log so far and ``with
at_line(n):`` states the line of the events made in it, for code that records on behalf
of someone else's function. The log format is described in ``docs/log-format.md``.

Examples
--------
>>> import tracing
>>> @tracing.traced
... def halve(n):
...     return n // 2
>>> with tracing.record(algorithm="demo") as log:
...     halve(10)
5
>>> [(e.seq, e.kind, e.name, e.args, e.result) for e in log.events]
[(0, 'call', 'halve', {'n': 10}, None), (1, 'return', 'halve', None, 5)]
>>> tracing.Log.from_json(log.to_json()) == log
True
"""

from tracing.decorators import lifetimes as lifetimes  # explicit re-export (not in __all__)
from tracing.decorators import traced, traced_class
from tracing.encoding import JSON, Traceable, encode
from tracing.events import EVENT_KINDS, SCHEMA, Event, Log
from tracing.recorder import (
    Recording,
    alive,
    at_line,
    change,
    enter,
    events_so_far,
    exit,
    note,
    record,
)
from tracing.shapes import SHAPE_KINDS, Shape

__all__ = [
    "EVENT_KINDS",
    "JSON",
    "SCHEMA",
    "SHAPE_KINDS",
    "Event",
    "Log",
    "Recording",
    "Shape",
    "Traceable",
    "alive",
    "at_line",
    "change",
    "encode",
    "enter",
    "events_so_far",
    "exit",
    "note",
    "record",
    "traced",
    "traced_class",
]
