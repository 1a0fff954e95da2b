"""A wrong heuristic's metaphor drawn still, for its card: the tool at B on the polygon.

The card "Scaling: spilled water" (and the clock hand's, the sweeping line's) draws its
metaphor as a :class:`metaphors.figures.Figure` of kind ``metaphor``: the polygon, T, and the
tool on its way to the vertex it picks, short of every candidate — the circle of water grown
from B, the hand turned from A, the line swept from B — with what it swept, in the colours of the lecture's analysis
(:func:`metaphors.analysis.tool_drawing`: the one swept colour, the tool in its own). The
card teaches the rule before its failure is shown: what the tool swept is shaded inside P
only, for the legend's swept blue means inside P and its red outside P (a card's blue past
an edge would say the opposite). That the swept part leaves P, in red, is what the pass on
the counterexample shows, after the card.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import shapely
from manim import Dot, Mobject, VGroup, VMobject
from manim import Polygon as MPolygon

from metaphors.analysis import moment, tool_colour, tool_drawing
from metaphors.drawing import Frame
from metaphors.figure_steps import comes_with, grows
from metaphors.stage import region
from metaphors.tags import tag
from metaphors.theme import Theme
from story.analysis import Point, inside
from story.registry import entry

#: how far the card's tool goes towards its pick (1: there): short of every candidate
CARD_REACH = 0.6
#: what the card's figure says below it, by the heuristic's metaphor
SAID = {"water": "the water from B wets {pick} first",
        "clock": "the hand at B passes {pick} first",
        "sweep": "the line from B touches {pick} first"}


@dataclass(frozen=True)
class Sheet:
    """The card's figure as a :class:`metaphors.stage.Canvas`: its frame and theme."""

    frame: Frame
    theme: Theme


#: a figure's box on screen: x0, y0, x1, y1
Bounds = tuple[float, float, float, float]


def metaphor_parts(heuristic: str, polygon_spec: str, frame: Frame, theme: Theme,
                   within: Bounds | None = None) -> tuple[list[Mobject], list[Mobject], str]:
    """``heuristic``'s tool on its way to its pick on ``polygon_spec`` (the run's own, read
    from its beats, :data:`CARD_REACH` of the way): T and what the tool swept (drawn under
    the vertices), the candidates marked (over them), and the words to say below it; the tool's faint part beyond T kept ``within``
    the figure's box."""
    metaphor = entry(heuristic).metaphor or ""
    if metaphor not in SAID:
        raise ValueError(f"{heuristic}: no water, clock hand or sweep line to draw")
    seen = moment(heuristic, polygon_spec)
    if seen.triangle is None:
        raise ValueError(f"{heuristic} on {polygon_spec}: the run shows no triangle T")
    t = tag(MPolygon(*frame.many(seen.triangle), color=theme.called,
                     stroke_width=theme.thin_stroke, fill_opacity=0), "called", "figure:T")
    if seen.motion is None:  # a polygon handed to the lecture may leave T empty
        return [t], [], "no candidate in T: AC is the diagonal"
    sheet, motion = Sheet(frame, theme), seen.motion

    def drawn_at(time: float) -> VGroup:
        """The tool at ``time`` (0 at B, 1 at its pick) and what it has swept so far."""
        tool = tag(tool_drawing(sheet, motion, time, tool_colour(theme, heuristic)),
                   "argument", "figure:tool")
        _swept_inside(tool, sheet, motion.swept(time), seen.points)
        if within is not None:
            _clip_beyond(tool, within)
        return tool

    # the tool moves with the card's first line, which says how it moves (it stood there
    # with the title, before any bullet said it: chapter 2 at 16 s), and stops short of the
    # first candidate: where it goes is the pass's to show, which follows on this polygon
    # (drawn on to its pick here too, the pass showed the same run twice); the candidates,
    # pink, with the title, as T
    tool = grows(comes_with(drawn_at(CARD_REACH), ""),
                 lambda time: drawn_at(time * CARD_REACH))
    where = dict(zip(seen.labels, seen.points, strict=True))
    marks = [tag(Dot(frame.to_scene(where[c]), radius=0.11, color=theme.candidate),
                 "candidate", "figure:candidate") for c in seen.candidates]
    return [t, tool], marks, SAID[metaphor].format(pick=seen.pick)


def _swept_inside(tool: VGroup, sheet: Sheet, swept: shapely.Geometry,
                  polygon: Sequence[Point]) -> None:
    """The tool's swept region (its part named ``swept``) shaded inside ``polygon`` only."""
    theme = sheet.theme
    tool.submobjects = [region(sheet, inside(swept, polygon), theme.swept, 0.3, "swept",
                               "argument") if part.name == "swept" else part
                        for part in tool.submobjects]


def _clip_beyond(tool: VGroup, within: Bounds) -> None:
    """The tool's faint lines beyond T cut to ``within``: the water's whole circle would run
    off the frame's edge and through the caption below the figure."""
    room = shapely.box(*within)
    for part in tool.submobjects:
        if part.name != "tool:beyond":
            continue
        kept: list[VMobject] = []
        for line in part.submobjects:
            corners = shapely.LineString([p[:2] for p in line.get_anchors()])
            for piece in shapely.get_parts(corners.intersection(room)):
                if piece.geom_type == "LineString" and piece.length > 0:
                    cut = line.copy()
                    cut.set_points_as_corners([(x, y, 0.0) for x, y in piece.coords])
                    kept.append(cut)
        part.submobjects = kept
