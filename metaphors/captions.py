"""The subtitle track of a scene: each caption held on screen until it has been read.

Every caption a scene shows goes through the scene's one :class:`CaptionTrack`
(:func:`metaphors.recorded.captions_of`): :meth:`~CaptionTrack.show` first holds the caption before it until
it has been read (:func:`story.reading.reading_time`: at least 0.83 s, at most 17
characters per second), ends its ``.srt`` cue there, and gives the keyword arguments that
put the new one up with the next play. So a beat lasts as long as its caption needs, and
the ``.srt`` says what is on screen: a cue ends when the next caption appears or the
screen is cleared (:meth:`~CaptionTrack.finish`).
"""

from __future__ import annotations

import math
from datetime import timedelta

from manim import Scene

from story.reading import reading_time

#: seconds added to each hold: the ``.srt`` keeps milliseconds, and a cue read to the
#: millisecond must not come out a hair too short
MARGIN = 0.01
#: the frame rate every quality's is a multiple of (15, 30, 60 fps)
BASE_RATE = 15


def whole_frames(seconds: float) -> float:
    """``seconds`` rounded up to whole frames at :data:`BASE_RATE` (so whole frames at every
    quality), for a wait: manim draws a still wait as ``int(seconds × fps)`` frames, and a
    wait of any other length would come out up to a frame short in the video.

    >>> [int(whole_frames(0.3) * fps) for fps in (15, 30, 60)]
    [5, 10, 20]
    """
    frames = math.ceil(seconds * BASE_RATE - 1e-6)
    return frames / BASE_RATE + 1e-8  # a hair over: int() of the frame count is exact


class CaptionTrack:
    """Which caption is up, since when; the scene waits for it to be read."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self.text = ""  # the caption on screen ("" none)
        self.since = 0.0  # the clock when it appeared
        # The clock counts the plays' own run times. The renderer's time would not do: a
        # render counts whole frames (a play of 0.25 s lasts 4 frames at 15 fps) and a dry
        # run does not, so holds reckoned on it would differ between the video and its scene
        # graph. Whole frames last at least as long, so a caption held here is held there too.
        self.clock = 0.0
        play = scene.play

        def timed_play(*args, **kwargs):
            play(*args, **kwargs)
            self.clock += float(scene.duration)

        scene.play = timed_play  # type: ignore[method-assign]  # the scene's own play, wrapped to count run times

    def now(self) -> float:
        return self.clock

    def left(self) -> float:
        """Seconds the caption on screen still needs to be read."""
        if not self.text:
            return 0.0
        return max(0.0, reading_time(self.text) + MARGIN - (self.now() - self.since))

    def hold(self) -> None:
        """Wait until the caption on screen has been read."""
        left = self.left()
        if left > 1e-9:
            self.scene.wait(whole_frames(left))

    def show(self, caption: str, run_time: float) -> dict:
        """The play arguments that put ``caption`` up, once the caption before it has been
        read (held here) and its cue ended; none if it is already up."""
        if caption == self.text:
            return {}
        self.hold()
        self.stretch()
        self.text, self.since = caption, self.now()
        return {"subcaption": caption, "subcaption_duration": max(run_time, 1e-3)}

    def stretch(self) -> None:
        """The cue of the caption on screen lasts until now (manim wrote it as long as the
        play that put it up)."""
        cues = getattr(getattr(self.scene.renderer, "file_writer", None), "subcaptions", None)
        if cues and self.text and cues[-1].content == self.text:
            now = timedelta(seconds=float(self.scene.renderer.time))  # the video's own time
            cues[-1].end = max(cues[-1].end, now)

    def finish(self) -> None:
        """The caption leaves the screen (read first): its cue ends now."""
        self.hold()
        self.stretch()
        self.text = ""
