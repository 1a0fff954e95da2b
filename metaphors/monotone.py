"""Monotone partition (Garey et al.): a horizontal line sweeps down, vertices are classified,
split and merge vertices get diagonals, the pieces are y-monotone, a stack triangulates each.

Positions, kinds, diagonals, pieces, the stack's chain at every step and the triangles come
from the log (the beats' data). Each split and merge vertex, and each diagonal, is a key
step: never fast-forwarded. Split and merge vertices have colours of their own
(:mod:`metaphors.theme`), never the red of "fails".
"""

from __future__ import annotations

import weakref
from collections.abc import Iterator, Mapping, Sequence
from itertools import pairwise

import numpy as np
from manim import (
    RIGHT,
    Animation,
    Create,
    DashedLine,
    Dot,
    FadeIn,
    FadeOut,
    Indicate,
    Line,
    Rectangle,
    Transform,
    VGroup,
    VMobject,
    linear,
    smooth,
)
from manim import Polygon as MPolygon
from shapely.geometry import Polygon as Region
from shapely.geometry import box
from shapely.geometry.base import BaseGeometry
from shapely.ops import unary_union

from metaphors.board import Board
from metaphors.drawing import count_words, ending_beat, neighbour_shades, triangulation_pieces
from metaphors.layout import (
    FRAME_AREA,
    SUBTITLE_TOP,
    Obstacles,
    Segment,
    area_of,
    areas_of,
    call_line_area,
    clear,
    free_place,
    grid,
    rects_at,
    ring_edges,
    subtitle_band,
    title_area,
)
from metaphors.performing import Performances, act, performs
from metaphors.sweep import around_labels
from metaphors.tags import tag
from rendering.typeset import text
from story.beats import Beat, Point, beat_kind, point, points_of
from story.storyboard import Reading, Walk
from story.words import named_together
from tracing import Event

#: the room between the stack's words (scene units)
STACK_BUFF = 0.12
#: how far the count n − 2 keeps from everything else on screen: a label beside it is not
#: read as its first word (scene units)
COUNT_GAP = 0.35
#: the sweep line's length (scene units), centred on the picture
SWEEP_WIDTH = 5.8
#: the gap the sweep line leaves round every vertex label (scene units), above and below it:
#: the tools' 0.04 let its dashes run up to M's and K's letters at their height, read as
#: struck through (chapter 5 at 28 s); 0.12, a label's gap from its edges
#: (:data:`metaphors.labels.EDGE_MARGIN`), still ran along the top of A's letter at L's
#: height (16–19 s): 0.18
SWEEP_LABEL_GAP = 0.18
#: the gap it leaves beside a label it passes at the label's height (scene units): 0.12 each
#: side of K and M (7 px at 480p) still read as a line through the letter (22.7–30 s); about
#: two letters' width, the label stands in a clear break of the line
SWEEP_LABEL_SIDE_GAP = 0.4
#: the gaps a kind word ("split", "merge" …) keeps from every label, dot and line, the
#: largest that fits (scene units): nearer than 0.12 to a label, the two read as one word
#: ("Gregular"); 0.18 keeps 0.12 diagonally off a label's corner too
KIND_GAPS = (0.18, 0.12)
#: the farthest a kind word's box stands from its vertex's dot (scene units), tried in turn:
#: 0.6 (7.5 % of the frame's height) beside it, else 1.0 where a crowded vertex (the left-most,
#: at the frame's margin) has no room nearer; farther, it is read as nobody's, and none is shown
KIND_REACH = (0.6, 1.0)
#: the farthest a kind word's box stands from its vertex as drawn, its dot or its label, where
#: it can (3.75 % of the frame's height): farther, it is read as nobody's (the reading rule's)
KIND_BESIDE = 0.3
#: every other vertex's dot and label stand at least this many times as far from the kind word
#: as its own vertex as drawn (its dot or its label): the word is read as its vertex's ("start"
#: between A and L was read as L's, "regular" between B and b₁'s label as b₁'s)
KIND_OWN = 1.5
#: each board's place for its stack (left, top, and whether it is a row), found once a run
_PLACES: weakref.WeakKeyDictionary[Board, tuple[float, float, bool]] = (
    weakref.WeakKeyDictionary())


def _sweep_line(board: Board, y: float) -> VGroup:
    """The dotted sweep line at ``y`` (P's coordinates), with a gap of
    :data:`SWEEP_LABEL_GAP` round every vertex label it would run through
    (:func:`metaphors.sweep.label_gaps`), under the labels (:data:`metaphors.board.LABEL_Z`):
    it may cross its own vertex's dot, never a label."""
    theme = board.theme
    x0, at = _sweep_span(board, y)
    labels = _sweep_gaps(board)
    group = VGroup(*[tag(DashedLine((p[0], p[1], 0), (q[0], q[1], 0), color=theme.sweep,
                                    stroke_width=theme.thin_stroke), "called", "sweep:line")
                     for p, q in around_labels([((x0, at), (x0 + SWEEP_WIDTH, at))], labels)])
    if not group.submobjects:  # keeps a transform happy: always one (empty) piece
        group.add(Line((x0, at, 0), (x0, at, 0), stroke_opacity=0))
    # the group's own colour too (its pieces have it already): one dotted line, not white
    return tag(group.set_stroke(theme.sweep, theme.thin_stroke, family=False), "called", "sweep")


def _sweep_gaps(board: Board) -> BaseGeometry:
    """Where the sweep line leaves a gap: every vertex label's box grown by
    :data:`SWEEP_LABEL_GAP` above and below and :data:`SWEEP_LABEL_SIDE_GAP` beside it (a
    line at a label's height ends far enough from it not to read as striking it)."""
    return unary_union([box(left - SWEEP_LABEL_SIDE_GAP, bottom - SWEEP_LABEL_GAP,
                            right + SWEEP_LABEL_SIDE_GAP, top + SWEEP_LABEL_GAP)
                        for left, bottom, right, top in
                        (area_of(marker[-1]) for marker in board.markers.values())])


def _sweep_span(board: Board, y: float) -> tuple[float, float]:
    """The sweep line's left end and height on screen, at ``y`` (P's coordinates)."""
    return board.frame.center[0] - SWEEP_WIDTH / 2, float(board.at((0.0, y))[1])


def _kind_place(board: Board, kind: VMobject, vertex: str, y: float) -> np.ndarray | None:
    """Where the kind word of ``vertex`` stands: the nearest place to its vertex as drawn,
    its dot or its label (on a grid, :func:`metaphors.layout.grid`, measured to the word's
    box), then to its dot, within
    :data:`KIND_REACH` of its dot that keeps every other vertex's dot and label :data:`KIND_OWN`
    times as far as its own, and a
    gap of :data:`KIND_GAPS` from every vertex label and dot, every edge and diagonal drawn, the
    sweep line at ``y``, the title and the panel, outside P's convex hull (in a notch or slot
    of P it reads as written on P), on screen above the subtitle; None where there is none
    (:func:`_kind_key` says it beside the picture)."""
    theme = board.theme
    dot = board.markers[vertex][0].get_center()[:2]
    size = (float(kind.width), float(kind.height))
    rings = board.outline_rings()
    edges: list[Segment] = [edge for ring in rings for edge in ring_edges([p[:2] for p in ring])]
    edges += [(m.get_start()[:2], m.get_end()[:2]) for name, m in board.objects.items()
              if isinstance(m, Line) and name.startswith("diagonal:")]
    # and the labels' leaders (:func:`metaphors.labels.leader`)
    edges += [(m[2].get_start()[:2], m[2].get_end()[:2]) for m in board.markers.values()
              if len(m.submobjects) > 2]
    x0, at = _sweep_span(board, y)
    edges.append(((x0, at), (x0 + SWEEP_WIDTH, at)))
    boxes = [area_of(marker[1]) for marker in board.markers.values()]
    boxes += [area_of(m) for m in (board.title, *board.panel.mobjects())]
    dots = [(*marker[0].get_center()[:2], theme.dot_radius) for marker in board.markers.values()]
    reach = max(KIND_REACH)
    window = (dot[0] - reach - size[0], dot[1] - reach - size[1],
              dot[0] + reach + size[0], dot[1] + reach + size[1])
    centres = grid(window, size)
    own = Obstacles(dots=[(*dot, 0.0)]).gaps(rects_at(centres, size))
    # the nearest to the vertex as drawn, its dot or its label, first: nearest its dot
    # alone, "regular" stood in the slot left of I, 0.35 from I's label and 0.45 from its
    # dot, read as nobody's, where beside I's label it was as near the dot
    marker = Obstacles(dots=[(*dot, 0.0)], boxes=[area_of(board.markers[vertex][1])])
    beside = marker.gaps(rects_at(centres, size))
    order = np.lexsort((np.round(own, 6), np.round(beside, 6)))  # the nearest first
    centres, own, beside = centres[order], own[order], beside[order]
    others = Obstacles(boxes=[area_of(m[1]) for v, m in board.markers.items() if v != vertex],
                       dots=[(*m[0].get_center()[:2], 0.0) for v, m in board.markers.items()
                             if v != vertex])
    ours = clear(centres, size, others, KIND_OWN * beside)
    # P's hull too: a word over P's fill is text over the picture (review s35: "merge" stood
    # on the fill beside M, "split" beside D), and so is one in a notch or slot of P, whose
    # dark hardly differs from P's faint fill (teacher review, faster9: "regular" in the slot
    # by I at 52 s and by F at 64 s, "merge" in K's notch at 42 s, "split" in D's, all read as
    # written on P); outside the hull, the edges' gap keeps it off them
    region = Region([p[:2] for p in rings[0]]).convex_hull
    obstacles = Obstacles(boxes=boxes, segments=edges, dots=dots, shapes=[region])
    within = (FRAME_AREA[0], SUBTITLE_TOP, FRAME_AREA[2], FRAME_AREA[3])
    free = [ours & clear(centres, size, obstacles, gap, within) for gap in KIND_GAPS]
    for most in KIND_REACH:
        # beside its dot or label, at the smaller gap if it must: at the larger gap first,
        # "regular" went 0.35 off I, into the slot, where 0.13 right of I's label was free;
        # never farther (chapter 5's "end" stood 0.52 off C, by the subtitle, read as
        # nobody's): with no room, the caption alone names the kind
        for near in (KIND_BESIDE,):
            for ok in free:
                ok = ok & (own <= most + 1e-9) & (beside <= near + 1e-9)
                if ok.any():
                    return np.array([*centres[int(np.argmax(ok))], 0.0])
    return None


def classify(board: Board, beat: Classify) -> None:
    """The sweep line reaches a vertex; the vertex shows its kind, in a clear place beside
    it (:func:`_kind_place`), until the next beat's words come."""
    theme, data = board.theme, beat
    line = _sweep_line(board, data.at[1])
    # lower-case words ("merge": no letter above the x-height): four sizes up from the
    # labels keeps them 2.5 % of the frame high, as the holes' labels are
    kind = tag(text(data.kind, font=theme.font, size=theme.label_size + 4,
                    colour=theme.role_colour(_kind_role(data.kind))), None, "kind")
    # a summary's fast step ("Vertices 7–10: the same steps, faster") names no vertex: its
    # word would flash by, too fast to read, so there is none
    named = beat.caption.startswith(f"{data.vertex}:")
    place = _kind_place(board, kind, data.vertex, data.at[1]) if named else None
    # the pulse in the vertex's own colour (blue, the one looked at; cyan or pink, a split or
    # merge vertex), as the panel shows it: manim's yellow pulse was read as a colour of its own
    colour = theme.role_colour(_kind_role(data.kind))
    anims: list[Animation] = [
        Indicate(board.markers[data.vertex], color=colour)]
    shown: VMobject | None = kind.move_to(place) if place is not None else None
    if shown is None and named:
        # no room beside it outside P's hull (M and K in their notches, I and F by the slot,
        # D by its notch): the kind said beside the picture, a split or merge vertex's as a
        # legend entry of its colour, the vertex lit in it; another's with its vertex named
        # ("I: regular vertex"): its blue is the vertex looked at, no kind's colour
        shown = _kind_key(board, data.kind, data.vertex, line)
    if shown is not None:  # None: no room, no word (the caption names the kind)
        anims.append(FadeIn(shown))
    # an edge that ends at this vertex leaves the line, and its helper with it
    anims += board.drop(*[key for key in board.objects
                          if key.startswith("helper:") and key.rsplit("–", 1)[-1] == data.vertex])
    if "sweep" in board.objects:
        anims.append(Transform(board.objects["sweep"], line))
    else:
        board.keep("sweep", line)
        anims.append(Create(line))
    # a summary's steps share its caption's reading time: each seen, none flashing by
    board.play(beat, *anims, run_time=0.8, least=0.0 if named else board.shared_time(beat))
    if shown is not None:  # up while its caption is read: it goes with the next beat's words
        board.leaving.append(shown)


#: the least gap between a kind's note beside the picture and any vertex label (scene units):
#: nearer, it is read as that vertex's (the reading rule's :data:`KIND_NOTE_OFF_LABELS`)
NOTE_OFF_LABELS = 0.5


def _kind_key(board: Board, kind: str, vertex: str, sweep: VGroup) -> VGroup | None:
    """The legend entry of a split or merge vertex (a dot in its colour, "merge vertex"), or
    the note of another kind, its vertex named ("I: regular vertex", in the blue of the vertex
    looked at: no swatch, which would make that blue a kind's), in the first free place
    beside the picture (:func:`metaphors.layout.free_place`, clear of what the stack keeps
    clear of, :func:`_taken`, of the sweep line and of the title's whole line: beside a short
    title it reads as part of it), None if none is."""
    theme = board.theme
    role = _kind_role(kind)
    colour = theme.role_colour(role)
    if role == "called":
        words = text(f"{vertex}: {kind} vertex", font=theme.font, size=theme.label_size + 2,
                     colour=colour)
        key = tag(VGroup(words), None, "legend:kind")
    else:
        words = text(f"{kind} vertex", font=theme.font, size=theme.label_size + 2,
                     colour=theme.ink)
        swatch = tag(Dot(radius=theme.dot_radius * 1.8, color=colour), kind, "legend:swatch")
        key = tag(VGroup(swatch, words.next_to(swatch, RIGHT, buff=0.15)), None, "legend:kind")
    drawn = [box(*area_of(piece)) for piece in sweep.submobjects]
    title = box(*title_area(board.title, whole_line=True))
    # and P's hull: in its slot, "F: regular vertex" was as much on the picture as "regular";
    # and room round every label: by L's, "F: regular vertex" read as L's (64 s)
    hull = Region([tuple(board.at(p)[:2]) for p in board.polygon.points]).convex_hull
    labels = [box(*area_of(marker[1])).buffer(NOTE_OFF_LABELS) for marker in board.markers.values()]
    found = free_place(key.width, key.height,
                       unary_union([_taken(board), title, hull, *drawn, *labels]))
    if found is None:
        return None
    left, top = found
    return key.move_to((left + key.width / 2, top - key.height / 2, 0))


#: the gap a helper's segment leaves round every vertex label it would run through (scene
#: units): a label's gap from its edges (:data:`metaphors.labels.EDGE_MARGIN`)
HELPER_LABEL_GAP = 0.12


def helper(board: Board, beat: Helper) -> None:
    """``vertex`` becomes the helper of ``edge``: the edge drawn thick and the horizontal
    segment from the vertex to it solid, both in the sweep's colour, over the dotted sweep
    line (the textbook's definition drawn: the segment lies inside P, and no vertex yet seen
    sees the edge from lower down). It stays while that vertex helps that edge; the next
    helper of the edge takes its place."""
    drawn = _helper_drawing(board, beat)
    key = _helper_key(beat.edge)
    anims: list = [_replace(board, key, drawn)]
    anims.append(Indicate(board.markers[beat.vertex], color=board.theme.sweep))
    least = 0.0 if beat.pace >= 1.0 else board.shared_time(beat)
    board.play(beat, *anims, run_time=0.9, least=least)


def _helper_key(edge: tuple[str, str]) -> str:
    """The key a helper's drawing is kept under: its edge's (``helper:A–B``)."""
    return f"helper:{edge[0]}–{edge[1]}"


def _helper_drawing(board: Board, beat: Helper) -> VGroup:
    """The edge, thick, and the segment from the vertex straight to it, each with a gap
    round every vertex label it would run through."""
    theme = board.theme
    labels = unary_union([box(*area_of(marker[-1])).buffer(HELPER_LABEL_GAP, join_style="mitre")
                          for marker in board.markers.values()])
    top, bottom = (board.vertex(v)[:2] for v in beat.edge)
    seen = (board.vertex(beat.vertex)[:2], board.at(beat.meets)[:2])
    parts = [tag(Line((*p, 0), (*q, 0), color=theme.sweep, stroke_width=theme.stroke * 2.2),
                 "called", "helper:edge") for p, q in around_labels([(tuple(top), tuple(bottom))], labels)]
    parts += [tag(Line((*p, 0), (*q, 0), color=theme.sweep, stroke_width=theme.stroke * 1.3),
                  "called", "helper:sight") for p, q in around_labels([(tuple(seen[0]), tuple(seen[1]))], labels)]
    group = VGroup(*parts)
    if not group.submobjects:  # keeps a transform happy: always one (empty) piece
        group.add(Line((*top, 0), (*top, 0), stroke_opacity=0))
    return tag(group, "called", "helper")


def monotone_diagonal(board: Board, beat: MonotoneDiagonal) -> None:
    """A diagonal drawn amber while its beat says why it is added, then settled in the ink
    of a diagonal made with the next beat (:meth:`Board.settles`): amber means "being
    decided now", and the holes' sweep kept its first diagonal so for 40 s."""
    u, w = beat.points
    key = f"diagonal:{''.join(beat.labels)}"
    line = tag(Line(board.at(u), board.at(w), color=board.theme.argument,
                    stroke_width=board.theme.stroke * 1.3), "argument", key)
    board.keep(key, line)
    board.play(beat, Create(line), *board.clear_labels(line),
               *board.panel.draw(key, u, w, "argument"), run_time=1.0)
    board.settles(key)


def piece_tints(pieces: Sequence[Sequence[Point]], palette: Sequence[str]) -> list[str]:
    """A tint for each piece, those sharing a side unlike (:func:`neighbour_shades`, its
    shades taken in ``palette``'s order). The pieces of a polygon without holes, split along
    diagonals, neighbour as a tree does: two tints do.

    >>> square = [(0, 0), (1, 0), (1, 1), (0, 1)]
    >>> piece_tints([square[:3], [square[0], square[2], square[3]], [(5, 5), (6, 5), (6, 6)]],
    ...             ("teal", "tan", "olive"))
    ['tan', 'teal', 'teal']
    """
    return [palette[shade % len(palette)] for shade in neighbour_shades(pieces)]


def pieces(board: Board, beat: Pieces) -> None:
    """The y-monotone pieces tinted, neighbours unlike, in divide and conquer's tints: the
    palette's blue read as the blue of what a call runs on, and its violet as the sweep's
    purple (chapter 5: a blue piece beside the violet rest of P)."""
    theme = board.theme
    tints = []
    for k, (points, colour) in enumerate(zip(beat.pieces, piece_tints(
            beat.pieces, theme.part_tints), strict=True)):
        tint = tag(MPolygon(*[board.at(p) for p in points], color=colour, stroke_width=1,
                            fill_color=colour, fill_opacity=theme.piece_opacity), None,
                   f"piece:{k + 1}")
        board.keep(f"piece:{k + 1}", tint)
        tints.append(FadeIn(tint))
    helpers = [key for key in board.objects if key.startswith("helper:")]
    board.play(beat, *board.drop("sweep", *helpers), *tints, run_time=1.2)


def stack_step(board: Board, beat: StackStep) -> None:
    """The stack changes: its waiting chain is redrawn along P through its vertices, each
    marked, and its column of slots refilled (the top marked); a triangle cut off is drawn
    as it leaves."""
    theme = board.theme
    chain = tag(_chain(board, beat.chain, beat.points), None, "stack:chain")
    column = tag(_column(board, beat.chain, beat.depth), None, "stack:column")
    anims: list = [*_restack(board, "stack:chain", chain),
                   *_restack(board, "stack:column", column)]
    if beat.triangle:
        cut = tag(MPolygon(*[board.at(p) for p in beat.triangle], color=theme.ink,
                           stroke_width=theme.thin_stroke, fill_color=theme.stack,
                           fill_opacity=0.25), None, "triangle")
        board.keep(f"triangle:{beat.seq}", cut)
        anims += [Create(cut), *board.clear_labels(cut)]
    else:  # a push: the vertex that now waits
        anims.append(Indicate(board.markers[beat.chain[-1]], color=theme.stack))
    board.play(beat, *anims, run_time=0.9)


def _replace(board: Board, key: str, new: VMobject) -> Transform | FadeIn:
    """``new`` takes the place of the object kept as ``key`` (or comes in, the first time)."""
    if key in board.objects:
        old = board.objects[key]
        return Transform(old, new)
    board.keep(key, new)
    return FadeIn(new)


#: the share of a stack change that the parts coming onto it wait, invisible, for the parts
#: moving to clear their place, and that the parts leaving take to fade
COMING_AFTER = 0.75


class Restack(Animation):
    """A group of named parts (the stack's column, its chain: ``old``, on screen) rewritten as
    ``new`` part by part, each paired by its name: one that stays moves to its new place, one
    that leaves fades out at once, one that comes fades in once the moves have cleared its
    place. One Transform of the whole group paired its parts by place, so that a leaving
    label faded over the "stack" heading (review s567). The group on screen stays ``old``,
    turned into ``new`` (its target, as a scene graph reads it)."""

    def __init__(self, old: VGroup, new: VGroup, **kwargs) -> None:
        super().__init__(old, rate_func=linear, **kwargs)
        self.old, self.target_mobject = old, new
        #: per part: the part on screen, where it starts and ends, how ("stays", "comes",
        #: "goes")
        self.parts: list[tuple[VMobject, VMobject, VMobject, str]] = []
        self.going: list[VMobject] = []

    def begin(self) -> None:
        new: VGroup = self.target_mobject
        names = {part.name for part in new}
        before = {part.name: part for part in self.old}
        self.going = [part for part in self.old if part.name not in names]
        for part in new:
            came = part.name not in before
            shown = part.copy().set_opacity(0) if came else before[part.name]
            self.parts.append((shown, shown.copy(), part, "comes" if came else "stays"))
        self.parts += [(part, part.copy(), part.copy().set_opacity(0), "goes")
                       for part in self.going]
        self.old.submobjects = [shown for shown, *_ in self.parts]
        super().begin()

    def interpolate_mobject(self, alpha: float) -> None:
        for shown, start, end, how in self.parts:
            t = smooth({"comes": max(0.0, (alpha - COMING_AFTER) / (1 - COMING_AFTER)),
                        "goes": min(1.0, alpha / (1 - COMING_AFTER))}.get(how, alpha))
            for part, a, b in zip(shown.family_members_with_points(),
                                  start.family_members_with_points(),
                                  end.family_members_with_points(), strict=True):
                part.interpolate(a, b, t)

    def finish(self) -> None:
        super().finish()
        self.old.remove(*self.going)  # faded: gone


def _restack(board: Board, key: str, group: VGroup) -> list:
    """The group kept as ``key`` (the stack's column, its chain) rewritten as ``group``
    (:class:`Restack`), or brought in."""
    old = board.objects.get(key)
    if not isinstance(old, VGroup):
        board.keep(key, group)
        return [FadeIn(group)]
    return [Restack(old, group)]


#: the radius of the mark on each waiting vertex, in dot radii: larger than a vertex's dot,
#: so that the chain's vertices are seen as its, one by one
CHAIN_MARK = 2.0


def _chain(board: Board, labels: Sequence[str], points: Sequence[Point]) -> VGroup:
    """The waiting chain drawn on P: a thick segment between each two vertices one above the
    other on the stack, and a mark on each vertex (named by its vertex: a change of the
    stack draws or takes away its own parts, :class:`Restack`). The issue asked for "the
    chain waiting to be triangulated, as it grows and pops": one yellow line through the
    chain's corners did not show which vertices wait."""
    theme = board.theme
    corners = [board.at(p) for p in points]
    placed = list(zip(labels, corners, strict=True))
    parts: list[VMobject] = [
        tag(Line(a, b, color=theme.stack, stroke_width=theme.stroke * 2.2), None,
            f"stack:chain:{u}–{v}") for (u, a), (v, b) in pairwise(placed)]
    parts += [tag(Dot(at, radius=theme.dot_radius * CHAIN_MARK, color=theme.stack), None,
                  f"stack:chain:{v}") for v, at in zip(labels, corners, strict=True)]
    return VGroup(*parts)


#: the stack's slots: a vertex's name in a box this much wider and taller than the widest and
#: tallest name of P (scene units), the slots this far apart, the top's mark this far off
SLOT_PAD, SLOT_BUFF, TOP_BUFF = (0.3, 0.16), 0.06, 0.12
#: what marks the top of the stack, beside its top slot
TOP_WORDS = "← top"


def _label_size(board: Board) -> int:
    """The stack's words' size: four up from the labels (2.5 % of the frame high and more,
    "stack" has no capital)."""
    return board.theme.label_size + 4


def _slot_size(board: Board) -> tuple[float, float]:
    """A slot's width and height: the widest and tallest name of P, padded."""
    theme = board.theme
    names = [text(v, font=theme.font, size=_label_size(board), colour=theme.ink)
             for v in board.where]
    return (max(n.width for n in names) + SLOT_PAD[0],
            max(n.height for n in names) + SLOT_PAD[1])


def _heading(board: Board) -> VMobject:
    theme = board.theme
    return tag(text("stack", font=theme.font, size=_label_size(board), colour=theme.stack),
               None, "stack:heading")


def _top_mark(board: Board) -> VMobject:
    theme = board.theme
    return tag(text(TOP_WORDS, font=theme.font, size=_label_size(board), colour=theme.stack),
               None, "stack:top")


def _column(board: Board, chain: Sequence[str], depth: int) -> VGroup:
    """The stack beside P, as a stack: "stack" over ``depth`` slots, the bottom slot lowest,
    each waiting vertex's name in its slot (a box in the stack's yellow), the top marked
    (:data:`TOP_WORDS`) beside the top slot filled; standing where the tallest stack of the
    run keeps clear of everything else on screen (:func:`_place`). Where no column fits, a
    row: "stack", then the names bottom first, left to right, the top marked after them."""
    theme = board.theme
    left, top, row = _place(board, depth)
    width, height = _slot_size(board)
    heading = _heading(board)
    parts: list[VMobject] = [heading]

    def slot(k: int) -> np.ndarray:
        """The centre of slot ``k`` (the bottom 0)."""
        if row:
            return np.array((left + heading.width + STACK_BUFF + width / 2
                             + k * (width + SLOT_BUFF), top - height / 2, 0.0))
        below = top - heading.height - STACK_BUFF
        return np.array((left + width / 2,
                         below - (max(depth, 1) - 1 - k) * (height + SLOT_BUFF) - height / 2,
                         0.0))

    if row:
        heading.move_to((left + heading.width / 2, top - height / 2, 0))
    else:
        heading.move_to((left + heading.width / 2, top - heading.height / 2, 0))
        parts += [tag(Rectangle(width=width, height=height, color=theme.stack,
                                stroke_width=theme.thin_stroke, stroke_opacity=0.45),
                      None, f"stack:slot:{k}").move_to(slot(k)) for k in range(max(depth, 1))]
    for k, v in reversed(list(enumerate(chain))):  # the top first, as the column is read
        name = text(v, font=theme.font, size=_label_size(board), colour=theme.ink)
        box = Rectangle(width=width, height=height, color=theme.stack,
                        stroke_width=theme.stroke, fill_color=theme.stack, fill_opacity=0.22)
        parts.append(tag(VGroup(box, name.move_to(box)), None, f"stack:{v}").move_to(slot(k)))
    if chain:
        mark = _top_mark(board)
        at = slot(len(chain) - 1)
        parts.append(mark.move_to((at[0] + width / 2 + TOP_BUFF + mark.width / 2, at[1], 0)))
    return VGroup(*parts)


def _place(board: Board, depth: int) -> tuple[float, float, bool]:
    """Where the run's stack stands: the left and top of the first free place
    (:func:`metaphors.layout.free_place`) for its tallest column (``depth`` slots, each as
    large as the largest label of P, the top's mark beside them), and whether it is a row.
    Found once a board, so the stack never jumps; where neither fits, the frame's top-left
    corner, as it was."""
    if board in _PLACES:
        return _PLACES[board]
    width, height = _slot_size(board)
    heading, mark = _heading(board), _top_mark(board)
    n = max(depth, 1)
    column = (max(width + TOP_BUFF + mark.width, heading.width),
              heading.height + STACK_BUFF + n * (height + SLOT_BUFF))
    row = (heading.width + STACK_BUFF + n * (width + SLOT_BUFF) + TOP_BUFF + mark.width,
           max(heading.height, height))
    taken = _taken(board)
    place: tuple[float, float, bool] = (FRAME_AREA[0], FRAME_AREA[3] - 0.6, False)
    for (w, h), as_row in ((column, False), (row, True)):
        found = free_place(w, h, taken)
        if found is not None:
            place = (*found, as_row)
            break
    _PLACES[board] = place
    return place


def _taken(board: Board) -> BaseGeometry:
    """What is on screen beside the stack: P's region, its markers (dots and labels), the
    title, the panel (its polygon, its code with the lights that run over its whole width,
    its call line) and the subtitles' band (:mod:`metaphors.layout`). Each as drawn, not grown
    as the black box's (:mod:`metaphors.pieces`): :func:`metaphors.layout.free_place` keeps
    its own clearance from all; and the panel by every box it shows and by the places that
    its lights and call line come to through the run (the stack and the count are placed
    once), whether or not the call line shows calls."""
    corners = [tuple(board.at(p)[:2]) for p in board.polygon.points]
    panel = board.panel
    areas = [*areas_of((*board.markers.values(), board.title, *panel.mobjects())),
             panel.lit_area(), call_line_area(), subtitle_band()]
    return unary_union([Region(corners), *(box(*a) for a in areas)])


def stack(board: Board, beat: Stack) -> None:
    """A piece is done: its chain and column go; a piece that is a triangle is drawn."""
    theme = board.theme
    drawn, made = [], []
    for k, triangle in enumerate(beat.triangles):
        t = tag(MPolygon(*[board.at(p) for p in triangle], color=theme.ink,
                         stroke_width=theme.thin_stroke, fill_opacity=0), None, "triangle")
        board.keep(f"triangle:{beat.seq}:{k}", t)
        drawn.append(Create(t))
        made.append(t)
    board.play(beat, *drawn, *board.drop("stack:chain", "stack:column"),
               *board.clear_labels(*made), run_time=1.0)
    if beat.triangulation:
        _whole(board, beat)


def _whole(board: Board, beat: Stack) -> None:
    """After the last piece: the pieces' tints give way to the whole triangulation, each
    triangle its own colour, and the count it had to reach, n − 2 (two more a hole)."""
    theme = board.theme
    tints = [k for k in board.objects if k.startswith("piece:")]
    whole = triangulation_pieces(beat.triangulation, board.at, theme)
    n = board.polygon.n + sum(len(h.points) for h in board.holes)
    count, gone = _count(board, count_words(n, len(board.holes), len(whole)))
    board.keep("triangulation", VGroup(*whole))
    if gone:  # the panel's polygon goes before the count comes in its place (never crossfaded)
        board.scene.play(*[FadeOut(m) for m in gone], run_time=0.5)
    shown: list[FadeIn] = []
    if count is not None:
        board.keep("counter", count)
        shown.append(FadeIn(count))
    # under its own caption, at full pace, its result row lit: the last piece's words are over
    # with holes, the caption says what the count's h is, as ear clipping's does; the caption
    # comes with the triangulation it counts, not before it (:func:`metaphors.fruit._whole`)
    board.play(ending_beat(beat, board.panel.pseudocode, len(whole), board.panel.run_call,
                           len(board.holes)),
               *board.drop(*tints), *[FadeIn(t) for t in whole], *shown,
               *board.clear_labels(*whole), *board.panel.whole(beat.triangulation),
               run_time=1.2, at_rest=True, together=True)
    board.scene.wait(1.0)


def _count(board: Board, words: str) -> tuple[VMobject | None, list[VMobject]]:
    """The count ``words`` (n − 2, or n + 2h − 2 with holes), where it keeps clear of P, its
    labels, the title, the panel and the subtitle (:func:`_taken`,
    :func:`metaphors.layout.free_place`), far enough from a label not to be read with it
    (:data:`COUNT_GAP`): outside P's hull where it can (not in a notch of P), on one line;
    where no line is free, in the panel's polygon's place, the panel giving it up (what to
    fade out: :meth:`metaphors.panel.Panel.give_up_polygon`); in two lines only where even
    that is not free (split over two lines in the top-left corner, "n − 2 = 13 − 2" over
    "= 11 triangles" read as two things, chapter 5 at 94 s). None where nothing fits (a
    panel of source takes the whole right half): the triangles and the caption's count alone
    then, as for divide and conquer (:mod:`metaphors.pieces`); under P the count met the
    bottom vertex's label and the subtitle."""
    theme = board.theme
    head, _, tail = words.rpartition(" = ")  # "n − 2 = 13 − 2", "11 triangles"

    def placed(said: str, around: BaseGeometry, gap: float) -> VMobject | None:
        count = tag(text(said, font=theme.font, size=theme.label_size + 2,
                         colour=theme.result), None, "counter")
        found = free_place(count.width, count.height, around, clearance=gap)
        if found is None:
            return None
        left, top = found
        return count.move_to((left + count.width / 2, top - count.height / 2, 0))

    def tries(taken: BaseGeometry, near: bool) -> list[tuple[BaseGeometry, float]]:
        hull = Region([tuple(board.at(p)[:2]) for p in board.polygon.points]).convex_hull
        # ``near``: the last try nearer P's labels and edges (a keyhole's long
        # "n + 2h − 2 = …" found no room else)
        return [(unary_union([taken, hull]), COUNT_GAP), (taken, COUNT_GAP),
                *([(taken, COUNT_GAP / 3)] if near else [])]

    panel = board.panel
    room = None
    if panel.shows_polygon and not panel.polygon_gone:
        panel.polygon_gone = True  # its place, as if it were gone, for the search
        room = _taken(board)
        panel.polygon_gone = False
    # one line clear of all; else in the panel's polygon's place; else nearer P; else two
    for said, taken, near, gone in ((words, _taken(board), False, False),
                                    (words, room, False, True),
                                    (words, _taken(board), True, False),
                                    (f"{head}\n= {tail}", _taken(board), True, False)):
        if taken is None:
            continue
        for around, gap in tries(taken, near):
            if (count := placed(said, around, gap)) is not None:
                return count, panel.give_up_polygon() if gone else []
    return None, []


# --- what the monotone triangulation reads from the log ------------------------------------------

KINDS = {
    "start": "both neighbours below, interior below: a start vertex",
    "end": "both neighbours above, interior above: an end vertex",
    "split": "both neighbours below, interior above: a split vertex needs a diagonal up",
    "merge": "both neighbours above, interior below: a merge vertex needs a diagonal down",
    "regular": "one neighbour above, one below: a regular vertex",
}


@beat_kind("classify")
class Classify(Beat):
    """The sweep reaches ``vertex`` (at ``at``): its ``kind`` (start, end, split, merge …)."""

    vertex: str
    kind: str
    at: Point


@beat_kind("monotone-diagonal")
class MonotoneDiagonal(Beat):
    """A diagonal that removes a split or merge vertex."""

    labels: tuple[str, str]
    points: tuple[Point, Point]


@beat_kind("helper")
class Helper(Beat):
    """``vertex`` becomes the helper of ``edge`` (its upper end, then its lower), the edge
    directly left of it: the lowest vertex yet that sees it straight to its left; ``meets``:
    where the horizontal through the vertex meets the edge."""

    vertex: str
    edge: tuple[str, str]
    meets: Point


@beat_kind("pieces")
class Pieces(Beat):
    """The y-monotone pieces (their points)."""

    pieces: tuple[tuple[Point, ...], ...]


@beat_kind("stack-step")
class StackStep(Beat):
    """The stack of a monotone piece changes: the ``chain`` waiting after it (labels, the
    bottom first, and their ``points``), and the ``triangle`` cut off (its points and
    ``cut``, its labels; both empty when a vertex is pushed)."""

    chain: tuple[str, ...]
    points: tuple[Point, ...]
    cut: tuple[str, ...]
    triangle: tuple[Point, ...]
    #: the most vertices the stack holds in the whole run (its column is made that tall)
    depth: int = 0


@beat_kind("stack")
class Stack(Beat):
    """A monotone piece is done. ``triangles``: those not cut off step by step (a piece
    that is a triangle already); after the last piece, every triangle of the run
    (``triangulation``; else empty)."""

    triangles: tuple[tuple[Point, ...], ...]
    triangulation: tuple[tuple[Point, ...], ...]


def _kind_role(kind: str) -> str:
    """The role a vertex of this kind plays: split and merge have their own colours."""
    return kind if kind in ("split", "merge") else "called"


def _kinds(walk: Walk) -> dict[str, str]:
    """The kind each vertex was classified as so far (its label's)."""
    return walk.memo("monotone.kinds", dict)


def _joined(walk: Walk) -> set[str]:
    """The vertices a diagonal joins (both ends of each ``add_diagonal``): the step where
    each became a helper is one the viewer must see (F became B–C's helper under "Vertices
    H, B, G and F: the same steps, faster", then "D joins its helper F"), and a vertex whose
    step adds a diagonal is seen whole (the holes' E: its helper step, after its diagonal,
    went under the next vertex's summary)."""
    labels = list(walk.root_points())
    return walk.memo("monotone.joined", lambda: {
        labels[k] for e in walk.log.events
        if e.kind == "return" and e.name == "add_diagonal" for k in walk.result_ints(e)})


def _key_vertices(walk: Walk) -> set[str]:
    """The vertices whose steps play at full pace under their own words (:func:`read_classify`)."""
    return walk.memo("monotone.key", set)


def read_classify(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """The sweep reaches v: its kind. Its steps are key steps (full pace, their own words,
    never in a summary) if it is a split or merge vertex, the first of its kind (each kind
    is taught once on the picture: the end vertices E and C went by in a summary, never
    named), or a helper a diagonal will join."""
    v, kind = walk.ref(call, "v"), walk.result_string(ret)
    _kinds(walk)[v] = kind
    seen = walk.memo("monotone.kinds seen", set)
    key = kind in ("split", "merge") or kind not in seen or v in _joined(walk)
    seen.add(kind)
    if key:
        _key_vertices(walk).add(v)
    yield walk.call_beat(Classify, f"{v}: {KINDS.get(kind, kind)}", call, ret,
                         key_step=key, roles={v: _kind_role(kind)},
                         vertex=v, kind=kind, at=point(walk.root_points()[v]))
    walk.count_claim("vertex", v)  # after its beat: the beat belongs to the vertex it classifies


def _helpers(walk: Walk) -> dict[tuple[str, str], str]:
    """Each edge's helper as the run has set it so far (an edge not here: its upper end,
    the vertex that put it on the line)."""
    return walk.memo("monotone.helpers", dict)


#: what a helper is, said with the first (de Berg et al.: the lowest vertex above the sweep
#: line whose horizontal segment to the edge lies inside P)
HELPER_WORDS = "the lowest vertex yet that sees {edge} straight left"


def read_helper(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """v becomes the helper of the edge directly left of it: the first time with what a
    helper is, then in place of whom."""
    where = walk.root_points()
    v, top, bottom = (walk.ref(call, name) for name in ("v", "top", "bottom"))
    helpers = _helpers(walk)
    first = not walk.memo("monotone.helped", list)
    walk.memo("monotone.helped", list).append(v)
    # one line each: two lines' first ran over the bottom vertex's label (C, at 37 s)
    edge = f"{top}–{bottom}"
    said = (f"{v} becomes {edge}'s helper: {HELPER_WORDS.format(edge=edge)}" if first
            else f"{v} becomes {edge}'s helper in place of {helpers.get((top, bottom), top)}")
    helpers[(top, bottom)] = v
    (x0, y0), (x1, y1), (_, y) = where[top], where[bottom], where[v]
    meets = (x0 + (x1 - x0) * (y - y0) / (y1 - y0), y) if y1 != y0 else (x1, y)
    beat = walk.call_beat(Helper, said, call, ret, key_step=first or v in _key_vertices(walk),
                          roles={v: _kind_role(_kinds(walk).get(v, ""))}, vertex=v,
                          edge=(top, bottom), meets=point(meets))
    yield walk.closing_claim(beat)  # a step of v's, not of the vertex after it


def read_diagonal(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    where = walk.root_points()
    labels = list(where)
    u, w = (labels[k] for k in walk.result_ints(ret))
    handler = walk.stack[-2].name if len(walk.stack) > 1 else ""
    edge = "–".join(_helped_edge(walk, w, ret))
    why = (f"the split vertex {u} joins {w}, the helper of edge {edge} on its left"
           if handler == "handle_split"
           else f"{edge}'s helper {w} is a merge vertex, so {u} joins it")
    # u keeps the colour of its kind: a merge vertex taking over (K from M) stays pink, not
    # the blue a start vertex had (one colour, one meaning: metaphors/theme.py)
    yield walk.call_beat(MonotoneDiagonal, f"Diagonal {named_together((u, w))}: {why}", call,
                         ret, key_step=True,
                         roles={u: _kind_role(_kinds(walk).get(u, "")), w: (
                        "argument" if handler == "handle_split" else "merge")},
                         labels=(u, w), points=(point(where[u]), point(where[w])))


def _helped_edge(walk: Walk, w: str, ret: Event) -> tuple[str, str]:
    """The edge whose helper ``w`` is when a diagonal joins it: as the run set it, else (the
    edge's own upper end, never set) the edge of the next helper set, the one the split
    vertex takes over."""
    found = [edge for edge, helper in _helpers(walk).items() if helper == w]
    if found:
        return found[-1]
    after = next((e for e in walk.log.events[ret.seq:]
                  if e.kind == "call" and e.name == "set_helper"), None)
    if after is None:
        return (w, w)
    return walk.ref(after, "top"), walk.ref(after, "bottom")


def read_pieces(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    pieces = [walk.entered_after(call, key) for key in walk.result_refs(ret)]
    yield walk.call_beat(Pieces, f"The diagonals cut the polygon into {len(pieces)} y-monotone "
                         "pieces", call, ret, pieces=tuple(points_of(p.get("points", [])) for p in pieces))


def _stacked(walk: Walk, indices: list[int]) -> tuple[str, ...]:
    labels = list(walk.root_points())
    return tuple(labels[k] for k in indices)


def _depth(walk: Walk) -> int:
    """The most vertices the run's stack holds: the longest stack a push leaves."""
    return int(walk.memo("monotone.depth", lambda: max(
        (len(walk.arg_ints(e, "stack")) + 1 for e in walk.log.events
         if e.kind == "call" and e.name == "push"), default=0)))


def _shown(walk: Walk) -> list[str]:
    """The chain the stack was last shown with (its labels, the bottom first)."""
    return walk.memo("monotone.shown", list)


def read_push(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """A vertex waits: the chain is the call's stack with it on top. After u met the other
    chain the stack is not what was last shown: the last vertex cut off with u (the bottom,
    whose triangles are all cut) is done, and the top it had waits again under u (as the
    textbook's "push u_{j−1} and u_j"); the caption says so, or the stack would jump."""
    where = walk.root_points()
    stack, u = walk.arg_ints(call, "stack"), walk.arg_int(call, "u")
    chain = _stacked(walk, [*stack, u])
    shown = _shown(walk)
    done = [v for v in shown if v not in chain]
    if done or shown != list(chain[:-1]):
        # the words say the change drawn: the bottom goes, the old top comes back (it had
        # "left" under the cut before: "H leaves", then "H and B wait" read as a contradiction)
        back = [v for v in chain[:-1] if v not in shown]
        said = [f"{_listed(done)} {'is' if len(done) == 1 else 'are'} done"
                ] if done else []
        if back:
            said.append(f"{_listed(back)} {'goes' if len(back) == 1 else 'go'} back on the "
                        f"stack, {chain[-1]} on top")
        else:
            said.append(f"{chain[-1]} waits on the stack")
        caption = ": ".join(said)
    else:
        caption = f"{chain[-1]} waits on the stack"
    shown[:] = chain
    yield walk.call_beat(StackStep, caption, call, ret, roles={},
                         chain=chain, points=points_of(where[v] for v in chain), cut=(), triangle=(),
                         depth=_depth(walk))


def _listed(labels: Sequence[str]) -> str:
    """``H``, ``H and I``, ``G, H and I``."""
    return labels[0] if len(labels) == 1 else ", ".join(labels[:-1]) + " and " + labels[-1]


def read_cut(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """A triangle is cut off: the stack's top leaves it."""
    where = walk.root_points()
    before = _stacked(walk, walk.arg_ints(call, "stack"))
    cut = _stacked(walk, walk.result_ints(ret))
    walk.memo("monotone.cut", list).append(cut)
    _shown(walk)[:] = before[:-1]
    yield walk.call_beat(StackStep, f"Triangle {named_together(cut)} cut off: {before[-1]} leaves",
                         call, ret, roles={}, chain=before[:-1],
                         points=points_of(where[v] for v in before[:-1]), cut=cut,
                         triangle=points_of(where[v] for v in cut), depth=_depth(walk))


def read_stack(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    where = walk.root_points()
    labels = list(where)
    triangles = [points_of(where[labels[k]] for k in walk.int_list(t, "a triangle"))
                 for t in walk.result_list(ret)]
    done = walk.memo("monotone.triangles", list)  # the triangles of the pieces so far
    done.extend(triangles)
    cut = walk.memo("monotone.cut", list)  # cut off step by step in this piece
    n = len(triangles)
    bare = _bare_run(walk, ret)
    caption = (f"This piece is done: {n} triangle{'s' if n != 1 else ''}" if cut
               else "This piece is a triangle already" if bare <= 1
               else f"{bare} pieces are triangles already")
    # all of them: n − 2, two more a hole (n counting the holes' vertices)
    whole = len(done) == len(labels) - 2 + 2 * len(walk.root_holes())
    yield walk.call_beat(Stack, caption, call, ret, triangles=() if cut else tuple(triangles),
                         triangulation=tuple(done) if whole else ())
    cut.clear()
    _shown(walk).clear()  # the next piece's stack starts empty


def _bare_run(walk: Walk, ret: Event) -> int:
    """How many pieces that are triangles already come one after another with the piece
    that ``ret`` ends (none if it is not one): they are drawn in a moment under one caption,
    which says how many there are (not "this piece" of three)."""
    pieces = walk.memo("monotone.pieces", lambda: [
        (e.seq, len(walk.result_list(e)) == 1) for e in walk.log.events
        if e.kind == "return" and e.name == "triangulate_monotone_piece"])
    k = next((i for i, (seq, _) in enumerate(pieces) if seq == ret.seq), None)
    if k is None or not pieces[k][1]:
        return 0
    first, last = k, k
    while first > 0 and pieces[first - 1][1]:
        first -= 1
    while last + 1 < len(pieces) and pieces[last + 1][1]:
        last += 1
    return last - first + 1


READS: Mapping[str, Reading] = {"classify_vertex": read_classify, "add_diagonal": read_diagonal,
         "set_helper": read_helper,
         "monotone_pieces": read_pieces, "triangulate_monotone_piece": read_stack,
         "push": read_push, "cut_off": read_cut}
PERFORMS: Performances = performs(act(Classify, classify),
                                  act(MonotoneDiagonal, monotone_diagonal), act(Helper, helper),
                                  act(Pieces, pieces), act(StackStep, stack_step),
                                  act(Stack, stack))
