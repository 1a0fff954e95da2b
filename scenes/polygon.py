"""The counterexample polygon, labelled, then triangulated triangle by triangle.

Run: ``manim -pql scenes/polygon.py`` (``TREX_POLYGON=<file or sample>`` picks the polygon).
"""

from manim import DOWN, UP, Create, FadeIn, Scene, Write

from geometry.cdt import constrained_delaunay
from geometry.io import read_polygon
from metaphors.drawing import Frame, polygon_mobject, triangulation_pieces, vertex_markers
from metaphors.scene import SpecScene
from metaphors.tags import tag
from metaphors.theme import THEME
from rendering.typeset import glyphs, text


class PolygonScene(SpecScene, Scene):
    algorithm = "cdt"  # the triangles it shows
    polygon = "counterexample"

    def construct(self):
        polygon = read_polygon(self.run_spec().polygon)
        self.camera.background_color = THEME.background
        frame = Frame(polygon.points, center=(0, 0), width=9, height=5)
        # the title says what is drawn, in words (no arrow: on screen "→" is code's); the
        # count comes once the triangles are there
        title = glyphs(
            f"A simple polygon of {polygon.n} vertices, cut into triangles",
            font=THEME.font, size=THEME.caption_size, colour=THEME.ink,
        ).to_edge(UP)
        self.play(Write(title), run_time=1)
        self.play(Create(polygon_mobject(polygon, frame)), run_time=1.5)
        self.play(FadeIn(vertex_markers(polygon, frame)), run_time=0.8)
        triangles = [[polygon.points[k] for k in tri] for tri in constrained_delaunay(polygon)]
        # a finished triangulation's tints (metaphors.theme's legend), not the roles' colours
        for triangle in triangulation_pieces(triangles, frame.to_scene):
            self.play(FadeIn(triangle), run_time=0.6)
        count = tag(text(f"n − 2 = {polygon.n} − 2 = {len(triangles)} triangles",
                         font=THEME.font, size=THEME.caption_size, colour=THEME.result),
                    "result", "counter").to_edge(DOWN)
        self.play(FadeIn(count), run_time=0.8)
        self.wait(1.5)
