"""Divide and conquer (Lennes): the verified diagonal becomes an edge and the polygon falls into
two pieces, each tinted unlike its neighbours; the run takes up each part in turn (the
recursion, ``next_part``: it lights up), and a part that is a triangle is done (the base case,
``done``: it fills in, in the result's green, unlike its neighbours); after the last the whole
triangulation shows with its count, n − 2. Each step lights its own row of the pseudocode. The
pieces, their points and labels come from the log (the ``split`` call and the pieces it
enters, the triangles ``done`` enters).

With its heuristic a black box (:class:`story.beats.FindDiagonal`), the piece worked on lights
up and a box beside the picture asks for its inner diagonal; the claim that comes out is drawn
by the frame every run shares (:mod:`metaphors.basics`).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import replace

from manim import DOWN, RIGHT, FadeIn, FadeOut, Indicate, Mobject, RoundedRectangle, VGroup
from manim import Polygon as MPolygon

from metaphors.board import Board, Playable
from metaphors.drawing import (
    count_words,
    ending_beat,
    neighbour_shades,
    shaded_triangle,
    triangulation_pieces,
)
from metaphors.layout import (
    METAPHOR,
    PANEL_POLYGON,
    Obstacles,
    Rect,
    area_of,
    areas_of,
    call_line_area,
    first_clear,
    grid,
    panel_area,
    subtitle_band,
    title_area,
)
from metaphors.panel import DIAGONAL_WIDTH
from metaphors.performing import Performances, act, performs
from metaphors.tags import tag
from rendering.typeset import text
from story.beats import Beat, FindDiagonal, Point, beat_kind, points_of
from story.pseudocode import PSEUDOCODE
from story.refs import state_of, target_of
from story.storyboard import Reading, Walk
from story.words import named_together
from tracing import Event


@beat_kind("split")
class Split(Beat):
    """The piece ``parent`` is cut into ``pieces`` (keys), with their points and labels."""

    pieces: tuple[str, ...]
    parent: str
    points: tuple[tuple[Point, ...], ...]  # one ring of points per piece
    labels: tuple[tuple[str, ...], ...]


def read_split(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    pieces = walk.result_refs(ret)
    entered = {target_of(e): state_of(e) for e in walk.log.events[ret.seq:]
               if e.kind == "enter" and e.target in pieces}
    labels = tuple(tuple(entered[k]["labels"]) for k in pieces if k in entered)
    # the split closes the claim of the diagonal it splits along (one step at a time); the
    # caption names it (the first half is the chain from one end to the other): the same
    # words for every split were said twice in the scene's first two diagonals (24 s, 45 s)
    yield walk.closing_claim(walk.call_beat(
        Split, f"Split along {_diagonal_name(labels)} into two smaller polygons", call, ret,
        pieces=tuple(pieces), parent=walk.ref(call, "piece"),
        points=tuple(points_of(entered[k]["points"]) for k in pieces if k in entered),
        labels=labels))


def _diagonal_name(halves: Sequence[Sequence[str]]) -> str:
    """The diagonal two halves share, by its ends (the first half runs from one to the
    other): ``DG``; "the diagonal" where the halves are not known.

    >>> _diagonal_name([("D", "E", "F", "G"), ("G", "H", "D")]), _diagonal_name([])
    ('DG', 'the diagonal')
    """
    if not halves or len(halves[0]) < 2:
        return "the diagonal"
    return named_together((halves[0][0], halves[0][-1]))


@beat_kind("next-part")
class NextPart(Beat):
    """The run takes up ``piece`` (a key), a part a split made, to triangulate it the same
    way: the recursion."""

    piece: str


@beat_kind("done")
class Done(Beat):
    """The part ``piece`` (a key) is a triangle, with its ``points`` and ``labels``: done, the
    base case. ``shade``: its fill among the run's triangles (:func:`neighbour_shades`)."""

    piece: str
    points: tuple[Point, ...]
    labels: tuple[str, ...]
    shade: int


#: what the recursion's step says (the first time, with what grey means:
#: :data:`GREY_SAID`)
SAME_WAY = "Triangulate this part the same way"


def read_next_part(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """A part taken up: a beat of its own unless it is a triangle (its ``done`` says so)."""
    piece = walk.ref(call, "piece")
    state = walk.live.get(piece) or walk.entered_after(call, piece)
    if len(state.get("labels", ())) != 3:
        yield walk.call_beat(NextPart, SAME_WAY, call, ret, piece=piece, roles={})


def read_done(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """A triangle done: its corners, and its shade among all the run's triangles."""
    made = walk.result_ref(ret)
    state = walk.entered_after(call, made)
    shades = walk.memo("triangle shades", lambda: _shades(walk))
    points = points_of(state["points"])
    # the last claim's (its split made the triangle): counted with the next, a triangle done
    # came under the next diagonal's summary ("Diagonal 10" over diagonal 9's triangles)
    yield walk.closing_claim(walk.call_beat(Done, f"{''.join(state['labels'])} is a triangle: done", call, ret,
                         piece=walk.ref(call, "piece"), points=points,
                         labels=tuple(state["labels"]), shade=shades[_corners_key(points)],
                         roles={}))


def _corners_key(points: Sequence[Sequence[float]]) -> tuple:
    return tuple(sorted((float(x), float(y)) for x, y in points))


def _shades(walk: Walk) -> dict[tuple, int]:
    """Each of the run's triangles (every one ``done`` enters, by its corners) → its shade:
    as the whole triangulation is drawn at the end (:func:`triangulation_pieces`)."""
    found = [points_of(state_of(e)["points"]) for e in walk.log.events
             if e.kind == "enter" and e.target is not None and e.target.startswith("△")]
    return {_corners_key(t): shade for t, shade in zip(found, neighbour_shades(found),
                                                       strict=True)}


def _tint_colour(board: Board, labels: Sequence[str], avoid: set[str]) -> str:
    """A palette colour for a new piece: unlike its neighbours (tints sharing an edge), then the
    least used; ties by palette order."""
    palette = board.theme.part_tints  # none reads as the blue of the part worked on
    tints = [m for k, m in board.objects.items() if k.startswith(("piece:", "triangle:"))]
    near = {_colour(m) for m in tints if len(set(_labels(m)) & set(labels)) >= 2}
    used = [_colour(m) for m in tints]
    return min(palette, key=lambda c: (c in avoid, c in near, used.count(c), palette.index(c)))


def _colour(tint: Mobject) -> str:
    """The palette colour of a tint (an attribute of its own, set by :func:`_tint`)."""
    colour: str = vars(tint)["trex_colour"]
    return colour


def _labels(tint: Mobject) -> list[str]:
    """The labels of a tint's corners (an attribute of its own, set by :func:`_tint`)."""
    labels: list[str] = vars(tint)["trex_labels"]
    return labels


def _tint(board: Board, points: Sequence[Sequence[float]], labels: Sequence[str],
          colour: str) -> MPolygon:
    """A part's tint, under the edges and labels."""
    theme = board.theme
    mobject = MPolygon(*[board.at(p) for p in points], stroke_width=0, fill_color=colour,
                       fill_opacity=theme.piece_opacity)
    mobject.set_z_index(-1)
    vars(mobject).update(trex_colour=colour, trex_labels=list(labels))  # see _colour, _labels
    return tag(mobject, "idle", "piece:" + "".join(labels))


def split(board: Board, beat: Split) -> None:
    """The verified diagonal becomes an edge; the two halves get their own tints (a half that
    is a triangle too: it is done when the run takes it up, :func:`done`)."""
    theme = board.theme
    anims = []
    line = board.objects.pop("claim", None)
    if line is not None:
        k = sum(1 for key in board.objects if key.startswith("diagonal:"))
        board.keep(f"diagonal:{k}", tag(line, "idle", line.name))
        anims.append(line.animate.set_color(theme.ink).set_stroke(width=theme.stroke))
        # and in the panel: the diagonal made, in the ink, where the piece was split
        anims += board.panel.recolour("claim", None, f"diagonal:{k}", width=DIAGONAL_WIDTH)
    anims += board.drop("verdict", f"piece:{beat.parent}")
    if board.outline.get_fill_opacity() > 0:
        anims.append(board.outline.animate.set_fill(opacity=0))
    chosen: set[str] = set()
    made: list[Mobject] = []
    for piece, points, labels in zip(beat.pieces, beat.points,
                                     beat.labels, strict=False):
        colour = _tint_colour(board, labels, chosen)
        chosen.add(colour)
        tint = _tint(board, points, labels, colour)
        board.keep(f"piece:{piece}", tint)
        anims.append(FadeIn(tint))
        made.append(tint)
    board.play(beat, *anims, *board.clear_labels(*made), run_time=1.2)


def next_part(board: Board, beat: NextPart) -> None:
    """The part taken up lights up, its vertices in their ink and the others grey (said the
    first time): its caption comes with the colour (:meth:`Board.play` ``together``)."""
    anims, said_grey = _light(board, beat.piece)
    if said_grey:
        beat = replace(beat, caption=f"{SAME_WAY}: grey vertices are not in it")
    board.play(beat, *anims, run_time=1.2, together=True)


def done(board: Board, beat: Done) -> None:
    """A triangle is done: its part fills in, in the result's green at its shade, the other
    vertices grey while it is looked at; after the last, the whole triangulation with its
    count."""
    theme = board.theme
    part = board.objects.pop(f"piece:{beat.piece}", None)
    corners = [board.at(p) for p in beat.points]
    triangle = shaded_triangle(corners, beat.shade, theme).set_z_index(-1)
    vars(triangle).update(trex_colour=theme.result, trex_labels=list(beat.labels))
    board.keep(f"triangle:{''.join(beat.labels)}", tag(triangle, "result",
                                                        f"triangle:{''.join(beat.labels)}"))
    anims: list[Playable] = [FadeIn(triangle)]
    if part is not None:
        anims.append(FadeOut(part))
    board.focus = frozenset(beat.labels)
    board.play(beat, *anims, run_time=1.2, together=True)
    if any(key.startswith("piece:") for key in board.objects):
        return
    # the last: the whole triangulation under its own caption, the black box gone before the
    # count comes where it stood (never two texts at once)
    triangles = sum(1 for key in board.objects if key.startswith("triangle:"))
    finder = board.objects.get("finder")
    if finder is not None:
        board.scene.play(*board.drop("finder"), run_time=0.5)
    # the caption with the triangulation it counts (:func:`metaphors.fruit._whole`)
    board.play(ending_beat(beat, board.panel.pseudocode, triangles, board.panel.run_call),
               *_whole(board, finder), run_time=1.2, at_rest=True, together=True)


def _whole(board: Board, finder: Mobject | None) -> list[Playable]:
    """After the last split: the finished triangles give way to the whole triangulation,
    each triangle its own colour, and the count it had to reach, n − 2 (where the black box
    ``finder`` stood, if there was one)."""
    theme = board.theme
    done = [k for k in board.objects if k.startswith("triangle:")]
    corners = [[board.where[label] for label in _labels(board.objects[k])] for k in done]
    whole = triangulation_pieces(corners, board.at, theme)  # the shades each was done in
    n = board.polygon.n
    shown: list[Playable] = [*board.drop(*done), *[FadeIn(t) for t in whole],
                             *board.clear_labels(*whole)]
    # the count where the black box stood, clear of the picture, the panel and the subtitle
    # (:func:`_place`); with no black box, beside the picture when the panel's rows leave
    # room there: a panel of source takes the whole right half, and under the picture the
    # count would meet the subtitle: the triangles alone then
    if finder is not None or board.panel.mode == PSEUDOCODE:
        # on one line where it finds room (broken, its halves read as two things)
        for said in (count_words(n, 0, len(whole)), f"n − 2 = {n} − 2\n= {len(whole)} triangles"):
            count = tag(text(said, font=theme.font, size=theme.label_size,
                             colour=theme.result), None, "counter")
            # nearest where the black box stood, as clear as it was
            spot = None if finder is None else _place(count, _taken(board),
                                                      near=tuple(finder.get_center()[:2]))
            if spot is not None:
                break
        if spot is not None:
            count.move_to((*spot, 0))
        else:  # from where the black box would stand: the picture's right-most labels stay clear
            count.move_to((BESIDE[0] - FINDER_WIDTH / 2 + count.width / 2, BESIDE[1] - 0.4, 0))
        board.keep("counter", count)
        shown.append(FadeIn(count))
    board.keep("triangulation", VGroup(*whole))
    return shown


#: beside the picture, between it and the panel's polygon, above the panel's rows: where the
#: black box would rather stand (:func:`_place`), and, after the last split, the count
BESIDE = ((METAPHOR.x + METAPHOR.width / 2 + PANEL_POLYGON.x - PANEL_POLYGON.width / 2) / 2
          + 0.15, PANEL_POLYGON.y - 0.4, 0.0)
FINDER_WIDTH = 1.2  # the black box's
#: the least gap between the black box and the picture, the panel, the title or a subtitle
FINDER_GAP = 0.1
#: how much further the black box keeps from the pictures' outlines and labels (the
#: metaphor's, the panel's)
PICTURE_GAP = 0.25
#: the step of the places tried for the black box (scene units)
FINDER_STEP = 0.05
#: the frame's half width and half height (scene units)
HALF_FRAME = (7.11, 4.0)


def _finder(board: Board) -> VGroup:
    """The black box: a closed box with a question mark, and what it is asked; the words
    under the box where there is room for both beside the picture, else to its right, and
    the box smaller (a panel of source leaves room only under its rows)."""
    for compact in (False, True):
        finder = _finder_shape(board, compact)
        place = _place(finder, _taken(board))
        if place is not None:
            break
    else:  # nowhere clear (a frame laid out otherwise): where it would rather stand
        finder, place = _finder_shape(board, compact=False), BESIDE[:2]
    return tag(finder.move_to((*place, 0)), "called", "finder")


def _finder_shape(board: Board, compact: bool) -> VGroup:
    theme = board.theme
    box = RoundedRectangle(corner_radius=0.12, width=1.0 if compact else FINDER_WIDTH,
                           height=0.56 if compact else 0.9, stroke_color=theme.called,
                           stroke_width=theme.stroke, fill_color=theme.background,
                           fill_opacity=1.0)
    mark = text("?", font=theme.font, size=36 if compact else 48,
                colour=theme.called).move_to(box)
    rows = ("an inner diagonal?",) if compact else ("an inner", "diagonal?")
    words = VGroup(*[text(row, font=theme.font, size=theme.label_size, colour=theme.ink)
                     for row in rows]).arrange(DOWN, buff=0.08)
    words.next_to(box, RIGHT if compact else DOWN, buff=0.15)
    return VGroup(box, mark, words)


def _taken(board: Board) -> list[Rect]:
    """What the black box must keep clear of: the picture (outline, vertices and labels), the
    panel (a source's whole box, as its window of lines moves; else its polygon, labels and
    rows, and the call line if it shows), the title, and the highest a two-line subtitle
    reaches (:mod:`metaphors.layout`). Unlike the monotone stack's (:mod:`metaphors.monotone`)
    the pictures are grown by :data:`PICTURE_GAP`: the box stands nearest the picture, and a
    box beside a label reads as part of its name; the rows by their ink, not the lights' width,
    and the subtitle's two lines as measured, not :data:`metaphors.layout.SUBTITLE_TOP`: the
    compact box fits under a source's rows, close over the subtitle, only so."""
    panel = board.panel
    taken = [*areas_of((board.outline, *board.markers.values()), PICTURE_GAP),
             title_area(board.title)]
    if panel.shows_polygon:
        taken += [*areas_of((panel.outline, *panel.markers.values()), PICTURE_GAP),
                  area_of(panel.code)]
    else:
        taken.append(panel_area(shows_polygon=False))
    if panel.shows_calls:
        taken.append(call_line_area())
    return [*taken, subtitle_band(board.theme)]


def _place(finder: Mobject, taken: Sequence[Rect],
           near: Sequence[float] = BESIDE) -> tuple[float, float] | None:
    """The centre nearest ``near`` (on a grid of :data:`FINDER_STEP`) where ``finder`` stays
    in the frame and :data:`FINDER_GAP` clear of every area ``taken``; None if none
    (:func:`metaphors.layout.first_clear`)."""
    size = (finder.width, finder.height)
    frame = (-HALF_FRAME[0] + FINDER_GAP, -HALF_FRAME[1] + FINDER_GAP,
             HALF_FRAME[0] - FINDER_GAP, HALF_FRAME[1] - FINDER_GAP)
    centres = grid(frame, size, FINDER_STEP, near=near[:2])
    k = first_clear(centres, size, Obstacles(boxes=taken), FINDER_GAP)
    if k is None:
        return None
    return (round(float(centres[k][0]), 6), round(float(centres[k][1]), 6))


#: what the first question on a smaller polygon says of the colours it brings: the labels
#: of the vertices not in it turn grey (:func:`metaphors.labels.new_colour`)
GREY_SAID = "Find an inner diagonal of this polygon: grey vertices are not in it"


def _light(board: Board, key: str) -> tuple[list[Playable], bool]:
    """The animations lighting the piece ``key`` (P itself if it has none) as the one worked
    on, its vertices in their ink and the others grey; and whether grey is said now (the
    first time a smaller polygon is: grey, "not in the current call", drawn and never
    explained read as a leftover)."""
    theme = board.theme
    piece = board.objects.get(f"piece:{key}", board.outline)
    every = frozenset(board.markers)
    focus = every if piece is board.outline else frozenset(_labels(piece))
    said = (board.focus is None or board.focus >= every) and not focus >= every
    board.focus = focus
    vars(piece)["trex_lit"] = True  # lit: asked for its diagonal, it is not lit again
    lit = piece.animate.set_fill(theme.called, opacity=theme.active_opacity)
    if piece is not board.outline:
        # a part of P outlined in the same blue, beside parts of other tints: it stands out
        # from the first step on it, not only from gravity's turn (a convex part was never
        # outlined); P's own outline keeps its edges (no other part to tell it from)
        lit = lit.set_stroke(theme.called, width=theme.active_stroke, opacity=1.0)
    return [lit], said


def find(board: Board, beat: FindDiagonal) -> None:
    """The black box is asked for an inner diagonal of the piece worked on (lit up here
    unless its recursion's step lit it: :func:`next_part`): its caption comes with the
    question's box and the piece's colour."""
    theme = board.theme
    finder = board.objects.get("finder")
    anims: list[Playable]
    if finder is None:
        finder = _finder(board)
        board.keep("finder", finder)
        anims = [FadeIn(finder, shift=0.2 * DOWN)]
    else:
        # asked again: its "?" pulses in the black box's own blue (amber is a pick's)
        anims = [Indicate(finder[1], color=theme.called, scale_factor=1.3)]
    if not vars(board.objects.get(f"piece:{beat.piece}", board.outline)).get("trex_lit"):
        lighting, said_grey = _light(board, beat.piece)
        anims += lighting
        if said_grey:
            beat = replace(beat, caption=GREY_SAID)
    board.play(beat, *anims, run_time=1.2, together=True)


READS: Mapping[str, Reading] = {"split": read_split, "next_part": read_next_part,
                                "done": read_done}
PERFORMS: Performances = performs(act(Split, split), act(FindDiagonal, find),
                                  act(NextPart, next_part), act(Done, done))
