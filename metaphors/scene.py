"""The Scene every video derives from: a function of (log, theme, pacing).

A subclass names its algorithm, default polygon and title; ``construct`` gets the log (a live
run, or ``TREX_LOG``), turns it into beats and plays them on a board. The scene never
re-decides what the algorithm decided.
"""

from __future__ import annotations

import os
from dataclasses import replace
from types import MappingProxyType

from manim import DOWN, FadeIn, FadeOut, Scene, VGroup, config
from manim.constants import RendererType

from geometry.user_heuristics import UserHeuristic, as_heuristic, load_attribute
from metaphors import catalog
from metaphors.board import Board
from metaphors.layout import METAPHOR
from metaphors.play import board_for, play_beats
from metaphors.tags import tag
from metaphors.theme import THEME
from rendering.camera import PathCamera
from rendering.renderer import BackdropRenderer
from rendering.typeset import text
from story.beats import Beat
from story.runs import run_logged, scene_log
from story.storyboard import Pacing
from tracing import Log


class TraceScene(Scene):
    """Plays the log of one algorithm run."""

    algorithm = "scaling"
    heuristic: str | None = None
    polygon = "counterexample"
    title = "Scaling: the nearest candidate"
    theme = THEME
    pacing = Pacing()
    metaphor_box = METAPHOR  # where the metaphor's polygon goes (left half by default)

    def __init__(self, renderer=None, **kwargs):
        if renderer is None and config.renderer == RendererType.CAIRO:
            renderer = BackdropRenderer(camera_class=kwargs.get("camera_class", PathCamera),
                                        skip_animations=kwargs.get("skip_animations", False))
        super().__init__(renderer=renderer, **kwargs)

    def log(self):
        return scene_log(self.algorithm, self.polygon, self.heuristic)

    def construct(self) -> None:
        self.camera.background_color = self.theme.background
        self.play_log(self.log(), self.title)
        self.wait(1.0)

    def beats(self, log) -> list[Beat]:
        return catalog.beats(log, self.pacing)

    def play_log(self, log, title: str) -> Board:
        """Turn one log into beats and play them on a fresh board (both kept, as
        ``trex_beats`` and ``trex_board``, for tests)."""
        self.trex_beats = self.beats(log)
        self.trex_board = board_for(self, log, self.trex_beats, title, self.theme)
        return play_beats(self.trex_board, self.trex_beats)


class SequenceScene(TraceScene):
    """Plays several runs one after another: a short title card, the run, then a clean board.

    ``runs`` lists (algorithm, polygon, title). The runs name their own polygons, so
    ``TREX_POLYGON`` is not read; ``TREX_LOG`` may list one saved log per run, joined with
    ``os.pathsep`` (``a.json:b.json:…``), to replay them instead of running live.
    """

    runs: tuple[tuple[str, str, str], ...] = ()
    #: × run time of each beat action: the set-up every run repeats goes quickly, the verdict
    #: stays long enough to read; ``pace`` for the rest
    paces = MappingProxyType({"polygon": 0.15, "pick": 0.15, "triangle": 0.2, "candidates": 0.2,
                              "claim": 0.3, "verdict": 0.55})
    pace = 0.32
    card_time = 0.8

    def beats(self, log) -> list[Beat]:
        return [replace(b, pace=self.paces.get(b.action, self.pace)) for b in catalog.beats(log)]

    def logs(self) -> list[Log]:
        saved = os.environ.get("TREX_LOG")
        if not saved:
            return [run_logged(algorithm, polygon) for algorithm, polygon, _ in self.runs]
        paths = saved.split(os.pathsep)
        if len(paths) != len(self.runs):
            raise ValueError(f"TREX_LOG lists {len(paths)} logs; this scene plays "
                             f"{len(self.runs)} runs (join their paths with {os.pathsep!r})")
        return [Log.load(path) for path in paths]

    def construct(self) -> None:
        self.camera.background_color = self.theme.background
        for k, (log, (_, _, title)) in enumerate(zip(self.logs(), self.runs, strict=True)):
            if self.mobjects:
                self.play(*[FadeOut(m) for m in self.mobjects], run_time=0.3)
                self.clear()
            self.card(k, title)
            self.play_log(log, title)
            self.wait(0.4)
        self.wait(0.5)

    def card(self, k: int, title: str) -> None:
        """A title card between runs: the run's number and its title."""
        theme = self.theme
        number = text(f"{k + 1} / {len(self.runs)}", font=theme.font, size=theme.label_size,
                      colour=theme.idle)
        name = text(title, font=theme.font, size=theme.title_size, colour=theme.ink, width=13)
        card = tag(VGroup(number, name).arrange(DOWN, buff=0.3), None, "card")
        self.play(FadeIn(card), run_time=0.25)
        self.wait(self.card_time - 0.5)
        self.play(FadeOut(card), run_time=0.25)


# --- the scene of a heuristic of one's own -------------------------------------------------------


def scene_for_heuristic(spec: str) -> type[Scene]:
    """The Scene class for ``path/to/file.py:name``.

    If ``name`` is a Scene class defined in the file, that class; otherwise ``name`` is a
    heuristic of one's own (see :mod:`geometry.user_heuristics`), loaded now so that a bad
    spec fails here, and the class plays its run on ``TREX_POLYGON`` (default: the
    counterexample) with the user's source in the panel. Raises
    :class:`geometry.user_heuristics.UserHeuristicError` (a ValueError, one-line message).
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
        "__doc__": f"The run of {heuristic.spec}, played with the user's source in the panel.",
    })
