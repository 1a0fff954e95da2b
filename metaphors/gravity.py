"""Gravity (Forišek–Steinová): the polygon turns so that gravity points down, a ball on a rubber
band hangs from the reflex vertex V, falls, slides down an edge to X; the band snags the first
vertex Y it sweeps. And divide and conquer's split: the two halves tinted, triangles filled in.

Every number comes from the log: the turn (``turn_picture``), the hit point, the ball's end
vertex, the band's final shape (``[V, X]`` straight or ``[V, Y, X]`` bent). Turning the picture
turns the board's frame too, so :meth:`Board.at` keeps mapping polygon points onto the turned
picture; after the verdict the picture turns back upright (a following step of divide and
conquer starts from the plain polygon, as the panel shows it).
"""

from __future__ import annotations

import math

import numpy as np
from manim import (
    DOWN,
    UP,
    Arrow,
    Circle,
    Dot,
    FadeIn,
    FadeOut,
    Flash,
    Indicate,
    Transform,
    VGroup,
    VMobject,
    rush_into,
)
from manim import Polygon as MPolygon

from metaphors import basics
from metaphors.layout import METAPHOR
from metaphors.tags import tag
from rendering.turn import Turn
from rendering.typeset import FlatText, text

#: board objects that stay put on screen when the polygon turns (keys of ``board.objects``)
FIXED = ("gravity", "plate", "counter")  # and every slice on the plate (fruit)
#: things that keep their size and stay upright when the picture turns and zooms
_UPRIGHT = (FlatText, Circle)


# --- helpers -------------------------------------------------------------------------------------


def _again(board, beat, *anims, run_time: float = 1.0) -> None:
    """A further play within a beat (the panel, roles and subtitle are already up to date)."""
    board.scene.play(*anims, run_time=max(0.1, run_time * beat.pace))


def _fit_zoom(board, angle: float) -> float:
    """Largest zoom ≤ 1 that keeps the polygon turned by ``angle`` inside the metaphor's box."""
    turned = board.frame.turned(angle, METAPHOR.center, 1.0)
    pts = np.array(turned.many(board.polygon.points))[:, :2] - np.array(METAPHOR.center)
    reach = np.abs(pts).max(axis=0)
    return float(min(1.0, METAPHOR.width / 2 / max(reach[0], 1e-9),
                     METAPHOR.height / 2 / max(reach[1], 1e-9)))


def _movers(board) -> list:
    """What turns with the polygon: outline, vertices, metaphor objects (not the fixed ones)."""
    fixed = [board.objects.get(k) for k in FIXED]
    fixed += [m for k, m in board.objects.items() if k.startswith("slice:")]
    return [m for m in board.left_group().submobjects if not any(m is f for f in fixed)]


def turn_to(board, angle: float) -> list:
    """Animations turning the picture to ``angle`` degrees (absolute; 0 is upright), and the
    board's frame with it. Labels, dots and the ball keep their size and stay upright."""
    old = board.frame
    new = old.turned(angle, METAPHOR.center, _fit_zoom(board, angle))
    delta = new.angle - old.angle
    k = new.zoom / old.zoom
    if abs(delta) < 1e-9 and abs(k - 1) < 1e-9:
        return []
    turns = {id(m): Turn(m, math.radians(delta), METAPHOR.center, k, upright=_UPRIGHT)
             for m in _movers(board)}
    line, mark = board.objects.get("claim"), board.objects.get("verdict")
    if line is not None and mark is not None and id(mark) in turns:  # the ✓ stays above
        above = turns[id(line)].end_centre(line) + (0.15 + mark.height / 2) * UP
        turns[id(mark)].shift = above - turns[id(mark)].end_centre(mark)
    board.frame = new
    return list(turns.values())


def _called(beat) -> str | None:
    """The vertex the call runs on (the ball hangs there)."""
    return next((k for k, role in beat.roles.items() if role == "called"), None)


def _ball(board, at):
    theme = board.theme
    return tag(Dot(at, radius=0.12, color=theme.ball, stroke_color=theme.ink, stroke_width=1.5),
               "argument", "ball")


def _band(board, corners):
    """The rubber band through scene points (a polyline)."""
    band = VMobject(stroke_color=board.theme.band, stroke_width=board.theme.stroke)
    band.set_points_as_corners([np.asarray(c, dtype=float) for c in corners])
    return tag(band, "argument", "band")


def _gravity_arrow(board):
    theme = board.theme
    left = METAPHOR.x - METAPHOR.width / 2 - 0.5
    top = METAPHOR.y + METAPHOR.height / 2 - 0.1
    arrow = Arrow((left, top, 0), (left, top - 1.0, 0), buff=0, color=theme.gravity,
                  stroke_width=4, max_tip_length_to_length_ratio=0.3)
    g = text("g", font=theme.font, size=theme.label_size + 4, slant="ITALIC",
             colour=theme.gravity).next_to(arrow, DOWN, buff=0.08)
    return tag(VGroup(arrow, g), None, "gravity")


# --- the gravity heuristic -----------------------------------------------------------------------


def gravity_turn(board, beat) -> None:
    """The polygon turns by ``turn_picture`` degrees so that gravity points down on screen."""
    theme = board.theme
    arrow = _gravity_arrow(board)
    anims = [FadeIn(arrow, shift=0.3 * DOWN)]
    active = board.objects.get(f"piece:{beat.data.get('polygon')}")
    if active is not None:  # divide and conquer: the piece being worked on lights up
        anims.append(tag(active, "called").animate.set_fill(opacity=theme.active_opacity)
                     .set_stroke(theme.called, width=theme.stroke * 2.5, opacity=1.0))
    board.play(beat, *anims, run_time=0.8)
    board.keep("gravity", arrow)
    turn = turn_to(board, beat.data["turn_picture"])
    if turn:
        _again(board, beat, *turn, run_time=2.0)


def drop(board, beat) -> None:
    """A ball hangs from V on its band, falls straight down and hits the boundary."""
    v = board.vertex(beat.data.get("vertex") or _called(beat))
    hit = board.at(beat.data["hit"])
    ball, band = _ball(board, v), _band(board, [v, v])
    board.keep("band", band)
    board.keep("ball", ball)
    board.play(beat, FadeIn(ball, scale=0.5), run_time=0.6)
    board.scene.add(band)
    board.scene.bring_to_front(ball)
    _again(board, beat, ball.animate(rate_func=rush_into).move_to(hit),
           Transform(band, _band(board, [v, hit]), rate_func=rush_into), run_time=1.0)
    mark = tag(Circle(radius=0.2, color=board.theme.argument, stroke_width=board.theme.stroke)
               .move_to(hit), "result", "hit")
    board.keep("hit", mark)
    board.scene.bring_to_front(ball)
    _again(board, beat, FadeIn(mark), Flash(hit, color=board.theme.argument, flash_radius=0.35),
           run_time=0.5)


def _scene_point(mobject) -> np.ndarray:
    return mobject.get_center()


def slide(board, beat) -> None:
    """The ball slides down the edge it hit to its lower end X; the band stretches behind it."""
    ball, band = board.objects.get("ball"), board.objects.get("band")
    states = beat.data["states"]
    if ball is None or not states:  # it landed on a vertex: nothing to slide
        board.play(beat, run_time=0.8)
        return
    x = board.at(states[-1]["at"])
    v = band.get_start()
    board.play(beat, ball.animate(rate_func=rush_into).move_to(x),
               Transform(band, _band(board, [v, x]), rate_func=rush_into), run_time=1.2)


def snag(board, beat) -> None:
    """The band swept the triangle V–hit–X: it snags the first vertex Y there, or stays
    straight."""
    theme = board.theme
    band = board.objects.get("band")
    states = beat.data["states"]
    if not states:  # the ball landed on a vertex: the band never moved off the drop line
        if band is None:
            board.play(beat, run_time=0.8)
        else:
            board.play(beat, Indicate(band, color=theme.result, scale_factor=1.0), run_time=0.8)
        return
    corners = [board.at(p) for p in states[-1]["points"]]
    hit = board.objects.get("hit")
    swept = None
    if hit is not None and len(corners) >= 2:
        swept = tag(MPolygon(corners[0], _scene_point(hit), corners[-1], stroke_width=0,
                             fill_color=theme.band, fill_opacity=0.18), "argument", "swept")
        swept.set_z_index(-1)
        board.play(beat, FadeIn(swept), run_time=0.7)
    bent = _band(board, corners)
    if band is None:
        board.keep("band", bent)
        _again(board, beat, FadeIn(bent), run_time=0.8)
    elif len(corners) == 3:
        y = corners[1]
        _again(board, beat, Transform(band, bent), Flash(y, color=theme.result, flash_radius=0.4),
               run_time=1.2)
    else:
        _again(board, beat, Transform(band, bent), Indicate(band, color=theme.result,
                                                            scale_factor=1.0), run_time=1.0)
    if swept is not None:
        _again(board, beat, FadeOut(swept), run_time=0.4)


def verdict(board, beat) -> None:
    """The shared verdict; then ball, band and impact mark go and the picture turns back."""
    basics.verdict(board, beat)
    gone = board.drop("ball", "band", "hit", "gravity")
    if gone:
        _again(board, beat, *gone, run_time=0.5)
    turn = turn_to(board, 0.0)
    if turn:
        _again(board, beat, *turn, run_time=1.5)


# --- divide and conquer ---------------------------------------------------------------------------


def _tint_colour(board, labels: list[str], avoid: set[str]) -> str:
    """A palette colour for a new piece: unlike its neighbours (tints sharing an edge), then the
    least used; ties by palette order."""
    palette = board.theme.pieces
    tints = [m for k, m in board.objects.items() if k.startswith(("piece:", "triangle:"))]
    near = {m.trex_colour for m in tints if len(set(m.trex_labels) & set(labels)) >= 2}
    used = [m.trex_colour for m in tints]
    return min(palette, key=lambda c: (c in avoid, c in near, used.count(c), palette.index(c)))


def _tint(board, points, labels, colour: str, done: bool):
    theme = board.theme
    role, name = ("result", "triangle:") if done else ("idle", "piece:")
    mobject = MPolygon(*[board.at(p) for p in points], stroke_width=0, fill_color=colour,
                       fill_opacity=theme.done_opacity if done else theme.piece_opacity)
    mobject.set_z_index(-1)
    mobject.trex_colour, mobject.trex_labels = colour, list(labels)
    return tag(mobject, role, name + "".join(labels))


def split(board, beat) -> None:
    """The verified diagonal becomes an edge; the two halves get their own tints, and a half
    that is a triangle is finished: it fills in."""
    theme = board.theme
    anims = []
    line = board.objects.pop("claim", None)
    if line is not None:
        k = sum(1 for key in board.objects if key.startswith("diagonal:"))
        board.keep(f"diagonal:{k}", tag(line, "idle", line.name))
        anims.append(line.animate.set_color(theme.ink).set_stroke(width=theme.stroke))
    anims += board.drop("verdict", f"piece:{beat.data.get('parent')}")
    if board.shape.get_fill_opacity() > 0:
        anims.append(board.shape.animate.set_fill(opacity=0))
    chosen: set[str] = set()
    for piece, points, labels in zip(beat.data["pieces"], beat.data.get("points", []),
                                     beat.data.get("labels", []), strict=False):
        done = len(points) == 3
        colour = _tint_colour(board, labels, chosen)
        chosen.add(colour)
        tint = _tint(board, points, labels, colour, done)
        board.keep(f"triangle:{''.join(labels)}" if done else f"piece:{piece}", tint)
        anims.append(FadeIn(tint))
    board.play(beat, *anims, run_time=1.2)
