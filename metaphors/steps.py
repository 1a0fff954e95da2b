"""Step marks (:class:`story.step_marks.StepMark`): where each step of a scene starts in its video, noted while it renders.

A *step* is what a presenter plays with one key press (``trex slides``): one beat of a run
(a call, a metaphor action, a verdict), a card's title or one of its lines, a question or its
answer. :func:`metaphors.recorded.mark_step` notes that a step starts now — the frame the
renderer is about to write — with its caption; the marks are kept on the scene (declared by
:class:`metaphors.recorded.Recorded`), so they come from the render itself and never from a second computation of its timing. A step lasts until
the next one starts; the last lasts to the end of the video.

What plays between two segments (the fade that clears the screen) belongs to the step after
it, so that every step ends on the picture it built: :func:`metaphors.recorded.lead_in` notes where that
transition starts, and the next mark starts there.

The frame is counted by the renderer's clock: manim's Cairo renderer adds ``1 / frame_rate``
to ``renderer.time`` for each frame it writes, so ``time × frame_rate`` is the number of
frames written so far (a frame index of the scene's video). Each ``play`` and ``wait`` is
encoded as a movie file of its own, which manim then joins packet by packet, so a mark (made
between two plays) always falls on the first frame of one of them: a key frame of the video.
"""

from __future__ import annotations

from manim import Scene

__all__ = ["frame_now"]


def frame_now(scene: Scene) -> int:
    """The index of the next frame the scene's renderer writes."""
    return round(float(scene.renderer.time) * scene.camera.frame_rate)
