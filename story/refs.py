"""The keys a log's calls refer to: one lookup for every reading of an argument, a result or
the log's meta.

A traced argument that is an object of the log is encoded as ``{"ref": key}``
(:mod:`tracing.encoding`); the readings of the metaphors ask for it by the parameter's name.
A log whose call lacks that parameter (a renamed one, a heuristic of one's own with other
names, a hand-edited log) gets one clear line naming the function and the parameter, not a
``KeyError`` from deep inside a scene.

>>> from tracing import Event
>>> call = Event(0, "call", "nearest_to", None, {"b": {"ref": "B"}, "k": 2}, call=0)
>>> ref(call, "b")
'B'
>>> ref(call, "c")
Traceback (most recent call last):
...
geometry.errors.LogFormatError: the log's call of nearest_to has no argument 'c'
>>> ref(call, "k")
Traceback (most recent call last):
...
geometry.errors.LogFormatError: the log's call of nearest_to: argument 'k' is not an object of the log

The log's meta (what ran, on what: ``algorithm``, ``shown`` …) is read by :func:`meta`:

>>> from tracing import Log
>>> meta(Log(meta={"algorithm": "gravity"}), "algorithm"), meta(Log(), "shown")
('gravity', None)
>>> meta(Log(meta={"shown": 3}), "shown")
Traceback (most recent call last):
...
geometry.errors.LogFormatError: the log's meta 'shown' is not a string
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any, cast

from geometry.errors import LogFormatError
from tracing import JSON, Event, Log


def ref(call: Event, name: str) -> str:
    """The key of the log's object that argument ``name`` of ``call`` refers to."""
    return _key(arg(call, name), f"the log's call of {call.name}: argument {name!r}")


def ref_list(call: Event, name: str) -> list[str]:
    """The keys of the log's objects that argument ``name`` of ``call`` lists."""
    value = arg(call, name)
    what = f"the log's call of {call.name}: argument {name!r}"
    if not isinstance(value, list):
        raise LogFormatError(f"{what} is not a list")
    return [_key(v, f"{what}: an item") for v in value]


def arg(call: Event, name: str) -> Any:
    """Argument ``name`` of ``call`` as the log encodes it (a value, not an object)."""
    args = call.args or {}
    if name not in args:
        raise LogFormatError(f"the log's call of {call.name} has no argument {name!r}")
    return args[name]


def meta(log: Log, key: str) -> str | None:
    """The log's meta ``key``, a string (None: the log has none)."""
    value = log.meta.get(key)
    if value is None or isinstance(value, str):
        return value
    raise LogFormatError(f"the log's meta {key!r} is not a string")


def result_ref(ret: Event) -> str:
    """The key of the log's object a traced function returned."""
    return _key(ret.result, f"the log's return of {ret.name}: its result")


def result_refs(ret: Event) -> list[str]:
    """The keys of the log's objects a traced function returned as a list."""
    what = f"the log's return of {ret.name}: its result"
    if not isinstance(ret.result, list):
        raise LogFormatError(f"{what} is not a list")
    return [_key(v, f"{what}: an item") for v in ret.result]


# --- a value of the log, checked as what a reading takes it for ---------------------------------
# The log holds plain JSON (tracing.JSON). A reading that takes a value for a list, a list of
# indices, a string or an object says so through these: a value of another shape is one clear
# line naming what was read, and the reading gets the type it expects.


def listed(value: JSON, what: str) -> Sequence[JSON]:
    """``value``, a list (None: an empty one).

    >>> listed([1, "a"], "x"), listed(None, "x")
    ([1, 'a'], ())
    >>> listed(3, "the result")
    Traceback (most recent call last):
    ...
    geometry.errors.LogFormatError: the result is not a list
    """
    if value is None:
        return ()
    if isinstance(value, list):
        return value
    raise LogFormatError(f"{what} is not a list")


def int_list(value: JSON, what: str) -> list[int]:
    """``value``, a list of integers (vertex indices …).

    >>> int_list([2, 0], "x")
    [2, 0]
    >>> int_list([2, "B"], "the stack")
    Traceback (most recent call last):
    ...
    geometry.errors.LogFormatError: the stack is not a list of integers
    """
    found = [v for v in listed(value, what) if isinstance(v, int) and not isinstance(v, bool)]
    if value is None or len(found) != len(listed(value, what)):
        raise LogFormatError(f"{what} is not a list of integers")
    return found


def integer(value: JSON, what: str) -> int:
    """``value``, an integer."""
    if isinstance(value, int) and not isinstance(value, bool):
        return value
    raise LogFormatError(f"{what} is not an integer")


def string(value: JSON, what: str) -> str:
    """``value``, a string."""
    if isinstance(value, str):
        return value
    raise LogFormatError(f"{what} is not a string")


def json_object(value: JSON, what: str) -> Mapping[str, Any]:
    """``value``, an object: its fields by name, each read on by the reading (Any: the reading
    decodes it into its record's field)."""
    if isinstance(value, dict):
        return value
    raise LogFormatError(f"{what} is not an object")


def arg_int(call: Event, name: str) -> int:
    """Argument ``name`` of ``call``, an integer (a vertex index …)."""
    return integer(arg(call, name), f"the log's call of {call.name}: argument {name!r}")


def arg_ints(call: Event, name: str) -> list[int]:
    """Argument ``name`` of ``call``, a list of integers (vertex indices …)."""
    return int_list(arg(call, name), f"the log's call of {call.name}: argument {name!r}")


def result_list(ret: Event) -> Sequence[JSON]:
    """What a traced function returned, a list (None: an empty one)."""
    return listed(ret.result, f"the log's return of {ret.name}: its result")


def result_ints(ret: Event) -> list[int]:
    """What a traced function returned, a list of integers (vertex indices …)."""
    return int_list(ret.result, f"the log's return of {ret.name}: its result")


def result_string(ret: Event) -> str:
    """What a traced function returned, a string."""
    return string(ret.result, f"the log's return of {ret.name}: its result")


def result_object(ret: Event) -> Mapping[str, Any]:
    """What a traced function returned, an object (its fields by name)."""
    return json_object(ret.result, f"the log's return of {ret.name}: its result")


def _key(value: Any, what: str) -> str:
    if isinstance(value, dict) and isinstance(value.get("ref"), str):
        key: str = value["ref"]
        return key
    raise LogFormatError(f"{what} is not an object of the log")


# --- the fields the recorder always writes -------------------------------------------------------
# An Event's target, state and call are optional (a note has none), but the recorder writes a
# target and a state on every enter and change event, and the seq of its call on every return:
# these say so to the type checker, and change nothing at run time.


def target_of(event: Event) -> str:
    """The key of the object an enter, change or exit event is about."""
    return cast(str, event.target)


def state_of(event: Event) -> dict[str, Any]:
    """The state of an enter or change event (a dict: the log's JSON object)."""
    return cast("dict[str, Any]", event.state)


def call_of(event: Event) -> int:
    """The seq of the call of a return event (or of the call open around another event)."""
    return cast(int, event.call)
