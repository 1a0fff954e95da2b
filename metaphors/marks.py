"""Where a verdict's mark (✓ or ✗) goes: beside its claim, clear of every edge and label.

A mark over an edge or a label reads as part of the picture (a ✓ on edge BC seems to judge
BC). It goes beside the middle of the claim it judges, inside the polygon if there is room
there, else outside it, farther off, and always at least :data:`MARK_GAP` from every edge
drawn (the polygon's, the diagonals', the claim itself) and from every label; the first such place in a
fixed order, so a run places it the same way every time.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence

import numpy as np
import shapely
from manim import DL, UR, Line, Mobject

from metaphors.board import Board
from metaphors.layout import Box, Obstacles, around, clear, rects_at, ring_edges

#: 2.5 % of the frame's height: the gap a mark keeps (the reading rule asks for 2 %)
MARK_GAP = 0.2
#: how far along its claim a mark may stand (fractions of it, the middle first)
ALONG = (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8)
#: the distances from the claim tried, beyond the mark's own half size (scene units)
AWAY = tuple(np.round(np.arange(0.05, 2.5, 0.05), 6))

Point = Sequence[float] | np.ndarray
Segment = tuple[Point, Point]
Area = tuple[float, float, float, float]  # left, bottom, right, top


def mark_spot(size: tuple[float, float], claim: Segment, edges: Iterable[Segment],
              labels: Iterable[Area], inside: shapely.Geometry, within: Box,
              avoid: shapely.Geometry | None = None) -> np.ndarray:
    """The centre for a mark ``size`` (width, height) judging ``claim``: the first place, in
    the order inside ``inside`` before outside it, nearest the claim, nearest its middle, on
    its left before its right, that stays in ``within``, :data:`MARK_GAP` from the claim,
    every edge and every label (twice that outside ``inside``), and off ``avoid`` (a shaded
    region) where it can be inside ``inside``: a mark just outside P seems to judge the edge
    it stands by, so a place inside P over the shading comes before any outside it; if there
    is none, the place of those that keeps the most gap (:func:`metaphors.layout.around`)."""
    a, b = np.asarray(claim[0], dtype=float)[:2], np.asarray(claim[1], dtype=float)[:2]
    along = b - a
    normal = np.array([-along[1], along[0]]) / max(float(np.linalg.norm(along)), 1e-9)
    reach = float(np.linalg.norm(np.array(size, dtype=float) / 2))
    centres = around([a + t * along for t in ALONG], [normal, -normal],
                     [reach + away for away in AWAY])
    rects = rects_at(centres, size)
    boxes = shapely.box(rects[:, 0], rects[:, 1], rects[:, 2], rects[:, 3])
    obstacles = Obstacles(boxes=list(labels), segments=[(a, b), *edges])
    gap = obstacles.gaps(rects)
    left, bottom = within.x - within.width / 2, within.y - within.height / 2
    framed = clear(centres, size, Obstacles(), 0.0,
                   (left, bottom, left + within.width, bottom + within.height))
    held = shapely.contains(inside, boxes)
    # outside P, twice as far: a mark just past an edge seems to judge that edge
    free = framed & (gap >= np.where(held, MARK_GAP, 2 * MARK_GAP))
    shaded = (shapely.intersects(boxes, avoid) if avoid is not None and not avoid.is_empty
              else np.zeros(len(centres), dtype=bool))
    if not (free & held).any():  # no room inside P across the claim: any way round it
        inner = _inside_round(size, (a, b), obstacles, inside, within, reach)
        if inner is not None:
            return inner
    if not free.any():
        return np.array([*centres[int(np.argmax(np.where(framed, gap, -1.0)))], 0.0])
    # the order of :func:`around` is the first-fit order: nearest, middle first, left first
    best = min(np.flatnonzero(free), key=lambda k: (not held[k], bool(shaded[k]), k))
    return np.array([*centres[best], 0.0])


#: the farthest from its claim a mark goes round it to stand inside P (else it stands
#: outside, across the claim: far off inside, it seems to judge something else)
INSIDE_REACH = 0.6
#: the directions tried round a claim's points when there is no room across it (every 15°)
ROUND = tuple((float(np.cos(t)), float(np.sin(t))) for t in np.radians(np.arange(0, 360, 15)))


def _inside_round(size: tuple[float, float], claim: tuple[np.ndarray, np.ndarray],
                  obstacles: Obstacles, inside: shapely.Geometry, within: Box,
                  reach: float) -> np.ndarray | None:
    """The place inside ``inside``, :data:`MARK_GAP` clear of ``obstacles`` and in
    ``within``, nearest the claim and at most :data:`INSIDE_REACH` from it, among places in
    every direction (:data:`ROUND`) round its points (:data:`ALONG`); None if there is none. A short claim in a crowded corner (prune
    and search's GB) has no room inside P straight across it, and its mark stood outside P,
    1.8 from it, beside another edge."""
    a, b = claim
    points = [a + t * (b - a) for t in ALONG]
    centres = around(points, ROUND, [reach + away for away in AWAY])
    rects = rects_at(centres, size)
    boxes = shapely.box(rects[:, 0], rects[:, 1], rects[:, 2], rects[:, 3])
    left, bottom = within.x - within.width / 2, within.y - within.height / 2
    line = shapely.LineString([a, b])
    near = shapely.distance(boxes, line)
    ok = (clear(centres, size, obstacles, MARK_GAP,
                (left, bottom, left + within.width, bottom + within.height))
          & shapely.contains(inside, boxes) & (near <= INSIDE_REACH))
    if not ok.any():
        return None
    best = min(np.flatnonzero(ok), key=lambda k: (round(float(near[k]), 6), k))
    return np.array([*centres[best], 0.0])


def area_of(mobject: Mobject, moved: Callable[[np.ndarray], np.ndarray] | None = None) -> Area:
    """A mobject's box on screen (``moved``: where its centre goes; its size stays)."""
    low, high = mobject.get_corner(DL), mobject.get_corner(UR)
    centre = (low + high) / 2
    shift = (moved(centre) - centre) if moved is not None else np.zeros(3)
    return (float(low[0] + shift[0]), float(low[1] + shift[1]),
            float(high[0] + shift[0]), float(high[1] + shift[1]))


def board_spot(board: Board, mark: Mobject, line: Mobject,
               moved: Callable[[np.ndarray], np.ndarray] | None = None) -> np.ndarray:
    """Where a run's verdict ``mark`` on the claim ``line`` goes on its board (:func:`mark_spot`):
    clear of the outline's edges (its holes' too: the largest ring is the outer one), the
    diagonals drawn and the vertex labels.
    ``moved``: where each point of the picture ends (a turn under way), None: as it is."""
    def end(p: np.ndarray) -> np.ndarray:
        return moved(p) if moved is not None else p

    # the outline as drawn, not P: ear clipping's fruit shrinks as its slices go
    rings = [[end(p) for p in ring] for ring in board.outline_rings()]
    edges = [edge for ring in rings for edge in ring_edges(ring)]
    edges += [(end(m.get_start()), end(m.get_end())) for key, m in board.objects.items()
              if key.startswith("diagonal:") and isinstance(m, Line)]
    labels = [area_of(part, moved) for marker in board.markers.values()
              for part in marker.submobjects]
    inside = shapely.Polygon([p[:2] for p in rings[0]], [[p[:2] for p in r] for r in rings[1:]])
    return mark_spot((mark.width, mark.height), (end(line.get_start()), end(line.get_end())),
                     edges, labels, inside, board.box)
