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
