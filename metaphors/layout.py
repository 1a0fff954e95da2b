"""Where things go on the 16:9 frame (14.2 × 8 units): metaphor left, panel right, subtitle below."""

from __future__ import annotations

import math
from dataclasses import dataclass

from shapely.geometry import box
from shapely.geometry.base import BaseGeometry
from shapely.prepared import prep


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
#: where the labels of the panel's polygon may stand: round it, under the title (its bottom
#: 3.35) and over the code (its top 0.33), each 0.05 clear
PANEL_LABELS = Box(3.6, 1.84, 5.8, 2.92)
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


# --- a free place for what a metaphor adds beside its polygon ------------------------------------

#: a rectangle of the frame: left, bottom, right, top
Rect = tuple[float, float, float, float]
#: the whole frame (14.2 × 8 units), less a margin of 0.3 (4 % of its height) that keeps a
#: thing off the screen's edge, where a projector may crop it
FRAME_AREA: Rect = (-6.8, -3.7, 6.8, 3.7)
#: the highest a subtitle reaches (two lines of it, grown up from :data:`SUBTITLE_BOTTOM`)
SUBTITLE_TOP = SUBTITLE_BOTTOM + 0.85
#: how far a placed thing keeps from everything else on screen
CLEARANCE = 0.12
#: the grid a free place is looked for on (scene units)
PLACE_STEP = 0.05


def free_place(width: float, height: float, taken: BaseGeometry, area: Rect = FRAME_AREA,
               clearance: float = CLEARANCE) -> tuple[float, float] | None:
    """The left and top of the first ``width`` × ``height`` rectangle in ``area`` that keeps
    ``clearance`` from everything ``taken`` (one shape: the polygon's region, the labels'
    and the panel's boxes …), None if there is none. The first: the left-most, and the
    highest of those (on a grid of :data:`PLACE_STEP`): a thing placed beside the polygon
    stands in the frame's left margin when it can, where the eye starts.

    >>> from shapely.geometry import box
    >>> free_place(1.0, 1.0, box(-7.0, -4.0, 0.0, 4.0), area=(-7.0, -4.0, 7.0, 4.0))
    (0.15, 4.0)
    >>> free_place(20.0, 1.0, box(0.0, 0.0, 1.0, 1.0)) is None
    True
    """
    near = prep(taken.buffer(clearance))
    left, bottom, right, top = area
    columns = math.floor(round((right - left - width) / PLACE_STEP, 6))
    rows = math.floor(round((top - bottom - height) / PLACE_STEP, 6))
    for i in range(columns + 1):
        x = round(left + i * PLACE_STEP, 6)
        for j in range(rows + 1):
            y = round(top - j * PLACE_STEP, 6)
            if not near.intersects(box(x, y - height, x + width, y)):
                return x, y
    return None
