"""The methods' card figures: gravity's ball and band, a prune-and-search round, the keyhole
cut of a hole, and a rule of one's own on P (issue 22 item 7).

Each is computed by the geometry the runs use (:mod:`geometry.gravity`,
:mod:`geometry.prune_search`, :mod:`geometry.bridges`, :mod:`usercode.heuristic`), nothing
placed by hand, and drawn into the box :mod:`metaphors.figures` hands over. Colours keep
their one meaning: the vertex a step works on amber (*argument*, ``figure:step``: gravity's
V, prune and search's middle vertex, a hole's right-most vertex — none of them a candidate
in T, which only a rule's figure marks, pink), a good sub-polygon in the run's tint over
the fruit (:func:`metaphors.fruit.good_style`), an inner diagonal or a bridge green
(*result*), a wrong claim red with the edge it crosses.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from itertools import pairwise

import numpy as np
from manim import DOWN, Arrow, Dot, Line, Mobject, VGroup
from manim import Polygon as MPolygon

from geometry import gravity as gravity_steps
from geometry.bridges import bridge_holes
from geometry.check import is_inner_diagonal
from geometry.frame import candidates_in_triangle, leftmost_vertex, triangle_at
from geometry.holes import PolygonWithHoles
from geometry.io import read_any_polygon, read_polygon
from geometry.polygon import Polygon
from geometry.prune_search import (
    GoodSubpolygon,
    ShrinkingPolygon,
    diagonal_at,
    good_subpolygon,
    is_middle_ear,
)
from metaphors.drawing import (
    Frame,
    crossed_edge,
    polygon_mobject,
)
from metaphors.figure_caption import figure_caption
from metaphors.figure_steps import comes_with
from metaphors.fruit import fruit_style
from metaphors.labels import LABEL_HALO, drawn_edges, measured_markers, placed_vertex_markers
from metaphors.tags import tag
from metaphors.theme import Theme
from rendering import typeset
from story.beats import Hole
from usercode.heuristic import load_user_heuristic, run_heuristic

#: the kinds drawn here, by the name a card's :class:`metaphors.figures.Figure` gives
KINDS = ("gravity", "prune", "keyhole", "rule")
Box = tuple[tuple[float, float], float, float]  # centre, width, height on screen


class TurnedFrame(Frame):
    """A frame that turns P by ``angle`` degrees (counter-clockwise) before fitting it to the
    box: the turned polygon fills the box, as the gravity run turns it."""

    def __init__(self, points: Sequence[tuple[float, float]], angle: float, center,
                 width: float, height: float) -> None:
        t = math.radians(angle)
        self.turn = np.array([[math.cos(t), -math.sin(t)], [math.sin(t), math.cos(t)]])
        super().__init__([tuple(self.turn @ np.asarray(p, float)) for p in points], center,
                         width, height)

    def to_scene(self, p: Sequence[float]) -> np.ndarray:
        return super().to_scene(self.turn @ np.asarray(p[:2], dtype=float))


def method_figure(kind: str, polygon_spec: str, heuristic: str, box: Box,
                  theme: Theme) -> list[Mobject]:
    """The mobjects of figure ``kind`` (one of :data:`KINDS`) on ``polygon_spec``, back to
    front; ``heuristic``: the rule a ``rule`` figure draws (``FILE.py:FUNCTION`` or a name)."""
    if kind == "keyhole":
        return _keyhole(polygon_spec, box, theme)
    polygon = read_polygon(polygon_spec)
    drawn: dict[str, Callable[..., tuple[Frame, list[Mobject], list[Mobject]]]] = {
        "gravity": _gravity, "prune": _prune, "rule": _rule}
    frame, under, over = drawn[kind](polygon, heuristic, box, theme)
    shape = tag(polygon_mobject(polygon, frame, theme), "idle", "figure:polygon")
    # a rule's labels clear of T's sides and of its claim, as the frame figure's are: H stood
    # across T's side from its vertex on the exercises' card
    lines = [edge for m in under if m.name in ("figure:T", "figure:claim")
             for edge in drawn_edges(m)] if kind == "rule" else []
    dots = tag(VGroup(*(m for _, m in measured_markers(polygon, (), frame, theme, lines=lines))),
               "idle", "figure:vertices")
    if kind == "prune":  # P as the run shows it: the fruit, its labels on dark halos
        shape.set_style(**_style(fruit_style(theme)))
        for marker in dots:
            marker[1].set_stroke(theme.background, width=LABEL_HALO, background=True)
    return [shape, *under, dots, *over]


def _style(style: dict) -> dict:
    """A mobject's constructor style (:func:`metaphors.fruit.fruit_style`) as ``set_style``
    takes it."""
    return {"stroke_color": style["color"], "stroke_width": style["stroke_width"],
            "fill_color": style["fill_color"], "fill_opacity": style["fill_opacity"]}


def _line(frame: Frame, p, q, colour: str, width: float, role: str | None,
          name: str) -> Mobject:
    return tag(Line(frame.to_scene(p), frame.to_scene(q), color=colour, stroke_width=width),
               role, name)


def _dot(frame: Frame, p, colour: str, role: str, name: str) -> Mobject:
    return tag(Dot(frame.to_scene(p), radius=0.11, color=colour), role, name)


# --- gravity ---------------------------------------------------------------------------------


def _gravity(polygon: Polygon, heuristic: str, box: Box,
             theme: Theme) -> tuple[Frame, list[Mobject], list[Mobject]]:
    """The rule's set-up, not its answer: P turned so that gravity points down (the arrow
    beside it, with the line that says to turn P) and the ball hanging at V (with the line
    that names V, and the words "V = C" under it). The fall, the slide, the band and the
    claim are the run's to show, after the card: the card drew them all and said the claim
    before the run played the same picture (chapter 3: the same example three times)."""
    v = gravity_steps.reflex_vertex(polygon) if polygon.n > 3 else None
    if v is None:  # convex: the ball has no reflex vertex to hang from
        frame = Frame(polygon.points, *box)
        said = "no reflex vertex: no ball to drop"
        return frame, [], [figure_caption(box, theme, (said, theme.ink))]
    g = gravity_steps.gravity_direction(polygon, v)
    frame = TurnedFrame(polygon.points, g.turn_picture, *box)
    ball = tag(Dot(frame.to_scene(v.point), radius=0.12, color=theme.ball,
                   stroke_color=theme.ink, stroke_width=1.5), "argument", "figure:ball")
    # V in the run's colour for it, blue from its pick to its claim
    return frame, [comes_with(_down_arrow(box, theme), "Turn")], [
        comes_with(_dot(frame, v.point, theme.called, "called", "figure:step"), "V"),
        comes_with(ball, "V"),
        comes_with(figure_caption(box, theme, (f"V = {v.label}: the ball hangs here",
                                               theme.ink)), "V")]


def _down_arrow(box: Box, theme: Theme) -> Mobject:
    """Gravity's arrow, "g", at the top left of the figure's box, pointing down."""
    (x, y), width, height = box
    left, top = x - width / 2 - 0.3, y + height / 2
    arrow = Arrow((left, top, 0), (left, top - 1.0, 0), buff=0, color=theme.gravity,
                  stroke_width=4, max_tip_length_to_length_ratio=0.3)
    g = typeset.text("g", font=theme.font, size=theme.label_size + 4, colour=theme.gravity)
    return tag(VGroup(arrow, g.next_to(arrow, DOWN, buff=0.08)), None, "figure:gravity")


# --- prune and search ------------------------------------------------------------------------


Round = tuple[GoodSubpolygon, int, tuple[int, int] | None]


def prune_rounds(polygon: Polygon) -> list[Round]:
    """FindAnEar's rounds on P: each good sub-polygon, its middle vertex and, when that is no
    ear, the diagonal (P's indices) that cuts the next good sub-polygon off; the last round's
    middle vertex is an ear."""
    rounds: list[Round] = []
    g = GoodSubpolygon.whole(ShrinkingPolygon(polygon))
    while True:
        v = g.vertex_at(g.middle())
        if is_middle_ear(g, v):
            return [*rounds, (g, v.index, None)]
        diagonal = diagonal_at(g, v)
        ids = g.indices()
        rounds.append((g, v.index, (int(ids[diagonal.pair[0]]), int(ids[diagonal.pair[1]]))))
        g = good_subpolygon(g, diagonal)


def _prune(polygon: Polygon, heuristic: str, box: Box,
           theme: Theme) -> tuple[Frame, list[Mobject], list[Mobject]]:
    """Prune and search's question, not its answer: P drawn as the run draws it, the fruit
    (:func:`method_figure`), and the middle vertex V of its first round marked, with the
    question the run answers ("an ear? if not, a diagonal from it halves P"). The diagonal,
    the smaller good sub-polygon and the ear are the run's to show: the card drew them
    (GB, E an ear) and the run drew the same again a few seconds later (chapter 4 at 66 s)."""
    frame = Frame(polygon.points, *box)
    if polygon.n < 4:
        return frame, [], [figure_caption(box, theme, ("a triangle: it is its own ear", theme.ink))]
    _, v, _ = prune_rounds(polygon)[0]
    name = polygon.labels[v]
    words = f"P's middle vertex {name}: an ear? If not, a diagonal from {name} halves P"
    over = [_dot(frame, polygon.points[v], theme.argument, "argument", "figure:step"),
            figure_caption(box, theme, (words, theme.ink))]
    return frame, [], over


# --- a rule of one's own ---------------------------------------------------------------------


def _rule(polygon: Polygon, heuristic: str, box: Box,
          theme: Theme) -> tuple[Frame, list[Mobject], list[Mobject]]:
    """The rule's frame on P (T shaded, its candidates marked) and its claim: green if inner,
    else red with the edge it crosses."""
    frame = Frame(polygon.points, *box)
    if polygon.n < 4:
        said = "a triangle: no diagonal to claim"
        return frame, [], [figure_caption(box, theme, (said, theme.ink))]
    t = triangle_at(polygon, leftmost_vertex(polygon))
    corners = [polygon.points[k.index] for k in (t.a, t.b, t.c)]
    shaded = tag(MPolygon(*frame.many(corners), color=theme.called,
                          stroke_width=theme.thin_stroke, fill_color=theme.called,
                          fill_opacity=0.2), "called", "figure:T")
    rule = load_user_heuristic(heuristic) if ":" in heuristic else heuristic
    i, j = run_heuristic(polygon, rule).pair
    verdict = is_inner_diagonal(polygon, i, j)
    colour, role = (theme.result, "result") if verdict.ok else (theme.rejected, "rejected")
    under = [shaded, _line(frame, polygon.points[i], polygon.points[j], colour,
                           theme.stroke * 1.6, role, "figure:claim")]
    if verdict.edge is not None:
        u, w = verdict.edge
        under.append(crossed_edge(frame.to_scene(polygon.points[u]),
                                  frame.to_scene(polygon.points[w]),
                                  f"figure:edge:{polygon.labels[u]}–{polygon.labels[w]}", theme))
    said = "an inner diagonal" if verdict.ok else "not inner"
    words = f"On this P the rule claims {polygon.labels[i]}{polygon.labels[j]}: {said}"
    # the candidates in their own colour, as the exercises' cards show them: amber is a claim's
    over = [_dot(frame, polygon.points[d.index], theme.candidate, "candidate", "figure:candidate")
            for d in candidates_in_triangle(polygon, t)]
    return frame, under, [*over, figure_caption(box, theme, (words, colour))]


# --- the keyhole cut -------------------------------------------------------------------------


def _keyhole(polygon_spec: str, box: Box, theme: Theme) -> list[Mobject]:
    """P with its holes, each hole's right-most vertex marked, where its cut will start: the
    question, not the cuts, which the run makes after the card (the card drew both bridges
    and the run cut them again: chapter 4 at 138 s). P is drawn as the run that follows
    draws it, the fruit, its labels on dark halos."""
    polygon_read = read_any_polygon(polygon_spec)
    if not isinstance(polygon_read, PolygonWithHoles):
        frame = Frame(polygon_read.points, *box)
        return [tag(polygon_mobject(polygon_read, frame, theme), "idle", "figure:polygon"),
                tag(placed_vertex_markers(polygon_read, frame, theme), "idle", "figure:vertices"),
                figure_caption(box, theme, ("no hole: nothing to cut", theme.ink))]
    starts, pts, labels = polygon_read.starts, polygon_read.points, polygon_read.labels
    outer = Polygon.from_points(pts[:starts[1]])  # ring 0: labelled as in the polygon read
    holes = [Hole(points=pts[a:b], labels=labels[a:b]) for a, b in pairwise(starts[1:])]
    frame = Frame(outer.points, *box)
    shape = polygon_mobject(outer, frame, theme, holes).set_style(**_style(fruit_style(theme)))
    drawn: list[Mobject] = [tag(shape, "idle", "figure:polygon")]
    markers = measured_markers(outer, holes, frame, theme)
    for _, marker in markers:  # on the fruit's orange, a label reads on its dark halo
        marker[1].set_stroke(theme.background, width=LABEL_HALO, background=True)
    drawn.append(tag(VGroup(*(m for _, m in markers[:outer.n])), "idle", "figure:vertices"))
    drawn += [tag(marker, "idle", f"figure:hole-vertex:{label}")
              for label, marker in markers[outer.n:]]
    # each hole's right-most vertex (the bridges' start, as the run computes them)
    starts_at = [p for p, _ in bridge_holes(polygon_read).bridges]
    drawn += [_dot(frame, pts[p], theme.argument, "argument", "figure:step") for p in starts_at]
    said = ", ".join(labels[p] for p in starts_at)
    words = f"{said}: each hole's right-most vertex, where its cut to the rind starts"
    return [*drawn, figure_caption(box, theme, (words, theme.ink))]


__all__ = ["KINDS", "TurnedFrame", "method_figure"]
