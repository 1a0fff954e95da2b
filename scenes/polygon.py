"""The counterexample polygon, labelled, then triangulated triangle by triangle.

Run: ``manim -pql scenes/polygon.py`` (``TREX_POLYGON=<file or sample>`` picks the polygon).
"""

import math
from collections.abc import Sequence

import numpy as np
import shapely
from manim import DL, DOWN, DR, UP, Create, FadeIn, Mobject, Scene, VGroup, Write

from geometry.cdt import constrained_delaunay
from geometry.io import read_polygon
from geometry.polygon import Polygon
from metaphors.drawing import Frame, polygon_mobject, triangulation_pieces
from metaphors.labels import placed_vertex_markers
from metaphors.layout import FRAME_AREA, area_of
from metaphors.scene import SpecScene
from metaphors.tags import tag
from metaphors.theme import THEME
from rendering.typeset import glyphs, text

#: the least gap between the words (title, count) and the picture, its labels included
WORDS_GAP = 0.4
#: room round the outline that a vertex's dot takes (the labels are measured once placed)
DOT_ROOM = 0.1
#: each framing tried is this much smaller than the one before
SCALE_STEP = 0.97
#: the framings tried at most before the old fixed one (9 × 5 about the centre)
TRIES = 40
#: the picture's centres tried at each scale, nearest the frame's centre first: off it by at
#: most 3 sideways (where a polygon's empty corner can leave the words room) and 0.5 up or down
CENTRES = sorted(((float(x), float(y)) for x in np.arange(-3.0, 3.01, 0.25)
                  for y in np.arange(-0.5, 0.51, 0.1)), key=lambda c: math.hypot(*c))
#: where the count may stand: under the picture's middle, or in a bottom corner
COUNT_PLACES = (DOWN, DL, DR)


def _shape(mobjects: Sequence[Mobject]) -> shapely.Geometry:
    """The boxes of these mobjects, one shape."""
    return shapely.union_all([shapely.box(*area_of(m)) for m in mobjects])


def _fits(shape: shapely.Geometry, words: shapely.Geometry) -> bool:
    return shapely.box(*FRAME_AREA).contains(shape) and shape.distance(words) >= WORDS_GAP


def framing(polygon: Polygon, title: Mobject, count: Mobject,
            diagonals: Sequence[tuple[int, int]]) -> tuple[Frame, VGroup]:
    """The largest framing of P, with its vertex markers, whose picture stays on screen and
    clear of the title (at the top) and of the count (which it moves to the first of
    :data:`COUNT_PLACES` that leaves room). A thin triangle needs it: framed 9 × 5 about the
    centre, the counterexample's BEC stood 3 % of the frame high, a sliver; P's empty
    corners (above its edge E–A, below B–C) make room for the words beside a larger P."""
    words = [(place, _shape([title, count.to_corner(place)])) for place in COUNT_PLACES]
    span = np.ptp(np.asarray(polygon.points, dtype=float), axis=0)
    left, bottom, right, top = FRAME_AREA
    scale = min((right - left) / span[0], (top - bottom) / span[1])
    for _ in range(TRIES):
        for centre in CENTRES:
            frame = Frame(polygon.points, centre, scale * span[0], scale * span[1])
            found = _placed(polygon, frame, diagonals, words)
            if found is not None:
                count.to_corner(found[0])
                return frame, found[1]
        scale *= SCALE_STEP
    frame = Frame(polygon.points, center=(0, 0), width=9, height=5)
    count.to_corner(DOWN)
    return frame, placed_vertex_markers(polygon, frame, THEME, diagonals)


def _placed(polygon: Polygon, frame: Frame, diagonals: Sequence[tuple[int, int]],
            words: Sequence[tuple[np.ndarray, shapely.Geometry]]
            ) -> tuple[np.ndarray, VGroup] | None:
    """The first place of the count whose words the picture framed so keeps clear of, and
    the markers placed on it; None if there is none."""
    outline = shapely.Polygon([p[:2] for p in frame.many(polygon.points)]).buffer(DOT_ROOM)
    markers: VGroup | None = None  # placed only once the outline leaves the words room
    for place, taken in words:
        if not _fits(outline, taken):
            continue
        if markers is None:
            markers = placed_vertex_markers(polygon, frame, THEME, diagonals)
        if _fits(_shape([part for marker in markers for part in marker]), taken):
            return place, markers
    return None


class PolygonScene(SpecScene, Scene):
    algorithm = "cdt"  # the triangles it shows
    polygon = "counterexample"

    def construct(self):
        polygon = read_polygon(self.run_spec().polygon)
        self.camera.background_color = THEME.background
        cut = constrained_delaunay(polygon)
        # the title says what is drawn, in words (no arrow: on screen "→" is code's); the
        # count comes once the triangles are there
        title = glyphs(
            f"A simple polygon of {polygon.n} vertices, cut into triangles",
            font=THEME.font, size=THEME.caption_size, colour=THEME.ink,
        ).to_edge(UP)
        count = tag(text(f"n − 2 = {polygon.n} − 2 = {len(cut)} triangles",
                         font=THEME.font, size=THEME.caption_size, colour=THEME.result),
                    "result", "counter")
        # each label clear of the edges and of the triangles' sides to come, as a run's board
        # places them (E stood on edge BC, over the sliver BEC)
        n = polygon.n
        diagonals = sorted({(min(i, j), max(i, j)) for tri in cut for i, j in
                            zip(tri, (*tri[1:], tri[0]), strict=True) if (j - i) % n not in (1, n - 1)})
        frame, markers = framing(polygon, title, count, diagonals)
        self.play(Write(title), run_time=1)
        self.play(Create(tag(polygon_mobject(polygon, frame), "idle", "polygon")), run_time=1.5)
        for label, marker in zip(polygon.labels, markers, strict=True):
            tag(marker, "idle", f"vertex:{label}")
        self.play(FadeIn(markers), run_time=0.8)
        triangles = [[polygon.points[k] for k in tri] for tri in cut]
        # a finished triangulation's tints (metaphors.theme's legend), not the roles' colours
        for triangle in triangulation_pieces(triangles, frame.to_scene):
            self.play(FadeIn(triangle), run_time=0.6)
        self.play(FadeIn(count), run_time=0.8)
        self.wait(1.5)
