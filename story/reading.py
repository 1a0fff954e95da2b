"""How long a caption must stay on screen for a class to read it.

At most :data:`READING_SPEED` characters per second (the BBC's and Netflix's limit for
children's programmes: the viewer also watches the animation), and never less than
:data:`SHORTEST_CUE` seconds.

>>> round(reading_time("✗ BD is not an inner diagonal"), 2)  # 29 characters
1.71
>>> reading_time("B")
0.83
"""

from __future__ import annotations

#: characters per second a class reads a caption at, at most
READING_SPEED = 17
#: seconds the shortest caption stays on screen
SHORTEST_CUE = 0.83


def reading_time(caption: str) -> float:
    """Seconds ``caption`` must stay on screen."""
    return max(SHORTEST_CUE, len(caption) / READING_SPEED)
