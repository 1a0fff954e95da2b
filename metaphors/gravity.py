"""Gravity (Forišek–Steinová): the polygon turns so that gravity points down, a ball on a rubber
band hangs from the reflex vertex V, falls, slides down an edge to X; the band snags the first
vertex Y it sweeps.

Every number comes from the log: the turn (``turn_picture``), the hit point, the ball's end
vertex, the band's final shape (``[V, X]`` straight or ``[V, Y, X]`` bent). The picture turns
as :mod:`metaphors.picture` turns it, and turns back after the verdict.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import Any

import numpy as np
from manim import (
    DOWN,
    Arrow,
    Circle,
    Dot,
    FadeIn,
    FadeOut,
    Flash,
    Indicate,
    Line,
    Mobject,
    Transform,
    VGroup,
    VMobject,
    rush_into,
)
from manim import Polygon as MPolygon

from metaphors.board import Board, animate
from metaphors.layout import METAPHOR
from metaphors.performing import Performances, act, performs
from metaphors.picture import again, turn_to
from metaphors.tags import tag
from rendering.typeset import text
from story.beats import Beat, beat_kind
from story.states import BallDrop, BallSlide, Point, RubberBand, point
from story.storyboard import Reading, Walk, read_pick, read_step
from tracing import Event


def _ball(board: Board, at: np.ndarray) -> Dot:
    theme = board.theme
    return tag(Dot(at, radius=0.12, color=theme.ball, stroke_color=theme.ink, stroke_width=1.5),
               "argument", "ball")


def _band(board: Board, corners: Sequence[np.ndarray]) -> VMobject:
    """The rubber band through scene points (a polyline)."""
    band = VMobject(stroke_color=board.theme.band, stroke_width=board.theme.stroke)
    band.set_points_as_corners([np.asarray(c, dtype=float) for c in corners])
    return tag(band, "argument", "band")


def _gravity_arrow(board: Board) -> VGroup:
    theme = board.theme
    left = METAPHOR.x - METAPHOR.width / 2 - 0.5
    top = METAPHOR.y + METAPHOR.height / 2 - 0.1
    arrow = Arrow((left, top, 0), (left, top - 1.0, 0), buff=0, color=theme.gravity,
                  stroke_width=4, max_tip_length_to_length_ratio=0.3)
    g = text("g", font=theme.font, size=theme.label_size + 4, slant="ITALIC",
             colour=theme.gravity).next_to(arrow, DOWN, buff=0.08)
    return tag(VGroup(arrow, g), None, "gravity")


# --- the gravity heuristic -----------------------------------------------------------------------


def gravity_turn(board: Board, beat: GravityTurn) -> None:
    """The polygon turns by ``turn_picture`` degrees so that gravity points down on screen."""
    theme = board.theme
    arrow = _gravity_arrow(board)
    anims = [FadeIn(arrow, shift=0.3 * DOWN)]
    active = board.objects.get(f"piece:{beat.polygon}")
    if active is not None:  # divide and conquer: the piece being worked on lights up
        anims.append(tag(active, "called").animate.set_fill(opacity=theme.active_opacity)
                     .set_stroke(theme.called, width=theme.stroke * 2.5, opacity=1.0))
    board.play(beat, *anims, run_time=0.8)
    board.keep("gravity", arrow)
    turn = turn_to(board, beat.turn_picture)
    if turn:
        again(board, beat, *turn, run_time=2.0)


def drop(board: Board, beat: Drop) -> None:
    """A ball hangs from V on its band, falls straight down and hits the boundary."""
    v = board.vertex(beat.drop.vertex)
    hit = board.at(beat.drop.hit)
    ball, band = _ball(board, v), _band(board, [v, v])
    # the labels the fall would hide move aside first: the drop is short (0.3 units on the
    # counterexample), and a label under the ball's path or the hit ring hid the very moment;
    # they go back when the ball does (metaphors.picture.upright)
    moves = board.clear_labels(*fall_shapes(v, hit), for_now=True)
    board.keep("band", band)
    board.keep("ball", ball)
    board.play(beat, FadeIn(ball, scale=0.5), *moves, run_time=0.6)
    board.scene.add(band)
    board.scene.bring_to_front(ball)
    again(board, beat, animate(ball, rate_func=rush_into).move_to(hit),
           Transform(band, _band(board, [v, hit]), rate_func=rush_into), run_time=1.0)
    mark = tag(Circle(radius=HIT_RADIUS, color=board.theme.argument, stroke_width=board.theme.stroke)
               .move_to(hit), "result", "hit")
    board.keep("hit", mark)
    board.scene.bring_to_front(ball)
    again(board, beat, FadeIn(mark), Flash(hit, color=board.theme.argument, flash_radius=0.35),
           run_time=0.5)


#: the hit ring's radius, and the room a label keeps round it (the ball's radius beyond it)
HIT_RADIUS, HIT_ROOM = 0.2, 0.14


def fall_shapes(v: np.ndarray, hit: np.ndarray) -> tuple[Mobject, ...]:
    """What the ball's fall covers, as lines a label must keep clear of
    (:meth:`Board.clear_labels`): its path from V to the hit, widened by the ball on either
    side, and a square round the hit ring with its diagonals (a label inside it is covered)."""
    r = HIT_RADIUS + HIT_ROOM
    side = np.array([0.12 + 0.04, 0.0, 0.0])
    corners = [hit + np.array([dx, dy, 0.0]) for dx, dy in ((-r, -r), (r, -r), (r, r), (-r, r))]
    return (Line(v - side, hit - side), Line(v + side, hit + side), MPolygon(*corners),
            Line(corners[0], corners[2]), Line(corners[1], corners[3]))


def _scene_point(mobject: Mobject) -> np.ndarray:
    return mobject.get_center()


def slide(board: Board, beat: Slide) -> None:
    """The ball slides down the edge it hit to its lower end X; the band stretches behind it."""
    ball, band = board.objects.get("ball"), board.objects.get("band")
    # it landed on a vertex: nothing to slide (the ball and band come together, from `drop`)
    if ball is None or band is None or beat.slide is None:
        board.play(beat, run_time=0.8)
        return
    x = board.at(beat.slide.to)
    v = band.get_start()
    board.play(beat, animate(ball, rate_func=rush_into).move_to(x),
               Transform(band, _band(board, [v, x]), rate_func=rush_into), run_time=1.2)


def snag(board: Board, beat: Snag) -> None:
    """The band swept the triangle V–hit–X: it snags the first vertex Y there, or stays
    straight."""
    theme = board.theme
    band = board.objects.get("band")
    if beat.band is None:  # the ball landed on a vertex: the band never moved off the drop line
        if band is None:
            board.play(beat, run_time=0.8)
        else:
            board.play(beat, Indicate(band, color=theme.result, scale_factor=1.0), run_time=0.8)
        return
    corners = [board.at(p) for p in beat.band.corners]
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
        again(board, beat, FadeIn(bent), run_time=0.8)
    elif len(corners) == 3:
        y = corners[1]
        again(board, beat, Transform(band, bent), Flash(y, color=theme.result, flash_radius=0.4),
               run_time=1.2)
    else:
        again(board, beat, Transform(band, bent), Indicate(band, color=theme.result,
                                                            scale_factor=1.0), run_time=1.0)
    if swept is not None:
        again(board, beat, FadeOut(swept), run_time=0.4)




# --- what gravity reads from the log ----------------------------------------------------------------


@beat_kind("gravity-turn")
class GravityTurn(Beat):
    """Gravity's direction for the piece ``polygon``; the picture turns by ``turn_picture``."""

    down: Point  # gravity's direction, a vector
    tilt: float
    turn_picture: float
    polygon: str


@beat_kind("drop")
class Drop(Beat):
    """The ball falls from V and hits the boundary (``drop``); ``result`` as the call shows it."""

    result: str
    drop: BallDrop


@beat_kind("slide")
class Slide(Beat):
    """The ball slides down the edge it hit to ``result``: ``slide`` says where it goes, None
    when it landed on a vertex."""

    result: str
    slide: BallSlide | None


@beat_kind("snag")
class Snag(Beat):
    """The band's shape (``band``: straight, or bent at the ``snagged`` vertex), None when
    the ball landed on a vertex; ``snagged`` None: the band stays straight."""

    band: RubberBand | None
    snagged: str | None


def read_turn(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    g = walk.result_object(ret)
    yield walk.call_beat(GravityTurn, "Turn the polygon so that gravity points down", call, ret,
                         down=point(g["down"]), tilt=g["tilt"], turn_picture=g["turn_picture"],
                         polygon=walk.ref(call, "polygon"))


def _hit(walk: Walk, call: Event) -> dict[str, Any]:
    """Where the ball hit (``at``; ``vertex`` when it landed on one)."""
    return walk.live.get("hit") or walk.entered_after(call, "hit")


def _drop(walk: Walk, call: Event, ret: Event) -> dict[str, Any]:
    return {"drop": BallDrop(vertex=walk.ref(call, "v"),
                             hit=point(walk.entered_after(ret, "hit")["at"]))}


def _slide(walk: Walk, call: Event, ret: Event) -> dict[str, Any]:
    """Where the ball slides to: nowhere when it landed on a vertex."""
    slid = "vertex" not in _hit(walk, call)
    return {"slide": BallSlide(to=point(walk.root_points()[walk.result_ref(ret)]))
            if slid else None}


def read_snag(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    snagged = None if ret.result is None else walk.result_ref(ret)
    caption = ("The rubber band stays straight" if snagged is None
               else f"The rubber band snags {snagged}")
    where = walk.root_points()
    corners = [walk.ref(call, "v"), *([snagged] if snagged is not None else []),
               walk.ref(call, "x")]
    band = None if "vertex" in _hit(walk, call) else RubberBand(
        corners=tuple(point(where[c]) for c in corners))
    yield walk.call_beat(Snag, caption, call, ret, band=band, snagged=snagged)


READS: Mapping[str, Reading] = {
    "reflex_vertex": read_pick("{result} is a reflex vertex: the ball will hang there",
                               "No reflex vertex: the polygon is convex"),
    "straight_vertex": read_pick("{result} is a straight vertex: the ball hangs there instead"),
    "gravity_direction": read_turn,
    "drop_ball": read_step(Drop, "The ball falls until it hits the boundary", _drop),
    "slide_to_vertex": read_step(Slide, "It slides down the edge to {result}", _slide),
    "band_snag": read_snag,
}
PERFORMS: Performances = performs(act(GravityTurn, gravity_turn), act(Drop, drop),
                                  act(Slide, slide), act(Snag, snag))
