"""Water: spilled at B it spreads as a growing disk (``scaling``); it rises from the shore AC
towards B (``scaling-correct``); it spreads but respects the walls (``scaling-walled``).

Radii, levels and the order in which vertices get wet are read from the log's shape states.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from typing import Any, TypeVar

import shapely
from manim import (
    FadeIn,
    FadeOut,
    Flash,
    Indicate,
    Mobject,
    UpdateFromAlphaFunc,
    VMobject,
    config,
)
from manim import Polygon as MPolygon

from geometry.visibility import visible_region
from metaphors.board import Board
from metaphors.layout import SUBTITLE_Y, TITLE_Y
from metaphors.performing import Performances, act, performs
from metaphors.tags import tag
from story.beats import Beat, beat_kind
from story.reach import distance
from story.states import Disk, Moving, Point, Tide, hits, point
from story.storyboard import Reading, Walk, pick_roles, read_step, refs, show
from tracing import Event


@beat_kind("water")
class Water(Moving):
    """Water spilled at B: the disk's ``states`` (centre, radius, the vertex it reached)."""

    states: tuple[Disk, ...]


@beat_kind("walled-water")
class WalledWater(Moving):
    """Water that respects the walls; ``visible`` pairs each vertex reached with whether B
    sees it."""

    states: tuple[Disk, ...]
    visible: tuple[tuple[str, bool], ...]


@beat_kind("flood")
class Flood(Moving):
    """Water rising from the shore AC: the tide's ``states`` (level, the vertex it reached)."""

    states: tuple[Tide, ...]


def _spread(walk: Walk, call: Event, ret: Event) -> dict[str, Any]:
    """The disk through each candidate in the order it wets them (:func:`story.reach.spreading`)."""
    centre = point(walk.root_points()[walk.ref(call, "b")])
    return {"states": (Disk(center=centre, radius=0.0),
                       *(Disk(center=centre, radius=r, reached=v)
                         for v, r in walk.reach(call, ret)))}


def _walled(walk: Walk, call: Event, ret: Event) -> dict[str, Any]:
    """The disk through each vertex B was tested to see, nearest first, until one was seen."""
    where = walk.root_points()
    labels = walk.entered_after(call, walk.ref(call, "t"))["labels"]
    centre = point(where[labels[1]])
    sees = [e for e in walk.log.events[call.seq:ret.seq] if e.kind == "call" and e.name == "sees"]
    reached = [walk.ref(s, "v") for s in sees]
    return {"states": (Disk(center=centre, radius=0.0, walled=True),
                       *(Disk(center=centre, radius=distance(centre, where[v]), reached=v,
                              walled=True) for v in reached)),
            "visible": tuple((v, bool(walk.returns[s.seq].result)) for v, s in
                             zip(reached, sees, strict=True))}


def _read_walled(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """Water that respects the edges: its beat (:func:`_walled`), its caption saying which
    vertices it never reaches (an edge in the way) before the one it wets, and the roles
    the picture and the panel share: what it wets amber (the claim to be), every candidate
    of T it never reaches still a candidate (D went white in the panel while it flashed an
    unexplained red on the picture, review of ScalingWalled at 9.0 s)."""
    made = _walled(walk, call, ret)
    result = show(ret.result)
    dry = [v for v, seen in made["visible"] if not seen]
    caption = (f"The edges keep the water from {_and(dry)}; the first vertex it wets is {result}"
               if dry else f"The water, kept in by the edges, wets {result} first")
    candidates = set(_frame_candidates(walk, call))
    made["roles"] = {**pick_roles(call, ret),
                     **{v: "candidate" for v in dry if v in candidates}}
    yield walk.call_beat(WalledWater, caption, call, ret, result=result, **made)


def _frame_candidates(walk: Walk, call: Event) -> list[str]:
    """The candidates in T the run found before ``call`` (none if it found none)."""
    found = [e for e in walk.log.events[:call.seq]
             if e.kind == "return" and e.name == "candidates_in_triangle"]
    return refs(found[-1].result) if found else []


def _and(names: list[str]) -> str:
    """``D``, ``D and F``, ``D, F and G``."""
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} and {names[-1]}"


def _rise(walk: Walk, call: Event, ret: Event) -> dict[str, Any]:
    """The tide rising from AC through each candidate, the last one dry (:func:`story.reach.rising`)."""
    t = walk.entered_after(call, walk.ref(call, "t"))
    a, b, c = (point(p) for p in t["points"])
    return {"states": (Tide(shore=(a, c), towards=b, level=0.0),
                       *(Tide(shore=(a, c), towards=b, level=h, reached=v)
                         for v, h in walk.reach(call, ret)))}


#: how far from the title's and the subtitle's middle line the water stops (above a one-line
#: subtitle's top, below the title's bottom)
TEXT_CLEARANCE = 0.35


def _triangle(board: Board, center: Point) -> shapely.Polygon:
    """T on screen: B (where the water is spilled) and its two neighbours."""
    points = board.polygon.points
    k = points.index(tuple(center))
    return shapely.Polygon([tuple(board.at(points[j])[:2])
                            for j in (k - 1, k, (k + 1) % len(points))])


def _disk(board: Board, center: Point, radius: float) -> MPolygon:
    """The water's disk inside T, as the card draws it: the water is spilled to find T's
    candidates, and the whole disk ran off the screen's left edge, was cut flat under the
    title and lay over B's and E's labels (chapter 2 at 32.6 s). Also cut where the
    picture's part of the screen ends (T reaches no further, but a polygon handed to the
    lecture may be drawn larger)."""
    x, y = board.at(center)[:2]
    right = board.box.x + board.box.width / 2
    disk = shapely.Point(x, y).buffer(max(board.length(radius), 1e-3), 64).intersection(
        shapely.box(-config.frame_width / 2, SUBTITLE_Y + TEXT_CLEARANCE, right,
                    TITLE_Y - TEXT_CLEARANCE)).intersection(_triangle(board, center))
    corners = [(px, py, 0.0) for px, py in list(disk.exterior.coords)[:-1]] if isinstance(
        disk, shapely.Polygon) and not disk.is_empty else [(x, y, 0.0)] * 3
    return tag(MPolygon(*corners, color=board.theme.water, stroke_width=board.theme.thin_stroke,
                        fill_color=board.theme.water, fill_opacity=0.3), "argument", "water")


def water(board: Board, beat: Water) -> None:
    """The disk grows to the first candidate it wets, the pick, and stops there."""
    states = beat.states
    disk = _disk(board, states[0].center, 0.0)
    # the pick stays a candidate until the water reaches it (:func:`wets`)
    shown = beat.before_pick()
    board.play(shown, FadeIn(disk), run_time=0.5)
    radius = 0.0
    for state, reached in hits(states[1:], until=beat.result):
        board.play(shown, _grow(board, disk, state.center, radius, state.radius), run_time=1.2)
        shown = wets(board, beat, shown, reached)
        radius = state.radius
    board.play(beat, FadeOut(disk), run_time=0.5)


M = TypeVar("M", bound=Moving)


def wets(board: Board, beat: M, shown: M, reached: str) -> M:
    """The water has reached ``reached``: the pick turns amber (the claim to be) now, with
    a flash where it stands (a pulse would hide its recolouring); another candidate pulses
    in its pink. Returns the beat as shown from now on."""
    if reached == beat.result:
        board.play(beat, Flash(board.vertex(reached), color=board.theme.argument,
                               flash_radius=0.3), run_time=0.6)
        return beat
    board.play(shown, Indicate(board.markers[reached], color=board.theme.candidate),
               run_time=0.6)
    return shown


def _grow(board: Board, disk: MPolygon, center: Point, start: float, end: float,
          ) -> UpdateFromAlphaFunc:
    """The disk growing from radius ``start`` to ``end``, cut anew in every frame: a
    Transform to the cut disk would shrink its cut edge into the picture on the way."""
    def update(mobject: Mobject, alpha: float) -> None:
        mobject.become(_disk(board, center, start + (end - start) * alpha))

    return UpdateFromAlphaFunc(disk, update)


def walled_water(board: Board, beat: WalledWater) -> None:
    """The disk clipped to what B sees: water that cannot flow through walls."""
    states = beat.states
    centre = states[0].center
    region = visible_region(board.polygon, board.polygon.points.index(tuple(centre)))
    disk = tag(MPolygon(board.at(centre), board.at(centre)), "argument", "water")
    # the pick stays a candidate until the water reaches it (:func:`wets`)
    shown = beat.before_pick()
    board.play(shown, FadeIn(disk), run_time=0.3)
    visible = dict(beat.visible)
    radius = 0.0
    for state, reached in hits(states[1:], until=beat.result):

        def wet(alpha: float, start: float = radius, end: float = state.radius):
            return region.intersection(
                shapely.Point(centre).buffer(max(start + (end - start) * alpha, 1e-9), 64))

        board.play(shown, _filling(board, disk, wet, "water", centre), run_time=1.2)
        # the vertex it wets flashes as it is wet (the pick amber, the claim to be, as the
        # panel shows it); one an edge keeps the water from is never wet, and does not flash
        # (it flashed red, a colour the legend keeps for "fails", and B's not seeing it went
        # unsaid)
        if visible.get(reached, False):
            shown = wets(board, beat, shown, reached)
        radius = state.radius
    board.play(beat, FadeOut(disk), run_time=0.5)


def _filling(board: Board, shape: VMobject, region_at, name: str, at: Point
             ) -> UpdateFromAlphaFunc:
    """The water filling ``region_at(alpha)`` (polygon coordinates) in every frame: a
    Transform from one clipped region to the next interpolates corner to corner, which
    opened a dry hole in the water (Scaling with walls at 10.3 s: a dark box at B) and
    bent the rising band round D."""
    def update(mobject: Mobject, alpha: float) -> None:
        mobject.become(_region_mobject(board, region_at(alpha), name, at))

    return UpdateFromAlphaFunc(shape, update)


def _region_mobject(board: Board, geometry: shapely.Geometry, name: str = "water",
                    at: Point = (0.0, 0.0)) -> VMobject:
    """The polygons of a region (polygon coordinates) as one filled shape, each part a path
    of its own: water clipped to the polygon may lie in two pools. No part: an invisible
    point at ``at``."""
    parts = [g for g in shapely.get_parts(geometry) if g.geom_type == "Polygon" and not g.is_empty]
    shape = VMobject(color=board.theme.water, stroke_width=board.theme.thin_stroke,
                     fill_color=board.theme.water, fill_opacity=0.3)
    if not parts:
        shape.set_points_as_corners([board.at(at), board.at(at)])
        shape.set_stroke(opacity=0).set_fill(opacity=0)
    for part in parts:
        corners = [board.at(p) for p in part.exterior.coords]
        shape.start_new_path(corners[0])
        shape.add_points_as_corners(corners[1:])
    return tag(shape, "argument", name)


def flood(board: Board, beat: Flood) -> None:
    """A band of water rises from AC towards B; each candidate goes under in turn, the last
    one still dry is the pick."""
    states = beat.states
    a, c = states[0].shore
    towards = states[0].towards
    # the water inside P only: the shore AC lies outside P where P has a notch, and water
    # drawn there in blue would contradict the legend (red: outside P)
    inner = shapely.Polygon(board.polygon.points).intersection(shapely.Polygon([a, c, towards]))
    band = _region_mobject(board, shapely.GeometryCollection(), "flood",
                           ((a[0] + c[0]) / 2, (a[1] + c[1]) / 2))
    # going under is no failure: a candidate still, as the clock's and the sweep's later
    # ones (red means "fails", metaphors.theme's legend); the last one, the pick, amber as
    # the water reaches it (:func:`wets`): the claim to be, and not before (shown as the
    # beat with the band coming in, E went amber, back to pink, then amber again)
    shown = beat.before_pick()
    board.play(shown, FadeIn(band), run_time=0.3)
    level = 0.0
    middle = ((a[0] + c[0]) / 2, (a[1] + c[1]) / 2)
    for state, reached in hits(states[1:], until=beat.result):

        def wet(alpha: float, start: float = level, end: float = state.level):
            return inner.intersection(_strip(a, c, towards, start + (end - start) * alpha))

        board.play(shown, _filling(board, band, wet, "flood", middle), run_time=1.2)
        shown = wets(board, beat, shown, reached)
        level = state.level
    board.play(beat, FadeOut(band), run_time=0.5)


def _strip(a: Point, c: Point, towards: Point, level: float) -> shapely.Polygon:
    """Points of the plane within `level` of line AC on B's side."""
    dx, dy = c[0] - a[0], c[1] - a[1]
    length = math.hypot(dx, dy)
    nx, ny = -dy / length, dx / length
    side = (towards[0] - a[0]) * nx + (towards[1] - a[1]) * ny
    if side < 0:
        nx, ny = -nx, -ny
    far = 1e3 * length
    ux, uy = dx / length * far, dy / length * far
    return shapely.Polygon([
        (a[0] - ux, a[1] - uy), (a[0] + ux, a[1] + uy),
        (a[0] + ux + nx * level, a[1] + uy + ny * level), (a[0] - ux + nx * level, a[1] - uy + ny * level),
    ])


READS: Mapping[str, Reading] = {
    "nearest_to": read_step(
        Water, "Water spilled at B spreads; the first candidate it wets is {result}", _spread,
        picks=True),
    "nearest_visible": _read_walled,
    "last_dry": read_step(
        Flood, "Water rises from the shore AC; the last dry candidate is {result}", _rise, picks=True),
}
PERFORMS: Performances = performs(act(Water, water), act(WalledWater, walled_water),
                                  act(Flood, flood))
