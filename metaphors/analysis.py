"""The lecture's analysis: a heuristic's decisive moment, in one continuous pass on one polygon.

A wrong heuristic (water, clock, sweep), once, nothing replayed: the polygon, T and its
candidates; its tool moves slowly to the vertex it picks — the circle grows, the hand turns,
the line sweeps — what it sweeps in the one swept colour whatever the metaphor; it freezes at
the pick, the decisive moment; the swept part outside the polygon (but inside T) turns red,
then the claim's crossed edge flashes and is named (the ✗, said once). Then its correction
(the registry's) on the same polygon: its tool moves to its own pick and the region its
argument is about (:meth:`story.analysis.Motion.witness`) is shaded, inside the polygon,
under one caption that says why. A correct heuristic is shown the second way only; gravity's
band sweeps a region that is always inside the polygon.

Everything is read from the runs' beats (:func:`metaphors.catalog.beats`: the metaphors' shape
states and the exactly judged verdict); the shapes are clipped in :mod:`story.analysis` and
drawn on a :class:`metaphors.stage.Stage`, whose every caption stays on screen as long as it
takes to read.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import TypeVar, cast

import numpy as np
import shapely
from manim import (
    DOWN,
    Animation,
    Arrow,
    Create,
    Dot,
    FadeIn,
    FadeOut,
    Flash,
    Indicate,
    Line,
    UpdateFromAlphaFunc,
    VGroup,
    VMobject,
    linear,
)

from metaphors import catalog
from metaphors.board import Board
from metaphors.captions import whole_frames
from metaphors.drawing import crossed_edge_dashed
from metaphors.gravity import RESTING, Drop, GravityTurn, Slide, Snag
from metaphors.play import TITLE_WIDTH
from metaphors.recorded import Recorded, mark_step
from metaphors.stage import BOX, OUTSIDE, Canvas, Stage, beside, path, place_name, region
from metaphors.tags import tag
from metaphors.theme import Theme
from rendering import typeset
from story.analysis import Band, Motion, inside, motion, outside, split
from story.beats import (
    Beat,
    Candidates,
    Claim,
    Point,
    ShowPolygon,
    ShowTriangle,
    Verdict,
)
from story.registry import entry, spoken
from story.spec import RunSpec
from story.states import Moving, Tool

#: seconds the tool takes to reach its pick: slowly, the moment the argument is about
SLOW = 5.0
#: seconds the picture holds still at the decisive moment (the pick, the red, the witness)
FREEZE = 1.5
#: the stroke width of the dark halo under an analysis's ✓ (:func:`halo`)
HALO_WIDTH = 7.0
#: the metaphor's name on screen, by the registry's metaphor module
NAMES = {"water": "Water", "clock": "Clock", "sweep": "Sweep", "gravity": "Gravity"}


@dataclass(frozen=True)
class Analysis:
    """A lecture segment: ``heuristic``'s decisive moment on ``polygon``, then (for a wrong
    one) its correction's on the same polygon, in one pass.

    ``intro`` (if any) is said as the polygon and T appear and the candidates light,
    ``fails`` as the swept part outside the polygon turns red, ``holds`` as the correction's
    region is shaded (the cue says why); they may name ``{n}`` (the polygon's vertices),
    ``{candidates}`` (T's), ``{pick}``
    (the vertex the tool reached), ``{claim}`` (the claimed diagonal) and ``{edge}`` (the
    edge the claim crosses). ``slow``: the seconds each tool takes to its pick; ``freeze``:
    the seconds the picture holds at the decisive moments.
    """

    heuristic: str
    polygon: str = "counterexample"
    fails: str = ""
    holds: str = ""
    title: str | None = None  # default: "Water: why Scaling fails" and the like
    slow: float = SLOW
    intro: str = ""
    freeze: float = FREEZE
    #: played on the picture the run before it left (the run ends there, turned, its ball,
    #: band and claim kept): gravity's swept region shaded, nothing drawn again (chapter 3
    #: drew the run's end state again before shading it)
    on_run: bool = False


@dataclass(frozen=True)
class Moment:
    """What one run's analysis shows, read from its beats: the polygon, T, the metaphor's
    step (``mover``: its beat, with its motion) or gravity's band, the claim and its verdict."""

    heuristic: str
    points: tuple[Point, ...]
    labels: tuple[str, ...]
    triangle: tuple[Point, ...] | None
    mover: Beat | None
    motion: Motion | None
    band: Band | None
    claim: Claim
    verdict: Verdict
    candidates: tuple[str, ...] = ()  # the vertices in T, as the run names them

    # what fails and holds read of a run with a motion (_check saw it has one, or a band)
    @property
    def moved(self) -> Motion:
        return cast(Motion, self.motion)

    @property
    def moving_beat(self) -> Beat:
        return cast(Beat, self.mover)

    @property
    def swept(self) -> Band:
        return cast(Band, self.band)

    def label_at(self, p: Sequence[float]) -> str:
        """The label of the vertex at ``p``."""
        return next(label for label, q in zip(self.labels, self.points, strict=True)
                    if abs(q[0] - p[0]) < 1e-9 and abs(q[1] - p[1]) < 1e-9)

    @property
    def pick(self) -> str:
        return self.motion.reached if self.motion else self.claim.labels[1]

    def words(self, template: str) -> str:
        """``template`` with its names filled in (see :class:`Analysis`)."""
        edge = "–".join(self.verdict.edge) if self.verdict.edge else ""
        return template.format(pick=self.pick, claim="".join(self.claim.labels), edge=edge,
                               candidates=", ".join(self.candidates), n=len(self.points))


def moment(heuristic: str, polygon: str) -> Moment:
    """The analysis of ``heuristic``'s run on ``polygon`` (a sample's name or a file)."""
    return moment_of(heuristic, catalog.beats(RunSpec(heuristic, polygon).log()))


def moment_of(heuristic: str, beats: Sequence[Beat]) -> Moment:
    """The analysis of a run of ``heuristic``, read from its beats: its first claim, and the
    step of its metaphor that made it (``motion`` None when T held no candidate)."""
    shown = _first(beats, ShowPolygon)
    t = next((b for b in beats if isinstance(b, ShowTriangle)), None)  # gravity has none
    claim, verdict = _first(beats, Claim), _first(beats, Verdict)
    mover = next((b for b in beats if _target(b) is not None), None)
    found = motion(cast(Tool, _target(mover)), t.points) if mover and t else None  # mover: a target's
    band = _band(beats)
    lit = next((b for b in beats if isinstance(b, Candidates)), None)
    return Moment(heuristic, shown.points, shown.labels, t.points if t else None, mover, found,
                  band, claim, verdict, tuple(lit.candidates) if lit else ())


B = TypeVar("B", bound=Beat)


def _first(beats: Sequence[Beat], kind: type[B]) -> B:
    found = next((b for b in beats if isinstance(b, kind)), None)
    if found is None:
        raise ValueError(f"the run has no {kind.action} beat to analyse")
    return found


def _target(beat: Beat) -> Tool | None:
    """The tool's state of a metaphor's step at the vertex it picks (None: no such step)."""
    return beat.at_pick() if isinstance(beat, Moving) else None


def _band(beats: Sequence[Beat]) -> Band | None:
    """Gravity's band from its turn, drop, slide and snag beats (None for another run)."""
    kinds = {b.action: b for b in reversed(beats)}  # the first of each
    turn, drop = _kind(kinds, GravityTurn), _kind(kinds, Drop)
    slide, snag = _kind(kinds, Slide), _kind(kinds, Snag)
    if drop is None or snag is None:
        return None
    where = dict(zip(_first(beats, ShowPolygon).labels, _first(beats, ShowPolygon).points,
                     strict=True))
    hit = _xy(drop.drop.hit)
    x = _xy(slide.slide.to) if slide is not None and slide.slide else hit
    y = _xy(where[snag.snagged]) if snag.snagged in where else None
    return Band(_xy(where[drop.drop.vertex]), hit, x, y, turn.turn_picture if turn else 0.0)


def _xy(p: Sequence[float]) -> tuple[float, float]:
    """A point of the log (a list, or a tuple) as a pair."""
    return (p[0], p[1])


def _kind(kinds: dict[str, Beat], kind: type[B]) -> B | None:
    """The beat of ``kind``'s action in ``kinds`` (action → beat), if any."""
    return cast("B | None", kinds.get(kind.action))


def tool_drawing(stage: Canvas, moving: Motion, t: float, colour: str,
                 within: Sequence[Point] | None = None) -> VGroup:
    """The tool at time ``t`` and what it has swept inside T: the region in the one swept
    colour whatever the metaphor, the tool in its own (thick inside T, faint beyond). No red
    yet: the part outside the polygon turns red when the tool has stopped (:func:`fails`).
    The rising water: in the water's colour — what it covers is not what the argument is
    about, what is still dry is — and, given the polygon (``within``), only inside it: the
    shore AC lies outside P, and blue water there would say "inside" where the legend's red
    says "outside P"; its level is thick inside P, faint outside."""
    theme, corners = stage.theme, moving.triangle
    swept, tool = moving.swept(t), moving.tool(t)
    if moving.rising:
        if within is None:
            return VGroup(region(stage, swept, colour, 0.35, "flood"),
                          path(stage, tool, colour, theme.stroke * 1.3, "tool"))
        return VGroup(
            region(stage, inside(swept, within), colour, 0.35, "flood"),
            path(stage, outside(tool, within), colour, theme.thin_stroke, "tool:beyond", None,
                 0.45),
            path(stage, inside(tool, within), colour, theme.stroke * 1.3, "tool"))
    return VGroup(
        region(stage, swept, theme.swept, 0.3, "swept", "argument"),
        path(stage, outside(tool, corners), colour, theme.thin_stroke, "tool:beyond", None,
             0.45),
        path(stage, inside(tool, corners), colour, theme.stroke * 1.3, "tool", "argument"),
    )


def moving(stage: Stage, draw, seconds: float) -> tuple[list, VGroup]:
    """The drawing ``draw(t)`` as t runs from 0 to 1, steadily, in ``seconds``: an
    animation, and the mobject it redraws."""
    drawing = tag(draw(0.0), "argument", "analysis:tool").set_z_index(1)
    return [UpdateFromAlphaFunc(drawing, lambda m, a: m.become(draw(a)), rate_func=linear,
                                run_time=seconds)], drawing


# --- the two halves ------------------------------------------------------------------------------


def tool_colour(theme: Theme, heuristic: str) -> str:
    metaphor = entry(heuristic).metaphor
    return {"water": theme.water, "clock": theme.hand, "sweep": theme.sweep}.get(
        metaphor or "", theme.band)


def light(stage: Stage, label: str, role: str) -> Animation:
    """Vertex ``label``'s marker turned to ``role``'s colour, and kept in it: a candidate
    pink from the frame on, the pick amber once reached, green once its claim holds, as a
    run's markers are (a pulse alone left D and E grey the 8.5 s the water spread)."""
    marker = tag(stage.markers[label], role, f"vertex:{label}")
    return cast(Animation, marker.animate.set_color(stage.theme.role_colour(role)))


def frame(stage: Stage, seen: Moment, analysis: Analysis) -> None:
    """The pass opens on the frame: the polygon, T and its candidates lit, said once."""
    # no "swept" key yet: it comes with the first swept region (:func:`fails`)
    stage.say(seen.words(analysis.intro), (stage.appear(), 1.5))
    # lit once on screen: a marker fading in is recorded white, not yet a candidate
    if seen.candidates:
        stage.scene.play(*[light(stage, c, "candidate") for c in seen.candidates],
                         run_time=0.8)
    stage.scene.wait(whole_frames(analysis.freeze / 2))  # a moment to look at the polygon


def fails(stage: Stage, wrong: Moment, analysis: Analysis) -> list:
    """The wrong heuristic's tool runs to its pick and freezes there; the part it swept outside
    the polygon turns red; the claim's crossed edge flashes and is named. Returns what the
    correction clears away."""
    theme, m = stage.theme, wrong.moved
    colour = tool_colour(theme, wrong.heuristic)
    motion_anims, drawing = moving(stage, lambda t: tool_drawing(stage, m, t, colour),
                                   analysis.slow)
    opening = [] if analysis.intro else stage.appear()
    # the "swept" key comes with the tool that sweeps, not before (it stood 8 s over a
    # picture with nothing swept, chapter 2 at 41.6 s)
    stage.say(wrong.moving_beat.caption, ([*opening, FadeIn(drawing),
                                           *stage.key(theme.swept, "swept", "swept")],
                                          1.5 if opening else 0.3),
              (motion_anims, analysis.slow),
              ([light(stage, wrong.pick, "argument")], 0.8),
              ([], analysis.freeze))  # frozen at the pick: the moment the argument is about
    stray = split(m.tool(1.0), stage.polygon.points, m.triangle)["astray"]
    outside_tool = path(stage, stray, theme.rejected, theme.stroke * 2.4, "analysis:astray",
                        "rejected").set_z_index(2)
    outside_area = region(stage, m.astray(stage.polygon.points), theme.rejected, 0.6,
                          "analysis:outside", "rejected").set_z_index(2)
    at = stage.vertex(wrong.pick)
    # the vertices on the red set apart from it by a dark halo (the pick amber, not pulsed
    # red: in the red it vanished), its amber flash says where the red reaches it
    stage.say(wrong.words(analysis.fails),
              ([Create(outside_tool), FadeIn(outside_area),
                *stage.key(theme.rejected, OUTSIDE, "astray"),
                # the pick flashes amber as the tool reaches it: red is the verdict's, and a
                # red burst here stood before the claim was drawn
                Flash(at, color=theme.argument, flash_radius=0.45),
                *stage.set_apart(m.astray(stage.polygon.points), stray)], 1.6),
              ([], analysis.freeze))
    return [drawing, outside_tool, outside_area, *crossing(stage, wrong, analysis.freeze)]


def crossing(stage: Stage, wrong: Moment, hold: float = 0.0) -> list:
    """The claim in red, the edge it crosses flashing and named, a flash where it crosses;
    then ``hold`` seconds still."""
    theme, verdict = stage.theme, wrong.verdict
    u, v = wrong.claim.labels
    claim = tag(Line(stage.vertex(u), stage.vertex(v), color=theme.rejected,
                     stroke_width=theme.stroke * 1.5), "rejected", "analysis:claim")
    shown = [claim.set_z_index(3)]
    anims: list[Animation] = [Create(claim)]
    flashes = []
    if verdict.edge:
        a, b = (stage.vertex(k) for k in verdict.edge)
        # dashed on its casing, under the solid claim: both solid red, BD and E–A read as one
        # red cross (chapter 2), as the recap's and the overview's did
        key = f"analysis:edge:{'–'.join(verdict.edge)}"
        edge = crossed_edge_dashed(a, b, key, theme).set_z_index(3)
        dashes = tag(edge[1], "rejected", key)  # what flashes: the red, not its casing
        name = tag(typeset.text(f"edge {'–'.join(verdict.edge)}", font=theme.font,
                                size=theme.label_size + 2, colour=theme.rejected),
                   "rejected", "analysis:edge-name").set_z_index(4)
        # off the red the pass is about, as off P's fill
        red = shapely.transform(wrong.moved.astray(stage.polygon.points),
                                lambda xy: np.array([stage.at(p)[:2] for p in xy])) \
            if wrong.motion is not None else None
        place_name(stage, name, a, b, [claim], red)
        shown += [edge, name]
        anims += [Create(edge), FadeIn(name)]
        flashes = [([Indicate(dashes, color=theme.ink, scale_factor=1.0)], 0.5),
                   ([Indicate(dashes, color=theme.ink, scale_factor=1.0)], 0.5)]
    if verdict.point:
        at = stage.at(verdict.point)
        spot = tag(Dot(at, radius=0.09, color=theme.rejected), "rejected", "analysis:crossing")
        shown.append(spot.set_z_index(4))
        anims += [FadeIn(spot), Flash(at, color=theme.rejected, flash_radius=0.5)]
    stage.say(verdict.caption, (anims, 1.2), *flashes, ([], hold))
    return shown


def holds(stage: Stage, right: Moment, analysis: Analysis, first: Sequence = ()) -> None:
    """A correct heuristic's tool reaches its pick; the region its argument is about is shaded,
    inside the polygon, and the claim drawn: one caption says why. ``first``: animations that
    clear the stage for it."""
    theme, first = stage.theme, list(first)
    if right.band is not None:
        _band_moves(stage, right, analysis, first)
        witness = right.band.swept(1.0)
        # the green witness covers the band's swept region: its key goes before it comes
        # (it stayed with no rose left, chapter 3 at 46 s)
        label, covered = "swept", stage.forget_key("band")
    else:
        m = right.moved
        colour = tool_colour(theme, right.heuristic)
        if m.rising:  # the water is no swept region: its own key
            first += [*stage.forget_legend(), *stage.key(colour, "under water", "water")]
        motion_anims, drawing = moving(
            stage, lambda t: tool_drawing(stage, m, t, colour, stage.polygon.points),
            analysis.slow)
        stage.say(right.moving_beat.caption, *out_then_in(first, 1.5), ([FadeIn(drawing)], 0.3),
                  (motion_anims, analysis.slow),
                  ([light(stage, right.pick, "argument")], 0.6))
        witness = m.witness()
        label = "still dry" if m.rising else "swept"
        # the green witness covers what was swept: the blue key goes before it comes (it
        # stayed with no blue left, chapter 2 at 145 and 210 s)
        covered = [] if m.rising else stage.forget_key("swept")
    shaded = region(stage, witness, theme.result, 0.45, "analysis:witness",
                    "result").set_z_index(2)
    u, v = right.claim.labels
    claim = tag(Line(stage.vertex(u), stage.vertex(v), color=theme.result,
                     stroke_width=theme.stroke * 1.5), "result", "analysis:claim").set_z_index(3)
    tick = tag(typeset.text("✓", font=theme.font, size=48, colour=theme.result), "result",
               "analysis:tick").set_z_index(4)
    beside(stage, tick, claim, witness)
    # the pick green with its claim, judged (a band's run lit no pick)
    judged = [light(stage, right.pick, "result")] if right.band is None else []
    shown = [FadeIn(shaded), Create(claim), FadeIn(halo(stage, tick)), FadeIn(tick), *judged,
             *stage.key(theme.result, f"{label}: in P", "witness")]
    gone = [(covered, 0.4)] if covered else []  # a play of its own: no text over a going one
    stage.say(right.words(analysis.holds), *gone, (shown, 1.5), ([], analysis.freeze))


def out_then_in(anims: Sequence[Animation], alone: float) -> list[tuple[list, float]]:
    """The plays of ``anims`` with what they take off played before what they put on: a text
    goes (the wrong heuristic's title, a legend entry) before the next comes in its place,
    never the two faded into each other (issue 22 item 9). None: one still play of ``alone``
    seconds."""
    gone: list[Animation] = [a for a in anims if isinstance(a, FadeOut)]
    come = [a for a in anims if not isinstance(a, FadeOut)]
    plays: list[tuple[list, float]] = [(gone, 0.4)] if gone else []
    if come or not plays:
        plays.append((come, 0.6 if anims else alone))
    return plays


def halo(stage: Stage, mark) -> VMobject:
    """A dark silhouette of ``mark`` (its glyph's outline, filled and thickly stroked in the
    background's colour) just under it: a green ✓ on the green witness shading reads."""
    theme = stage.theme
    backing = VMobject(fill_color=theme.background, fill_opacity=1.0,
                       stroke_color=theme.background, stroke_width=HALO_WIDTH)
    backing.set_points(mark.points.copy())
    return tag(backing, None, "analysis:tick:halo").set_z_index(mark.z_index - 0.5)


def _band_moves(stage: Stage, right: Moment, analysis: Analysis, first: list) -> None:
    """Gravity: the run's end, told once — not its steps again (review r34: turn, fall,
    slide and snag said and shown a second time): the ball at X on its taut band, the line
    it fell along, then the region the band swept between that line and itself."""
    theme, band = stage.theme, right.swept
    ball = tag(Dot(stage.at(band.x), radius=0.12, color=theme.ball, stroke_color=theme.ink,
                   stroke_width=1.5, fill_opacity=RESTING), "argument",  # X's dot shows
               "analysis:ball").set_z_index(5)
    fell = path(stage, shapely.LineString([band.v, band.hit]), theme.band, theme.thin_stroke,
                "analysis:fall", "argument").set_z_index(3)
    taut = path(stage, shapely.LineString(band.corners(1.0)), theme.band, theme.stroke * 1.3,
                "analysis:band", "argument").set_z_index(3)
    swept = tag(region(stage, band.swept(1.0), theme.band, 0.3, "swept"), "argument",
                "analysis:swept").set_z_index(1)
    v, x = (right.label_at(p) for p in (band.v, band.x))
    shape = f"taut round {right.label_at(band.y)}" if band.y else "straight"
    stage.say(f"The ball fell from {v} and slid to {x}; the band is {shape}",
              (first + stage.appear() + [FadeIn(_gravity_arrow(stage)), FadeIn(fell),
                                         FadeIn(taut), FadeIn(ball)], 1.5),
              ([], analysis.freeze))
    stage.say("On the way it swept the shaded part, between the fall and the band",
              ([FadeIn(swept), *stage.key(theme.band, "band swept", "band")], 1.0),
              ([], analysis.freeze))


def _gravity_arrow(stage: Stage):
    theme = stage.theme
    left, top = BOX.x - BOX.width / 2 - 0.3, BOX.y + BOX.height / 2 - 0.3
    arrow = Arrow((left, top, 0), (left, top - 1.0, 0), buff=0, color=theme.gravity,
                  stroke_width=4, max_tip_length_to_length_ratio=0.3)
    g = typeset.text("g", font=theme.font, size=theme.label_size + 4, colour=theme.gravity)
    return tag(VGroup(arrow, g.next_to(arrow, DOWN, buff=0.08)), None, "gravity")


def play_analysis(scene, analysis: Analysis, theme: Theme) -> None:
    """Play the segment: the wrong heuristic fails, then its correction holds — or, for a
    correct one, why it holds."""
    known = entry(analysis.heuristic)
    name = NAMES.get(known.metaphor or "", str(known.metaphor).capitalize())
    first = moment(analysis.heuristic, analysis.polygon)
    _check(analysis, first)
    if analysis.on_run:
        holds_on_run(scene.played_board, scene.played_beats[-1], first, analysis,
                     analysis.title or f"{name}: why {spoken(analysis.heuristic)} is right")
        return
    said = spoken(analysis.heuristic)  # the thesis's names, never the slugs (issue 22)
    if known.correct:
        holds(_stage(scene, first, analysis.title or f"{name}: why {said} is right", theme),
              first, analysis)
        return
    if known.correction is None:
        raise ValueError(f"{analysis.heuristic} is wrong and has no correction to analyse")
    right = moment(known.correction, analysis.polygon)
    stage = _stage(scene, first, analysis.title or f"{name}: why {said} fails", theme,
                   right.claim.labels)
    if analysis.intro:
        frame(stage, first, analysis)
    cleared = fails(stage, first, analysis)
    # the correction's first appearance in the chapter: named with its picture
    # the wrong pick is a candidate again, for the correction to pick among
    again = [light(stage, first.pick, "candidate")] if first.pick in first.candidates else []
    holds(stage, right, analysis, [
        *[FadeOut(m) for m in cleared], *stage.forget_key("astray"), *again,
        *stage.retitle(f"{name}: the correction, {spoken(known.correction, first=True)}")])


def holds_on_run(board: Board, last: Beat, right: Moment, analysis: Analysis,
                 title: str) -> None:
    """Gravity's why, on the run's last picture (:attr:`Analysis.on_run`): the title says what
    is asked, and the region the band swept, shaded as it swept, turns green under the words
    that say why the claim is inner — the claim, its ends and its ✓ green already, from the
    run's verdict. Nothing is drawn again: the analysis redrew the picture the run had just
    ended on, ball, band and all, and said its steps again (chapter 3 at 38-45 s)."""
    theme, band = board.theme, right.swept
    witness = region(board, band.swept(1.0), theme.result, 0.45, "analysis:witness",
                     "result").set_z_index(-1)
    new_title = tag(typeset.glyphs(title, font=theme.font, size=30, colour=theme.ink),
                    None, "title").move_to(board.title.get_center())
    if new_title.width > TITLE_WIDTH:
        new_title.scale_to_fit_width(TITLE_WIDTH)
    old_title, board.title = board.title, new_title
    board.captions.hold()  # the run's last words are read in their own step
    board.scene.play(FadeOut(old_title), run_time=0.4)  # out, then in: never crossfaded
    swept = board.objects.pop("swept", None)
    tick = board.objects.get("verdict")
    # the ✓ on a dark halo, should the green reach it
    backing = [FadeIn(halo(cast(Stage, board), tick))] if tick is not None else []
    # the run's last beat, saying why: its lit row, its roles (the claim's ends green) kept
    said = replace(last, caption=right.words(analysis.holds))
    mark_step(cast(Recorded, board.scene), said.caption, kind="analysis")
    board.play(said, FadeIn(new_title), *([FadeOut(swept)] if swept is not None else []),
               FadeIn(witness), *backing, run_time=1.5, least=analysis.freeze, together=True)
    board.keep("witness", witness)
    board.close()


def _stage(scene, seen: Moment, title: str, theme: Theme, *later: tuple[str, str]) -> Stage:
    """The stage of ``seen``, its labels clear of its claim and of the ``later`` ones (its
    correction's)."""
    red = seen.moved.astray(seen.points) if seen.motion is not None else None  # none if right
    return Stage(scene, seen.points, seen.labels, seen.triangle, title, theme,
                 seen.band.turn if seen.band else 0.0, (seen.claim.labels, *later), red)


def _check(analysis: Analysis, seen: Moment) -> None:
    """Raise ValueError (one line) for an analysis with nothing to show."""
    where = f"{analysis.heuristic} on {analysis.polygon}"
    if seen.motion is None and seen.band is None:
        raise ValueError(f"{where}: no candidate in T, so no motion to analyse")
    if not entry(analysis.heuristic).correct and seen.verdict.ok:
        raise ValueError(f"{where}: its claim {''.join(seen.claim.labels)} is an inner "
                         "diagonal, so there is no failure to analyse")
