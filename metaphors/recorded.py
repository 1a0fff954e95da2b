"""What a scene notes while it renders, declared: its step marks, the lead-in of the next
step, where the last step ends, its caption track, and the beats and board of the run it
played last.

:class:`Recorded` is mixed into every scene of this project (:class:`metaphors.scene.TraceScene`)
and sets this state up in ``__init__`` — as manim-slides' ``BaseSlide`` declares its
``_slides`` — so nothing is stashed on the Scene by name. The functions below are how the
scenes, the boards and the stages note a step (:mod:`metaphors.steps`) and show a caption
(:mod:`metaphors.captions`); ``trex render`` reads the marks back with :func:`recorded_steps`
and :func:`steps_end`, which give nothing for a Scene that notes none (a plain manim one).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from manim import Scene

from metaphors.captions import CaptionTrack
from metaphors.steps import frame_now
from story.beats import Beat
from story.step_marks import StepMark

if TYPE_CHECKING:
    from metaphors.board import Board

    _Mixin = Scene  # mixed into a Scene, which the checker is told; at run time a plain class
else:
    _Mixin = object


class Recorded(_Mixin):
    """Mixed in before ``Scene``: the state a scene accumulates while it renders."""

    #: the steps noted so far, in order (:func:`mark_step`)
    step_marks: list[StepMark]
    #: where the transition into the next step starts (:func:`lead_in`); None: at its mark
    lead_in_frame: int | None
    #: the frame the last step ends before (:func:`end_steps`); None: the end of the video
    steps_end_frame: int | None
    #: every caption the scene shows goes through this one track (made by the first
    #: :func:`captions_of`: its clock counts the plays from the first caption on)
    caption_track: CaptionTrack | None
    #: the first frame (:func:`story.reading.frame_key`) of the run played last, if any
    frames_seen: set[tuple]
    #: the beats and the board of the run played last (for tests and checks)
    played_beats: list[Beat]
    played_board: Board | None

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        self.step_marks = []
        self.lead_in_frame = None
        self.steps_end_frame = None
        self.caption_track = None
        self.frames_seen = set()
        self.played_beats = []
        self.played_board = None
        super().__init__(*args, **kwargs)


def mark_step(scene: Recorded, caption: str, call: str | None = None,
              kind: str = "beat") -> None:
    """Note that a step starts now (or where :func:`lead_in` last said), with ``caption``."""
    start, scene.lead_in_frame = scene.lead_in_frame, None
    scene.step_marks.append(StepMark(frame_now(scene) if start is None else start, caption,
                                     call, kind))


def lead_in(scene: Recorded) -> None:
    """What plays from now on, up to the next :func:`mark_step`, opens that step (a lead-in
    already noted and not yet used stays where it is)."""
    if scene.lead_in_frame is None:
        scene.lead_in_frame = frame_now(scene)


def end_steps(scene: Recorded) -> None:
    """The last step ends now: what plays after it (a closing fade) is in no step."""
    scene.steps_end_frame = frame_now(scene)


def recorded_steps(scene: Scene) -> list[StepMark]:
    """The marks noted while the scene played, in order (none for a plain Scene)."""
    return list(scene.step_marks) if isinstance(scene, Recorded) else []


def steps_end(scene: Scene) -> int | None:
    """The frame the last step ends before (None: the end of the video)."""
    return scene.steps_end_frame if isinstance(scene, Recorded) else None


def captions_of(scene: Recorded) -> CaptionTrack:
    """The scene's caption track (made on first use)."""
    if scene.caption_track is None:
        scene.caption_track = CaptionTrack(scene)
    return scene.caption_track
