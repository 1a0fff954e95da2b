"""Turning the picture: a rigid turn (and zoom) about a pivot, labels and dots kept upright.

Gravity turns the whole metaphor so that gravity points down. manim's way, a ``Transform``
along an arc to a turned copy, interpolates every point, colour and width of every part
between two copies each frame; :class:`Turn` keeps each part's starting points and applies
one 2×2 matrix per frame. Parts of the ``upright`` types (text, dots) keep their size and
orientation: they move with their centre.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from typing import cast

import numpy as np
from manim import Animation, Mobject


class Turn(Animation):
    """Turn ``mobject`` by ``angle`` radians about ``pivot`` and zoom it by ``zoom``.

    ``upright`` parts only move with their centre; ``shift`` moves the whole mobject by this
    much more, in step with the turn (it ends ``shift`` away from the plain turn), and
    ``moves`` (by ``id``) an upright part by this much more again (a vertex's label going to
    its place on the turned picture as its dot turns).

    Examples
    --------
    >>> from manim import Dot, Line, VGroup
    >>> group = VGroup(Line([1, 0, 0], [2, 0, 0]), Dot([1, 0, 0]))
    >>> turn = Turn(group, math.pi / 2, pivot=[0, 0, 0], zoom=2.0, upright=(Dot,))
    >>> turn.begin(); turn.interpolate(1.0); turn.finish()
    >>> group[0].get_end().round(6) + 0.0  # turned, twice as far out
    array([0., 4., 0.])
    >>> bool(np.isclose(group[1].width, Dot().width)), group[1].get_center().round(6) + 0.0
    (True, array([0., 2., 0.]))
    """

    def __init__(self, mobject: Mobject, angle: float, pivot, zoom: float = 1.0,
                 upright: tuple[type, ...] = (), shift=(0.0, 0.0, 0.0),
                 moves: Mapping[int, np.ndarray] | None = None, **kwargs):
        self.angle, self.zoom, self.upright = float(angle), float(zoom), upright
        self.pivot = np.asarray(pivot, dtype=float)[:2]
        self.shift = np.asarray(shift, dtype=float)
        self.moves = dict(moves or {})
        super().__init__(mobject, **kwargs)

    def begin(self) -> None:
        # (part, its starting points, the centre it moves with: None if it turns itself, and
        # the move of the upright part it is in)
        none = np.zeros(3)
        self._parts = [(part, part.points.copy(), centre, self.moves.get(owner, none))
                       for part, centre, owner in _parts(cast(Mobject, self.mobject),
                                                         self.upright, None, 0)]
        super().begin()

    def create_starting_mobject(self) -> Mobject:
        return Mobject()  # the starting points are all it needs: no copy of the mobject

    def interpolate_mobject(self, alpha: float) -> None:
        alpha = self.rate_func(alpha)
        turn = self.matrix(alpha)
        for part, start, centre, move in self._parts:
            points = start.copy()
            if centre is None:
                points[:, :2] = (start[:, :2] - self.pivot) @ turn.T + self.pivot
            else:
                points[:, :2] += (centre - self.pivot) @ turn.T + self.pivot - centre
            points += alpha * (self.shift + move)
            part.points = points

    def matrix(self, alpha: float) -> np.ndarray:
        """The turn and zoom ``alpha`` of the way."""
        angle, zoom = alpha * self.angle, 1.0 + alpha * (self.zoom - 1.0)
        cos, sin = math.cos(angle), math.sin(angle)
        return zoom * np.array([[cos, -sin], [sin, cos]])

    def end_centre(self, part: Mobject) -> np.ndarray:
        """Where ``part``'s centre ends without ``shift`` (the mobject not yet turned)."""
        centre = part.get_center()
        turned = (centre[:2] - self.pivot) @ self.matrix(1.0).T + self.pivot
        return np.array([*turned, centre[2]])


def _parts(mobject: Mobject, upright: tuple[type, ...], centre: np.ndarray | None,
           owner: int) -> Iterator[tuple[Mobject, np.ndarray | None, int]]:
    """Each family member with its points, the centre of the upright part it is in and that
    part's ``id`` (0 outside one)."""
    if centre is None and isinstance(mobject, upright):
        centre, owner = mobject.get_center()[:2], id(mobject)
    if len(mobject.points):
        yield mobject, centre, owner
    for child in mobject.submobjects:
        yield from _parts(child, upright, centre, owner)
