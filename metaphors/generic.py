"""The generic panel: how a log plays when no metaphor is known for it (a heuristic of one's own).

The storyboard gives such a run two generic beats besides the shared ones (polygon, pick,
triangle, candidates, claim, verdict):

- ``call``: a traced function of the user's returned; the panel shows its call line, the
  vertices (and shapes) it used are coloured by role;
- ``shape``: a shape entered, changed or exited (``data``: ``key``, ``event`` and the
  ``state`` from the log). Points (``at``), segments (``points`` or ``ends``), polygons
  (``points``), circles (``center``, ``radius``), lines (``through`` + ``direction``, or two
  ``points``), rays (``origin`` + ``heading`` in degrees, or ``origin`` + ``through``) and
  texts (``at``, ``text``) are drawn in polygon coordinates, coloured by their role (the
  state's ``role`` if it names one, else amber: in play). Other kinds play as a caption.

:func:`scene_for_heuristic` makes the Scene that ``trex render`` renders for
``file.py:function``; :func:`board_for` builds the board a log plays on (the panel shows the
user's own source, carried in the log's meta).
"""

from __future__ import annotations

import math

import numpy as np
from manim import Circle, Create, Dot, FadeIn, Line, Scene, Transform, VGroup
from manim import Polygon as MPolygon

from metaphors.board import Board
from metaphors.layout import METAPHOR
from metaphors.tags import tag
from rendering import typeset
from story.roles import ROLES

#: Kinds the generic performer draws.
DRAWN_KINDS = ("point", "segment", "polygon", "circle", "line", "ray", "text")
_PREFIX = "shape:"


# --- the board ---------------------------------------------------------------------------------


def board_for(scene: Scene, log, beats, title: str, theme) -> Board:
    """The board a log plays on, as :class:`~metaphors.scene.TraceScene` builds it (the first
    beat's polygon, the scene's ``metaphor_box``), plus the log's own ``code`` (a user's source,
    ``[[line, text], …]``) in the panel when it carries one, and the title fitted to the frame."""
    first = beats[0]
    board = Board(scene, first.data["points"], first.data["labels"], log.meta.get("shown"),
                  title, theme, getattr(scene, "metaphor_box", METAPHOR))
    code = log.meta.get("code")
    if code:
        show_code(board.panel, code)
    if board.title.width > 13.4:
        board.title.scale_to_fit_width(13.4)
    return board


def show_code(panel, code) -> None:
    """Put the given (line number, text) rows in the panel's code block (before it is shown)."""
    panel.code_lines = tuple((int(number), str(text)) for number, text in code)
    panel.code = panel._code_block()


# --- performers --------------------------------------------------------------------------------


def call(board, beat) -> None:
    """A user's traced function returned: call line, roles (vertices and drawn shapes)."""
    board.play(beat, *_recolour_shapes(board, beat.roles), run_time=0.8)


def shape(board, beat) -> None:
    """A shape appears (drawn), changes (morphs) or goes (fades)."""
    key, event, state = beat.data["key"], beat.data["event"], beat.data.get("state")
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
        tag(old, new.trex_role)
    board.play(beat, *anims, run_time=0.8 if old is None else 1.0)


def _is_stroke(state: dict) -> bool:
    return state.get("kind") in ("segment", "line", "ray", "polygon", "circle")


def _recolour_shapes(board, roles: dict[str, str]) -> list:
    anims = []
    for key, role in roles.items():
        mobject = board.objects.get(_PREFIX + key)
        if mobject is None or role not in ROLES or getattr(mobject, "trex_role", None) == role:
            continue
        anims.append(tag(mobject, role).animate.set_color(board.theme.role_colour(role)))
    return anims


# --- drawing a state ---------------------------------------------------------------------------


def mobject_for(board, state: dict, role: str, key: str = ""):
    """The mobject of a shape's state in the board's coordinates, or None if it has none."""
    kind = state.get("kind")
    if kind not in DRAWN_KINDS:
        return None
    try:
        mobject = _DRAW[kind](board, state, board.theme.role_colour(role))
    except (KeyError, TypeError, ValueError, IndexError, ZeroDivisionError):
        return None
    if mobject is None:
        return None
    return tag(mobject, role, f"{_PREFIX}{key}")


def _xy(p) -> tuple[float, float]:
    x, y = float(p[0]), float(p[1])
    if not (math.isfinite(x) and math.isfinite(y)):
        raise ValueError("not a finite point")
    return x, y


def _point(board, state, colour):
    at = board.at(_xy(state["at"]))
    dot = Dot(at, radius=board.theme.dot_radius * 1.6, color=colour)
    label = state.get("label")
    if not label:
        return dot
    text = typeset.text(str(label), font=board.theme.font, size=board.theme.label_size,
                         colour=colour)
    return VGroup(dot, text.next_to(dot, direction=np.array([1.0, 1.0, 0.0]), buff=0.08))


def _segment(board, state, colour):
    a, b = state["points"] if "points" in state else state["ends"]
    start, end = board.at(_xy(a)), board.at(_xy(b))
    if np.allclose(start, end):
        return Dot(start, radius=board.theme.dot_radius, color=colour)
    return Line(start, end, color=colour, stroke_width=board.theme.stroke * 1.3)


def _polygon(board, state, colour):
    corners = [board.at(_xy(p)) for p in state["points"]]
    if len(corners) < 3:
        return None
    return MPolygon(*corners, color=colour, stroke_width=board.theme.stroke,
                    fill_color=colour, fill_opacity=0.18)


def _circle(board, state, colour):
    radius = float(state["radius"])
    if not math.isfinite(radius) or radius < 0:
        return None
    return Circle(radius=max(board.length(radius), 1e-3), color=colour,
                  stroke_width=board.theme.stroke, fill_color=colour,
                  fill_opacity=0.15).move_to(board.at(_xy(state["center"])))


def _line(board, state, colour):
    if "points" in state:
        a, b = (_xy(p) for p in state["points"])
    else:
        a = _xy(state["through"])
        dx, dy = _xy(state["direction"])
        b = (a[0] + dx, a[1] + dy)
    ends = clip_to_box(board.at(a), board.at(b), both_ways=True)
    return None if ends is None else Line(*ends, color=colour,
                                          stroke_width=board.theme.stroke * 1.3)


def _ray(board, state, colour):
    origin = _xy(state["origin"])
    if "through" in state:
        towards = _xy(state["through"])
    else:
        heading = math.radians(float(state["heading"]) + float(state.get("angle", 0.0)))
        towards = (origin[0] + math.cos(heading), origin[1] + math.sin(heading))
    ends = clip_to_box(board.at(origin), board.at(towards), both_ways=False)
    return None if ends is None else Line(*ends, color=colour,
                                          stroke_width=board.theme.stroke * 1.3)


def _text(board, state, colour):
    return typeset.text(str(state["text"]), font=board.theme.font, size=board.theme.label_size,
                        colour=colour).move_to(board.at(_xy(state["at"])))


_DRAW = {"point": _point, "segment": _segment, "polygon": _polygon, "circle": _circle,
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


# --- the scene of a user's heuristic --------------------------------------------------------------


def scene_for_heuristic(spec: str) -> type[Scene]:
    """The Scene class for ``path/to/file.py:name``.

    If ``name`` is a Scene class defined in the file, that class; otherwise ``name`` is a
    heuristic of one's own (see :mod:`geometry.user_heuristics`), loaded now so that a bad
    spec fails here, and the class plays its run on the polygon it is handed (plain
    ``manim``: ``TREX_POLYGON``; default: the counterexample) with the generic panel. Raises
    :class:`geometry.user_heuristics.UserHeuristicError` (a ValueError, one-line message).
    """
    from geometry.user_heuristics import as_heuristic, load_attribute

    path, name, value = load_attribute(spec)
    if isinstance(value, type) and issubclass(value, Scene):
        return value
    return heuristic_scene(as_heuristic(spec, path, name, value))


def heuristic_scene(heuristic) -> type[Scene]:
    """A TraceScene subclass that plays a loaded user heuristic's run."""
    from metaphors.scene import TraceScene

    return type(f"Heuristic_{heuristic.name}", (GenericScene, TraceScene), {
        "algorithm": heuristic.spec,
        "heuristic": None,
        "polygon": "counterexample",
        "title": heuristic.title,
        "__module__": __name__,
        "__doc__": f"The run of {heuristic.spec}, played with the generic panel.",
    })


class GenericScene:
    """Mixed into a TraceScene: plays its log on :func:`board_for` (the user's source shown);
    keeps the beats and the board (``trex_beats``, ``trex_board``) for tests."""

    def play_log(self, log, title: str) -> Board:
        from metaphors.actions import perform

        beats = self.beats(log)
        board = board_for(self, log, beats, title, self.theme)
        self.trex_beats, self.trex_board = beats, board
        for beat in beats:
            perform(board, beat)
        return board
