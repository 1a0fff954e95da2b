"""Vertex labels placed by measuring: every label of a drawn polygon (a run's board, an
analysis's stage, a card's figure, an exercise) in the nearest free place round its vertex,
outside the polygon where it can stand there, clear of every edge, every dot and every label
placed before by :data:`EDGE_MARGIN`, the outward bisector of its angle tried first.

:func:`metaphors.drawing.vertex_markers` puts a label a fixed step away from the polygon's
centre, which crowds the labels of a needle or a notch and can lay one on an edge (chapter
2's K on edge L–K, M on edge A–M).

>>> corners = [np.array(p, dtype=float) for p in [(0, 0), (4, 0), (4, 3), (0, 3)]]
>>> at = place_labels(corners, [(0.2, 0.2)] * 4, [])
>>> [tuple(round(float(c), 2) for c in p) for p in at]  # out along each corner's bisector
[(-0.23, -0.23), (4.23, -0.23), (4.23, 3.23), (-0.23, 3.23)]
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from itertools import pairwise
from typing import Any

import numpy as np
import shapely
from manim import Dot, Line, LineJointType, Mobject, VGroup
from manim import Polygon as MPolygon

from geometry.polygon import Polygon
from metaphors.drawing import Frame
from metaphors.layout import (
    FRAME_AREA,
    Obstacles,
    Rect,
    Segment,
    clear,
    dot_gaps,
    grid,
    rects_at,
    ring_edges,
)
from metaphors.theme import THEME, Theme
from rendering import typeset
from story.beats import Hole

#: the least gap (scene units) a moved label keeps from a line drawn later (a diagonal), a
#: dot or another label
MARGIN = 0.05
#: the least gap between a placed label and an edge of its polygon, a dot or another label:
#: 1.5 % of the frame's height (8 units); nearer, the letter reads as sitting on the line
EDGE_MARGIN = 0.12
#: the gaps tried between a vertex and its label's box (the side nearest it), nearest first:
#: from just clear of the dot (:data:`metaphors.theme.Theme.dot_radius` and a margin) out
GAPS = tuple(round(0.18 + 0.03 * i, 6) for i in range(15))
#: the turns tried away from the outward bisector (degrees), nearest first: every 15°
TURNS = tuple(sorted(range(-180, 180, 15), key=lambda t: (abs(t), -t)))
#: the gap a leader leaves at each end, by the dot and by the letter (scene units)
LEADER_END = 0.05
#: a leader's opacity: a thin line fainter than an edge
LEADER_OPACITY = 0.7


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


def places_round(at: np.ndarray, away: np.ndarray, size: tuple[float, float]) -> np.ndarray:
    """The centres a label ``size`` may take round its vertex ``at``, nearest first (its box's
    nearest side :data:`GAPS` away), then nearest the direction ``away`` (:data:`TURNS`)."""
    t = np.radians(TURNS)
    units = np.column_stack([np.cos(t) * away[0] - np.sin(t) * away[1],
                             np.sin(t) * away[0] + np.cos(t) * away[1]])
    # as :func:`metaphors.layout.around` puts them, at once: the box's reach along each way
    reach = np.abs(units) @ (np.asarray(size, dtype=float) / 2)
    steps = np.asarray(GAPS)[:, None] + reach[None, :]
    return (np.asarray(at, dtype=float)[:2] + steps[..., None] * units[None]).reshape(-1, 2)


def _own(centres: np.ndarray, size: tuple[float, float], k: int,
         dots: Sequence[np.ndarray]) -> np.ndarray:
    """Which label boxes stand nearer their own dot (``dots[k]``) than any other: a label
    midway between two dots names neither."""
    near = dot_gaps(rects_at(centres, size), [(float(p[0]), float(p[1]), 0.0) for p in dots])
    others = np.delete(near, k, axis=1).min(axis=1, initial=np.inf)
    return np.asarray(near[:, k] < others, dtype=bool)


def _seen(centres: np.ndarray, at: np.ndarray, edges: Sequence[Segment]) -> np.ndarray:
    """Which centres the vertex ``at`` sees: the line to each crosses none of ``edges``
    except at ``at`` itself (a label across an edge, however clear of it, names what lies
    beyond it: chapter 4's G stood 0.5 off, outside edge B–C)."""
    away = [(a, b) for a, b in edges
            if min(np.linalg.norm(np.asarray(a)[:2] - at), np.linalg.norm(np.asarray(b)[:2] - at))
            > 1e-9]
    if not away:
        return np.ones(len(centres), dtype=bool)
    walls = shapely.union_all([shapely.LineString([np.asarray(a)[:2], np.asarray(b)[:2]])
                               for a, b in away])
    rays = shapely.linestrings(np.stack([np.broadcast_to(at, centres.shape), centres], axis=1))
    return ~np.asarray(shapely.intersects(rays, walls), dtype=bool)


def best_place(centres: np.ndarray, size: tuple[float, float], obstacles: Obstacles,
               margin: float, inside: shapely.Geometry | None = None,
               own: np.ndarray | None = None) -> int:
    """The index of the place to take among ``centres`` (in order of preference): the first
    ``margin`` clear of ``obstacles`` (and ``own``: nearer its own dot) whose box is not
    ``inside`` (the polygon's region: a label outside reads on the background, not over a
    fill), else the first clear one, else the one with the widest gap."""
    rects = rects_at(centres, size)
    gaps = obstacles.gaps(rects)
    left, bottom, right, top = FRAME_AREA
    ok = ((gaps >= margin - 1e-9) & (rects[:, 0] >= left) & (rects[:, 1] >= bottom)
          & (rects[:, 2] <= right) & (rects[:, 3] <= top))
    if own is not None:
        ok &= own
    if inside is not None and ok.any():
        outside = ok & ~shapely.intersects(shapely.box(*rects.T), inside)
        if outside.any():
            return int(np.argmax(outside))
    return int(np.argmax(ok)) if ok.any() else int(np.argmax(gaps))


def place_labels(corners: Sequence[np.ndarray], sizes: Sequence[tuple[float, float]],
                 segments: Sequence[Segment], dot: float = THEME.dot_radius) -> list[np.ndarray]:
    """The centre of each corner's label (``sizes``: each label's width and height), as
    :func:`place_ring_labels` places them on a polygon of one ring. Deterministic."""
    return place_ring_labels([corners], sizes, segments, dot)


def place_ring_labels(rings: Sequence[Sequence[np.ndarray]], sizes: Sequence[tuple[float, float]],
                      segments: Sequence[Segment], dot: float = THEME.dot_radius
                      ) -> list[np.ndarray]:
    """The centre of each vertex's label on a polygon of several rings (its outer ring, then
    its holes': ``sizes`` runs over their vertices in that order): the nearest place round
    its vertex, nearest its outward bisector, outside the polygon if one is free there
    (:func:`best_place`), :data:`EDGE_MARGIN` clear of every ring's edges, every segment of
    ``segments`` (lines the picture draws), every dot and every label placed before,
    nearer its own dot than any other, and seen from it across no edge or line
    (:func:`_seen`). Deterministic."""
    return [centre for centre, _ in placed_labels(rings, sizes, segments, dot)]


def placed_labels(rings: Sequence[Sequence[np.ndarray]], sizes: Sequence[tuple[float, float]],
                  segments: Sequence[Segment], dot: float = THEME.dot_radius,
                  leaders: bool = False) -> list[tuple[np.ndarray, bool]]:
    """Each label's centre as :func:`place_ring_labels` places it, and whether it has a
    leader: ``leaders``, a label with no place outside P round its dot (:data:`GAPS`) then
    goes beside P, clear of every other label, with a short thin line to its dot
    (:func:`leader_place`), where there is such a place: over P's fill, the lecture
    polygon's G (the slot's inner corner) and M (the notch between A and L) stood on the
    picture, and a place outside P by their dot was nearer H's dot, A's. The others are
    placed first, each in its own place as without leaders."""
    pts = [[np.asarray(c, dtype=float)[:2] for c in ring] for ring in rings]
    dots = [p for ring in pts for p in ring]
    edges: list[Segment] = [edge for ring in pts for edge in ring_edges(ring)]
    edges += [(np.asarray(a, dtype=float)[:2], np.asarray(b, dtype=float)[:2]) for a, b in segments]
    base = Obstacles(segments=edges, dots=[(float(p[0]), float(p[1]), dot) for p in dots])
    region = shapely.Polygon(pts[0], pts[1:]) if len(pts[0]) >= 3 else None
    placed: list[Rect] = []
    centres: list[tuple[np.ndarray, bool]] = []
    for k, (ring, i) in enumerate([(r, i) for r in pts for i in range(len(r))]):
        away = outward(ring[i - 1], ring[i], ring[(i + 1) % len(ring)])
        tried = places_round(ring[i], away, sizes[k])
        mine = _own(tried, sizes[k], k, dots) & _seen(tried, ring[i], edges)
        centre = tried[best_place(tried, sizes[k], base.plus(boxes=placed), EDGE_MARGIN,
                                  region, mine)]
        placed.append(tuple(rects_at(centre, sizes[k])[0]))
        centres.append((centre, False))
    if not leaders or region is None:
        return centres
    lines: list[Segment] = []  # the leaders drawn: each kept clear of the others
    for k, at in enumerate(dots):
        if not shapely.intersects(shapely.box(*placed[k]), region):
            continue
        others = [box for j, box in enumerate(placed) if j != k]
        led = leader_place(at, sizes[k], base.plus(boxes=others, segments=lines), edges,
                           region, [p for j, p in enumerate(dots) if j != k], dot)
        if led is not None:
            placed[k] = tuple(rects_at(led, sizes[k])[0])
            centres[k] = (led, True)
            lines.append(leader_ends(at, led, sizes[k], dot))
    return centres


#: how far a label with a leader may stand from its dot (its box; 15 % of the frame's height):
#: farther, the leader runs along the picture like an edge (G's, the length of the slot)
LEADER_REACH = 1.2
#: the least gap between a label with a leader and any other vertex's dot or label: it stands
#: apart, and its leader says whose it is
LEADER_APART = 0.2


def leader_place(at: np.ndarray, size: tuple[float, float], obstacles: Obstacles,
                 edges: Sequence[Segment], region: shapely.Geometry,
                 others: Sequence[np.ndarray], dot: float = THEME.dot_radius
                 ) -> np.ndarray | None:
    """The centre of a label beside P with a leader to its dot ``at``: the place nearest
    the dot (on a grid, :func:`metaphors.layout.grid`) within :data:`LEADER_REACH`, in the
    frame, wholly outside ``region``, :data:`EDGE_MARGIN` clear of ``obstacles`` (edges,
    lines, dots, the other labels) and :data:`LEADER_APART` of the other dots (``others``)
    and labels, seen from the dot (the leader crosses no edge), whose leader passes
    :data:`MARGIN` clear of every other dot and label; None if there is none."""
    w, h = size
    window = (at[0] - LEADER_REACH - w, at[1] - LEADER_REACH - h,
              at[0] + LEADER_REACH + w, at[1] + LEADER_REACH + h)
    tried = grid(window, size, step=0.02, near=at)
    if not len(tried):
        return None
    rects = rects_at(tried, size)
    boxes = shapely.box(*rects.T)
    apart = Obstacles(boxes=obstacles.boxes, dots=[(float(p[0]), float(p[1]), dot) for p in others])
    ok = ((shapely.distance(boxes, shapely.Point(at)) <= LEADER_REACH)
          # a little over the margin: the scene graph rounds boxes to 0.001
          & clear(tried, size, obstacles, EDGE_MARGIN + 0.005, FRAME_AREA)
          & clear(tried, size, apart, LEADER_APART)
          & ~shapely.intersects(boxes, region))
    near = [shapely.Point(p).buffer(dot) for p in others]
    near += [shapely.box(*box) for box in obstacles.boxes]
    for k in np.flatnonzero(ok):
        if not _seen(tried[k:k + 1], at, edges)[0]:
            continue
        a, b = leader_ends(at, tried[k], size, dot)
        line = shapely.LineString([a, b])
        if all(line.distance(shape) >= MARGIN for shape in near):
            return tried[k]
    return None


def leader_ends(at: np.ndarray, centre: np.ndarray, size: tuple[float, float],
                dot: float = THEME.dot_radius) -> tuple[np.ndarray, np.ndarray]:
    """The ends of a label's leader: from just off its dot ``at`` towards the label's centre
    ``centre``, to just short of its box (``size``), :data:`LEADER_END` off each."""
    a, c = np.asarray(at, dtype=float)[:2], np.asarray(centre, dtype=float)[:2]
    d = c - a
    length = float(np.linalg.norm(d))
    if length < 1e-9:
        return a, a
    u = d / length
    # where the way from the dot meets the box's side (the box centred on ``c``)
    half = np.asarray(size, dtype=float) / 2
    inside = min(half[0] / abs(u[0]) if abs(u[0]) > 1e-9 else np.inf,
                 half[1] / abs(u[1]) if abs(u[1]) > 1e-9 else np.inf)
    start = dot + LEADER_END
    end = max(start, length - inside - LEADER_END)
    return a + u * start, a + u * end


def leader(at: np.ndarray, label: Mobject, theme: Theme = THEME) -> Line:
    """A label's leader (:func:`leader_ends`): a thin line in the label's ink from its dot
    ``at`` to the label, named ``leader`` (no text: the reading rules' label boxes pass it)."""
    a, b = leader_ends(at, label.get_center(), (label.width, label.height), theme.dot_radius)
    # thin and a little faint: not read as an edge or a diagonal
    return Line((a[0], a[1], 0.0), (b[0], b[1], 0.0), color=theme.ink,
                stroke_width=theme.thin_stroke, stroke_opacity=LEADER_OPACITY)


def move_label(marker: Mobject, centre: Sequence[float] | np.ndarray) -> Mobject:
    """A vertex marker (a dot and a label, and a leader if it has one) with its label at
    ``centre``: its leader drawn again from the dot to the label's new place."""
    marker[1].move_to((centre[0], centre[1], 0.0))
    if len(marker.submobjects) > 2:
        a, b = leader_ends(marker[0].get_center(), marker[1].get_center(),
                           (marker[1].width, marker[1].height), marker[0].width / 2)
        marker[2].set_points_as_corners([(a[0], a[1], 0.0), (b[0], b[1], 0.0)])
    return marker


def placed_vertex_markers(polygon: Polygon, frame: Frame, theme: Theme = THEME,
                          diagonals: Sequence[tuple[int, int]] = (),
                          lines: Sequence[Sequence[tuple[float, float]]] = (),
                          leaders: bool = True) -> VGroup:
    """A dot and a label per vertex, in the polygon's order (:func:`measured_markers`), clear
    of ``diagonals`` (pairs of vertex indices drawn on the picture) and of ``lines``
    (polylines in P's units drawn on it too: an answer's line); a still picture's label
    with no room outside P beside P with a leader (``leaders``)."""
    segments = [segment for line in lines for segment in pairwise(frame.many(list(line)))]
    return VGroup(*(m for _, m in measured_markers(polygon, (), frame, theme, diagonals,
                                                    segments, leaders)))


#: the width of the dark halo a vertex's label (and dot) is given where it stands on a fill it
#: would not read on: ear clipping's fruit (grey, red or green on its orange all but vanish),
#: an analysis's red "outside P"; the halo follows its label wherever it moves, in any colour
LABEL_HALO = 6.0


def haloed(marker: VGroup, colour: str, dot: bool = False) -> VGroup:
    """A copy of a vertex's marker (its dot and label) whose label has a halo of ``colour``
    :data:`LABEL_HALO` wide, drawn behind its glyphs (a background stroke: recolouring the
    label, and moving it, keep it); ``dot``: its dot too, a ring round it."""
    # round joins (a mitred halo spikes at M's and K's points): set on the label itself, as
    # a transform to the copy does not carry them
    marker[1].joint_type = LineJointType.ROUND
    copy = marker.copy()
    copy[1].set_stroke(colour, width=LABEL_HALO, background=True)
    if dot:
        copy[0].set_stroke(colour, width=LABEL_HALO, background=True)
    return copy


def measured_markers(polygon: Polygon, holes: Sequence[Hole], frame: Frame,
                     theme: Theme = THEME, diagonals: Sequence[tuple[int, int]] = (),
                     lines: Sequence[Segment] = (), leaders: bool = False
                     ) -> list[tuple[str, VGroup]]:
    """(label, dot and label) for every vertex of the polygon and of its holes, each label
    where :func:`place_ring_labels` puts it: clear of the edges, of ``diagonals`` (pairs of
    the polygon's vertex indices: the claims a picture will draw, which its labels are
    placed before) and of ``lines`` (on screen: a keyhole's bridges). ``leaders``: a label
    with no room outside P round its dot stands beside P, and its marker has a third part,
    its leader (:func:`placed_labels`)."""
    rings = [frame.many(polygon.points), *(frame.many(h.points) for h in holes)]
    names = [*polygon.labels, *(label for h in holes for label in h.labels)]
    # lower-case letters stand lower than capitals: a size larger keeps them 2.5 % high
    sizes = [theme.label_size] * polygon.n + [theme.label_size + 4] * (len(names) - polygon.n)
    texts = [typeset.text(name, font=theme.font, size=size, colour=theme.ink)
             for name, size in zip(names, sizes, strict=True)]
    segments = [*((rings[0][i], rings[0][j]) for i, j in diagonals), *lines]
    centres = placed_labels(rings, [(t.width, t.height) for t in texts], segments,
                            theme.dot_radius, leaders)
    points = [point for ring in rings for point in ring]
    markers = []
    for name, at, text, (centre, led) in zip(names, points, texts, centres, strict=True):
        text.move_to((centre[0], centre[1], 0.0))
        marker = VGroup(Dot(at, radius=theme.dot_radius, color=theme.ink), text)
        if led:
            marker.add(leader(at, text, theme))
        markers.append((name, marker))
    return markers


def crossed_labels(rings: Sequence[Sequence[str]], markers: dict[str, VGroup],
                   drawn: Sequence[Segment], new: Sequence[Segment],
                   dot: float = THEME.dot_radius, apart: float = MARGIN,
                   fill: shapely.Geometry | None = None,
                   standing: Mapping[str, np.ndarray] | None = None,
                   near: float = MARGIN) -> dict[str, np.ndarray]:
    """The labels that the ``new`` segments come within ``near`` (:data:`MARGIN`) of, each with a new
    centre: the first place round its vertex (:func:`places_round`: out along the bisector
    of its ring, each ring a list of labels, their dots where the markers stand now)
    :data:`EDGE_MARGIN` clear of the segments ``drawn`` (the edges, the lines on the
    picture) and ``new``, of the dots and of the other labels, else the first :data:`MARGIN`
    clear of those and ``apart`` from the other labels (more than :data:`MARGIN` where labels
    crowd); of the places each asks, one off ``fill`` (the polygon's region: ear clipping's
    fruit) first, as :func:`best_place` prefers (moved off a test triangle, the keyhole's
    a₂ went from its hole onto the orange); a label with no clear place stays.
    ``standing``: the centres some labels are measured at instead of where they stand (they
    go back there: ear clipping's labels moved aside off a test triangle gone now)."""
    at = {name: np.asarray(m[0].get_center(), dtype=float)[:2] for name, m in markers.items()}
    standing = standing or {}
    boxes = {name: tuple(rects_at(np.asarray(standing.get(name, m[1].get_center()),
                                             dtype=float)[:2], (m[1].width, m[1].height))[0])
             for name, m in markers.items() if len(m) > 1}
    lines = Obstacles(segments=[(np.asarray(a, float)[:2], np.asarray(b, float)[:2])
                                for a, b in new])
    base = Obstacles(segments=[*drawn, *new],
                     dots=[(float(p[0]), float(p[1]), dot) for p in at.values()])
    moved: dict[str, np.ndarray] = {}
    for ring in rings:
        for i, name in enumerate(ring):
            if name not in boxes or lines.gaps(np.array([boxes[name]]))[0] >= near:
                continue
            size = (boxes[name][2] - boxes[name][0], boxes[name][3] - boxes[name][1])
            d = outward(at[ring[i - 1]], at[name], at[ring[(i + 1) % len(ring)]])
            tried = places_round(at[name], d, size)
            others = Obstacles(boxes=[box for other, box in boxes.items() if other != name])
            ok = _off(tried, size, fill, clear(tried, size, base, EDGE_MARGIN)
                      & clear(tried, size, others, max(apart, EDGE_MARGIN)))
            if not ok.any():  # between the ways tried, on a finer grid (:func:`_finer`)
                tried = _finer(at[name], size)
                ok = _off(tried, size, fill, clear(tried, size, base, EDGE_MARGIN)
                          & clear(tried, size, others, max(apart, EDGE_MARGIN)))
            if not ok.any():
                tried = places_round(at[name], d, size)
                ok = _off(tried, size, fill,
                          clear(tried, size, base, MARGIN) & clear(tried, size, others, apart))
            if ok.any():
                moved[name] = tried[int(np.argmax(ok))]
                boxes[name] = tuple(rects_at(moved[name], size)[0])
    return moved


#: the step of the finer grid a crossed label's place is looked for on (scene units)
FINE_STEP = 0.02


def _finer(at: np.ndarray, size: tuple[float, float]) -> np.ndarray:
    """The centres round the dot ``at`` on a grid of :data:`FINE_STEP` whose box (``size``)
    stands :data:`GAPS` from it (nearest first): the places between the ways
    :func:`places_round` tries, 15° apart (at the whole triangulation's end, b₂ had room
    between two of them, and stood on a triangle's side)."""
    reach = max(GAPS)
    w, h = size
    window = (at[0] - reach - w, at[1] - reach - h, at[0] + reach + w, at[1] + reach + h)
    centres = grid(window, size, FINE_STEP, near=at)
    gaps = dot_gaps(rects_at(centres, size), [(float(at[0]), float(at[1]), 0.0)])[:, 0]
    return centres[(gaps >= GAPS[0] - 1e-9) & (gaps <= reach + 1e-9)]


def drawn_edges(mobject: Mobject) -> list[Segment]:
    """The straight lines a drawn line or polygon (a triangle, a group of them) shows."""
    if isinstance(mobject, Line):
        return [(mobject.get_start(), mobject.get_end())]
    if isinstance(mobject, MPolygon):
        return ring_edges(list(mobject.get_vertices()))
    if isinstance(mobject, VGroup):
        return [edge for part in mobject.submobjects for edge in drawn_edges(part)]
    return []


def _off(centres: np.ndarray, size: tuple[float, float], fill: shapely.Geometry | None,
         ok: np.ndarray) -> np.ndarray:
    """``ok``, kept to the places whose boxes are off ``fill`` if any of them is."""
    if fill is None or not ok.any():
        return ok
    rects = rects_at(centres, size)
    off = ok & ~shapely.intersects(shapely.box(*rects.T), fill)
    return off if off.any() else ok


def filled_region(rings: Sequence[Sequence[Any]]) -> shapely.Geometry | None:
    """The region an outline's rings (the first outer, the rest holes; 2-D points) bound,
    made valid (a keyhole's ring runs both ways along its cut); None without a ring of three
    points."""
    if not rings or len(rings[0]) < 3:
        return None
    return shapely.make_valid(shapely.Polygon(rings[0], rings[1:]))


def off_the_fill(ring: Sequence[np.ndarray], labels: Mapping[str, tuple[np.ndarray, Rect]],
                 segments: Sequence[Segment], dot: float = THEME.dot_radius
                 ) -> dict[str, np.ndarray]:
    """The labels (``labels``: each one's vertex and box) that stand over the region
    ``ring`` bounds, each with a new centre: the first place round its vertex
    (:func:`places_round`, out along its bisector on ``ring``) wholly outside the region,
    :data:`EDGE_MARGIN` clear of its edges, of ``segments``, of the dots and of the other
    labels, nearer its own dot than any other and seen from it (:func:`_seen`), in the
    frame. A label with no such place stays; so does one whose vertex is not on ``ring``.

    Ear clipping's fruit shrinks as its slices go: a hole's label, over the fruit while the
    hole had no room for it, finds room outside once the slices round its vertex are cut.

    >>> square = [np.array(p, dtype=float) for p in [(0, 0), (4, 0), (4, 3), (0, 3)]]
    >>> moved = off_the_fill(square, {"A": (square[0], (0.1, 0.1, 0.3, 0.3))}, [])
    >>> [round(float(c), 2) for c in moved["A"]]  # out along the corner's bisector
    [-0.23, -0.23]
    """
    pts = [np.asarray(p, dtype=float)[:2] for p in ring]
    region = filled_region([pts])
    if region is None or region.is_empty:
        return {}
    edges = [*ring_edges(pts), *segments]
    dots = [np.asarray(at, dtype=float)[:2] for at, _ in labels.values()]
    boxes = {name: box for name, (_, box) in labels.items()}
    moved: dict[str, np.ndarray] = {}
    for k, (name, (_, box)) in enumerate(labels.items()):
        i = next((j for j, p in enumerate(pts) if np.linalg.norm(p - dots[k]) < 1e-6), None)
        if i is None or not shapely.intersects(shapely.box(*box), region):
            continue
        size = (box[2] - box[0], box[3] - box[1])
        tried = places_round(dots[k], outward(pts[i - 1], pts[i], pts[(i + 1) % len(pts)]), size)
        others = Obstacles(segments=edges, dots=[(float(p[0]), float(p[1]), dot) for p in dots],
                           boxes=[b for other, b in boxes.items() if other != name])
        rects = rects_at(tried, size)
        ok = (clear(tried, size, others, EDGE_MARGIN, FRAME_AREA)
              & ~shapely.intersects(shapely.box(*rects.T), region)
              & _own(tried, size, k, dots) & _seen(tried, dots[k], edges))
        if ok.any():
            moved[name] = tried[int(np.argmax(ok))]
            boxes[name] = tuple(rects[int(np.argmax(ok))])
    return moved


def seen_by(centres: np.ndarray, at: np.ndarray, edges: Sequence[Segment]) -> np.ndarray:
    """Which of ``centres`` (an n × 2 array) the vertex ``at`` sees across none of ``edges``
    (:func:`_seen`)."""
    return _seen(np.asarray(centres, dtype=float)[:, :2], np.asarray(at, dtype=float)[:2], edges)


def seen_from(at: np.ndarray, centre: np.ndarray, edges: Sequence[Segment]) -> bool:
    """Whether a label centred at ``centre`` is seen from its vertex ``at`` across none of
    ``edges`` (:func:`_seen`)."""
    return bool(_seen(np.asarray([centre[:2]], dtype=float), np.asarray(at, dtype=float)[:2],
                      edges)[0])


def new_colour(marker: Mobject, label: str, role: str, was: str, theme: Theme,
               focus: frozenset[str] | None, at_rest: bool = False) -> str | None:
    """The colour a vertex marker changes to for ``role`` (it was in role ``was``), None if it
    stays as drawn. ``at_rest``: its ink. ``focus``: the labels of the part of P the call runs
    on (divide and conquer's piece): an idle vertex in it is in its ink, one outside it grey,
    so that grey says "not in this polygon" (as chapter 1 says it); None (all of P): a
    marker changes only with its role, and an idle one is in the ink it was drawn in, like
    those never in a call. Grey there told apart "was in a call" from "never was", which no
    caption says: B, C, A, L and B went grey in chapters 2 to 6 while the picture still
    used them (gravity's band hung from C), blue or green again a second later."""
    if not at_rest and focus is None and was == role:
        return None
    if at_rest:
        colour = theme.ink
    elif role == "idle":
        colour = theme.idle if focus is not None and label not in focus else theme.ink
    else:
        colour = theme.role_colour(role)
    kept = at_rest or focus is not None or role == "idle"
    return None if kept and drawn_in(marker, colour) else colour


def drawn_in(marker: Mobject, colour: str) -> bool:
    """Whether every part of a vertex marker (its dot, its label) is drawn in ``colour``."""
    return all(part.get_color().to_hex().lower() == colour.lower() for part in marker)


__all__ = ["EDGE_MARGIN", "MARGIN", "best_place", "crossed_labels", "drawn_edges",
           "filled_region", "leader", "leader_ends", "leader_place", "measured_markers",
           "move_label", "new_colour", "off_the_fill", "outward", "place_labels",
           "place_ring_labels", "placed_labels", "placed_vertex_markers", "places_round",
           "seen_from"]
