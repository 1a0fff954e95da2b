"""A card's idea drawn beside its words: the polygon with what the card speaks of.

A card of the lecture (:class:`metaphors.lecture.Card`) may name a :class:`Figure`: a kind
and a polygon (None: the lecture's). The figure is computed from the geometry, exactly as
the runs are, and drawn in the card's left half, its words on the right, so a card is not
text alone on black (issue 22 item 7). Colours keep the lecture's meanings: an inner
diagonal and an ear in the *result* green, the triangles of a triangulation in the pieces'
colours.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass

from manim import (
    DL,
    DOWN,
    DR,
    LEFT,
    RIGHT,
    UL,
    UP,
    UR,
    Circle,
    DashedLine,
    Dot,
    Line,
    Mobject,
    VGroup,
)
from manim import Polygon as MPolygon

from geometry.batch import in_closed_triangle
from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.frame import candidates_in_triangle, leftmost_vertex, triangle_at
from geometry.io import read_polygon
from geometry.polygon import Polygon
from geometry.predicates import orient, signed_area2
from geometry.triangulate import triangulate
from metaphors import figure_faster, figure_overview, figure_recap, method_figures
from metaphors.drawing import (
    Frame,
    crossed_edge,
    polygon_mobject,
    triangle_mobject,
    triangulation_figure,
)
from metaphors.figure_caption import figure_caption
from metaphors.figure_metaphors import metaphor_parts
from metaphors.figure_plots import Area, Series, axis_names, line_plot
from metaphors.figure_steps import comes_with, said_only
from metaphors.labels import drawn_edges, measured_markers, placed_vertex_markers
from metaphors.tags import tag
from metaphors.theme import THEME, Theme
from rendering import typeset
from story.registry import spoken
from story.runs import run_logged

#: where a figure is drawn: the left half of the screen, below the card's title
FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT = (-3.5, -0.1), 6.2, 4.6
BOX = (FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT)
KINDS = ("triangulation", "diagonal", "ears", "ear", "growth", "frame", "claims", "metaphor",
         *method_figures.KINDS, *figure_faster.KINDS, *figure_overview.KINDS,
         *figure_recap.KINDS)
#: the figures drawn across the whole width, a row of pictures, each with its line under it
#: (:class:`metaphors.lecture.Card`'s ``layout``): the recap's algorithms
WIDE_KINDS = ("three-triangulations",)
#: where a wide figure is drawn when no box is handed: under the title, the words below
WIDE_BOX = ((0.0, 0.55), 14.0, 4.5)
#: the recap's rules, one picture after another on one polygon: the left half, as large as
#: the labels leave room for under the title and over the frame's foot (its failing claim
#: leaves P by 4 % of the frame's height: :data:`BOX` is smaller)
RECAP_BOX = ((-3.45, -0.4), 6.4, 5.5)
#: the growth plot: each algorithm's ear tests, counted in its log, on random polygons
GROWTH_SIZES = (10, 20, 30, 40, 50, 60)
GROWTH_SEEDS = (1, 2, 3)
#: each by the name the lecture says (faster ear clipping was "ear status kept" here only)
GROWTH_RUNS = (("ear-clipping-naive", "naive"), ("ear-clipping", spoken("ear-clipping")),
               ("prune-and-search", "prune and search"))


@dataclass(frozen=True)
class Figure:
    """What a card draws: ``kind`` (one of :data:`KINDS`) on ``polygon`` (None: the
    lecture's); ``heuristic`` names the rule that finds a ``diagonal``, ``heuristics`` the
    rules whose ``claims`` are drawn (green when inner, red with the edge they cross), and a
    ``metaphor`` figure the wrong heuristic whose tool is drawn at its pick."""

    kind: str
    polygon: str | None = None
    heuristic: str = "gravity"
    heuristics: tuple[str, ...] = ()  # the rules whose claims a ``claims`` figure draws

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"a figure is one of {', '.join(KINDS)}, not {self.kind!r}")


def figure_mobjects(figure: Figure, polygon_spec: str, theme: Theme = THEME,
                    box: figure_recap.Box | None = None) -> list[Mobject]:
    """The figure's mobjects, back to front, on ``figure.polygon`` or else ``polygon_spec``;
    a wide one (:data:`WIDE_KINDS`) in ``box`` (default :data:`WIDE_BOX`)."""
    if figure.kind in figure_recap.KINDS:  # the recap's rows of rules
        return figure_recap.figure_mobjects(figure.kind, figure.polygon or polygon_spec,
                                            figure.heuristics, theme, box or RECAP_BOX)
    if figure.kind == "three-triangulations":
        return figure_faster.figure_mobjects(figure.kind, figure.polygon or polygon_spec, theme,
                                             box or WIDE_BOX)
    if figure.kind == "growth":
        return _growth(theme)
    if figure.kind in method_figures.KINDS:  # gravity, prune and search, keyhole, a rule
        return method_figures.method_figure(figure.kind, figure.polygon or polygon_spec,
                                            figure.heuristic, BOX, theme)
    if figure.kind in figure_faster.KINDS:  # the faster algorithms' and the recap's
        return figure_faster.figure_mobjects(figure.kind, figure.polygon or polygon_spec, theme,
                                             BOX)
    polygon = read_polygon(figure.polygon or polygon_spec)
    frame = Frame(polygon.points, FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT)
    shape = tag(polygon_mobject(polygon, frame, theme), "idle", "figure:polygon")
    if figure.kind == "metaphor":
        vertices = tag(placed_vertex_markers(polygon, frame, theme), "idle", "figure:vertices")
        # its run is read from the polygon's spec, not the polygon
        under, over, said = metaphor_parts(figure.heuristic, figure.polygon or polygon_spec,
                                           frame, theme, _bounds()) if polygon.n >= 4 else (
            [], [], "a triangle: no diagonal to find")
        # no words under a tool stopped at its pick: the card's bullets say what it picks,
        # one at a time, and "the water from B wets D first" below the figure read as a
        # subtitle beside them and gave the pick away before its bullet (chapter 2 at 16 s)
        label = [] if over else [figure_caption(BOX, theme, (said, theme.ink))]
        return [shape, *under, *label, vertices, *over]
    if figure.kind in figure_overview.KINDS:  # the overview's: P's labels drawn here
        parts = figure_overview.overview_figure(figure.kind, figure.polygon or polygon_spec,
                                                BOX, theme)
    else:
        drawn = {"triangulation": _triangulation, "diagonal": _diagonal, "ears": _ears,
                 "frame": _frame, "claims": _claims, "ear": _ear}[figure.kind]
        parts = drawn(figure, polygon, frame, theme)
    # fills go under the dots and labels, also those that come with a later line than the
    # labels (drawn in the order they came, the overview's triangles tinted G and M); marks
    # on a vertex go over its dot
    vertices = _vertices(polygon, frame, theme, parts).set_z_index(1)
    marks = [m.set_z_index(1) for m in parts if m.name == "figure:candidate"]
    return [shape, *[m for m in parts if m not in marks], vertices, *marks]


#: the parts whose lines cut P's fill: a label across one stands on two colours, or on the
#: line (chapter 1's G stood on the triangulation's side B–E, M beside the diagonal BM); not
#: a diagonal through a vertex (chapter 1's GK through H), which leaves that vertex's label
#: no place on its side of P
_CUTTING = ("figure:triangle", "figure:inner-diagonal", "figure:diagonal", "figure:T",
            "figure:pick", "figure:claim")


def _vertices(polygon: Polygon, frame: Frame, theme: Theme, parts: list[Mobject]) -> Mobject:
    """The vertex markers, each label clear of the lines the figure cuts P with
    (:data:`_CUTTING`) as of its edges: one that has no room outside P round its dot (M in
    its notch) stands beside P with a leader, else inside one piece of the fill, off its
    sides."""
    lines = [edge for m in parts if m.name in _CUTTING for edge in drawn_edges(m)]
    return tag(VGroup(*(m for _, m in measured_markers(polygon, (), frame, theme, lines=lines,
                                                      leaders=True))),
               "idle", "figure:vertices")


def _triangulation(figure: Figure, polygon: Polygon, frame: Frame,
                   theme: Theme) -> list[Mobject]:
    """P cut into its n − 2 triangles (divide and conquer's with ``figure.heuristic``, as
    chapter 1's run ends on them), the count, and one of its inner diagonals drawn in green,
    the one seen best to be inside (long, and far from the other vertices: their product the
    most): the card names that idea first (issue 22 item 2). Ear clipping's fanned P's
    triangles from B: G, which has no room outside P, found none inside one triangle either,
    and its label stood by H."""
    triangles = triangulate(polygon, "divide-and-conquer", figure.heuristic).triangles
    # as the run's end draws them: the result's green, neighbours in other shades
    pieces = triangulation_figure(polygon, triangles, frame, "figure:triangle", theme)
    n = polygon.n
    cuts = sorted({tuple(sorted((t[k], t[k - 1]))) for t in triangles for k in range(3)}
                  - {tuple(sorted((v, (v + 1) % n))) for v in range(n)})
    marked: list[Mobject] = []
    if cuts:  # a triangle has none; a long one passing far from the other vertices
        i, j = max(cuts, key=lambda c: _clearance(polygon, *c) * math.dist(
            polygon.points[c[0]], polygon.points[c[1]]))
        marked.append(tag(Line(frame.to_scene(polygon.points[i]),
                               frame.to_scene(polygon.points[j]), color=theme.result,
                               stroke_width=theme.stroke * 1.6), "result",
                          "figure:inner-diagonal"))
    count = f"n = {n}: {len(triangles)} triangles, {len(cuts)} inner diagonals"
    # the green diagonal and the count naming inner diagonals with the line that says what
    # an inner one is (before: from the title, the diagonal unexplained for 9 s)
    return [*pieces, *(comes_with(m, "inner") for m in marked),
            comes_with(figure_caption(BOX, theme, (count, theme.result)), "inner")]


def _diagonal(figure: Figure, polygon: Polygon, frame: Frame, theme: Theme) -> list[Mobject]:
    """One inner diagonal (the heuristic's claim) splitting P into two smaller polygons."""
    if polygon.n < 4:  # a polygon handed to the lecture may be a triangle
        return [figure_caption(BOX, theme, ("a triangle: nothing to split", theme.ink))]
    i, j = find_diagonal(polygon, figure.heuristic).pair
    lo, hi = sorted((i, j))
    halves = [list(range(lo, hi + 1)), [*range(hi, polygon.n), *range(0, lo + 1)]]
    tints = [tag(MPolygon(*frame.many([polygon.points[k] for k in half]),
                          color=theme.part_tints[n], stroke_width=0, fill_color=theme.part_tints[n],
                          fill_opacity=theme.piece_opacity), None, "figure:half")
             for n, half in enumerate(halves)]
    line = tag(Line(frame.to_scene(polygon.points[i]), frame.to_scene(polygon.points[j]),
                    color=theme.result, stroke_width=theme.stroke * 1.5), "result",
               "figure:diagonal")
    name = f"{polygon.labels[i]}{polygon.labels[j]}"
    sizes = " and ".join(str(len(h)) for h in halves)
    words = f"{name} splits {polygon.n} vertices into {sizes}"
    return [*tints, line, figure_caption(BOX, theme, (words, theme.result))]


def _clearance(polygon: Polygon, i: int, j: int) -> float:
    """How near the segment from vertex ``i`` to vertex ``j`` passes to P's other vertices
    (in P's units)."""
    (ax, ay), (bx, by) = polygon.points[i], polygon.points[j]
    dx, dy = bx - ax, by - ay
    near = math.inf
    for k, (px, py) in enumerate(polygon.points):
        if k not in (i, j):
            t = max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)))
            near = min(near, math.hypot(px - ax - t * dx, py - ay - t * dy))
    return near


def _frame(figure: Figure, polygon: Polygon, frame: Frame, theme: Theme) -> list[Mobject]:
    """The frame every heuristic shares: B the left-most vertex, T = ABC shaded, and the
    candidates (P's vertices inside T) marked, in the colours the runs give them."""
    t = triangle_at(polygon, leftmost_vertex(polygon))
    corners = (t.a.index, t.b.index, t.c.index)
    inside = [v.index for v in candidates_in_triangle(polygon, t)]
    shaded, asked = _frame_lines(polygon, frame, theme)
    dots = [tag(Dot(frame.to_scene(polygon.points[k]), radius=0.11, color=theme.candidate),
                "candidate", "figure:candidate") for k in inside]
    names = ", ".join(polygon.labels[k] for k in inside) or "none"
    words = f"T = {''.join(polygon.labels[k] for k in corners)}; candidates in T: {names}"
    # the words the card says, on the picture, each with the line that says it: B convex,
    # and a reflex vertex (:func:`ringed_reflex`); clear of the labels as the figure draws
    # them (:func:`_vertices`, clear of T's sides and the pick's line)
    labels = _label_boxes(_vertices(polygon, frame, theme, [shaded, *asked]))
    kinds = [*_vertex_word(polygon, frame, theme, t.b.index, "convex", labels),
             *next((w for v in _reflex(polygon)
                    if (w := _vertex_word(polygon, frame, theme, v, "reflex", labels))), [])]
    # T with the line that names it, the candidates with the one that speaks of them (on a
    # card that says neither, with its title)
    caption = figure_caption(BOX, theme, (words, theme.ink))
    return [comes_with(shaded, "T"), *(comes_with(d, "candidate") for d in dots), *kinds,
            *asked, comes_with(caption, "candidate")]


def _frame_lines(polygon: Polygon, frame: Frame, theme: Theme) -> tuple[Mobject, list[Mobject]]:
    """The frame figure's lines over P: T = ABC shaded, and the first candidate's claim to
    be, dashed amber (not yet judged), with the line that asks of it ("is BG inner?": BG
    was said and never drawn), if T holds a candidate."""
    t = triangle_at(polygon, leftmost_vertex(polygon))
    corners = (t.a.index, t.b.index, t.c.index)
    shaded = tag(MPolygon(*frame.many([polygon.points[k] for k in corners]), color=theme.called,
                          stroke_width=theme.thin_stroke, fill_color=theme.called,
                          fill_opacity=0.2), "called", "figure:T")
    inside = [v.index for v in candidates_in_triangle(polygon, t)]
    asked = [said_only(tag(DashedLine(frame.to_scene(polygon.points[t.b.index]),
                                      frame.to_scene(polygon.points[inside[0]]),
                                      color=theme.argument, stroke_width=theme.stroke,
                                      dash_length=theme.dash_length * 1.5),
                           "argument", "figure:pick"),
                       f"{polygon.labels[t.b.index]}{polygon.labels[inside[0]]}")
             ] if inside else []
    return shaded, asked


def _label_boxes(vertices: Mobject) -> list[Box]:
    """The boxes of the labels of a figure's vertex markers (:func:`_vertices`)."""
    return [_box(marker[1]) for marker in vertices.submobjects]


def ringed_reflex(polygon_spec: str, theme: Theme = THEME) -> str | None:
    """The label of the reflex vertex a ``frame`` figure of ``polygon_spec`` rings (the
    first with room for its word), None if it rings none: the card's line that says what
    the ring marks names it. Its labels as :func:`_frame` draws them (one placement)."""
    polygon = read_polygon(polygon_spec)
    frame = Frame(polygon.points, FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT)
    shaded, asked = _frame_lines(polygon, frame, theme)
    labels = _label_boxes(_vertices(polygon, frame, theme, [shaded, *asked]))
    return next((polygon.labels[v] for v in _reflex(polygon)
                 if _vertex_word(polygon, frame, theme, v, "reflex", labels)), None)


def _reflex(polygon: Polygon) -> list[int]:
    """P's reflex vertices (decided exactly)."""
    n, pts = polygon.n, polygon.points
    return [v for v in range(n) if orient(pts[v - 1], pts[v], pts[(v + 1) % n]) < 0]


def _vertex_word(polygon: Polygon, frame: Frame, theme: Theme, v: int,
                 word: str, labels: Sequence[Box]) -> list[Mobject]:
    """A ring round vertex ``v`` and ``word`` beside it: outside P, clear of its edges and
    of the vertices' ``labels`` (their boxes as the figure draws them: checked against
    labels placed without T's sides, the word could stand on a label drawn clear of them),
    inside the figure's half of the screen (tagged ``figure:<word>``); none if no side of
    ``v`` has room for the word."""
    at = frame.to_scene(polygon.points[v])
    # in ink: amber marks the candidates, green and red what holds and what fails
    # capitalised, as the vertices' labels: a word of short letters ("convex") then still
    # stands 2.5 % of the frame's height at the labels' size
    shown = typeset.text(word.capitalize(), font=theme.font, size=theme.label_size,
                         colour=theme.ink)
    outline = [frame.to_scene(p)[:2] for p in polygon.points]
    for side in (DOWN, UP, LEFT, RIGHT, DL, DR, UL, UR):
        for gap in (0.3, 0.55, 0.8):  # beyond the ring, then further out
            shown.move_to(at + side * (gap + (shown.width if side[0] else shown.height) / 2))
            box = _box(shown)
            if _in_figure(box) and _clear(box, outline) and not any(
                    _overlap(box, other) for other in labels):
                ring = Circle(radius=0.17, color=theme.ink,
                              stroke_width=theme.thin_stroke).move_to(at)
                # with the card's line that says the word, and on no card that does not
                # (the exercises' card showed "Convex" and "Reflex" and never said them)
                return [said_only(tag(VGroup(ring, shown), None, f"figure:{word}"), word)]
    return []


Box = tuple[float, float, float, float]  # x0, y0, x1, y1 on screen


def _bounds() -> Box:
    """The figure's box on screen."""
    (x, y), w, h = FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT
    return (x - w / 2, y - h / 2, x + w / 2, y + h / 2)


def _box(mobject: Mobject, pad: float = 0.06) -> Box:
    """A mobject's box on screen, ``pad`` wider on every side."""
    (x0, y0), (x1, y1) = mobject.get_corner(DL)[:2], mobject.get_corner(UR)[:2]
    return (x0 - pad, y0 - pad, x1 + pad, y1 + pad)


def _overlap(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _in_figure(box: Box) -> bool:
    """Whether ``box`` lies in the figure's half of the screen, below the card's title."""
    x, y = FIGURE_CENTER
    return (max(-7.0, x - FIGURE_WIDTH / 2 - 0.4) <= box[0] and box[2] <= x + FIGURE_WIDTH / 2
            and y - FIGURE_HEIGHT / 2 - 0.4 <= box[1] and box[3] <= y + FIGURE_HEIGHT / 2 + 0.4)


def _clear(box: Box, outline: list) -> bool:
    """Whether ``box`` lies outside the polygon ``outline`` (scene points) and no edge of it
    passes through the box."""
    x0, y0, x1, y1 = box
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    if any(_inside(c, outline) for c in corners):
        return False
    return not any(_meets_box(a, b, x0, y0, x1, y1)
                   for a, b in zip(outline, [*outline[1:], outline[0]], strict=True))


def _inside(point: tuple[float, float], outline: list) -> bool:
    """Even-odd test: whether ``point`` is inside the closed ``outline``."""
    x, y = point
    inside = False
    for (ax, ay), (bx, by) in zip(outline, [*outline[1:], outline[0]], strict=True):
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            inside = not inside
    return inside


def _meets_box(a, b, x0: float, y0: float, x1: float, y1: float) -> bool:
    """Whether the segment ``a``–``b`` passes through the box (sampled finely enough for a
    word beside a vertex: every 1/64 of the segment)."""
    return any(x0 <= a[0] + (b[0] - a[0]) * k / 64 <= x1
               and y0 <= a[1] + (b[1] - a[1]) * k / 64 <= y1 for k in range(65))


def _claims(figure: Figure, polygon: Polygon, frame: Frame, theme: Theme) -> list[Mobject]:
    """Each rule's claim on P: green if it is an inner diagonal, else red, the edge it
    crosses thick in red."""
    if polygon.n < 4:
        return [figure_caption(BOX, theme, ("a triangle: no diagonal to claim", theme.ink))]
    drawn: list[Mobject] = []
    seen: set[tuple[int, int]] = set()
    for name in figure.heuristics:
        pair = find_diagonal(polygon, name).pair
        if pair in seen:  # rules that claim the same diagonal draw it once
            continue
        seen.add(pair)
        verdict = is_inner_diagonal(polygon, *pair)
        colour = theme.result if verdict.ok else theme.rejected
        i, j = pair
        drawn.append(tag(Line(frame.to_scene(polygon.points[i]),
                              frame.to_scene(polygon.points[j]), color=colour,
                              stroke_width=theme.stroke * 1.6),
                         "result" if verdict.ok else "rejected", "figure:claim"))
        if verdict.edge is not None:
            u, v = verdict.edge
            drawn.append(crossed_edge(frame.to_scene(polygon.points[u]),
                                      frame.to_scene(polygon.points[v]),
                                      f"figure:edge:{polygon.labels[u]}–{polygon.labels[v]}",
                                      theme))
    return drawn


def _convex(polygon: Polygon) -> list[int]:
    """P's strictly convex vertices (decided exactly)."""
    n, pts = polygon.n, polygon.points
    return [v for v in range(n) if orient(pts[v - 1], pts[v], pts[(v + 1) % n]) > 0]


def _ears_of(polygon: Polygon) -> list[int]:
    """P's ears: the convex vertices V whose V−1 V+1 is an inner diagonal."""
    n = polygon.n
    return [v for v in _convex(polygon) if is_inner_diagonal(polygon, (v - 1) % n, (v + 1) % n)]


def _ear(figure: Figure, polygon: Polygon, frame: Frame, theme: Theme) -> list[Mobject]:
    """What an ear is, on P: its roomiest ear's triangle in green, and the first convex vertex
    that is no ear, its triangle in red with the vertex inside it marked."""
    n, pts = polygon.n, polygon.points
    convex = _convex(polygon)
    ears = _ears_of(polygon)
    blocked = [(v, k) for v in convex if v not in ears
               for k in range(n) if k not in ((v - 1) % n, v, (v + 1) % n)
               and in_closed_triangle(pts[k], pts[v - 1], pts[v], pts[(v + 1) % n])]
    drawn: list[Mobject] = []
    said = []
    if ears:  # the roomiest ear: a sliver would not be seen
        v = max(ears, key=lambda e: abs(signed_area2([pts[e - 1], pts[e], pts[(e + 1) % n]])))
        drawn.append(tag(triangle_mobject(polygon, ((v - 1) % n, v, (v + 1) % n), frame,
                                          theme.result, theme), "result", "figure:ear"))
        said.append(f"{polygon.labels[v]} is an ear")
    if blocked:
        v, k = blocked[0]
        drawn.append(tag(triangle_mobject(polygon, ((v - 1) % n, v, (v + 1) % n), frame,
                                          theme.rejected, theme), "rejected", "figure:not-ear"))
        drawn.append(tag(Dot(frame.to_scene(pts[k]), radius=0.11, color=theme.rejected),
                         "rejected", "figure:candidate"))
        said.append(f"{polygon.labels[v]} is not: {polygon.labels[k]} lies in its triangle")
    return [*drawn, figure_caption(BOX, theme, ("; ".join(said) or "a triangle", theme.ink))]


#: the ears of P drawn faint (the two that do not overlap drawn strong over them)
FAINT_EAR_OPACITY = 0.12


def _ears(figure: Figure, polygon: Polygon, frame: Frame, theme: Theme) -> list[Mobject]:
    """Every ear of P (a convex vertex V whose V−1 V+1 is an inner diagonal) faint, and two
    ears that do not overlap (:func:`_two_ears`) strong over them: the theorem the card
    states. All seven in one green overlapped (E and F, I and J), and no two were seen
    to be the two the card speaks of."""
    n, ears = polygon.n, _ears_of(polygon)

    def triangle(v: int, opacity: float, width: float, name: str) -> Mobject:
        drawn = triangle_mobject(polygon, ((v - 1) % n, v, (v + 1) % n), frame, theme.result,
                                 theme)
        drawn.set_fill(opacity=opacity).set_stroke(width=width)
        return tag(drawn, "result", name)

    faint = [triangle(v, FAINT_EAR_OPACITY, theme.thin_stroke, "figure:ear") for v in ears]
    two = _two_ears(polygon, ears)
    strong = [triangle(v, theme.fill_opacity + 0.2, theme.stroke, "figure:two-ears")
              for v in two]
    names = ", ".join(polygon.labels[v] for v in ears) or "none (a triangle)"
    lines = [(f"the ears of P: {names}", theme.ink)]
    if two:
        lines.append((f"two that do not overlap: {' and '.join(polygon.labels[v] for v in two)}",
                      theme.result))
    return [*faint, *strong, figure_caption(BOX, theme, *lines)]


def _two_ears(polygon: Polygon, ears: list[int]) -> tuple[int, ...]:
    """Two of ``ears`` whose triangles do not overlap (Meisters: a polygon of more than three
    vertices has two), the pair seen best: sharing no corner if any pair does, then the
    smaller of the two the largest; none if no two are found (a triangle)."""
    from shapely.geometry import Polygon as Region

    n, pts = polygon.n, polygon.points
    corners = {v: {(v - 1) % n, v, (v + 1) % n} for v in ears}
    regions = {v: Region([pts[k] for k in ((v - 1) % n, v, (v + 1) % n)]) for v in ears}
    apart = [(u, v) for u in ears for v in ears if u < v
             and regions[u].intersection(regions[v]).area <= 1e-9 * regions[u].area]
    if not apart:
        return ()
    return max(apart, key=lambda pair: (not corners[pair[0]] & corners[pair[1]],
                                        min(regions[v].area for v in pair)))


@functools.cache  # the same runs for every build of the chapter in one process
def ear_tests(algorithm: str, n: int) -> int:
    """How many vertices ``algorithm`` tests for an ear on random polygons of ``n``
    vertices (``random-2opt:n:SEED``, :data:`GROWTH_SEEDS`), counted in their logs, on
    average."""
    runs = [run_logged(algorithm, f"random-2opt:{n}:{seed}") for seed in GROWTH_SEEDS]
    return round(sum(len(log.find(kind="call", name="is_ear")) for log in runs) / len(runs))


#: what the growth plot's y axis counts, in the taught words (the runs' captions ask "Is A an
#: ear?"), and what the legend's numbers are: unsaid, "235" and "10" read as the same thing
EAR_TESTS = f"ear tests (is V an ear?)\neach a mean of {len(GROWTH_SEEDS)} random polygons"
GROWTH_WORDS = f"The number by each name: its ear tests at n = {GROWTH_SIZES[-1]}"


def _growth(theme: Theme) -> list[Mobject]:
    """Ear tests against n for the three ear clippers: measured, not asymptotic; the axes
    named (:data:`EAR_TESTS`: room left for the names below and above the plot), and what
    the legend's numbers are (:data:`GROWTH_WORDS`)."""
    left, bottom = FIGURE_CENTER[0] - FIGURE_WIDTH / 2 + 0.6, FIGURE_CENTER[1] - FIGURE_HEIGHT / 2
    area = Area(left, bottom + 0.55, FIGURE_WIDTH - 1.0, FIGURE_HEIGHT - 1.3)
    series = [Series(f"figure:growth:{name}", tuple(ear_tests(name, n) for n in GROWTH_SIZES),
                     theme.pieces[k % len(theme.pieces)]) for k, (name, _) in enumerate(GROWTH_RUNS)]
    drawn, _ = line_plot(GROWTH_SIZES, series, area, theme)
    drawn += axis_names(area, "vertices n", EAR_TESTS, theme)
    for k, ((_, said), line) in enumerate(zip(GROWTH_RUNS, series, strict=True)):
        label = typeset.text(f"{said}: {line.counts[-1]}", font=theme.font,
                             size=theme.label_size, colour=line.colour)
        # the legend in the plot's top left, which the rising lines leave empty
        label.move_to((left + 0.3, area.bottom + area.height - 0.2 - 0.42 * k, 0),
                      aligned_edge=LEFT)
        drawn.append(tag(label, None, "figure:legend"))
    return [*drawn, figure_caption(BOX, theme, (GROWTH_WORDS, theme.ink))]


def overview_examples(polygon_spec: str) -> tuple[str, ...]:
    """The names the overview's definitions card speaks of, drawn in the figure's box
    (:func:`metaphors.figure_overview.example_names`)."""
    return tuple(figure_overview.example_names(polygon_spec, BOX))


__all__ = ["FIGURE_CENTER", "FIGURE_HEIGHT", "FIGURE_WIDTH", "GROWTH_RUNS", "GROWTH_SIZES",
           "KINDS", "RECAP_BOX", "WIDE_BOX", "WIDE_KINDS", "Figure", "ear_tests", "figure_mobjects",
           "overview_examples", "ringed_reflex"]
