"""How far each motion travels to reach each vertex: the water's radius, the clock hand's
angle, the sweeping line's offset, the rising water's level.

Drawing data. A heuristic decides with exact predicates (:mod:`geometry.predicates`) and
its log holds its arguments and its pick; from those, the storyboard (for the animation)
and the exercises (for their words) compute these floats here. Each reach lists the
candidates as the motion reaches them, ``(label, value)``: by value, ties by the order
counter-clockwise after the motion's origin, and the heuristic's pick where the rule puts
it — first, or last for the rising water (the last candidate to get wet).

Examples
--------
>>> where = {"A": (1.6, 8.0), "B": (1.0, 4.5), "C": (9.0, 2.0), "D": (3.0, 6.5),
...          "E": (4.6, 4.1)}
>>> order = list(where)
>>> spreading(where, order, "B", ["D", "E"], "D")  # doctest: +NORMALIZE_WHITESPACE
[('D', 2.8284271247461903), ('E', 3.6221540552549665)]
>>> rising(where, order, ("A", "C"), "B", ["D", "E"], "E")  # doctest: +NORMALIZE_WHITESPACE
[('D', 0.28341088128954894), ('E', 1.1399415447424075)]
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from story.refs import arg, ref, ref_list, result_ref
from tracing import Event

Point = Sequence[float]
Reach = list[tuple[str, float]]


def distance(p: Point, q: Point) -> float:
    return math.hypot(q[0] - p[0], q[1] - p[1])


def side_normal(direction: Point, through: Point, point: Point) -> tuple[float, float]:
    """Unit normal of the line through `through` along `direction`, pointing to `point`'s side.

    >>> side_normal([0.0, 1.0], [1.0, 4.5], [3.0, 6.5])
    (1.0, 0.0)
    >>> [round(v, 4) for v in side_normal([7.4, -6.0], [1.0, 4.5], [4.6, 4.1])]  # towards AC
    [0.6298, 0.7768]
    """
    dx, dy = direction
    norm = math.hypot(dx, dy)
    nx, ny = dy / norm, -dx / norm
    if nx * (point[0] - through[0]) + ny * (point[1] - through[1]) < 0:
        nx, ny = -nx, -ny
    return (nx + 0.0, ny + 0.0)


def heading(p: Point, q: Point) -> float:
    """Direction from p to q, in degrees."""
    return math.degrees(math.atan2(q[1] - p[1], q[0] - p[0]))


def turned(centre: Point, start: Point, p: Point) -> float:
    """The angle (degrees, unsigned) a hand at ``centre`` set to ``start`` turns to reach p."""
    return abs((heading(centre, p) - heading(centre, start) + 180.0) % 360.0 - 180.0)


def offset(through: Point, direction: Point, p: Point) -> float:
    """How far the line through ``through`` along ``direction`` moves to reach p."""
    dx, dy = direction
    return abs(dx * (p[1] - through[1]) - dy * (p[0] - through[0])) / math.hypot(dx, dy)


def line_distance(a: Point, c: Point, p: Point) -> float:
    """Distance from p to the line AC."""
    cross = (c[0] - a[0]) * (p[1] - a[1]) - (c[1] - a[1]) * (p[0] - a[0])
    return abs(cross) / distance(a, c)


def _ordered(values: dict[str, float], where: Mapping[str, Point], order: Sequence[str],
             origin: str, pick: str, pick_last: bool = False) -> Reach:
    """Candidates as the motion reaches them: the pick first (or last), then by value, then
    as the heuristics break ties — nearer the origin, then counter-clockwise after it."""
    n, start = len(order), order.index(origin)

    def key(label: str) -> tuple[bool, float, float, int]:
        near, ccw = distance(where[origin], where[label]), (order.index(label) - start) % n
        if pick_last:  # what stays dry longest comes last: the tie rule runs backwards
            return (label == pick, values[label], -near, -ccw)
        return (label != pick, values[label], near, ccw)

    return [(label, values[label]) for label in sorted(values, key=key)]


def spreading(where: Mapping[str, Point], order: Sequence[str], b: str,
              candidates: Sequence[str], pick: str) -> Reach:
    """Water spilled at B: the radius at which it wets each candidate."""
    return _ordered({v: distance(where[b], where[v]) for v in candidates}, where, order, b,
                    pick)


def turning(where: Mapping[str, Point], order: Sequence[str], centre: str, start: str,
            candidates: Sequence[str], pick: str) -> Reach:
    """A clock hand at ``centre`` set to ``start``: the angle at which it passes each."""
    values = {v: turned(where[centre], where[start], where[v]) for v in candidates}
    return _ordered(values, where, order, centre, pick)


def sweeping(where: Mapping[str, Point], order: Sequence[str], b: str, direction: Point,
             candidates: Sequence[str], pick: str) -> Reach:
    """A line through B along ``direction``: how far it moves to touch each candidate."""
    values = {v: offset(where[b], direction, where[v]) for v in candidates}
    return _ordered(values, where, order, b, pick)


def rising(where: Mapping[str, Point], order: Sequence[str], shore: tuple[str, str], b: str,
           candidates: Sequence[str], pick: str) -> Reach:
    """Water rising from the shore AC towards B: the level at which each candidate goes
    under; the pick, the last dry one, last."""
    a, c = (where[x] for x in shore)
    values = {v: line_distance(a, c, where[v]) for v in candidates}
    return _ordered(values, where, order, b, pick, pick_last=True)


# --- from the log --------------------------------------------------------------------------------


def reach_of(call: Event, ret: Event, where: Mapping[str, Point], order: Sequence[str],
             state_of: Callable[[str], dict[str, Any]]) -> Reach | None:
    """The reach of a heuristic's step from its call and return, or None for another call.

    ``where`` maps labels to points (``order``: the labels counter-clockwise), and
    ``state_of(key)`` gives the logged state of an object (the triangle T).
    """
    pick = result_ref(ret) if isinstance(ret.result, dict) else None
    if pick is None:
        return None
    if call.name == "nearest_to":
        return spreading(where, order, ref(call, "b"), ref_list(call, "candidates"), pick)
    if call.name == "first_hit_rotating":
        return turning(where, order, ref(call, "centre"), ref(call, "start"),
                       ref_list(call, "candidates"), pick)
    if call.name == "first_hit_sweeping":
        return sweeping(where, order, ref(call, "b"), arg(call, "direction"),
                        ref_list(call, "candidates"), pick)
    if call.name == "last_dry":
        a, b, c = state_of(ref(call, "t"))["labels"]
        return rising(where, order, (a, c), b, ref_list(call, "candidates"), pick)
    return None
