"""The exercises' countdown: a ring that empties and the seconds left, in one animation.

One play for the whole wait (not one per second), so the scene graph stays small and the
question's caption is the only one on screen while the class thinks.
"""

from __future__ import annotations

from manim import TAU, Arc, Mobject, UpdateFromAlphaFunc, VGroup, VMobject

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


def countdown(seconds: int, at: tuple[float, float, float],
              theme: Theme = THEME) -> tuple[VGroup, UpdateFromAlphaFunc]:
    """The countdown mobject (full ring, ``seconds`` shown) and the animation that runs it
    down to 1 over ``seconds`` seconds; the caller adds the mobject and plays the animation.

    The digits are typeset once, up front: a frame only swaps which one is shown.
    """
    digits = [_digit(k, at, theme) for k in range(seconds, 0, -1)]
    shown = tag(VGroup(_ring(1.0, at, theme), digits[0].copy()), None, "countdown")

    def update(group: Mobject, alpha: float) -> None:
        left = min(int(alpha * seconds), seconds - 1)
        group.submobjects[0].become(_ring(1.0 - alpha, at, theme))
        group.submobjects[1].become(digits[left])

    return shown, UpdateFromAlphaFunc(shown, update, run_time=seconds)


__all__ = ["RING_RADIUS", "countdown"]
