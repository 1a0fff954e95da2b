"""Parts of manim replaced for speed, with the same pixels: the camera, the renderer that keeps
the text layers between plays (their contract: :mod:`rendering.layers`), typesetting, the turn.
Imports manim only."""
