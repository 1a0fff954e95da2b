"""Vertex labels placed by measuring: each outside its vertex along the angle's bisector,
turned or pushed further out until it touches no edge, no dot and no label placed before.

:func:`metaphors.drawing.vertex_markers` puts a label a fixed step away from the polygon's
centre, which crowds the labels of a needle or a notch and can lay one on an edge; the
exercises, read by a class with no run to explain them, place theirs here.

>>> corners = [np.array(p, dtype=float) for p in [(0, 0), (4, 0), (4, 3), (0, 3)]]
>>> at = place_labels(corners, [(0.2, 0.2)] * 4, [])
>>> [tuple(round(float(c), 2) for c in p) for p in at]  # out along each corner's bisector
[(-0.18, -0.18), (4.18, -0.18), (4.18, 3.18), (-0.18, 3.18)]
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import pairwise

import numpy as np
from manim import Dot, Mobject, VGroup

from geometry.polygon import Polygon
from metaphors.drawing import Frame
from metaphors.layout import (
    Obstacles,
    Rect,
    Segment,
    around,
    clear,
    first_clear,
    rects_at,
    ring_edges,
)
from metaphors.theme import THEME, Theme
from rendering import typeset
from story.beats import Hole

#: the least gap (scene units) between a label and an edge, a dot or another label
MARGIN = 0.05
#: the first distance tried from the vertex to the label's centre, and the farthest
NEAREST, FARTHEST, STEP = 0.26, 0.62, 0.04
#: the turns tried away from the bisector (degrees), nearest first
TURNS = (0, 20, -20, 40, -40, 60, -60, 90, -90, 120, -120, 150, -150)



def outward(before: np.ndarray, at: np.ndarray, after: np.ndarray) -> np.ndarray:
    """The unit vector out of a counter-clockwise polygon at vertex ``at`` along the bisector
    of its angle (through the outside)."""
    u, w = before[:2] - at[:2], after[:2] - at[:2]
    u, w = u / np.linalg.norm(u), w / np.linalg.norm(w)
    s = u + w
    if np.linalg.norm(s) < 1e-9:  # a straight angle: the outside is right of the way on
        d = after[:2] - before[:2]
        return np.array([d[1], -d[0]]) / np.linalg.norm(d)
    convex = (at[0] - before[0]) * (after[1] - at[1]) - (at[1] - before[1]) * (after[0] - at[0]) > 0
    return -s / np.linalg.norm(s) if convex else s / np.linalg.norm(s)


def _turned(d: np.ndarray, degrees: float) -> np.ndarray:
    t = np.radians(degrees)
    return np.array([np.cos(t) * d[0] - np.sin(t) * d[1], np.sin(t) * d[0] + np.cos(t) * d[1]])


#: the distances tried from a vertex to its label's centre, nearest first
RADII = tuple(round(NEAREST + STEP * i, 6) for i in range(round((FARTHEST - NEAREST) / STEP) + 1))


def place_labels(corners: Sequence[np.ndarray], sizes: Sequence[tuple[float, float]],
                 segments: Sequence[Segment], dot: float = THEME.dot_radius) -> list[np.ndarray]:
    """The centre of each corner's label (``sizes``: each label's width and height): the
    nearest to its corner, and then to its bisector, that keeps :data:`MARGIN` from every
    edge of the polygon, every segment of ``segments`` (diagonals drawn), every dot and every
    label placed before; the bisector's nearest place if none does. Deterministic."""
    return place_ring_labels([corners], sizes, segments, dot)


def place_ring_labels(rings: Sequence[Sequence[np.ndarray]], sizes: Sequence[tuple[float, float]],
                      segments: Sequence[Segment], dot: float = THEME.dot_radius,
                      first: Sequence[np.ndarray] | None = None) -> list[np.ndarray]:
    """:func:`place_labels` for a polygon of several rings (its outer ring, then its holes':
    ``sizes`` and ``first`` run over their vertices in that order): each label clear of every
    ring's edges and dots. ``first``: a place to try for each label before the measured ones
    (where a label has always stood, if it is clear); the first of those if none is."""
    pts = [[np.asarray(c, dtype=float)[:2] for c in ring] for ring in rings]
    edges: list[Segment] = [edge for ring in pts for edge in ring_edges(ring)]
    edges += [(np.asarray(a, dtype=float)[:2], np.asarray(b, dtype=float)[:2]) for a, b in segments]
    base = Obstacles(segments=edges, dots=[(float(p[0]), float(p[1]), dot)
                                           for ring in pts for p in ring])
    placed: list[Rect] = []
    centres = []
    for k, (ring, i) in enumerate([(r, i) for r in pts for i in range(len(r))]):
        d = outward(ring[i - 1], ring[i], ring[(i + 1) % len(ring)])
        tried = around([ring[i]], [_turned(d, turn) for turn in TURNS], RADII)
        if first is not None:
            tried = np.vstack([np.asarray(first[k], dtype=float)[:2], tried])
        found = first_clear(tried, sizes[k], base.plus(boxes=placed), MARGIN)
        centre = tried[found] if found is not None else (
            tried[0] if first is not None else ring[i] + d * NEAREST)
        placed.append(tuple(rects_at(centre, sizes[k])[0]))
        centres.append(centre)
    return centres


def placed_vertex_markers(polygon: Polygon, frame: Frame, theme: Theme = THEME,
                          diagonals: Sequence[tuple[int, int]] = (),
                          lines: Sequence[Sequence[tuple[float, float]]] = ()) -> VGroup:
    """A dot and a label per vertex, as :func:`metaphors.drawing.vertex_markers` draws them,
    each label placed by :func:`place_labels` (clear of the edges, of ``diagonals``, pairs
    of vertex indices drawn on the picture, and of ``lines``, polylines in P's units drawn
    on it too)."""
    corners = frame.many(polygon.points)
    texts = [typeset.text(label, font=theme.font, size=theme.label_size, colour=theme.ink)
             for label in polygon.labels]
    segments = [(corners[i], corners[j]) for i, j in diagonals]
    for line in lines:
        drawn = frame.many(list(line))
        segments += list(pairwise(drawn))
    centres = place_labels(corners, [(t.width, t.height) for t in texts], segments,
                           theme.dot_radius)
    group = VGroup()
    for at, text, centre in zip(corners, texts, centres, strict=True):
        text.move_to((centre[0], centre[1], 0.0))
        group.add(VGroup(Dot(at, radius=theme.dot_radius, color=theme.ink), text))
    return group


def measured_markers(polygon: Polygon, holes: Sequence[Hole], frame: Frame,
                     theme: Theme = THEME, diagonals: Sequence[tuple[int, int]] = ()
                     ) -> list[tuple[str, VGroup]]:
    """(label, dot and label) for every vertex of the board's polygon and of its holes, each
    label where :func:`metaphors.drawing.vertex_markers` and
    :func:`metaphors.drawing.hole_markers` put it (a fixed step away from its ring's centre)
    if that is clear, else in the first clear place round its vertex
    (:func:`place_ring_labels`): an edge through a label reads as part of the line. Likewise
    clear of ``diagonals`` (pairs of the polygon's vertex indices: the claims a picture will
    draw, which its labels are placed before)."""
    rings = [frame.many(polygon.points), *(frame.many(h.points) for h in holes)]
    names = [*polygon.labels, *(label for h in holes for label in h.labels)]
    # lower-case letters stand lower than capitals: a size larger keeps them 2.5 % high
    steps = [(0.32, theme.label_size)] * polygon.n + [
        (0.3, theme.label_size + 4)] * (len(names) - polygon.n)
    texts = [typeset.text(name, font=theme.font, size=size, colour=theme.ink)
             for name, (_, size) in zip(names, steps, strict=True)]
    first: list[np.ndarray] = []
    for ring in rings:
        centre = np.mean(ring, axis=0)
        for point in ring:
            away = (point - centre)[:2]
            norm = float(np.linalg.norm(away))
            first.append(point[:2] + (away / norm if norm > 1e-9 else np.array([0.0, -1.0]))
                         * steps[len(first)][0])
    segments = [(rings[0][i], rings[0][j]) for i, j in diagonals]
    centres = place_ring_labels(rings, [(t.width, t.height) for t in texts], segments,
                                theme.dot_radius, first=first)
    points = [point for ring in rings for point in ring]
    markers = []
    for name, at, text, centre in zip(names, points, texts, centres, strict=True):
        text.move_to((centre[0], centre[1], 0.0))
        markers.append((name, VGroup(Dot(at, radius=theme.dot_radius, color=theme.ink), text)))
    return markers


def crossed_labels(rings: Sequence[Sequence[str]], markers: dict[str, VGroup],
                   drawn: Sequence[Segment], new: Sequence[Segment],
                   dot: float = THEME.dot_radius, apart: float = MARGIN) -> dict[str, np.ndarray]:
    """The labels that the ``new`` segments come within :data:`MARGIN` of, each with a new
    centre: the first clear place round its vertex (:func:`place_ring_labels`' order: out
    along the bisector of its ring, each ring a list of labels, their dots where the markers
    stand now), clear of the segments ``drawn`` (the edges, the lines on the picture) and
    ``new``, of the dots and of the other labels (``apart`` from those: more than
    :data:`MARGIN` where labels crowd); a label with no clear place stays."""
    at = {name: np.asarray(m[0].get_center(), dtype=float)[:2] for name, m in markers.items()}
    boxes = {name: tuple(rects_at(m[1].get_center()[:2], (m[1].width, m[1].height))[0])
             for name, m in markers.items() if len(m) > 1}
    lines = Obstacles(segments=[(np.asarray(a, float)[:2], np.asarray(b, float)[:2])
                                for a, b in new])
    base = Obstacles(segments=[*drawn, *new],
                     dots=[(float(p[0]), float(p[1]), dot) for p in at.values()])
    moved: dict[str, np.ndarray] = {}
    for ring in rings:
        for i, name in enumerate(ring):
            if name not in boxes or lines.gaps(np.array([boxes[name]]))[0] >= MARGIN:
                continue
            size = (boxes[name][2] - boxes[name][0], boxes[name][3] - boxes[name][1])
            d = outward(at[ring[i - 1]], at[name], at[ring[(i + 1) % len(ring)]])
            tried = around([at[name]], [_turned(d, turn) for turn in TURNS], RADII)
            others = [box for other, box in boxes.items() if other != name]
            ok = (clear(tried, size, base, MARGIN)
                  & clear(tried, size, Obstacles(boxes=others), apart))
            found = int(np.argmax(ok)) if ok.any() else None
            if found is not None:
                moved[name] = tried[found]
                boxes[name] = tuple(rects_at(tried[found], size)[0])
    return moved


__all__ = ["MARGIN", "crossed_labels", "measured_markers", "outward", "place_labels",
           "place_ring_labels", "placed_vertex_markers"]


def drawn_in(marker: Mobject, colour: str) -> bool:
    """Whether every part of a vertex marker (its dot, its label) is drawn in ``colour``."""
    return all(part.get_color().to_hex().lower() == colour.lower() for part in marker)
