"""Gravity (Forišek–Steinová): the polygon turns so that gravity points down, a ball on a rubber
band hangs from the reflex vertex V, falls, slides down an edge to X; the band snags the first
vertex Y it sweeps.

Every number comes from the log: the turn (``turn_picture``), the hit point, the ball's end
vertex, the band's final shape (``[V, X]`` straight or ``[V, Y, X]`` bent). The picture turns
as :mod:`metaphors.picture` turns it, and turns back after the verdict.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import replace
from typing import Any

import numpy as np
import shapely
from manim import (
    DOWN,
    Arrow,
    Dot,
    FadeIn,
    FadeOut,
    Flash,
    Indicate,
    Line,
    Mobject,
    Rectangle,
    Transform,
    UpdateFromAlphaFunc,
    VGroup,
    VMobject,
    linear,
    rush_into,
)
from manim import Polygon as MPolygon

from metaphors.board import Board, Playable, animate
from metaphors.drawing import Frame
from metaphors.layout import METAPHOR
from metaphors.performing import Performances, act, performs
from metaphors.picture import _UPRIGHT, FIXED, _movers, again, turn_to
from metaphors.tags import tag
from rendering.turn import Turn
from rendering.typeset import text
from story.analysis import band_at, wraps
from story.beats import Beat, beat_kind
from story.states import BallDrop, BallSlide, Point, RubberBand, point
from story.storyboard import Reading, Walk, read_pick, read_step
from tracing import Event

#: the ball's radius, and the room a label keeps from the ball at rest (its stroke, and a gap
#: that reads as apart: :data:`metaphors.labels.MARGIN`)
BALL_RADIUS, BALL_ROOM = 0.12, 0.06


def _ball(board: Board, at: np.ndarray) -> Dot:
    theme = board.theme
    return tag(Dot(at, radius=BALL_RADIUS, color=theme.ball, stroke_color=theme.ink, stroke_width=1.5),
               "argument", "ball")


#: the dark casing under the band on the fruit, of the theme's stroke: its rose on the
#: fruit's orange was all but invisible (prune and search, chapter 4 at 79-88 s; contrast
#: 1.1 : 1)
BAND_CASING = 2.6


def _band(board: Board, corners: Sequence[np.ndarray]) -> VMobject:
    """The rubber band through scene points (a polyline); over the fruit, on a dark casing
    (a background stroke: the band's moves and reshapes keep it)."""
    band = VMobject(stroke_color=board.theme.band, stroke_width=board.theme.stroke)
    if "fruit" in board.objects:
        band.set_stroke(board.theme.background, width=board.theme.stroke * BAND_CASING,
                        background=True)
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
                     .set_stroke(theme.called, width=theme.active_stroke, opacity=1.0))
    board.play(beat, *anims, run_time=0.8)
    board.keep("gravity", arrow)
    turn = turn_to(board, beat.turn_picture)
    if turn:
        again(board, beat, *turn, run_time=2.0)


def drop(board: Board, beat: Drop) -> None:
    """A ball hangs from V on its band, falls straight down and hits the boundary. A fall
    too short to be seen (:data:`FALL_LEAST`; the counterexample's, with E 2.7 % of the
    frame's height above B–C, fell 0.3 units) is shown in a close-up: the picture zooms onto
    the whole moment — the fall, the slide to where the ball comes to rest, the band — and
    stays close until the claim is judged (:func:`metaphors.picture.upright` zooms back out).
    It zoomed back out as soon as the ball hit, before the slide: the band staying straight
    and the claim beside edge B–C were a faint line 60 × 70 px wide (chapter 3 at 65-70 s).
    Where the ball hits flashes; no ring stays there (a mark nobody named, round E's dot)."""
    v, hit = board.vertex(beat.drop.vertex), board.at(beat.drop.hit)
    rest = hit if beat.rest is None else board.at(beat.rest)
    close = CloseUp.onto(board, v, hit, rest)
    ball = _ball(board, v)
    hangs: list[Playable] = [FadeIn(ball, scale=0.5)]
    if close is not None:
        # the words and roles change first: a marker recoloured as it fades would be two
        # animations of one mobject in one play; the words say what the zoom is for, and the
        # ball they speak of hangs at V as they come, carried by the zoom (it came only under
        # the next caption, 2.8 s after them: chapter 3 at 57 s)
        zooming = replace(beat, caption=CLOSE_WORDS)
        board.play(zooming, *hangs, run_time=0.4)
        hangs = []
        faded = close.fade_first()  # before the zoom: faded as it zooms, they stood off P
        if faded:
            again(board, zooming, *faded, run_time=0.5)
        again(board, zooming, *close.zoom_in(), animate(ball).shift(close.zoomed(v) - v),
              run_time=1.2)
        close.zoomed_in()
        board.close_up = close
        v, hit = board.vertex(beat.drop.vertex), board.at(beat.drop.hit)
    band = _band(board, [v, v])
    # the labels the fall would hide move aside first: a label under the ball's path or where
    # it hits hid the very moment; they go back when the ball does (metaphors.picture.upright)
    moves = board.clear_labels(*fall_shapes(v, hit), for_now=True)
    board.keep("band", band)
    board.keep("ball", ball)
    board.play(beat, *hangs, *moves, run_time=0.6)
    board.scene.add(band)
    board.scene.bring_to_front(ball)
    again(board, beat, animate(ball, rate_func=rush_into).move_to(hit),
           Transform(band, _band(board, [v, hit]), rate_func=rush_into), run_time=1.0)
    board.scene.bring_to_front(ball)
    # a burst within the room kept clear round the hit (:func:`fall_shapes`): its rays
    # reached no label
    again(board, beat, Flash(hit, color=board.theme.argument, flash_radius=HIT_FLASH,
                             line_length=HIT_FLASH), run_time=0.5)


#: the least fall, in scene units, drawn at its own size: 8 % of the frame's height (a shorter
#: one is drawn in a close-up, :class:`CloseUp`); and the most a close-up zooms
FALL_LEAST, ZOOM_MOST = 0.64, 4.0
#: what a close-up's caption says as it zooms in
CLOSE_WORDS = "A close-up: the ball falls only a short way"
#: how far inside the board's box a vertex must stand, zoomed, to be shown in a close-up
#: (its label beside it stays inside the box too)
CLOSE_MARGIN = 0.45
#: the room a close-up keeps round the fall and slide it frames, inside that margin: the
#: ✓ beside the claim, the labels beside V and X
CLOSE_ROOM = 0.35


class CloseUp:
    """The picture zoomed ``zoom`` times about ``pivot`` (the fall's middle), nothing leaving
    the board's box: one drawing of P stands in for its outline, redrawn at each frame as P
    zoomed so far and cut at the box (its fill and its edges, framed by the box's edge while
    zoomed) — never two copies crossfaded, nor a patch cut at another zoom (review r34: a
    fill rectangle outside edge A–B); the vertices outside the box fade, those inside stay.
    The board's frame follows, so :meth:`Board.at` maps onto the close-up until :meth:`done`."""

    def __init__(self, board: Board, pivot: np.ndarray, zoom: float):
        self.board, self.pivot, self.zoom = board, np.asarray(pivot, dtype=float), zoom
        box = board.box
        lo = np.array([box.x - box.width / 2, box.y - box.height / 2])
        hi = np.array([box.x + box.width / 2, box.y + box.height / 2])
        self.box = shapely.box(*lo, *hi)
        theme = board.theme
        self.rings = [[p[:2] for p in ring] for ring in board.outline_rings()]
        # drawn as the outline is: ear clipping's fruit stays the fruit (it turned P's navy
        # and white edges in chapter 4's close-up, 73-77 s, and orange again after)
        outline = board.outline
        self.style = (outline.get_fill_color().to_hex(), outline.get_fill_opacity(),
                      outline.get_stroke_color().to_hex(), outline.get_stroke_width())
        self.fragment = self.drawn(1.0)
        # the window's edge, while zoomed: P's fill cut square at the box reads as a close-up
        # seen through a frame, not as a polygon with straight new sides
        self.window = tag(Rectangle(width=box.width, height=box.height, color=theme.dial,
                                    stroke_width=theme.thin_stroke).move_to((box.x, box.y, 0)),
                          "idle", "close-up:window")
        shrunk = (lo + CLOSE_MARGIN, hi - CLOSE_MARGIN)
        self.shown: dict[str, Mobject] = {}
        self.hidden: dict[str, Mobject] = {}
        for label, marker in board.markers.items():
            at = self.zoomed(board.vertex(label))
            fits = bool(np.all(at[:2] >= shrunk[0]) and np.all(at[:2] <= shrunk[1]))
            (self.shown if fits else self.hidden)[label] = marker
        self.outline, self.frame = board.outline, board.frame
        self.before = {id(m) for m in (board.outline, *board.objects.values())}
        self.others = [m for m in _movers(board) if m is not board.outline
                       and not any(m is marker for marker in board.markers.values())]

    def drawn(self, scale: float) -> VGroup:
        """P zoomed ``scale`` times about the pivot, cut at the board's box: its fill, then its
        edges (at 1: the outline as drawn)."""
        centre = self.pivot[:2]
        fill, opacity, edge, width = self.style
        rings = [[centre + scale * (np.asarray(p) - centre) for p in ring] for ring in self.rings]
        inside = shapely.Polygon(rings[0], rings[1:]).intersection(self.box)
        parts: list[VMobject] = []
        for piece in shapely.get_parts(inside):
            if isinstance(piece, shapely.Polygon) and piece.area > 0:
                parts.append(MPolygon(*[(x, y, 0.0) for x, y in piece.exterior.coords[:-1]],
                                      stroke_width=0, fill_color=fill, fill_opacity=opacity))
        for ring in rings:
            for a, b in zip(ring, [*ring[1:], ring[0]], strict=True):
                cut = shapely.LineString([a, b]).intersection(self.box)
                for seg in shapely.get_parts(cut):
                    if isinstance(seg, shapely.LineString) and seg.length > 0:
                        (x0, y0), (x1, y1) = seg.coords[0], seg.coords[-1]
                        parts.append(Line((x0, y0, 0.0), (x1, y1, 0.0), color=edge,
                                          stroke_width=width))
        return tag(VGroup(*parts), "idle", "close-up")

    def _zooming(self, start: float, end: float) -> UpdateFromAlphaFunc:
        """The drawing of P zoomed from ``start`` to ``end`` times, linearly in the play's
        (smoothed) time, as the markers and a :class:`Turn` move."""
        return UpdateFromAlphaFunc(
            self.fragment, lambda m, a: m.become(self.drawn(start + a * (end - start))))

    @classmethod
    def onto(cls, board: Board, v: np.ndarray, hit: np.ndarray,
             rest: np.ndarray | None = None) -> CloseUp | None:
        """The close-up onto the fall from ``v`` to ``hit`` and the slide on to ``rest`` (scene
        points), None when the fall is long enough. The zoom fits the three, with room for
        their labels, in the board's box (at most :data:`ZOOM_MOST`), and carries their
        middle to the box's centre: a zoom and a shift, which is a zoom about one fixed
        point (the pivot)."""
        fall = float(np.linalg.norm(hit - v))
        if fall >= FALL_LEAST or fall < 1e-9:
            return None
        spots = np.array([v, hit, hit if rest is None else rest], dtype=float)[:, :2]
        low, high = spots.min(axis=0), spots.max(axis=0)
        box = board.box
        room = np.array([box.width, box.height]) - 2 * (CLOSE_MARGIN + CLOSE_ROOM)
        zoom = min(ZOOM_MOST, *(room / np.maximum(high - low, 1e-9)))
        zoom = max(zoom, 1.01)
        if abs(board.frame.angle) < 1e-9 and abs(zoom * board.frame.zoom - 1) < 1e-6:
            zoom *= 1.01  # a pure shift, which a frame cannot hold: a hair more zoom
        middle, centre = (low + high) / 2, np.array(box.center[:2], dtype=float)
        # the point that the zoom keeps fixed, f + zoom (middle − f) = centre
        pivot = (centre - zoom * middle) / (1 - zoom)
        return cls(board, np.array([*pivot, 0.0]), zoom)

    def zoomed(self, q: np.ndarray) -> np.ndarray:
        return self.pivot + self.zoom * (np.asarray(q, dtype=float) - self.pivot)

    def _frame(self) -> Frame:
        """The board's frame followed by this zoom: one turn and zoom about its fixed point."""
        old = self.frame
        turn = np.radians(old.angle)
        rot = np.array([[np.cos(turn), -np.sin(turn)], [np.sin(turn), np.cos(turn)]])
        k, c, p = self.zoom, old.pivot[:2], self.pivot[:2]
        # x ↦ p + k (c − p) + k z R (x − c), c the old frame's pivot: a turn and zoom about the
        # point it keeps, f = (I − k z R)⁻¹ (p + k (c − p) − k z R c)
        linear = k * old.zoom * rot
        offset = p + k * (c - p) - linear @ c
        fixed = np.linalg.solve(np.eye(2) - linear, offset)
        return old.turned(old.angle, fixed, old.zoom * k)

    def fade_first(self) -> list[Playable]:
        """What the close-up leaves out fades, before the zoom in: the vertices outside its
        box, and what else stands on the picture (faded as P zoomed, they were ghosts over
        it where P no longer was: chapter 4's L, K and M over the zoomed fruit)."""
        return [FadeOut(m) for m in (*self.hidden.values(), *self.others)]

    def zoom_in(self) -> list[Playable]:
        board = self.board
        board.scene.replace(self.outline, self.fragment)  # the same picture, in its place
        anims: list[Playable] = [self._zooming(1.0, self.zoom), FadeIn(self.window)]
        anims += [animate(m).shift(self.zoomed(board.vertex(label)) - board.vertex(label))
                  for label, m in self.shown.items()]
        board.frame = self._frame()
        board.outline = self.fragment
        return anims

    def _move_hidden(self, sign: float) -> None:
        """The faded markers moved with the zoom (``sign`` 1) or back (−1), off screen: the
        label clearing measures against every marker where the frame puts its vertex."""
        for label, m in self.hidden.items():
            q = self.frame.to_scene(self.board.where[label])
            m.shift(sign * (self.zoomed(q) - q))

    def zoomed_in(self) -> None:
        """After the zoom in: the faded markers stand where the close-up puts them."""
        self._move_hidden(1.0)

    def made_here(self, key: str) -> bool:
        """Whether the board's object ``key`` was drawn up close (it was not there before)."""
        return key in self.board.objects and id(self.board.objects[key]) not in self.before

    def zoom_out(self) -> list[Playable]:
        board = self.board
        self._move_hidden(-1.0)
        anims: list[Playable] = [self._zooming(self.zoom, 1.0), FadeOut(self.window)]
        back = self.frame
        for label, m in self.shown.items():
            anims.append(animate(m).shift(back.to_scene(board.where[label])
                                          - board.vertex(label)))
        # what was drawn up close (the ball, the band, what it swept, the claim)
        # zooms back with the picture; not what stood before (faded, or the outline itself:
        # ear clipping's fruit, which the close-up's drawing stood in for, is not zoomed)
        anims += [Turn(m, 0.0, self.pivot, 1 / self.zoom, upright=_UPRIGHT)
                  for key, m in board.objects.items()
                  if key not in FIXED and id(m) not in self.before]
        board.frame = back
        return anims

    def done(self) -> None:
        """The picture is whole again: the close-up's fragment goes."""
        self.board.outline = self.outline
        self.board.scene.replace(self.fragment, self.outline)
        self.board.close_up = None

    def come_back(self) -> list[Playable]:
        """What the close-up faded (:meth:`fade_first`) comes back, once the picture is
        whole: faded in with the zoom out, at their places in the whole picture, the
        vertices outside the box stood off P while it was still drawn zoomed (chapter 3 at
        75 s: A's dot above the box)."""
        return [FadeIn(m) for m in (*self.hidden.values(), *self.others)]


#: the reach of the spot where the ball hits (its burst), and the room a label keeps round
#: it (the ball's radius beyond it); the burst's radius and rays
HIT_RADIUS, HIT_ROOM = 0.2, 0.14
HIT_FLASH = 0.15


def fall_shapes(v: np.ndarray, hit: np.ndarray) -> tuple[Mobject, ...]:
    """What the ball's fall covers, as lines a label must keep clear of
    (:meth:`Board.clear_labels`): its path from V to the hit, widened by the ball on either
    side, and a square round where it hits with its diagonals (a label inside it is covered
    by the ball and its burst)."""
    side = np.array([BALL_RADIUS + 0.04, 0.0, 0.0])
    return (Line(v - side, hit - side), Line(v + side, hit + side),
            *_square(hit, HIT_RADIUS + HIT_ROOM))


def _scene_point(mobject: Mobject) -> np.ndarray:
    return mobject.get_center()


def slide(board: Board, beat: Slide) -> None:
    """The ball slides down the edge it hit to its lower end X; the band stretches behind it,
    taut at every moment: it wraps each vertex it meets (:func:`story.analysis.wraps`) the
    moment its straight line would leave P, one play per piece of the slide, drawn in every
    frame as :func:`story.analysis.band_at` has it (what tests/test_gravity_band.py samples).
    What the band has swept so far is shaded as it goes, under words that say so (it came
    after the slide, unnamed, chapter 3 at 30.5 s), and stays till the verdict. From the
    first vertex it wraps the caption says the band snags it, and the row that says so is lit
    (the slide's stayed lit 0.9 s under "The rubber band snags H": the gravity scene at 12 s)."""
    ball, band = board.objects.get("ball"), board.objects.get("band")
    # it landed on a vertex: nothing to slide (the ball and band come together, from `drop`)
    if ball is None or band is None or beat.slide is None or beat.slide.hit is None:
        board.play(beat, run_time=0.8)
        return
    # in P's units, as the log has them: the band's corners are P's vertices, exactly
    v, hit, x = (board.frame.from_scene(band.get_start()), beat.slide.hit, beat.slide.to)
    pieces = wraps(v, hit, x, list(board.where.values()))
    ends = [t for t, _ in pieces[1:]] + [1.0]
    swept = _swept(board, pieces, hit, x, 0.0)
    board.keep("swept", swept)
    board.scene.add(swept)
    for k, ((start, corners), end) in enumerate(zip(pieces, ends, strict=True)):
        to = board.at(band_at(pieces, hit, x, end)[-1])
        moving = animate(ball, rate_func=linear).move_to(to)
        moves: list[Playable] = []
        if k == len(pieces) - 1:  # it comes to rest on X: see-through, X's dot shows in it
            moving = moving.set_fill(opacity=RESTING)
            # and X's label moves off it (the counterexample's C touched it), back with it
            moves = board.clear_labels(*ball_shapes(to), for_now=True)
        anims = [moving, _stretching(board, band, pieces, hit, x, (start, end)),
                 _sweeping(board, swept, pieces, hit, x, (start, end)), *moves]
        said = beat
        if k > 0:  # the band wraps a vertex: it snags it, and the vertex pulses as it does
            y = _label_at(board, corners[1])
            said = _snagging(board, beat, y)
            if k == 1 and y in board.markers:
                anims.append(Indicate(board.markers[y], color=board.theme.argument))
        # the words, Y's amber and the band wrapping Y in one play: Y went amber in the panel
        # a play before the band reached it (the gravity scene, play 19)
        board.play(said, *anims, run_time=max(SLIDE_SECONDS * (end - start), 0.1),
                   together=said is not beat)
    # the ball rests at X under X's dot and label: on top it hid the vertex it names
    if beat.result in board.markers:
        board.scene.bring_to_front(board.markers[beat.result])


def _swept(board: Board, pieces: Sequence, hit: Point, x: Point, t: float) -> VMobject:
    """What the band has swept by time ``t`` of the slide: V, where the ball hit, the ball,
    and back along the band (by the vertices it wraps), shaded under the picture."""
    corners = band_at(pieces, hit, x, t)
    ring = [corners[0], hit, *corners[:0:-1]]
    shape = MPolygon(*[board.at(c) for c in ring], stroke_width=0, fill_color=board.theme.band,
                     fill_opacity=SWEPT_OPACITY)
    return tag(shape, "argument", "swept").set_z_index(-1)


def _sweeping(board: Board, swept: Mobject, pieces: Sequence, hit: Point, x: Point,
              span: tuple[float, float]) -> UpdateFromAlphaFunc:
    """The swept region redrawn in every frame of a piece of the slide, with the band."""
    start, end = span

    def draw(mobject: Mobject, alpha: float) -> None:
        mobject.become(_swept(board, pieces, hit, x, start + alpha * (end - start)))

    return UpdateFromAlphaFunc(swept, draw, rate_func=linear)


#: the swept region's fill
SWEPT_OPACITY = 0.18


def _snagging(board: Board, beat: Slide, y: str) -> Slide:
    """The slide's beat from the moment its band wraps ``y``: the words say it snags Y, the
    row that says so is lit, and Y turns amber, the claim to be, then (it turned amber a
    second later, with the band's last shape: chapter 3 at 31 s)."""
    row = next((k for k, r in enumerate(board.panel.pseudocode) if "band_snag" in r.calls),
               beat.row)
    return replace(beat, caption=f"The rubber band snags {y}", row=row,
                   seq=beat.seq if beat.snag_seq is None else beat.snag_seq,
                   roles={**beat.roles, y: "argument"})


def _stretching(board: Board, band: Mobject, pieces: Sequence, hit: Point, x: Point,
                span: tuple[float, float]) -> UpdateFromAlphaFunc:
    """The band drawn, in every frame of a piece of the slide (``span``: its times), as
    :func:`story.analysis.band_at` has it then: one computation of the band, drawn and tested
    (a Transform between its ends bent the band off its taut shape as the corners moved)."""
    start, end = span

    def draw(mobject: Mobject, alpha: float) -> None:
        corners = band_at(pieces, hit, x, start + alpha * (end - start))
        mobject.set_points_as_corners([board.at(c) for c in corners])

    return UpdateFromAlphaFunc(band, draw, rate_func=linear)


def _label_at(board: Board, p: Point) -> str:
    """The label of the vertex at ``p`` (P's units)."""
    return min(board.where, key=lambda k: math.dist(board.where[k], p))


def ball_shapes(at: np.ndarray) -> tuple[Mobject, ...]:
    """A square round the ball at rest on ``at`` with its diagonals, as lines a label must
    keep clear of (:meth:`Board.clear_labels`): a label inside the square is covered."""
    return _square(at, BALL_RADIUS + BALL_ROOM)


def _square(at: np.ndarray, r: float) -> tuple[Mobject, ...]:
    """A square of half side ``r`` round ``at``, and its diagonals."""
    corners = [at + np.array([dx, dy, 0.0]) for dx, dy in ((-r, -r), (r, -r), (r, r), (-r, r))]
    return (MPolygon(*corners), Line(corners[0], corners[2]), Line(corners[1], corners[3]))


#: the seconds of the ball's slide from the hit to X, and the fill of the ball at rest on X
#: (the ball hid the vertex it names: review r34, C at 66 s)
SLIDE_SECONDS, RESTING = 1.2, 0.4


def _xy(p: np.ndarray) -> tuple[float, float]:
    return (float(p[0]), float(p[1]))


def snag(board: Board, beat: Snag) -> None:
    """The band swept the triangle V–hit–X (shaded as it went, :func:`slide`): it snags the
    first vertex Y there, which pulses, or stays straight."""
    theme = board.theme
    band = board.objects.get("band")
    if beat.band is None:  # the ball landed on a vertex: the band never moved off the drop line
        if band is None:
            board.play(beat, run_time=0.8)
        else:
            board.play(beat, Indicate(band, color=theme.argument, scale_factor=1.0),
                       run_time=0.8)
        return
    corners = [board.at(p) for p in beat.band.corners]
    bent = _band(board, corners)
    if band is None:
        board.keep("band", bent)
        board.play(beat, FadeIn(bent), run_time=0.8)
    elif len(corners) == 3:
        # the claim to be (amber), pulsed as the band wrapped it (:func:`slide`): no burst,
        # whose rays crossed H's label (chapter 3 at 31 s)
        board.play(beat, Transform(band, bent), run_time=1.2)
    else:
        board.play(beat, Transform(band, bent), Indicate(band, color=theme.argument,
                                                         scale_factor=1.0), run_time=1.0)


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
    rest: Point | None = None  # where the ball comes to rest after its slide (None: no slide)


@beat_kind("slide")
class Slide(Beat):
    """The ball slides down the edge it hit to ``result``: ``slide`` says where it goes, None
    when it landed on a vertex."""

    result: str
    slide: BallSlide | None
    #: the seq of the band's snag after the slide: from the moment the band wraps a vertex
    #: the slide speaks as the snag does (its row lit, named as the snag names it)
    snag_seq: int | None = None


@beat_kind("snag")
class Snag(Beat):
    """The band's shape (``band``: straight, or bent at the ``snagged`` vertex), None when
    the ball landed on a vertex; ``snagged`` None: the band stays straight."""

    band: RubberBand | None
    snagged: str | None


def read_turn(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    g = walk.result_object(ret)
    # the words name V, the vertex the turn is about: its colour, blue, is said with them
    # (chapter 4's G, red as no ear, turned blue under "…so that gravity points down")
    v = walk.ref(call, "v")
    # the arrow that comes with these words is named by them (an unnamed "g" stood there)
    yield walk.call_beat(GravityTurn, f"Turn the polygon so that gravity (g) points down "
                         f"into P at {v}", call, ret,
                         down=point(g["down"]), tilt=g["tilt"], turn_picture=g["turn_picture"],
                         polygon=walk.ref(call, "polygon"))


def _hit(walk: Walk, call: Event) -> dict[str, Any]:
    """Where the ball hit (``at``; ``vertex`` when it landed on one)."""
    return walk.live.get("hit") or walk.entered_after(call, "hit")


def _drop(walk: Walk, call: Event, ret: Event) -> dict[str, Any]:
    return {"drop": BallDrop(vertex=walk.ref(call, "v"),
                             hit=point(walk.entered_after(ret, "hit")["at"])),
            "rest": _rest(walk, ret)}


def _rest(walk: Walk, ret: Event) -> Point | None:
    """Where the ball dropped at ``ret`` comes to rest: the vertex the slide after it returns
    (None: it landed on a vertex, or no slide follows)."""
    for later in walk.log.events[ret.seq + 1:]:
        if later.kind == "return" and later.name == "slide_to_vertex":
            return point(walk.root_points()[walk.result_ref(later)])
        if later.kind == "return" and later.name == "drop_ball":
            break
    return None


def _slide(walk: Walk, call: Event, ret: Event) -> dict[str, Any]:
    """Where the ball slides to: nowhere when it landed on a vertex. X keeps its ink: the
    ball resting on it marks it (lit green, what the call gives, it turned amber a second
    later as the snag's input, chapter 3 at 30 s, and white at the claim — three colours,
    none said); V stays blue, the band hanging from it (:meth:`Board.held_roles`)."""
    hit = _hit(walk, call)
    snag = next((e.seq for e in walk.log.events[ret.seq + 1:]
                 if e.kind == "call" and e.name == "band_snag"), None)
    return {"slide": BallSlide(to=point(walk.root_points()[walk.result_ref(ret)]),
                               hit=point(hit["at"]))
            if "vertex" not in hit else None, "roles": {}, "snag_seq": snag}


def read_snag(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """The band's last shape. The vertex it snags is the claim to be, amber as the caption
    names it (as a heuristic's pick is as its tool reaches it); a straight band lights
    nothing: its claim VX names X the next moment (X lit amber under "The rubber band stays
    straight" said nothing of X)."""
    snagged = None if ret.result is None else walk.result_ref(ret)
    caption = ("The rubber band stays straight" if snagged is None
               else f"The rubber band snags {snagged}")
    where = walk.root_points()
    v = walk.ref(call, "v")
    corners = [v, *([snagged] if snagged is not None else []), walk.ref(call, "x")]
    band = None if "vertex" in _hit(walk, call) else RubberBand(
        corners=tuple(point(where[c]) for c in corners))
    roles = {v: "called", **({snagged: "argument"} if snagged is not None else {})}
    yield walk.call_beat(Snag, caption, call, ret, band=band, snagged=snagged, roles=roles)


def read_v(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """V, said as the row says it: the first reflex vertex after B, the left-most vertex
    picked just before (B was never named: chapter 3)."""
    b = next((walk.result_ref(e) for e in reversed(walk.log.events[:call.seq])
              if e.kind == "return" and e.name == "leftmost_vertex" and e.result), None)
    after = f"the first reflex vertex after {b}" if b else "a reflex vertex"
    yield from read_pick(f"{{result}} is {after}: the ball will hang there",
                         "No reflex vertex: the polygon is convex", role=V_ROLE)(walk, call, ret)


#: V's one role through the run: the vertex the ball hangs from, blue from its pick to its
#: claim (it was green as picked, what the call gives, and blue a second later as the
#: polygon turned, unsaid: chapter 3 at 20 s)
V_ROLE = "called"
READS: Mapping[str, Reading] = {
    "reflex_vertex": read_v,
    "straight_vertex": read_pick("{result} is a straight vertex: the ball hangs there instead",
                                 role=V_ROLE),
    "gravity_direction": read_turn,
    "drop_ball": read_step(Drop, "The ball falls until it hits the boundary", _drop),
    # the shading that comes with the slide is named by its words (it came unnamed, and was
    # explained only 10 s later: chapter 3 at 30.5 s)
    "slide_to_vertex": read_step(Slide, "It slides down the edge to {result}; the band sweeps "
                                 "the shaded part", _slide),
    "band_snag": read_snag,
}
PERFORMS: Performances = performs(act(GravityTurn, gravity_turn), act(Drop, drop),
                                  act(Slide, slide), act(Snag, snag))
