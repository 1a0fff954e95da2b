"""The exercises' countdown: a ring that empties and the seconds left, one play a second.

Each second is a play of its own, at a constant rate: the number on screen is the play's, for
exactly one second, and the scene graph says so (one play for the whole wait eased the ring
and its numbers with the play's default smooth rate: "15" stayed 3.7 s, "14" to "2" rushed
by at half a second each, and "1" stayed 3.7 s).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from manim import (
    TAU,
    Animation,
    Arc,
    FadeOut,
    Mobject,
    UpdateFromAlphaFunc,
    VGroup,
    VMobject,
    linear,
)

from metaphors.tags import tag
from metaphors.theme import THEME, Theme
from rendering import typeset

RING_RADIUS = 0.55


def _ring(fraction: float, at: tuple[float, float, float], theme: Theme) -> Arc:
    # A full arc has zero length at fraction 0; keep a hair of it so the mobject has points.
    angle = max(fraction, 1e-3) * TAU
    return Arc(radius=RING_RADIUS, start_angle=TAU / 4, angle=angle, arc_center=at,
               color=theme.argument, stroke_width=theme.stroke * 1.5)


def _digit(k: int, at: tuple[float, float, float], theme: Theme) -> VMobject:
    digit = typeset.text(str(k), font=theme.font, size=theme.caption_size + 8,
                         colour=theme.argument)
    return digit.move_to(at)


def countdown(seconds: int, at: tuple[float, float, float], theme: Theme = THEME
              ) -> tuple[VGroup, Iterator[UpdateFromAlphaFunc], Callable[[], Animation]]:
    """The countdown mobject (full ring, ``seconds`` shown), its seconds: ``seconds``
    animations of one second each, at a constant rate, to be played in turn (the caller adds
    the mobject and plays each as it comes), and its end: the animation that shows 0 on the
    empty ring as it fades (to be played with what comes when the time is up; the count
    stopped at 1, a second before the answer came).

    Each second shows its number from its first frame: the iterator puts it up before it
    hands over the second's animation (so that the scene graph, written before the play,
    holds it). The digits are typeset once, up front: a second only swaps which one is shown.
    """
    digits = [_digit(k, at, theme) for k in range(seconds, -1, -1)]
    shown = tag(VGroup(_ring(1.0, at, theme), digits[0]), None, "countdown")

    def second(left: int) -> UpdateFromAlphaFunc:
        def update(group: Mobject, alpha: float) -> None:
            group.submobjects[0].become(_ring((left - alpha) / seconds, at, theme))

        # the number itself, not its glyphs copied onto the last (the graph reads its text)
        shown[1] = digits[seconds - left]
        return UpdateFromAlphaFunc(shown, update, run_time=1.0, rate_func=linear)

    def end() -> Animation:
        shown[0].become(_ring(0.0, at, theme)).set_stroke(opacity=0.0)  # empty: no hair of it
        shown[1] = digits[-1]  # 0, from the play's first frame
        return FadeOut(shown)

    return shown, (second(left) for left in range(seconds, 0, -1)), end


__all__ = ["RING_RADIUS", "countdown"]
