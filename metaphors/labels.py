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

import numpy as np
from manim import Dot, VGroup

from geometry.polygon import Polygon
from metaphors.drawing import Frame
from metaphors.theme import THEME, Theme
from rendering import typeset

#: the least gap (scene units) between a label and an edge, a dot or another label
MARGIN = 0.05
#: the first distance tried from the vertex to the label's centre, and the farthest
NEAREST, FARTHEST, STEP = 0.26, 0.62, 0.04
#: the turns tried away from the bisector (degrees), nearest first
TURNS = (0, 20, -20, 40, -40, 60, -60, 90, -90, 120, -120, 150, -150)

Box = tuple[float, float, float, float]  # left, bottom, right, top
Segment = tuple[np.ndarray, np.ndarray]


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


def box_gap(box: Box, a: np.ndarray, b: np.ndarray) -> float:
    """The distance between a box and the segment ``a``–``b`` (0 when they meet)."""
    left, bottom, right, top = box
    if _crosses_box(box, a, b):
        return 0.0
    corners = [np.array(c) for c in ((left, bottom), (right, bottom), (right, top), (left, top))]
    ends = min(_box_point_gap(box, p) for p in (a[:2], b[:2]))
    return min(ends, *(_point_segment_gap(c, a[:2], b[:2]) for c in corners))


def boxes_gap(one: Box, other: Box) -> float:
    """The distance between two boxes (0 when they meet or overlap)."""
    dx = max(other[0] - one[2], one[0] - other[2], 0.0)
    dy = max(other[1] - one[3], one[1] - other[3], 0.0)
    return float(np.hypot(dx, dy))


def _box_point_gap(box: Box, p: np.ndarray) -> float:
    dx = max(box[0] - p[0], p[0] - box[2], 0.0)
    dy = max(box[1] - p[1], p[1] - box[3], 0.0)
    return float(np.hypot(dx, dy))


def _point_segment_gap(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    d = b - a
    t = float(np.clip(np.dot(p - a, d) / max(float(np.dot(d, d)), 1e-18), 0.0, 1.0))
    return float(np.linalg.norm(p - a - t * d))


def _crosses_box(box: Box, a: np.ndarray, b: np.ndarray) -> bool:
    """Whether the segment meets the box (Liang–Barsky clipping)."""
    t0, t1 = 0.0, 1.0
    d = b[:2] - a[:2]
    for p, q in ((-d[0], a[0] - box[0]), (d[0], box[2] - a[0]),
                 (-d[1], a[1] - box[1]), (d[1], box[3] - a[1])):
        if abs(p) < 1e-12:
            if q < 0:
                return False
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return False
    return True


def _box(centre: np.ndarray, size: tuple[float, float]) -> Box:
    w, h = size
    return (centre[0] - w / 2, centre[1] - h / 2, centre[0] + w / 2, centre[1] + h / 2)


def _turned(d: np.ndarray, degrees: float) -> np.ndarray:
    t = np.radians(degrees)
    return np.array([np.cos(t) * d[0] - np.sin(t) * d[1], np.sin(t) * d[0] + np.cos(t) * d[1]])


def place_labels(corners: Sequence[np.ndarray], sizes: Sequence[tuple[float, float]],
                 segments: Sequence[Segment], dot: float = THEME.dot_radius) -> list[np.ndarray]:
    """The centre of each corner's label (``sizes``: each label's width and height): the
    nearest to its corner, and then to its bisector, that keeps :data:`MARGIN` from every
    edge of the polygon, every segment of ``segments`` (diagonals drawn), every dot and every
    label placed before; the bisector's nearest place if none does. Deterministic."""
    n = len(corners)
    pts = [np.asarray(c, dtype=float)[:2] for c in corners]
    lines = [(pts[k], pts[(k + 1) % n]) for k in range(n)]
    lines += [(np.asarray(a, dtype=float)[:2], np.asarray(b, dtype=float)[:2]) for a, b in segments]
    placed: list[Box] = []
    centres = []
    for k in range(n):
        d = outward(pts[k - 1], pts[k], pts[(k + 1) % n])
        centre = _first_clear(pts, k, d, sizes[k], lines, placed, dot)
        centre = pts[k] + d * NEAREST if centre is None else centre
        placed.append(_box(centre, sizes[k]))
        centres.append(centre)
    return centres


def _first_clear(pts: list[np.ndarray], k: int, d: np.ndarray, size: tuple[float, float],
                 lines: list[Segment], placed: list[Box], dot: float) -> np.ndarray | None:
    steps = round((FARTHEST - NEAREST) / STEP) + 1
    for r in (NEAREST + STEP * i for i in range(steps)):
        for turn in TURNS:
            centre = pts[k] + _turned(d, turn) * r
            box = _box(centre, size)
            if all(box_gap(box, a, b) >= MARGIN for a, b in lines) \
                    and all(_box_point_gap(box, p) >= dot + MARGIN for p in pts) \
                    and all(boxes_gap(box, other) >= MARGIN for other in placed):
                return centre
    return None


def placed_vertex_markers(polygon: Polygon, frame: Frame, theme: Theme = THEME,
                          diagonals: Sequence[tuple[int, int]] = ()) -> VGroup:
    """A dot and a label per vertex, as :func:`metaphors.drawing.vertex_markers` draws them,
    each label placed by :func:`place_labels` (clear of the edges and of ``diagonals``, pairs
    of vertex indices drawn on the picture)."""
    corners = frame.many(polygon.points)
    texts = [typeset.text(label, font=theme.font, size=theme.label_size, colour=theme.ink)
             for label in polygon.labels]
    segments = [(corners[i], corners[j]) for i, j in diagonals]
    centres = place_labels(corners, [(t.width, t.height) for t in texts], segments,
                           theme.dot_radius)
    group = VGroup()
    for at, text, centre in zip(corners, texts, centres, strict=True):
        text.move_to((centre[0], centre[1], 0.0))
        group.add(VGroup(Dot(at, radius=theme.dot_radius, color=theme.ink), text))
    return group


__all__ = ["MARGIN", "box_gap", "boxes_gap", "outward", "place_labels", "placed_vertex_markers"]
