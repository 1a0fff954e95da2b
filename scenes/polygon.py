"""The counterexample polygon, labelled, then triangulated triangle by triangle.

Run: ``manim -pql scenes/polygon.py`` (``TREX_POLYGON=<file or sample>`` picks the polygon).
"""

from manim import UP, Create, FadeIn, Scene, Write

from geometry.cdt import constrained_delaunay
from geometry.io import read_polygon
from metaphors.drawing import Frame, polygon_mobject, triangle_mobject, vertex_markers
from metaphors.scene import SpecScene
from metaphors.theme import THEME
from rendering.typeset import glyphs


class PolygonScene(SpecScene, Scene):
    algorithm = "cdt"  # the triangles it shows
    polygon = "counterexample"

    def construct(self):
        polygon = read_polygon(self.run_spec().polygon)
        self.camera.background_color = THEME.background
        frame = Frame(polygon.points, center=(0, -0.3), width=9, height=5.5)
        title = glyphs(
            f"A simple polygon: {polygon.n} vertices → {polygon.n - 2} triangles",
            font=THEME.font, size=THEME.caption_size, colour=THEME.ink,
        ).to_edge(UP)
        self.play(Write(title), run_time=1)
        self.play(Create(polygon_mobject(polygon, frame)), run_time=1.5)
        self.play(FadeIn(vertex_markers(polygon, frame)), run_time=0.8)
        palette = (THEME.called, THEME.result, THEME.argument)
        for k, tri in enumerate(constrained_delaunay(polygon)):
            triangle = triangle_mobject(polygon, tri, frame, palette[k % len(palette)])
            self.play(FadeIn(triangle), run_time=0.6)
        self.wait(1)
