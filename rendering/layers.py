"""The z-layer contract between the board and :class:`~rendering.renderer.BackdropRenderer`.

manim draws, in every frame of a play, each mobject the play moves and, once before the
play, every other one into a static image. The board puts the text around the picture
beneath everything else, in two layers, and nothing else may use these z-indices:

- :data:`STILL_Z`: the text that stays all scene long (title, code), lowest;
- :data:`BACKDROP_Z`: the text that changes from beat to beat (the lit row and its light,
  the call line, the subtitle), drawn over it.

Nothing overlaps them, so the renderer may keep each layer's pixels between plays and draw
only the rest over a copy (``tests/test_redraw.py`` checks the frames stay manim's, bit for
bit). Everything else the board draws has a z-index above :data:`BACKDROP_Z`.
"""

STILL_Z = -11
BACKDROP_Z = -10
#: the z-indices of the layers kept, bottom first
LAYERS = (STILL_Z, BACKDROP_Z)
