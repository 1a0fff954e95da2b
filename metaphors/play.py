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

from metaphors.board import Board
from metaphors.catalog import perform
from metaphors.fruit import Keyhole, Slice
from metaphors.gravity import GravityTurn
from metaphors.layout import Box
from metaphors.monotone import MonotoneDiagonal
from metaphors.recorded import Recorded, captions_of, mark_step
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
              theme) -> Board:
    """The board a log plays on; its panel shows what the scene's ``panel`` says (the
    pseudocode, when the run has some, or the source)."""
    first = cast(ShowPolygon, beats[0])  # a storyboard opens with its polygon
    holes = first.holes if isinstance(first, ShowPolygon) else ()
    recorded = cast(Recorded, scene)  # every BoardScene is Recorded (TraceScene, the player's)
    board = Board(recorded, first.points, first.labels, meta(log, "shown"), title, theme,
                  scene.metaphor_box, holes, captions=captions_of(recorded),
                  claims=list(dict.fromkeys([
                      *(beat.labels for beat in beats if isinstance(beat, Claim)),
                      *(side for beat in beats if isinstance(beat, ShowTriangle)
                        for side in _sides(beat.labels))])),
                  cuts=[*(beat.points for beat in beats if isinstance(beat, Keyhole)),
                        *knife_cuts([beat for beat in beats if beat.pace >= 1.0])],
                  drawn=panel_lines(beats),
                  # a label with no room outside P beside it, with a leader, where the picture
                  # never turns (a turn keeps labels upright and places them again)
                  leaders=not any(isinstance(beat, GravityTurn) for beat in beats))
    board.panel.shows_calls = scene.call_line
    board.kept_end = scene.keep_end
    board.panel.run_call = run_call(log)
    code = log.meta.get("code")
    rows, stages = pseudocode_stages(log)
    if scene.panel == PSEUDOCODE and rows:
        board.panel.show_pseudocode(rows, stages)
    elif code:
        board.panel.show_code(code)
    if board.title.width > TITLE_WIDTH:
        board.title.scale_to_fit_width(TITLE_WIDTH)
    return board


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
