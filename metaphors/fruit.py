"""Fruit (ear clipping): the polygon is a fruit with a rind; a knife cuts along an ear's
diagonal, the slice moves to a plate, and a counter shows ``k / n−2 slices``.

Every slice, and what is left of the fruit after it, comes from the log (the beats' data).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import replace
from typing import Any, cast

import manim
import numpy as np
from manim import (
    Add,
    Create,
    Dot,
    Ellipse,
    FadeIn,
    FadeOut,
    Line,
    Mobject,
    Polygram,
    Rectangle,
    Transform,
    VGroup,
)
from manim import (
    Polygon as MPolygon,
)

from geometry.batch import in_closed_triangle
from geometry.predicates import orient
from metaphors.board import Board, Playable
from metaphors.drawing import count_words, ending_beat, triangulation_pieces
from metaphors.labels import EDGE_MARGIN, MARGIN, drawn_edges, haloed, move_label, off_the_fill
from metaphors.layout import Obstacles, area_of, rects_at
from metaphors.performing import Performances, act, performs
from metaphors.tags import tag
from metaphors.theme import Theme
from rendering import typeset
from story.beats import Beat, Hole, Point, beat_kind, point, points_of
from story.storyboard import Reading, Walk, call_line, call_roles, show
from story.words import named_together
from tracing import Event

_DIGITS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
PLATE_Y = -2.55
PLATE_WIDTH = 5.6


#: the plate's height, and the part of its width the slices take (the ends are too thin)
PLATE_HEIGHT, PLATE_USED = 0.9, 0.82


def plate_slot(k: int, total: int) -> tuple[float, float, float]:
    """Where slice ``k`` of ``total`` goes on the plate: its centre's offset from the plate's
    centre, and the widest and tallest it may be there, so that every slice lies inside the
    plate's ellipse (near the ends the ellipse is thin: the slices keep to the middle part,
    :data:`PLATE_USED`, and are lower there).

    >>> x, w, h = plate_slot(11, 11)
    >>> round(x, 3), round(w, 3), round(h, 3)
    (2.087, 0.355, 0.45)
    """
    used = PLATE_WIDTH * PLATE_USED
    slot = used / max(total, 1)
    x = -used / 2 + slot * (k - 0.5)
    edge = abs(x) + slot * 0.85 / 2  # the slice's far side
    room = PLATE_HEIGHT * math.sqrt(max(0.0, 1 - (2 * edge / PLATE_WIDTH) ** 2))
    return x, slot * 0.85, min(0.6, 0.85 * room)


def fruit_style(theme: Theme) -> dict[str, Any]:
    """How the fruit is drawn: its flesh and its rind (a card's figure of a fruit too)."""
    return {"color": theme.rind, "stroke_width": theme.stroke * 2.2,
            "fill_color": theme.fruit, "fill_opacity": 0.75}


def good_style(theme: Theme) -> dict[str, Any]:
    """How prune and search's good sub-polygon is tinted over the fruit: the *called* blue
    of what the search runs on, here and on the card that tells of it (the card drew it in
    two of the pieces' tints over P's navy, the run in this tint over the fruit: three
    colours for one thing)."""
    return {"color": theme.called, "stroke_width": theme.stroke, "fill_color": theme.called,
            "fill_opacity": theme.piece_opacity}


#: how opaque a tested vertex's triangle is, and how wide its edge (of the theme's stroke)
TEST_OPACITY, TEST_STROKE = 0.3, 1.5


def _fruit(board: Board, points: Sequence[Sequence[float]],
           holes: Sequence[Hole] = ()) -> MPolygon | Polygram:
    style = fruit_style(board.theme)
    if holes:  # the whole fruit, its holes cut out (rings of one mobject; holes unfilled)
        rings = [[board.at(p) for p in ring] for ring in (points, *(h.points for h in holes))]
        return tag(Polygram(*[[*ring, ring[0]] for ring in rings], **style), "idle", "fruit")
    return tag(MPolygon(*[board.at(p) for p in points], **style), "idle", "fruit")


def _setup(board: Board, beat: Beat) -> None:
    """The first time: the polygon turns into a fruit, every label gets its dark halo
    (:func:`metaphors.labels.haloed`: a label over the fruit's orange reads — grey, red or
    green on it all but vanish, and even white is under 3 : 1), a plate and a counter
    appear."""
    if "fruit" in board.objects:
        return
    theme = board.theme
    x = board.frame.center[0]
    plate = tag(Ellipse(width=PLATE_WIDTH, height=PLATE_HEIGHT, color=theme.plate, stroke_width=2,
                        fill_color=theme.plate, fill_opacity=0.12), None, "plate")
    plate.move_to((x, PLATE_Y, 0))
    fruit = _fruit(board, board.polygon.points, board.holes)
    # every label on a dark halo, coming with the fruit
    halos = [Transform(marker, haloed(marker, theme.background))
             for marker in board.markers.values()
             if isinstance(marker, VGroup) and len(marker) > 1]
    slices = board.polygon.n + sum(len(h.points) + 2 for h in board.holes) - 2
    board.keep("plate", plate)
    board.keep("fruit", fruit)
    board.keep("counter", _counter(board, 0, getattr(beat, "total", slices)))
    board.scene.play(Transform(board.outline, fruit), FadeIn(plate),
                     FadeIn(board.objects["counter"]), *halos, run_time=0.8 * beat.pace)
    board.scene.remove(fruit)
    board.objects["fruit"] = board.outline


def _counter(board: Board, k: int, total: int) -> Mobject:
    return _counter_text(board, f"{k} / {total} slices", board.theme.ink)


def _counter_text(board: Board, words: str, colour: str) -> Mobject:
    theme = board.theme
    text = tag(typeset.text(words, font=theme.font, size=theme.label_size, colour=colour),
               None, "counter")
    return text.move_to((board.frame.center[0], PLATE_Y + 0.68, 0))


class Indicate(manim.Indicate):
    """A vertex's pulse: its dot grows and, with its label, takes the colour for a moment;
    the label keeps its size and place. manim's scales the whole marker about its middle:
    a label set off its dot (the fruit's G, moved clear of the slices) grew to twice its
    size and flew ~45 px off its vertex at 25 s of ear clipping. Any other mobject pulses
    as manim's does."""

    def create_target(self) -> Mobject:
        target = cast(Mobject, self.mobject.copy())
        parts = target.submobjects
        if isinstance(target, VGroup) and len(parts) == 2 and isinstance(parts[0], Dot):
            parts[0].scale(self.scale_factor)
        else:
            target.scale(self.scale_factor)
        return target.set_color(self.color)


class Replace(Add):
    """A cut inside a play: ``new`` is on screen from the play's first frame and ``old`` off
    it then (the count: a fade from nothing left no count for its first frames, and taking
    the old one off before the play left none while a caption before it was still read)."""

    def __init__(self, new: Mobject, old: Mobject | None) -> None:
        super().__init__(new)
        self.old = old

    def _setup_scene(self, scene: Any) -> None:
        if scene is not None and self.old is not None:
            scene.remove(self.old)
        super()._setup_scene(scene)


def ear_test(board: Board, beat: EarTest) -> None:
    """The vertex tested pulses with its triangle: an ear's, empty, in the green of a correct
    result, up until its slice takes it (:func:`clip`); a vertex that is no ear shows why:
    its triangle in red with the vertex inside it pulsing too, or, not convex, its angle
    (:func:`angle_wedge`: its triangle had no area at a straight vertex, prune and search's
    H at 96 s, or lay outside the fruit at a reflex one), up for its own step only
    (:attr:`Board.passing`: left up, it lay under the gravity step's ✓ for the diagonal
    found next)."""
    _setup(board, beat)
    theme = board.theme
    colour = theme.result if beat.ear else theme.rejected
    gone: list[Playable] = [*board.drop(*_TEST)]
    corners = [board.at(p) for p in beat.triangle]
    angle = not beat.ear and beat.inside is None and len(corners) == 3
    wedge = angle_wedge(corners, theme, _room(board, corners[1])) if angle else None
    if beat.triangle:
        # the labels the triangle (or the angle) would lie over move clear of it first (a
        # pulse and a move of one marker in one play would cancel): a label on its red over
        # the fruit's orange was hard to read, and its edge ran through the keyhole's c₂;
        # apart from the others as the knife moves them (MAB's green moved M 0.07 under K);
        # moved aside off a red shape (it goes with the next words), they go back with it
        lines = covering(corners) if wedge is None else covering_wedge(wedge)
        moves = board.clear_labels(lines, apart=LABEL_APART, aside=not beat.ear, returning=True)
        if wedge is not None:  # the angle's own label stays by it, on a dark card: moved
            # off, G's went over its slot, nearer H's dot than its own
            own = board.markers[unprimed(beat.vertex)]
            moves = [m for m in moves if getattr(m, "mobject", None) is not own]
        if moves:
            board.scene.play(*gone, *moves, run_time=max(0.1, 0.4 * beat.pace))
            gone = []
    elif gone:  # the triangle before goes, and the labels moved aside off it come back
        gone += board.labels_aside_back(set())
    anims: list[Playable] = [*gone, Indicate(board.markers[unprimed(beat.vertex)], color=colour)]
    if wedge is not None:
        anims += _test_shape(board, wedge, covering_wedge(wedge), WEDGE_OPACITY)
    elif beat.triangle:
        anims += _test_triangle(board, beat.triangle, "result" if beat.ear else "rejected")
    if beat.inside:
        anims.append(Indicate(board.markers[unprimed(beat.inside)], color=theme.rejected,
                              scale_factor=1.6))
    board.play(beat, *anims, run_time=0.6 if beat.ear else 0.9)
    if not beat.ear:
        board.passes(*_TEST)


def _test_triangle(board: Board, triangle: Sequence[Point], role: str) -> list[Playable]:
    """The animations bringing in a tested vertex's triangle outlined and tinted in ``role``'s
    colour (an ear's green, a vertex that is no ear's red), and a dark card under a label
    left on it."""
    theme = board.theme
    colour = theme.role_colour(role)
    outline = tag(MPolygon(*[board.at(p) for p in triangle], color=colour,
                           stroke_width=theme.stroke * TEST_STROKE, fill_color=colour),
                  role, "ear-triangle")
    return _test_shape(board, outline, covering(outline.get_vertices()), TEST_OPACITY)


def _test_shape(board: Board, shape: MPolygon, lines: VGroup, opacity: float) -> list[Playable]:
    """The animations bringing in what a test shows (its triangle, or its angle), faded in
    to ``opacity`` under the vertices and their labels (the vertex inside a triangle is what
    the caption names, "G lies in its triangle", and a fade-in would put the triangle over
    it), and a dark card under a label an edge of it runs through (``lines``: :func:`covering`,
    all of it for a label without a halo)."""
    shape.set_fill(opacity=0).set_stroke(opacity=0)
    board.keep("ear-triangle", shape)  # what the test shows: it goes with the test
    board.scene.add(shape)
    anims: list[Playable] = []
    backing = _backing(board, lines, _outline_edges(shape))
    if backing is not None:  # an edge through a label left on it: a dark card
        board.keep("ear-backing", backing)
        board.scene.add(backing)
        anims.append(backing.animate.set_fill(opacity=BACKING_OPACITY))
    board.scene.bring_to_front(*board.markers.values())
    anims.append(shape.animate.set_fill(opacity=opacity).set_stroke(opacity=1.0))
    return anims


#: a not-convex vertex's angle mark (:func:`angle_wedge`): its largest radius (scene units,
#: 5 % of the frame's height), the part of its shorter edge it may reach along, of the room
#: to the nearest edge not its own, and the least it is drawn (under 2.7 % of the frame's
#: height, the ring round the dot is too thin to see at a glance)
WEDGE_RADIUS, WEDGE_REACH, WEDGE_ROOM, WEDGE_LEAST = 0.4, 0.7, 0.8, 0.22
#: the gap round the vertex's dot (its red dot on the red wedge vanished)
WEDGE_HOLE = 0.12
#: its fill's opacity: the rejected red at 0.3 over the fruit's orange reads as more orange
WEDGE_OPACITY = 0.6


def angle_wedge(corners: Sequence[np.ndarray], theme: Theme,
                room: float = math.inf) -> MPolygon:
    """The inside angle of the middle corner of ``corners`` (V−1, V, V+1 on screen, the ring
    counter-clockwise): a red sector round V (clear of its dot), from its edge to V+1 round
    through the inside to its edge to V−1, the reason a vertex that is not convex is no ear
    (180° at a straight vertex, more at a reflex one), seen where its triangle has no area.
    ``room``: how near V the nearest edge not its own comes (the sector keeps inside the
    fruit). Its outer arc first, then its inner arc back.

    >>> from metaphors.theme import THEME
    >>> w = angle_wedge([np.array(p, float) for p in ((-1, 0, 0), (0, 0, 0), (1, 0, 0))], THEME)
    >>> round(float(w.get_top()[1]), 2), round(float(w.get_bottom()[1]), 2)
    (0.4, 0.0)
    """
    a, v, c = (np.asarray(p, dtype=float)[:2] for p in corners)
    start = math.atan2(*(c - v)[::-1])
    sweep = (math.atan2(*(a - v)[::-1]) - start) % math.tau or math.tau
    shorter = min(float(np.linalg.norm(a - v)), float(np.linalg.norm(c - v)))
    radius = max(WEDGE_LEAST, min(WEDGE_RADIUS, WEDGE_REACH * shorter, WEDGE_ROOM * room))
    steps = max(8, math.ceil(math.degrees(sweep) / 10))
    turns = [start + sweep * k / steps for k in range(steps + 1)]
    arc = [(v[0] + r * math.cos(t), v[1] + r * math.sin(t), 0.0)
           for r, ts in ((radius, turns), (WEDGE_HOLE, turns[::-1])) for t in ts]
    return tag(MPolygon(*arc, color=theme.rejected, stroke_width=theme.stroke,
                        fill_color=theme.rejected, fill_opacity=WEDGE_OPACITY),
               "rejected", "ear-angle")


def _room(board: Board, at: np.ndarray) -> float:
    """How near ``at`` (a vertex of the fruit, on screen) the fruit's edges not ending there
    come."""
    p = np.asarray(at, dtype=float)[:2]
    near = math.inf
    for ring in board.outline_rings():
        for q, r in zip(ring, [*ring[1:], ring[0]], strict=True):
            q, r = np.asarray(q, dtype=float)[:2], np.asarray(r, dtype=float)[:2]
            if min(np.linalg.norm(q - p), np.linalg.norm(r - p)) < 1e-6:
                continue
            t = float(np.clip(np.dot(p - q, r - q) / max(float(np.dot(r - q, r - q)), 1e-12),
                              0, 1))
            near = min(near, float(np.linalg.norm(q + t * (r - q) - p)))
    return near


def covering_wedge(wedge: MPolygon) -> VGroup:
    """An angle's wedge (:func:`angle_wedge`) as lines a label must keep clear of: its sides,
    and the radii across it from its inner arc to its outer one (a label inside it meets
    one)."""
    ring = [np.asarray(p, dtype=float) for p in wedge.get_vertices()]
    half = len(ring) // 2
    lines = VGroup(*[Line(p, q) for p, q in zip(ring, [*ring[1:], ring[0]], strict=True)])
    lines.add(*[Line(ring[k], ring[len(ring) - 1 - k]) for k in range(1, half - 1)])
    return lines


#: the gap (scene units) between the lines that stand for a test triangle's inside
HATCH = 0.08


def covering(corners: Sequence[np.ndarray]) -> VGroup:
    """A triangle as lines a label must keep clear of (:meth:`Board.clear_labels`): its edges
    and, across it, lines parallel to its last edge :data:`HATCH` apart (a label inside it,
    which no edge meets, is covered too)."""
    a, b, c = (np.asarray(p, dtype=float) for p in corners)
    lines = VGroup(*[Line(p, q) for p, q in ((a, b), (b, c), (c, a))])
    u = c - b
    w = a - b
    height = abs(float(u[0] * w[1] - u[1] * w[0])) / max(float(np.linalg.norm(u[:2])), 1e-9)
    n = max(1, math.ceil(height / HATCH))
    lines.add(*[Line(a + (b - a) * k / n, a + (c - a) * k / n) for k in range(1, n)])
    return lines


#: what a test triangle shows, taken away with it
_TEST = ("ear-triangle", "ear-backing")
#: a backing's margin round its label (scene units) and its opacity
BACKING_PAD, BACKING_OPACITY = 0.04, 0.85


def _outline_edges(shape: MPolygon) -> list[tuple[np.ndarray, np.ndarray]]:
    """The edges of a test's shape (its triangle's three, its angle's arcs and sides)."""
    ring = [np.asarray(p, dtype=float) for p in shape.get_vertices()]
    return list(zip(ring, [*ring[1:], ring[0]], strict=True))


def _backing(board: Board, lines: VGroup,
             edges: Sequence[tuple[np.ndarray, np.ndarray]]) -> VGroup | None:
    """Dark cards (the background's colour, transparent until faded in) under the labels
    left on a test's shape that an edge of it (``edges``) still meets, or, a label without a
    dark halo, any of ``lines`` (:func:`covering`: its inside too), their markers where they
    stand now; None if none: a red label on the red triangle over the fruit's orange is hard
    to read, and an edge through a label reads as part of it. A haloed label inside the
    shape, clear of its edges, reads as every label on the fruit does: a card under it (ear
    clipping's G, inside B's triangle) was a box no other label had."""
    inside = Obstacles(segments=[(line.get_start(), line.get_end())
                                 for line in lines.submobjects])
    rim = Obstacles(segments=list(edges))
    cards = VGroup()
    for label, marker in sorted(board.markers.items()):
        if not isinstance(marker, VGroup) or len(marker) < 2:
            continue
        text = marker[1]
        box = rects_at(text.get_center()[:2], (text.width, text.height))
        haloed = text.get_stroke_width(background=True) > 0
        if (rim if haloed else inside).gaps(box)[0] >= MARGIN:
            continue
        card = Rectangle(width=text.width + 2 * BACKING_PAD, height=text.height + 2 * BACKING_PAD,
                         stroke_width=0, fill_color=board.theme.background, fill_opacity=0)
        cards.add(tag(card.move_to(text.get_center()), None, f"backing:{label}"))
    return tag(cards, None, "ear-backing") if len(cards) else None


#: a keyhole cut's width (of the theme's stroke): a slit, narrower than the knife that cut it
CUT_WIDTH = 1.6


def _shrunk(board: Board, beat: Slice) -> Playable:
    """The fruit shrinking to the rest after a slice. A fruit still drawn with its holes
    (three rings) first becomes, unseen, the one keyholed ring it is (its keyholes' dark
    slits show the same shape): morphed from three rings into one, it broke into shards and
    loose vertices for half a second (chapter 4 at 140.3 s, review s35)."""
    before, k = _with_ear(beat) if len(board.outline.get_subpaths()) > 1 else ([], 0)
    if before:
        board.outline.become(_fruit(board, before))
        # and to the rest as a ring of as many points, the ear's vertex sliding onto the
        # middle of its diagonal (one point fewer, the keyholed ring's bridges misaligned
        # and tore it as badly): clip puts the rest's own ring in after the play
        a, _, c = beat.points
        middle = ((a[0] + c[0]) / 2, (a[1] + c[1]) / 2)
        return Transform(board.outline, _fruit(board, [*before[:k], middle, *before[k + 1:]]))
    return Transform(board.outline, _fruit(board, beat.rest))


def _with_ear(beat: Slice) -> tuple[list[Point], int]:
    """The ring before ``beat``'s slice and where the ear's vertex stands in it: the rest
    with that vertex back between the ear's two other corners, either way round (a
    keyholed ring passes a bridge's ends twice, so the place is returned, not looked up);
    ([], 0) if they are not side by side in it."""
    a, b, c = ((float(p[0]), float(p[1])) for p in beat.points)
    rest = [(float(p[0]), float(p[1])) for p in beat.rest]
    for k, p in enumerate(rest):
        if {p, rest[(k + 1) % len(rest)]} == {a, c}:
            return [*rest[:k + 1], b, *rest[k + 1:]], k + 1
    return [], 0


def keyhole(board: Board, beat: Keyhole) -> None:
    """A hole opens to the rind: the knife cuts from the hole's vertex P to M, and the cut
    stays, a dark slit (:data:`CUT_WIDTH`), for the slicing to go round."""
    _setup(board, beat)
    theme = board.theme
    p, m = (board.at(q) for q in beat.points)
    knife = tag(Line(p, m, color=theme.knife, stroke_width=theme.stroke * 2), "called", "knife")
    # the background seen through the fruit, as through its holes (5.4 : 1 on the orange;
    # the rind's olive was 1.1 : 1, and the c₁–F cut all but vanished)
    cut = tag(Line(p, m, color=theme.background, stroke_width=theme.stroke * CUT_WIDTH),
              "result", f"keyhole:{beat.hole}")
    board.play(beat, Create(knife), Indicate(board.markers[beat.corners[0]], color=theme.result),
               run_time=0.8)
    # then, the cut made, what it is for (:attr:`Keyhole.then`), the one caption up
    then = "; ".join(w for w in (beat.then, beat.primes if board.panel.shows_calls else "") if w)
    said = replace(beat, caption=then) if then else beat
    board.play(said, FadeOut(knife), FadeIn(cut), *board.clear_labels(cut),
               *board.panel.draw(f"keyhole:{beat.hole}", *beat.points, None), run_time=0.5)
    board.keep(f"keyhole:{beat.hole}", cut)


#: the gap a label the knife moves aside keeps from the other labels: with the labels'
#: least (0.05), M, pushed in under K, stood 0.07 below it and read as one with it
LABEL_APART = 0.1


def clip(board: Board, beat: Slice) -> None:
    """The knife cuts along the ear's diagonal; the slice goes to its place on the plate."""
    _setup(board, beat)
    theme, data = board.theme, beat
    a, b, c = data.points
    knife = tag(Line(board.at(a), board.at(c), color=theme.knife, stroke_width=theme.stroke * 2),
                "called", "knife")
    # the ear's green triangle stays up while the knife cuts along its side
    board.play(beat, Create(knife), *board.clear_labels(knife, apart=LABEL_APART), run_time=0.6)
    piece = tag(MPolygon(*[board.at(p) for p in (a, b, c)], color=theme.rind,
                         stroke_width=theme.thin_stroke, fill_color=theme.fruit,
                         fill_opacity=0.9), "result", f"slice:{''.join(data.corners)}")
    target = piece.copy()
    x, width, height = plate_slot(data.k, data.total)
    target.scale_to_fit_width(min(width, target.width)).scale_to_fit_height(
        min(height, target.height))
    target.move_to((board.frame.center[0] + x, PLATE_Y, 0))
    counter = _counter(board, data.k, data.total)
    # the count is cut, not morphed (glyphs melting into each other read as other numbers)
    # nor faded in (a fade from nothing left no count in its first frames: at the fast
    # steps' pace, two frames of three): the old goes and the new is there in one frame
    # the ear's triangle goes as its slice is taken to the plate
    anims: list[Playable] = [*board.drop(*_TEST), Transform(piece, target), FadeOut(knife),
                             Replace(counter, board.objects.get("counter"))]
    board.keep("counter", counter)
    if data.rest:
        anims.append(_shrunk(board, data))
        anims += _sliced_off(board, data.rest)
        anims += _labels_off_fruit(board, data.rest)
        # the panel's polygon is what is left of the fruit too (it kept the sliced vertices)
        anims += board.panel.slice_off(*_with_ear(data), data.rest)
    else:  # the last slice: the keyhole cuts go (no fruit is left round them); the fruit's
        # last triangle stays while its caption is read, until the whole triangulation
        anims += board.drop(*[key for key in board.objects if key.startswith("keyhole:")])
    anims += _good_shrinks(board, data.good)
    board.scene.add(piece)
    board.play(beat, *anims, run_time=1.0)
    if data.rest:  # the same shape, as the rest's own ring (:func:`_shrunk`)
        board.outline.become(_fruit(board, data.rest))
        board.panel.settle_outline()
    board.keep(f"slice:{data.k}", piece)
    if data.triangulation:
        _whole(board, beat)


def _sliced_off(board: Board, rest: Sequence[Point]) -> list[Playable]:
    """The markers of the vertices the slice takes off the fruit (none of ``rest``'s points,
    what is left: a keyhole's vertex stays while a copy of it is on the ring), fading where
    they stand: left up, they floated round the shrinking fruit, and turned with it; sent
    with the slice to the plate, A's label flew over G's (ear clipping at 7 s). Kept aside
    (:attr:`Board.off`) for the whole triangulation."""
    left = {(round(x, 9), round(y, 9)) for x, y in rest}
    gone = [label for label in board.markers
            if tuple(round(c, 9) for c in board.where[label]) not in left]
    for label in gone:
        board.off[label] = board.markers.pop(label)
        board.roles.pop(label, None)
    return [FadeOut(board.off[label], scale=0.5) for label in gone]


def _labels_off_fruit(board: Board, rest: Sequence[Point]) -> list[Playable]:
    """The moves, with a slice, of the labels left over the fruit (``rest``: what is left of
    it) that find room outside it now (:func:`metaphors.labels.off_the_fill`), clear of the
    lines on the picture (the keyhole cuts, the good part's edge): a hole's label stood on
    the orange, on its dark halo, while the hole had no room for it, and stayed there once
    the slices round its vertex had left the dark all round it (chapter 4's a₂ and b₂)."""
    labels = {name: (m[0].get_center(), area_of(m[1]))
              for name, m in board.markers.items() if isinstance(m, VGroup) and len(m) > 1}
    lines = [edge for m in board.objects.values() if m is not board.outline
             for edge in drawn_edges(m)]
    moves: list[Playable] = []
    for name, centre in off_the_fill([board.at(p) for p in rest], labels, lines,
                                     board.theme.dot_radius).items():
        moved = board.markers[name].copy()
        move_label(moved, centre)
        moves.append(Transform(board.markers[name], moved))
    return moves


def _markers_back(board: Board) -> list[Mobject]:
    """The sliced-off markers back on the board (:func:`_sliced_off`), at their vertices (the
    picture may have turned and zoomed since they went) and in the ink of the ending, still
    off screen: to come in with the whole triangulation."""
    back = []
    for label, marker in sorted(board.off.items()):
        marker.shift(board.vertex(label) - marker[0].get_center())
        marker.set_color(board.theme.ink)
        board.markers[label] = tag(marker, "idle")
        back.append(marker)
    board.off = {}
    return back


def _placed(moves: list[Playable], unseen: Sequence[Mobject]) -> list[Playable]:
    """``moves`` (:meth:`Board.clear_labels`' transforms) but those of the ``unseen`` markers,
    which are made at once (they fade in where they stand: a fade in and a move of one marker
    in one play would cancel one of them)."""
    kept: list[Playable] = []
    for move in moves:
        marker = next((m for m in unseen if getattr(move, "mobject", None) is m), None)
        if isinstance(move, Transform) and marker is not None:
            marker.become(move.target_mobject)
        else:
            kept.append(move)
    return kept


def _whole(board: Board, beat: Slice) -> None:
    """After the last slice: every slice back in its place in P, the whole triangulation, and
    the count it had to reach (n − 2, with two more per hole)."""
    theme = board.theme
    pieces = triangulation_pieces(beat.triangulation, board.at, theme)
    holes = len(board.holes)
    n = board.polygon.n + sum(len(h.points) for h in board.holes)
    result = _counter_text(board, count_words(n, holes, beat.total), theme.result)
    # cut in where the last count stood (:func:`clip`): 11 / 11 is up until this replaces it
    # (taken off here, it was gone while the last slice's caption was still read)
    shown = Replace(result, board.objects.get("counter"))
    board.keep("counter", result)
    board.keep("triangulation", VGroup(*pieces))
    # every vertex is one again: the sliced-off ones come back with the triangles
    back = _markers_back(board)
    # under its own caption, at full pace: the last slice's words are over; what the steps
    # left (prune and search's good part, its last diagonal and ✓) goes. The caption comes
    # with the triangulation it counts (``together``): led by its words, "The whole
    # triangulation: 11 triangles" stood half a second over the last slice (review)
    board.play(ending_beat(beat, board.panel.pseudocode, beat.total, board.panel.run_call,
                           holes),
               *board.drop("good", *_FOUND), FadeOut(board.outline),
               *[FadeIn(p) for p in pieces], shown, *[FadeIn(m) for m in back],
               *board.panel.whole(beat.triangulation),
               *_placed(board.clear_labels(*pieces, near=EDGE_MARGIN), back),
               run_time=1.2, at_rest=True, together=True)
    board.scene.wait(1.0)




#: what a diagonal's search leaves on the picture (:mod:`metaphors.basics`): its claim and verdict
_FOUND = ("claim", "verdict", "crossed", "crossing")


def _good_region(board: Board, points: Sequence[Point]) -> MPolygon:
    return tag(MPolygon(*[board.at(p) for p in points], **good_style(board.theme)), "called",
               "good")


def _good_shrinks(board: Board, points: Sequence[Point]) -> list[Playable]:
    """The good sub-polygon's tint after a slice: it shrinks with the fruit (the slice was
    cut from it, :func:`geometry.prune_search.clip_middle_ear`), or goes with the slice
    that leaves it only its cutting edge (the search goes on in the polygon round it). On
    screen past that, it lay over fruit already on the plate, and over no fruit at all
    once the last slice was cut."""
    if "good" not in board.objects:
        return []
    if len(points) < 3:
        return [*board.drop("good")]
    return [Transform(board.objects["good"], _good_region(board, points)),
            *board.panel.tint("good", points)]


def good(board: Board, beat: Good) -> None:
    """Prune and search: the good sub-polygon kept, tinted; the previous one fades, and so do
    the vertex found no ear (its red triangle) and the diagonal found and its ✓: the good
    part's edge is that diagonal now (left on screen, the next search's claim would take
    their keys and leave them behind, unturned)."""
    region = _good_region(board, beat.points)
    # the panel tints it too (board.drop takes the panel's last one with the picture's)
    board.play(beat, *board.drop("good", *_TEST, *_FOUND), FadeIn(region),
               *board.panel.tint("good", beat.points), run_time=1.2)
    board.keep("good", region)


# --- what ear clipping reads from the log --------------------------------------------------------


@beat_kind("keyhole")
class Keyhole(Beat):
    """Hole ``hole`` joined to the ring at ``corners[1]`` by the cut ``corners[0]``–``corners[1]``
    (its ``points``): the keyhole of ear clipping with holes."""

    hole: int
    corners: tuple[str, str]
    points: tuple[Point, Point]
    #: the words said once the cut is made (what it is for), after the caption said while the
    #: knife cuts (which cut, from where to where); empty: the caption stays
    then: str = ""
    #: what the ring names the cut's ends past it (``c₂′``, ``F′``), said after ``then`` only
    #: where a call line shows those names (a scene's, ``clip_ear(c₁′, F″, c₂)``): the
    #: picture labels each vertex once, and the lecture, with no call line, said names that
    #: were nowhere on screen (chapter 4 at 153 s)
    primes: str = ""


@beat_kind("ear-test")
class EarTest(Beat):
    """Is ``vertex`` an ear (``ear``)? Its ``triangle`` (points: an ear's, empty, or the one
    that shows why the vertex is not; empty when not found on the fruit) and, not an ear,
    the vertex ``inside`` it (None when the vertex is not convex)."""

    vertex: str
    ear: bool
    triangle: tuple[Point, ...]
    inside: str | None


@beat_kind("clip")
class Slice(Beat):
    """Slice ``k`` of ``total`` cut off at ``corners``; ``rest`` is what is left of the fruit;
    ``good``, prune and search's good sub-polygon the slice was cut from, as it is left
    (its points; fewer than three once only its cutting edge is left; empty in ear clipping,
    or where the search is in the whole polygon)."""

    corners: tuple[str, ...]
    points: tuple[Point, ...]
    k: int
    total: int
    rest: tuple[Point, ...]
    triangulation: tuple[tuple[Point, ...], ...]  # after the last slice, every slice's corners' points; else empty
    good: tuple[Point, ...] = ()


@beat_kind("last-slice")
class LastSlice(Slice):
    """The triangle left over at the end: the last slice."""


@beat_kind("good")
class Good(Beat):
    """Prune and search keeps a good sub-polygon (its points and labels)."""

    points: tuple[Point, ...]
    labels: tuple[str, ...]


def unprimed(label: str) -> str:
    """The vertex a slot's label names: a bridge end's copies (``D′``, ``D″`` …) are ``D``."""
    return label.rstrip("′″‴⁰¹²³⁴⁵⁶⁷⁸⁹")


def read_ear_test(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    v, ear = walk.ref(call, "v"), bool(ret.result)
    triangle = _triangle(walk, v)
    why = None if ear or triangle is None else _why_not(triangle)
    if ear:  # both conditions (issue 22 item 11): a reflex vertex's triangle may be empty
        caption = f"Is {v} an ear? yes: {v} is convex and its triangle holds no other vertex"
    elif why is None:  # not found on the fruit as it stands (never seen): say it plainly
        caption = f"Is {v} an ear? no: a cut between its neighbours is not a clean slice"
    elif why[1] is None:  # its angle, drawn (:func:`angle_wedge`), says why
        caption = f"Is {v} an ear? no: {v} is not convex, its angle is {_angle_words(why[0])}"
    else:
        caption = f"Is {v} an ear? no: {why[1]} lies in its triangle"
    roles = {unprimed(v): "result" if ear else "rejected"}
    if why is not None and why[1] is not None:
        roles[unprimed(why[1])] = "rejected"
    shown = triangle[0] if triangle is not None and (ear or why is not None) else ()
    yield walk.call_beat(EarTest, caption, call, ret, roles=roles, vertex=v, ear=ear,
                         triangle=points_of(shown), inside=why[1] if why else None)


def _ring(walk: Walk) -> tuple[list[str], list]:
    """The fruit's ring before any slice: P's labels and points, or with holes the ring its
    keyholes made (kept: it has exited by the last slice)."""
    labels, points = walk.root_polygon()
    kept = walk.memo("fruit.keyhole", dict)
    if "keyhole" in walk.live:
        kept.update(walk.live["keyhole"])
    if kept:
        labels, points = kept["labels"], kept["points"]
    return labels, points


#: a vertex's triangle on the fruit as it stands: its corners' points, and the points of
#: the fruit's other vertices, by label
_Triangle = tuple[list, dict[str, Any]]


def _triangle(walk: Walk, v: str) -> _Triangle | None:
    """``v``'s triangle on the fruit as it stands (``v`` and its neighbours) and the fruit's
    other vertices; None if ``v`` is not on it."""
    labels, points = _ring(walk)
    gone = {c[1] for c in walk.memo("fruit.clipped", list)}
    ring = [k for k, label in enumerate(labels) if label not in gone]
    if v not in labels or labels.index(v) not in ring:
        return None
    at = ring.index(labels.index(v))
    corners = [ring[at - 1], ring[at], ring[(at + 1) % len(ring)]]
    others = {labels[k]: points[k] for k in ring if k not in corners}
    return [points[k] for k in corners], others


def _angle_words(corners: Sequence[Any]) -> str:
    """How a not-convex vertex's inside angle is said: "180°" at a straight vertex (its
    neighbours and it on one line, exactly), else "over 180°"."""
    return "180°" if orient(*corners) == 0 else "over 180°"


def _why_not(triangle: _Triangle) -> tuple[list, str | None] | None:
    """Why a vertex is no ear: its triangle's points and a vertex in the closed triangle, or
    None there when the vertex is not convex; None if neither is found."""
    (a, b, c), others = triangle
    if orient(a, b, c) <= 0:
        return [a, b, c], None
    inside = next((label for label, q in others.items() if in_closed_triangle(q, a, b, c)), None)
    return ([a, b, c], inside) if inside is not None else None


def read_join_hole(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    p, m = (show(r) for r in walk.result_list(ret))
    hole = int("".join(ch for ch in p if ch in "₀₁₂₃₄₅₆₇₈₉").translate(_DIGITS))
    point_of = walk.root_points()
    caption, then = _keyhole_words(walk.memo("fruit.holes cut", list), hole, p, m)
    copies = _far_side(walk, ret, p)
    # the call lines name them (clip_ear(c₁′, F″, c₂)): said once, where they are shown
    primes = (f"past the cut, {p} and {m} are named {copies[0]} and {copies[1]}"
              if copies is not None else "")
    yield walk.call_beat(Keyhole, caption, call, ret,
                         roles={p: "result", m: "result"}, hole=hole, corners=(p, m),
                         points=(point(point_of[p]), point(point_of[m])), then=then,
                         primes=primes)


def _keyhole_words(cut: list[int], hole: int, p: str, m: str) -> tuple[str, str]:
    """What a keyhole cut from ``p`` to ``m`` is, said while the knife cuts, and what it is
    for, said once it is made: the first says the rule (each hole, the right-most first, cut
    from its right-most vertex to a vertex it sees) and why (one ring, which ear clipping
    slices); the next holes, the rule again, shorter. ``cut``: the holes cut so far in the
    run (appended to). Before, "Hole 2: a keyhole cut from c₂ to F" showed the cut and never
    said what it was or why.

    >>> _keyhole_words([], 2, "c₂", "F")[0]
    'Hole 2, the right-most, first: a keyhole cut from its right-most vertex c₂ to F, a rind vertex it sees'
    """
    first = not cut
    cut.append(hole)
    if first:
        return (f"Hole {hole}, the right-most, first: a keyhole cut from its right-most "
                f"vertex {p} to {m}, a rind vertex it sees",
                "Hole and rind are now one ring, which the knife slices as before")
    return (f"Then hole {hole}: a keyhole cut from its right-most vertex {p} to {m}, a vertex "
            "it sees", "One ring again")


def _far_side(walk: Walk, ret: Event, p: str) -> tuple[str, str] | None:
    """The labels the fruit's ring gives the ends of the keyhole cut from ``p`` on its far
    side (the ring passes the cut twice: ``… M, P, (the hole), P′, M′ …``,
    :mod:`geometry.bridges`), as the keyhole the run slices enters the log; None if it
    does not."""
    ring = walk.entered_after(ret, "keyhole").get("labels") or []
    far = next((k for k, label in enumerate(ring) if label != p and unprimed(label) == p), None)
    if far is None:
        return None
    return ring[far], ring[(far + 1) % len(ring)]


def read_clip(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """A slice cut off (``clip_ear``), or at the end of the run the triangle left over."""
    labels, points = _ring(walk)
    if not labels:
        return
    clipped = walk.memo("fruit.clipped", list)  # the ears cut so far
    if ret.name == "clip_ear":
        corners = [show(r) for r in walk.result_list(ret)]
        kind = Slice
    else:
        gone = {c[1] for c in clipped}
        corners = [x for x in labels if x not in gone]
        if len(corners) != 3:
            return
        kind = LastSlice
    clipped.append(corners)
    caption = f"Slice {named_together(corners)}: {len(clipped)} / {len(labels) - 2} slices"
    if len(clipped) == 1:  # the plate is said once, as the first slice goes onto it
        caption = (f"Slice {named_together(corners)} off, onto the plate: "
                   f"1 / {len(labels) - 2} slices")
    fields = _slice(corners, labels, points, clipped)
    fields["good"] = _good_left(walk)
    if kind is Slice:
        yield walk.call_beat(kind, caption, call, ret, **fields)
        walk.count_claim("slice")  # after its beat: the beat belongs to the slice it cuts
    else:  # the run's own call: its result is said at the end, counted
        # (metaphors.drawing.ending_beat), not here as index triples
        yield walk.beat(kind, caption, call, call=call_line(call, None),
                        roles=call_roles(call, ret), **fields)


def _slice(corners: list[str], labels: list[str], points: list,
           clipped: list[list[str]]) -> dict[str, Any]:
    where = dict(zip(labels, points, strict=True))
    gone = {c[1] for c in clipped[:-1]}
    return {
        "corners": tuple(corners),
        "points": points_of(where[c] for c in corners),
        "k": len(clipped),
        "total": len(labels) - 2,
        # what is left of the fruit once this slice is off (empty after the last one)
        "rest": points_of(where[x] for x in labels if x not in gone | {corners[1]})
        if len(clipped) < len(labels) - 2 else (),
        "triangulation": tuple(points_of(where[c] for c in cut) for cut in clipped)
        if len(clipped) == len(labels) - 2 else (),
    }


def _good_left(walk: Walk) -> tuple[Point, ...]:
    """The points of the innermost good sub-polygon shown (:func:`read_good`) as the log
    has it now, after a slice (it shrinks, ``change``): empty once it has exited, or when
    none was shown (ear clipping; prune and search searching the whole polygon)."""
    for key in reversed(walk.memo("fruit.good", list)):
        if key in walk.live:
            return points_of(walk.live[key].get("points", []))
    return ()


def read_good(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    walk.memo("fruit.good", list).append(walk.result_ref(ret))
    state = walk.entered_after(ret, walk.result_ref(ret))
    yield walk.call_beat(Good, "A good sub-polygon: one cut edge, about half the vertices; "
                         "its middle vertex is tested next", call, ret,
                         points=points_of(state["points"]), labels=tuple(state["labels"]))


READS: Mapping[str, Reading] = {
    "is_ear": read_ear_test, "clip_ear": read_clip, "ear-clipping": read_clip,
    "ear-clipping-naive": read_clip, "prune-and-search": read_clip,
    "good_subpolygon": read_good,
    "join_hole": read_join_hole}
PERFORMS: Performances = performs(act(EarTest, ear_test), act(Keyhole, keyhole),
                                  act(Slice, clip), act(LastSlice, clip), act(Good, good))
