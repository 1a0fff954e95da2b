"""The analysis of a heuristic's decisive moment: what its tool sweeps on the way to the vertex
it picks, and which part of that lies outside the polygon.

Drawing data for the lecture's analysis (:mod:`metaphors.analysis`). The pick and the verdict
come from the log (decided exactly by the heuristic and :mod:`geometry.check`); here the
shapes are clipped against the polygon with shapely, in polygon coordinates, for the picture.

A *motion* is the tool of a heuristic moving from where it starts (``t = 0``) to the vertex
it picks (``t = 1``): the water's circle growing, the clock hand turning, the line sweeping,
the water rising from the shore AC. Its :meth:`Motion.witness` is the part of T the argument
is about — the region swept on the way (the disk, the wedge, the strip), or what is still
dry when the rising water reaches its pick. A wrong heuristic's witness reaches outside the
polygon (:meth:`Motion.astray`, drawn red); a correct one's lies inside it, so the segment
from B to the pick does too. Gravity's band (:class:`Band`) sweeps the region between the
drop line and the band, always inside the polygon.

Examples
--------
>>> P = [(1.6, 8.0), (1.0, 4.5), (9.0, 2.0), (3.0, 6.5), (4.6, 4.1)]  # A B C D E
>>> T = P[:3]
>>> water = motion(Disk(center=(1.0, 4.5), radius=2.83, reached="D"), T)
>>> round(water.astray(P).area, 3) > 0  # the circle wets D through the wall E–A
True
>>> line = motion(Line(through=(1.0, 4.5), direction=(7.4, -6.0), offset=1.9566,
...                     reached="E"), T)
>>> line.astray(P).area < 1e-6  # the corrected sweep stays inside P until it reaches E
True
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import shapely
from shapely.geometry.base import BaseGeometry

from story.reach import side_normal
from story.states import Disk, Hand, Line, Tide, Tool

Point = Sequence[float]

#: how far a shape may stray from the polygon and still count as inside (polygon units,
#: relative to the polygon's size): shapely's float clipping leaves slivers along edges
SLACK = 1e-7
#: degrees per step of a swept wedge's far arc (it lies outside T, so only its ends matter)
ARC_STEP = 5.0


def shape(points: Sequence[Point]) -> shapely.Polygon:
    """The shapely polygon through ``points``."""
    return shapely.Polygon([tuple(p[:2]) for p in points])


def _size(region: BaseGeometry) -> float:
    x0, y0, x1, y1 = region.bounds
    size: float = max(x1 - x0, y1 - y0, 1e-12)
    return size


def outside(geometry: BaseGeometry, polygon: Sequence[Point]) -> BaseGeometry:
    """The part of ``geometry`` outside ``polygon`` (its boundary counts as inside).

    >>> round(outside(shapely.LineString([(-1, 1), (3, 1)]), [(0, 0), (2, 0), (2, 2), (0, 2)])
    ...       .length, 6)
    2.0
    """
    region = shape(polygon)
    return _clean(geometry.difference(region.buffer(SLACK * _size(region))))


def inside(geometry: BaseGeometry, polygon: Sequence[Point]) -> BaseGeometry:
    """The part of ``geometry`` inside ``polygon`` (boundary included)."""
    region = shape(polygon)
    return _clean(geometry.intersection(region.buffer(SLACK * _size(region))))


def _clean(geometry: BaseGeometry) -> BaseGeometry:
    """Without the slivers and crumbs float clipping leaves (parts far thinner than SLACK)."""
    parts = [g for g in shapely.get_parts(geometry)
             if (g.area if g.geom_type == "Polygon" else g.length) > 1e-9]
    return shapely.union_all(parts) if parts else shapely.GeometryCollection()


def lies_inside(geometry: BaseGeometry, polygon: Sequence[Point]) -> bool:
    """Whether ``geometry`` lies in ``polygon`` (up to float slack).

    >>> lies_inside(shapely.box(0.5, 0.5, 1, 1), [(0, 0), (2, 0), (2, 2), (0, 2)])
    True
    """
    empty: bool = outside(geometry, polygon).is_empty
    return empty


def split(geometry: BaseGeometry, polygon: Sequence[Point],
          triangle: Sequence[Point]) -> dict[str, BaseGeometry]:
    """``geometry`` in three parts: ``inside`` the polygon, ``astray`` (outside it but inside
    T: the part that can reach a wrong vertex first) and ``beyond`` (outside both).

    >>> parts = split(shapely.LineString([(-1, 1), (5, 1)]), [(0, 0), (2, 0), (2, 2), (0, 2)],
    ...               [(0, 0), (4, 0), (4, 2)])
    >>> {k: round(g.length, 3) for k, g in parts.items()}
    {'inside': 2.0, 'astray': 2.0, 'beyond': 2.0}
    """
    out = outside(geometry, polygon)
    return {"inside": inside(geometry, polygon), "astray": inside(out, triangle),
            "beyond": outside(out, triangle)}


# --- the motions -----------------------------------------------------------------------------


@dataclass(frozen=True)
class Motion:
    """A heuristic's tool from its start to its pick, in polygon coordinates.

    ``state`` is the tool's state at the pick (:mod:`story.states`): a :class:`Disk` (water
    spilled at its centre, growing to its radius), a :class:`Hand` (a clock hand set to its
    heading, turning by its angle; ``sign`` +1 counter-clockwise), a :class:`Line` (the line
    through a point along its direction, moving by its offset along the unit normal
    ``normal``) or a :class:`Tide` (water rising from its shore to its level towards B, along
    ``normal``). ``triangle`` is T.
    """

    state: Tool
    triangle: tuple[tuple[float, float], ...]
    sign: int = 1
    normal: tuple[float, float] = (1.0, 0.0)

    @property
    def reached(self) -> str:
        """The vertex the tool stops at."""
        return str(self.state.reached)

    @property
    def rising(self) -> bool:
        """Whether this is the rising water: its witness is what is still dry."""
        return isinstance(self.state, Tide)

    @property
    def origin(self) -> tuple[float, float]:
        """Where the tool starts from: the disk's centre, the hand's hub, the line's point,
        B for the tide."""
        match self.state:
            case Disk(center=p) | Hand(origin=p) | Line(through=p) | Tide(towards=p):
                return _pt(p)
        raise TypeError(f"no motion for {self.state!r}")

    @property
    def t_shape(self) -> shapely.Polygon:
        return shape(self.triangle)

    def _far(self) -> float:
        """A length far beyond T: lines this long leave T on both sides."""
        return 4 * _size(self.t_shape) + 4 * math.dist(self.origin, self.t_shape.centroid.coords[0])

    def tool(self, t: float = 1.0) -> BaseGeometry:
        """The tool at time ``t`` (0: the start, 1: at its pick): the circle's rim, or the
        hand, the line or the water's level inside T."""
        match self.state:
            case Disk(radius=radius):
                return shapely.Point(self.origin).buffer(max(t * float(radius), 1e-9),
                                                         64).exterior
            case Hand(heading=heading, angle=angle):
                far = _ahead(self.origin, float(heading) + self.sign * t * float(angle),
                             self._far())
                return _within(shapely.LineString([self.origin, far]), self.t_shape)
        (px, py), (dx, dy) = self._line_at(t), self._direction()
        norm, length = math.hypot(dx, dy), self._far()
        ux, uy = dx / norm * length, dy / norm * length
        return _within(shapely.LineString([(px - ux, py - uy), (px + ux, py + uy)]),
                       self.t_shape)

    def swept(self, t: float = 1.0) -> BaseGeometry:
        """What the tool has passed over by time ``t``, inside T (for the rising water: what
        is under water)."""
        match self.state:
            case Disk(radius=radius):
                region = shapely.Point(self.origin).buffer(max(t * float(radius), 1e-9), 64)
            case Hand(heading=heading, angle=angle):
                heading, angle = float(heading), float(angle)
                steps = max(2, math.ceil(angle * t / ARC_STEP) + 1)
                region = shapely.Polygon([self.origin, *(
                    _ahead(self.origin, heading + self.sign * angle * t * k / (steps - 1),
                           self._far()) for k in range(steps))])
            case _:
                region = _strip(self._line_at(0.0), self._line_at(t), self._direction(),
                                self._far())
        return _clean(self.t_shape.intersection(region))

    def witness(self) -> BaseGeometry:
        """The part of T the argument is about, at the pick: what the tool swept on its way
        there; for the rising water, what is still dry (on B's side of the level)."""
        if self.rising:
            return _clean(self.t_shape.difference(self.swept(1.0)))
        return self.swept(1.0)

    def astray(self, polygon: Sequence[Point]) -> BaseGeometry:
        """The witness's part outside ``polygon``: empty for a correct heuristic."""
        return outside(self.witness(), polygon)

    def _direction(self) -> tuple[float, float]:
        """The direction of the line, or of the tide's level (along its shore)."""
        match self.state:
            case Line(direction=d):
                return _pt(d)
            case Tide(shore=(a, c)):
                return (float(c[0]) - float(a[0]), float(c[1]) - float(a[1]))
        raise TypeError(f"{self.state!r} moves along no line")

    def _line_at(self, t: float) -> tuple[float, float]:
        """A point of the line (or the level) at time ``t``."""
        nx, ny = self.normal
        match self.state:
            case Tide(shore=(a, _), level=level):
                (ax, ay), amount = _pt(a), float(level)
                return (ax + nx * t * amount, ay + ny * t * amount)
            case Line(offset=offset):
                (ox, oy), amount = self.origin, float(offset)
                return (ox + nx * t * amount, oy + ny * t * amount)
        raise TypeError(f"{self.state!r} moves along no line")


def motion(reached: Tool, triangle: Sequence[Point]) -> Motion:
    """The motion that ends in a metaphor's tool state at its pick (the states the
    storyboard computes: :mod:`story.reach` via the metaphors' readings; each starts from
    radius, angle, offset or level 0).

    >>> m = motion(Hand(origin=(9.0, 2.0), heading=162.6, angle=8.16, reached="E"),
    ...            [(1.6, 8.0), (1.0, 4.5), (9.0, 2.0)])
    >>> type(m.state).__name__, m.sign, m.reached
    ('Hand', -1, 'E')
    """
    t = tuple((float(p[0]), float(p[1])) for p in triangle)
    match reached:
        case Disk():
            return Motion(reached, t)
        case Hand(origin=origin, heading=heading, angle=angle):
            return Motion(reached, t, sign=_turn_sign(_pt(origin), float(heading), angle, t))
        case Line(through=through, direction=direction):
            return Motion(reached, t, normal=side_normal(_pt(direction), _pt(through),
                                                         _centroid(t)))
        case Tide(shore=(a, c), towards=towards):
            direction = (float(c[0]) - float(a[0]), float(c[1]) - float(a[1]))
            return Motion(reached, t, normal=side_normal(direction, _pt(a), _pt(towards)))
    raise TypeError(f"no motion for {reached!r}")


def _pt(p: Point) -> tuple[float, float]:
    return (float(p[0]), float(p[1]))


def _centroid(points: Sequence[Point]) -> tuple[float, float]:
    return _pt(shape(points).centroid.coords[0])


def _ahead(origin: Point, heading: float, length: float) -> tuple[float, float]:
    a = math.radians(heading)
    return (origin[0] + math.cos(a) * length, origin[1] + math.sin(a) * length)


def _turn_sign(origin: Point, heading: float, angle: float, triangle: Sequence[Point]) -> int:
    """The way a hand at a corner of T turns: into T (the way towards its centre)."""
    (cx, cy), (ox, oy) = _centroid(triangle), origin
    towards = math.degrees(math.atan2(cy - oy, cx - ox))
    return 1 if (towards - heading + 180.0) % 360.0 - 180.0 > 0 else -1


def _strip(p: Point, q: Point, direction: Point, far: float) -> shapely.Polygon:
    """The strip between the lines through p and q along ``direction``."""
    dx, dy = direction
    norm = math.hypot(dx, dy)
    ux, uy = dx / norm * far, dy / norm * far
    return shapely.Polygon([(p[0] - ux, p[1] - uy), (p[0] + ux, p[1] + uy),
                            (q[0] + ux, q[1] + uy), (q[0] - ux, q[1] - uy)]).buffer(0)


def _within(line: shapely.LineString, region: shapely.Polygon) -> BaseGeometry:
    """The part of a line in a region (boundary included)."""
    return _clean(line.intersection(region.buffer(SLACK * _size(region))))


# --- gravity's band ------------------------------------------------------------------------------


@dataclass(frozen=True)
class Band:
    """Gravity's rubber band from the reflex vertex ``v`` to the ball, which slides from the
    point it ``hit`` down to the vertex ``x``; the band snags ``y`` on the way, or stays
    straight (``y`` None). ``turn`` is the degrees the picture turns so gravity points down.

    >>> band = Band((0.0, 0.0), (6.11, 2.36), (4.0, 8.0), (4.0, 4.0), -111.1)
    >>> band.corners(1.0)
    [(0.0, 0.0), (4.0, 4.0), (4.0, 8.0)]
    >>> band.corners(0.0)
    [(0.0, 0.0), (6.11, 2.36)]
    >>> round(band.swept(1.0).area, 2)  # the triangle V-hit-X without V-Y-X, behind Y
    11.72
    """

    v: tuple[float, float]
    hit: tuple[float, float]
    x: tuple[float, float]
    y: tuple[float, float] | None
    turn: float = 0.0

    def ball(self, t: float) -> tuple[float, float]:
        """Where the ball is at time ``t`` of its slide (0: where it hit, 1: at X)."""
        (hx, hy), (xx, xy) = self.hit, self.x
        return (hx + (xx - hx) * t, hy + (xy - hy) * t)

    @property
    def snag_time(self) -> float | None:
        """When the band meets Y: the ball on the line V–Y."""
        if self.y is None:
            return None
        (vx, vy), (yx, yy) = self.v, self.y
        (hx, hy), (xx, xy) = self.hit, self.x
        ex, ey, dx, dy = xx - hx, xy - hy, yx - vx, yy - vy
        denom = ex * dy - ey * dx
        if abs(denom) < 1e-15:
            return 0.0
        return min(1.0, max(0.0, ((vx - hx) * dy - (vy - hy) * dx) / denom))

    def corners(self, t: float) -> list[tuple[float, float]]:
        """The band at time ``t``: V to the ball, bent round Y once it has met it."""
        ball = self.ball(t)
        snag = self.snag_time
        if snag is not None and t > snag and self.y is not None:  # a snag time needs a Y
            return [self.v, self.y, ball]
        return [self.v, ball]

    def swept(self, t: float) -> BaseGeometry:
        """What the band has swept by time ``t``: V, the hit point, the ball (and Y)."""
        corners = [self.v, self.hit, self.ball(t)]
        snag = self.snag_time
        if snag is not None and t > snag and self.y is not None:  # a snag time needs a Y
            corners.append(self.y)
        region = shapely.Polygon(corners)
        return region.buffer(0) if region.area > 1e-12 else shapely.GeometryCollection()


# --- the band pulled taut ----------------------------------------------------------------------


def _cross(o: Point, a: Point, b: Point) -> float:
    return float((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]))


def _strictly_inside(p: Point, a: Point, b: Point, c: Point) -> bool:
    """Whether ``p`` lies inside the triangle a-b-c, off its sides (by a relative hair)."""
    hair = 1e-9 * max(abs(_cross(a, b, c)), 1e-12)
    sides = (_cross(a, b, p), _cross(b, c, p), _cross(c, a, p))
    return all(s > hair for s in sides) or all(s < -hair for s in sides)


def taut(v: Point, hit: Point, ball: Point, points: Sequence[Point]) -> list[tuple[float, float]]:
    """The rubber band from ``v`` to the ball, pulled taut round the ``points`` (the
    polygon's vertices) it has swept: the ball slid from ``hit`` along an edge, so the band
    swept the triangle v-hit-ball, and it wraps round the vertices inside it — the arc of
    their convex hull (with v and the ball) from v to the ball on the hit's side. Never the
    straight v-ball once a vertex stands in the way: that one runs outside P.

    >>> taut((0, 0), (0, -4), (4, -4), [(1, -2), (9, 9)])  # (1, -2) is in the way
    [(0.0, 0.0), (1.0, -2.0), (4.0, -4.0)]
    >>> taut((0, 0), (0, -4), (1, -4), [(3, -2)])
    [(0.0, 0.0), (1.0, -4.0)]
    """
    start, end = _pt(v), _pt(ball)
    inside = [_pt(p) for p in points if _strictly_inside(p, v, hit, ball)]
    if not inside:
        return [start, end]
    ring = [_pt(p) for p in shapely.MultiPoint([start, end, *inside]).convex_hull
            .exterior.coords[:-1]]
    i, j = ring.index(start), ring.index(end)
    ahead = [ring[(i + k) % len(ring)] for k in range((j - i) % len(ring) + 1)]
    back = [ring[(i - k) % len(ring)] for k in range((i - j) % len(ring) + 1)]
    return ahead if len(ahead) > len(back) else back  # the other arc is the straight v-ball


def wraps(v: Point, hit: Point, x: Point, points: Sequence[Point]
          ) -> list[tuple[float, list[tuple[float, float]]]]:
    """The band's slide from ``hit`` to ``x`` in pieces ``(t, corners)``: from the time
    ``t`` (0 at the hit, 1 at X) it wraps the ``corners`` before its free end, the ball, up
    to the next piece's time; each piece begins as the band's free end meets one more vertex
    (the ball on the line through the last two corners).

    >>> wraps((0, 0), (0, -4), (4, -4), [(1, -2)])
    [(0.0, [(0.0, 0.0)]), (0.5, [(0.0, 0.0), (1.0, -2.0)])]
    """
    corners = taut(v, hit, x, points)[:-1]
    (hx, hy), (xx, xy) = _pt(hit), _pt(x)
    pieces = [(0.0, corners[:1])]
    for k in range(1, len(corners)):
        (ax, ay), (bx, by) = corners[k - 1], corners[k]
        ex, ey, dx, dy = xx - hx, xy - hy, bx - ax, by - ay
        denom = ex * dy - ey * dx
        t = ((ax - hx) * dy - (ay - hy) * dx) / denom if abs(denom) > 1e-15 else pieces[-1][0]
        pieces.append((min(1.0, max(pieces[-1][0], t)), corners[:k + 1]))
    return pieces


def band_at(pieces: Sequence[tuple[float, list[tuple[float, float]]]], hit: Point, x: Point,
            t: float) -> list[tuple[float, float]]:
    """The band drawn at time ``t`` of the slide (:func:`wraps`' ``pieces``): the corners it
    wraps by then, and the ball, ``t`` of the way from ``hit`` to ``x``.

    >>> band_at(wraps((0, 0), (0, -4), (4, -4), [(1, -2)]), (0, -4), (4, -4), 0.75)
    [(0.0, 0.0), (1.0, -2.0), (3.0, -4.0)]
    """
    corners = next(c for start, c in reversed(pieces) if start <= t or start == 0.0)
    (hx, hy), (xx, xy) = _pt(hit), _pt(x)
    return [*corners, (hx + t * (xx - hx), hy + t * (xy - hy))]
