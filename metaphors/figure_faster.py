"""The figures of the faster algorithms' cards and of the recap (issue 22 item 7).

Each is computed from the geometry, as the runs are, in a card's figure box (``box``: its
centre, width and height), the card's words on the right:

* ``monotone-pieces``: what y-monotone means, drawn before the run names a kind of vertex:
  a horizontal line (in the sweep's colour) that meets P in two segments or more, each
  segment solid, and P cut into its y-monotone pieces by the sweep's diagonals (in the
  amber the run draws them in), each piece tinted: the line meets each piece once. The
  split and merge vertices are not marked: the run teaches them (the card named them 12 s
  before the run said what they are);
* ``measured``: the steps (sign tests: orientations and comparisons) faster ear clipping
  and monotone partition take, counted in real runs (:func:`story.sign_tests.measured`) on
  half discs whose straight side is dented in (ear clipping's worst case: its n² shows),
  against n on logarithmic axes named and ticked in plain words, two lines in the ink, each
  with its own mark and its name beside its end (no legend, no role's colour), the half disc
  drawn beside the words that say what was counted;
* ``delaunay-circle``: P's constrained Delaunay triangulation with one triangle's
  circumcircle, every vertex clearly inside or outside it, those inside (none of them seen
  from inside the triangle) marked;
* ``three-triangulations``: P as divide and conquer, faster ear clipping and monotone
  partition triangulate it, each with its bound: three different triangulations side by
  side (each alone is the end of a run, or the overview's figure; together they are new).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from itertools import pairwise

import numpy as np
import shapely
from manim import DR, RIGHT, UL, Circle, DashedLine, Dot, Line, Mobject, VGroup
from manim import Polygon as MPolygon

from geometry.cdt import constrained_delaunay
from geometry.io import read_polygon
from geometry.monotone import Sweep, classify_vertex, make_monotone
from geometry.monotone_pieces import monotone_pieces
from geometry.polygon import Polygon
from geometry.results import TriangleIndices
from geometry.triangulate import triangulate
from metaphors.drawing import Frame, polygon_mobject, triangle_mobject, triangulation_figure
from metaphors.figure_caption import figure_caption
from metaphors.figure_plots import Area, Series, axis_names, line_plot
from metaphors.labels import EDGE_MARGIN, placed_vertex_markers
from metaphors.layout import area_of
from metaphors.monotone import piece_tints
from metaphors.tags import tag
from metaphors.theme import Theme
from rendering import typeset
from story.registry import spoken
from story.sign_tests import measured

Box = tuple[tuple[float, float], float, float]  # a figure's centre, width and height

KINDS = ("monotone-pieces", "measured", "delaunay-circle", "three-triangulations")
#: the measured plot: the two faster algorithms, counted on polygons of these sizes
MEASURED_SIZES = (10, 20, 40, 80, 160)
MEASURED_RUNS = ("ear-clipping", "monotone")
#: the polygons counted (a sample family): half discs whose straight side is dented in, where
#: ear clipping's n² shows. Only these: the random polygons' two lines, where the two keep
#: pace, ran together with monotone partition's here, and with two dashed bounds made six
#: lines and a legend table that the teacher's review found crowded (the card says the
#: random polygons' result in words)
MEASURED_SHAPE = "half-disc"
#: each run's mark (:data:`metaphors.figure_plots.MARKS`): the lines are told apart by their
#: marks and the names beside their ends, both drawn in the ink, no role's colour (the palette's
#: teal and tan were the pieces' tints, its blue the called blue)
MEASURED_MARKS = {"ear-clipping": "square", "monotone": "dot"}
#: the half disc drawn beside the words that say what was counted (its dented side is seen),
#: this many vertices, this high (scene units)
ICON_N, ICON_HEIGHT = 12, 0.4
#: the recap's triangulations and the time bound each card says
RECAPPED = (("divide-and-conquer", "O(n²)"), ("ear-clipping", "O(n²)"),
            ("monotone", "O(n log n)"))


def figure_mobjects(kind: str, polygon_spec: str, theme: Theme, box: Box) -> list[Mobject]:
    """The mobjects of the figure ``kind`` (one of :data:`KINDS`), back to front."""
    if kind == "measured":
        return _measured(theme, box)
    polygon = read_polygon(polygon_spec)
    drawn = {"monotone-pieces": _pieces, "delaunay-circle": _circle,
             "three-triangulations": _three}[kind]
    return drawn(polygon, theme, box)


def _names(labels: Sequence[str]) -> str:
    """``D``, ``D and K``, ``D, K and M``."""
    return labels[0] if len(labels) == 1 else ", ".join(labels[:-1]) + " and " + labels[-1]


# --- monotone pieces -----------------------------------------------------------------------------


@dataclass(frozen=True)
class Partition:
    """P cut by the monotone sweep: its diagonals, its pieces (vertex indices, counter-
    clockwise) and the split and merge vertices the diagonals remove."""

    diagonals: tuple[tuple[int, int], ...]
    pieces: tuple[tuple[int, ...], ...]
    split: tuple[int, ...]
    merge: tuple[int, ...]


def monotone_partition(polygon: Polygon) -> Partition:
    """The partition the monotone run makes (:func:`geometry.monotone.make_monotone`)."""
    diagonals = make_monotone(polygon)
    sweep = Sweep(polygon)
    kinds = {i: classify_vertex(sweep, polygon.vertex(i)) for i in sweep.order}
    return Partition(tuple(diagonals), tuple(p.ids for p in monotone_pieces(polygon, diagonals)),
                     tuple(i for i in sweep.order if kinds[i] == "split"),
                     tuple(i for i in sweep.order if kinds[i] == "merge"))


#: the least angle (degrees) at which the y-monotone card's line crosses an edge of P
LEVEL_STEEPEST = 20.0


def level_line(polygon: Polygon) -> tuple[float, list[tuple[float, float]]] | None:
    """A height at which a horizontal line meets P in two segments or more, and the
    segments (their x), in P's units: of the heights halfway between two vertices' heights,
    the one whose shortest segment, and whose room between the vertices above and below,
    are longest (halfway between K and M, the line seemed to run through both), crossing no
    edge at less than :data:`LEVEL_STEEPEST` (under D, it ran along D–E and seemed to meet
    it). None if P is y-monotone or no height will do.

    >>> y, segments = level_line(read_polygon("lecture"))
    >>> y, [(round(a, 2), round(b, 2)) for a, b in segments]
    (13.0, [(4.81, 5.9), (7.57, 9.25)])
    """
    region = shapely.Polygon(polygon.points)
    (left, _, right, _), heights = region.bounds, sorted({p[1] for p in polygon.points})
    best: tuple[float, float, list[tuple[float, float]]] | None = None
    edges = list(zip(polygon.points, [*polygon.points[1:], polygon.points[0]], strict=True))
    for low, high in pairwise(heights):
        y = (low + high) / 2
        met = shapely.LineString([(left - 1, y), (right + 1, y)]).intersection(region)
        parts = sorted((min(c[0] for c in g.coords), max(c[0] for c in g.coords))
                       for g in getattr(met, "geoms", [met]) if not g.is_empty)
        crossed = [math.degrees(math.atan2(abs(q[1] - p[1]), abs(q[0] - p[0])))
                   for p, q in edges if min(p[1], q[1]) < y < max(p[1], q[1])]
        if len(parts) >= 2 and min(crossed) >= LEVEL_STEEPEST:
            shortest = min(min(b - a for a, b in parts), high - low)
            if best is None or shortest > best[0]:
                best = (shortest, y, parts)
    return None if best is None else (best[1], best[2])


def _pieces(polygon: Polygon, theme: Theme, box: Box) -> list[Mobject]:
    frame = Frame(polygon.points, *box)
    cut = monotone_partition(polygon)
    level = level_line(polygon)
    corners = [[polygon.points[k] for k in piece] for piece in cut.pieces]
    # the run's tints, neighbours unlike (a blue piece read as what a call runs on)
    tints = [tag(MPolygon(*frame.many(points), color=tint, stroke_width=0, fill_color=tint,
                          fill_opacity=theme.done_opacity), None, "figure:piece")
             for points, tint in zip(corners, piece_tints(corners, theme.part_tints),
                                     strict=True)]
    # amber, as the run draws them (its diagonals stay amber): one colour, one meaning
    lines = [tag(Line(frame.to_scene(polygon.points[u]), frame.to_scene(polygon.points[w]),
                      color=theme.argument, stroke_width=theme.stroke * 1.5), "argument",
                 "figure:diagonal") for u, w in cut.diagonals]
    if level is None:
        return [tag(polygon_mobject(polygon, frame, theme), "idle", "figure:polygon"), *tints,
                *lines, tag(placed_vertex_markers(polygon, frame, theme), "idle",
                            "figure:vertices"),
                figure_caption(box, theme, ("P is y-monotone already: one piece", theme.ink))]
    y, segments = level
    xs = [p[0] for p in polygon.points]
    reach = (max(xs) - min(xs)) * 0.06  # the line runs on a little beyond P, dashed
    # dashed where it runs outside P, its segments in P solid and in ink: the sweep's lilac
    # did not read on the pieces' purple tint
    whole = tag(DashedLine(frame.to_scene((min(xs) - reach, y)), frame.to_scene((max(xs) + reach, y)),
                           color=theme.idle, stroke_width=theme.thin_stroke,
                           dash_length=theme.dash_length), None, "figure:level-line")
    met = [tag(Line(frame.to_scene((a, y)), frame.to_scene((b, y)), color=theme.ink,
                    stroke_width=theme.stroke * 1.6), None, "figure:level-segment")
           for a, b in segments]
    # the pieces, each met once, are the tints: the card's words say what they are
    words = [(f"This line meets P in {len(segments)} segments: P is not y-monotone", theme.ink)]
    # the labels clear of the line as of the diagonals (a label on it reads as struck through)
    markers = placed_vertex_markers(polygon, frame, theme, lines=[
        [(min(xs) - reach, y), (max(xs) + reach, y)]])
    return [tag(polygon_mobject(polygon, frame, theme), "idle", "figure:polygon"), *tints,
            *lines, whole, *met, tag(markers, "idle", "figure:vertices"),
            figure_caption(box, theme, *words)]


# --- measured work -------------------------------------------------------------------------------


def measured_series(theme: Theme) -> list[Series]:
    """The plot's lines: each algorithm's counts at :data:`MEASURED_SIZES` on the dented half
    discs (:data:`MEASURED_SHAPE`), in the ink with its own mark (:data:`MEASURED_MARKS`)."""
    return [Series(f"figure:measured:{name}",
                   tuple(measured(name, n, MEASURED_SHAPE) for n in MEASURED_SIZES),
                   theme.ink, mark=MEASURED_MARKS[name], filled=True)
            for name in MEASURED_RUNS]


#: what the plot's y axis counts, in plain words, and what one of them is (its caption)
STEPS = "steps (geometric tests)"
STEP = "a test: which side of a line a point is on, or which of two points is nearer"
#: what the lines were counted on, said under the x axis's name beside the drawn half disc
COUNTED_ON = "counted on dented half discs"
#: where each line's name stands: by its mark at a size, above the steeper line (up and to
#: the left of its mark at 80, where the line is lower; at 40 it ran into the "1 000" tick)
#: and below the other (down and to the right of its mark at 40, where it is higher): beside
#: its own line, clear of both, in the room the rising lines leave; and its gap from the
#: mark (scene units)
NAME_AT, NAME_GAP = {True: 80, False: 40}, 0.14


def _measured(theme: Theme, box: Box) -> list[Mobject]:
    """The plot with its axes named and ticked in the ink, each line's name beside it (no
    legend to look up), what the lines were counted on (the half disc drawn) and what a
    step is."""
    (x, y), width, height = box
    # under the x axis: its ticks, its name, then what was counted on
    bottom = y - height / 2 + 1.45
    area = Area(x - width / 2 + 1.0, bottom, width - 1.15, y + height / 2 - 0.45 - bottom)
    series = measured_series(theme)
    drawn, at = line_plot(MEASURED_SIZES, series, area, theme, log=True, ticks=theme.ink)
    drawn += axis_names(area, "vertices n", STEPS, theme)
    steepest = max(series, key=lambda s: s.counts[-1] / s.counts[0])
    for name, line in zip(MEASURED_RUNS, series, strict=True):
        said = typeset.text(spoken(name), font=theme.font, size=theme.label_size,
                            colour=theme.ink)
        n = NAME_AT[line is steepest]
        mark = np.array(at(n, line.counts[MEASURED_SIZES.index(n)]))
        if line is steepest:
            said.move_to(mark + np.array((-NAME_GAP, NAME_GAP, 0.0)), aligned_edge=DR)
        else:
            said.move_to(mark + np.array((NAME_GAP, -NAME_GAP, 0.0)), aligned_edge=UL)
        drawn.append(tag(said, None, "figure:series-name"))
    icon = _icon(theme)
    said = typeset.text(COUNTED_ON, font=theme.font, size=theme.label_size, colour=theme.ink)
    left = area.left + area.width / 2 - (icon.width + 0.15 + said.width) / 2  # the two centred
    icon.move_to((left + icon.width / 2, area.bottom - 1.05, 0))
    said.next_to(icon, RIGHT, buff=0.15)
    drawn += [icon, tag(said, None, "figure:counted-on")]
    return [*drawn, figure_caption(box, theme, (STEP, theme.ink))]


def _icon(theme: Theme) -> Mobject:
    """A small half disc with its dented side (``half-disc`` of :data:`ICON_N` vertices),
    :data:`ICON_HEIGHT` high, outlined in ink."""
    polygon = read_polygon(f"half-disc:{ICON_N}")
    shape = MPolygon(*[(x, y, 0.0) for x, y in polygon.points], color=theme.ink,
                     stroke_width=theme.thin_stroke)
    return tag(shape.scale_to_fit_height(ICON_HEIGHT), None, "figure:icon")


# --- the constrained Delaunay circle -------------------------------------------------------------


@dataclass(frozen=True)
class Circumcircle:
    """A triangle's circumcircle: its centre and squared radius, exactly, and the polygon's
    vertices strictly inside it."""

    triangle: TriangleIndices
    centre: tuple[Fraction, Fraction]
    radius2: Fraction
    inside: tuple[int, ...]

    @property
    def radius(self) -> float:
        return math.sqrt(self.radius2)


def circumcircle(polygon: Polygon, triangle: TriangleIndices) -> Circumcircle:
    """The circle through the triangle's corners, and the vertices strictly inside it
    (exact: rationals)."""
    (ax, ay), (bx, by), (cx, cy) = ([Fraction(c) for c in polygon.points[k]] for k in triangle)
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    a2, b2, c2 = ax * ax + ay * ay, bx * bx + by * by, cx * cx + cy * cy
    centre = ((a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / d,
              (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / d)
    r2 = (ax - centre[0]) ** 2 + (ay - centre[1]) ** 2
    inside = tuple(k for k, (px, py) in enumerate(polygon.points) if k not in triangle
                   and (Fraction(px) - centre[0]) ** 2 + (Fraction(py) - centre[1]) ** 2 < r2)
    return Circumcircle(triangle, centre, r2, inside)


#: the share of its radius by which every vertex of P stands clear of the circle drawn,
#: inside it or outside: M stood 5 % inside the circle of DFG, its dot on the line, read as
#: neither in nor out (review s567, s35)
CLEAR_OF_RIM = 0.15


def _off_rim(polygon: Polygon, circle: Circumcircle) -> list[float]:
    """How far each vertex not on the circle stands from its rim, a share of its radius
    (negative inside)."""
    (x, y), r = (float(v) for v in circle.centre), circle.radius
    return [math.dist((x, y), p) / r - 1 for k, p in enumerate(polygon.points)
            if k not in circle.triangle]


def clearly_inside(polygon: Polygon, circle: Circumcircle) -> tuple[int, ...]:
    """The vertices inside ``circle`` by at least :data:`CLEAR_OF_RIM` of its radius."""
    (x, y), r = (float(v) for v in circle.centre), circle.radius
    return tuple(k for k in circle.inside
                 if math.dist((x, y), polygon.points[k]) <= r * (1 - CLEAR_OF_RIM))


def clear_of_rim(polygon: Polygon, circle: Circumcircle) -> bool:
    """Whether every vertex stands :data:`CLEAR_OF_RIM` inside or outside ``circle``."""
    return all(abs(d) >= CLEAR_OF_RIM - 1e-9 for d in _off_rim(polygon, circle))


def ranked_circles(polygon: Polygon) -> list[Circumcircle]:
    """The circles the figure may draw, the best first: of the triangles whose circle stays
    near P (within a quarter of P's size of its box), those with every vertex clearly inside
    or outside (:func:`clear_of_rim`; if none is, all of them), the one with the most
    vertices inside it — the constrained triangulation's point: they are hidden from the
    triangle — then the one lying most over P (an empty circle in the midst of P's vertices
    shows what it keeps out; one mostly off P, as BCG's, shows little); if no circle stays
    near P, the smallest first."""
    circles = [circumcircle(polygon, t) for t in constrained_delaunay(polygon)]
    xs, ys = [p[0] for p in polygon.points], [p[1] for p in polygon.points]
    room = max(max(xs) - min(xs), max(ys) - min(ys)) / 4

    def near(c: Circumcircle) -> bool:
        (x, y), r = (float(v) for v in c.centre), c.radius
        return (x - r >= min(xs) - room and x + r <= max(xs) + room
                and y - r >= min(ys) - room and y + r <= max(ys) + room)

    fitting = [c for c in circles if near(c)]
    if not fitting:
        return sorted(circles, key=lambda c: c.radius2)
    clear = [c for c in fitting if clear_of_rim(polygon, c)] or fitting
    region = shapely.Polygon(polygon.points)

    def over_p(c: Circumcircle) -> float:
        disk = shapely.Point(*(float(v) for v in c.centre)).buffer(c.radius, 64)
        return float(disk.intersection(region).area / disk.area)

    return sorted(clear, key=lambda c: (len(clearly_inside(polygon, c)), len(c.inside),
                                        over_p(c)), reverse=True)


#: the points of the circle given to the labels' placement as a line to keep clear of
CIRCLE_CORNERS = 96


@dataclass(frozen=True)
class CircleFigure:
    """A circle drawn in the figure's box: its frame, the triangulation's sides (vertex
    indices), its rim (P's units) and the vertex markers placed clear of both."""

    circle: Circumcircle
    frame: Frame
    sides: tuple[tuple[int, int], ...]
    markers: VGroup


def circle_figure(polygon: Polygon, circle: Circumcircle, theme: Theme, box: Box) -> CircleFigure:
    """The frame and the labels of ``circle``'s figure: the labels clear of the triangles'
    sides and of the circle too (review s567: "K" stood on the circle, "G" on edge G–C)."""
    (cx, cy), r = (float(v) for v in circle.centre), circle.radius
    frame = Frame([*polygon.points, (cx - r, cy - r), (cx + r, cy + r)], *box)
    sides = tuple((t[k], t[(k + 1) % 3]) for t in constrained_delaunay(polygon) for k in range(3))
    rim = [(cx + r * math.cos(a), cy + r * math.sin(a))
           for a in (2 * math.pi * k / CIRCLE_CORNERS for k in range(CIRCLE_CORNERS + 1))]
    markers = placed_vertex_markers(polygon, frame, theme, sides, [rim])
    return CircleFigure(circle, frame, sides, markers)


def _labels_clear(polygon: Polygon, figure: CircleFigure) -> bool:
    """Whether every label of ``figure`` found a place :data:`metaphors.labels.EDGE_MARGIN`
    clear of its circle and of every side (HKM's circle ran along M's label), nearer its
    own dot than any other (:func:`_labels_own`)."""
    (cx, cy), r = (float(v) for v in figure.circle.centre), figure.circle.radius
    scene = figure.frame
    rim = shapely.Point(*scene.to_scene((cx, cy))[:2]).buffer(r * scene.scale, 256).exterior
    lines = shapely.union_all([rim, *(shapely.LineString([scene.to_scene(polygon.points[u])[:2],
                                                          scene.to_scene(polygon.points[w])[:2]])
                                      for u, w in figure.sides)])
    return all(shapely.box(*area_of(marker[1])).distance(lines) >= EDGE_MARGIN - 1e-6
               for marker in figure.markers) and _labels_own(figure.markers)


def _labels_own(markers: VGroup) -> bool:
    """Whether each label without a leader stands nearer its own dot than any other dot
    (CDG's circle: G's label, with no room by G on the circle, stood above H's dot, and H's,
    led off to the right, left G's the nearest label to H: "the circle of CDG" named a G
    the viewer found at H)."""
    dots = [shapely.Point(*marker[0].get_center()[:2]) for marker in markers]
    for k, marker in enumerate(markers):
        if len(marker) > 2:  # its leader points at its dot
            continue
        box = shapely.box(*area_of(marker[1]))
        own = box.distance(dots[k])
        if any(box.distance(dot) < own for j, dot in enumerate(dots) if j != k):
            return False
    return True


def shown_circle(polygon: Polygon, theme: Theme, box: Box) -> CircleFigure:
    """The figure's circle: the best of :func:`ranked_circles` whose labels all stand clear of
    its lines (:func:`_labels_clear`), else the best."""
    figures = (circle_figure(polygon, c, theme, box) for c in ranked_circles(polygon))
    first = next(figures)
    if _labels_clear(polygon, first):
        return first
    return next((f for f in figures if _labels_clear(polygon, f)), first)


def _circle(polygon: Polygon, theme: Theme, box: Box) -> list[Mobject]:
    """P's constrained Delaunay triangles, the shown triangle (:func:`shown_circle`) green
    with its circle, and the vertices inside the circle marked amber, the labels clear of
    the lines (:func:`circle_figure`); a vertex only just inside the circle, its mark on the
    line, is said to be so (where no circle keeps every vertex clear of it)."""
    shown = shown_circle(polygon, theme, box)
    circle, frame = shown.circle, shown.frame
    (cx, cy), r = (float(v) for v in circle.centre), circle.radius
    triangles = constrained_delaunay(polygon)
    edges = [tag(triangle_mobject(polygon, t, frame, theme.idle, theme).set_fill(opacity=0),
                 None, "figure:triangle") for t in triangles]
    chosen = tag(triangle_mobject(polygon, circle.triangle, frame, theme.result, theme),
                 "result", "figure:delaunay")
    ring = tag(Circle(radius=r * frame.scale, color=theme.result, stroke_width=theme.stroke)
               .move_to(frame.to_scene((cx, cy))), "result", "figure:circumcircle")
    marks = [tag(Dot(frame.to_scene(polygon.points[k]), radius=0.11, color=theme.argument),
                 "argument", "figure:hidden") for k in circle.inside]
    vertices = tag(shown.markers, "idle", "figure:vertices")
    return [tag(polygon_mobject(polygon, frame, theme), "idle", "figure:polygon"), *edges,
            chosen, ring, vertices, *marks,
            figure_caption(box, theme, *_circle_words(polygon, circle, theme))]


def _circle_words(polygon: Polygon, circle: Circumcircle,
                  theme: Theme) -> list[tuple[str, str]]:
    """What the Delaunay figure says: the vertices in the circle (those only just inside it
    said so), and that P's edges hide them from the triangle."""
    name = "".join(polygon.labels[k] for k in circle.triangle)
    if not circle.inside:
        return [(f"the circle of {name} holds no other vertex", theme.ink)]
    clear = clearly_inside(polygon, circle)
    # a vertex only just inside said so where it is named: two rows, as the caption has room
    inside = _names([polygon.labels[k] + ("" if k in clear else " (just)")
                     for k in circle.inside])
    one = len(circle.inside) == 1
    return [(f"{inside} {'lies' if one else 'lie'} in {name}'s circle,", theme.argument),
            (f"but P's edges hide {'it' if one else 'them'} from {name}", theme.ink)]


# --- the recap: three triangulations -------------------------------------------------------------


def recap_triangulations(polygon: Polygon) -> list[tuple[str, str, tuple[TriangleIndices, ...]]]:
    """(algorithm, bound, triangles) for each of :data:`RECAPPED` (divide and conquer with
    Gravity, as the lecture ran it)."""
    return [(name, bound, triangulate(polygon, name).triangles) for name, bound in RECAPPED]


#: over each of the recap's pictures, the room for its heading (its name and bound, then its
#: count); round P, for its labels' room
COUNT_ROOM, PICTURE_MARGIN = 0.8, 0.25
#: the headings' rows: the name's centre above the count's (scene units)
HEADING_ROW = 0.36


def panels(count: int, box: Box) -> list[tuple[tuple[float, float], Box]]:
    """``count`` pictures side by side across ``box``: per picture, where its heading goes
    (centred over it) and the box P is fitted into."""
    (x, y), width, height = box
    each, top = width / count, y + height / 2
    fitted = height - COUNT_ROOM - 2 * PICTURE_MARGIN
    return [((x - width / 2 + each * (k + 0.5), top - COUNT_ROOM / 2),
             ((x - width / 2 + each * (k + 0.5), top - COUNT_ROOM - PICTURE_MARGIN - fitted / 2),
              each - 2 * PICTURE_MARGIN, fitted))
            for k in range(count)]


def _diagonals(polygon: Polygon, triangles: Sequence[TriangleIndices]) -> list[tuple[int, int]]:
    """The diagonals of a triangulation: the triangles' sides that are not P's edges."""
    n = polygon.n
    sides = {tuple(sorted((t[a], t[b]))) for t in triangles for a, b in ((0, 1), (1, 2), (0, 2))}
    return sorted((i, j) for i, j in sides if (j - i) % n not in (1, n - 1))


def _three(polygon: Polygon, theme: Theme, box: Box) -> list[Mobject]:
    """Side by side across ``box`` (a wide card's: its words, one per algorithm, go under
    the pictures): each algorithm's triangulation of P, big enough to count its triangles,
    its diagonals drawn in the ink so that the three read as three (in green shades alone
    they looked alike, review of the recap at 42 s), and over it its name and bound, as its
    line says them, and its count (the three stood unnamed until their lines came, one by
    one)."""
    drawn: list[Mobject] = []
    for (name, bound, triangles), (heading, fitted) in zip(recap_triangulations(polygon),
                                                           panels(len(RECAPPED), box),
                                                           strict=True):
        frame = Frame(polygon.points, *fitted)
        drawn.append(tag(polygon_mobject(polygon, frame, theme), "idle", "figure:polygon"))
        drawn += triangulation_figure(polygon, triangles, frame, f"figure:triangle:{name}",
                                      theme)
        drawn += [tag(Line(frame.to_scene(polygon.points[i]), frame.to_scene(polygon.points[j]),
                           color=theme.ink, stroke_width=theme.stroke * 0.8),
                      None, f"figure:diagonal:{name}") for i, j in _diagonals(polygon, triangles)]
        (x, y), room = heading, fitted[1] + 2 * PICTURE_MARGIN
        title = typeset.text(f"{spoken(name, start=True)}, {bound}", font=theme.font,
                             size=theme.label_size + 2, colour=theme.ink, width=room)
        drawn.append(tag(title.move_to((x, y + HEADING_ROW / 2, 0)), None, "figure:name"))
        count = f"{len(triangles)} triangle{'s' * (len(triangles) > 1)}"
        text = typeset.text(count, font=theme.font, size=theme.label_size + 2,
                            colour=theme.result)
        drawn.append(tag(text.move_to((x, y - HEADING_ROW / 2, 0)), "result", "figure:count"))
    return drawn


__all__ = ["KINDS", "MEASURED_MARKS", "MEASURED_RUNS", "MEASURED_SHAPE", "MEASURED_SIZES",
           "RECAPPED", "CircleFigure", "Circumcircle", "Partition", "circle_figure",
           "circumcircle", "clear_of_rim", "clearly_inside", "figure_mobjects", "level_line",
           "measured_series", "monotone_partition", "panels",
           "ranked_circles", "recap_triangulations", "shown_circle"]
