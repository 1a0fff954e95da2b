"""The sweep line: a line through B moves across T and the first candidate it touches is D.

``translation`` sweeps a vertical line rightwards (wrong); ``translation-correct`` sweeps a line
parallel to AC from B towards AC (right). The line is drawn solid where it lies in the polygon
and dashed outside; the part outside the polygon but inside T — the part that can touch a
wrong vertex first — is dashed red. That is the whole story of why one fails and the other
cannot (thesis ch. 2.1.2, Correct Translation).

Offsets and the order of the hits are the log's shape states; the side the line moves to is
the side the candidates lie on. The solid/dashed split (shared with the clock hand) is plain
shapely on the scene's own outlines.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import shapely
from manim import (
    Animation,
    Circle,
    Create,
    DashedLine,
    FadeIn,
    FadeOut,
    Flash,
    Indicate,
    Line,
    Mobject,
    VGroup,
)

from metaphors.board import Board
from metaphors.layout import (
    FRAME_AREA,
    area_of,
    areas_of,
    free_place,
    panel_column,
    subtitle_band,
    title_area,
)
from metaphors.performing import Performances, act, performs
from metaphors.stage import OUTSIDE, legend_entry
from metaphors.tags import tag
from story.beats import beat_kind
from story.reach import side_normal
from story.refs import arg
from story.states import Line as Sweeping
from story.states import Moving, Point, hits, point
from story.storyboard import Reading, Walk, read_step
from tracing import Event


@beat_kind("sweep")
class Sweep(Moving):
    """The sweeping line's ``states`` (through, direction, offset, the vertex reached)."""

    states: tuple[Sweeping, ...]


#: How far inside/outside counts as "on the boundary" (scene units).
EPS = 1e-6
#: the gap a tool's line leaves round a vertex label it would run through
LABEL_GAP = 0.04
#: a dashed tail of a tool's line beyond a vertex shorter than this is left out: one or two
#: dashes next to the vertex's label read as a prime ("A′": the hand set to A, Rotation at 9 s)
SHORTEST_TAIL = 0.4


# --- plain geometry (any coordinates) ------------------------------------------------------------


def split_segment(a, b, region, zone=None) -> dict[str, list[tuple[tuple, tuple]]]:
    """Pieces of the segment a–b, each from the end nearer `a`, ordered from `a`.

    ``inside``: in `region` (its boundary counts as inside); ``outside``: the rest, minus
    ``astray``: the outside pieces that lie in `zone` (the triangle T), if a zone is given.

    >>> square = shapely.box(0, 0, 2, 2)
    >>> split_segment((-1, 1), (3, 1), square)
    {'inside': [((0.0, 1.0), (2.0, 1.0))], 'outside': [((-1.0, 1.0), (0.0, 1.0)), ((2.0, 1.0), (3.0, 1.0))], 'astray': []}
    >>> split_segment((0, 0), (0, 2), square)["inside"]  # along the boundary: inside
    [((0.0, 0.0), (0.0, 2.0))]
    >>> split_segment((1, 1), (4, 1), square, zone=shapely.box(2.5, 0, 5, 2))["astray"]
    [((2.5, 1.0), (4.0, 1.0))]
    """
    segment = shapely.LineString([tuple(a[:2]), tuple(b[:2])])
    grown = region.buffer(EPS)
    inside = segment.intersection(grown)
    outside = segment.difference(grown)
    astray = shapely.GeometryCollection()
    if zone is not None:
        near = zone.buffer(EPS)
        astray = outside.intersection(near)
        outside = outside.difference(near)
    return {"inside": _pieces(inside, a), "outside": _pieces(outside, a),
            "astray": _pieces(astray, a)}


def _pieces(geometry, a) -> list[tuple[tuple, tuple]]:
    """The line pieces of a shapely result as (start, end) pairs, oriented and ordered from a."""
    found = []
    for part in _lines(geometry):
        p, q = part.coords[0], part.coords[-1]
        if math.dist(p, q) <= 10 * EPS:
            continue
        if math.dist(a[:2], q) < math.dist(a[:2], p):
            p, q = q, p
        found.append(((round(p[0], 5) + 0.0, round(p[1], 5) + 0.0),
                      (round(q[0], 5) + 0.0, round(q[1], 5) + 0.0)))
    return sorted(found, key=lambda pq: math.dist(a[:2], pq[0]))


def _lines(geometry):
    if geometry.is_empty:
        return
    if geometry.geom_type == "LineString":
        yield geometry
    elif hasattr(geometry, "geoms"):
        for part in geometry.geoms:
            yield from _lines(part)


# --- on the board (scene coordinates) ------------------------------------------------------------


def outline(mobject):
    """The shapely polygon of a drawn polygon mobject (scene coordinates), or None."""
    if mobject is None:
        return None
    corners = [tuple(p[:2]) for p in mobject.get_vertices()]
    shape = shapely.Polygon(corners)
    return shape if shape.is_valid and shape.area > 0 else shapely.make_valid(shape)


def drawn_segment(board: Board, start: np.ndarray, end: np.ndarray, colour: str, name: str,
                  clip: shapely.Polygon | None = None, astray: bool = True) -> VGroup:
    """The segment start–end (scene points): solid in the polygon, dashed outside it, dashed red
    where it is outside the polygon but inside T. ``clip``: a shapely box to cut it to first.
    ``astray`` False: the part outside P inside T dashed as the rest outside, not red (the
    tool has found its pick: what it passes later is no verdict)."""
    theme = board.theme
    if clip is not None:
        start, end = _cut(start, end, clip)
    parts = split_segment(start, end, outline(board.outline), outline(board.objects.get("T")))
    if not astray:
        parts = {**parts, "outside": [*parts["outside"], *parts["astray"]], "astray": []}
    # a gap where the line would run through a vertex label: the label stays readable
    labels = label_gaps(board)
    parts = {kind: around_labels(pieces, labels) for kind, pieces in parts.items()}
    # nor one or two dashes left beside a vertex or a label's gap (they read as "A′")
    corners = [board.vertex(label)[:2] for label in board.markers]
    parts["outside"] = [(p, q) for p, q in parts["outside"] if math.dist(p, q) >= SHORTEST_TAIL
                        or (min(math.dist(e, c) for e in (p, q) for c in corners) >= 0.1
                            and (labels.is_empty
                                 or shapely.LineString([p, q]).distance(labels) > 1e-3))]
    group = VGroup()
    for p, q in parts["inside"]:
        group.add(tag(Line(_3d(p), _3d(q), color=colour, stroke_width=theme.stroke),
                      "argument", f"{name}:inside"))
    for p, q in parts["outside"]:
        group.add(tag(DashedLine(_3d(p), _3d(q), color=colour, stroke_width=theme.thin_stroke * 1.5,
                                 dash_length=theme.dash_length), "idle", f"{name}:outside"))
    for p, q in parts["astray"]:
        group.add(tag(DashedLine(_3d(p), _3d(q), color=theme.rejected,
                                 stroke_width=theme.stroke * 1.3,
                                 dash_length=theme.dash_length), "rejected", f"{name}:astray"))
    if not group.submobjects:  # keeps `become` happy: always at least one (empty) piece
        group.add(Line(_3d(start), _3d(start), stroke_opacity=0))
    return group


def label_gaps(board: Board, gap: float = LABEL_GAP) -> shapely.Geometry:
    """The vertex labels' boxes, each grown by ``gap``: where a tool's line leaves a gap
    (:func:`around_labels`)."""
    return shapely.union_all([shapely.box(*area_of(marker[1])).buffer(gap, join_style="mitre")
                              for marker in board.markers.values()])


def around_labels(pieces: list[tuple[tuple, tuple]], labels: shapely.Geometry,
                  ) -> list[tuple[tuple, tuple]]:
    """The pieces with the parts inside ``labels`` cut out.

    >>> around_labels([((0.0, 0.0), (4.0, 0.0))], shapely.box(1, -1, 2, 1))
    [((0.0, 0.0), (1.0, 0.0)), ((2.0, 0.0), (4.0, 0.0))]
    """
    kept = []
    for p, q in pieces:
        for part in _lines(shapely.LineString([p, q]).difference(labels)):
            a, b = part.coords[0], part.coords[-1]
            if math.dist(a, b) > 10 * EPS:
                kept.append(((a[0], a[1]), (b[0], b[1])))
    return kept


def follower(board: Board, axis: Line, colour: str, name: str,
             clip: shapely.Polygon | None = None, picked: list[bool] | None = None) -> VGroup:
    """The visible drawing of an (invisible) axis line: redrawn whenever the axis moves.
    ``picked``: a flag the performer sets once the tool reached its pick; from then on no
    part of the line is red (Correct Rotation's hand, turning on from its pick D to E on the
    mirror image, drew C–E red across the notch, as if the correct rule failed)."""
    def draw() -> VGroup:
        return drawn_segment(board, axis.get_start(), axis.get_end(), colour, name, clip,
                             astray=not (picked and picked[0]))

    drawing = draw()
    drawing.add_updater(lambda m: m.become(draw()))
    return drawing


def light(board: Board, label: str, first: bool, axis: Line,
          clip: shapely.Polygon | None = None, ahead: shapely.Geometry | None = None,
          ) -> tuple[list[Mobject], list[Animation]]:
    """A ring round a candidate the tool has just reached: amber for the first, the pick,
    with an amber flash; a candidate's pink after.

    If the first one is reached by a part of the tool outside the polygon but inside T, that
    part is traced over in red, and the legend says what red is (the analyses' entry,
    :data:`metaphors.stage.OUTSIDE`), beside the picture (:func:`_legend_place`): the claim
    to come will cross an edge there. ``ahead``: what the tool will still sweep over (scene
    coordinates) while the legend is up; the legend keeps off it, so that no moving shape
    crosses a text. Returns the new objects (to fade with the tool) and the animations.
    """
    theme = board.theme
    # the first touched is the pick, the claim to be (amber); the others stay candidates
    role = "argument" if first else "candidate"
    colour = theme.role_colour(role)
    at = board.vertex(label)
    ring = tag(Circle(radius=0.13, color=colour, stroke_width=theme.stroke).move_to(at),
               role, f"lit:{label}")
    kept = [ring]
    anims: list[Animation] = [FadeIn(ring, scale=1.6)]
    if not first:  # the pick is not pulsed: the play turns it amber now, as the tool reaches it
        anims.append(Indicate(board.markers[label], color=colour))
    else:  # it flashes amber, as the water's pick does (:func:`metaphors.water.wets`)
        anims.append(Flash(at, color=theme.argument, flash_radius=0.3))
    piece = _astray_at(board, axis, clip, at) if first else None
    if piece is not None:
        p, q = _3d(piece[0]), _3d(piece[1])
        trace = tag(Line(p, q, color=theme.rejected, stroke_width=theme.stroke * 2),
                    "rejected", f"astray:{label}")
        key = legend_entry(theme, theme.rejected, OUTSIDE, "astray")
        left, top = _legend_place(board, key, _tool(axis, clip), ahead)
        key.move_to((left + key.width / 2, top - key.height / 2, 0))
        kept += [trace, key]
        # no red burst: red is the verdict's, which comes with the claim (a red flash at the
        # pick stood before any claim was made, Rotation in chapter 2)
        anims += [Create(trace), FadeIn(key)]
    return kept, anims


def _legend_place(board: Board, key: Mobject, tool: shapely.LineString,
                  ahead: shapely.Geometry | None = None) -> tuple[float, float]:
    """The left and top of the run's legend entry: the first free place
    (:func:`metaphors.layout.free_place`) clear of the panel, the title, the subtitles, the
    vertex labels, P's and T's fills and the tool, where it is now and where it will still
    sweep (``ahead``: no moving shape crosses a text) — beside the picture's box (the box the
    sweep line is drawn in) where it can, else anywhere off the picture; where nothing is
    clear, the frame's top-left corner."""
    picture = [g for g in (outline(board.outline), outline(board.objects.get("T")))
               if g is not None]
    moving = [tool.buffer(0.08), *([ahead] if ahead is not None else [])]
    taken = shapely.union_all([*picture, *moving, *_beside(board)])
    x0, y0, x1, y1 = shapely.union_all(picture).bounds if picture else (0, 0, 0, 0)
    margin = 0.35  # the sweep line's margin round the polygon's box (:func:`_long_line`)
    frame_box = shapely.box(x0 - margin, y0 - margin, x1 + margin, y1 + margin)
    for around in (shapely.union(taken, frame_box), taken):
        found = free_place(key.width, key.height, around)
        if found is not None:
            return found
    return FRAME_AREA[0], FRAME_AREA[3]


def _beside(board: Board) -> list[shapely.Geometry]:
    """What stands on screen beside the picture (:mod:`metaphors.layout`): its vertex labels
    (and dots), the panel's whole column, the subtitles' band and the title's whole line.
    Wider than the monotone stack's (:mod:`metaphors.monotone`): an entry among the panel's
    polygon labels, code and call line read as the panel's ("A ▪ outside P, in T"), and one
    beside a short title as part of it."""
    areas = [*areas_of(board.markers.values()), panel_column(), subtitle_band(),
             title_area(board.title, whole_line=True)]
    return [shapely.box(*a) for a in areas]


def _tool(axis: Line, clip: shapely.Polygon | None = None) -> shapely.LineString:
    """The tool's segment as shapely (scene coordinates)."""
    start, end = axis.get_start(), axis.get_end()
    if clip is not None:
        start, end = _cut(start, end, clip)
    return shapely.LineString([tuple(start[:2]), tuple(end[:2])])


def _astray_at(board: Board, axis: Line, clip: shapely.Polygon | None,
               at: np.ndarray) -> tuple[tuple, tuple] | None:
    """The piece of the tool outside the polygon but inside T that passes through `at`."""
    (x0, y0), (x1, y1) = _tool(axis, clip).coords
    start, end = np.array([x0, y0, 0.0]), np.array([x1, y1, 0.0])
    parts = split_segment(start, end, outline(board.outline), outline(board.objects.get("T")))
    point = shapely.Point(at[:2])
    for p, q in parts["astray"]:
        if shapely.LineString([p, q]).distance(point) < 1e-3:
            return p, q
    return None


def _3d(p) -> np.ndarray:
    return np.array([p[0], p[1], 0.0])


# --- the performer -------------------------------------------------------------------------------


def sweep(board: Board, beat: Sweep) -> None:
    """The line starts through B and moves across T by the log's offsets, and stops at the
    first candidate it touches, the pick, which lights amber: the candidates after it decide
    nothing (:func:`story.states.hits`)."""
    states = beat.states
    first = states[0]
    through, direction = first.through, first.direction
    reached = hits(states[1:], until=beat.result)
    if not reached:
        board.play(beat, run_time=1.0)
        return
    normal = side_normal(direction, through, board.polygon.points[
        board.polygon.labels.index(reached[0][1])])
    start, end, box = _long_line(board, through, direction)
    axis = tag(Line(start, end, stroke_opacity=0), "argument", "sweep")
    picked = [False]  # set once the line has reached its pick
    drawing = follower(board, axis, board.theme.sweep, "sweep", clip=box,
                       picked=picked).set_z_index(1)
    origin = board.at(through)
    step = board.at((through[0] + normal[0], through[1] + normal[1])) - origin  # one unit, scene
    board.scene.add(axis)
    # the pick stays a candidate until the line reaches it: amber then, with its ring
    board.play(beat.before_pick(), FadeIn(drawing), run_time=0.6)
    lit, offset = [], 0.0
    last = reached[-1][0].offset
    for k, (state, label) in enumerate(reached):
        travel = state.offset - offset
        offset = state.offset
        board.play(beat if picked[0] else beat.before_pick(), axis.animate.shift(step * travel),
                   run_time=0.6 + board.length(abs(travel)) / 2.5)
        # what the line still sweeps over, from here to its last candidate
        now, then = _tool(axis, box), _tool(axis.copy().shift(step * (last - offset)), box)
        ahead = shapely.MultiPoint([*now.coords, *then.coords]).convex_hull
        kept, anims = light(board, label, k == 0, axis, box, ahead)
        lit += kept
        board.play(beat, *anims, run_time=0.8 if k == 0 else 0.6)
        picked[0] = True
    drawing.clear_updaters()
    board.scene.remove(axis)
    board.play(beat, FadeOut(drawing), *[FadeOut(r) for r in lit], run_time=0.5)


def _long_line(board: Board, through: Point, direction: Point,
               ) -> tuple[np.ndarray, np.ndarray, shapely.Polygon]:
    """A line through `through` along `direction`, far longer than the polygon (scene points),
    and the box the drawing is cut to: the polygon's bounding box grown by a margin, so the line
    never leaves the metaphor's half of the screen."""
    margin = 0.35
    lo = board.outline.get_corner(np.array([-1, -1, 0]))[:2] - margin
    hi = board.outline.get_corner(np.array([1, 1, 0]))[:2] + margin
    origin = board.at(through)[:2]
    ahead = board.at((through[0] + direction[0], through[1] + direction[1]))[:2] - origin
    ahead = ahead / np.linalg.norm(ahead)
    reach = float(np.linalg.norm(hi - lo)) * 3
    return _3d(origin - ahead * reach), _3d(origin + ahead * reach), shapely.box(*lo, *hi)


def _cut(start, end, box):
    """The part of start–end inside the box (a zero-length segment at start if none)."""
    cut = shapely.LineString([tuple(start[:2]), tuple(end[:2])]).intersection(box)
    if cut.is_empty or cut.geom_type != "LineString":
        return start, start
    return _3d(cut.coords[0]), _3d(cut.coords[-1])


def _move(walk: Walk, call: Event, ret: Event) -> dict[str, Any]:
    """The line through B, then at each candidate it touches (:func:`story.reach.sweeping`)."""
    through = point(walk.root_points()[walk.ref(call, "b")])
    direction = point(arg(call, "direction"))
    return {"states": (Sweeping(through=through, direction=direction, offset=0.0),
                       *(Sweeping(through=through, direction=direction, offset=d, reached=v)
                         for v, d in walk.reach(call, ret)))}


READS: Mapping[str, Reading] = {"first_hit_sweeping": read_step(
    Sweep, "The line sweeps across T; the first candidate it touches is {result}", _move,
    picks=True)}
PERFORMS: Performances = performs(act(Sweep, sweep))
