"""Where things go on the 16:9 frame (14.2 × 8 units): metaphor left, panel right, subtitle below."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Box:
    """A rectangle of the frame: centre and size."""

    x: float
    y: float
    width: float
    height: float

    @property
    def center(self) -> tuple[float, float]:
        return (self.x, self.y)


TITLE_Y = 3.55
METAPHOR = Box(-3.45, -0.05, 5.6, 5.6)
# the panel's polygon leaves room for its vertex labels (up to 0.47 outside it) below the title
# and above the code
PANEL_POLYGON = Box(3.6, 1.82, 4.6, 2.0)
PANEL_CODE = Box(3.6, -0.95, 6.2, 2.55)
# the source (``--panel source``) takes the polygon's place too: title to call line
PANEL_SOURCE = Box(3.58, 0.45, 6.7, 5.3)
PANEL_CALL_Y = -2.65
SUBTITLE_Y = -3.55
#: the widest a subtitle line may be (scene units) before it takes two lines
SUBTITLE_WIDTH = 13.4
#: the lowest a subtitle reaches: a subtitle of two lines grows upwards from it
SUBTITLE_BOTTOM = -3.8


def subtitle_centre(height: float) -> tuple[float, float, float]:
    """Where a subtitle ``height`` tall is centred: on :data:`SUBTITLE_Y`, or higher if it
    would reach below :data:`SUBTITLE_BOTTOM`.

    >>> subtitle_centre(0.3), subtitle_centre(0.8)
    ((0, -3.55, 0), (0, -3.4, 0))
    """
    return (0, round(max(SUBTITLE_Y, SUBTITLE_BOTTOM + height / 2), 6), 0)
