"""The picture the lecture's analysis plays on, and shapes drawn on it.

A :class:`Stage` is the polygon in a box of its own (no panel: the analysis has the screen),
its labels, T, a title, a legend and the subtitle; :meth:`Stage.say` plays animations under
one caption, held for its reading time by the scene's caption track (:mod:`metaphors.captions`).
:func:`region` and :func:`path` draw shapely shapes given in polygon coordinates (the ones
:mod:`story.analysis` computes); :func:`place_name` and :func:`beside` put a label where it
reads.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

import numpy as np
import shapely
from manim import Create, FadeIn, FadeOut, Line, Square, Transform, VGroup, VMobject, Write
from manim import Polygon as MPolygon

from geometry.polygon import Polygon
from metaphors.captions import whole_frames
from metaphors.drawing import Frame, polygon_mobject
from metaphors.labels import haloed, measured_markers
from metaphors.layout import (
    SUBTITLE_WIDTH,
    TITLE_Y,
    Box,
    area_of,
    ring_edges,
    subtitle_centre,
)
from metaphors.marks import mark_spot
from metaphors.recorded import captions_of, mark_step
from metaphors.tags import tag
from metaphors.theme import Theme
from rendering import typeset

#: where the polygon goes: the left two thirds, the legend to its right; its bottom high
#: enough that a label under its lowest vertex stays clear of a two-line subtitle (from 2.9
#: below the middle, chapter 2's "Parallel to AC, … / E is the farthest …" ran over C's
#: label at 176-182 s)
BOX = Box(-1.0, 0.15, 8.0, 5.1)
LEGEND = (3.6, 2.2)  # top left corner of the legend
#: what red is in a wrong heuristic's pass and in its run: the one legend entry for both
#: (its words narrow enough for the legend's column, from :data:`LEGEND` to the frame's margin)
OUTSIDE = "outside P, in T"
#: how far round a red line (a tool's part outside P, stroked thick) a marker counts as on it
RED_LINE_REACH = 0.04


class Stage:
    """The picture an analysis plays on — the polygon (turned by ``turn`` degrees), its
    labels (clear of the ``claims`` it will draw), T (``triangle``, if any), a title, the
    subtitle and a legend — and the one way it speaks: :meth:`say`."""

    def __init__(self, scene, points, labels, triangle, title: str, theme: Theme,
                 turn: float = 0.0, claims: Sequence[tuple[str, str]] = (), red=None):
        self.scene, self.theme = scene, theme
        self.polygon = Polygon(tuple(map(tuple, points)), tuple(labels),
                               tuple(range(len(labels))))
        self.frame = _fitted(self.polygon.points, turn)
        self.outline = tag(polygon_mobject(self.polygon, self.frame, theme), "idle",
                           "analysis:polygon")
        # the labels clear of the claims to come (``claims``: pairs of labels) as of the edges
        pairs = [(self.polygon.labels.index(u), self.polygon.labels.index(v)) for u, v in claims]
        # and of T's sides (D stood 0.08 from T's side AC in chapter 2's analyses)
        corners = self.frame.many(triangle) if triangle else []
        sides = [(corners[k - 1], corners[k]) for k in range(len(corners))]
        # and of the red region to come (``red``, shapely in P's coordinates: the part of a
        # wrong tool outside P), its outline as lines: the amber D stood on the red wedge, a
        # halo round it (chapter 2 at 56 s)
        sides += _outline_of(red, self.frame)
        self.markers = {label: tag(m, "idle", f"vertex:{label}").set_z_index(4) for label, m in
                        measured_markers(self.polygon, (), self.frame, theme, pairs, sides)}
        self.triangle = None
        if triangle:
            self.triangle = tag(MPolygon(*self.frame.many(triangle), color=theme.called,
                                         stroke_width=theme.thin_stroke, fill_opacity=0),
                                "called", "analysis:T").set_z_index(3)
        self.title = self._title(title)
        self.subtitle = None
        self.legend: list = []

    def _title(self, words: str):
        title = tag(typeset.glyphs(words, font=self.theme.font, size=30, colour=self.theme.ink,
                                   width=13.2), None, "analysis:title")
        return title.move_to((0, TITLE_Y, 0))

    def at(self, p) -> np.ndarray:
        return self.frame.to_scene(p)

    def vertex(self, label: str) -> np.ndarray:
        return self.at(self.polygon.points[self.polygon.labels.index(label)])

    def appear(self) -> list:
        """The animations that put the polygon, its labels, T and the title on screen; the
        picture the card before drew (the scene's ``carried``), moved into place first
        (:func:`hand_over`)."""
        carried, self.scene.carried = getattr(self.scene, "carried", None), None
        cut = hand_over(self.scene, carried, self.outline, list(self.markers.values()))
        anims = [Write(self.title), *(cut or [Create(self.outline), *[
            FadeIn(m) for m in self.markers.values()]])]
        return anims + ([Create(self.triangle)] if self.triangle is not None else [])

    def set_apart(self, red, line=None) -> list:
        """The transforms giving each marker that the red region ``red`` (shapely, polygon
        coordinates: a tool's sweep outside P) or the red ``line`` (its stroke) touches — its
        label or its dot — a dark halo: the vertex reads on the red, and the red round it
        (chapter 2's amber D, the pick, stood inside the red wedge, its dot on the wedge's
        edge: neither read)."""
        def on_screen(shape):
            return shapely.transform(shape, lambda xy: np.array([self.at(p)[:2] for p in xy]))

        shapes = [on_screen(red)]
        if line is not None:
            shapes.append(on_screen(line).buffer(RED_LINE_REACH))
        touched = shapely.union_all(shapes)
        return [Transform(marker, haloed(marker, self.theme.background, dot=True))
                for marker in self.markers.values()
                if any(touched.intersects(shapely.box(*area_of(part))) for part in marker)]

    def retitle(self, words: str) -> list:
        new = self._title(words)
        old, self.title = self.title, new
        return [FadeOut(old), FadeIn(new)]

    def say(self, caption: str, *plays: tuple[list, float]) -> None:
        """Plays under one caption, shown at the bottom and as the cue, once the caption
        before it has been read (the scene's caption track holds it,
        :mod:`metaphors.captions`); this one is held in turn before the next, or before the
        screen is cleared."""
        words = self._words(caption)
        (first, first_time), *rest = plays
        first_time = max(first_time, 0.3)
        cue = captions_of(self.scene).show(caption, first_time)  # may wait for the one before
        mark_step(self.scene, caption, kind="analysis")
        if self.subtitle is not None:  # read: a cut, so two subtitles are never up at once
            self.scene.remove(self.subtitle)
        self.subtitle = words
        self.scene.play(FadeIn(words), *first, run_time=first_time, **cue)
        for anims, run_time in rest:
            if anims:
                self.scene.play(*anims, run_time=run_time)
            else:
                self.scene.wait(whole_frames(run_time))

    def _words(self, caption: str):
        """The subtitle: one line, or two balanced ones (:func:`rendering.typeset.balanced`)."""
        words = typeset.balanced(caption, font=self.theme.font, size=self.theme.caption_size,
                                 colour=self.theme.ink, width=SUBTITLE_WIDTH)
        return tag(words, None, "subtitle").move_to(subtitle_centre(words.height))

    def key(self, colour: str, words: str, name: str, opacity: float = 0.45) -> list:
        """A legend entry (:func:`legend_entry`) below the ones shown."""
        x, y = LEGEND[0], LEGEND[1] - 0.55 * len(self.legend)
        key = legend_entry(self.theme, colour, words, name, opacity).shift((x, y, 0))
        self.legend.append(key)
        return [FadeIn(key)]

    def forget_key(self, name: str) -> list:
        """Take the legend entry ``name`` off (the entries below it do not move up: it is
        the last one shown when it is taken off)."""
        gone = [k for k in self.legend if k.name == f"legend:{name}"]
        self.legend = [k for k in self.legend if k not in gone]
        return [FadeOut(m) for m in gone]

    def forget_legend(self) -> list:
        gone, self.legend = self.legend, []
        return [FadeOut(m) for m in gone]


def legend_entry(theme: Theme, colour: str, words: str, name: str, opacity: float = 0.45
                 ) -> VGroup:
    """A legend entry: a swatch of ``colour`` and its words to its right, the swatch's
    left-middle at the origin (an analysis's legend, a run's "outside P, in T")."""
    swatch = Square(0.3, color=colour, stroke_width=theme.thin_stroke, fill_color=colour,
                    fill_opacity=opacity).move_to((0.15, 0, 0))
    label = typeset.text(words, font=theme.font, size=theme.label_size, colour=theme.ink)
    label.next_to(swatch, direction=np.array([1.0, 0, 0]), buff=0.18)
    return tag(VGroup(swatch, label), None, f"legend:{name}")


def _outline_of(shape, frame: Frame) -> list[tuple[np.ndarray, np.ndarray]]:
    """The sides of a shapely region's outlines (P's coordinates), on screen."""
    if shape is None or shape.is_empty:
        return []
    parts = getattr(shape, "geoms", [shape])
    found = []
    for part in parts:
        ring = [frame.to_scene(p) for p in list(part.exterior.coords)[:-1]] \
            if hasattr(part, "exterior") else []
        found += [(ring[k - 1], ring[k]) for k in range(len(ring))]
    return found


def _fitted(points, angle: float) -> Frame:
    """The frame of :data:`BOX`, turned by ``angle`` degrees and zoomed to fit it."""
    frame = Frame(points, BOX.center, BOX.width, BOX.height)
    if not angle:
        return frame
    turned = np.array(frame.turned(angle, BOX.center).many(points))[:, :2] - np.array(BOX.center)
    reach = np.abs(turned).max(axis=0)
    zoom = min(1.0, BOX.width / 2 / max(reach[0], 1e-9), BOX.height / 2 / max(reach[1], 1e-9))
    return frame.turned(angle, BOX.center, zoom)


# --- one picture per idea: a picture handed on to the next segment ------------------------------


def _at_the_end(t: float) -> float:
    """A rate that holds still until the animation's last frame (a fade that is a cut)."""
    return 1.0 if t >= 1.0 else 0.0


def _at_once(t: float) -> float:
    """A rate at its end from the first frame (a fade that is a cut)."""
    return 1.0


def hand_over(scene, carried, polygon, markers: Sequence, shown: Sequence = ()) -> list:
    """The picture the last segment left (``carried``: its polygon, its vertex markers in
    the polygon's order, and the mobjects on screen that hold them) moved and grown into the
    place of the new ``polygon`` and ``markers`` (played here), then given up to them:
    returns the cut for the new picture's first play (the new ones in, ``shown`` if they
    come as a group, the carried ones out: the same drawing in the same place).
    Nothing if nothing is carried or it is not this picture: the new one comes as usual. One
    picture per idea: chapter 2's card drew the counterexample small, faded it, and its pass
    drew it again full size (review, 20-30 s)."""
    if carried is None:
        return []
    old_polygon, old_markers, holders = carried
    if len(old_markers) != len(markers):
        return []
    scene.play(Transform(old_polygon, polygon.copy()),
               *[Transform(old, new.copy()) for old, new in zip(old_markers, markers,
                                                                 strict=True)],
               run_time=1.2)
    return [*[FadeIn(m, rate_func=_at_once) for m in (polygon, *(shown or markers))],
            *[FadeOut(m, rate_func=_at_the_end) for m in holders]]


# --- shapes as mobjects ---------------------------------------------------------------------------


class Canvas(Protocol):
    """Where shapes are drawn: a frame (polygon to scene coordinates) and a theme — a
    :class:`Stage`, or a card's figure (:mod:`metaphors.figure_metaphors`)."""

    @property
    def frame(self) -> Frame: ...

    @property
    def theme(self) -> Theme: ...


def region(stage: Canvas, geometry, colour: str, opacity: float, name: str,
           role: str | None = None) -> VGroup:
    """The polygons of a shapely geometry (polygon coordinates), filled."""
    group = VGroup(*[
        MPolygon(*stage.frame.many(list(part.exterior.coords)[:-1]), color=colour,
                 stroke_width=stage.theme.thin_stroke, stroke_opacity=min(1.0, 2 * opacity),
                 fill_color=colour, fill_opacity=opacity)
        for part in shapely.get_parts(geometry) if part.geom_type == "Polygon"])
    return tag(_never_empty(stage, group), role, name)


def path(stage: Canvas, geometry, colour: str, width: float, name: str,
         role: str | None = None, opacity: float = 1.0) -> VGroup:
    """The lines of a shapely geometry (polygon coordinates), stroked."""
    group = VGroup()
    for part in shapely.get_parts(geometry):
        if part.geom_type in ("LineString", "LinearRing") and part.length > 0:
            line = VMobject(stroke_color=colour, stroke_width=width, stroke_opacity=opacity)
            line.set_points_as_corners(stage.frame.many(list(part.coords)))
            group.add(line)
    return tag(_never_empty(stage, group), role, name)


def _never_empty(stage: Canvas, group: VGroup) -> VGroup:
    """At least one (invisible) piece: ``become`` needs something to become."""
    if not group.submobjects:
        at = stage.frame.center
        group.add(Line(at, at, stroke_opacity=0))
    return group


# --- labels --------------------------------------------------------------------------------------


#: the least gap an edge's name keeps from the fills it is kept off (3 % of the frame's height)
NAME_OFF = 0.24


def place_name(stage: Stage, name, a, b, avoid: Sequence = (), off=None) -> None:
    """Put an edge's name beside it (a to b, scene points), where it keeps clearest of the
    polygon's edges, the vertices and their labels, and the lines in ``avoid``; ``off``
    (shapely, on screen: the red "outside P" region) and P's fill kept :data:`NAME_OFF` away,
    where such a place is within reach ("edge E–A" stood in T's thin corridor 0.14 from the
    red wedge, read as written on it: chapter 2 at 56 s)."""
    corners = [tuple(p[:2]) for p in stage.frame.many(stage.polygon.points)]
    lines = [shapely.LineString([corners[k - 1], corners[k]]) for k in range(len(corners))]
    lines += [shapely.LineString([tuple(m.get_start()[:2]), tuple(m.get_end()[:2])])
              for m in avoid]
    marks = [shapely.box(*m.get_corner(np.array([-1, -1, 0]))[:2],
                         *m.get_corner(np.array([1, 1, 0]))[:2]).buffer(0.05)
             for marker in stage.markers.values() for m in marker]
    busy = shapely.union_all([*lines, *marks])
    edge = shapely.LineString([tuple(a[:2]), tuple(b[:2])])
    direction = (b - a) / max(float(np.linalg.norm(b - a)), 1e-9)
    normal = np.array([-direction[1], direction[0], 0.0])
    half = np.array([name.width / 2, name.height / 2])

    def box(centre) -> shapely.Polygon:
        return shapely.box(*(centre[:2] - half), *(centre[:2] + half))

    spots = [a + (b - a) * k + normal * side * (gap + float(np.abs(normal[:2]) @ half))
             for k in (0.2, 0.35, 0.5, 0.65, 0.8) for side in (1, -1)
             for gap in (0.15, 0.4, 0.7, 1.0)]
    fills = shapely.union_all([shapely.Polygon(corners), *([off] if off is not None else [])])
    left, bottom = BOX.x - BOX.width / 2, BOX.y - BOX.height / 2
    room = shapely.box(left, bottom, left + BOX.width, bottom + BOX.height)
    clear = [p for p in spots if box(p).distance(fills) >= NAME_OFF and room.contains(box(p))]
    best = max(clear or spots, key=lambda p: min(box(p).distance(busy), 0.3)
               - 0.2 * box(p).distance(edge))
    name.move_to(best)


def beside(stage: Stage, mark, line, region_) -> None:
    """Put a mark beside a line, off a shaded region (given in the polygon's coordinates)
    and clear of every edge (the polygon's, T's) and label (:func:`metaphors.marks.mark_spot`)."""
    ring = [stage.vertex(label) for label in stage.polygon.labels]
    edges = ring_edges(ring)
    if stage.triangle is not None:
        edges += ring_edges(list(stage.triangle.get_vertices()))
    labels = [area_of(part) for marker in stage.markers.values() for part in marker]
    shaded = shapely.transform(region_, lambda xy: np.array([stage.at(p)[:2] for p in xy]))
    mark.move_to(mark_spot((mark.width, mark.height), (line.get_start(), line.get_end()),
                           edges, labels, shapely.Polygon([p[:2] for p in ring]), BOX,
                           avoid=shaded))
