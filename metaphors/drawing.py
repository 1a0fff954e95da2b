"""Mobjects for the geometry: a polygon with labelled vertices, triangles, fitting into a frame."""

from __future__ import annotations

import copy
from collections.abc import Sequence
from dataclasses import replace
from typing import Any, TypeVar

import numpy as np
from manim import DOWN, DashedLine, Dot, Line, Polygram, VGroup
from manim import Polygon as MPolygon

from geometry.polygon import Polygon
from metaphors.tags import tag
from metaphors.theme import THEME, Theme
from rendering import typeset
from story.beats import Beat, Hole
from story.pseudocode import PseudocodeRow, result_row


class Frame:
    """Maps polygon coordinates into a box of the Manim scene (uniform scale, centred),
    optionally turned by ``angle`` degrees (counter-clockwise) and zoomed about ``pivot``.

    >>> f = Frame([(0, 0), (4, 0), (4, 2)], center=(0, 0), width=4, height=4)
    >>> f.to_scene((4, 2)).tolist()
    [2.0, 1.0, 0.0]
    >>> t = f.turned(90)
    >>> t.to_scene((4, 2)).round(6).tolist(), f.angle, t.angle
    ([-1.0, 2.0, 0.0], 0.0, 90.0)
    """

    def __init__(self, points: Sequence[tuple[float, float]], center, width: float, height: float):
        arr = np.asarray(points, dtype=float)
        lo, hi = arr.min(axis=0), arr.max(axis=0)
        span = np.maximum(hi - lo, 1e-12)
        self.base_scale = float(min(width / span[0], height / span[1]))
        self.mid = (lo + hi) / 2
        self.center = np.array([center[0], center[1], 0.0])
        self.angle = 0.0  # degrees, counter-clockwise on screen
        self.pivot = self.center.copy()
        self.zoom = 1.0

    @property
    def scale(self) -> float:
        """Scene length of one polygon unit (the zoom of a turn included)."""
        return self.base_scale * self.zoom

    def turned(self, angle: float, pivot=None, zoom: float = 1.0) -> Frame:
        """A copy of this frame turned to ``angle`` degrees (absolute, not added) about
        ``pivot`` (default: the box's centre) and zoomed by ``zoom``; ``turned(0)`` is upright."""
        other = copy.copy(self)
        other.angle = float(angle)
        other.pivot = self.center.copy() if pivot is None else np.array(
            [pivot[0], pivot[1], 0.0], dtype=float)
        other.zoom = float(zoom)
        return other

    def to_scene(self, p: Sequence[float]) -> np.ndarray:
        x, y = (np.asarray(p[:2], dtype=float) - self.mid) * self.base_scale
        at = self.center + np.array([x, y, 0.0])
        if self.angle == 0.0 and self.zoom == 1.0:
            return at
        t = np.radians(self.angle)
        c, s = np.cos(t), np.sin(t)
        dx, dy = (at - self.pivot)[:2] * self.zoom
        return self.pivot + np.array([c * dx - s * dy, s * dx + c * dy, 0.0])

    def from_scene(self, q: Sequence[float] | np.ndarray) -> tuple[float, float]:
        """The polygon point this frame puts at scene point ``q`` (:meth:`to_scene` undone).

        >>> f = Frame([(0, 0), (4, 2)], (0, 0), 4, 4).turned(90)
        >>> [round(v, 6) for v in f.from_scene(f.to_scene((4, 2)))]
        [4.0, 2.0]
        """
        t = np.radians(self.angle)
        c, s = np.cos(t), np.sin(t)
        dx, dy = (np.asarray(q, dtype=float) - self.pivot)[:2] / self.zoom
        at = self.pivot[:2] + np.array([c * dx + s * dy, -s * dx + c * dy])
        p = (at - self.center[:2]) / self.base_scale + self.mid
        return float(p[0]), float(p[1])

    def many(self, points: Sequence[Sequence[float]]) -> list[np.ndarray]:
        return [self.to_scene(p) for p in points]


def polygon_mobject(polygon: Polygon, frame: Frame, theme: Theme = THEME,
                    holes: Sequence[Hole] = ()) -> MPolygon | Polygram:
    """The polygon's outline with a light fill; with ``holes`` (each clockwise) one mobject of several rings, the holes left unfilled (winding number 0)."""
    style: dict[str, Any] = {"color": theme.ink, "stroke_width": theme.stroke, "fill_color": theme.polygon_fill,
             "fill_opacity": theme.fill_opacity}
    if holes:
        rings = [frame.many(polygon.points), *(frame.many(h.points) for h in holes)]
        return Polygram(*[[*ring, ring[0]] for ring in rings], **style)
    return MPolygon(*frame.many(polygon.points), **style)


def hole_markers(holes: Sequence[Hole], frame: Frame, theme: Theme = THEME) -> list:
    """(label, marker) for every hole vertex; a label sits away from its hole's centre, in
    the region."""
    out = []
    for hole in holes:
        centre = np.mean(frame.many(hole.points), axis=0)
        for point, label in zip(hole.points, hole.labels, strict=True):
            # lower-case letters stand lower than capitals: a size larger keeps them 2.5 % of
            # the frame's height
            out.append((label, _marker(frame.to_scene(point), centre, label, theme, 0.3,
                                       theme.label_size + 4)))
    return out


def _marker(at, centre, label: str, theme: Theme, gap: float,
            size: float | None = None) -> VGroup:
    away = at - centre
    norm = np.linalg.norm(away)
    direction = away / norm if norm > 1e-9 else DOWN
    dot = Dot(at, radius=theme.dot_radius, color=theme.ink)
    text = typeset.text(label, font=theme.font, size=size or theme.label_size, colour=theme.ink)
    text.move_to(at + direction * gap)
    return VGroup(dot, text)


def vertex_markers(polygon: Polygon, frame: Frame, theme: Theme = THEME) -> VGroup:
    """A dot and a label per vertex; the label sits outside the polygon, away from its centre."""
    centre = np.mean(frame.many(polygon.points), axis=0)
    group = VGroup()
    for point, label in zip(polygon.points, polygon.labels, strict=True):
        group.add(_marker(frame.to_scene(point), centre, label, theme, 0.32))
    return group


def triangle_mobject(
    polygon: Polygon, tri: Sequence[int], frame: Frame, colour, theme: Theme = THEME
) -> MPolygon:
    """One triangle of a triangulation, filled in the given colour."""
    return MPolygon(
        *frame.many([polygon.points[k] for k in tri]),
        color=colour,
        stroke_width=theme.thin_stroke,
        fill_color=colour,
        fill_opacity=theme.fill_opacity,
    )


def neighbour_shades(rings: Sequence[Sequence[Sequence[float]]]) -> list[int]:
    """Each ring's shade (for triangles, an index into
    :attr:`metaphors.theme.Theme.triangle_shades`), two rings that share a side never alike,
    so that each is counted (chapter 1's GCD and GDF, side by side in one purple, read as
    one). Greedy, breadth first from the first ring in sorted order, each neighbour in sorted
    order: a polygon's pieces sharing sides (triangles, or the parts of any cut along
    diagonals) form a tree, so two shades alternate; with holes a third may come. The same
    rings give the same shades in any order.

    >>> neighbour_shades([((0, 0), (1, 0), (0, 1)), ((1, 0), (1, 1), (0, 1)),
    ...                   ((1, 1), (2, 1), (1, 0))])
    [0, 1, 0]
    >>> neighbour_shades([((2, 0), (3, 0), (3, 1), (2, 1)), ((0, 0), (2, 0), (2, 1))])
    [1, 0]
    """
    corners = [[(float(x), float(y)) for x, y in ring] for ring in rings]
    keys = [tuple(sorted(ring)) for ring in corners]
    sides: dict[frozenset, list[int]] = {}  # a side (its two corners) → the rings on it
    for k, ring in enumerate(corners):
        for side in zip(ring, [*ring[1:], ring[0]], strict=True):
            sides.setdefault(frozenset(side), []).append(k)
    near: list[set[int]] = [set() for _ in keys]
    for on_side in sides.values():
        for k in on_side:
            near[k].update(j for j in on_side if j != k)
    ordered = [sorted(js, key=lambda j: keys[j]) for js in near]
    shades: dict[int, int] = {}
    for root in sorted(range(len(keys)), key=lambda k: keys[k]):
        if root in shades:
            continue
        shades[root], queue = 0, [root]
        while queue:
            for j in ordered[queue.pop(0)]:
                if j not in shades:
                    taken = {shades[m] for m in near[j] if m in shades}
                    shades[j] = min(s for s in range(len(taken) + 1) if s not in taken)
                    queue.append(j)
    return [shades[k] for k in range(len(keys))]


def shaded_triangle(corners: Sequence[np.ndarray], shade: int, theme: Theme = THEME) -> MPolygon:
    """One finished triangle (its corners on screen) in the result's green, at the fill of its
    ``shade`` (:func:`neighbour_shades`), its sides a thin green line."""
    fill = theme.triangle_shades[shade % len(theme.triangle_shades)]
    return MPolygon(*corners, color=theme.result, stroke_width=theme.thin_stroke,
                    fill_color=theme.result, fill_opacity=fill)


def triangulation_pieces(triangles: Sequence[Sequence[Sequence[float]]], at: Any,
                         theme: Theme = THEME) -> list[MPolygon]:
    """A whole triangulation, each triangle (its corners' points, placed on screen by ``at``)
    in the result's green, neighbours in other shades (:func:`neighbour_shades`): how a run's
    result is drawn at its end. Not in the pieces' tints: those are the parts a split or a
    partition makes (chapter 1's purple was "the other half" at 41 s and a triangle at 83 s)."""
    return [tag(shaded_triangle([at(p) for p in corners], shade, theme), "result",
                "triangulation")
            for corners, shade in zip(triangles, neighbour_shades(triangles), strict=True)]


def triangulation_figure(polygon: Polygon, triangles: Sequence[Sequence[int]], frame: Frame,
                         name: str, theme: Theme = THEME) -> list[MPolygon]:
    """The triangles of ``polygon`` (by vertex index) drawn in ``frame`` as a run's result is
    (:func:`triangulation_pieces`), each tagged ``name``: a card's or a comparison's."""
    corners = [[polygon.points[k] for k in t] for t in triangles]
    return [tag(m, "result", name) for m in triangulation_pieces(corners, frame.to_scene, theme)]


def whole_caption(triangles: int, holes: int = 0) -> str:
    """The caption over a run's ending, the whole triangulation drawn: the step before it
    (a split, a slice, a stack) is over, and its caption would no longer say what is on
    screen. With ``holes``, it says what the count's h is (:func:`count_words`: "n + 2h − 2"
    stood under the triangulation with h said nowhere).

    >>> whole_caption(17, 2)
    'The whole triangulation: 17 triangles, with h = 2 holes'
    """
    if not holes:
        return f"The whole triangulation: {triangles} triangles"
    return (f"The whole triangulation: {triangles} triangles, "
            f"with h = {holes} hole{'s' if holes > 1 else ''}")


B = TypeVar("B", bound=Beat)


def ending_beat(beat: B, pseudocode: Sequence[PseudocodeRow], triangles: int,
                run_call: str | None = None, holes: int = 0) -> B:
    """The beat of a run's ending, after its last step ``beat``: the whole triangulation's
    caption (:func:`whole_caption`), at full pace, and the pseudocode's row saying the result
    lit (:func:`story.pseudocode.result_row`), not the last step's row, which no longer says
    what the picture shows; the last step's row if the listing has none. Its call line
    likewise: the run's own call (``run_call``, :func:`story.storyboard.run_call`) with the
    triangles it returns, not the last step's call (``split(P, 0, 2) → [P, P]`` under the
    whole triangulation); the last step's if the run's call is not known.

    >>> from story.pseudocode import RESULT
    >>> rows = (PseudocodeRow("divide P along it", ("split",)),
    ...         PseudocodeRow("their union is the triangulation of P", (RESULT,)))
    >>> end = ending_beat(Beat(caption="Split", seq=9, row=0, pace=0.35), rows, 11)
    >>> end.caption, end.row, end.pace
    ('The whole triangulation: 11 triangles', 1, 1.0)
    >>> ending_beat(Beat(caption="Split", seq=9, row=0), rows[:1], 11).row
    0
    >>> split = Beat(caption="Split", seq=9, call="split(P, 0, 2) → [P, P]")
    >>> ending_beat(split, rows, 11, "divide_and_conquer(P, gravity)").call
    'divide_and_conquer(P, gravity) →\xa011\xa0triangles'
    >>> ending_beat(split, rows, 11).call
    'split(P, 0, 2) → [P, P]'
    """
    row = result_row(pseudocode)
    # the result kept on one line (no-break spaces): "→ 11" and "triangles" are one thing
    call = beat.call if run_call is None else f"{run_call} →\u00a0{triangles}\u00a0triangles"
    return replace(beat, caption=whole_caption(triangles, holes), pace=1.0,
                   row=beat.row if row is None else row, call=call)


def count_words(n: int, holes: int, triangles: int) -> str:
    """The count a whole triangulation had to reach, in words a class reads: n − 2 for a
    polygon of ``n`` vertices, two more for each of its ``holes`` (``n`` counting the holes'
    vertices too).

    >>> count_words(12, 0, 10)
    'n − 2 = 12 − 2 = 10 triangles'
    >>> count_words(12, 2, 14)
    'n + 2h − 2 = 12 + 4 − 2 = 14 triangles'
    """
    if not holes:
        return f"n − 2 = {n} − 2 = {triangles} triangles"
    return f"n + 2h − 2 = {n} + {2 * holes} − 2 = {triangles} triangles"


def crossed_edge(start: Any, end: Any, name: str, theme: Theme = THEME) -> Line:
    """The edge a wrong claim crosses, from ``start`` to ``end`` on screen: thick, in the red
    of what fails (runs, analyses, exercises and figures draw it alike)."""
    return tag(Line(start, end, color=theme.rejected, stroke_width=theme.stroke * 2.5),
               "rejected", name)


#: the dashes of a card's crossed edge: long, so that the edge reads as one thick dashed
#: line beside the solid claim that crosses it
EDGE_DASH = 0.2
#: how much wider than a red line its dark casing is, each side (stroke width units)
CASING = 2.0


def crossed_edge_dashed(start: Any, end: Any, name: str, theme: Theme = THEME) -> VGroup:
    """The edge a wrong claim crosses on a card's figure, in the red of what fails, thick and
    dashed on a dark casing: the claim across it is solid (both solid red, the recap's BD and
    E–A read as one red cross, and the overview's DI and F–G)."""
    width = theme.stroke * 2.2
    casing = Line(start, end).set_stroke(color=theme.background, width=width + 2 * CASING,
                                         opacity=1.0)
    return tag(VGroup(tag(casing, None, "figure:casing"),
                      DashedLine(start, end, color=theme.rejected, stroke_width=width,
                                 dash_length=EDGE_DASH, dashed_ratio=0.55)), "rejected", name)
