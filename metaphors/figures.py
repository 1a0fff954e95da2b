"""A card's idea drawn beside its words: the polygon with what the card speaks of.

A card of the lecture (:class:`metaphors.lecture.Card`) may name a :class:`Figure`: a kind
and a polygon (None: the lecture's). The figure is computed from the geometry, exactly as
the runs are, and drawn in the card's left half, its words on the right, so a card is not
text alone on black (issue 22 item 7). Colours keep the lecture's meanings: an inner
diagonal and an ear in the *result* green, the triangles of a triangulation in the pieces'
colours.
"""

from __future__ import annotations

from dataclasses import dataclass

from manim import Line, Mobject
from manim import Polygon as MPolygon

from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from geometry.polygon import Polygon
from geometry.predicates import orient
from geometry.triangulate import triangulate
from metaphors.drawing import Frame, polygon_mobject, triangle_mobject, vertex_markers
from metaphors.tags import tag
from metaphors.theme import THEME, Theme
from rendering import typeset

#: where a figure is drawn: the left half of the screen, below the card's title
FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT = (-3.5, -0.1), 6.2, 4.6
KINDS = ("triangulation", "diagonal", "ears")


@dataclass(frozen=True)
class Figure:
    """What a card draws: ``kind`` (one of :data:`KINDS`) on ``polygon`` (None: the
    lecture's); ``heuristic`` names the rule that finds a ``diagonal``."""

    kind: str
    polygon: str | None = None
    heuristic: str = "gravity"

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"a figure is one of {', '.join(KINDS)}, not {self.kind!r}")


def figure_mobjects(figure: Figure, polygon_spec: str, theme: Theme = THEME) -> list[Mobject]:
    """The figure's mobjects, back to front, on ``figure.polygon`` or else ``polygon_spec``."""
    polygon = read_polygon(figure.polygon or polygon_spec)
    frame = Frame(polygon.points, FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT)
    drawn = {"triangulation": _triangulation, "diagonal": _diagonal, "ears": _ears}[figure.kind]
    shape = tag(polygon_mobject(polygon, frame, theme), "idle", "figure:polygon")
    return [shape, *drawn(figure, polygon, frame, theme),
            tag(vertex_markers(polygon, frame, theme), "idle", "figure:vertices")]


def _label(words: str, theme: Theme, colour: str) -> Mobject:
    shown = typeset.text(words, font=theme.font, size=theme.label_size + 2, colour=colour)
    # below the picture and the labels of its lowest vertices
    return shown.move_to((FIGURE_CENTER[0], FIGURE_CENTER[1] - FIGURE_HEIGHT / 2 - 0.8, 0))


def _triangulation(figure: Figure, polygon: Polygon, frame: Frame,
                   theme: Theme) -> list[Mobject]:
    """P cut into its n − 2 triangles (ear clipping's), and the count."""
    triangles = triangulate(polygon, "ear-clipping").triangles
    pieces = [tag(triangle_mobject(polygon, t, frame, theme.pieces[k % len(theme.pieces)],
                                   theme), "result", "figure:triangle")
              for k, t in enumerate(triangles)]
    count = f"n = {polygon.n}: {len(triangles)} triangles, {len(triangles) - 1} diagonals"
    return [*pieces, tag(_label(count, theme, theme.result), None, "figure:label")]


def _diagonal(figure: Figure, polygon: Polygon, frame: Frame, theme: Theme) -> list[Mobject]:
    """One inner diagonal (the heuristic's claim) splitting P into two smaller polygons."""
    if polygon.n < 4:  # a polygon handed to the lecture may be a triangle
        return [tag(_label("a triangle: nothing to split", theme, theme.ink), None,
                    "figure:label")]
    i, j = find_diagonal(polygon, figure.heuristic).pair
    lo, hi = sorted((i, j))
    halves = [list(range(lo, hi + 1)), [*range(hi, polygon.n), *range(0, lo + 1)]]
    tints = [tag(MPolygon(*frame.many([polygon.points[k] for k in half]),
                          color=theme.pieces[n], stroke_width=0, fill_color=theme.pieces[n],
                          fill_opacity=theme.piece_opacity), None, "figure:half")
             for n, half in enumerate(halves)]
    line = tag(Line(frame.to_scene(polygon.points[i]), frame.to_scene(polygon.points[j]),
                    color=theme.result, stroke_width=theme.stroke * 1.5), "result",
               "figure:diagonal")
    name = f"{polygon.labels[i]}{polygon.labels[j]}"
    sizes = " and ".join(str(len(h)) for h in halves)
    words = f"{name} splits {polygon.n} vertices into {sizes}"
    return [*tints, line, tag(_label(words, theme, theme.result), None, "figure:label")]


def _ears(figure: Figure, polygon: Polygon, frame: Frame, theme: Theme) -> list[Mobject]:
    """Every ear of P: a convex vertex V whose V−1 V+1 is an inner diagonal, its triangle
    shaded."""
    n, pts = polygon.n, polygon.points
    ears = [v for v in range(n)
            if orient(pts[v - 1], pts[v], pts[(v + 1) % n]) > 0
            and is_inner_diagonal(polygon, (v - 1) % n, (v + 1) % n)]
    shaded = [tag(triangle_mobject(polygon, ((v - 1) % n, v, (v + 1) % n), frame,
                                   theme.result, theme), "result", "figure:ear")
              for v in ears]
    names = ", ".join(polygon.labels[v] for v in ears) or "none (a triangle)"
    return [*shaded, tag(_label(f"the ears of P: {names}", theme, theme.result), None,
                         "figure:label")]


__all__ = ["FIGURE_CENTER", "FIGURE_HEIGHT", "FIGURE_WIDTH", "KINDS", "Figure",
           "figure_mobjects"]
