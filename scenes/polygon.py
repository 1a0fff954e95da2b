"""The counterexample polygon, labelled, then triangulated triangle by triangle.

Run: ``manim -pql scenes/polygon.py`` (``TREX_POLYGON=<file or sample>`` picks the polygon).
"""

from manim import DOWN, UP, Create, FadeIn, Scene, Write

from geometry.cdt import constrained_delaunay
from geometry.io import read_polygon
from metaphors.drawing import Frame, polygon_mobject, triangulation_pieces
from metaphors.labels import placed_vertex_markers
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
        self.play(Create(tag(polygon_mobject(polygon, frame), "idle", "polygon")), run_time=1.5)
        cut = constrained_delaunay(polygon)
        # each label clear of the edges and of the triangles' sides to come, as a run's board
        # places them (E stood on edge BC, over the sliver BEC)
        n = polygon.n
        diagonals = sorted({(min(i, j), max(i, j)) for tri in cut for i, j in
                            zip(tri, (*tri[1:], tri[0]), strict=True) if (j - i) % n not in (1, n - 1)})
        markers = placed_vertex_markers(polygon, frame, THEME, diagonals)
        for label, marker in zip(polygon.labels, markers, strict=True):
            tag(marker, "idle", f"vertex:{label}")
        self.play(FadeIn(markers), run_time=0.8)
        triangles = [[polygon.points[k] for k in tri] for tri in cut]
        # a finished triangulation's tints (metaphors.theme's legend), not the roles' colours
        for triangle in triangulation_pieces(triangles, frame.to_scene):
            self.play(FadeIn(triangle), run_time=0.6)
        count = tag(text(f"n − 2 = {polygon.n} − 2 = {len(triangles)} triangles",
                         font=THEME.font, size=THEME.caption_size, colour=THEME.result),
                    "result", "counter").to_edge(DOWN)
        self.play(FadeIn(count), run_time=0.8)
        self.wait(1.5)
