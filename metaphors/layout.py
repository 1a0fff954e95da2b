"""Where things go on the 16:9 frame (14.2 × 8 units): metaphor left, panel right, subtitle below."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from manim import DL, UR, Mobject
from shapely.geometry.base import BaseGeometry

from metaphors.theme import Theme
from rendering.typeset import text


@dataclass(frozen=True)
class Box:
    """A rectangle of the frame: centre and size."""

    x: float
    y: float
    width: float
    height: float

    @property
    def center(self) -> tuple[float, float]:
        return (self.x, self.y)

    @property
    def rect(self) -> Rect:
        """Its left, bottom, right and top."""
        return (self.x - self.width / 2, self.y - self.height / 2, self.x + self.width / 2,
                self.y + self.height / 2)


TITLE_Y = 3.55
METAPHOR = Box(-3.45, -0.05, 5.6, 5.6)
# the panel's polygon leaves room for its vertex labels (up to 0.47 outside it) below the title
# and above the code
PANEL_POLYGON = Box(3.6, 1.82, 4.6, 2.0)
#: where the panel's pseudocode stands (its lights run across it), 0.2 to 6.8 across: as wide
#: as the frame's margin lets it, for rows at their size (the monotone sweep's widest, 6.4)
PANEL_CODE = Box(3.5, -0.95, 6.6, 2.55)
#: where the labels of the panel's polygon may stand: round it, under the title (its bottom
#: 3.35) and over the code (its top 0.33), each 0.05 clear
PANEL_LABELS = Box(3.6, 1.84, 5.8, 2.92)
# the source (``--panel source``) takes the polygon's place too: title to call line
PANEL_SOURCE = Box(3.58, 0.45, 6.7, 5.3)
PANEL_CALL_Y = -2.65
SUBTITLE_Y = -3.55
#: the widest a subtitle line may be (scene units) before it takes two lines
SUBTITLE_WIDTH = 13.4
#: the lowest a subtitle reaches: a subtitle of two lines grows upwards from it
SUBTITLE_BOTTOM = -3.8


def subtitle_centre(height: float) -> tuple[float, float, float]:
    """Where a subtitle ``height`` tall is centred: on :data:`SUBTITLE_Y`, or higher if it
    would reach below :data:`SUBTITLE_BOTTOM`.

    >>> subtitle_centre(0.3), subtitle_centre(0.8)
    ((0, -3.55, 0), (0, -3.4, 0))
    """
    return (0, round(max(SUBTITLE_Y, SUBTITLE_BOTTOM + height / 2), 6), 0)


# --- one search for a clear place: candidates in a first-fit order, measured against obstacles ---

#: a rectangle of the frame: left, bottom, right, top
Rect = tuple[float, float, float, float]
#: a point of the frame (scene units), and a straight line drawn between two
XY = Sequence[float] | np.ndarray
Segment = tuple[XY, XY]


def ring_edges(ring: Sequence[XY]) -> list[Segment]:
    """The edges of a closed ring of points, each from a point to the next.

    >>> ring_edges([(0, 0), (1, 0), (0, 1)])
    [((0, 0), (1, 0)), ((1, 0), (0, 1)), ((0, 1), (0, 0))]
    """
    return [(p, ring[(k + 1) % len(ring)]) for k, p in enumerate(ring)]
#: the whole frame (14.2 × 8 units), less a margin of 0.3 (4 % of its height) that keeps a
#: thing off the screen's edge, where a projector may crop it
FRAME_AREA: Rect = (-6.8, -3.7, 6.8, 3.7)
#: the highest a subtitle reaches (two lines of it, grown up from :data:`SUBTITLE_BOTTOM`)
SUBTITLE_TOP = SUBTITLE_BOTTOM + 0.85
#: how far a placed thing keeps from everything else on screen
CLEARANCE = 0.12
#: the grid a free place is looked for on (scene units)
PLACE_STEP = 0.05


@dataclass(frozen=True)
class Obstacles:
    """What a thing placed on screen keeps clear of: boxes (labels, text, a panel's parts),
    segments (edges, diagonals, a claim), dots (centre and radius) and any other shapes (a
    polygon's region, a shaded part of it)."""

    boxes: Sequence[Rect] = ()
    segments: Sequence[Segment] = ()
    dots: Sequence[tuple[float, float, float]] = ()
    shapes: Sequence[BaseGeometry] = ()

    def plus(self, *, boxes: Sequence[Rect] = (), segments: Sequence[Segment] = ()
             ) -> Obstacles:
        """These obstacles and more."""
        return Obstacles((*self.boxes, *boxes), (*self.segments, *segments), self.dots,
                         self.shapes)

    def gaps(self, rects: np.ndarray) -> np.ndarray:
        """The distance from each rectangle (rows of left, bottom, right, top) to the nearest
        obstacle: 0 where one meets it, infinite where there are none."""
        rects = np.asarray(rects, dtype=float).reshape(-1, 4)
        gap = np.full(len(rects), np.inf)
        if not len(rects):
            return gap
        candidates = shapely.box(rects[:, 0], rects[:, 1], rects[:, 2], rects[:, 3])
        lines = [shapely.LineString([np.asarray(a, float)[:2], np.asarray(b, float)[:2]])
                 for a, b in self.segments]
        solid = [*(shapely.box(*r) for r in self.boxes), *lines, *self.shapes]
        if solid:
            gap = np.minimum(gap, shapely.distance(candidates, shapely.union_all(solid)))
        if len(self.dots):
            gap = np.minimum(gap, np.maximum(dot_gaps(rects, self.dots).min(axis=1), 0.0))
        return gap


def dot_gaps(rects: np.ndarray, dots: Sequence[tuple[float, float, float]]) -> np.ndarray:
    """The distance from each rectangle (rows of left, bottom, right, top) to each dot
    (centre and radius; negative where they overlap), one row a rectangle: computed at once,
    not a shapely call a dot (a label's places are tried by the hundred).

    >>> dot_gaps(np.array([[0.0, 0.0, 1.0, 1.0]]), [(4.0, 5.0, 1.0), (0.5, 0.5, 0.1)]).tolist()
    [[4.0, -0.1]]
    """
    rects = np.asarray(rects, dtype=float).reshape(-1, 4)
    d = np.asarray(dots, dtype=float).reshape(-1, 3)
    dx = np.maximum(np.maximum(rects[:, None, 0] - d[None, :, 0], 0.0),
                    d[None, :, 0] - rects[:, None, 2])
    dy = np.maximum(np.maximum(rects[:, None, 1] - d[None, :, 1], 0.0),
                    d[None, :, 1] - rects[:, None, 3])
    return np.hypot(np.maximum(dx, 0.0), np.maximum(dy, 0.0)) - d[None, :, 2]


def rects_at(centres: np.ndarray, size: tuple[float, float]) -> np.ndarray:
    """The rectangles ``size`` (width, height) centred on each of ``centres``."""
    c = np.asarray(centres, dtype=float).reshape(-1, 2)
    w, h = size[0] / 2, size[1] / 2
    return np.column_stack([c[:, 0] - w, c[:, 1] - h, c[:, 0] + w, c[:, 1] + h])


def around(anchors: Sequence[XY], directions: Sequence[XY], distances: Sequence[float],
           size: tuple[float, float] | None = None) -> np.ndarray:
    """Candidate centres round anchors, in first-fit order: the nearest distance first, then
    anchor by anchor, then direction by direction (unit vectors). A distance is the centre's
    from its anchor, or, given the thing's ``size``, its box's nearest side's.

    >>> around([(0, 0)], [(1, 0), (0, 1)], [1.0, 2.0]).tolist()
    [[1.0, 0.0], [0.0, 1.0], [2.0, 0.0], [0.0, 2.0]]
    >>> around([(0, 0)], [(1, 0)], [0.5], size=(1.0, 0.2)).tolist()
    [[1.0, 0.0]]
    """
    points = [np.asarray(a, dtype=float)[:2] for a in anchors]
    units = [np.asarray(d, dtype=float)[:2] for d in directions]
    half = np.zeros(2) if size is None else np.asarray(size, dtype=float) / 2
    return np.array([p + u * (r + float(np.abs(u) @ half))
                     for r in distances for p in points for u in units]).reshape(-1, 2)


def next_to(anchors: Sequence[XY], directions: Sequence[XY], gaps: Sequence[float],
            size: tuple[float, float]) -> np.ndarray:
    """Candidate centres for a thing ``size`` (width, height) beside anchors as manim's
    ``next_to`` puts it: ``gap`` from the anchor along each direction (unit steps on the axes:
    a diagonal puts its corner there, a side its side), in first-fit order: the nearest gap
    first, then anchor by anchor, then direction by direction.

    >>> next_to([(0, 0)], [(1, 0), (1, 1)], [0.5], size=(1.0, 0.2)).tolist()
    [[1.0, 0.0], [1.0, 0.6]]
    """
    points = [np.asarray(a, dtype=float)[:2] for a in anchors]
    steps = [np.asarray(d, dtype=float)[:2] for d in directions]
    half = np.asarray(size, dtype=float) / 2
    return np.array([p + d * (gap + half) for gap in gaps for p in points for d in steps]
                    ).reshape(-1, 2)


def grid(area: Rect, size: tuple[float, float], step: float = PLACE_STEP,
         near: XY | None = None) -> np.ndarray:
    """Candidate centres on a grid of ``step`` for a thing ``size`` that stays in ``area``, in
    first-fit order: nearest ``near`` first (ties: the lower row, then the left), or, with no
    ``near``, column by column from the left, each from the top (its left and top on the
    grid from the area's left and top)."""
    left, bottom, right, top = area
    w, h = size
    columns = math.floor(round((right - left - w) / step, 6)) + 1
    rows = math.floor(round((top - bottom - h) / step, 6)) + 1
    if columns <= 0 or rows <= 0:
        return np.zeros((0, 2))
    xs = np.round(left + np.arange(columns) * step, 6) + w / 2
    ys = np.round(top - np.arange(rows) * step, 6) - h / 2
    if near is None:
        columns_x, columns_y = np.meshgrid(xs, ys, indexing="ij")
        return np.column_stack([columns_x.ravel(), columns_y.ravel()])
    rows_x, rows_y = np.meshgrid(xs, ys[::-1])  # rows from the bottom, each from the left
    x, y = rows_x.ravel(), rows_y.ravel()
    order = np.argsort((x - near[0]) ** 2 + (y - near[1]) ** 2, kind="stable")
    return np.column_stack([x[order], y[order]])


def clear(centres: np.ndarray, size: tuple[float, float], obstacles: Obstacles,
          clearance: float | np.ndarray = CLEARANCE, within: Rect | None = None) -> np.ndarray:
    """Which candidates (centres of a thing ``size``) keep ``clearance`` (one, or one a
    candidate) from every obstacle and stay in ``within``."""
    rects = rects_at(centres, size)
    ok = obstacles.gaps(rects) >= np.asarray(clearance) - 1e-9
    if within is not None:
        left, bottom, right, top = within
        ok &= ((rects[:, 0] >= left - 1e-9) & (rects[:, 1] >= bottom - 1e-9)
               & (rects[:, 2] <= right + 1e-9) & (rects[:, 3] <= top + 1e-9))
    return np.asarray(ok, dtype=bool)


def first_clear(centres: np.ndarray, size: tuple[float, float], obstacles: Obstacles,
                clearance: float | np.ndarray = CLEARANCE, within: Rect | None = None
                ) -> int | None:
    """The index of the first candidate that is :func:`clear`, None if none is."""
    ok = clear(centres, size, obstacles, clearance, within)
    return int(np.argmax(ok)) if ok.any() else None


def free_place(width: float, height: float, taken: BaseGeometry, area: Rect = FRAME_AREA,
               clearance: float = CLEARANCE) -> tuple[float, float] | None:
    """The left and top of the first ``width`` × ``height`` rectangle in ``area`` that keeps
    ``clearance`` from everything ``taken`` (one shape: the polygon's region, the labels'
    and the panel's boxes …), None if there is none. The first: the left-most, and the
    highest of those (on a grid of :data:`PLACE_STEP`): a thing placed beside the polygon
    stands in the frame's left margin when it can, where the eye starts.

    >>> from shapely.geometry import box
    >>> free_place(1.0, 1.0, box(-7.0, -4.0, 0.0, 4.0), area=(-7.0, -4.0, 7.0, 4.0))
    (0.15, 4.0)
    >>> free_place(20.0, 1.0, box(0.0, 0.0, 1.0, 1.0)) is None
    True
    """
    centres = grid(area, (width, height))
    k = first_clear(centres, (width, height), Obstacles(shapes=(taken,)), clearance)
    if k is None:
        return None
    return round(float(centres[k][0]) - width / 2, 6), round(float(centres[k][1]) + height / 2, 6)


# --- what stands on screen: the areas a new text keeps clear of, each a Rect ---------------------
# One home for them: the monotone stack and its count (metaphors.monotone), the black box
# (metaphors.pieces) and the sweep's legend entry (metaphors.sweep) each compose what they need
# and say why theirs differ.

#: past every edge of the frame (14.2 × 8): a band across the frame, or a column or line to its
#: edge, reaches this far, so that nothing is found beyond it
BEYOND_FRAME: Rect = (-8.0, -4.5, 8.0, 4.5)


def area_of(mobject: Mobject, moved: Callable[[np.ndarray], np.ndarray] | None = None) -> Rect:
    """A mobject's box on screen (``moved``: where its centre goes; its size stays)."""
    low, high = mobject.get_corner(DL), mobject.get_corner(UR)
    centre = (low + high) / 2
    shift = (moved(centre) - centre) if moved is not None else np.zeros(3)
    return (float(low[0] + shift[0]), float(low[1] + shift[1]),
            float(high[0] + shift[0]), float(high[1] + shift[1]))


def areas_of(mobjects: Iterable[Mobject], grown_by: float = 0.0) -> list[Rect]:
    """The boxes of ``mobjects`` (a picture's vertex markers, its outline …), each grown by
    ``grown_by`` on every side.

    >>> from manim import Square
    >>> areas_of([Square(side_length=2.0)], grown_by=0.5)
    [(-1.5, -1.5, 1.5, 1.5)]
    """
    return [(left - grown_by, bottom - grown_by, right + grown_by, top + grown_by)
            for left, bottom, right, top in map(area_of, mobjects)]


def title_area(title: Mobject, whole_line: bool = False) -> Rect:
    """The title's box; ``whole_line``: its whole line, across the frame from the title's
    bottom up."""
    if not whole_line:
        return area_of(title)
    return (BEYOND_FRAME[0], area_of(title)[1], BEYOND_FRAME[2], BEYOND_FRAME[3])


def panel_area(shows_polygon: bool) -> Rect:
    """The box the panel's lights run over: its code's (:data:`PANEL_CODE`, the whole width
    under its polygon), or a source's (:data:`PANEL_SOURCE`) where source takes the polygon's
    place: the whole box, as its window of lines moves."""
    return (PANEL_CODE if shows_polygon else PANEL_SOURCE).rect


def panel_column() -> Rect:
    """The panel's whole column: from the left of its widest part (its polygon's labels, its
    code, a source) to the frame's right, top to bottom."""
    left = min(b.rect[0] for b in (PANEL_CODE, PANEL_LABELS, PANEL_SOURCE))
    return (left, BEYOND_FRAME[1], BEYOND_FRAME[2], BEYOND_FRAME[3])


#: how far the call line reaches above :data:`PANEL_CALL_Y` (monospace, its brackets and
#: descenders), on one line and wrapped to two (centred on it)
CALL_LINE_REACH = {1: 0.14, 2: 0.315}


def code_floor(calls: bool, call_lines: int = 2) -> float:
    """The lowest the panel's code may reach: 0.035 above its call line of ``call_lines``
    lines where the call line shows calls (a code reaching below a call's two lines keeps
    its call line to one: :meth:`metaphors.panel.Panel._call_line`), else 0.1 above the
    subtitles' two lines (:data:`SUBTITLE_TOP`).

    >>> code_floor(True), code_floor(True, call_lines=1), code_floor(False)
    (-2.3, -2.475, -2.85)
    """
    reach = CALL_LINE_REACH[call_lines]
    return round(PANEL_CALL_Y + reach + 0.035 if calls else SUBTITLE_TOP + 0.1, 6)


def call_line_area() -> Rect:
    """The panel's call line (under its code, as wide), whatever call it says."""
    return Box(PANEL_CODE.x, PANEL_CALL_Y, PANEL_CODE.width, 0.4).rect


def subtitle_band(theme: Theme | None = None) -> Rect:
    """The subtitles' band: across the frame up to :data:`SUBTITLE_TOP`, the highest two lines
    of any subtitle reach. Given the ``theme``, the two lines measured: as wide as a subtitle
    may be (:data:`SUBTITLE_WIDTH`), up to two lines of the tallest glyphs its captions have, a
    line's gap apart (:func:`rendering.typeset.balanced`); 0.05 lower, for what must fit close
    above the subtitles."""
    if theme is None:
        return (BEYOND_FRAME[0], BEYOND_FRAME[1], BEYOND_FRAME[2], SUBTITLE_TOP)
    two_lines = 2 * text("(Ag)", font=theme.font, size=theme.caption_size).height + 0.1
    top = subtitle_centre(two_lines)[1] + two_lines / 2
    return (-SUBTITLE_WIDTH / 2, BEYOND_FRAME[1], SUBTITLE_WIDTH / 2, top)
