"""Gravity's close-up (:class:`metaphors.gravity.CloseUp`): the board's frame in the close-up
maps every polygon point where the zoom puts the old frame's point, so the ball, the band and
the hit ring land on the zoomed picture."""

import numpy as np
import pytest

from metaphors.drawing import Frame
from metaphors.gravity import CloseUp

POINTS = [(0, 0), (4, 0), (4, 2), (1, 3)]


@pytest.mark.parametrize("angle, pivot, zoom", [(0.0, None, 1.0), (37.0, (-3.0, 0.5), 0.8),
                                                (-120.0, (-2.0, -1.0), 1.0)])
def test_the_close_ups_frame_is_the_old_one_zoomed_about_the_fall(angle, pivot, zoom):
    old = Frame(POINTS, (-3.45, -0.05), 5.6, 5.6).turned(angle, pivot, zoom)
    close = CloseUp.__new__(CloseUp)  # the frame's arithmetic only: no board
    close.frame, close.pivot, close.zoom = old, np.array([-3.0, -1.5, 0.0]), 2.5
    new = close._frame()
    for p in [*POINTS, (2.5, 1.2)]:
        assert np.allclose(new.to_scene(p), close.zoomed(old.to_scene(p)))
    assert new.angle == old.angle and new.zoom == pytest.approx(old.zoom * 2.5)
