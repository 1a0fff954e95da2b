"""Turning algorithm values into plain, deterministic JSON data.

Everything that enters a log (call arguments, results, object states, note data,
recording metadata) goes through :func:`encode` first. The rules never look at
memory ids or ``repr()``, so the same run always gives the same log.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping, Sequence
from typing import Any, Protocol, TypeAlias, Union, runtime_checkable

__all__ = ["JSON", "MAX_DEPTH", "Traceable", "encode", "trace_key_of"]

#: Plain JSON data as a log holds it (what :func:`encode` makes, what ``json`` reads back):
#: objects, arrays, strings, numbers, booleans and null, to be read, not changed.
JSON: TypeAlias = Union[Mapping[str, "JSON"], Sequence["JSON"], str, int, float, bool, None]  # noqa: UP007  # a recursive alias: its forward refs need Union

#: Containers nested deeper than this are cut off as ``{"type": ...}`` (guards cycles).
MAX_DEPTH = 32

_PASS_THROUGH = (type(None), bool, int, str)


@runtime_checkable
class Traceable(Protocol):
    """An object the algorithm wants drawn.

    It has a stable string key and describes its drawable state as plain JSON data
    whose ``"kind"`` is one of point / segment / polygon / circle / ray / line /
    band / text (other kinds are allowed).

    Examples
    --------
    >>> class Vertex:
    ...     def __init__(self, label, x, y):
    ...         self.trace_key, self.xy = label, [x, y]
    ...     def trace_state(self):
    ...         return {"kind": "point", "at": self.xy}
    >>> isinstance(Vertex("B", 1.0, 4.5), Traceable)
    True
    >>> isinstance(3, Traceable)
    False
    """

    @property
    def trace_key(self) -> str:
        """The object's stable key (an attribute or a property)."""
        ...

    def trace_state(self) -> dict[str, Any]:
        """Return the object's drawable state as plain JSON data."""
        ...


def trace_key_of(value: Any) -> str | None:
    """Return ``value.trace_key`` if it is a string, else ``None``.

    Examples
    --------
    >>> class Keyed:
    ...     trace_key = "P1"
    >>> trace_key_of(Keyed()), trace_key_of(object())
    ('P1', None)
    """
    key = getattr(value, "trace_key", None)
    return key if isinstance(key, str) else None


def encode(value: Any, _depth: int = 0) -> Any:
    """Encode ``value`` as plain JSON data for the log.

    Parameters
    ----------
    value : Any
        An argument, result, state or note value.

    Returns
    -------
    Any
        ``{"ref": key}`` for an object with a string ``trace_key``; ``None``, bools,
        ints and strs as they are; floats as they are except non-finite ones, which
        become ``"nan"``, ``"inf"`` or ``"-inf"``; tuples and lists as lists of encoded
        items; dicts with string keys as dicts of encoded values; dataclass instances
        as dicts of their encoded fields; numpy-like scalars through ``.item()``;
        anything else as ``{"type": <type name>}`` (never its repr).

    Examples
    --------
    >>> encode((1, 2.5, None, "A"))
    [1, 2.5, None, 'A']
    >>> encode({"r": float("inf"), "bad": float("nan")})
    {'r': 'inf', 'bad': 'nan'}
    >>> class Vertex:
    ...     trace_key = "B"
    >>> encode([Vertex(), {"x": Vertex()}])
    [{'ref': 'B'}, {'x': {'ref': 'B'}}]
    >>> from dataclasses import dataclass
    >>> @dataclass
    ... class Hit:
    ...     at: tuple
    ...     t: float
    >>> encode(Hit((1, 2), 0.5))
    {'at': [1, 2], 't': 0.5}
    >>> encode({1, 2}), encode({1: "a"}), encode(object())
    ({'type': 'set'}, {'type': 'dict'}, {'type': 'object'})
    """
    kind = type(value)
    if kind in _PASS_THROUGH:
        return value
    if kind is float:
        return value if math.isfinite(value) else _float_name(value)
    key = trace_key_of(value)
    if key is not None:
        return {"ref": key}
    if _depth >= MAX_DEPTH:
        return {"type": kind.__name__}
    return _encode_other(value, _depth + 1)


def _encode_other(value: Any, depth: int) -> Any:
    """Encode containers, subclasses of plain types and numpy-like scalars."""
    if isinstance(value, list | tuple):
        return [encode(item, depth) for item in value]
    if isinstance(value, dict):
        if all(type(name) is str for name in value):
            return {name: encode(item, depth) for name, item in value.items()}
        return {"type": type(value).__name__}
    if isinstance(value, bool | int | str | float):
        return encode(_plain_scalar(value), depth)
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {f.name: encode(getattr(value, f.name), depth) for f in dataclasses.fields(value)}
    scalar = _numpy_like_item(value)
    if scalar is not None:
        return encode(scalar, depth)
    return {"type": type(value).__name__}


def _plain_scalar(value: bool | int | str | float) -> bool | int | str | float:
    """Convert a subclass instance (``IntEnum``, ``str`` subclass …) to its base type."""
    for base in (bool, int, str, float):
        if isinstance(value, base):
            return base(value)
    raise TypeError(type(value).__name__)  # pragma: no cover - guarded by the caller


def _numpy_like_item(value: Any) -> bool | int | str | float | None:
    """Return ``value.item()`` for a zero-dimensional numpy-like scalar, else ``None``."""
    item = getattr(value, "item", None)
    if not callable(item) or getattr(value, "ndim", 0) != 0:
        return None
    try:
        scalar = item()
    except Exception:
        return None
    return scalar if type(scalar) in (bool, int, str, float) else None


def _float_name(value: float) -> str:
    """Name a non-finite float: ``"nan"``, ``"inf"`` or ``"-inf"``."""
    if math.isnan(value):
        return "nan"
    return "inf" if value > 0 else "-inf"
