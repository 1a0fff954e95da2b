"""The clock: a hand at B, set to A, turns — the first candidate it passes is D
(``rotation``; the thesis's clock has B in the middle and the candidates as hour marks: the
hand is all that is drawn of it). ``rotation-ccw`` sets it to C and turns the other way;
``rotation-correct`` moves the clock to C and sets it to B.

The hand is drawn solid inside the polygon and dashed outside; the part outside the polygon
but inside T is dashed red on the way to the first candidate — when the hand reaches it with
that part, the claim will cross an edge; turning on past it, the hand is red nowhere. The
angles and the order of the candidates are the log's shape states (each ``angle`` unsigned,
from the start ``heading``); the way the hand turns is the way towards the candidates.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence
from typing import Any

import numpy as np
import shapely
from manim import DEGREES, Dot, FadeIn, FadeOut, Line, Rotate

from metaphors.board import Board
from metaphors.performing import Performances, act, performs
from metaphors.sweep import follower, light
from metaphors.tags import tag
from story.beats import Beat, beat_kind
from story.reach import heading
from story.states import Hand, Moving, Point, hits, point
from story.storyboard import Reading, Walk, read_step
from tracing import Event


@beat_kind("clock")
class Clock(Moving):
    """The clock hand's ``states`` (heading, angle turned, the candidate reached)."""

    states: tuple[Hand, ...]


#: how far the hand reaches past the farthest candidate (scene units)
HAND_MARGIN = 0.35


def turn_sign(origin: Sequence[float], heading: float, point: Sequence[float]) -> int:
    """+1 if the hand turns counter-clockwise from `heading` (degrees) to reach `point`, else −1.

    >>> turn_sign([1.0, 4.5], 80.27, [3.0, 6.5])  # from A towards D: clockwise
    -1
    >>> turn_sign([1.0, -4.5], -80.27, [3.0, -6.5])  # the twin, from C: counter-clockwise
    1
    """
    towards = math.degrees(math.atan2(point[1] - origin[1], point[0] - origin[0]))
    delta = (towards - heading + 180.0) % 360.0 - 180.0
    return 1 if delta > 0 else -1


def clock(board: Board, beat: Clock) -> None:
    """The hand appears at its hub, set to the start vertex; it turns through the log's
    angles, and stops at the first candidate it passes, the pick, which lights amber: the
    candidates after it decide nothing (:func:`story.states.hits`).

    A hand turning about its hub is the clock: no face is drawn, nor hour marks (a grey
    wedge of 15–33 px at the hub, with an amber tick on the hand at the pick, that nothing
    on screen explained; review of the rotation scenes)."""
    theme = board.theme
    states = beat.states
    first = states[0]
    origin, heading = first.origin, first.heading
    reached = hits(states[1:], until=beat.result)
    if not reached:
        board.play(beat, run_time=1.0)
        return
    labels = [label for _, label in reached]
    sign = turn_sign(origin, heading, _point(board, labels[0]))
    centre = board.at(origin)
    reach = max(float(np.linalg.norm(board.vertex(label) - centre)) for label in labels)
    tip = centre + _unit(board.at(_ahead(origin, heading)) - centre) * (reach + HAND_MARGIN)

    last = reached[-1][0].angle
    hub = tag(Dot(centre, radius=theme.dot_radius * 1.4, color=theme.hand), "argument", "hub")
    axis = tag(Line(centre, tip, stroke_opacity=0), "argument", "hand")
    picked = [False]  # set once the hand has passed its pick
    hand = follower(board, axis, theme.hand, "hand", picked=picked).set_z_index(1)  # over the rings
    board.scene.add(axis)
    # the pick stays a candidate until the hand passes it: amber then, with its ring
    board.play(beat.before_pick(), FadeIn(hand), FadeIn(hub), run_time=0.8)

    lit, turned = [], 0.0
    for k, (state, label) in enumerate(reached):
        step = state.angle - turned
        turned = state.angle
        board.play(beat if picked[0] else beat.before_pick(),
                   Rotate(axis, angle=sign * step * DEGREES, about_point=centre),
                   run_time=0.6 + abs(step) / 60)
        kept, anims = light(board, label, k == 0, axis,
                            ahead=_wedge(centre, axis.get_end(), sign * (last - turned)))
        lit += kept
        board.play(beat, *anims, run_time=0.8 if k == 0 else 0.6)
        picked[0] = True
    hand.clear_updaters()
    board.scene.remove(axis)
    board.play(beat, *[FadeOut(m) for m in (hand, hub, *lit)], run_time=0.5)


def _wedge(centre: np.ndarray, tip: np.ndarray, degrees: float) -> shapely.Polygon:
    """What a hand from ``centre`` to ``tip`` sweeps over as it turns by ``degrees``
    (counter-clockwise if positive): a fan, in scene coordinates.

    >>> round(_wedge(np.array([0.0, 0, 0]), np.array([1.0, 0, 0]), 90).area, 2)  # a quarter disk
    0.79
    """
    (cx, cy), (dx, dy) = centre[:2], (tip - centre)[:2]
    steps = max(2, math.ceil(abs(degrees) / 3) + 1)
    fan = [(cx, cy)]
    for k in range(steps):
        a = math.radians(degrees * k / (steps - 1))
        fan.append((cx + dx * math.cos(a) - dy * math.sin(a), cy + dx * math.sin(a) + dy * math.cos(a)))
    shape = shapely.Polygon(fan)
    return shape if shape.area > 1e-9 else shapely.LineString(fan[:2]).buffer(1e-6)


def _point(board: Board, label: str) -> Point:
    return board.polygon.points[board.polygon.labels.index(label)]


def _ahead(origin: Point, heading: float) -> Point:
    return (origin[0] + math.cos(math.radians(heading)),
            origin[1] + math.sin(math.radians(heading)))


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)


def _turn(walk: Walk, call: Event, ret: Event) -> dict[str, Any]:
    """The hand set to the start, then at each candidate it passes (:func:`story.reach.turning`)."""
    where = walk.root_points()
    centre = point(where[walk.ref(call, "centre")])
    towards = heading(centre, where[walk.ref(call, "start")])
    return {"states": (Hand(origin=centre, heading=towards, angle=0.0),
                       *(Hand(origin=centre, heading=towards, angle=a, reached=v)
                         for v, a in walk.reach(call, ret)))}


def read_clock(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """The clock's step, its words naming where the clock stands: its centre turns blue
    with them (Correct Rotation's C turned blue under "The clock hand turns; …", unsaid)."""
    centre = walk.ref(call, "centre")
    caption = f"The clock hand at {centre} turns; the first candidate it passes is {{result}}"
    yield from read_step(Clock, caption, _turn, picks=True)(walk, call, ret)


READS: Mapping[str, Reading] = {"first_hit_rotating": read_clock}
PERFORMS: Performances = performs(act(Clock, clock))
