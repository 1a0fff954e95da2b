"""The recap's figures: each rule with the picture of why, one after another, on one polygon.

The recap (chapter 7) sums up what the lecture showed (issue 22 item 8): the rules that
fail, each with the picture of why; the rules that hold, and why. Each rule's picture comes
with the card's line that speaks of it and goes when the next rule's comes
(:func:`metaphors.figure_steps.with_line`, :func:`metaphors.figure_steps.replacing`), on one
polygon drawn large: side by side, three pictures of P leave BD 3 % of the frame's height
outside P, under the 4 % a failure needs to be seen.

* ``failing-motions``: line ``k`` brings ``heuristics[k]``'s tool, grown from B to the
  vertex it picks, what it swept inside P in the swept blue and, at the pick, its part
  outside P (in T) red; the line after the last brings their claim, red on a dark casing,
  in place of the last tool, and the edge it crosses, which flashes and stays dashed: a
  solid claim across a dashed edge, told apart though both are red;
* ``holding-motions``: line 0 brings the corrections' claim, green, to stay; line ``k``
  brings ``heuristics[k]``'s tool at its pick and the region its argument is about
  (:meth:`story.analysis.Motion.witness`: what the line and the clock swept in T before
  their pick, what the rising water leaves dry), green, inside P; gravity: the ball's fall
  and slide, the band, the region it swept (inside P) and its claim, green, in place of the
  corrections' (the two claims along B–C read as one path).

The pictures are read from the runs' beats (:func:`metaphors.analysis.moment`), as chapter
2's analysis draws them, never placed by hand.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import shapely
from manim import Arrow, DashedLine, Dot, Line, Mobject, VGroup, VMobject

from geometry.io import read_polygon
from geometry.polygon import Polygon
from metaphors.analysis import Moment, moment, tool_colour, tool_drawing
from metaphors.drawing import Frame, polygon_mobject
from metaphors.figure_caption import figure_caption
from metaphors.figure_metaphors import Sheet
from metaphors.figure_steps import grows, replacing, with_line
from metaphors.labels import measured_markers
from metaphors.stage import path, region
from metaphors.tags import tag
from metaphors.theme import Theme
from story.analysis import Band, inside, split

Box = tuple[tuple[float, float], float, float]  # centre, width, height on screen
KINDS = ("failing-motions", "holding-motions")
#: how much wider than a red line its dark casing is, each side (stroke width units)
CASING = 2.0
#: the groups a part belongs to (:func:`metaphors.figure_steps.replacing`): a rule's why,
#: taken off by the next rule's; the claim; the wrong rules' pick, theirs all
WHY, CLAIM, PICK = "why", "claim", "pick"
#: the layer of the vertices' labels, over the tools' shading and the claims
OVER = 3
#: the dashes of a crossed edge: long, so that the edge reads as one thick dashed line
#: beside the solid claim that crosses it
EDGE_DASH = 0.2


def figure_mobjects(kind: str, polygon_spec: str, heuristics: Sequence[str], theme: Theme,
                    box: Box) -> list[Mobject]:
    """The figure ``kind`` (one of :data:`KINDS`) for ``heuristics`` on ``polygon_spec`` in
    ``box``, back to front."""
    if kind not in KINDS:
        raise ValueError(f"a recap figure is one of {', '.join(KINDS)}, not {kind!r}")
    polygon = read_polygon(polygon_spec)
    if polygon.n < 4:  # a polygon handed to the lecture may be a triangle
        frame = Frame(polygon.points, *box)
        return [tag(polygon_mobject(polygon, frame, theme), "idle", "figure:polygon"),
                figure_caption(box, theme, ("a triangle: no diagonal to claim", theme.ink))]
    seen = [moment(name, polygon_spec) for name in heuristics]
    if kind == "failing-motions":
        return _failing(seen, theme, box)
    return _holding(seen, theme, box)


def _polygon(seen: Moment) -> Polygon:
    """The run's polygon, as its beats show it."""
    return Polygon(tuple((float(p[0]), float(p[1])) for p in seen.points), tuple(seen.labels),
                   tuple(range(len(seen.labels))))


def _picture(seen: Moment, frame: Frame, theme: Theme) -> list[Mobject]:
    """P and T's outline (thin, the frame's blue)."""
    drawn: list[Mobject] = [tag(polygon_mobject(_polygon(seen), frame, theme), "idle",
                                "figure:polygon")]
    if seen.triangle:
        drawn.append(tag(VMobject(stroke_color=theme.called, stroke_width=theme.thin_stroke)
                         .set_points_as_corners(frame.many([*seen.triangle, seen.triangle[0]])),
                         "called", "figure:T"))
    return drawn


def _markers(seen: Moment, frame: Frame, theme: Theme,
             claims: Sequence[tuple[str, str]]) -> Mobject:
    """The vertices' labels, clear of every claim the figure draws, over what the tools
    shade (they come after the labels: D's label stood under the red, pink)."""
    labels = list(seen.labels)
    pairs = [(labels.index(u), labels.index(v)) for u, v in claims]
    return tag(VGroup(*(m for _, m in measured_markers(_polygon(seen), (), frame, theme,
                                                        pairs))), "idle", "figure:vertices"
               ).set_z_index(OVER)


def _at(seen: Moment, label: str):
    return dict(zip(seen.labels, seen.points, strict=True))[label]


def _claim(frame: Frame, seen: Moment, theme: Theme, colour: str, role: str) -> Mobject:
    """The claim, as thick as a card's claims, on a dark casing: it reads over the fills it
    crosses (the red of what left P, fading as it comes) and beside the dashed edge."""
    a, b = (frame.to_scene(_at(seen, k)) for k in seen.claim.labels)
    width = theme.stroke * 1.6
    return tag(VGroup(_casing(Line(a, b), theme, width),
                      Line(a, b, color=colour, stroke_width=width)), role, "figure:claim")


def _casing(line: VMobject, theme: Theme, width: float) -> VMobject:
    """A dark line for under a line of ``width``, wider by :data:`CASING` each side."""
    return tag(line.set_stroke(color=theme.background, width=width + 2 * CASING, opacity=1.0),
               None, "figure:casing")


def _pick(frame: Frame, seen: Moment, theme: Theme, role: str) -> Mobject:
    """The pick's dot, over its vertex's (and what the tools shade)."""
    return tag(Dot(frame.to_scene(_at(seen, seen.pick)), radius=0.11,
                   color=theme.role_colour(role)), role, "figure:pick").set_z_index(OVER + 1)


# --- the rules that fail ---------------------------------------------------------------------


def _failing(seen: Sequence[Moment], theme: Theme, box: Box) -> list[Mobject]:
    """Each wrong rule's tool with its line, in place of the last one's; then the claim they
    share (each, if they differ) and the edge it crosses."""
    first = seen[0]
    frame = Frame(first.points, *box)
    drawn = _picture(first, frame, theme)
    moving = [s for s in seen if s.motion is not None]
    if not moving:  # a polygon handed to the lecture may leave T empty: no tool moves
        return [*drawn, _markers(first, frame, theme, []), _no_candidate(box, theme)]
    # one pick for all: amber from the first line to the claim's, not faded out and in again
    shared = len({s.pick for s in moving}) == 1
    for k, rule in enumerate(seen):
        if rule.motion is not None:
            drawn += [replacing(with_line(part, k), WHY)
                      for part in _tool_astray(rule, frame, theme, pick=not shared)]
    if shared:
        drawn.append(replacing(with_line(_pick(frame, moving[0], theme, "argument"),
                                         seen.index(moving[0])), PICK))
    claims = _distinct(seen)
    drawn.append(_markers(first, frame, theme, [c.claim.labels for c in claims]))
    # the last tool goes: the claim and the edge it crosses, alone, are told apart
    drawn += [replacing(with_line(part, len(seen)), CLAIM, WHY, PICK)
              for claim in claims for part in _crossing(claim, frame, theme)]
    return drawn


def _distinct(seen: Sequence[Moment]) -> list[Moment]:
    """The moments with a claim no earlier one made, in order."""
    found: dict[tuple[str, ...], Moment] = {}
    for s in seen:
        found.setdefault(tuple(s.claim.labels), s)
    return list(found.values())


def _no_candidate(box: Box, theme: Theme) -> Mobject:
    return figure_caption(box, theme, ("no candidate in T: AC is the diagonal", theme.ink))


def _tool_astray(seen: Moment, frame: Frame, theme: Theme, pick: bool) -> list[Mobject]:
    """A wrong rule's tool grown from B to its pick: blue inside P; at the pick its part
    outside P, in T, red; its pick amber (if ``pick``)."""
    sheet, m = Sheet(frame, theme), seen.moved
    colour = tool_colour(theme, seen.heuristic)
    points = seen.points

    def at(t: float) -> VGroup:
        tool = tool_drawing(sheet, m, t, colour)
        tool.submobjects = [region(sheet, inside(m.swept(t), points), theme.swept, 0.3,
                                   "swept", "argument") if part.name == "swept" else part
                            for part in tool.submobjects]
        if t >= 1.0:  # the decisive moment: what left P turns red
            astray = split(m.tool(1.0), points, m.triangle)["astray"]
            tool.add(region(sheet, m.astray(points), theme.rejected, 0.6, "figure:outside",
                            "rejected"),
                     path(sheet, astray, theme.rejected, theme.stroke * 1.6, "figure:astray",
                          "rejected"))
        return tag(tool, "argument", "figure:tool")

    return [grows(at(1.0), at), *([_pick(frame, seen, theme, "argument")] if pick else [])]


def _crossing(seen: Moment, frame: Frame, theme: Theme) -> list[Mobject]:
    """The claim, red, the edge it crosses flashing then dashed, and where it crosses (green,
    alone, if it is inner: a polygon handed to the lecture)."""
    drawn = [_claim(frame, seen, theme, _verdict_colour(seen, theme), _verdict_role(seen))]
    if seen.verdict.edge:
        a, b = (frame.to_scene(_at(seen, k)) for k in seen.verdict.edge)
        name = f"figure:edge:{'–'.join(seen.verdict.edge)}"
        drawn.insert(0, grows(crossed_edge_dashed(a, b, name, theme),
                              _flashing(a, b, name, theme)))
    if seen.verdict.point:
        drawn.append(tag(Dot(frame.to_scene(seen.verdict.point), radius=0.09,
                             color=theme.rejected), "rejected", "figure:crossing"))
    return drawn


def crossed_edge_dashed(a, b, name: str, theme: Theme) -> Mobject:
    """The edge a wrong claim crosses, in the red of what fails, thick and dashed on a dark
    casing: the claim across it is solid (both solid red, BD and E–A read as one red cross)."""
    width = theme.stroke * 2.2
    return tag(VGroup(_casing(Line(a, b), theme, width),
                      DashedLine(a, b, color=theme.rejected, stroke_width=width,
                                 dash_length=EDGE_DASH, dashed_ratio=0.55)), "rejected", name)


def _flashing(a, b, name: str, theme: Theme) -> Callable[[float], Mobject]:
    """The crossed edge as it comes in: it flashes twice (thick, in ink), then stays dashed
    red (:func:`crossed_edge_dashed`)."""
    def at(t: float) -> Mobject:
        if t < 0.8 and int(t * 5) % 2 == 0:
            return tag(VGroup(Line(a, b, color=theme.ink, stroke_width=theme.stroke * 2.6)),
                       "rejected", name)
        return crossed_edge_dashed(a, b, name, theme)
    return at


# --- the rules that hold ---------------------------------------------------------------------


def _holding(seen: Sequence[Moment], theme: Theme, box: Box) -> list[Mobject]:
    """The corrections' claim with line 0, to stay; each rule's why with line ``k``, in place
    of the last one's (gravity's claim in place of the corrections')."""
    first = seen[0]
    frame = Frame(first.points, *box)
    drawn = _picture(first, frame, theme)
    corrections = _distinct([s for s in seen if s.band is None and s.motion is not None])
    shared = [replacing(with_line(part, 0), CLAIM) for s in corrections for part in (
        _claim(frame, s, theme, _verdict_colour(s, theme), _verdict_role(s)),
        _pick(frame, s, theme, _verdict_role(s)))]
    whys: list[Mobject] = []
    for k, rule in enumerate(seen):
        if rule.band is not None:  # gravity's claim in place of the corrections': BE and
            # EC along B–C read as one path
            whys += [replacing(with_line(part, k), WHY, WHY, CLAIM)
                     for part in _band(rule, frame, theme)]
        elif rule.motion is not None:
            whys += [replacing(with_line(part, k), WHY) for part in _witness(rule, frame, theme)]
    if not whys:  # no candidate in T, no reflex vertex: nothing moves
        return [*drawn, _markers(first, frame, theme, []), _no_candidate(box, theme)]
    every = [s.claim.labels for s in seen]
    return [*drawn, *whys, _markers(first, frame, theme, every), *shared]


def _verdict_role(seen: Moment) -> str:
    return "result" if seen.verdict.ok else "rejected"


def _verdict_colour(seen: Moment, theme: Theme) -> str:
    return theme.role_colour(_verdict_role(seen))


def _witness(seen: Moment, frame: Frame, theme: Theme) -> list[Mobject]:
    """A correct rule's tool at its pick and the region its argument is about, green."""
    sheet, m = Sheet(frame, theme), seen.moved
    tool = tool_drawing(sheet, m, 1.0, tool_colour(theme, seen.heuristic), seen.points)
    # the green witness covers what the line and the hand swept: no swept blue under it
    tool.submobjects = [p for p in tool.submobjects if p.name != "swept"]
    return [region(sheet, m.witness(), theme.result, 0.45, "figure:witness", "result"),
            tag(tool, "argument", "figure:tool")]


def _band(seen: Moment, frame: Frame, theme: Theme) -> list[Mobject]:
    """Gravity: the ball's fall from V (an arrow: down, for gravity) and its slide to X, the
    band and the region it swept (inside P), the ball at X and the claim, green."""
    band: Band = seen.swept
    sheet = Sheet(frame, theme)
    fall = tag(Arrow(frame.to_scene(band.v), frame.to_scene(band.hit), buff=0.0,
                     color=theme.gravity, stroke_width=theme.stroke,
                     max_tip_length_to_length_ratio=0.25), None, "figure:fall")
    slide = tag(Line(frame.to_scene(band.hit), frame.to_scene(band.x), color=theme.ball,
                     stroke_width=theme.stroke), None, "figure:slide")
    swept = tag(region(sheet, band.swept(1.0), theme.band, 0.3, "swept"), "argument",
                "figure:band-swept")
    taut = path(sheet, shapely.LineString(band.corners(1.0)), theme.band, theme.stroke,
                "figure:band", "argument")
    ball = tag(Dot(frame.to_scene(band.x), radius=0.12, color=theme.ball, stroke_color=theme.ink,
                   stroke_width=1.5), "argument", "figure:ball")
    return [swept, fall, slide, taut, _claim(frame, seen, theme, theme.result, "result"), ball]


__all__ = ["KINDS", "crossed_edge_dashed", "figure_mobjects"]
