"""A Cairo renderer that draws the title and the code once, not once per play.

Before each play manim draws every mobject the play leaves still into a static image, which
each frame of the play starts from. In our scenes most of that is text that stays all scene
long — the title and the algorithm's code, at :data:`~metaphors.layout.STILL_Z` beneath
everything else (see ``Board.settle``). :class:`BackdropRenderer` keeps those pixels and draws
only the rest of the still mobjects over a copy of them, as long as that bottom layer is the
same: the same mobjects in the same state (their drawn attributes are hashed) and the same
camera. The frames are the same pixels as manim's (``tests/test_redraw.py`` compares whole
renders, frame by frame).
"""

from __future__ import annotations

import hashlib
from collections.abc import Iterable
from enum import Enum

import numpy as np
from manim import Mobject
from manim.renderer.cairo_renderer import CairoRenderer
from manim.utils.color import ManimColor

from metaphors.layout import STILL_Z

_PLAIN = (int, float, str, bool, type(None), Enum)


class BackdropRenderer(CairoRenderer):
    """manim's Cairo renderer, with the pixels of the bottom layer (title, code) kept between
    plays."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._backdrop: tuple[bytes, np.ndarray] | None = None  # (state, pixels)
        self.reused = 0  # plays that started from the kept backdrop

    def save_static_frame_data(self, scene, static_mobjects: Iterable[Mobject]):
        still = list(static_mobjects)  # family members with points, sorted by z-index
        count = next((k for k, m in enumerate(still) if m.z_index != STILL_Z), len(still))
        if count == 0:
            return super().save_static_frame_data(scene, still)
        backdrop, rest = still[:count], still[count:]
        state = drawn_state(self.camera, backdrop)
        if self._backdrop is None or self._backdrop[0] != state:
            self.static_image = None
            self.update_frame(scene, mobjects=backdrop)  # the background, then the backdrop
            self._backdrop = (state, self.get_frame())
        else:
            self.reused += 1
        self.static_image = self._backdrop[1]
        if rest:
            self.update_frame(scene, mobjects=rest)  # over a copy of the backdrop's pixels
            self.static_image = self.get_frame()
        return self.static_image


def drawn_state(camera, mobjects: Iterable[Mobject]) -> bytes:
    """A digest of everything that decides these mobjects' pixels: the camera's frame and
    background, and each mobject's type and attributes (arrays, numbers, strings, colours,
    enums — the points and colours among them; submobjects are listed on their own)."""
    digest = hashlib.blake2b(digest_size=20)
    for value in (camera.pixel_array.shape, camera.frame_width, camera.frame_height,
                  tuple(camera.frame_center), str(camera.background_color),
                  camera.background_opacity, getattr(camera, "background_image", None)):
        digest.update(repr(value).encode())
    for mobject in mobjects:
        digest.update(type(mobject).__qualname__.encode())
        for key, value in sorted(mobject.__dict__.items()):
            if isinstance(value, np.ndarray):
                digest.update(f"{key}:{value.dtype}{value.shape}".encode())
                digest.update(np.ascontiguousarray(value).tobytes())
            elif isinstance(value, _PLAIN):
                digest.update(repr((key, value)).encode())
            elif isinstance(value, ManimColor):
                digest.update(repr((key, value.to_hex(with_alpha=True))).encode())
    return digest.digest()
