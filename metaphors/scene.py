"""The Scene every video derives from: a function of (log, theme, pacing).

A subclass names its algorithm, default polygon and title; ``construct`` gets the log of
its run (:class:`story.spec.RunSpec`: a live run, or a saved log), turns it into beats and
plays them on a board. The scene never re-decides what the algorithm decided.

The run is handed to the scene class as data: ``Scaling.handed(polygon="star")`` (or
``with_spec(spec)``) is a subclass carrying its ``spec``; ``trex`` and the tests play
those. What the panel shows is the class attribute ``panel``: the run's pseudocode
(``"pseudocode"``, the default; the source when the run has none) or the real source
(``"source"``); ``Scaling.with_panel("source")`` is a subclass showing the source. A scene handed nothing (``manim -pql scenes/scaling.py``) plays its default run,
with ``TREX_POLYGON`` and ``TREX_LOG`` from the environment (:mod:`story.environment`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from types import MappingProxyType
from typing import Self, TypeVar, cast

from manim import Camera, FadeOut, Scene, config
from manim.constants import RendererType

from metaphors import catalog
from metaphors.board import Board
from metaphors.layout import METAPHOR, TITLE_Y
from metaphors.play import TITLE_WIDTH, board_for, go_on, play_beats
from metaphors.recorded import Recorded, captions_of, lead_in, mark_step
from metaphors.tags import tag
from metaphors.theme import THEME
from rendering.camera import PathCamera
from rendering.renderer import BackdropRenderer
from rendering.typeset import glyphs
from story.beats import Beat, Note, ShowPolygon
from story.environment import spec_from_environment, specs_from_environment
from story.pseudocode import PANELS, PSEUDOCODE
from story.reading import frame_key, frame_summarised
from story.registry import heuristics, spoken
from story.sequence import framed_again, going_on, in_its_name
from story.spec import RunSpec
from story.storyboard import Pacing
from tracing import Log
from usercode.heuristic import UserHeuristic, as_heuristic, load_user_heuristic
from usercode.loading import is_user_spec, load_attribute

T = TypeVar("T")


def _subclass(cls: type[T], **attributes) -> type[T]:
    """A subclass of ``cls`` with the same name (manim names its files after it) carrying
    ``attributes``."""
    made = type(cls.__name__, (cls,), {"__module__": cls.__module__,
                                       "__qualname__": cls.__qualname__,
                                       "__doc__": cls.__doc__, **attributes})
    return cast("type[T]", made)  # a subclass of cls


class SpecScene:
    """Mixed into a Scene that plays one run: its default run (the class attributes
    ``algorithm``, ``polygon``, ``heuristic``) and the run it was handed (``spec``)."""

    algorithm: str
    polygon: str
    heuristic: str | None = None
    #: the run handed to the class (None: the default run, as the environment says)
    spec: RunSpec | None = None

    @classmethod
    def default_spec(cls) -> RunSpec:
        """The run the class names: its algorithm on its default polygon."""
        return RunSpec(cls.algorithm, cls.polygon, heuristic=cls.heuristic)

    @classmethod
    def with_spec(cls, spec: RunSpec) -> type[Self]:
        """This scene, handed ``spec``: it reads no environment."""
        return _subclass(cls, spec=spec)

    @classmethod
    def handed(cls, polygon: str | None = None, saved: Sequence[str] = ()) -> type[Self]:
        """This scene handed its default run, on ``polygon`` if given, or replaying the one
        saved log in ``saved``."""
        spec = cls.default_spec() if polygon is None else cls.default_spec().on(polygon)
        if len(saved) > 1:
            raise ValueError(f"{len(saved)} saved logs handed; {cls.__name__} plays one run")
        if saved:
            spec = spec.replaying(saved[0])
        return cls.with_spec(spec)

    @classmethod
    def from_environment(cls) -> type[Self]:
        """This scene handed what ``manim`` would give it: its default run with
        ``TREX_POLYGON`` and ``TREX_LOG``. Raises ValueError for a TREX_LOG it cannot play."""
        return cls.with_spec(spec_from_environment(cls.default_spec()))

    def run_spec(self) -> RunSpec:
        """The run this scene plays: the one handed, else the default as the environment
        says."""
        return self.spec if self.spec is not None else spec_from_environment(self.default_spec())


class TraceScene(SpecScene, Recorded, Scene):
    """Plays the log of one algorithm run."""

    camera: Camera  # Cairo's: this project renders with Cairo only (not OpenGLCamera)

    algorithm = "scaling"
    heuristic: str | None = None
    polygon = "counterexample"
    title = "Scaling: the nearest candidate"
    theme = THEME
    pacing = Pacing()
    metaphor_box = METAPHOR  # where the metaphor's polygon goes (left half by default)
    #: what the panel shows: the run's pseudocode (the source when it has none) or "source"
    panel = PSEUDOCODE
    #: whether the panel's call line shows each step's real call (``nearest_to(B, [D, E]) →
    #: D``): a programmer wants it; the lecture, which shows no code, turns it off
    call_line = True
    #: whether the run's last picture is kept as it is (turned, its ball and band): the
    #: lecture's analysis goes on from it (:attr:`metaphors.analysis.Analysis.on_run`)
    keep_end = False
    #: whether divide and conquer's heuristic is a black box: each diagonal is asked for and
    #: comes out, none of the heuristic's steps shown (the overview, before any is taught)
    black_box = False

    def __init__(self, renderer=None, **kwargs):
        if renderer is None and config.renderer == RendererType.CAIRO:
            renderer = BackdropRenderer(camera_class=kwargs.get("camera_class", PathCamera),
                                        skip_animations=kwargs.get("skip_animations", False))
        super().__init__(renderer=renderer, **kwargs)

    @classmethod
    def with_heuristic(cls, heuristic: str) -> type[Self]:
        """This scene with divide and conquer's diagonals found by ``heuristic``: a built-in's
        name, or ``file.py:function`` of one's own (loaded now, so that a bad spec is one
        line: :class:`usercode.errors.UserHeuristicError`). The run goes on to its
        first wrong claim; the title names the heuristic. Raises ValueError for a scene whose
        run takes no heuristic, or an unknown name."""
        if cls.heuristic is None:
            raise ValueError(f"{cls.__name__} plays {cls.algorithm}, which takes no heuristic")
        if is_user_spec(heuristic):
            name = load_user_heuristic(heuristic).name
        elif heuristic in heuristics():
            name = heuristic
        else:
            raise ValueError(f"unknown heuristic {heuristic!r}; expected one of "
                             f"{', '.join(heuristics())}, or FILE.py:FUNCTION of your own")
        # the title names the heuristic as the screen says it (story.registry.SPOKEN)
        was, said = spoken(cls.heuristic), spoken(name)
        title = (cls.title.replace(was, said) if was in cls.title
                 else f"{cls.title} (heuristic: {said})")
        return _subclass(cls, heuristic=heuristic, title=title)

    @classmethod
    def with_panel(cls, panel: str) -> type[Self]:
        """This scene with its panel showing ``panel`` (one of
        :data:`story.pseudocode.PANELS`). Raises ValueError for another value."""
        if panel not in PANELS:
            raise ValueError(f"unknown panel {panel!r}; expected one of {', '.join(PANELS)}")
        return _subclass(cls, panel=panel)

    def log(self) -> Log:
        return self.run_spec().log()

    def construct(self) -> None:
        self.camera.background_color = self.theme.background  # type: ignore[assignment]  # manim's setter is typed ManimColor, and parses any colour
        self.play_log(self.log(), self.title)
        self.wait(1.0)
        captions_of(self).finish()  # the last cue lasts as long as its caption is shown

    def beats(self, log) -> list[Beat]:
        return catalog.beats(log, self.pacing, black_box=self.black_box)

    def play_log(self, log, title: str) -> Board:
        """Turn one log into beats and play them on a fresh board (both kept, as
        ``played_beats`` and ``played_board``, for tests)."""
        beats = self.beats(log)
        # the frame the run just before showed too (same polygon, T, candidates): one
        # caption. Only the last one shown is "as before": a frame shown two runs ago, with
        # another between, is no longer what the viewer just saw (the counterexample scene
        # said "The frame as before" as the mirror image gave way to the polygon)
        key, seen = frame_key(beats), self.frames_seen
        self.played_beats = frame_summarised(beats) if key is not None and key in seen else beats
        if key is not None:
            seen.clear()
            seen.add(key)
        self.played_board = board_for(self, log, self.played_beats, title, self.theme)
        return play_beats(self.played_board, self.played_beats)


class SequenceScene(TraceScene):
    """Plays several runs one after another, as a teacher would show them: its point said
    first, over its first polygon; the runs on one polygon on one board, each going on from
    the one before (a correction after the rule it mends: the polygon not drawn again, T and
    the candidates said once, the claim and the verdict in the rule's name); a later polygon
    on a board of its own; its ending said over the last picture. No card on black: each
    run's title stands over its picture (a card of 34–48 characters up 0.8 s could not be
    read).

    ``runs`` lists (algorithm, polygon, title). The runs name their own polygons: a handed
    polygon, or ``TREX_POLYGON``, is not played; ``specs`` (or ``TREX_LOG``, one saved log per
    run joined with ``os.pathsep``: ``a.json:b.json:…``) may replay saved logs instead.
    ``pictures`` names each polygon the runs play on, in order, with what is said as it is
    drawn (the first: the scene's point, ``{n}`` its vertices); ``title`` stands over the
    first polygon while its point is said; ``ending`` is said last.
    """

    runs: tuple[tuple[str, str, str], ...] = ()
    #: the runs handed to the class, one per run (None: the defaults, as the environment says)
    specs: tuple[RunSpec, ...] | None = None
    #: each polygon the runs play on, in order: its name (the runs on it go on "on the same
    #: polygon") and what is said as it is drawn; a polygon past these is "polygon", unsaid
    pictures: tuple[tuple[str, str], ...] = ()
    #: said over the last picture, at the end ("" nothing)
    ending: str = ""
    #: × run time of each beat action: the set-up every run repeats goes quickly; the tools
    #: move at their own pace, the whole of their caption's time (the water covered T in
    #: 0.8 s, then the picture stood still 2.5 s under its caption)
    paces = MappingProxyType({"polygon": 0.15, "pick": 0.15, "triangle": 0.2, "candidates": 0.2,
                              "claim": 0.3, "verdict": 0.55})
    pace = 1.0

    def beats(self, log) -> list[Beat]:
        return [replace(b, pace=self.paces.get(b.action, self.pace)) for b in catalog.beats(log)]

    @classmethod
    def default_specs(cls) -> tuple[RunSpec, ...]:
        """The runs the class names, live."""
        return tuple(RunSpec(algorithm, polygon) for algorithm, polygon, _ in cls.runs)

    @classmethod
    def with_specs(cls, specs: Sequence[RunSpec]) -> type[Self]:
        """This scene, handed one spec per run: it reads no environment."""
        if len(specs) != len(cls.runs):
            raise ValueError(f"{len(specs)} runs handed; {cls.__name__} plays {len(cls.runs)}")
        return _subclass(cls, specs=tuple(specs))

    @classmethod
    def handed(cls, polygon: str | None = None, saved: Sequence[str] = ()) -> type[Self]:
        """This scene handed its runs, live (``polygon`` is ignored: the runs name their
        own), or replaying ``saved``, one log per run."""
        specs = cls.default_specs()
        if saved:
            if len(saved) != len(specs):
                raise ValueError(f"{len(saved)} saved logs handed; {cls.__name__} plays "
                                 f"{len(specs)} runs")
            specs = tuple(s.replaying(path) for s, path in zip(specs, saved, strict=True))
        return cls.with_specs(specs)

    @classmethod
    def from_environment(cls) -> type[Self]:
        """This scene handed what ``manim`` would give it: ``TREX_LOG``'s logs, if any."""
        return cls.with_specs(specs_from_environment(cls.default_specs()))

    def run_specs(self) -> tuple[RunSpec, ...]:
        """The runs this scene plays: those handed, else the defaults as the environment
        says."""
        if self.specs is not None:
            return self.specs
        return specs_from_environment(self.default_specs())

    def logs(self) -> list[Log]:
        return [spec.log() for spec in self.run_specs()]

    def construct(self) -> None:
        self.camera.background_color = self.theme.background  # type: ignore[assignment]  # manim's setter is typed ManimColor, and parses any colour
        runs = [self.beats(log) for log in self.logs()]
        boards = boards_of(runs)
        said: set[str] = set()
        board: Board | None = None
        for k, (log, beats, (algorithm, _, title)) in enumerate(
                zip(self.logs(), runs, self.runs, strict=True)):
            picture, opening = self._picture(boards[k])
            name = spoken(algorithm, start=True)
            captions_of(self).finish()  # the caption on screen is read in its own step
            lead_in(self)  # what clears the last run opens this run's first step
            if board is not None and boards[k] == boards[k - 1]:
                self.play(*go_on(board, self, log, title), run_time=0.4)
                beats = going_on(beats, name, picture)
            else:
                if self.mobjects:
                    self.play(*[FadeOut(m) for m in self.mobjects], run_time=0.3)
                    self.clear()
                later = [runs[j] for j in range(k + 1, len(runs)) if boards[j] == boards[k]]
                first = boards[k] == 0 and self.title != title
                board = board_for(self, log, beats, self.title if first else title,
                                  self.theme, later=later)
                beats = self._opening(beats, boards[k], picture, opening)
                if first:  # the scene's title over its point, then the run's own
                    beats = self._retitled(board, beats, title)
            beats = in_its_name(beats, name, said)
            self.played_beats, self.played_board = beats, board
            play_beats(board, beats)
        if board is not None and self.ending:
            self._end(board)
        captions_of(self).finish()  # the last cue lasts as long as its caption is shown

    def _picture(self, board: int) -> tuple[str, str]:
        """The name of the ``board``-th polygon and what is said as it is drawn."""
        if board < len(self.pictures):
            return self.pictures[board]
        return "polygon", ""

    def _opening(self, beats: list[Beat], board: int, picture: str, opening: str) -> list[Beat]:
        """The first run's beats on a board: the polygon drawn under what the scene says of
        it (its point, for the first: ``{n}`` its vertices); on a later board, B, T and the
        candidates under one caption, as said of the polygon before."""
        shown = next((b for b in beats if isinstance(b, ShowPolygon)), None)
        words = opening.format(n=len(shown.labels) if shown else 0)
        if board > 0:
            return framed_again(beats, picture, words or f"The {picture}")
        return [replace(b, caption=words) if isinstance(b, ShowPolygon) and words else b
                for b in beats]

    def _retitled(self, board: Board, beats: list[Beat], title: str) -> list[Beat]:
        """The beats after the polygon's played under the run's own title: the scene's
        goes with the first of them and the run's comes with its words (two titles never
        fade through each other: the scene's goes in a play of its own)."""
        first, rest = beats[:1], beats[1:]
        play_beats(board, first)
        self.play(FadeOut(board.title), run_time=0.3)
        board.title = tag(glyphs(title, font=self.theme.font, size=30, colour=self.theme.ink),
                          None, "title").move_to((0, TITLE_Y, 0))
        if board.title.width > TITLE_WIDTH:
            board.title.scale_to_fit_width(TITLE_WIDTH)
        board.arriving.append(board.title)
        return rest

    def _end(self, board: Board) -> None:
        """The scene's ending, said over its last picture as it stands: its claim's ends keep
        their colour (back in the ink, B and D stood white under the green BD it ended on)."""
        last = self.played_beats[-1] if self.played_beats else None
        note = Note(caption=self.ending, seq=(last.seq + 1) if last else 0,
                    row=last.row if last else None, pace=1.5,
                    roles=dict(last.roles) if last else {})
        mark_step(self, note.caption, None, note.action)  # a step of its own: a slide too
        board.play(note)
        board.close()


def boards_of(runs: Sequence[Sequence[Beat]]) -> list[int]:
    """For each run, the board it plays on, counted from 0: a run on the polygon of the run
    before goes on on its board (its first beat draws the same points and labels).

    >>> from story.beats import ShowPolygon as P
    >>> square, twin = P(caption="a", seq=0, points=((0, 0), (1, 0)), labels=("A", "B")), P(caption="b", seq=0, points=((0, 1), (1, 0)), labels=("A", "B"))
    >>> boards_of([[square], [square], [twin], [twin], [square]])
    [0, 0, 1, 1, 2]
    """
    boards: list[int] = []
    for k, beats in enumerate(runs):
        same = k > 0 and _polygon_of(beats) == _polygon_of(runs[k - 1])
        boards.append(boards[-1] if same else (boards[-1] + 1 if boards else 0))
    return boards


def _polygon_of(beats: Sequence[Beat]) -> tuple | None:
    shown = next((b for b in beats if isinstance(b, ShowPolygon)), None)
    return None if shown is None else (tuple(map(tuple, shown.points)), tuple(shown.labels))


# --- the scene of a heuristic of one's own -------------------------------------------------------


def scene_for_heuristic(spec: str) -> type[Scene]:
    """The Scene class for ``path/to/file.py:name``.

    If ``name`` is a Scene class defined in the file, that class; otherwise ``name`` is a
    heuristic of one's own (see :mod:`usercode.heuristic`), loaded now so that a bad
    spec fails here, and the class plays its run on the polygon it is handed (plain
    ``manim``: ``TREX_POLYGON``; default: the counterexample) with the user's source in the
    panel. Raises
    :class:`usercode.errors.UserHeuristicError` (a ValueError, one-line message).
    """
    path, name, value = load_attribute(spec)
    if isinstance(value, type) and issubclass(value, Scene):
        return value
    return heuristic_scene(as_heuristic(spec, path, name, value))


def heuristic_scene(heuristic: UserHeuristic) -> type[Scene]:
    """A TraceScene subclass that plays a loaded user heuristic's run."""
    return type(f"Heuristic_{heuristic.name}", (TraceScene,), {
        "algorithm": heuristic.spec,
        "heuristic": None,
        "polygon": "counterexample",
        "title": heuristic.title,
        "__module__": __name__,
        "__doc__": f"The run of {heuristic.spec}, played with the user's source (or the "
                   "pseudocode of its docstring) in the panel.",
    })
