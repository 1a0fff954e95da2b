"""A Cairo renderer that draws the text around the picture once, not once per play.

Before each play manim draws every mobject the play leaves still into a static image, which
each frame of the play starts from. In our scenes most of that is text, beneath everything
else (see ``Board.settle``): the title and the algorithm's code, which stay all scene long,
at :data:`~rendering.layers.STILL_Z`, and the subtitle, call line and lit code row, which
change once a beat (every two to four plays), at :data:`~rendering.layers.BACKDROP_Z`.
:class:`BackdropRenderer` keeps the pixels of each of those layers (drawn over the ones
below) and draws only the rest of the still mobjects over a copy of them, as long as the
layers are the same: the same mobjects in the same state (their drawn attributes are hashed)
and the same camera. The frames are the same pixels as manim's (``tests/test_redraw.py``
compares whole renders, frame by frame).
"""

from __future__ import annotations

import hashlib
from collections.abc import Iterable, Sequence
from enum import Enum
from typing import Any

import numpy as np
from manim import Mobject
from manim.renderer.cairo_renderer import CairoRenderer
from manim.utils.color import ManimColor

from rendering.layers import LAYERS

_PLAIN = (int, float, str, bool, type(None), Enum, np.generic)


class BackdropRenderer(CairoRenderer):
    """manim's Cairo renderer, with the pixels of the bottom layers (title and code; the
    text of the beat) kept between plays."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        # z -> (state, camera background it was drawn on, pixels)
        self._kept: dict[int, tuple[bytes, np.ndarray | None, np.ndarray]] = {}
        self.reused = 0  # layers taken from the kept pixels instead of drawn

    def save_static_frame_data(self, scene, static_mobjects: Iterable[Mobject]):
        still = list(static_mobjects)  # family members with points, sorted by z-index
        image, state, start = None, b"", 0
        for z in LAYERS:
            end = start
            while end < len(still) and still[end].z_index == z:
                end += 1
            if end == start:
                break
            state = drawn_state(self.camera, still[start:end], state)
            kept = self._kept.get(z)
            # manim replaces the background array whenever it changes it (set_background,
            # background_color): the very array the layer was drawn on is part of its state
            if kept is None or kept[0] != state or kept[1] is not self.camera.background:
                self.static_image = image
                self.update_frame(scene, mobjects=still[start:end])  # over the layer below
                kept = self._kept[z] = (state, self.camera.background, self.get_frame())
            else:
                self.reused += 1
            image, start = kept[2], end
        if start == 0:
            return super().save_static_frame_data(scene, still)
        self.static_image = image
        if start < len(still):
            self.update_frame(scene, mobjects=still[start:])  # over a copy of the layers
            self.static_image = self.get_frame()
        return self.static_image


def drawn_state(camera, mobjects: Sequence[Mobject], below: bytes = b"") -> bytes:
    """A digest of everything that decides these mobjects' pixels: the camera's frame and
    background, each mobject's type and attributes (arrays, numbers, strings, colours,
    enums — the points and colours among them; submobjects are listed on their own), and
    ``below``, the state of what they are drawn over."""
    digest = hashlib.blake2b(below, digest_size=20)
    digest.update(repr((camera.pixel_array.shape, camera.frame_width, camera.frame_height,
                        tuple(camera.frame_center), str(camera.background_color),
                        camera.background_opacity,
                        getattr(camera, "background_image", None))).encode())
    for mobject in mobjects:
        plain: list = [type(mobject).__qualname__]
        for key, value in sorted(mobject.__dict__.items()):
            if isinstance(value, np.ndarray):
                plain.append((key, value.dtype.str, value.shape))
                digest.update(np.ascontiguousarray(value).data)
            elif isinstance(value, _PLAIN):
                plain.append((key, value))
            elif isinstance(value, ManimColor):
                plain.append((key, value.to_hex(with_alpha=True)))
        digest.update(repr(plain).encode())
    return digest.digest()
