"""The algorithm panel (right half): the polygon plainly, the running code with its line lit,
and the call line ``nearest_to(B, [D, E]) → D``; every object coloured by its role.

The code is the run's pseudocode in the thesis's words (:mod:`story.pseudocode`, lit by each
beat's ``row``) or the real source of the shown function (lit by each beat's ``line``); either
way a row is named by its place in the listing, ``code:1`` the first (docs/scene-graph.md). The source is what a panel shows
until :meth:`Panel.show_pseudocode` is called (:func:`metaphors.play.board_for` decides).

The source is shown at a readable size (:data:`SOURCE_SIZE`), never shrunk: its long lines
wrap (:mod:`metaphors.listing`; a wrapped line's rows are ``code:7``, ``code:7.2`` …, all lit
together), and a listing taller than the panel shows a window of whole lines holding the lit
one, with a note of the lines above and below it; the window changes only when the lit line
leaves it. It takes the panel's polygon's place too: the metaphor on the left colours the
same vertices by the same roles.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import cast

import numpy as np
from manim import (
    DOWN,
    LEFT,
    Animation,
    Create,
    Dot,
    FadeIn,
    FadeOut,
    Line,
    LineJointType,
    Mobject,
    Rectangle,
    Transform,
    VGroup,
)
from manim import (
    Polygon as MPolygon,
)

from geometry.polygon import Polygon
from metaphors.drawing import Frame, polygon_mobject
from metaphors.labels import LABEL_HALO, new_colour, seen_by
from metaphors.layout import (
    PANEL_CALL_Y,
    PANEL_CODE,
    PANEL_LABELS,
    PANEL_POLYGON,
    PANEL_SOURCE,
    Box,
    Obstacles,
    Rect,
    around,
    clear,
    code_floor,
    panel_area,
    ring_edges,
)
from metaphors.listing import Row, Window, listing_rows, window_for
from metaphors.pseudocode import source_of
from metaphors.tags import tag
from metaphors.theme import THEME, Theme
from rendering import typeset
from rendering.layers import BACKDROP_Z
from story.beats import Beat, Hole, Point
from story.pseudocode import PSEUDOCODE, SOURCE, PseudocodeRow

#: the distance between the pseudocode's rows (scene units; less when more rows than fit are
#: shown): 4.25 % of the frame's height, for rows of the theme's ``pseudocode_size``
PSEUDOCODE_PITCH = 0.34
#: the least distance between them: the font's size (rows set solid), at which a row's
#: descenders keep 0.02 from the next row's brackets (a row's ink is 0.26 high at most). Rows
#: are never shrunk to fit (their capitals would be under 2.5 % of the frame): a long
#: pseudocode reaches lower, into the room the call line leaves, closer, then higher, its
#: polygon shorter (the holes' sweep, 10 rows over a call line, fits at this pitch)
PSEUDOCODE_LEAST_PITCH = 0.28
#: how far a pseudocode row moves right for each level (two leading spaces) of indentation
PSEUDOCODE_INDENT = 0.3
#: the source's monospace size: its shortest row (``else:``, ``tests += 1``) is 0.23 units
#: high, 2.9 % of the frame's height
SOURCE_SIZE = 22
#: the distance between the source's rows (scene units)
SOURCE_PITCH = 0.36
#: how far the source's rows keep from the sides of their light
SOURCE_MARGIN = 0.12


#: how the names of what the run draws in the panel start (``panel/claim``, ``panel/part``):
#: not ``panel:``, which names the panel's own parts and its vertex markers (``panel:K``)
DRAWN = "panel/"
#: the z-index of the panel's vertex markers: over the lines the run draws in the panel (its
#: claims, diagonals and cuts), as the board's markers are over the picture's
#: (:data:`metaphors.board.LABEL_Z`)
MARKER_Z = 5
#: a claim's width, and the width of the edge it crosses, of the theme's stroke: drawn over
#: P, they stand out from its edges (the picture's are wider still, at its size)
CLAIM_WIDTH, CROSSED_WIDTH = 1.4, 1.8
#: a diagonal's width, of the theme's stroke (a diagonal made, the whole triangulation's):
#: thinner than P's edges, so that a triangulation of many triangles stays light in the
#: panel's small copy of P
DIAGONAL_WIDTH = 0.5
#: how opaque the tint of the part of P a call works on is (divide and conquer's piece)
PART_OPACITY = 0.35
#: how opaque the panel's polygon's fill is
FILL_OPACITY = 0.12


class Panel:
    """The right half of every scene. ``follow_roles(beat)`` and ``follow_text(beat)`` return
    the animations that bring it up to date with a beat (roles; lit line and call line)."""

    def __init__(self, points, labels, shown: str | None, theme: Theme = THEME, holes=(),
                 avoided: Sequence[tuple[Point, Point]] = ()):
        self.theme = theme
        self.polygon = Polygon(tuple(map(tuple, points)), tuple(labels),
                               tuple(range(len(labels))))
        self.holes = holes
        #: label → point (P's and its holes' vertices, in P's coordinates)
        self.where: dict[str, Point] = {
            label: (float(p[0]), float(p[1]))
            for ring_labels, ring_points in ((self.polygon.labels, self.polygon.points),
                                             *((h.labels, h.points) for h in holes))
            for label, p in zip(ring_labels, ring_points, strict=True)}
        #: the segments the panel's labels keep clear of besides P's edges: the claims, cuts
        #: and diagonals the run will draw in it, so that none is drawn through a label (the
        #: board's labels keep clear of the claims likewise)
        self.avoided = [((float(a[0]), float(a[1])), (float(b[0]), float(b[1])))
                        for a, b in avoided]
        #: the run's state drawn over the polygon (:meth:`draw`): claims, the edge a claim
        #: crosses, diagonals, keyhole cuts, by the key the picture keeps them under
        self.lines: dict[str, Mobject] = {}
        #: the markers of the vertices sliced off the polygon (:meth:`slice_off`), by label
        self.off: dict[str, Mobject] = {}
        #: the tint of the part of P the running call works on, and its labels (:meth:`_part`)
        self.part: Mobject | None = None
        self.part_labels: tuple[str, ...] = ()
        #: the ring the outline becomes once a slice's play is over (:meth:`settle_outline`)
        self.after_slice: list[Point] | None = None
        self._draw_polygon(0.0)
        #: the box the pseudocode's rows and lights take (:meth:`_pseudocode_block`)
        self.code_box = PANEL_CODE
        self.mode = SOURCE
        self.code_lines = source_of(shown) if shown else ()
        self.pseudocode: tuple[PseudocodeRow, ...] = ()
        #: (seq, rows): the rows from the beat of that seq on (:meth:`show_pseudocode`)
        self.later: list[tuple[int, tuple[PseudocodeRow, ...]]] = []
        self.code_scale = 1.0  # how much the rows were shrunk to fit the box's width (never its height)
        # the source: its rows, the window of lines shown (None: all of them), and each
        # shown line's row mobjects and the middle of their slots
        self.rows: tuple[Row, ...] = ()
        self.window: Window | None = None
        self.shown: dict[int, list] = {}
        self.slot_y: dict[int, list[float]] = {}
        self.code = self._code_block()
        # pseudocode: the height of every row's light, and the middle of each row's line
        self.light_height: float | None = None
        self.line_y: list[float] = []
        # (row, the light behind it, the row's copy in ink over the grey row)
        self.lit: tuple[int, Rectangle, Mobject] | None = None
        #: the claim drawn on the panel's polygon (:meth:`claim`), if any
        self.call = tag(typeset.text(" ", font=theme.mono_font, size=20), None, "panel:call")
        self.call.move_to((PANEL_CODE.x, PANEL_CALL_Y, 0))
        #: the text of the call line on screen (a beat of the same call leaves it up)
        self.call_text = " "
        #: the call line being replaced, for the board to cut (see :meth:`cut_outgoing`)
        self.outgoing_call: Mobject | None = None
        #: the light and lit copy of a row typeset anew, likewise (see :meth:`_rename`)
        self.outgoing_lit: list[Mobject] = []
        #: whether the call line shows each beat's real call: a programmer's render does, the
        #: lecture does not (issue 22: no code in the lecture; see TraceScene.call_line)
        self.shows_calls = True
        #: the run's own call, without its result: the call line of the run's ending says it
        #: with the result (metaphors.drawing.ending_beat); None: not known
        self.run_call: str | None = None
        self.roles: dict[str, str] = {}
        #: the panel's polygon was taken off at the run's end (:meth:`give_up_polygon`)
        self.polygon_gone = False

    def give_up_polygon(self) -> list:
        """Take the panel's polygon and its markers off for the rest of the run, and give
        them (to fade out): at a run's end, where the whole triangulation is drawn large, the
        small copy says nothing more and its place holds what has no other (the monotone
        count on one line, split over two in the top-left corner before). Nothing if it
        shows none. What the run drew on it goes with it (its diagonals, its tinted part)."""
        if not self.drawing:
            return []
        self.polygon_gone = True
        drawn = [*self.lines.values(), *([self.part] if self.part is not None else [])]
        self.lines, self.part = {}, None
        return [self.outline, *self.markers.values(), *drawn]

    def show_code(self, code) -> None:
        """Show these (line number, text) rows instead (before the panel is on screen): a
        heuristic of one's own carries its source in its log."""
        self.code_lines = tuple((int(number), str(text)) for number, text in code)
        self.code = self._code_block()

    def show_pseudocode(self, rows,
                        later: Sequence[tuple[int, tuple[PseudocodeRow, ...]]] = ()) -> None:
        """Show these pseudocode rows (:class:`story.pseudocode.PseudocodeRow`) instead of the source
        (before the panel is on screen); each beat's ``row`` then lights one of them.
        ``later``: (seq, rows) in order, from the beat of that seq on those rows instead (the
        run has picked the vertex they name, or tied a placeholder to its vertex:
        :func:`story.storyboard.pseudocode_stages`)."""
        self.mode = PSEUDOCODE
        self.pseudocode = tuple(rows)
        self.later = list(later)
        self.code = self._pseudocode_block()
        if self.code_box.rect[3] > PANEL_CODE.rect[3] + 1e-9:  # the rows need the room
            self._draw_polygon(self.code_box.rect[3] - PANEL_CODE.rect[3])

    def _draw_polygon(self, raised: float) -> None:
        """The panel's polygon and its markers, in :data:`PANEL_POLYGON` with its bottom (and
        its labels' area's) ``raised`` by so much: the room a long pseudocode takes."""
        box, area = (Box(b.x, b.y + raised / 2, b.width, b.height - raised)
                     for b in (PANEL_POLYGON, PANEL_LABELS))
        self.frame = Frame(self.polygon.points, box.center, box.width, box.height)
        self.outline = tag(polygon_mobject(self.polygon, self.frame, self.theme, self.holes),
                           "idle", "panel:polygon")
        self.outline.set_fill(opacity=FILL_OPACITY)
        lines = [(self.frame.to_scene(a), self.frame.to_scene(b)) for a, b in self.avoided]
        self.markers = {
            label: tag(m, "idle", f"panel:{label}").set_z_index(MARKER_Z)
            for label, m in panel_markers(self.polygon, self.holes, self.frame, self.theme, area,
                                          lines)
        }


    def lit_area(self) -> Rect:
        """The box the panel's lights run over: its pseudocode's (:attr:`code_box`, the whole
        width under its polygon), or the source's (:func:`metaphors.layout.panel_area`)."""
        return self.code_box.rect if self.shows_polygon else panel_area(False)

    @property
    def shows_polygon(self) -> bool:
        """Whether the panel draws its polygon: not when source code takes its place (module
        docs); a run whose source cannot be read keeps it."""
        return self.mode != SOURCE or not self.code_lines

    @property
    def drawing(self) -> bool:
        """Whether the panel's polygon is on screen: shown (not the source) and not taken off
        at the run's end (:meth:`give_up_polygon`)."""
        return self.shows_polygon and not self.polygon_gone

    def mobjects(self) -> list:
        if not self.drawing:
            return [self.code, self.call]
        return [self.outline, *self.markers.values(), self.code, self.call]

    def changing(self) -> list:
        """The panel's text that changes from beat to beat, bottom first: the light, the lit
        row, the call line (the code itself changes only when a source's window moves). See
        :meth:`metaphors.board.Board.settle`."""
        return [*(self.lit[1:] if self.lit else ()), self.call]

    def _code_block(self) -> VGroup:
        """The source's rows (:data:`SOURCE_SIZE`, wrapped to the panel's width), all of them
        if they fit its height, else the first window of them."""
        lines, slots = [text for _, text in self.code_lines], self._slots()
        self.rows = listing_rows(lines, self._columns(), most=slots)
        if len(self.rows) > slots:  # a window's notes take two slots: no line may take more
            self.rows = listing_rows(lines, self._columns(), most=slots - 2)
        fits = len(self.rows) <= slots
        self.window = None if fits else window_for(self._row_counts(), slots - 2, 0)
        return self._window_block()

    def _cell(self) -> float:
        """The width of a monospace cell of the source."""
        return typeset.text("M" * 20, font=self.theme.mono_font, size=SOURCE_SIZE).width / 20

    def _columns(self) -> int:
        return int((PANEL_SOURCE.width - 2 * SOURCE_MARGIN) / self._cell() + 1e-6)

    def _slots(self) -> int:
        """How many rows the panel holds (a window's two notes among them)."""
        return int(PANEL_SOURCE.height / SOURCE_PITCH + 1e-6)

    def _row_counts(self) -> list[int]:
        counts = [0] * len(self.code_lines)
        for row in self.rows:
            counts[row.line] += 1
        return counts

    def _window_block(self) -> VGroup:
        """The rows of the window's lines (every line's when there is no window), one slot
        each from the top, placed by their baselines, and the notes of the lines above and
        below the window."""
        window = self.window or Window(0, len(self.code_lines))
        font, size, idle, cell = self.theme.mono_font, SOURCE_SIZE, self.theme.idle, self._cell()
        left = PANEL_SOURCE.x - PANEL_SOURCE.width / 2 + SOURCE_MARGIN
        top = PANEL_SOURCE.y + PANEL_SOURCE.height / 2
        slot = iter(range(self._slots()))
        parts, self.shown, self.slot_y = [], {}, {}

        def place(mobject, indent: int) -> float:
            y = top - (next(slot) + 0.5) * SOURCE_PITCH
            x = left + indent * cell + _ink_left(mobject.original_text, font, size)
            mobject.move_to((x, y, 0), aligned_edge=LEFT)
            mobject.shift([0, _baseline_offset(mobject, font, size), 0])
            parts.append(mobject)
            return y

        if self.window is not None:  # the first slot holds the note of the lines above
            above = _note(window.first, "above")
            if above:
                place(tag(typeset.text(above, font=font, size=size, colour=idle), "idle",
                          "panel:above"), 0)
            else:
                next(slot)
        for row in self.rows:
            if window.holds(row.line):
                mobject = tag(typeset.text(row.text or " ", font=font, size=size, colour=idle),
                              "idle", row.name)
                y = place(mobject, row.indent)
                self.shown.setdefault(row.line, []).append(mobject)
                self.slot_y.setdefault(row.line, []).append(y)
        below = _note(len(self.code_lines) - window.end, "below")
        if self.window is not None and below:
            place(tag(typeset.text(below, font=font, size=size, colour=idle), "idle",
                      "panel:below"), 0)
        return VGroup(*parts)

    def _pseudocode_block(self) -> VGroup:
        """The pseudocode rows in the theme's font, indented by level, each placed by its
        baseline, at their size: never shrunk to fit a height (only a row wider than the
        panel is, which the reading rules then report). Rows that fit :data:`PANEL_CODE` one
        every :data:`PSEUDOCODE_PITCH` are centred in it; more reach from its top down to
        :func:`code_floor`, closer (down to :data:`PSEUDOCODE_LEAST_PITCH`), then up
        (:func:`code_box`)."""
        font, size = self.theme.font, self.theme.pseudocode_size
        rows = VGroup(*[
            tag(typeset.text(step.text.strip() or " ", font=font, size=size,
                             colour=self.theme.idle), "idle", f"code:{k}")
            for k, step in enumerate(self.pseudocode, start=1)
        ])
        if not len(rows):
            return rows
        self.code_box, pitch = code_box(len(rows), self.shows_calls)
        offsets = [_baseline_offset(row, font, size) for row in rows]
        for k, (row, step) in enumerate(zip(rows, self.pseudocode, strict=True)):
            row.move_to((PSEUDOCODE_INDENT * step.depth, -k * pitch, 0), aligned_edge=LEFT)
            row.shift((0, offsets[k], 0))
        # as wide as its widest row will be: a row the run renames later ("claim VY = CH, or
        # VX …") keeps inside the box too (it ran off the frame's edge, centred for the rows
        # it replaced)
        widest = max([rows.width, *(indent + width for indent, width in
                                    self._later_widths(font, size))])
        scale = min(1.0, self.code_box.width / widest)
        if scale < 1.0:
            rows.scale(scale, about_point=rows.get_left())
        self.code_scale = scale
        # the block's lines, not its ink, centred in the box (its ink is higher where its
        # last row has no descenders)
        first_line = rows[0].get_y() - scale * offsets[0]
        middle = self.code_box.y + scale * pitch * (len(rows) - 1) / 2
        rows.shift((self.code_box.x - scale * widest / 2 - rows.get_left()[0],
                    middle - first_line, 0))
        self.light_height = pitch * scale - 0.04
        self.line_y = [row.get_y() - scale * d for row, d in zip(rows, offsets, strict=True)]
        return rows

    def _later_widths(self, font: str, size: float) -> list[tuple[float, float]]:
        """The indent and width of every row the run renames later (:attr:`later`)."""
        shown = {row.text for row in self.pseudocode}
        texts = {row.text for _, rows in self.later for row in rows} - shown
        return [(PSEUDOCODE_INDENT * PseudocodeRow(t).depth,
                 typeset.text(t.strip() or " ", font=font, size=size).width) for t in sorted(texts)]

    def follow_roles(self, beat: Beat, at_rest: bool = False,
                     focus: frozenset[str] | None = None) -> list[Animation]:
        """Animations recolouring the panel's vertices to this beat's roles (none shown with
        the source), and tinting the part of P its call works on (:meth:`_part`);
        ``at_rest``: all back to their ink (:meth:`metaphors.board.Board.play`);
        ``focus``: the part of P the call runs on, as the board's
        (:func:`metaphors.labels.new_colour`)."""
        if not self.drawing:
            return []
        return [*self._part(() if at_rest else beat.within), *self._recolour(beat.roles, at_rest, focus)]

    # --- the run's state, drawn plainly over the panel's polygon ------------------------------
    # DESIGN: "the same polygon drawn plainly with objects coloured by their role in the
    # current call". The performers hand the panel what they draw on the picture (under the
    # picture's own keys: a claim, the edge it crosses, a diagonal, a keyhole cut, what a
    # slice leaves of P), and :meth:`metaphors.board.Board.drop` takes the panel's away with
    # the picture's: the panel kept the bare polygon while the picture sliced it, split it and
    # claimed diagonals in it (review: at 9 s of ear clipping it still drew A, sliced off).

    def _colour(self, role: str | None) -> str:
        """A role's colour; the ink for none (or idle): a diagonal made, a cut."""
        return self.theme.ink if role in (None, "idle") else self.theme.role_colour(role)

    def draw(self, key: str, a: Sequence[float], b: Sequence[float], role: str | None,
             width: float = 1.0) -> list[Animation]:
        """Draw the segment from ``a`` to ``b`` (points of P) under ``key`` in ``role``'s
        colour (the ink for None), ``width`` times the theme's stroke; one drawn under that
        key before goes. None while the source takes the polygon's place."""
        if not self.drawing:
            return []
        gone = self.drop(key)
        line = tag(Line(self.frame.to_scene(a), self.frame.to_scene(b), color=self._colour(role),
                        stroke_width=self.theme.stroke * width), role or "idle", f"{DRAWN}{key}")
        self.lines[key] = line
        return [*gone, Create(line)]

    def recolour(self, key: str, role: str | None, new_key: str | None = None,
                 width: float | None = None) -> list[Animation]:
        """The segment under ``key`` turning to ``role``'s colour (and ``width``), kept under
        ``new_key`` from now on if given (the claim split along becomes a diagonal)."""
        line = self.lines.pop(key, None)
        if line is None:
            return []
        self.lines[new_key or key] = tag(line, role or "idle", f"{DRAWN}{new_key or key}")
        target = line.copy().set_color(self._colour(role))
        if width is not None:
            target.set_stroke(width=self.theme.stroke * width)
        return [Transform(line, target)]

    def drop(self, *keys: str) -> list[Animation]:
        """Fade-outs of the segments under these keys (those the panel has)."""
        return [FadeOut(self.lines.pop(key)) for key in keys if key in self.lines]

    def _part(self, labels: tuple[str, ...]) -> list[Animation]:
        """The part of P the running call works on (``labels``: divide and conquer's piece,
        :attr:`story.beats.Beat.within`) tinted in the blue of what a call runs on; none, no
        tint. On the picture each piece has a tint of its own, and which one the heuristic
        works on showed nowhere ("No reflex vertex: the polygon is convex": which one?)."""
        if labels == self.part_labels or any(label not in self.where for label in labels):
            return []
        self.part_labels = labels
        anims: list[Animation] = [FadeOut(self.part)] if self.part is not None else []
        self.part = None
        if labels:
            self.part = tag(MPolygon(*[self.frame.to_scene(self.where[label]) for label in labels],
                                     stroke_width=0, fill_color=self.theme.called,
                                     fill_opacity=PART_OPACITY), "called", f"{DRAWN}part")
            self.part.set_z_index(-1)  # under the outline's edges and the lines drawn
            anims.append(FadeIn(self.part))
        return anims

    def tint(self, key: str, points: Sequence[Sequence[float]]) -> list[Animation]:
        """The part of P at ``points`` tinted in the blue of what a call runs on, under
        ``key`` (prune and search's good sub-polygon, as the picture tints it): faded in, or
        the tint under ``key`` shrinking to it."""
        if not self.drawing:
            return []
        shape = tag(MPolygon(*[self.frame.to_scene(p) for p in points], stroke_width=0,
                             fill_color=self.theme.called, fill_opacity=PART_OPACITY),
                    "called", f"{DRAWN}{key}")
        shape.set_z_index(-1)  # under the outline's edges and the lines drawn
        if key in self.lines:
            return [Transform(self.lines[key], shape)]
        self.lines[key] = shape
        return [FadeIn(shape)]

    def _ring(self, points: Sequence[Sequence[float]]) -> MPolygon:
        """The panel's outline as one ring of ``points`` (what slicing leaves of P)."""
        ring = MPolygon(*[self.frame.to_scene(p) for p in points], color=self.theme.ink,
                        stroke_width=self.theme.stroke, fill_color=self.theme.polygon_fill,
                        fill_opacity=FILL_OPACITY)
        return tag(ring, "idle", "panel:polygon")

    def slice_off(self, before: Sequence[Point], at: int, rest: Sequence[Point]
                  ) -> list[Animation]:
        """A slice cut off: the outline shrinks to ``rest`` (its ear's vertex, at ``at`` in
        the ring ``before`` the slice, sliding onto the middle of the cut, as the fruit does),
        and the markers of the vertices no longer on it go (faded where they stand). The ring
        ``before`` is put in unseen first (a polygon with holes, drawn as three rings, is one
        ring with its keyhole cuts, the same shape): the keyhole cuts are its edges then.
        :meth:`settle_outline` puts the rest's own ring in after the play."""
        if not self.drawing:
            return []
        anims: list[Animation] = []
        if before:
            self.outline.become(self._ring(before))
            a, c = before[at - 1], before[(at + 1) % len(before)]
            middle = ((a[0] + c[0]) / 2, (a[1] + c[1]) / 2)
            anims.append(Transform(self.outline, self._ring([*before[:at], middle,
                                                             *before[at + 1:]])))
            anims += self.drop(*[key for key in self.lines if key.startswith("keyhole:")])
        else:
            anims.append(Transform(self.outline, self._ring(rest)))
        self.after_slice = list(rest)
        left = {(round(x, 9), round(y, 9)) for x, y in rest}
        for label in [label for label in self.markers
                      if tuple(round(c, 9) for c in self.where[label]) not in left]:
            self.off[label] = self.markers.pop(label)
            self.roles.pop(label, None)
            anims.append(FadeOut(self.off[label]))
        return anims

    def settle_outline(self) -> None:
        """After a slice's play: the outline as the rest's own ring (:meth:`slice_off`)."""
        if self.after_slice is not None:
            self.outline.become(self._ring(self.after_slice))
            self.after_slice = None

    def whole(self, triangles: Sequence[Sequence[Point]]) -> list[Animation]:
        """The run's end: P whole again (with its holes), every vertex sliced off back in its
        ink, and the triangulation drawn in it, each triangle's edges thin in the ink (the
        picture shows the whole triangulation: the panel kept the last slice)."""
        if not self.drawing:
            return []
        outline = tag(polygon_mobject(self.polygon, self.frame, self.theme, self.holes),
                      "idle", "panel:polygon")
        outline.set_fill(opacity=FILL_OPACITY)
        old, self.outline = self.outline, outline
        anims: list[Animation] = [FadeOut(old), FadeIn(outline), *self.drop(*list(self.lines))]
        drawn = VGroup(*[MPolygon(*[self.frame.to_scene(p) for p in corners],
                                  color=self.theme.ink,
                                  stroke_width=self.theme.stroke * DIAGONAL_WIDTH,
                                  fill_opacity=0) for corners in triangles])
        self.lines["triangulation"] = tag(drawn, "result", f"{DRAWN}triangulation")
        anims.append(FadeIn(drawn))
        for label, marker in sorted(self.off.items()):
            marker.set_color(self.theme.ink)
            self.markers[label] = tag(marker, "idle")
            anims.append(FadeIn(marker))
        self.off = {}
        return anims

    def follow_text(self, beat: Beat) -> list[Animation]:
        """Animations moving the light to this beat's line and showing its call line (none if
        neither changes)."""
        if self.mode == PSEUDOCODE:
            anims = [*self._rename(beat), *self._light_row(beat.row)]
        else:
            anims = self._light_line(beat.line)
        if beat.call is not None and self.shows_calls:
            anims += self._call_line(beat.call)
        return anims

    def _recolour(self, roles: Mapping[str, str], at_rest: bool = False,
                  focus: frozenset[str] | None = None) -> list[Animation]:
        anims = []
        wanted = {label: roles.get(label, "idle") for label in self.markers}
        for label, role in wanted.items():
            marker = self.markers[label]
            colour = new_colour(marker, label, role, self.roles.get(label, "idle"), self.theme,
                                focus, at_rest)
            if colour is not None:
                anims.append(tag(marker, "idle" if at_rest else role).animate.set_color(colour))
        self.roles = {label: "idle" for label in self.markers} if at_rest else wanted
        return anims

    def _light_line(self, line: int | None) -> list[Animation]:
        """Light the rows of the source line ``line``, bringing the window to it first if it
        is not shown (the rows fade out and the new window's fade in)."""
        index = next((k for k, (number, _) in enumerate(self.code_lines) if number == line), None)
        if index is None or (self.lit is not None and self.lit[0] == index):
            return []
        anims = []
        if self.window is not None and not self.window.holds(index):
            self.window = window_for(self._row_counts(), self._slots() - 2, index, self.window)
            old, self.code = self.code, self._window_block()
            anims = [FadeOut(old), FadeIn(self.code)]
        rows, ys = self.shown[index], self.slot_y[index]
        light = self._light(SOURCE_PITCH * len(rows) - 0.04, (ys[0] + ys[-1]) / 2,
                            PANEL_SOURCE)
        copy = tag(VGroup(*[tag(row.copy().set_color(self.theme.ink), "called", row.name)
                            for row in rows]), "called", rows[0].name)
        return [*anims, *self._relight(index, light, copy)]

    def _rename(self, beat: Beat) -> list[Animation]:
        """From the beat that picks the vertex on: the rows that name it in its place, each
        typeset anew where the old one stood (a cut); a lit row that changed is lit again,
        its old light and copy cut too (:meth:`cut_outgoing`). No animation: none is
        returned (a list, as the panel's other steps give)."""
        due = [rows for seq, rows in self.later if seq <= beat.seq]
        if not due:
            return []
        rows, self.later = due[-1], [stage for stage in self.later if stage[0] > beat.seq]
        font, size = self.theme.font, self.theme.pseudocode_size
        for k, (old, new) in enumerate(zip(self.pseudocode, rows, strict=True)):
            if old.text == new.text:
                continue
            row = tag(typeset.text(new.text.strip() or " ", font=font, size=size,
                                   colour=self.theme.idle), "idle", f"code:{k + 1}")
            row.scale(self.code_scale)
            shown = self.code[k]
            row.move_to((shown.get_left()[0], self.line_y[k] + self.code_scale
                         * _baseline_offset(row, font, size), 0), aligned_edge=LEFT)
            # a cut, in place: never crossfaded over the old one, and the code stays in the
            # still layer (no play redraws it in every frame: tests/test_redraw.py)
            row.set_z_index(shown.z_index)
            self.code.submobjects[k] = row
            if self.lit is not None and self.lit[0] == k:  # its lit copy says the old text
                self.outgoing_lit, self.lit = list(self.lit[1:]), None
        self.pseudocode = rows
        return []

    def _light_row(self, index: int | None) -> list[Animation]:
        """Light pseudocode row ``index``: a light fades in behind it and a copy of the row
        in ink over the grey row, while the last ones fade out. The rows themselves never
        change, and nothing slides over them, so they stay in the still layer of every frame.
        None, or the row already lit: the light stays where it is."""
        if index is None or not 0 <= index < len(self.code) or (
                self.lit is not None and self.lit[0] == index):
            return []
        row = self.code[index]
        # rows to light: the pseudocode is shown, and with it the lights' height
        light = self._light(cast(float, self.light_height), self.line_y[index], self.code_box)
        copy = tag(row.copy().set_color(self.theme.ink), "called", row.name)
        return self._relight(index, light, copy)

    def _light(self, height: float, y: float, box) -> Rectangle:
        """The light behind a lit row (or a lit line's rows), across the code's box."""
        light = tag(Rectangle(width=box.width, height=height, stroke_width=0,
                              fill_color=self.theme.called, fill_opacity=0.3), "called",
                    "panel:lit")
        return light.move_to((box.x, y, 0))

    def _relight(self, index: int, light: Rectangle, copy) -> list[Animation]:
        """Fade the last light and copy out and these in (over the rows, under all else)."""
        for mobject in (light, copy):
            mobject.set_z_index(BACKDROP_Z)  # the copy would keep the row's STILL_Z
        anims = [FadeOut(m) for m in self.lit[1:]] if self.lit is not None else []
        self.lit = (index, light, copy)
        return [*anims, FadeIn(light), FadeIn(copy)]

    def _call_line(self, text: str) -> list[Animation]:
        """The call line saying ``text``: none if it says so already (the water's, the
        hand's and the line's beats of one call were each cut and faded in again, so that the
        same line flickered two to six times)."""
        if text == self.call_text:
            return []
        self.call_text = text
        font, width = self.theme.mono_font, PANEL_CODE.width
        new: Mobject
        if self.code_box.rect[1] < code_floor(True) - 1e-9:
            # the code reaches down to where a call's second line would stand: one line, cut
            new = typeset.text(_one_line(text, font, 20, width), font=font, size=20,
                               colour=self.theme.ink)
        else:
            new = _call_text(text, font, 20, self.theme.ink, width)
        new = tag(new, "called", "panel:call")
        new.move_to((PANEL_CODE.x, PANEL_CALL_Y, 0))
        # the old one is cut, not faded out: two calls fading through each other in one
        # place are unreadable (issue 22: never two texts over each other)
        self.outgoing_call, self.call = self.call, new
        return [FadeIn(new)]

    def cut_outgoing(self) -> list[Mobject]:
        """The call line being replaced and a renamed row's old light, once (the board takes
        them off the screen at once)."""
        gone = [*([self.outgoing_call] if self.outgoing_call is not None else []),
                *self.outgoing_lit]
        self.outgoing_call, self.outgoing_lit = None, []
        return gone


def _note(lines: int, where: str) -> str:
    """The note of the lines a window leaves out above or below it ('' for none).

    >>> _note(1, "above"), _note(12, "below"), _note(0, "below")
    ('⋮ 1 line above', '⋮ 12 lines below', '')
    """
    return f"⋮ {lines} line{'s' if lines != 1 else ''} {where}" if lines else ""


def call_pieces(text: str) -> list[str]:
    """A call line cut where a programmer would break it: after each argument's comma (at
    the call's own level, never inside a list or a nested call) and before its result's
    arrow; the pieces joined by spaces are the text again.

    >>> call_pieces("first_hit_sweeping(B, [6.1, -5.9], [D, E], T(ABC)) → E")
    ['first_hit_sweeping(B,', '[6.1, -5.9],', '[D, E],', 'T(ABC))', '→ E']
    >>> call_pieces("candidates_in_triangle(P, T(ABC)) → [D, E]")
    ['candidates_in_triangle(P,', 'T(ABC))', '→ [D, E]']
    """
    pieces, depth, start, called = [], 0, 0, False  # called: the call's parenthesis closed
    for k, c in enumerate(text):
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            called = called or depth == 0
        at_space = c == " " and k > start
        if at_space and ((depth == 1 and not called and text[k - 1] == ",") or (
                depth == 0 and text.startswith("→", k + 1))):
            pieces.append(text[start:k])
            start = k + 1
    return [*pieces, text[start:]]


def call_lines(text: str, font: str, size: float, width: float) -> list[str]:
    """The lines of a call line ``text`` at ``size`` within ``width``: as many of its
    :func:`call_pieces` on each as fit (a piece wider than ``width`` alone on its line). The
    call wrapped as words broke its lists ("[D," then "E]) → D", review of the scenes:
    TranslationCorrect's ``[D,`` / ``E], T(ABC)) → E``).

    >>> call_lines("first_hit_sweeping(B, [6.1, -5.9], [D, E], T(ABC)) → E",
    ...            "DejaVu Sans Mono", 20, 6.6)
    ['first_hit_sweeping(B, [6.1, -5.9],', '[D, E], T(ABC)) → E']
    """
    lines: list[str] = []
    for piece in call_pieces(text):
        trial = f"{lines[-1]} {piece}" if lines else piece
        if lines and typeset.natural_width(trial, font, size) <= width:
            lines[-1] = trial
        else:
            lines.append(piece)
    return lines


def _call_text(text: str, font: str, size: float, colour: str, width: float) -> Mobject:
    """The call line set in as many lines as it needs (:func:`call_lines`), left-aligned."""
    parts = [typeset.text(line, font=font, size=size, colour=colour, width=width)
             for line in call_lines(text, font, size, width)]
    if len(parts) == 1:
        return parts[0]
    return VGroup(*parts).arrange(DOWN, aligned_edge=LEFT, buff=0.1)


def _one_line(text: str, font: str, size: float, width: float) -> str:
    """``text`` cut at its end, with an ellipsis, to fit ``width`` at ``size``.

    >>> _one_line("nearest_to(B, [D, E]) → D", "DejaVu Sans Mono", 20, 9.0)
    'nearest_to(B, [D, E]) → D'
    >>> _one_line("nearest_to(B, [D, E]) → D", "DejaVu Sans Mono", 20, 2.5)
    'nearest_to(B,…'
    """
    cut = text
    while len(cut) > 1 and typeset.natural_width(
            cut if cut == text else cut + "…", font, size) > width:
        cut = cut[:-1].rstrip()
    return cut if cut == text else cut + "…"


def _ink_left(string: str, font: str, size: float) -> float:
    """How far right of where its first cell starts a text's ink starts, less the same for
    ``M``: placed by their ink, monospace rows would be out of line by their first glyphs'
    side bearings. (Ink of ``M`` + string: from M's bearing to the string's ink end.)"""
    def width(text: str) -> float:
        return typeset.natural_width(text, font, size)

    return (width("M" + string) - width(string)) - (width("MM") - width("M"))


def _baseline_offset(row, font: str, size: float) -> float:
    """How far to move a row up (down if negative) so that its line, not its own glyphs, is
    centred where it was: a text is centred on its glyphs (one with descenders sits higher
    than one without), but the same text followed by a bar ``|``, which reaches from the
    lowest descender to above the capitals, is centred on the line."""
    if not len(row.points):
        return 0.0
    with_bar = typeset.outline(row.original_text + " |", font, float(size))
    own = typeset.outline(row.original_text, font, float(size))
    return float(with_bar[0][1] - own[0][1]) if len(with_bar) and len(own) else 0.0


def code_box(rows: int, calls: bool) -> tuple[Box, float]:
    """The box ``rows`` pseudocode rows take and their pitch: :data:`PANEL_CODE` when they fit
    it at :data:`PSEUDOCODE_PITCH`; else from its top down to :func:`code_floor` (above a
    call line of two lines, or, if the rows need it, of one), a pitch as close as they need
    (no closer than :data:`PSEUDOCODE_LEAST_PITCH`); else higher than its top (the panel's
    polygon makes room: :meth:`Panel._draw_polygon`).

    >>> code_box(6, calls=True)[0] == PANEL_CODE, code_box(6, calls=True)[1]
    (True, 0.34)
    >>> def rows_in(rows, calls):
    ...     box, pitch = code_box(rows, calls)
    ...     return round(pitch, 4), round(box.rect[1], 3), round(box.rect[3], 3)
    >>> rows_in(10, calls=False), rows_in(8, calls=True), rows_in(10, calls=True)
    ((0.3175, -2.85, 0.325), (0.3281, -2.3, 0.325), (0.28, -2.475, 0.325))
    """
    if rows * PSEUDOCODE_PITCH <= PANEL_CODE.height + 1e-9:
        return PANEL_CODE, PSEUDOCODE_PITCH
    left, _, right, top = PANEL_CODE.rect
    floors = [code_floor(True), code_floor(True, call_lines=1)] if calls else [code_floor(False)]
    bottom = next((f for f in floors if (top - f) / rows >= PSEUDOCODE_LEAST_PITCH - 1e-9),
                  floors[-1])
    pitch = max(PSEUDOCODE_LEAST_PITCH, min(PSEUDOCODE_PITCH, (top - bottom) / rows))
    top = max(top, bottom + rows * pitch)
    bottom = top - rows * pitch  # the rows' own slots, from the top: no more
    return Box((left + right) / 2, (top + bottom) / 2, right - left, top - bottom), pitch


# --- the panel polygon's labels: each clear of the outline, the dots and the other labels -------

#: how far a label of the panel's polygon keeps from its outline, its dots and other labels
LABEL_CLEARANCE = 0.05
#: the distances a label's box may stand from its vertex, nearest first
LABEL_DISTANCES = (0.1, 0.16, 0.24, 0.34, 0.46)
#: the directions a label may stand in from its vertex (every 15°)
LABEL_DIRECTIONS = 24
#: how much nearer its own dot than any other a label's centre stands (a label midway
#: between two dots, as the keyhole's b₂ between a₂ and b₂, names neither)
LABEL_OWN = 1.25
#: the least a label keeps from the outline and the dots where it has no place nearer its
#: own dot :data:`LABEL_CLEARANCE` clear (the reading rule asks for 0.03)
LABEL_NARROW = 0.035
#: the finer ring of places a label with no roomy place of its own is looked for on
FINE_DISTANCES = tuple(round(0.04 + 0.02 * i, 2) for i in range(22))
FINE_DIRECTIONS = 72


def panel_markers(polygon: Polygon, holes: Sequence[Hole], frame: Frame, theme: Theme,
                  area: Box = PANEL_LABELS, lines: Sequence[tuple[np.ndarray, np.ndarray]] = ()
                  ) -> list[tuple[str, VGroup]]:
    """(label, dot and label) for every vertex of the panel's polygon and of its holes.

    The panel draws P small: the board's rule (a label away from the centre, at a fixed
    distance: :func:`metaphors.drawing.vertex_markers`) puts labels of close vertices over an
    edge or over each other (the lecture's M and K). Here each label takes the nearest free
    place around its vertex (:func:`_label_places`): within ``area``, clear by
    :data:`LABEL_CLEARANCE` of every edge, every dot and every other label, and nearer its own
    vertex than any other (:func:`_assigned`). A label with no such place is left out (its
    dot stays): a label over an edge or another label would be misread, and a smaller one
    would be under 2.5 % of the frame's height. Every scene's and chapter's polygon keeps all
    its labels (tests.reading_rules.crowded_panel_labels). ``lines``: segments on screen the
    labels keep clear of as of the edges (the claims, cuts and diagonals the run draws)."""
    rings = [frame.many(polygon.points), *(frame.many(h.points) for h in holes)]
    vertices = [(label, point, _away(point, rings[0]), theme.label_size)
                for label, point in zip(polygon.labels, rings[0], strict=True)]
    for hole, ring in zip(holes, rings[1:], strict=True):
        # lower-case letters stand lower than capitals: a size larger keeps them 2.5 % high
        vertices += [(label, point, _away(point, ring), theme.label_size + 4)
                     for label, point in zip(hole.labels, ring, strict=True)]
    texts = [typeset.text(label, font=theme.font, size=size, colour=theme.ink)
             for label, _, _, size in vertices]
    points = [(float(p[0]), float(p[1])) for _, p, _, _ in vertices]
    edges = [edge for ring in rings for edge in ring_edges(ring)]
    dots = [(x, y, theme.dot_radius) for x, y in points]
    fixed = Obstacles(segments=edges, dots=dots)
    drawn = Obstacles(segments=[*edges, *((a[:2], b[:2]) for a, b in lines)], dots=dots)
    bounds = (area.x - area.width / 2, area.y - area.height / 2,
              area.x + area.width / 2, area.y + area.height / 2)

    def places_of(k: int, away: float, width: float, height: float
                  ) -> list[tuple[tuple[float, float], Rect]]:
        """Vertex ``k``'s places: roomy ones clear of the lines drawn too, if it has any;
        else those clear of the edges (a vertex many diagonals meet, ear clipping's G, has
        no room between them: kept clear of all, its label stood nearer C than G)."""
        if lines:
            # roomy ones first, then the narrower ones still nearer their own dot than any
            # other: kept clear of the edges only, chapter 1's M, H and G stood on the
            # diagonals drawn through them (68-102 s)
            for clear_of_all in _tiers(k, points, away, width, height, drawn, bounds,
                                       LABEL_DISTANCES, LABEL_DIRECTIONS)[:2]:
                if clear_of_all:
                    return clear_of_all
        return _label_places(k, points, away, width, height, fixed, bounds)

    places = [places_of(k, away, t.width, t.height)
              for k, ((_, _, away, _), t) in enumerate(zip(vertices, texts, strict=True))]
    chosen = _assigned(places)
    markers = []
    for k, ((label, point, _, _), t) in enumerate(zip(vertices, texts, strict=True)):
        dot = Dot(point, radius=theme.dot_radius, color=theme.ink)
        if k in chosen:
            t.move_to((*chosen[k], 0))
            # a halo in the background's colour, unseen but where a line the run draws
            # passes under the label (a diagonal of the whole triangulation, a slice's cut
            # where no place clear of them was left): the line stops short of its glyphs
            t.set_stroke(theme.background, width=LABEL_HALO, background=True)
            t.joint_type = LineJointType.ROUND
            markers.append((label, VGroup(dot, t)))
        else:
            markers.append((label, VGroup(dot)))
    return markers


def _away(point: np.ndarray, ring: list[np.ndarray]) -> float:
    """The angle from the centre of ``ring`` to ``point``: where a label stands by default."""
    centre = np.mean(ring, axis=0)
    dx, dy = (point - centre)[:2]
    return math.atan2(dy, dx) if math.hypot(dx, dy) > 1e-9 else -math.pi / 2


def _label_places(k: int, points: list[tuple[float, float]], away: float, width: float,
                  height: float, fixed: Obstacles, bounds: Rect
                  ) -> list[tuple[tuple[float, float], Rect]]:
    """The free places of vertex ``k``'s ``width`` × ``height`` label, best first: each its
    centre and its box, in ``bounds``, clear of ``fixed`` (the outline and the dots), its box
    nearer its own vertex than any other (a label between two dots names neither). First
    those :data:`LABEL_CLEARANCE` clear whose centre stands :data:`LABEL_OWN` times nearer its
    own dot than any other, then those only :data:`LABEL_NARROW` clear that do, then the
    rest :data:`LABEL_CLEARANCE` clear (a crowded hole's vertex: the keyhole's b₂ between a₂
    and G); each tier nearest first, then nearest to the direction ``away``."""
    found = _tiers(k, points, away, width, height, fixed, bounds, LABEL_DISTANCES,
                   LABEL_DIRECTIONS)
    if not found[0]:  # none roomy and its own: look closer, on a finer ring of places
        found = _tiers(k, points, away, width, height, fixed, bounds, FINE_DISTANCES,
                       FINE_DIRECTIONS)
    return [place for tier in found for place in tier]


def _tiers(k: int, points: list[tuple[float, float]], away: float, width: float, height: float,
           fixed: Obstacles, bounds: Rect, distances: Sequence[float], directions: int
           ) -> list[list[tuple[tuple[float, float], Rect]]]:
    """:func:`_label_places`' three tiers, on ``distances`` × ``directions`` round vertex ``k``;
    the places across a line from the dot (:func:`metaphors.labels.seen_by`) in the last."""
    turns = [(step + 1) // 2 * (1 if step % 2 else -1) * 2 * math.pi / directions
             for step in range(directions)]
    # the box's side nearest the vertex stands a distance from it
    centres = around([points[k]], [(math.cos(away + t), math.sin(away + t)) for t in turns],
                     distances, size=(width, height))
    wide = clear(centres, (width, height), fixed, LABEL_CLEARANCE, bounds)
    narrow = clear(centres, (width, height), fixed, LABEL_NARROW, bounds)
    # seen from its dot, across no edge: the counterexample's E stood below edge B–C, cut
    # off from its vertex above it (chapter 3 at 52 s)
    seen = seen_by(centres, np.array(points[k]), fixed.segments)
    tiers: list[list[tuple[tuple[float, float], Rect]]] = [[], [], [], [], [], []]
    for (x, y), roomy, tight, sees in zip(centres.tolist(), wide, narrow, seen, strict=True):
        rect = (x - width / 2, y - height / 2, x + width / 2, y + height / 2)
        own, others = _gap(rect, points[k]), [q for j, q in enumerate(points) if j != k]
        if not tight or not all(_gap(rect, q) > own for q in others):
            continue
        mine = all(math.dist((x, y), q) >= LABEL_OWN * math.dist((x, y), points[k])
                   for q in others)
        tier = 0 if mine and roomy else 1 if mine else 2 if roomy else None
        if tier is not None:
            tiers[tier if sees else tier + 3].append(((x, y), rect))
    # a place across an edge only where its side of the edge has none (the counterexample's
    # E, 0.1 over B–C in the panel, has no room there: it keeps its label)
    return [tiers[0], tiers[1], tiers[2] + tiers[3] + tiers[4] + tiers[5]]


def _gap(rect: Rect, point: tuple[float, float]) -> float:
    """How far ``point`` is from the box ``rect``."""
    x0, y0, x1, y1 = rect
    return math.hypot(max(x0 - point[0], 0.0, point[0] - x1), max(y0 - point[1], 0.0, point[1] - y1))


#: the least gap between two labels side by side on one line: more than a space, so that
#: they read as two words (the keyhole's a₂ and b₂, 0.05 apart, read "a₂b₂")
LABEL_WORD_GAP = 0.12


def _apart(a: Rect, b: Rect) -> bool:
    """Whether two labels' boxes keep :data:`LABEL_CLEARANCE` apart, and
    :data:`LABEL_WORD_GAP` when they stand side by side (their heights overlap by half the
    lower one's)."""
    beside = min(a[3], b[3]) - max(a[1], b[1]) > min(a[3] - a[1], b[3] - b[1]) / 2
    across = LABEL_WORD_GAP if beside else LABEL_CLEARANCE
    return (a[2] + across <= b[0] or b[2] + across <= a[0]
            or a[3] + LABEL_CLEARANCE <= b[1] or b[3] + LABEL_CLEARANCE <= a[1])


#: the most candidate places :func:`_assigned` tries before it settles for the most labels found
ASSIGN_BUDGET = 200_000


def _assigned(places: list[list[tuple[tuple[float, float], Rect]]]) -> dict[int, tuple[float, float]]:
    """A place for each label, no two too close (:func:`_apart`): a depth-first search, the
    most hemmed-in label first and each label's best places first, so the first whole
    assignment found keeps labels near their vertices. If none is found within
    :data:`ASSIGN_BUDGET` tries, each label in turn takes its best place still free, and a
    label with none is left out (deterministic either way)."""
    order = sorted((k for k in range(len(places)) if places[k]), key=lambda k: (len(places[k]), k))
    tries = 0

    def search(i: int, taken: dict[int, int]) -> bool:
        nonlocal tries
        if i == len(order):
            return True
        k = order[i]
        for c, (_, rect) in enumerate(places[k]):
            tries += 1
            if tries > ASSIGN_BUDGET:
                return False
            if all(_apart(rect, places[j][d][1]) for j, d in taken.items()):
                taken[k] = c
                if search(i + 1, taken):
                    return True
                del taken[k]
        return False

    taken: dict[int, int] = {}
    if not search(0, taken):
        taken = {}
        for k in order:
            c = next((c for c, (_, rect) in enumerate(places[k])
                      if all(_apart(rect, places[j][d][1]) for j, d in taken.items())), None)
            if c is not None:
                taken[k] = c
    return {k: places[k][c][0] for k, c in taken.items()}
