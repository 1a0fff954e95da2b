"""Checking a user's answer: two vertices of the polygon it was handed, or a one-line refusal.

A heuristic of one's own may answer with a :class:`~geometry.frame.Diagonal` or a pair of
vertices given as indices (``polygon.points[i]``), labels (``"B"``) or
:class:`~geometry.polygon.Vertex` objects. Anything else is a :class:`UserHeuristicError`
whose ``way`` says what kind of wrong answer it was (a hunt keeps shrinking a polygon while
the answer stays wrong the same way).
"""

from __future__ import annotations

import operator
from typing import Any

from geometry.frame import Diagonal
from geometry.polygon import Polygon, Vertex
from usercode.errors import UserHeuristicError

__all__ = ["claimed", "endpoints"]


def endpoints(polygon: Polygon, answer: Any, name: str = "the heuristic") -> tuple[Vertex, Vertex]:
    """The two vertices of an answer: a Diagonal, or a pair of indices, labels or Vertex objects.

    >>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
    >>> [v.label for v in endpoints(p, ("B", 4))]
    ['B', 'E']
    >>> endpoints(p, ("B", "Q"), "mine")
    Traceback (most recent call last):
    ...
    usercode.errors.UserHeuristicError: mine returned ('B', 'Q'): 'Q' is not a vertex label (A … E)
    """
    pair: Any = (answer.u, answer.v) if isinstance(answer, Diagonal) else answer
    try:
        items = list(pair) if not isinstance(pair, str | bytes | dict) else None
    except TypeError:
        items = None
    if items is None or len(items) != 2:
        raise UserHeuristicError(
            f"{name} returned {_short(answer)}: expected a Diagonal or a pair of vertices "
            "(indices, labels or Vertex objects)", way="answer: not a pair")
    return _vertex(polygon, items[0], answer, name), _vertex(polygon, items[1], answer, name)


def claimed(events, key: str) -> bool:
    """Whether ``events`` hold the return of a ``claim`` of the diagonal ``key`` (``"BD"``):
    the user's function called ``claim()`` itself, so the log has its claim already."""
    return any(e.kind == "return" and e.name == "claim" and e.result == {"ref": key}
               for e in events)


def _vertex(polygon: Polygon, item: Any, answer: Any, name: str) -> Vertex:
    """One end of the answer as a vertex of ``polygon``: a Vertex of it, a label, an index."""
    if isinstance(item, Vertex):
        return _own_vertex(polygon, item, answer, name)
    if isinstance(item, str):
        if item in polygon.labels:
            return polygon.vertex(polygon.labels.index(item))
        raise UserHeuristicError(
            f"{name} returned {_short(answer)}: {item!r} is not a vertex label "
            f"({polygon.labels[0]} … {polygon.labels[-1]})", way="answer: not a label")
    index = None if isinstance(item, bool) else _index(item)  # True is no vertex index
    if index is not None:
        if 0 <= index < polygon.n:
            return polygon.vertex(index)
        raise UserHeuristicError(
            f"{name} returned {_short(answer)}: index {index} is out of range 0…{polygon.n - 1}",
            way="answer: index out of range")
    raise UserHeuristicError(
        f"{name} returned {_short(answer)}: {_short(item)} is not a vertex "
        "(give an index, a label or a Vertex)", way="answer: not a vertex")


def _own_vertex(polygon: Polygon, item: Vertex, answer: Any, name: str) -> Vertex:
    """``item`` if it is a vertex of this polygon (same index, same point), else one line."""
    if 0 <= item.index < polygon.n and polygon.points[item.index] == item.point:
        return polygon.vertex(item.index)
    raise UserHeuristicError(
        f"{name} returned {_short(answer)}: vertex {item.label} is not a vertex of this polygon",
        way="answer: a vertex of another polygon")


def _index(item: Any) -> int | None:
    """``item`` as an index (an int, a numpy integer …), None if it is none."""
    try:
        return operator.index(item)
    except TypeError:
        return None


def _short(value: Any) -> str:
    """``repr(value)`` on one line, at most 60 characters (a message stays one line)."""
    text = " ".join(repr(value).split())
    return text if len(text) <= 60 else text[:57] + "..."
