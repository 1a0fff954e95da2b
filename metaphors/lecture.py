"""How a lecture chapter plays: its segments in order, as one Manim section.

A chapter is a list of segments (plain data): a card of text, a run of an algorithm
played by the metaphor scenes, the analysis of a heuristic's decisive moment
(:mod:`metaphors.analysis`), the reference triangulation beside ours, or an exercise
(question, a pause with a countdown, the answer animated). The chapters themselves — what
they say and show — are the scene files ``scenes/chapters/ch<k>_<slug>.py``, each a
:class:`LectureScene` naming its segments; ``trex lecture`` renders them (in parallel) and
joins them.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import cast

import numpy as np
import shapely
from manim import (
    DOWN,
    LEFT,
    RIGHT,
    UP,
    Animation,
    Create,
    Dot,
    FadeIn,
    FadeOut,
    Flash,
    Line,
    VGroup,
    VMobject,
    Write,
)

from geometry.cdt import constrained_delaunay
from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from geometry.polygon import Polygon
from geometry.results import TriangleIndices
from geometry.triangulate import triangulate
from metaphors import catalog, figure_steps
from metaphors.analysis import Analysis, play_analysis
from metaphors.captions import whole_frames
from metaphors.countdown import countdown
from metaphors.drawing import (
    Frame,
    crossed_edge,
    polygon_mobject,
    triangulation_figure,
)
from metaphors.figures import WIDE_BOX, WIDE_KINDS, Figure, figure_mobjects
from metaphors.labels import LABEL_HALO, measured_markers
from metaphors.layout import METAPHOR, Box
from metaphors.recorded import captions_of, end_steps, lead_in, mark_step
from metaphors.scene import TraceScene
from metaphors.stage import OUTSIDE, Stage, hand_over, place_name, region
from metaphors.stills import MARKERS_AT, answer_front, still_mobjects
from metaphors.tags import tag
from metaphors.theme import Theme
from rendering import typeset
from rendering.typeset import FlatText
from story.exercises import (
    Exercise,
    checking_time,
    crossed_edges,
    hunted_exercise,
    make_exercises,
    measured_pairs,
)
from story.hunt import hunt
from story.registry import spoken
from story.runs import record_user_run
from story.spec import RunSpec
from story.storyboard import Pacing
from usercode.heuristic import load_user_heuristic, run_heuristic

#: the widest a card's line may be (scene units): a longer one wraps
CARD_WIDTH = 13.2
#: a card with a figure: its title's height, and its words in the right half
FIGURED_TITLE_Y, FIGURED_WORDS_X, FIGURED_WIDTH = 3.2, 3.35, 6.4
#: a card with a wide figure (a row of pictures): the row's top, under the title, the words'
#: foot, over the frame's bottom, the room between the row and its words, and the room
#: between two columns of words
WIDE_TOP, WIDE_FOOT, WIDE_GAP, WIDE_BUFF = 2.85, -3.8, 0.2, 0.15
#: the comparison's pictures: their centre's height and their height, under the name (3.2)
#: and the count (the labels of P's top vertices keep clear of it), over the note (-3.55)
COMPARE_Y, COMPARE_HEIGHT, COMPARE_COUNT_Y = -0.45, 4.6, 2.65


def _on_run(segment) -> bool:
    """Whether ``segment`` plays on the picture the run before it left."""
    return isinstance(segment, Analysis) and segment.on_run


def _one_picture(before, segment, lecture_polygon: str) -> bool:
    """Whether ``segment`` draws the polygon ``before`` left on screen, the same, so that the
    picture goes on: a wrong heuristic's card (its metaphor on the counterexample) and its
    pass, and that pass and the next heuristic's card (chapter 2)."""
    def drawn(s) -> str | None:
        if isinstance(s, Card) and s.figure is not None and s.figure.kind == "metaphor":
            return s.figure.polygon or lecture_polygon
        if isinstance(s, Analysis) and not s.on_run:
            return s.polygon
        return None

    return drawn(before) is not None and drawn(before) == drawn(segment)


def inner_edges(polygon, triangles: Sequence[TriangleIndices]) -> list[tuple[int, int]]:
    """The triangles' sides that are no edge of P: the triangulation's diagonals.

    >>> from geometry.polygon import Polygon
    >>> inner_edges(Polygon.from_points([(0, 0), (1, 0), (1, 1), (0, 1)]), [(0, 1, 2), (0, 2, 3)])
    [(0, 2)]
    """
    n = polygon.n
    sides = {tuple(sorted((t[a], t[b]))) for t in triangles for a, b in ((0, 1), (1, 2), (0, 2))}
    return sorted((i, j) for i, j in sides if (j - i) % n not in (1, n - 1))

FRUIT_BOX = Box(-3.45, 0.8, 5.6, 3.9)  # room for the plate below the fruit
#: an exercise's picture on the left, so its answer is written beside it, never over it
QUIZ_BOX = ((-2.7, -0.1), 7.4, 5.6)
ANSWER_AT, ANSWER_WIDTH = (4.25, -0.3, 0), 4.6
COUNTDOWN_AT = (4.25, 1.6, 0)
#: seconds the answer takes to come in (its text, what it draws; the countdown's 0 fading)
ANSWER_COMING = 1.2
#: the space before a number (a no-break space there keeps it on its word's line)
_NUMBER = re.compile(r" (?=\d)")
#: the colour of each pick's front, as its metaphor draws it (:mod:`metaphors.theme`)
#: an answer that says no (its text in the red of what fails)
_SAYS_NO = re.compile(r"no\b")
#: T's part outside P in an answer, as opaque as the analyses' (:func:`metaphors.analysis.fails`)
OUTSIDE_OPACITY = 0.6
#: the row of the red's key, under the answer (the picture's legend row)
KEY_Y = -3.6
_FRONT_COLOUR = {"scaling": "water", "scaling-correct": "water", "rotation": "hand",
                 "rotation-ccw": "hand", "rotation-correct": "hand", "translation": "sweep",
                 "translation-correct": "sweep"}
DEFAULT_PACING = Pacing(full=2, fast=0.35)


def _on_screen(area, frame: Frame):
    """A shapely region in the polygon's coordinates, as it stands on screen."""
    return shapely.transform(area, lambda xy: np.array([frame.to_scene(p)[:2] for p in xy]))


def _off_the_red(name, a, b, red, busy) -> None:
    """An edge's name moved off the red region ``red`` (on screen), if it stands on it: to
    the spot beside the edge, either side, clear of the red and clearest of ``busy`` (P's
    edges on screen; an exercise's "edge F–G" stood on T's red part outside P, and read as
    the red's own); left where none is."""
    if not _box(name.get_center(), name).intersects(red):
        return
    along = (b - a) / max(float(np.linalg.norm(b - a)), 1e-9)
    normal = np.array([-along[1], along[0], 0.0])
    lift = float(np.abs(normal[:2]) @ np.array([name.width / 2, name.height / 2]))
    spots = [a + (b - a) * k + normal * side * (gap + lift)
             for k, side, gap in itertools.product((0.2, 0.35, 0.5, 0.65, 0.8), (1, -1),
                                                   (0.2, 0.45))]
    clear = [p for p in spots if not _box(p, name).intersects(red)]
    if clear:
        name.move_to(max(clear, key=lambda p: min(_box(p, name).distance(busy), 0.3)))


def _box(centre, name) -> shapely.Polygon:
    half = np.array([name.width / 2, name.height / 2])
    return shapely.box(*(centre[:2] - half), *(centre[:2] + half))


@dataclass(frozen=True)
class _Sheet:
    """An exercise's picture as :func:`metaphors.stage.region` and
    :func:`metaphors.stage.place_name` read it: its frame, theme, polygon and markers."""

    frame: Frame
    theme: Theme
    polygon: Polygon | None = None
    markers: Mapping[int, VMobject] | None = None  # a vertex's index → its marker (dot, label)


@dataclass(frozen=True)
class Card:
    """A title and a few lines of text, shown one after another, each its own caption and
    each held until it has been read (:mod:`metaphors.captions`)."""

    title: str
    lines: tuple[str, ...] = ()
    figure: Figure | None = None  # its idea drawn on the left, the words on the right
    #: per line, a figure whose claims (and crossed edges) come in with that line, in place
    #: of the last line's: each claim drawn when its words say it, one at a time (review
    #: r567: two green claims drawn from the start read as one path); None: none
    line_figures: tuple[Figure | None, ...] = ()
    #: where the words go with a figure: ``"right"`` of it; under a wide figure (a row of
    #: pictures, :data:`metaphors.figures.WIDE_KINDS`) in ``"columns"``, each line under
    #: its own picture (one statement per picture)
    layout: str = "right"

    def __post_init__(self) -> None:
        wide = self.figure is not None and self.figure.kind in WIDE_KINDS
        if self.layout not in ("right", "columns") or wide != (self.layout == "columns"):
            raise ValueError(f"card {self.title!r}: layout {self.layout!r} for a "
                             f"{'wide' if wide else 'narrow'} figure")


@dataclass(frozen=True)
class Run:
    """An algorithm run on a polygon, played by the metaphor scenes.

    ``polygon`` None: the lecture's polygon (:meth:`LectureScene.lecture_polygon`).
    ``black_box``: divide and conquer's heuristic is not shown, only each diagonal asked for
    and the one that comes out (:attr:`metaphors.scene.TraceScene.black_box`).
    """

    algorithm: str
    polygon: str | None
    title: str
    heuristic: str | None = None
    box: Box = METAPHOR
    pacing: Pacing = DEFAULT_PACING
    speed: float = 0.8  # × every beat's run time
    black_box: bool = False

    def spec(self, lecture_polygon: str) -> RunSpec:
        """The run this segment plays: on its own polygon, else on the lecture's."""
        return RunSpec(self.algorithm, self.polygon or lecture_polygon, heuristic=self.heuristic)


@dataclass(frozen=True)
class Compare:
    """Our triangulation beside the constrained Delaunay reference, on the same polygon."""

    polygon: str | None
    ours: str = "ear-clipping"
    seconds: float = 6.0


@dataclass(frozen=True)
class Hunted:
    """A heuristic the lecture did not cover (``FILE.py:FUNCTION``), a counterexample hunted
    for at build time (:func:`story.hunt.hunt`, fixed ``seed`` and ``budget``): a card says
    how it was found, then the class is asked whether its claim there is inner, as an
    exercise (the next number, ``think`` seconds counted down), and the answer draws what the
    rule measured and where its claim leaves P. ``general``: hunt only polygons in general
    position whose wrong claim crosses an edge, so that the class sees it fail (issue 22)."""

    heuristic: str
    title: str
    rule: str  # the rule in words
    name: str = "the rule"  # its short name, as the question says it
    #: why it claims its vertex, in words (no number): ``{pick}`` and ``{others}`` the labels
    why: str = "it picks {pick}, not {others}"
    seed: int = 0
    budget: int = 2000
    general: bool = True
    figure: Figure | None = None  # the card's figure (e.g. the rule drawn on a polygon)
    think: int = 15


@dataclass(frozen=True)
class Quiz:
    """Exercises from :func:`story.exercises.make_exercises`: ask, count down, answer."""

    count: int = 3
    seed: int = 2022
    think: int = 15  # seconds the question stays up, counted down, before its answer


class LectureScene(TraceScene):
    """Plays one chapter: its segments in order, as one Manim section."""

    chapter_title = "Chapter"
    #: the chapter's name (``--chapters gravity``, ``03-gravity.mp4``); a lecture chapter's
    #: file is ``scenes/chapters/ch<k>_<slug>.py`` (:func:`trex.chapters.lecture_chapters`)
    slug = ""
    #: notes for whoever teaches the chapter (Forišek–Steinová's experience), never played:
    #: ``trex lecture`` writes them to ``teacher-notes.md``, the slides show them in the
    #: speaker window, the handout prints them
    teacher_notes: tuple[Card, ...] = ()
    polygon = "lecture"  # the lecture's polygon, unless one is handed (trex lecture --polygon)
    call_line = False  # no code in the lecture: a run's steps are its lit rows and captions
    #: the picture the segment before left to go on (:func:`metaphors.stage.hand_over`)
    carried: tuple | None = None
    asked = 0  # the number of the last exercise asked (a hunted one takes the next)

    def chapter_segments(self) -> tuple:
        """The chapter's segments, in order (a chapter's scene file says them)."""
        raise NotImplementedError(f"{type(self).__name__} names no segments")

    def lecture_polygon(self) -> str:
        """The polygon of the runs that name none: the handed one, else ``TREX_POLYGON``
        (plain ``manim``), else the ``lecture`` sample."""
        return self.run_spec().polygon

    def construct(self) -> None:
        self.camera.background_color = self.theme.background  # type: ignore[assignment]  # manim's setter is typed ManimColor, and parses any colour
        self.next_section(self.chapter_title)
        segments = self.chapter_segments()
        for k, segment in enumerate(segments):
            # an analysis on the run before it goes on from its last picture: the run keeps
            # it (not turned back, its ball and band kept), and the screen is not cleared
            self.keep_end = k + 1 < len(segments) and _on_run(segments[k + 1])
            # a heuristic's card and its pass draw one polygon: the picture goes on, moved
            # into place, not faded and drawn again (hand_over)
            self.carried = self._picture() if k and _one_picture(
                segments[k - 1], segment, self.lecture_polygon()) else None
            if not _on_run(segment):
                self.clear_screen(keep=self._kept())
            self.play_segment(segment)
        captions_of(self).hold()  # the last caption is read within the last step
        end_steps(self)
        self.clear_screen()
        self.wait(0.5)

    def play_segment(self, segment) -> None:
        """Play one segment by its kind."""
        if not isinstance(segment, (Card, Run)):
            # it draws a polygon of its own: the next run's frame is no longer the one just
            # seen, not "as before" (chapter 2 once said so of a run on another polygon after
            # the counterexample's analysis)
            self.frames_seen.clear()
        match segment:
            case Card():
                self.play_card(segment)
            case Run():
                self.play_run(segment)
            case Hunted():
                self.play_hunted(segment)
            case Analysis():
                self.play_analysis(segment)
            case Compare():
                self.play_compare(segment)
            case Quiz():
                self.play_quiz(segment)
            case _:
                raise TypeError(f"{type(self).__name__}: no way to play {segment!r}")

    def clear_screen(self, keep: Sequence = ()) -> None:
        """Fade out everything but ``keep`` (the caption on screen read first): the fade opens
        the step that follows (it ends on its picture)."""
        captions_of(self).finish()
        lead_in(self)
        going = [m for m in self.mobjects if all(m is not k for k in keep)]
        if going:
            self.play(*[FadeOut(m) for m in going], run_time=0.4)
            self.remove(*going)

    def _picture(self):
        """The polygon on screen and its vertex markers in the polygon's order (a card's
        figure's or a pass's), or None: what :func:`metaphors.stage.hand_over` moves on."""
        named = {getattr(m, "name", ""): m for m in self.mobjects}
        polygon = named.get("figure:polygon") or named.get("analysis:polygon")
        if polygon is None:
            return None
        if "figure:vertices" in named:
            group = named["figure:vertices"]
            return polygon, list(group.submobjects), [polygon, group]
        markers = [m for m in self.mobjects if getattr(m, "name", "").startswith("vertex:")]
        return polygon, markers, [polygon, *markers]

    def _kept(self) -> list:
        """What the screen keeps for the next segment: the picture it carries on."""
        return [] if self.carried is None else list(self.carried[2])

    def text(self, text: str, size: int, colour: str | None = None) -> FlatText:
        return typeset.text(text, font=self.theme.font, size=size,
                            colour=colour or self.theme.ink, width=CARD_WIDTH)

    def card_line(self, line: str, width: float = CARD_WIDTH) -> FlatText | VGroup:
        """A card's line after its bullet; a long one on balanced rows (not shrunk), the
        rows after the first indented under the words, not the bullet."""
        font, size, colour = self.theme.font, self.theme.caption_size, self.theme.idle
        one = typeset.text("• " + line, font=font, size=size, colour=colour)
        if one.width <= width:
            return one
        indent = (typeset.text("• M", font=font, size=size).width
                  - typeset.text("M", font=font, size=size).width)
        if width < CARD_WIDTH:  # beside a figure: as many rows as it needs, none shrunk
            shown = typeset.wrapped("• " + line, font=font, size=size, colour=colour,
                                    width=width - indent)
        else:
            shown = typeset.balanced(line, font=font, size=size, colour=colour, lead="• ",
                                     width=width - indent, aligned_edge=LEFT)
        if isinstance(shown, VGroup):
            for row in shown[1:]:
                row.shift(RIGHT * indent)
        return shown

    # --- segments ---------------------------------------------------------------------------------

    def mark_card_line(self, line: str | None, card: Card) -> None:
        """A card's title (``line`` None) or one of its lines starts a step of its own: call
        before it appears (:mod:`metaphors.steps`)."""
        if line is None:
            mark_step(self, card.title, kind="card")
        else:
            mark_step(self, line, kind="card-line")

    def play_card(self, card: Card) -> None:
        captions = captions_of(self)
        title = tag(typeset.glyphs(card.title, font=self.theme.font, size=self.theme.title_size,
                                   colour=self.theme.ink, width=CARD_WIDTH), None, "card:title")
        width = CARD_WIDTH if card.figure is None else FIGURED_WIDTH
        if card.layout == "columns":  # each line as wide as its picture
            width = WIDE_BOX[1] / max(1, len(card.lines)) - 2 * WIDE_BUFF
        lines = [tag(self.card_line(line, width), None, "card:line") for line in card.lines]
        box = None
        if card.figure is None:
            group = VGroup(title, *lines).arrange(DOWN, aligned_edge=LEFT, buff=0.35)
            group.move_to((0, 0.3, 0))
        elif card.layout == "right":  # the title on top, the figure on the left, the words right
            title.move_to((0, FIGURED_TITLE_Y, 0))
            column = VGroup(*lines).arrange(DOWN, aligned_edge=LEFT, buff=0.35)
            column.move_to((FIGURED_WORDS_X, -0.3, 0))
        else:  # the title on top, the row of pictures under it, a line under each
            title.move_to((0, FIGURED_TITLE_Y, 0))
            box = self._columns(lines)
        title.set_x(0)
        # the figure's parts, each with the words that say it (the title: the rest)
        parts = figure_steps.steps(figure_mobjects(card.figure, self.lecture_polygon(),
                                                   self.theme, box) if card.figure else [],
                                   card.lines)
        # the picture the pass before drew, moved into the figure's place (chapter 2)
        carried, self.carried = self.carried, None
        named = {getattr(m, "name", ""): m for m in parts[0]}
        shape, vertices = named.get("figure:polygon"), named.get("figure:vertices")
        cut = hand_over(self, carried, shape, list(vertices.submobjects), [vertices]) \
            if shape is not None and vertices is not None else []
        cue = captions.show(card.title, 0.8)  # the caption before is read in its own step
        self.mark_card_line(None, card)
        self.play(Write(title), *cut, *[FadeIn(m) for m in parts[0]
                                        if not cut or m not in (shape, vertices)],
                  run_time=0.8, **cue)
        shown: list[VMobject] = []  # the last figure's claims and crossed edges
        on: list = list(parts[0])  # the figure's parts on screen
        # the parts that give way to the next as a line comes (figure_steps.goes_with)
        leaving = figure_steps.leaving(parts, card.lines)
        for line, words, (claims, edges), said, gone in zip(
                lines, card.lines, self._line_claims(card), parts[1:], leaving, strict=True):
            drawn = [figure_steps.coming(m) for m in said]
            grown = max((seconds for _, seconds in drawn), default=0.0)
            cue = captions.show(words, max(0.5, grown))
            self.mark_card_line(words, card)
            # a rule's picture goes as the next one's comes (the recap's, on one polygon), and
            # a part goes with the line that names its goes_with word (the overview's)
            off = [*figure_steps.going(on, said), *gone]
            off = [m for k, m in enumerate(off) if all(m is not o for o in off[:k])]
            on = [*(m for m in on if all(m is not o for o in off)), *said]
            going = [*(FadeOut(m) for m in off), *([FadeOut(m) for m in shown] if claims else [])]
            coming = [*claims, *edges]
            usual = 0.5 if not coming else 1.0
            run_time = max(usual, grown)
            self.play(FadeIn(line, shift=UP * 0.1, rate_func=figure_steps.done_by(
                usual / run_time)), *going, *[Create(m) for m in coming],
                      *[anim for anim, _ in drawn], run_time=run_time, **cue)
            shown = [*(claims or shown), *edges]
        captions.hold()

    @staticmethod
    def _columns(lines: Sequence[VMobject]) -> tuple[tuple[float, float], float, float]:
        """Place a wide card's ``lines`` each under its own picture, their tops level, the
        tallest one's foot at :data:`WIDE_FOOT`. Returns the row of pictures' box."""
        (x, _), width, _ = WIDE_BOX
        each = width / max(1, len(lines))
        top = WIDE_FOOT + max((line.height for line in lines), default=0.0)
        for k, line in enumerate(lines):
            line.move_to((x - width / 2 + each * (k + 0.5), 0, 0)).align_to((0, top, 0), UP)
        height = WIDE_TOP - top - WIDE_GAP
        return ((x, WIDE_TOP - height / 2), width, height)

    def _line_claims(self, card: Card) -> list[tuple[list[VMobject], list[VMobject]]]:
        """Per line: the claims its figure brings (in place of the last figure's), and the
        crossed edges its words name. A crossed edge comes with the first line from its
        figure's on (before the next figure's) that names it, else with its claim: drawn
        with the claim, E–A was red 5.5 s before the caption said so (review s567)."""
        plan: list[tuple[list[VMobject], list[VMobject]]] = [([], []) for _ in card.lines]
        figures = [(k, f) for k, f in enumerate(card.line_figures[:len(card.lines)])
                   if f is not None]
        ends = [*(j for j, _ in figures[1:]), len(card.lines)][:len(figures)]
        for (k, figure), until in zip(figures, ends, strict=True):
            for m in figure_mobjects(figure, self.lecture_polygon(), self.theme):
                if isinstance(m, VMobject) and m.name == "figure:claim":
                    plan[k][0].append(m)
                elif isinstance(m, VMobject) and m.name.startswith("figure:edge:"):
                    edge = m.name.removeprefix("figure:edge:")
                    said = next((j for j in range(k, until) if edge in card.lines[j]), k)
                    plan[said][1].append(m)
        return plan

    def play_run(self, run: Run, log=None) -> None:
        """The run played as the metaphor scenes play it (``log``: its log, if already
        recorded), then a short pause."""
        log = log if log is not None else run.spec(self.lecture_polygon()).log()
        self.metaphor_box = run.box
        self.pacing = run.pacing
        self.speed = run.speed
        self.black_box = run.black_box
        self.play_log(log, run.title)
        self.wait(0.8)

    def play_hunted(self, hunted: Hunted) -> None:
        heuristic = load_user_heuristic(hunted.heuristic)
        found = hunt(heuristic, budget=hunted.budget, seed=hunted.seed,
                     general=hunted.general)
        if not found.found or found.polygon is None:
            raise ValueError(f"{heuristic.name}: no counterexample in {found.tried} polygons")
        polygon = found.polygon
        # the card tells what the computer did, not the command that did it (issue 22), and
        # the shrinking only where it took vertices away ("It shrank the first failure to 5
        # vertices" was said of a failure that had 5 already, and never explained)
        shrunk = (f"Then it took vertices away while the rule still failed: {polygon.n} are "
                  "left.",) if (found.first or 0) > polygon.n else ()
        self.play_card(Card(hunted.title, (
            f"{hunted.name}: {hunted.rule[:1].lower()}{hunted.rule[1:]}, a rule this lecture "
            "did not cover.",
            f"The computer tried {found.tried} small polygons, fewest vertices first, until "
            "the rule failed on one.", *shrunk), hunted.figure))
        # asked as an exercise (it was played as a run the class only watched, with "Distance
        # to C for D: 2.2" from coordinates it never saw): the answer draws what was measured
        log = record_user_run(heuristic, polygon, f"hunted (seed {hunted.seed})")
        claim = run_heuristic(polygon, heuristic)
        exercise = hunted_exercise(self.asked + 1, f"hunted (seed {hunted.seed})", polygon,
                                   hunted.name, claim.pair, hunted.why,
                                   measured_pairs(log, polygon.labels))
        self.clear_screen()
        self.ask(exercise, hunted.think)

    def play_analysis(self, analysis: Analysis) -> None:
        play_analysis(self, analysis, self.theme)

    def beats(self, log):
        return [replace(b, pace=b.pace * self.speed)
                for b in catalog.beats(log, self.pacing, black_box=self.black_box)]

    def play_compare(self, compare: Compare) -> None:
        polygon = read_polygon(compare.polygon or self.lecture_polygon())
        ours = triangulate(polygon, compare.ours).triangles
        sides = ((-3.6, spoken(compare.ours, start=True), ours),
                 (3.6, spoken("cdt", start=True), constrained_delaunay(polygon)))
        for x, name, triangles in sides:
            self.compare_side(polygon, x, name, triangles)
        note = tag(self.text(f"Both: {polygon.n - 2} triangles for {polygon.n} vertices — "
                             "different diagonals, both valid", self.theme.caption_size), None,
                   "compare:note")
        note.move_to((0, -3.55, 0))
        cue = captions_of(self).show(note.original_text, 0.5)
        mark_step(self, note.original_text, kind="compare")
        self.play(FadeIn(note), run_time=0.5, **cue)
        self.wait(compare.seconds)

    def compare_side(self, polygon, x: float, name: str,
                     triangles: Sequence[TriangleIndices]) -> None:
        """One side of the comparison: its name, P with its vertex labels (the note says the
        diagonals differ: the labels say which), then its triangles with their count under
        the name, as the caption says it (the count was said 6 s before any was shown)."""
        theme, captions = self.theme, captions_of(self)
        frame = Frame(polygon.points, (x, COMPARE_Y), 6.0, COMPARE_HEIGHT)
        outline = tag(polygon_mobject(polygon, frame, theme), "idle", f"compare:{name}")
        label = tag(self.text(name, theme.caption_size), None, "compare:name")
        label.move_to((x, 3.2, 0))
        count = tag(self.text(f"{len(triangles)} triangles", theme.caption_size, theme.result),
                    "result", "compare:count")
        count.move_to((x, COMPARE_COUNT_Y, 0))
        # over the triangles' fills, clear of their diagonals (the labels are placed first)
        markers = [tag(m, "idle", f"compare:vertex:{v}").set_z_index(1) for v, m in
                   measured_markers(polygon, (), frame, theme, inner_edges(polygon, triangles))]
        said = f"{name}: {len(triangles)} triangles"
        captions.hold()  # the caption before is read in its own step
        mark_step(self, said, kind="compare")
        self.play(FadeIn(label), Create(outline), *[FadeIn(m) for m in markers], run_time=0.6)
        # as every run's result is drawn: the result's green, neighbours in other shades
        pieces = triangulation_figure(polygon, triangles, frame, "compare:triangle", theme)
        self.play(*[FadeIn(p) for p in pieces], FadeIn(count), run_time=1.2,
                  **captions.show(said, 1.2))

    def play_quiz(self, quiz: Quiz) -> None:
        for exercise in make_exercises(quiz.count, quiz.seed):
            self.clear_screen()
            self.ask(exercise, quiz.think)

    def ask(self, exercise: Exercise, think: int) -> None:
        """The question, ``think`` seconds counted down to 0, then the answer with its reason
        beside the picture, up until the class has read it and checked it against the
        picture (:func:`story.exercises.checking_time`)."""
        picture = [tag(m, None, "exercise") for m in still_mobjects(exercise, self.theme,
                                                                     QUIZ_BOX)]
        captions = captions_of(self)
        cue = captions.show(exercise.question, 0.8)
        mark_step(self, exercise.question, kind="question")
        self.play(*[FadeIn(m) for m in picture], run_time=0.8, **cue)
        clock, seconds, time_up = countdown(think, COUNTDOWN_AT, self.theme)
        self.add(clock)
        for second in seconds:
            self.play(second)
        answer = f"{exercise.answer}: {exercise.reason}"
        cue = captions.show(answer, ANSWER_COMING)
        mark_step(self, answer, kind="answer")
        self.play(time_up(), *self.answer_animations(exercise, picture[MARKERS_AT]),
                  run_time=ANSWER_COMING, **cue)
        self.wait(whole_frames(checking_time(exercise, answer) - ANSWER_COMING))
        self.asked = exercise.number

    def answer_animations(self, exercise: Exercise, markers: VGroup) -> list:
        """The answer's text beside the picture, and on the picture what it says: a pick's
        vertex in green (its dot and its label, ``markers`` the picture's) with the
        metaphor's front reaching it; each diagonal named, green or red, a crossed edge red
        and named, T's part outside P red (:meth:`_outside`)."""
        theme, polygon = self.theme, exercise.polygon
        frame = Frame(polygon.points, *QUIZ_BOX)
        # a number keeps to the word before it: "25.5" stood alone on the answer's last line
        said = _NUMBER.sub("\u00a0", f"Answer: {exercise.answer} — {exercise.reason}")
        # a "no" in the red of what fails, never the green of "correct" (the hunted rule's
        # "no (it claims BE)" stood green, chapter 6 at 120 s)
        role = "rejected" if _SAYS_NO.match(exercise.answer) else "result"
        text = tag(typeset.wrapped(said, size=theme.caption_size, colour=theme.role_colour(role),
                                   font=theme.font, width=ANSWER_WIDTH), role, "answer")
        text.move_to(ANSWER_AT)
        anims: list[Animation] = [FadeIn(text)]
        # what the rule compared, under its claim: over the crossed edge it may run along (the
        # hunted rule's CD is edge C–D), thinner, so both read; the answer says "amber"
        for i, j in exercise.measured:
            anims.append(Create(tag(Line(frame.to_scene(polygon.points[i]),
                                         frame.to_scene(polygon.points[j]), color=theme.argument,
                                         stroke_width=theme.stroke * 1.2),
                                    "argument", "answer:measured").set_z_index(3)))
        if exercise.kind == "pick":
            anims += self._picked(exercise, frame, markers)
        rejected = []
        # the vertices over the red of T's part outside P (E's label stood on it, unread)
        markers.set_z_index(3)
        astray = self._astray(exercise)
        for i, j in exercise.options or self._claimed(exercise):
            verdict = is_inner_diagonal(polygon, i, j)
            colour = theme.result if verdict.ok else theme.rejected
            line = tag(Line(frame.to_scene(polygon.points[i]), frame.to_scene(polygon.points[j]),
                            color=colour, stroke_width=theme.stroke * 1.5),
                       "result" if verdict.ok else "rejected", "answer:diagonal").set_z_index(2)
            anims.append(Create(line))
            if not verdict.ok:
                rejected.append(line)
            anims += self._crossing(verdict, polygon, (i, j), frame, markers,
                                    [line, *self._rim(astray, frame)], astray)
        if rejected:
            anims += self._outside(astray, frame)
        return anims

    @staticmethod
    def _astray(exercise: Exercise):
        """T's part outside P (shapely, the polygon's coordinates)."""
        polygon = exercise.polygon
        t = shapely.Polygon([polygon.points[k] for k in exercise.triangle])
        return t.difference(shapely.Polygon(polygon.points))

    @staticmethod
    def _rim(area, frame: Frame) -> list[Line]:
        """The sides of a region as lines on screen, for a name to keep off: an edge's name
        stood on T's red part outside P, where it read as the red's own."""
        rims = [list(part.exterior.coords) for part in shapely.get_parts(area)
                if part.geom_type == "Polygon"]
        return [Line(frame.to_scene(a), frame.to_scene(b))
                for ring in rims for a, b in itertools.pairwise(ring)]

    def _outside(self, astray, frame: Frame) -> list[Animation]:
        """T's part outside P (``astray``) in the red of what fails, with its key: where a
        wrong claim goes (as chapter 2's analyses show it; T stood all blue in the answers,
        chapter 6 at 120 s, its part outside P unmarked)."""
        theme = self.theme
        area = region(_Sheet(frame, theme), astray, theme.rejected, OUTSIDE_OPACITY,
                      "answer:outside", "rejected").set_z_index(1)
        key = tag(typeset.text(f"red: {OUTSIDE}", font=theme.font, size=theme.label_size,
                               colour=theme.rejected), "rejected", "answer:key")
        key.move_to((ANSWER_AT[0], KEY_Y, 0))
        return [FadeIn(area), FadeIn(key)]

    def _picked(self, exercise: Exercise, frame: Frame, markers: VGroup) -> list[Animation]:
        """The pick in green, label and all (its label stayed amber beside a green dot), and
        the front that reached it first, in its metaphor's colour."""
        theme, polygon = self.theme, exercise.polygon
        pick = polygon.label_of(exercise.answer)
        at = frame.to_scene(polygon.points[pick])
        dot = tag(Dot(at, radius=0.13, color=theme.result), "result", "pick")
        colour = getattr(theme, _FRONT_COLOUR[exercise.heuristic or ""])
        fronts = [tag(VMobject(stroke_color=colour, stroke_width=theme.stroke * 1.5)
                      .set_points_as_corners(frame.many(line)), None, "answer:front")
                  for line in answer_front(exercise)]
        return [*[Create(f) for f in fronts], FadeIn(dot, scale=2.5),
                tag(markers[pick], "result").animate.set_color(theme.result)]

    def _crossing(self, verdict, polygon, pair: tuple[int, int], frame: Frame,
                  markers: VGroup, avoid: Sequence[Line], astray) -> list:
        """A rejected diagonal's crossed edges, thick in red and named beside them ("edge
        C–D", as chapter 2's analyses name it; the answer's text names them too:
        :func:`story.exercises.crossed_edges`), and a flash where each is crossed."""
        if verdict.edge is None:
            return []
        theme = self.theme
        anims: list[Animation] = []
        sheet = _Sheet(frame, theme, polygon, dict(enumerate(markers)))
        area = _on_screen(astray, frame)
        ring = [tuple(frame.to_scene(p)[:2]) for p in polygon.points]
        edges = shapely.LinearRing(ring)
        for (u, v), point in crossed_edges(polygon, *pair):
            edge = f"{polygon.labels[u]}–{polygon.labels[v]}"
            a, b = frame.to_scene(polygon.points[u]), frame.to_scene(polygon.points[v])
            name = tag(typeset.text(f"edge {edge}", font=theme.font, size=theme.label_size + 2,
                                    colour=theme.rejected), "rejected", "answer:edge-name")
            # on a dark halo, as the vertex labels: over an edge it must cross, it still reads
            name.set_stroke(theme.background, width=LABEL_HALO, background=True)
            place_name(cast(Stage, sheet), name, a, b, avoid)
            _off_the_red(name, a, b, area, edges)
            anims += [Create(crossed_edge(a, b, f"edge:{edge}", theme).set_z_index(2)),
                      FadeIn(name.set_z_index(4)),
                      Flash(frame.to_scene(point), color=theme.rejected, flash_radius=0.45)]
        return anims

    @staticmethod
    def _claimed(exercise: Exercise) -> tuple[tuple[int, int], ...]:
        if exercise.claim is not None:  # a rule of one's own: its claim as the hunt ran it
            return (exercise.claim,)
        if exercise.kind == "claim" and exercise.heuristic:
            return (find_diagonal(exercise.polygon, exercise.heuristic).pair,)
        return ()
