"""The Scene every video derives from: a function of (log, theme, pacing).

A subclass names its algorithm, default polygon and title; ``construct`` gets the log (a live
run, or ``TREX_LOG``), turns it into beats and plays them on a board. The scene never
re-decides what the algorithm decided.
"""

from __future__ import annotations

from manim import Scene

from metaphors.actions import perform
from metaphors.board import Board
from metaphors.runs import scene_log
from metaphors.storyboard import Pacing, storyboard
from metaphors.theme import THEME


class TraceScene(Scene):
    """Plays the log of one algorithm run."""

    algorithm = "scaling"
    heuristic: str | None = None
    polygon = "counterexample"
    title = "Scaling: the nearest candidate"
    theme = THEME
    pacing = Pacing()

    def log(self):
        return scene_log(self.algorithm, self.polygon, self.heuristic)

    def construct(self) -> None:
        self.camera.background_color = self.theme.background
        log = self.log()
        beats = storyboard(log, self.pacing)
        first = beats[0]
        board = Board(self, first.data["points"], first.data["labels"], log.meta.get("shown"),
                      self.title, self.theme)
        for beat in beats:
            perform(board, beat)
        self.wait(1.0)
