"""The one play loop: a log's beats played on a board, for scenes, the user's panel and the
step player alike.

:func:`board_for` builds the board a log plays on (the first beat's polygon, the scene's
metaphor box; in the panel the run's pseudocode, unless the scene's ``panel`` asks for the
source or the run has none; the log's own ``code`` when it carries one: a user's source) and
:func:`play_beats` performs every beat on it, then closes the board (the last caption's cue
lasts until the run ends).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from itertools import groupby
from typing import Protocol, cast

import numpy as np
from manim import Animation, FadeOut, Mobject

from metaphors.board import Board
from metaphors.catalog import perform
from metaphors.fruit import Keyhole, Slice
from metaphors.gravity import GravityTurn
from metaphors.layout import TITLE_Y, Box
from metaphors.monotone import MonotoneDiagonal
from metaphors.panel import Panel
from metaphors.recorded import Recorded, captions_of, mark_step
from metaphors.tags import tag
from rendering.typeset import glyphs
from story.beats import Beat, Claim, Point, ShowPolygon, ShowTriangle
from story.pseudocode import PSEUDOCODE
from story.refs import meta
from story.storyboard import pseudocode_stages, run_call
from tracing import Log

#: widest title (scene units) before it is shrunk to fit the frame
TITLE_WIDTH = 13.4


class BoardScene(Protocol):
    """What a board asks of its scene (a :class:`metaphors.scene.TraceScene`, which records
    steps and captions as :class:`metaphors.recorded.Recorded`): where the metaphor goes and
    what the panel shows."""

    metaphor_box: Box
    panel: str
    call_line: bool  # False in the lecture: a run's steps are its rows and captions
    keep_end: bool  # the run's last picture kept as it is: an analysis goes on from it


def board_for(scene: BoardScene, log: Log, beats: Sequence[Beat], title: str,
              theme, *, later: Sequence[Sequence[Beat]] = ()) -> Board:
    """The board a log plays on; its panel shows what the scene's ``panel`` says (the
    pseudocode, when the run has some, or the source). ``later``: the beats of the runs
    that go on on this board after this one (:func:`go_on`): the labels keep clear of their
    claims too."""
    first = cast(ShowPolygon, beats[0])  # a storyboard opens with its polygon
    holes = first.holes if isinstance(first, ShowPolygon) else ()
    recorded = cast(Recorded, scene)  # every BoardScene is Recorded (TraceScene, the player's)
    runs = [beats, *later]
    claims = [*(beat.labels for run in runs for beat in run if isinstance(beat, Claim)),
              *(side for run in runs for beat in run if isinstance(beat, ShowTriangle)
                for side in _sides(beat.labels))]
    board = Board(recorded, first.points, first.labels, meta(log, "shown"), title, theme,
                  scene.metaphor_box, holes, captions=captions_of(recorded),
                  claims=list(dict.fromkeys(claims)),
                  cuts=[*(beat.points for beat in beats if isinstance(beat, Keyhole)),
                        *knife_cuts([beat for beat in beats if beat.pace >= 1.0])],
                  drawn=[line for run in runs for line in panel_lines(run)],
                  # a label with no room outside P beside it, with a leader, where the picture
                  # never turns (a turn keeps labels upright and places them again)
                  leaders=not any(isinstance(beat, GravityTurn) for run in runs for beat in run))
    board.kept_end = scene.keep_end
    _fill_panel(board.panel, scene, log)
    _fit_title(board.title)
    return board


def _fill_panel(panel: Panel, scene: BoardScene, log: Log) -> None:
    """The panel's text for ``log``'s run: its pseudocode (its rows named as the run goes:
    :func:`story.storyboard.pseudocode_stages`), or its source, and the call line's
    settings."""
    panel.shows_calls = scene.call_line
    panel.run_call = run_call(log)
    code = log.meta.get("code")
    rows, stages = pseudocode_stages(log)
    if scene.panel == PSEUDOCODE and rows:
        panel.show_pseudocode(rows, stages)
    elif code:
        panel.show_code(code)


def _fit_title(title: Mobject) -> None:
    if title.width > TITLE_WIDTH:
        title.scale_to_fit_width(TITLE_WIDTH)


def go_on(board: Board, scene: BoardScene, log: Log, title: str) -> list[Animation]:
    """Make ``board`` ready for another run on its polygon (a correction after the rule it
    mends: the same polygon, not drawn again). Returns the fades of what goes — the last
    run's claim, its verdict and the edge it crossed, its title and its panel's text — for
    one play; the run's title and its panel's text come with its first words
    (:attr:`Board.arriving`). The panel's small polygon stays, its labels in their roles."""
    old = board.panel
    panel = Panel(board.polygon.points, board.polygon.labels, meta(log, "shown"), board.theme,
                  board.holes)
    _fill_panel(panel, scene, log)
    kept = np.allclose(panel.outline.points, old.outline.points)
    if kept:  # the same box: the polygon drawn there stays
        panel.outline, panel.markers, panel.roles = old.outline, old.markers, old.roles
    # and what the last run drew on the panel's polygon (its claim, the edge it crossed, the
    # part it worked in): the new run draws its own
    going = [board.title, old.code, old.call, *(old.lit[1:] if old.lit else ()),
             *old.lines.values(), *([old.part] if old.part else []),
             *([] if kept else [old.outline, *old.markers.values()])]
    board.panel = panel
    board.title = tag(glyphs(title, font=board.theme.font, size=30, colour=board.theme.ink),
                      None, "title").move_to((0, TITLE_Y, 0))
    _fit_title(board.title)
    board.arriving = [board.title, *(panel.mobjects() if not kept else [panel.code, panel.call])]
    return [*(FadeOut(m) for m in going), *board.drop("claim", "crossed", "crossing", "verdict")]


def knife_cuts(beats: Sequence[Beat]) -> list[tuple[Point, Point]]:
    """The cuts the knife will make in ``beats``, one a slice (from its first corner to its
    last). The board's labels are placed clear of those of the slices played at full pace,
    each under its own caption: placed clear of the edges only, ear clipping's G stood on
    the cut BD, moved above its dot as B's triangle was tested, and off the fruit after the
    slice (three places in 12 s). Clear of every cut, the keyhole's hole labels stood up to
    1.1 from their vertices: the fast slices' cuts are not."""
    return [(beat.points[0], beat.points[2]) for beat in beats
            if isinstance(beat, Slice) and len(beat.points) == 3]


def panel_lines(beats: Sequence[Beat]) -> list[tuple[Point, Point]]:
    """The segments a run will draw in the panel's polygon (:class:`metaphors.panel.Panel`):
    its claims, its keyhole cuts, the monotone sweep's diagonals and the cut of each slice
    (the triangulation's diagonals drawn at its end)."""
    return [*(beat.points for beat in beats
              if isinstance(beat, Claim | Keyhole | MonotoneDiagonal)), *knife_cuts(beats)]


def _sides(corners: Sequence[str]) -> list[tuple[str, str]]:
    """The sides of T = ABC as pairs of labels: its labels are placed clear of them as of
    the claims (the exercise's E, placed clear of P's edges only, stood 0.1 from T's side
    AC, and its pulse as a candidate pushed it onto the line)."""
    return [(corners[k - 1], corners[k]) for k in range(len(corners))]


def stretches(beats: Sequence[Beat]) -> list[int]:
    """For each beat, how many beats its caption stands over: the unbroken stretch of
    beats with that caption it is one of (a summary's fast steps), not every beat of the
    run that says the same words.

    >>> from story.beats import Note
    >>> stretches([Note(caption=c, seq=k) for k, c in enumerate("aabba")])
    [2, 2, 2, 2, 1]
    """
    counts: list[int] = []
    for _, group in groupby(beats, key=lambda beat: beat.caption):
        n = len(list(group))
        counts.extend([n] * n)
    return counts


def play_beats(board: Board, beats: Sequence[Beat],
               after: Callable[[int, Beat], None] | None = None) -> Board:
    """Perform each beat on the board (``after(k, beat)`` once each is played, k from 1),
    then close it. Each beat is a step of the video (:func:`metaphors.recorded.mark_step`)."""
    for k, (beat, share) in enumerate(zip(beats, stretches(beats), strict=True), start=1):
        board.share = share  # the beats its caption stands over (Board.shared_time)
        if beat.caption != board.caption:
            board.captions.hold()  # the caption before is read in its own step
        mark_step(cast(Recorded, board.scene), beat.caption, beat.call, beat.action)  # board_for's
        perform(board, beat)
        if after is not None:
            after(k, beat)
    board.close()
    return board
