"""A ready-made traceable for temporary drawables (water circles, sweep lines, bands …)."""

from __future__ import annotations

import sys
from typing import Any

from tracing.recorder import ACTIVE_RECORDER

__all__ = ["SHAPE_KINDS", "Shape"]

#: Kinds the scene generator knows how to draw; other kinds are allowed.
SHAPE_KINDS = ("point", "segment", "polygon", "circle", "ray", "line", "band", "text")


class Shape:
    """A keyed drawable described by a kind and plain JSON fields.

    As a context manager it enters on ``__enter__`` and exits on ``__exit__`` (both
    events carry the line of the ``with``); :meth:`update` records a change.

    Parameters
    ----------
    key : str
        Unique, stable key (``trace_key``), e.g. ``"W(B)"``.
    kind : str
        What to draw: one of :data:`SHAPE_KINDS` or another kind.
    **fields
        The drawable state besides the kind, e.g. ``center=[1, 4.5], radius=0.0``.

    Examples
    --------
    >>> import tracing
    >>> with tracing.record() as log:
    ...     with Shape("W(B)", "circle", center=[1, 4.5], radius=0.0) as water:
    ...         water.update(radius=2.3)
    >>> [(e.kind, e.name, e.target, e.state) for e in log.events]
    ... # doctest: +NORMALIZE_WHITESPACE
    [('enter', 'circle', 'W(B)', {'kind': 'circle', 'center': [1, 4.5], 'radius': 0.0}),
     ('change', 'circle', 'W(B)', {'kind': 'circle', 'center': [1, 4.5], 'radius': 2.3}),
     ('exit', 'circle', 'W(B)', None)]
    """

    __slots__ = ("fields", "kind", "trace_key")

    def __init__(self, key: str, kind: str, /, **fields: Any) -> None:
        _check_fields(fields)
        self.trace_key = key
        self.kind = kind
        self.fields = fields

    def trace_state(self) -> dict[str, Any]:
        """Return ``{"kind": kind, **fields}``.

        Examples
        --------
        >>> Shape("S", "segment", ends=[[0, 0], [1, 1]]).trace_state()
        {'kind': 'segment', 'ends': [[0, 0], [1, 1]]}
        """
        return {"kind": self.kind, **self.fields}

    def update(self, **fields: Any) -> None:
        """Change some fields and record a change event with the new full state.

        Examples
        --------
        >>> band = Shape("band", "band", width=1)
        >>> band.update(width=2)  # no recording open: only the fields change
        >>> band.fields
        {'width': 2}
        """
        _check_fields(fields)
        self.fields.update(fields)
        recorder = ACTIVE_RECORDER.get()
        if recorder is not None:
            recorder.change(self, sys._getframe(1).f_lineno)

    def __enter__(self) -> Shape:
        recorder = ACTIVE_RECORDER.get()
        if recorder is not None:
            recorder.enter(self, sys._getframe(1).f_lineno)
        return self

    def __exit__(self, *exc_info: object) -> None:
        recorder = ACTIVE_RECORDER.get()
        if recorder is not None:
            recorder.exit(self, sys._getframe(1).f_lineno)

    def __repr__(self) -> str:
        return f"Shape({self.trace_key!r}, {self.kind!r}, **{self.fields!r})"


def _check_fields(fields: dict[str, Any]) -> None:
    """Reject a field called ``kind``: the kind is fixed when the shape is made."""
    if "kind" in fields:
        raise ValueError("a Shape's kind is its second argument, not a field")
