"""The generic panel: how a log plays when no metaphor is known for it (a heuristic of one's own).

The storyboard gives such a run two generic beats besides the shared ones (polygon, pick,
triangle, candidates, claim, verdict):

- ``call``: a traced function of the user's returned; the panel shows its call line, the
  vertices (and shapes) it used are coloured by role;
- ``shape``: a shape entered, changed or exited (``key``, ``event`` and the ``state``
  from the log). Points (``at``), segments (``points`` or ``ends``), polygons
  (``points``), circles (``center``, ``radius``), lines (``through`` + ``direction``, or two
  ``points``), rays (``origin`` + ``heading`` in degrees, or ``origin`` + ``through``) and
  texts (``at``, ``text``) are drawn in polygon coordinates, coloured by their role (the
  state's ``role`` if it names one, else amber: in play). Other kinds play as a caption.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
from manim import Circle, Create, Dot, FadeIn, Line, Transform, VGroup, VMobject
from manim import Polygon as MPolygon

from metaphors.board import Board, Playable
from metaphors.layout import METAPHOR
from metaphors.performing import Performances, act, performs
from metaphors.tags import role_of, tag
from rendering import typeset
from story.beats import Call, ShapeChange
from story.roles import ROLES
from story.storyboard import Reading
from tracing import JSON

#: Kinds the generic performer draws.
DRAWN_KINDS = ("point", "segment", "polygon", "circle", "line", "ray", "text")
_PREFIX = "shape:"


# --- performers --------------------------------------------------------------------------------


def call(board: Board, beat: Call) -> None:
    """A user's traced function returned: call line, roles (vertices and drawn shapes)."""
    board.play(beat, *_recolour_shapes(board, beat.roles), run_time=0.8)


def shape(board: Board, beat: ShapeChange) -> None:
    """A shape appears (drawn), changes (morphs) or goes (fades)."""
    key, event, state = beat.key, beat.event, beat.state
    name = _PREFIX + key
    old = board.objects.get(name)
    anims = _recolour_shapes(board, {k: r for k, r in beat.roles.items() if k != key})
    if event == "exit" or state is None:
        anims += board.drop(name)
        board.play(beat, *anims, run_time=0.5)
        return
    role = beat.roles.get(key, "argument")
    new = mobject_for(board, state, role if role in ROLES else "argument", key)
    if new is None:  # nothing to draw (unknown kind, or fields it cannot read): caption only
        anims += board.drop(name)
    elif old is None:
        board.keep(name, new)
        anims.append(Create(new) if _is_stroke(state) else FadeIn(new))
    else:
        anims.append(Transform(old, new))
        tag(old, role_of(new))
    board.play(beat, *anims, run_time=0.8 if old is None else 1.0)


def _is_stroke(state: Mapping[str, JSON]) -> bool:
    return state.get("kind") in ("segment", "line", "ray", "polygon", "circle")


def _recolour_shapes(board: Board, roles: Mapping[str, str]) -> list[Playable]:
    anims = []
    for key, role in roles.items():
        mobject = board.objects.get(_PREFIX + key)
        if mobject is None or role not in ROLES or role_of(mobject) == role:
            continue
        anims.append(tag(mobject, role).animate.set_color(board.theme.role_colour(role)))
    return anims


# --- drawing a state ---------------------------------------------------------------------------


def mobject_for(board: Board, state: Mapping[str, JSON], role: str, key: str = ""
                ) -> VMobject | None:
    """The mobject of a shape's state in the board's coordinates, or None if it has none (the
    drawing reads the log's fields as it finds them: one it cannot read draws nothing)."""
    kind = state.get("kind")
    if kind not in DRAWN_KINDS:
        return None
    try:
        mobject = _DRAW[kind](board, dict(state), board.theme.role_colour(role))
    except (KeyError, TypeError, ValueError, IndexError, ZeroDivisionError):
        return None
    if mobject is None:
        return None
    return tag(mobject, role, f"{_PREFIX}{key}")


def _xy(p: Any) -> tuple[float, float]:
    x, y = float(p[0]), float(p[1])
    if not (math.isfinite(x) and math.isfinite(y)):
        raise ValueError("not a finite point")
    return x, y


def _point(board: Board, state: dict[str, Any], colour: str) -> Dot | VGroup:
    at = board.at(_xy(state["at"]))
    dot = Dot(at, radius=board.theme.dot_radius * 1.6, color=colour)
    label = state.get("label")
    if not label:
        return dot
    text = typeset.text(str(label), font=board.theme.font, size=board.theme.label_size,
                         colour=colour)
    return VGroup(dot, text.next_to(dot, direction=np.array([1.0, 1.0, 0.0]), buff=0.08))


def _segment(board: Board, state: dict[str, Any], colour: str) -> Dot | Line:
    a, b = state["points"] if "points" in state else state["ends"]
    start, end = board.at(_xy(a)), board.at(_xy(b))
    if np.allclose(start, end):
        return Dot(start, radius=board.theme.dot_radius, color=colour)
    return Line(start, end, color=colour, stroke_width=board.theme.stroke * 1.3)


def _polygon(board: Board, state: dict[str, Any], colour: str) -> MPolygon | None:
    corners = [board.at(_xy(p)) for p in state["points"]]
    if len(corners) < 3:
        return None
    return MPolygon(*corners, color=colour, stroke_width=board.theme.stroke,
                    fill_color=colour, fill_opacity=0.18)


def _circle(board: Board, state: dict[str, Any], colour: str) -> Circle | None:
    radius = float(state["radius"])
    if not math.isfinite(radius) or radius < 0:
        return None
    return Circle(radius=max(board.length(radius), 1e-3), color=colour,
                  stroke_width=board.theme.stroke, fill_color=colour,
                  fill_opacity=0.15).move_to(board.at(_xy(state["center"])))


def _line(board: Board, state: dict[str, Any], colour: str) -> Line | None:
    if "points" in state:
        a, b = (_xy(p) for p in state["points"])
    else:
        a = _xy(state["through"])
        dx, dy = _xy(state["direction"])
        b = (a[0] + dx, a[1] + dy)
    ends = clip_to_box(board.at(a), board.at(b), both_ways=True)
    return None if ends is None else Line(*ends, color=colour,
                                          stroke_width=board.theme.stroke * 1.3)


def _ray(board: Board, state: dict[str, Any], colour: str) -> Line | None:
    origin = _xy(state["origin"])
    if "through" in state:
        towards = _xy(state["through"])
    else:
        heading = math.radians(float(state["heading"]) + float(state.get("angle", 0.0)))
        towards = (origin[0] + math.cos(heading), origin[1] + math.sin(heading))
    ends = clip_to_box(board.at(origin), board.at(towards), both_ways=False)
    return None if ends is None else Line(*ends, color=colour,
                                          stroke_width=board.theme.stroke * 1.3)


def _text(board: Board, state: dict[str, Any], colour: str) -> VMobject:
    return typeset.text(str(state["text"]), font=board.theme.font, size=board.theme.label_size,
                        colour=colour).move_to(board.at(_xy(state["at"])))


#: how each drawn kind is drawn: (board, state, colour) → its mobject, or None
_DRAW: dict[str, Callable[[Board, dict[str, Any], str], VMobject | None]] = {
    "point": _point, "segment": _segment, "polygon": _polygon, "circle": _circle,
    "line": _line, "ray": _ray, "text": _text}


def clip_to_box(a, b, both_ways: bool, box=METAPHOR):
    """The part of the line a→b (a ray from a if not ``both_ways``) inside the box (scene
    coordinates), as two points, or None.

    >>> [p.tolist() for p in clip_to_box(np.array([0., 0, 0]), np.array([1., 0, 0]), True,
    ...                                  box=type(METAPHOR)(0, 0, 4, 2))]
    [[-2.0, 0.0, 0.0], [2.0, 0.0, 0.0]]
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    d = b - a
    low, high = (-math.inf if both_ways else 0.0), math.inf
    for axis, (centre, size) in enumerate(((box.x, box.width), (box.y, box.height))):
        lo, hi = centre - size / 2, centre + size / 2
        if abs(d[axis]) < 1e-12:
            if not lo <= a[axis] <= hi:
                return None
            continue
        t1, t2 = (lo - a[axis]) / d[axis], (hi - a[axis]) / d[axis]
        low, high = max(low, min(t1, t2)), min(high, max(t1, t2))
    if not (math.isfinite(low) and math.isfinite(high)) or high - low < 1e-9:
        return None
    return a + low * d, a + high * d


READS: Mapping[str, Reading] = {}  # the storyboard reads a user's calls and shapes itself
PERFORMS: Performances = performs(act(Call, call), act(ShapeChange, shape))
