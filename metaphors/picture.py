"""The picture on the left turns and zooms as one: gravity turns it so that gravity points
down; after each verdict it turns back upright (a following step starts from the plain
polygon, as the panel shows it), and what the turn brought (ball, band, impact mark, the
gravity arrow) goes. Turning the picture turns the board's frame too, so :meth:`Board.at`
keeps mapping polygon points onto the turned picture.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from manim import Circle, Mobject, VGroup

from metaphors.board import Board, Playable
from metaphors.drawing import Frame
from metaphors.labels import drawn_edges, place_ring_labels, seen_from
from metaphors.layout import ring_edges
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
    board's frame with it. Labels, dots and the ball keep their size and stay upright; each
    label goes to its place on the turned picture (:func:`_label_places`)."""
    old = board.frame
    new = old.turned(angle, board.box.center, _fit_zoom(board, angle))
    delta = new.angle - old.angle
    k = new.zoom / old.zoom
    if abs(delta) < 1e-9 and abs(k - 1) < 1e-9:
        return []
    pivot = np.asarray(board.box.center, dtype=float)

    probe = Turn(Mobject(), math.radians(delta), pivot, k)
    placed = _label_places(board, new, lambda p: _turned(probe, p))
    # the dot turns with the picture, its label goes to its new place as it does
    moves = {id(board.markers[name][1]): at - probe.end_centre(board.markers[name][1])
             for name, at in placed.items()}
    turns = {id(m): Turn(m, math.radians(delta), pivot, k, upright=_UPRIGHT, moves=moves)
             for m in _movers(board)}
    line, mark = board.objects.get("claim"), board.objects.get("verdict")
    if line is not None and mark is not None and id(mark) in turns:
        # the mark placed again for the turned picture, clear of the labels' new places
        turn = turns[id(mark)]
        spot = board_spot(board, mark, line, moved=lambda p: _turned(turn, p), placed=placed)
        turn.shift = spot - turn.end_centre(mark)
    board.frame = new
    return list(turns.values())


def _label_places(board: Board, new: Frame,
                  moved: Callable[[np.ndarray], np.ndarray]) -> dict[str, np.ndarray]:
    """The centre of every vertex label on the picture turned to the frame ``new`` (``moved``:
    where a point of the picture goes): turned upright, back where it stood beside its dot
    before the picture turned (:attr:`Board.home`: a label stays put on the picture it was
    placed for); turned, placed again on the picture as it will stand
    (:func:`metaphors.labels.place_ring_labels`: its outline, the lines drawn on it and the
    claims still to come). Kept upright and carried round with the turn, the labels of a
    thin fruit shrunk by a zoom stood inside it (chapter 4's M and G) and left its ✓ no room.
    The labels moved off the ball's way for now, or aside off a test triangle, are placed
    too: they do not go back."""
    markers = {name: m for name, m in board.markers.items()
               if isinstance(m, VGroup) and len(m) > 1}
    if _upright(board.frame):
        board.home = {name: m[1].get_center() - m[0].get_center() for name, m in markers.items()}
    for name in markers:
        board.moved_for_now.pop(name, None)
        board.aside.pop(name, None)
    if _upright(new) and board.home:
        home, board.home = board.home, {}
        return {name: new.to_scene(board.where[name]) + home[name]
                for name in markers if name in home}
    rings = [[name for name in ring if name in markers]
             for ring in (board.polygon.labels, *(h.labels for h in board.holes))]
    rings = [ring for ring in rings if ring]
    drawn = [edge for ring in board.outline_rings() for edge in ring_edges(ring)]
    drawn += [edge for m in _movers(board) if m is not board.outline
              and not any(m is marker for marker in markers.values()) for edge in drawn_edges(m)]
    segments = [(moved(np.asarray(a, dtype=float)), moved(np.asarray(b, dtype=float)))
                for a, b in drawn]
    points = board.polygon.points
    segments += [(new.to_scene(points[i]), new.to_scene(points[j])) for i, j in board.claim_pairs
                 if board.polygon.labels[i] in markers and board.polygon.labels[j] in markers]
    centres = place_ring_labels([[new.to_scene(board.where[name]) for name in ring]
                                 for ring in rings],
                                [(markers[name][1].width, markers[name][1].height)
                                 for ring in rings for name in ring],
                                segments, board.theme.dot_radius)
    names = [name for ring in rings for name in ring]
    edges = [edge for ring in rings for edge in
             ring_edges([new.to_scene(board.where[name]) for name in ring])]
    # a label with no place its dot sees (across an edge, it names what lies beyond: the
    # turned fruit's notch M stood over edge K–H) turns with the picture, as it stood
    return {name: np.array([c[0], c[1], 0.0]) for name, c in zip(names, centres, strict=True)
            if seen_from(new.to_scene(board.where[name]), c, edges)}


def _upright(frame: Frame) -> bool:
    """Whether ``frame`` is the picture as first drawn: not turned, not zoomed."""
    return abs(frame.angle) < 1e-9 and abs(frame.zoom - 1.0) < 1e-9


def _turned(turn: Turn, point: np.ndarray) -> np.ndarray:
    """Where a point of the picture ends when ``turn`` is over (``shift`` left out)."""
    return np.array([*((point[:2] - turn.pivot) @ turn.matrix(1.0).T + turn.pivot), point[2]])


#: the seconds a close-up holds its judged claim before it zooms back out
CLOSE_HOLD = 1.2
#: what a turned picture holds for one claim: the verdict takes it away (in this order)
TRANSIENT = ("ball", "band", "swept", "gravity")


def upright(board: Board, beat: Beat) -> None:
    """After a verdict: the turn's objects go, a close-up zooms back out (gravity's, which
    stays close from the fall to the verdict) and the picture turns back upright. Not on a
    board whose run an analysis goes on from (:attr:`Board.kept_end`): it shades what the
    band swept on the picture as the run left it."""
    if board.kept_end:
        return
    close = board.close_up
    if close is not None:  # the ✓ seen up close, by the claim it judges, before all goes
        board.scene.wait(max(0.1, CLOSE_HOLD * beat.pace))
    # the ✓ or ✗ seen up close beside its claim goes with them, before the zoom back: kept
    # at its size, it landed on the claim, the needle of P it stood in shrunk under it
    # (chapter 3's ✓ on EC at 76-78 s); gone with the zoom, it faded under the labels the
    # zoom brings back (chapter 4's ✓ under M); the claim's colour and the words still judge it
    up_close = ("verdict",) if close is not None and close.made_here("verdict") else ()
    gone = board.drop(*TRANSIENT, *up_close)
    if gone:
        again(board, beat, *gone, run_time=0.5)
    if close is not None:
        # the labels moved off the ball's way go back first, up close where they were moved:
        # carried out with the zoom from their places for now, G's stood on H's (chapter 4)
        back = board.labels_back()
        if back:
            again(board, beat, *back, run_time=0.4)
        again(board, beat, *close.zoom_out(), run_time=1.2)
        close.done()
        faded = close.come_back()  # once the picture is whole, not while it zooms
        if faded:
            again(board, beat, *faded, run_time=0.5)
    turn = turn_to(board, 0.0)
    if turn:
        again(board, beat, *turn, run_time=1.5)
    back = board.labels_back()  # the labels moved off the ball's way, once it is upright
    if back:
        again(board, beat, *back, run_time=0.4)

