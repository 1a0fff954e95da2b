"""The frame every run shares, performed: the polygon, a picked vertex, the triangle T, the
candidates, the claim, the verdict (✓, or a red flash where the claim crosses an edge), notes.
(The storyboard reads these steps itself: :mod:`story.storyboard`.)"""

from __future__ import annotations

from collections.abc import Mapping

from manim import (
    RIGHT,
    Create,
    DashedLine,
    Dot,
    FadeIn,
    Flash,
    Indicate,
    Line,
    LineJointType,
    Write,
)
from manim import (
    Polygon as MPolygon,
)

from metaphors.board import Board, Playable
from metaphors.drawing import crossed_edge
from metaphors.marks import board_spot
from metaphors.panel import CLAIM_WIDTH, CROSSED_WIDTH
from metaphors.performing import Performances, act, performs
from metaphors.picture import upright
from metaphors.tags import tag
from rendering.typeset import text
from story.beats import (
    Beat,
    Candidates,
    Claim,
    Note,
    Pick,
    ShowPolygon,
    ShowTriangle,
    Verdict,
)
from story.storyboard import Reading


def polygon(board: Board, beat: ShowPolygon) -> None:
    # the panel and the first words come with the title and the picture, never before them
    # (issue 22: up a second before the picture they speak of). One FadeIn per marker:
    # FadeIn(*markers) would put them on screen as one group, and manim redraws a whole group
    # in every frame when any member of it changes colour
    board.play(beat, Write(board.title), Create(board.outline),
               *[FadeIn(m) for m in board.markers.values()],
               *[FadeIn(m) for m in board.panel.mobjects()], run_time=1.5, together=True)


def pick(board: Board, beat: Pick) -> None:
    marker = board.markers[beat.vertex]
    # in the colour it keeps (the left-most vertex's blue, a reflex vertex's green)
    colour = board.theme.role_colour(beat.roles.get(beat.vertex, "result"))
    board.play(beat, Indicate(marker, color=colour), run_time=1.0)


def triangle(board: Board, beat: ShowTriangle) -> None:
    t = tag(MPolygon(*[board.at(p) for p in beat.points], color=board.theme.called,
                     stroke_width=board.theme.thin_stroke, fill_color=board.theme.called,
                     fill_opacity=0.15), "called", "T")
    board.keep("T", t)
    board.play(beat, Create(t), run_time=1.0)


def candidates(board: Board, beat: Candidates) -> None:
    # in the candidates' own colour, as the legend and the panel show them: amber is the
    # claim's (review s567: a run of one's own pulsed them amber beside the panel's pink)
    board.play(beat, *[Indicate(board.markers[c], color=board.theme.candidate, scale_factor=1.4)
                       for c in beat.candidates], run_time=1.0)


def claim(board: Board, beat: Claim) -> None:
    u, v = beat.points
    # Amber until judged: green is kept for a claim that holds, red for one that fails.
    line = tag(Line(board.at(u), board.at(v), color=board.theme.argument,
                    stroke_width=board.theme.stroke * 1.5), "argument", "claim")
    board.keep("claim", line)
    # a label it would run through (Correct Scaling's E, on BE) steps aside as it is drawn;
    # the panel draws it too, in the same amber (the panel showed only its ends' colours)
    board.play(beat, Create(line), *board.clear_labels(line),
               *board.panel.draw("claim", u, v, "argument", CLAIM_WIDTH), run_time=1.0)


def verdict(board: Board, beat: Verdict) -> None:
    """The claim judged: a tick, or the claim red, the crossed edge and a flash at the crossing;
    then a turned picture turns back upright (:func:`metaphors.picture.upright`). The verdict's
    caption comes in the play that gives the claim its colour (``together``): played first
    on its own, "✓ DG is an inner diagonal" stood a second over an amber DG (chapter 1 at
    38 s, chapters 3 and 6 likewise for ✗)."""
    _judged(board, beat)
    upright(board, beat)


def _judged(board: Board, beat: Verdict) -> None:
    line = board.objects.get("claim")
    theme = board.theme
    if "T" in board.objects:
        board.scene.play(*board.drop("T"), run_time=0.3 * beat.pace)
    if beat.ok:
        mark = tag(text("✓", font=theme.font, size=48, colour=theme.result), "result", "tick")
        if "fruit" in board.objects:  # green on the fruit's orange (1.5 : 1): a dark halo
            mark.set_stroke(theme.background, width=6.0, background=True)
            mark.joint_type = LineJointType.ROUND
        finder = board.objects.get("finder")
        if finder is not None:  # the black box's answer holds: beside the box, off P
            mark.next_to(finder[0], RIGHT, buff=BOX_GAP)
        elif line is not None:  # beside the claim, clear of every edge and label
            mark.move_to(board_spot(board, mark, line))
        board.keep("verdict", mark)
        held: list[Playable] = [] if line is None else [line.animate.set_color(theme.result)]
        if line is not None:
            tag(line, "result", "claim")
        held += board.panel.recolour("claim", "result")
        board.play(beat, *held, FadeIn(mark, scale=1.5), run_time=1.0, together=True)
        return
    anims: list[Playable] = []
    if line is not None:
        anims.append(tag(line, "rejected", "claim").animate.set_color(theme.rejected))
    anims += board.panel.recolour("claim", "rejected")
    edge = beat.edge
    if edge:
        crossed = crossed_edge(board.vertex(edge[0]), board.vertex(edge[1]),
                               f"edge:{'–'.join(edge)}", theme)
        board.keep("crossed", crossed)
        # in the panel too: the claim red across the red edge it crosses
        anims += [Create(crossed), *board.panel.draw("crossed", board.where[edge[0]],
                                                     board.where[edge[1]], "rejected",
                                                     CROSSED_WIDTH)]
    if beat.point:
        at = board.at(beat.point)
        spot = tag(Dot(at, radius=0.09, color=theme.rejected), "rejected", "crossing")
        board.keep("crossing", spot)
        anims += [FadeIn(spot), Flash(at, color=theme.rejected, flash_radius=0.5)]
    mark = tag(text("✗", font=theme.font, size=48, colour=theme.rejected), "rejected", "cross")
    if line is not None:  # beside the claim, clear of every edge and label
        mark.move_to(board_spot(board, mark, line))
    board.keep("verdict", mark)
    board.play(beat, *anims, FadeIn(mark, scale=1.5), run_time=1.5, together=True)


#: the gap between the black box and the ✓ beside it: its answer checked, "an inner diagonal?"
#: answered off the picture (on P's fill, chapter 1's ✓ marks stood on the polygon, 68-102 s)
BOX_GAP = 0.2


def note(board: Board, beat: Beat) -> None:
    """Any beat as its caption only (the performer of a beat kind with none of its own)."""
    board.play(beat, run_time=1.5)


def dashed(board: Board, a, b, role: str, name: str) -> DashedLine:
    """A dashed segment between polygon points (used for lines outside the polygon)."""
    return tag(DashedLine(board.at(a), board.at(b), color=board.theme.role_colour(role),
                          stroke_width=board.theme.thin_stroke), role, name)


READS: Mapping[str, Reading] = {}  # the frame's steps are read by the storyboard itself
PERFORMS: Performances = performs(
    act(ShowPolygon, polygon), act(Pick, pick), act(ShowTriangle, triangle),
    act(Candidates, candidates), act(Claim, claim), act(Verdict, verdict), act(Note, note))
