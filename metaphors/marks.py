"""Where a verdict's mark (✓ or ✗) goes: beside its claim, clear of every edge and label.

A mark over an edge or a label reads as part of the picture (a ✓ on edge BC seems to judge
BC), and one past an edge seems to judge that edge. It goes beside the middle of the claim it
judges, inside the polygon if there is room there; else in the place inside the polygon
nearest the claim's middle (a claim along a thin spike has no room beside it), a little
smaller if it must (never under :data:`LEAST_SCALE` of its size), within :data:`MARK_REACH`
of the claim, or over the claim itself, where that finds a place; only where the polygon has
no room for it at all, outside it, farther off; always at least :data:`MARK_GAP` from every
edge drawn (the polygon's, the diagonals', the claim itself) and from every label (inside,
:data:`LEAST_GAP` where nothing else fits). The first such place in a fixed order
(:mod:`metaphors.layout`'s candidates and :func:`metaphors.layout.clear`), so a run places it
the same way every time.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence

import numpy as np
import shapely
from manim import Line, Mobject

from metaphors.board import Board
from metaphors.layout import (
    Box,
    Obstacles,
    area_of,
    around,
    clear,
    grid,
    rects_at,
    ring_edges,
)

#: 2.5 % of the frame's height: the gap a mark keeps (the reading rule asks for 2 %)
MARK_GAP = 0.2
#: the least gap a mark inside the polygon keeps where nothing keeps :data:`MARK_GAP` (2 %
#: of the frame's height, the reading rule's)
LEAST_GAP = 0.16
#: the smallest a mark is drawn (of its size) to fit inside a thin polygon: a ✓ of 48 points
#: stays 3 % of the frame's height
LEAST_SCALE = 0.7
#: the scales tried, largest first
SCALES = (1.0, 0.85, LEAST_SCALE)
#: the farthest a mark stands from its claim where a place that near is found (3.75 % of
#: the frame's height: the reading rule asks for 5 %): farther, it seems to judge nothing
MARK_REACH = 0.3
#: the least gap a mark keeps beside its claim where labels and diagonals crowd it: nearer
#: anything else than its claim, it reads as theirs; farther off, as judging nothing
CROWDED_GAP = LEAST_GAP
#: the farthest a mark stands from its claim, beside it: farther, it judges nothing
MARK_FARTHEST = 0.4
#: the grid the place inside the polygon nearest the claim is looked for on (scene units)
STEP = 0.05
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
    it stands by, so a place inside P over the shading comes before any outside it. With no
    such place beside the claim inside ``inside``, the place inside it nearest the claim's
    middle (:func:`inside_spot`, :data:`MARK_GAP` then :data:`LEAST_GAP`); then outside; if
    there is none, the place of those that keeps the most gap
    (:func:`metaphors.layout.around`)."""
    return scaled_spot(size, claim, edges, labels, inside, within, avoid, scales=(1.0,))[0]


def scaled_spot(size: tuple[float, float], claim: Segment, edges: Iterable[Segment],
                labels: Iterable[Area], inside: shapely.Geometry, within: Box,
                avoid: shapely.Geometry | None = None, scales: Sequence[float] = SCALES
                ) -> tuple[np.ndarray, float]:
    """:func:`mark_spot`, the mark smaller (each of ``scales`` in turn) where its own size
    finds no place inside ``inside``: the centre and the scale. Beside the claim at full
    size (within :data:`MARK_FARTHEST`) comes first, then by it inside at each scale, then
    beside it at the least scale where it is crowded (:func:`_crowded_spot`), then anywhere
    inside at each scale, then outside at full size."""
    a, b = np.asarray(claim[0], dtype=float)[:2], np.asarray(claim[1], dtype=float)[:2]
    edges, labels = list(edges), list(labels)
    obstacles = Obstacles(boxes=labels, segments=[(a, b), *edges])
    left, bottom = within.x - within.width / 2, within.y - within.height / 2
    frame = (left, bottom, left + within.width, bottom + within.height)
    centres, held, framed, gap, shaded = _beside(size, a, b, obstacles, inside, frame, avoid)
    # outside P, twice as far: a mark just past an edge seems to judge that edge
    free = framed & (gap >= np.where(held, MARK_GAP, 2 * MARK_GAP))
    # no farther than :data:`MARK_FARTHEST` (the places go on 2.5 off: divide and
    # conquer's ✓ for MK stood 2.4 off, in another part of P, judging nothing there)
    close = _near(centres, size, a, b)
    if (free & held & close).any():
        # the order of :func:`around` is the first-fit order: nearest, middle first, left first
        best = min(np.flatnonzero(free & held & close), key=lambda k: (bool(shaded[k]), k))
        return np.array([*centres[best], 0.0]), 1.0
    # by the claim, within :data:`MARK_REACH`, each scale in turn; then on it (its own line
    # no obstacle: the mark over the line it judges): prune and search's ✓ for GB, a short
    # claim between G's and H's labels, stood 0.73 off over the fruit
    claim_line = shapely.LineString([a, b])
    lines = Obstacles(boxes=labels, segments=edges)
    for near in (obstacles, lines):
        for scale in scales:
            spot = inside_spot((size[0] * scale, size[1] * scale), (a + b) / 2, near, inside,
                               frame, by=claim_line)
            if spot is not None:
                return np.array([*spot, 0.0]), scale
    # where labels and diagonals crowd it, beside it at the least size and
    # :data:`CROWDED_GAP`, before anywhere else inside
    crowded = _crowded_spot(size, a, b, obstacles, inside, frame, scales[-1])
    if crowded is not None:
        return crowded
    for scale in scales:
        spot = inside_spot((size[0] * scale, size[1] * scale), (a + b) / 2, obstacles, inside,
                           frame)
        if spot is not None:
            return np.array([*spot, 0.0]), scale
    if free.any():
        return np.array([*centres[int(np.flatnonzero(free)[0])], 0.0]), 1.0
    return np.array([*centres[int(np.argmax(np.where(framed, gap, -1.0)))], 0.0]), 1.0


def _near(centres: np.ndarray, size: tuple[float, float], a: np.ndarray, b: np.ndarray
          ) -> np.ndarray:
    """Which places for a thing ``size`` at ``centres`` are within :data:`MARK_FARTHEST` of
    the claim ``a``–``b``."""
    rects = rects_at(centres, size)
    boxes = shapely.box(rects[:, 0], rects[:, 1], rects[:, 2], rects[:, 3])
    return shapely.distance(boxes, shapely.LineString([a, b])) <= MARK_FARTHEST


def _crowded_spot(size: tuple[float, float], a: np.ndarray, b: np.ndarray,
                  obstacles: Obstacles, inside: shapely.Geometry,
                  frame: tuple[float, float, float, float], least: float
                  ) -> tuple[np.ndarray, float] | None:
    """Beside the claim ``a``–``b`` inside P, within :data:`MARK_FARTHEST` of it, the mark
    ``least`` its size, keeping :data:`CROWDED_GAP` from everything; None if there is none."""
    small = (size[0] * least, size[1] * least)
    centres, held, framed, gap, _ = _beside(small, a, b, obstacles, inside, frame, None)
    ok = held & framed & (gap >= CROWDED_GAP) & _near(centres, small, a, b)
    if ok.any():
        return np.array([*centres[int(np.flatnonzero(ok)[0])], 0.0]), least
    return None


def _beside(size: tuple[float, float], a: np.ndarray, b: np.ndarray, obstacles: Obstacles,
            inside: shapely.Geometry, frame: tuple[float, float, float, float],
            avoid: shapely.Geometry | None):
    """The places beside the claim ``a``–``b`` in first-fit order (:data:`ALONG`,
    :data:`AWAY`, left first), and for each: inside ``inside``, in ``frame``, its gap to the
    obstacles, over ``avoid``."""
    along = b - a
    normal = np.array([-along[1], along[0]]) / max(float(np.linalg.norm(along)), 1e-9)
    reach = float(np.linalg.norm(np.array(size, dtype=float) / 2))
    centres = around([a + t * along for t in ALONG], [normal, -normal],
                     [reach + away for away in AWAY])
    rects = rects_at(centres, size)
    boxes = shapely.box(rects[:, 0], rects[:, 1], rects[:, 2], rects[:, 3])
    framed = clear(centres, size, Obstacles(), 0.0, frame)
    shaded = (shapely.intersects(boxes, avoid) if avoid is not None and not avoid.is_empty
              else np.zeros(len(centres), dtype=bool))
    return centres, shapely.contains(inside, boxes), framed, obstacles.gaps(rects), shaded


def inside_spot(size: tuple[float, float], near: Point, obstacles: Obstacles,
                inside: shapely.Geometry, frame: tuple[float, float, float, float],
                by: shapely.Geometry | None = None) -> np.ndarray | None:
    """The centre of the place for a thing ``size`` wholly inside ``inside`` and in ``frame``,
    nearest ``near`` on a grid of :data:`STEP` (:func:`metaphors.layout.grid`), that keeps
    :data:`MARK_GAP` from the obstacles, else :data:`LEAST_GAP`, and, given ``by`` (the
    claim), stands within :data:`MARK_REACH` of it; None if there is none."""
    minx, miny, maxx, maxy = inside.bounds
    area = (max(minx, frame[0]), max(miny, frame[1]), min(maxx, frame[2]), min(maxy, frame[3]))
    centres = grid(area, size, STEP, near=np.asarray(near, dtype=float)[:2])
    if not len(centres):
        return None
    rects = rects_at(centres, size)
    boxes = shapely.box(rects[:, 0], rects[:, 1], rects[:, 2], rects[:, 3])
    held = shapely.contains(inside, boxes)
    if by is not None:
        held &= shapely.distance(boxes, by) <= MARK_REACH
    for gap in (MARK_GAP, LEAST_GAP):
        ok = held & clear(centres, size, obstacles, gap, frame)
        if ok.any():
            return centres[int(np.argmax(ok))]
    return None


def _area_at(mobject: Mobject, centre: np.ndarray) -> Area:
    """``mobject``'s box, its centre at ``centre``."""
    box = rects_at(np.asarray(centre, dtype=float)[:2], (mobject.width, mobject.height))[0]
    return (float(box[0]), float(box[1]), float(box[2]), float(box[3]))


def board_spot(board: Board, mark: Mobject, line: Mobject,
               moved: Callable[[np.ndarray], np.ndarray] | None = None,
               placed: Mapping[str, np.ndarray] | None = None) -> np.ndarray:
    """Where a run's verdict ``mark`` on the claim ``line`` goes on its board (:func:`mark_spot`):
    clear of the outline's edges (its holes' too: the largest ring is the outer one), the
    diagonals drawn and the vertex labels; the mark made smaller if only that fits it inside
    the outline (:func:`scaled_spot`).
    ``moved``: where each point of the picture ends (a turn under way: the mark keeps its
    size), None: as it is. ``placed``: the centres the turn puts the vertex labels at
    (:func:`metaphors.picture.turn_to` places them again for the turned picture)."""
    def end(p: np.ndarray) -> np.ndarray:
        return moved(p) if moved is not None else p

    # the outline as drawn, not P: ear clipping's fruit shrinks as its slices go
    rings = [[end(p) for p in ring] for ring in board.outline_rings()]
    edges = [edge for ring in rings for edge in ring_edges(ring)]
    edges += [(end(m.get_start()), end(m.get_end())) for key, m in board.objects.items()
              if key.startswith("diagonal:") and isinstance(m, Line)]
    placed = placed or {}
    labels = [area_of(part, moved) for name, marker in board.markers.items()
              for part in marker.submobjects[:1 if name in placed else 2]]
    # a label's leader (:func:`metaphors.labels.leader`) is a line, not a box round it
    edges += [(end(m[2].get_start()), end(m[2].get_end())) for name, m in board.markers.items()
              if len(m.submobjects) > 2 and name not in placed]
    # a label placed again: its own size, at its new place
    labels += [_area_at(board.markers[name][1], at) for name, at in placed.items()]
    # and where the labels moved off the ball's way will come back to (the picture upright)
    labels += [area_of(board.markers[label][1].copy().move_to(board.at(place)), moved)
               for label, place in board.moved_for_now.items()]
    inside = shapely.Polygon([p[:2] for p in rings[0]], [[p[:2] for p in r] for r in rings[1:]])
    spot, scale = scaled_spot((mark.width, mark.height),
                              (end(line.get_start()), end(line.get_end())), edges, labels,
                              inside, board.box, scales=SCALES if moved is None else (1.0,))
    if scale != 1.0:  # the picture as it is, not one turning: the turn moves the mark
        mark.scale(scale)
    return spot
