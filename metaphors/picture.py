"""The picture on the left turns and zooms as one: gravity turns it so that gravity points
down; after each verdict it turns back upright (a following step starts from the plain
polygon, as the panel shows it), and what the turn brought (ball, band, impact mark, the
gravity arrow) goes. Turning the picture turns the board's frame too, so :meth:`Board.at`
keeps mapping polygon points onto the turned picture.
"""

from __future__ import annotations

import math

import numpy as np
from manim import Circle, Mobject

from metaphors.board import Board, Playable
from metaphors.marks import board_spot
from rendering.turn import Turn
from rendering.typeset import FlatText
from story.beats import Beat

#: board objects that stay put on screen when the polygon turns (keys of ``board.objects``)
FIXED = ("gravity", "plate", "counter")  # and every slice on the plate (fruit)
#: things that keep their size and stay upright when the picture turns and zooms
_UPRIGHT = (FlatText, Circle)


def again(board: Board, beat: Beat, *anims: Playable, run_time: float = 1.0) -> None:
    """A further play within a beat (the panel, roles and subtitle are already up to date)."""
    board.scene.play(*anims, run_time=max(0.1, run_time * beat.pace))


def _fit_zoom(board: Board, angle: float) -> float:
    """Largest zoom ≤ 1 that keeps the polygon turned by ``angle`` inside the board's box (a
    fruit's leaves room for the plate and counter below it: the turned fruit keeps off them)."""
    box = board.box
    turned = board.frame.turned(angle, box.center, 1.0)
    pts = np.array(turned.many(board.polygon.points))[:, :2] - np.array(box.center[:2])
    reach = np.abs(pts).max(axis=0)
    return float(min(1.0, box.width / 2 / max(reach[0], 1e-9),
                     box.height / 2 / max(reach[1], 1e-9)))


def _movers(board: Board) -> list[Mobject]:
    """What turns with the polygon: outline, vertices, metaphor objects (not the fixed ones)."""
    fixed = [board.objects.get(k) for k in FIXED]
    fixed += [m for k, m in board.objects.items() if k.startswith("slice:")]
    return [m for m in board.left_group().submobjects if not any(m is f for f in fixed)]


def turn_to(board: Board, angle: float) -> list[Turn]:
    """Animations turning the picture to ``angle`` degrees (absolute; 0 is upright), and the
    board's frame with it. Labels, dots and the ball keep their size and stay upright."""
    old = board.frame
    new = old.turned(angle, board.box.center, _fit_zoom(board, angle))
    delta = new.angle - old.angle
    k = new.zoom / old.zoom
    if abs(delta) < 1e-9 and abs(k - 1) < 1e-9:
        return []
    turns = {id(m): Turn(m, math.radians(delta), board.box.center, k, upright=_UPRIGHT)
             for m in _movers(board)}
    line, mark = board.objects.get("claim"), board.objects.get("verdict")
    if line is not None and mark is not None and id(mark) in turns:
        # the mark placed again for the turned picture: its labels keep upright, so a place
        # clear of them before the turn need not be after it
        turn = turns[id(mark)]
        spot = board_spot(board, mark, line, moved=lambda p: _turned(turn, p))
        turn.shift = spot - turn.end_centre(mark)
    board.frame = new
    return list(turns.values())


def _turned(turn: Turn, point: np.ndarray) -> np.ndarray:
    """Where a point of the picture ends when ``turn`` is over (``shift`` left out)."""
    return np.array([*((point[:2] - turn.pivot) @ turn.matrix(1.0).T + turn.pivot), point[2]])


#: what a turned picture holds for one claim: the verdict takes it away (in this order)
TRANSIENT = ("ball", "band", "hit", "gravity")


def upright(board: Board, beat: Beat) -> None:
    """After a verdict: the turn's objects go and the picture turns back upright."""
    gone = board.drop(*TRANSIENT)
    if gone:
        again(board, beat, *gone, run_time=0.5)
    turn = turn_to(board, 0.0)
    if turn:
        again(board, beat, *turn, run_time=1.5)
    back = board.labels_back()  # the labels moved off the ball's way, once it is upright
    if back:
        again(board, beat, *back, run_time=0.4)
