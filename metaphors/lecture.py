"""The lecture: seven chapters in the Forišek–Steinová structure, each its own scene file.

A chapter is a list of segments (plain data): a card of text, a run of an algorithm
played by the metaphor scenes, the reference triangulation beside ours, or an exercise
(question, a pause with a countdown, the answer animated). :class:`LectureScene` plays a
chapter's segments as one Manim section; ``trex lecture`` renders the chapters (in
parallel) and joins them.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from manim import DOWN, LEFT, UP, Create, Dot, FadeIn, FadeOut, Line, VGroup, Write

from geometry.cdt import constrained_delaunay
from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from geometry.polygon import Polygon
from geometry.samples import make_sample
from geometry.triangulate import triangulate
from metaphors import catalog
from metaphors.drawing import Frame, polygon_mobject, triangle_mobject
from metaphors.layout import METAPHOR, Box
from metaphors.scene import TraceScene
from metaphors.stills import BOX_CENTER, BOX_HEIGHT, BOX_WIDTH, still_mobjects
from metaphors.tags import tag
from rendering import typeset
from rendering.typeset import FlatText
from story.exercises import Exercise, make_exercises
from story.registry import entry
from story.runs import run_logged
from story.spec import RunSpec
from story.storyboard import Pacing

FRUIT_BOX = Box(-3.45, 0.8, 5.6, 3.9)  # room for the plate below the fruit
DEFAULT_PACING = Pacing(full=2, fast=0.35)


@dataclass(frozen=True)
class Chapter:
    """One chapter: its own scene file and class, and its place in the lecture."""

    number: int
    slug: str
    title: str
    scene_file: str
    scene_class: str


@dataclass(frozen=True)
class Card:
    """A title and a few lines of text, shown for ``seconds``."""

    title: str
    lines: tuple[str, ...] = ()
    seconds: float = 5.0


@dataclass(frozen=True)
class Run:
    """An algorithm run on a polygon, played by the metaphor scenes.

    ``polygon`` None: the lecture's polygon (:meth:`LectureScene.lecture_polygon`).
    """

    algorithm: str
    polygon: str | None
    title: str
    heuristic: str | None = None
    box: Box = METAPHOR
    pacing: Pacing = DEFAULT_PACING
    speed: float = 0.8  # × every beat's run time

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
class Quiz:
    """Exercises from :func:`story.exercises.make_exercises`: ask, count down, answer."""

    count: int = 3
    seed: int = 2022
    think: int = 3  # seconds of countdown


def working_example(heuristic: str, n: int = 9, tries: int = 500) -> str:
    """A seeded random polygon where a wrong heuristic happens to claim an inner diagonal,
    with at least two candidates in T so the choice matters (deterministic search).

    >>> working_example("scaling")
    'random-2opt:9:3'
    """
    for seed in range(tries):
        spec = f"random-2opt:{n}:{seed}"
        polygon = Polygon.from_points(make_sample("random-2opt", n, seed))
        log = run_logged(heuristic, spec)
        candidates = next((e.result for e in log.events
                           if e.kind == "return" and e.name == "candidates_in_triangle"), [])
        if len(candidates or []) >= 2 and is_inner_diagonal(
                polygon, *find_diagonal(polygon, heuristic).pair):
            return spec
    raise LookupError(f"no polygon among {tries} seeds where {heuristic} works")


class LectureScene(TraceScene):
    """Plays one chapter: its segments in order, as one Manim section."""

    chapter_title = "Chapter"
    slug = "overview"
    polygon = "lecture"  # the lecture's polygon, unless one is handed (trex lecture --polygon)

    def chapter_segments(self) -> tuple:
        return SEGMENTS[self.slug]()

    def lecture_polygon(self) -> str:
        """The polygon of the runs that name none: the handed one, else ``TREX_POLYGON``
        (plain ``manim``), else the ``lecture`` sample."""
        return self.run_spec().polygon

    def construct(self) -> None:
        self.camera.background_color = self.theme.background
        self.next_section(self.chapter_title)
        for segment in self.chapter_segments():
            self.clear_screen()
            getattr(self, f"play_{type(segment).__name__.lower()}")(segment)
        self.clear_screen()
        self.wait(0.5)

    def clear_screen(self) -> None:
        if self.mobjects:
            self.play(*[FadeOut(m) for m in self.mobjects], run_time=0.4)
            self.clear()

    def text(self, text: str, size: int, colour: str | None = None) -> FlatText:
        return typeset.text(text, font=self.theme.font, size=size,
                            colour=colour or self.theme.ink, width=13.2)

    # --- segments ---------------------------------------------------------------------------------

    def play_card(self, card: Card) -> None:
        title = tag(typeset.glyphs(card.title, font=self.theme.font, size=self.theme.title_size,
                                   colour=self.theme.ink, width=13.2), None, "card:title")
        lines = [tag(self.text("• " + line, self.theme.caption_size, self.theme.idle), None,
                     "card:line") for line in card.lines]
        group = VGroup(title, *lines).arrange(DOWN, aligned_edge=LEFT, buff=0.35)
        group.move_to((0, 0.3, 0))
        title.set_x(0)
        caption = card.title + (": " + " ".join(card.lines) if card.lines else "")
        self.play(Write(title), run_time=0.8, subcaption=caption,
                  subcaption_duration=card.seconds)
        for line in lines:
            self.play(FadeIn(line, shift=UP * 0.1), run_time=0.5)
        self.wait(max(0.5, card.seconds - 0.8 - 0.5 * len(lines)))

    def play_run(self, run: Run) -> None:
        log = run.spec(self.lecture_polygon()).log()
        self.metaphor_box = run.box
        self.pacing = run.pacing
        self.speed = run.speed
        self.play_log(log, run.title)
        self.wait(0.8)

    def beats(self, log):
        return [replace(b, pace=b.pace * self.speed) for b in catalog.beats(log, self.pacing)]

    def play_compare(self, compare: Compare) -> None:
        polygon = read_polygon(compare.polygon or self.lecture_polygon())
        ours = triangulate(polygon, compare.ours).triangles
        sides = ((-3.6, compare.ours, ours), (3.6, "constrained Delaunay (shapely)",
                                              constrained_delaunay(polygon)))
        theme = self.theme
        for x, name, triangles in sides:
            frame = Frame(polygon.points, (x, -0.2), 6.0, 5.2)
            outline = tag(polygon_mobject(polygon, frame, theme), "idle", f"compare:{name}")
            label = tag(self.text(name, theme.caption_size), None, "compare:name")
            label.move_to((x, 3.2, 0))
            self.play(FadeIn(label), Create(outline), run_time=0.6)
            pieces = [tag(triangle_mobject(polygon, t, frame, theme.pieces[k % len(theme.pieces)],
                                           theme), None, "compare:triangle")
                      for k, t in enumerate(triangles)]
            self.play(*[FadeIn(p) for p in pieces], run_time=1.2,
                      subcaption=f"{name}: {len(triangles)} triangles")
        note = tag(self.text(f"Both: {polygon.n - 2} triangles for {polygon.n} vertices — "
                             "different diagonals, both valid", theme.caption_size), None,
                   "compare:note")
        note.move_to((0, -3.55, 0))
        self.play(FadeIn(note), run_time=0.5, subcaption=note.original_text)
        self.wait(compare.seconds)

    def play_quiz(self, quiz: Quiz) -> None:
        for exercise in make_exercises(quiz.count, quiz.seed):
            self.clear_screen()
            self.ask(exercise, quiz.think)

    def ask(self, exercise: Exercise, think: int) -> None:
        """The question, a countdown, the answer with its reason."""
        theme = self.theme
        picture = [tag(m, None, "exercise") for m in still_mobjects(exercise, theme)]
        self.play(*[FadeIn(m) for m in picture], run_time=0.8, subcaption=exercise.question)
        for k in range(think, 0, -1):
            digit = tag(self.text(str(k), 60, theme.argument), None, "countdown")
            digit.move_to((6.3, 2.7, 0))
            self.play(FadeIn(digit), run_time=0.2)
            self.wait(0.6)
            self.play(FadeOut(digit), run_time=0.2)
        self.play(*self.answer_animations(exercise), run_time=1.2,
                  subcaption=f"{exercise.answer}: {exercise.reason}")
        self.wait(3.0)

    def answer_animations(self, exercise: Exercise) -> list:
        theme, polygon = self.theme, exercise.polygon
        frame = Frame(polygon.points, BOX_CENTER, BOX_WIDTH, BOX_HEIGHT)
        text = tag(self.text(f"Answer: {exercise.answer} — {exercise.reason}", 24,
                             theme.result), "result", "answer")
        text.move_to((0, -3.05, 0))
        anims = [FadeIn(text)]
        if exercise.kind == "pick":
            label = exercise.answer.strip().split()[0]
            if label in polygon.labels:
                at = frame.to_scene(polygon.points[polygon.label_of(label)])
                dot = tag(Dot(at, radius=0.13, color=theme.result), "result", "pick")
                anims.append(FadeIn(dot, scale=2.5))
        for i, j in exercise.options or self._claimed(exercise):
            ok = bool(is_inner_diagonal(polygon, i, j))
            colour = theme.result if ok else theme.rejected
            anims.append(Create(tag(Line(frame.to_scene(polygon.points[i]),
                                         frame.to_scene(polygon.points[j]), color=colour,
                                         stroke_width=theme.stroke * 1.5),
                                    "result" if ok else "rejected", "answer:diagonal")))
        return anims

    @staticmethod
    def _claimed(exercise: Exercise) -> tuple[tuple[int, int], ...]:
        if exercise.kind == "claim" and exercise.heuristic:
            return (find_diagonal(exercise.polygon, exercise.heuristic).pair,)
        return ()


# --- the chapters ---------------------------------------------------------------------------------

#: The wrong heuristic of each metaphor, told in three cards: the metaphor, why it fails, and
#: why its correction (the registry's) holds. The family is named after the metaphor.
FAMILIES = (
    ("scaling",
     ("Spill water at B: it spreads as a growing circle.",
      "The first candidate it wets is D, the nearest one."),
     ("The circle grows through the walls of the polygon:",
      "it wets D from outside, before any water could get there from inside.",
      "The edge E–A lies between B and D."),
     ("Go backwards: let water rise from the shore AC towards B.",
      "The last dry candidate is the farthest from AC — always an inner diagonal:",
      "below that level nothing blocks the way from B.")),
    ("rotation",
     ("Put a clock at B, set the hand to A and let it turn towards C.",
      "The first candidate the hand passes is D."),
     ("Part of the hand lies outside the polygon when it passes D:",
      "that outside part hits D first. The hand is not inside T all the time."),
     ("Move the clock to C and set it to B.",
      "Before any part of the hand inside T leaves the polygon, it must pass a vertex:",
      "the first one forms an inner diagonal with B.")),
    ("translation",
     ("Sweep a vertical line from B to the right.",
      "The first candidate it touches is D, the left-most."),
     ("The vertical line leaves the polygon at A's side before it reaches D:",
      "the part outside the polygon touches D first."),
     ("Sweep a line parallel to AC instead.",
      "It reaches A and C at the same moment it leaves T,",
      "so the first vertex it touches is a candidate, seen from inside.")),
)


def family_segments(family: tuple) -> tuple:
    wrong, metaphor, analysis, correction = family
    known = entry(wrong)
    if known.correct or known.correction is None:
        raise ValueError(f"{wrong} is no wrong heuristic with a correction")
    name, right = known.metaphor.capitalize(), known.correction
    return (
        Card(f"{name}: the metaphor", metaphor),
        Run(wrong, working_example(wrong), f"{wrong} on a polygon where it happens to work"),
        Run(wrong, "counterexample", f"{wrong} on the counterexample"),
        Card(f"{name}: why it fails", analysis),
        Run(right, "counterexample", f"{right}: the correction"),
        Card(f"{name}: why the correction holds", correction),
    )


CHAPTERS = tuple(
    Chapter(k, slug, title, f"scenes/chapters/ch{k}_{slug}.py", cls)
    for k, (slug, title, cls) in enumerate(
        (
            ("overview", "Overview", "Overview"),
            ("heuristics", "Inner diagonals: water, clock, sweep", "Heuristics"),
            ("gravity", "Gravity", "Gravity"),
            ("ears", "Ears", "Ears"),
            ("faster", "Faster algorithms", "Faster"),
            ("experience", "Experience", "Experience"),
            ("exercises", "Exercises", "Exercises"),
        ),
        start=1,
    )
)


def overview() -> tuple:
    return (
        Card("Triangulating a simple polygon", (
            "A simple polygon: its edges meet only where neighbours share a vertex.",
            "A diagonal joins two vertices; an inner diagonal lies inside the polygon.",
            "Every simple polygon with n vertices splits into exactly n − 2 triangles.")),
        Card("Lennes, 1911: divide and conquer", (
            "Find an inner diagonal, split the polygon along it, repeat on both halves.",
            "Everything hinges on one question: how do we find an inner diagonal?")),
        Run("divide-and-conquer", None, "Lennes' divide and conquer (diagonals by gravity)",
            heuristic="gravity", speed=0.6),
    )


def heuristics() -> tuple:
    frame = Card("The frame every heuristic shares", (
        "B: the left-most vertex (lowest on ties) — always convex.",
        "A and C: its neighbours; T = triangle ABC.",
        "No other vertex in T: AC is an inner diagonal. Otherwise pick a candidate D: is BD?"))
    return (frame, *[s for family in FAMILIES for s in family_segments(family)])


def gravity() -> tuple:
    return (
        Card("Gravity (Forišek and Steinová)", (
            "Hang a ball on a rubber band at a reflex vertex V.",
            "Turn the polygon so that both edges at V point up, and let the ball drop.",
            "It hits an edge and slides down to a vertex X; the band may snag a vertex Y first.")),
        Run("gravity", "gravity-snag", "Gravity: the band snags a vertex"),
        Card("Why the band is always right", (
            "The band stays inside the polygon the whole time:",
            "the first vertex it touches is seen from V through the inside.",
            "So VY — or VX when the band stays straight — is an inner diagonal.")),
        Run("gravity", "counterexample", "Gravity on the counterexample"),
    )


def ears() -> tuple:
    return (
        Card("Ears: slicing fruit", (
            "An ear: three consecutive vertices whose triangle holds no other vertex.",
            "Slice an ear off, put it on the plate, repeat until one triangle is left.")),
        Run("ear-clipping-naive", None, "Ear clipping (Meisters): slice the first ear found",
            box=FRUIT_BOX, speed=0.6),
        Card("The two-ears theorem (Meisters, 1975)", (
            "Every simple polygon with more than three vertices has two ears",
            "that do not overlap — so there is always a slice to cut.",
            "Testing every vertex: O(n²) for one ear, O(n³) for all.")),
        Card("Prune and search (ElGindy, Everett, Toussaint)", (
            "Test the middle vertex of a good sub-polygon (one cut edge).",
            "Not an ear? Its diagonal cuts off a smaller good sub-polygon — keep that half.",
            "About half the vertices go each time: one ear in O(n).")),
        Run("prune-and-search", None, "Prune and search: the good sub-polygons shrink",
            box=FRUIT_BOX, speed=0.5),
        Card("How fast", (
            "Ear clipping, naive: O(n³). With ear status kept up to date: O(n²).",
            "Finding one ear by prune and search: O(n); clipping them all: O(n²).")),
    )


def faster() -> tuple:
    return (
        Card("Garey, Johnson, Preparata, Tarjan (1978)", (
            "Sweep a horizontal line downwards; classify each vertex.",
            "Diagonals at split and merge vertices cut the polygon into y-monotone pieces.",
            "A stack triangulates each piece in linear time: O(n log n) in all.")),
        Run("monotone", None, "Monotone partition, then the stack", speed=0.7),
        Card("Tarjan and van Wyk (1988)", (
            "O(n log log n), with finger trees and Jordan sorting;",
            "Kirkpatrick, Klawe and Tarjan matched it with simple data structures (1990).")),
        Card("Chazelle (1991)", (
            "Linear time: O(n). Correct, celebrated — and famously hard to implement.",
            "No implementation is known to be practical.")),
        Card("Constrained Delaunay", (
            "Delaunay triangulation of the vertices, keeping the polygon's edges:",
            "the reference triangulation libraries use (here: shapely / GEOS).")),
        Compare(None),
    )


def experience() -> tuple:
    return (
        Card("Teaching notes: the wrong heuristics first", (
            "Let students propose a way to find D before showing any.",
            "Almost everyone proposes the nearest or the left-most vertex.",
            "The counterexample needs only five vertices: draw it on the board.")),
        Card("Teaching notes: metaphors", (
            "Water, a clock, a sweeping line: each wrong heuristic is a familiar motion.",
            "Ask where the motion leaves the polygon — that is the bug.",
            "The corrections keep the motion inside T and inside the polygon.")),
        Card("Teaching notes: from metaphor to proof", (
            "Kinesthetic heuristics are fast to invent and easy to get wrong.",
            "Ask for the invariant: what does the water, hand or line never cross?",
            "Then write the proof with that invariant.")),
    )


def exercises() -> tuple:
    return (
        Card("Exercises", (
            "Each question shows a polygon and its triangle T.",
            "Answer before the countdown ends; the answer is checked by the geometry code.")),
        Quiz(count=3, seed=2022),
    )


SEGMENTS = {
    "overview": overview,
    "heuristics": heuristics,
    "gravity": gravity,
    "ears": ears,
    "faster": faster,
    "experience": experience,
    "exercises": exercises,
}
