"""A step mark: where one step of a scene starts in its video, and what the step is.

A *step* is what a presenter plays with one key press (``trex slides``): one beat of a run,
a card's title or one of its lines, a question or its answer. The scenes note a mark as
each step starts, while they render (:mod:`metaphors.steps`, :mod:`metaphors.recorded`);
``trex`` keeps them beside the video (``NAME.steps.json``) and cuts the video into one clip
per step at them (:mod:`trex.clips`). One type for both sides, so nothing converts one mark
into another; no manim here.

>>> StepMark(23, "B is the left-most vertex").to_dict()
{'frame': 23, 'caption': 'B is the left-most vertex', 'call': None, 'kind': 'beat'}
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["StepMark"]


@dataclass(frozen=True)
class StepMark:
    """A step: the video frame it starts at, its caption, the call line shown (if any) and
    what kind of step it is (a beat's action, ``card``, ``card-line``, ``question`` …)."""

    frame: int
    caption: str
    call: str | None = None
    kind: str = "beat"

    def to_dict(self) -> dict[str, int | str | None]:
        """Plain JSON data, as ``NAME.steps.json`` holds each step."""
        return {"frame": self.frame, "caption": self.caption, "call": self.call,
                "kind": self.kind}
