"""The overview's card figures: what a diagonal is, inner or not, drawn as each is said; why a
triangulation has n − 2 triangles; and the question the rest of the lecture answers.

Each example is chosen from the geometry (:func:`examples`), so that the chapter's words name
the picture's own vertices on any polygon handed to the lecture: an inner diagonal, one that
leaves P across one edge (its part outside P at least 4 % of the frame's height, passing no
vertex, so that the class sees it leave), and one through a vertex if P has one. The
diagonal P is cut along to show n₁ + n₂ = n + 2 is one of the triangulation's own, not the
first the chapter's run cuts along (the card split along DG, then the run did again).
Colours keep their one meaning: a diagonal not yet judged amber, an inner one green, one
that fails red with the edge it crosses, the parts of a cut in the pieces' tints, the
triangles in the result's green shades (:func:`metaphors.drawing.triangulation_pieces`).
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from manim import RIGHT, UP, Circle, Line, Mobject, RoundedRectangle, VGroup
from manim import Polygon as MPolygon

from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from geometry.polygon import Polygon
from geometry.triangulate import triangulate
from metaphors.drawing import Frame, crossed_edge_dashed, triangulation_figure
from metaphors.figure_caption import GAP, caption_size, figure_caption
from metaphors.figure_steps import comes_with, goes_with
from metaphors.labels import placed_vertex_markers
from metaphors.tags import tag
from metaphors.theme import Theme
from rendering import typeset

#: the kinds drawn here, by the name a card's :class:`metaphors.figures.Figure` gives
KINDS = ("definitions", "why-n-2", "question")
Box = tuple[tuple[float, float], float, float]  # centre, width, height on screen
#: the black box answering the lecture's runs, unseen in the overview (chapter 1's run)
ANSWERING = "gravity"
#: a wrong diagonal shown leaves P by more than 4 % of the frame's height (0.32) and keeps
#: further than 3 % (0.24) from every vertex not its own, on screen
LEAST_OUT, LEAST_GAP = 0.4, 0.3
#: the least gap the crossed edge's name keeps from P's fill (3 % of the frame's height): in
#: the slot between F–G and H–I, 0.06 off both, "F–G" read as written on P (review, 16 s)
NAME_OFF = 0.24
#: the farthest the name stands from its edge: off P, the mouth of the slot the edge lines
NAME_REACH = 0.9


@dataclass(frozen=True)
class Examples:
    """The overview's diagonals of P, as pairs of vertex indices (None: P has none such):
    ``inner`` an inner one, cut along to count the vertices; ``leaving`` one that leaves P
    across the one edge ``edge``; ``through`` one inside P but through the vertex
    ``vertex``."""

    inner: tuple[int, int] | None
    leaving: tuple[int, int] | None
    edge: tuple[int, int] | None
    through: tuple[int, int] | None
    vertex: int | None

    def name(self, pair: tuple[int, int] | None, polygon: Polygon) -> str:
        """A diagonal's name, its two labels ("" for none)."""
        return "" if pair is None else "".join(polygon.labels[k] for k in pair)


def _segment(polygon: Polygon, frame: Frame, i: int, j: int) -> shapely.LineString:
    return shapely.LineString([frame.to_scene(polygon.points[k])[:2] for k in (i, j)])


def _gap(polygon: Polygon, frame: Frame, i: int, j: int) -> float:
    """How near the diagonal i–j passes, on screen, to P's other vertices."""
    seg = _segment(polygon, frame, i, j)
    return min((seg.distance(shapely.Point(frame.to_scene(p)[:2]))
                for k, p in enumerate(polygon.points) if k not in (i, j)), default=np.inf)


def _crossed(polygon: Polygon, frame: Frame, i: int, j: int) -> list[tuple[int, int]]:
    """The edges of P (not at i or j) the diagonal i–j crosses."""
    n, seg = polygon.n, _segment(polygon, frame, i, j)
    return [(u, (u + 1) % n) for u in range(n) if not {u, (u + 1) % n} & {i, j}
            and seg.intersects(_segment(polygon, frame, u, (u + 1) % n))]


def _halves(polygon: Polygon, i: int, j: int) -> tuple[list[int], list[int]]:
    """The two polygons the diagonal i–j cuts P into, as vertex indices."""
    lo, hi = sorted((i, j))
    return list(range(lo, hi + 1)), [*range(hi, polygon.n), *range(0, lo + 1)]


@functools.cache  # one choice per polygon and box: the chapter's words and its figures agree
def examples(polygon_spec: str, box: Box) -> Examples:
    """The overview's diagonals of the polygon ``polygon_spec`` drawn in ``box``: the inner
    one a diagonal of the triangulation the chapter's run ends on (not the first it cuts
    along: that step is the run's), the most even cut, then the longest and clearest; the
    leaving one crossing one edge only, seen leaving (:data:`LEAST_OUT`, :data:`LEAST_GAP`),
    the clearest; the one through a vertex inside P otherwise, the longest."""
    polygon = read_polygon(polygon_spec)
    frame = Frame(polygon.points, *box)
    n = polygon.n
    pairs = [(i, j) for i in range(n) for j in range(i + 2, n) if (i, j) != (0, n - 1)]
    if not pairs:
        return Examples(None, None, None, None, None)
    region = shapely.Polygon([frame.to_scene(p)[:2] for p in polygon.points])
    verdicts = {pair: is_inner_diagonal(polygon, *pair) for pair in pairs}
    i, j = sorted(find_diagonal(polygon, ANSWERING).pair)
    first = (i, j)
    cuts = {tuple(sorted((t[k], t[k - 1]))) for t in
            triangulate(polygon, "divide-and-conquer", ANSWERING).triangles for k in range(3)}
    cut = [p for p in pairs if p in cuts and p != first] or [first]
    inner = max(cut, key=lambda p: (min(map(len, _halves(polygon, *p))), _gap(
        polygon, frame, *p) * _segment(polygon, frame, *p).length))
    leaving = [p for p in pairs if verdicts[p].code == "crosses"
               and len(_crossed(polygon, frame, *p)) == 1
               and _segment(polygon, frame, *p).difference(region).length >= LEAST_OUT
               and _gap(polygon, frame, *p) >= LEAST_GAP]
    wrong = max(leaving, key=lambda p: _gap(polygon, frame, *p), default=None)
    through = [p for p in pairs if verdicts[p].code == "through-vertex"
               and _segment(polygon, frame, *p).difference(region).length < 1e-9]
    via = max(through, key=lambda p: _segment(polygon, frame, *p).length, default=None)
    return Examples(inner, wrong, _crossed(polygon, frame, *wrong)[0] if wrong else None,
                    via, verdicts[via].vertex if via else None)


def overview_figure(kind: str, polygon_spec: str, box: Box, theme: Theme) -> list[Mobject]:
    """The figure ``kind`` (one of :data:`KINDS`), but P itself and its labels (the card's
    figure draws those, clear of these lines)."""
    polygon = read_polygon(polygon_spec)
    frame = Frame(polygon.points, *box)
    found = examples(polygon_spec, box)
    if kind == "definitions":
        return _definitions(polygon, frame, found, box, theme)
    if kind == "why-n-2":
        return _why_n_minus_2(polygon, frame, found, box, theme)
    return [comes_with(_question(box, theme), "question")]


def _line(polygon: Polygon, frame: Frame, pair: tuple[int, int], colour: str, role: str,
          name: str, theme: Theme) -> Line:
    i, j = pair
    return tag(Line(frame.to_scene(polygon.points[i]), frame.to_scene(polygon.points[j]),
                    color=colour, stroke_width=theme.stroke * 1.6), role, name)


def _definitions(polygon: Polygon, frame: Frame, found: Examples, box: Box,
                 theme: Theme) -> list[Mobject]:
    """A diagonal drawn amber as the line says what a diagonal is (naming it), green as the
    next says it is inner; one that leaves P red with the edge it crosses thick and named,
    as its line says so; one through a vertex red, the vertex ringed, likewise."""
    if found.inner is None:  # a triangle: no diagonal at all
        return [figure_caption(box, theme, ("a triangle: no diagonal", theme.ink))]
    name = found.name(found.inner, polygon)
    said = _line(polygon, frame, found.inner, theme.argument, "argument", "figure:diagonal",
                 theme)
    inner = _line(polygon, frame, found.inner, theme.result, "result",
                  "figure:inner-diagonal", theme)
    parts: list[Mobject] = [goes_with(comes_with(said, name), "inner"),
                            comes_with(inner, "inner")]
    if found.leaving is not None and found.edge is not None:
        wrong = found.name(found.leaving, polygon)
        u, v = found.edge
        edge = f"{polygon.labels[u]}–{polygon.labels[v]}"
        crossed = crossed_edge_dashed(frame.to_scene(polygon.points[u]),
                                      frame.to_scene(polygon.points[v]), f"figure:edge:{edge}",
                                      theme)
        words = _edge_name(polygon, frame, found, edge, theme)  # the edge's name, red by it
        parts += [comes_with(_line(polygon, frame, found.leaving, theme.rejected, "rejected",
                                   "figure:claim", theme), wrong),
                  comes_with(crossed, wrong), comes_with(words, wrong)]
    if found.through is not None and found.vertex is not None:
        via = found.name(found.through, polygon)
        ring = Circle(radius=0.17, color=theme.rejected, stroke_width=theme.stroke).move_to(
            frame.to_scene(polygon.points[found.vertex]))
        parts += [comes_with(_line(polygon, frame, found.through, theme.rejected, "rejected",
                                   "figure:through", theme), via),
                  comes_with(tag(ring, "rejected", "figure:through-vertex"), via)]
    return parts


def _edge_name(polygon: Polygon, frame: Frame, found: Examples, words: str,
               theme: Theme) -> Mobject:
    """The crossed edge's name, in red beside it, outside P where there is room, clear of
    P's edges, the diagonals drawn and the vertices' labels (as an analysis names it)."""
    assert found.edge is not None and found.leaving is not None  # drawn only with both
    shown = typeset.text(words, font=theme.font, size=caption_size(theme),
                         colour=theme.rejected)
    ring = [frame.to_scene(p)[:2] for p in polygon.points]
    lines = [shapely.LineString([ring[k - 1], ring[k]]) for k in range(len(ring))]
    lines += [_segment(polygon, frame, *pair) for pair in (found.inner, found.leaving,
                                                           found.through) if pair]
    # the labels where the figure puts them: clear of the diagonals it draws across P
    placed = placed_vertex_markers(polygon, frame, theme, [found.inner, found.leaving]
                                   if found.inner else [found.leaving])
    labels = [shapely.box(*part.get_corner(np.array([-1, -1, 0]))[:2],
                          *part.get_corner(np.array([1, 1, 0]))[:2])
              for marker in placed for part in marker]
    if found.vertex is not None:  # the ring round the vertex a diagonal passes through
        lines.append(shapely.Point(ring[found.vertex]).buffer(0.2))
    busy = shapely.union_all([*lines, *labels])
    inside = shapely.Polygon(ring)
    edge = _segment(polygon, frame, *found.edge)
    crossing = _segment(polygon, frame, *found.leaving).intersection(edge)
    half = np.array([shown.width / 2, shown.height / 2])
    # every place within reach of the edge (a grid), outside P and clear of the lines and the
    # labels: the nearest to where the diagonal crosses it (in the slot beside the crossing
    # there was no room: the name stood over F's label and across DI)
    (x0, y0, x1, y1), reach = edge.bounds, 1.2
    xs = np.arange(x0 - reach, x1 + reach, 0.05)
    ys = np.arange(y0 - reach, y1 + reach, 0.05)
    cx, cy = (v.ravel() for v in np.meshgrid(xs, ys))
    boxes = shapely.box(cx - half[0], cy - half[1], cx + half[0], cy + half[1])
    # off the picture: clear of P's hull, not in a slot of P with its fill on both sides
    # (in the slot between F–G and H–I, "F–G" read as written on P: review, 16 s)
    room = ((shapely.distance(boxes, inside.convex_hull) >= NAME_OFF)
            & (shapely.distance(boxes, busy) >= 0.06)
            & (shapely.distance(boxes, edge) <= NAME_REACH) & _in_frame(boxes))
    near = np.where(room, shapely.distance(boxes, crossing), np.inf)
    k = int(np.argmin(near))
    if not np.isfinite(near[k]):  # no room: beside the edge's middle, as best it can
        k = int(np.argmin(shapely.distance(shapely.points(cx, cy), edge.centroid)))
    best = np.array([cx[k], cy[k], 0.0])
    return tag(shown.move_to(best), "rejected", "figure:edge-name")


def _in_frame(boxes: np.ndarray) -> np.ndarray:
    """Which boxes lie inside the frame's left half, where a card's figure is drawn."""
    x0, y0, x1, y1 = shapely.bounds(boxes).T
    return (x0 >= -7.0) & (x1 <= -0.2) & (y0 >= -3.4) & (y1 <= 2.6)


def _why_n_minus_2(polygon: Polygon, frame: Frame, found: Examples, box: Box,
                   theme: Theme) -> list[Mobject]:
    """P's triangulation (the one the chapter's run ends on, drawn as it is drawn there);
    then P cut along one of its diagonals into two parts, n₁ + n₂ = n + 2 counted under it;
    then the triangles again, each part's (the induction); then the count for this P."""
    triangles = triangulate(polygon, "divide-and-conquer", ANSWERING).triangles
    n = polygon.n

    def drawn() -> list[Mobject]:
        return list(triangulation_figure(polygon, triangles, frame, "figure:triangle", theme))

    count = figure_caption(box, theme, (f"n = {n}: {len(triangles)} triangles, "
                                        f"{max(0, n - 3)} diagonals", theme.result))
    if found.inner is None:  # a triangle: itself
        return [*(comes_with(m, "") for m in drawn()), comes_with(count, "Here")]
    name = found.name(found.inner, polygon)
    halves = _halves(polygon, *found.inner)
    tints = [tag(MPolygon(*frame.many([polygon.points[k] for k in half]), stroke_width=0,
                          fill_color=theme.part_tints[k], fill_opacity=theme.piece_opacity * 1.5),
                 None, "figure:half") for k, half in enumerate(halves)]
    cut = _line(polygon, frame, found.inner, theme.result, "result", "figure:inner-diagonal",
                theme)
    sizes = " + ".join(str(len(h)) for h in halves)
    counted = figure_caption(box, theme, (f"{name}: {sizes} = {n} + 2 vertices", theme.ink))
    return [*(goes_with(comes_with(m, ""), name) for m in drawn()),
            *(goes_with(comes_with(m, name), "induction") for m in tints),
            comes_with(cut, name), goes_with(comes_with(counted, name), "induction"),
            *(comes_with(m, "induction") for m in drawn()), comes_with(count, "Here")]


def _question(box: Box, theme: Theme) -> Mobject:
    """The black box the overview's run asks (:mod:`metaphors.pieces`): a closed box with a
    question mark and what it is asked, below P where a figure's words go."""
    frame = RoundedRectangle(corner_radius=0.1, width=0.8, height=0.56, stroke_color=theme.called,
                             stroke_width=theme.stroke, fill_color=theme.background,
                             fill_opacity=1.0)
    mark = typeset.text("?", font=theme.font, size=36, colour=theme.called).move_to(frame)
    words = typeset.text("an inner diagonal?", font=theme.font,
                         size=caption_size(theme), colour=theme.ink)
    shown = VGroup(VGroup(frame, mark), words).arrange(RIGHT, buff=0.2)
    (x, y), _, height = box
    shown.move_to((x, y - height / 2 - GAP, 0), aligned_edge=UP)
    return tag(shown, "called", "figure:question")


def example_names(polygon_spec: str, box: Box) -> Sequence[str]:
    """The names the definitions card speaks of, in order: the inner diagonal, the leaving
    one and the edge it crosses, the one through a vertex and that vertex ("" for none)."""
    polygon = read_polygon(polygon_spec)
    found = examples(polygon_spec, box)
    edge = ("" if found.edge is None
            else f"{polygon.labels[found.edge[0]]}–{polygon.labels[found.edge[1]]}")
    return (found.name(found.inner, polygon), found.name(found.leaving, polygon), edge,
            found.name(found.through, polygon),
            "" if found.vertex is None else polygon.labels[found.vertex])


__all__ = ["KINDS", "Examples", "example_names", "examples", "overview_figure"]
