"""Exercises on the frame of the inner-diagonal heuristics, with answers the geometry checks.

Three kinds, mixed in turn:

``pick``
    "Which vertex does Rotation pick?" — the answer is the label of D from
    :func:`geometry.diagonals.find_diagonal`; the reason tells the order in which the
    metaphor reaches the candidates, computed from the run's log (:mod:`story.reach`), with
    the clock hand's angles (a length, in the polygon's units, would mean nothing on screen);
    the answer draws the metaphor's front as it reaches the pick (:func:`front`).
``claim``
    "Is the claim of Scaling an inner diagonal?" (a wrong heuristic) — yes or no from
    :func:`geometry.check.is_inner_diagonal`, with its reason. Yes and no alternate in a
    seeded order, so a set of two or more holds both.
``inner``
    "Which of these diagonals are inner: AC, BD, BE?" — AC and B to every candidate; each
    checked exactly. Always a mix: AC is not inner when T holds a candidate, the farthest
    candidate from AC is (thesis, lemma 2). (A B-diagonal that is not inner is rare on a
    polygon with room, no needle and no notch: asking for one made the search tens of times
    longer.)

Every polygon is a seeded sample spec (``random-2opt:11:48213``) that any ``trex`` command
reads again; its triangle T = ABC holds 2–4 candidates, and it has room (no angle under 15°,
inside or out, no vertex near an edge it is not on: :func:`_roomy`). The search is a deterministic
function of the seed, so the same seed gives the same exercises. No manim here.

>>> exercises = make_exercises(3, seed=1)
>>> [e.kind for e in exercises]
['pick', 'claim', 'inner']
>>> exercises == make_exercises(3, seed=1)
True
"""

from __future__ import annotations

import itertools
import math
import random
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, field, replace

from shapely.geometry import LineString
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry import Polygon as Region
from shapely.geometry.base import BaseGeometry

import tracing
from geometry.check import CheckResult, is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.errors import GeometryError
from geometry.frame import candidates_in_triangle, leftmost_vertex, triangle_at
from geometry.polygon import Polygon
from geometry.predicates import (
    Contact,
    Point,
    intersection_point,
    segment_contact,
    squared_distance,
)
from geometry.samples import sample_from_spec
from story.hunt import in_general_position
from story.reach import reach_of
from story.reading import reading_time
from story.refs import call_of, state_of, target_of
from story.registry import entry, heuristics, spoken, wrong
from story.words import why_not_inner

__all__ = [
    "KINDS",
    "PICKABLE",
    "Exercise",
    "answers_markdown",
    "checking_time",
    "confusions",
    "crossed_edges",
    "front",
    "front_gap",
    "hunted_exercise",
    "make_exercises",
    "measured_pairs",
]

KINDS = ("pick", "claim", "inner")
#: (generator, smallest n, largest n): shapes whose T often holds several candidates.
#: Only 2-opt polygons: combs stand their teeth on one line, and an exercise is in general
#: position (issue 22 item 6); stars and spirals rarely hold two candidates in T.
GENERATORS = (("random-2opt", 8, 13), ("random-2opt", 10, 16))
#: the claims' shapes: a wrong claim the class sees fail, on a polygon whose AC keeps clear of
#: every vertex, comes about once in 1,500 drawn polygons of 5–9 vertices and once in 5,000
#: of 8–16 (a wrong rule's pick lies near AC, where the rule's motion meets it first)
CLAIM_GENERATOR = ("random-2opt", 5, 9)
MIN_CANDIDATES, MAX_CANDIDATES = 2, 4
MIN_GAP = 0.04  # closest two vertices, as a fraction of the bounding box's diagonal (legibility)
MAX_TRIES = 20_000
#: a rejected diagonal's part outside P, as a fraction of P's height (its width over
#: :data:`PICTURE_ASPECT`): 0.06 of the 5.6-unit picture is 4 % of the 8-unit frame, so the
#: class sees the failure (issue 22 items 3 and 6)
MIN_OUTSIDE, PICTURE_ASPECT = 0.06, 7.4 / 5.6
#: the least gap, on the same scale, between a diagonal shown and a vertex not its own: a
#: crossing near a vertex looks like passing through it (3 % of the frame); also the least
#: gap between a vertex and an edge it is not on (a notch or a spike the class cannot read)
MIN_CLEARANCE = 0.045
#: the least angle at a vertex, inside or out (degrees): a needle under it is a sliver on
#: screen, its labels crowded (the lecture polygon's rule, issue 22 item 5)
MIN_ANGLE = 15.0
#: how long an answer stays up (seconds): at least :data:`LEAST_CHECKING`, and its reading
#: time with :data:`CHECK_EACH` for each thing on the picture it asks the class to check (an
#: answer naming three diagonals was up 4.5 s, too short to check them against the picture)
LEAST_CHECKING, CHECK_EACH = 8.0, 2.0

#: each rule's story as a reason tells it: its lead, and what its number means at the pick
#: (the ``{v}`` in it, an angle) or None: a length is left unsaid (the class cannot measure it
#: on screen, and "15.1 from B" in the polygon's units meant nothing to it); the other
#: candidates come after the pick as "E at 36.0°", or by name alone
_STORY: dict[str, tuple[str, str | None]] = {
    "scaling": ("the water spilled at B reaches", None),
    "rotation": ("the clock hand at B, set to A, passes", "after turning {v}"),
    "rotation-ccw": ("the clock hand at B, set to C, turning back, passes", "after turning {v}"),
    "rotation-correct": ("the clock hand at C, set to B, passes", "after turning {v}"),
    "translation": ("the vertical line swept rightwards from B reaches", None),
    "translation-correct": ("the line parallel to AC, swept from B, reaches", None),
    "scaling-correct": ("the water rising from the shore AC wets", None),
}
#: how a value prints: an angle in degrees to a tenth; two values printed alike are a tie
_PRINTED = "{:.1f}"
#: Heuristics that pick a candidate of T by a rule a student can apply by hand: those whose
#: metaphor's story is told above, in the registry's order.
PICKABLE = tuple(name for name in heuristics() if name in _STORY)


@dataclass(frozen=True)
class Exercise:
    """One exercise: the question, its checked answer and reason, and what its still shows."""

    number: int
    kind: str
    spec: str
    heuristic: str | None
    question: str
    answer: str
    reason: str
    triangle: tuple[int, int, int]  # indices of A, B, C
    candidates: tuple[int, ...]  # indices of the candidates in T
    options: tuple[tuple[int, int], ...] = ()  # the diagonals a question names (inner)
    polygon: Polygon = field(compare=False, repr=False, default=None)  # type: ignore[assignment]  # always given (by _exercise); the default only lets it follow the fields that have one
    #: the claim asked about, for a rule the registry does not run (a heuristic of one's own:
    #: :func:`hunted_exercise`); None: the registry's heuristic claims it
    claim: tuple[int, int] | None = None
    #: the vertex pairs whose distance the rule compared: the answer draws them, so that
    #: the class sees what "nearer" means ("Distance to C for D: 2.2" was a bare number)
    measured: tuple[tuple[int, int], ...] = ()

    @property
    def title(self) -> str:
        return f"{self.number}. {self.question}"

    @property
    def checks(self) -> int:
        """How many things the answer asks the class to check against the picture: each
        diagonal a question names, else its one pick or claim (the answer stays up the
        longer: :data:`CHECK_EACH`)."""
        return max(1, len(self.options))

    @property
    def still(self) -> str:
        """File name of the exercise's picture."""
        return f"exercise-{self.number:02d}.png"


# --- the search -----------------------------------------------------------------------------------


def _specs(rng: random.Random, used: set[str], generator: tuple[str, int, int]) -> Iterator[str]:
    """An endless, seeded stream of fresh sample specs of one generator."""
    name, lo, hi = generator
    while True:
        spec = f"{name}:{rng.randint(lo, hi)}:{rng.randrange(100_000)}"
        if spec not in used:
            yield spec


def _legible(polygon: Polygon) -> bool:
    """No two vertices too close to tell apart, and no three on one line (general position:
    a claim then fails by crossing an edge, not by passing through a vertex)."""
    pts = polygon.points
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    size = math.hypot(max(xs) - min(xs), max(ys) - min(ys))
    closest = min(math.dist(p, q) for p, q in itertools.combinations(pts, 2))
    return closest >= MIN_GAP * size and in_general_position(pts)


def _angle(p: Point, q: Point, r: Point) -> float:
    """The inner angle at ``q`` of a counter-clockwise polygon, ``p`` before it and ``r``
    after it, in degrees (0 to 360)."""
    u, v = (p[0] - q[0], p[1] - q[1]), (r[0] - q[0], r[1] - q[1])
    return math.degrees(math.atan2(v[0] * u[1] - v[1] * u[0], v[0] * u[0] + v[1] * u[1])) % 360


def _roomy(polygon: Polygon) -> bool:
    """No needle and no notch (every angle, inside and out, at least :data:`MIN_ANGLE`), and
    no vertex nearer than :data:`MIN_CLEARANCE` to an edge it is not on: checked once per
    finished polygon, so that the search pays for it only on polygons that fit otherwise."""
    pts, n = polygon.points, polygon.n
    if not all(MIN_ANGLE <= _angle(pts[v - 1], pts[v], pts[(v + 1) % n]) <= 360 - MIN_ANGLE
               for v in range(n)):
        return False
    least = MIN_CLEARANCE * _scale(polygon)
    edges = [LineString([pts[e], pts[(e + 1) % n]]) for e in range(n)]
    return all(edges[e].distance(ShapelyPoint(pts[v])) >= least
               for v in range(n) for e in range(n) if v not in (e, (e + 1) % n))


def _scale(polygon: Polygon) -> float:
    """P's size as the picture fits it: its height, or its width over the picture's aspect."""
    xs, ys = [p[0] for p in polygon.points], [p[1] for p in polygon.points]
    return max((max(xs) - min(xs)) / PICTURE_ASPECT, max(ys) - min(ys))


def _clear(polygon: Polygon, i: int, j: int) -> bool:
    """Whether the segment from vertex ``i`` to ``j`` keeps clear of every other vertex."""
    segment = LineString([polygon.points[i], polygon.points[j]])
    least = MIN_CLEARANCE * _scale(polygon)
    return all(segment.distance(ShapelyPoint(q)) >= least
               for k, q in enumerate(polygon.points) if k not in (i, j))


def _visibly_outside(polygon: Polygon, i: int, j: int) -> bool:
    """Whether the segment from vertex ``i`` to ``j`` leaves P by enough to be seen, clear of
    the vertices (so that it is seen to cross an edge)."""
    pts = polygon.points
    outside = LineString([pts[i], pts[j]]).difference(Region(pts)).length
    return outside >= MIN_OUTSIDE * _scale(polygon) and _clear(polygon, i, j)


@dataclass(frozen=True)
class _Frame:
    spec: str
    polygon: Polygon
    triangle: tuple[int, int, int]
    candidates: tuple[int, ...]


def _may_hold_candidates(points: list[Point]) -> bool:
    """Whether T's bounding box holds :data:`MIN_CANDIDATES` other vertices: a candidate
    lies in T, so in its box (exact: comparisons of the same floats). Most drawn polygons
    fail here, before they are validated a second time as a :class:`Polygon`."""
    n = len(points)
    b = min(range(n), key=lambda k: (points[k][0], points[k][1]))  # left-most, lowest on ties
    corners = [points[b - 1], points[b], points[(b + 1) % n]]
    x0, x1 = min(p[0] for p in corners), max(p[0] for p in corners)
    y0, y1 = min(p[1] for p in corners), max(p[1] for p in corners)
    inside = sum(1 for p in points if x0 <= p[0] <= x1 and y0 <= p[1] <= y1)
    return inside - 3 >= MIN_CANDIDATES


def _frame(spec: str) -> _Frame | None:
    """The polygon of ``spec`` with its T and candidates, if it makes a fair exercise."""
    try:
        points = sample_from_spec(spec)
        if not _may_hold_candidates(points):
            return None
        polygon = Polygon.from_points(points)
    except GeometryError:
        return None
    t = triangle_at(polygon, leftmost_vertex(polygon))
    candidates = tuple(v.index for v in candidates_in_triangle(polygon, t))
    # AC clear of every vertex: whether a vertex is a candidate is read off the picture
    if not MIN_CANDIDATES <= len(candidates) <= MAX_CANDIDATES or not _roomy(polygon) \
            or not _clear(polygon, t.a.index, t.c.index) or not _legible(polygon):
        return None
    return _Frame(spec, polygon, (t.a.index, t.b.index, t.c.index), candidates)


class _Pool:
    """The polygons drawn so far, per generator, in the order drawn: a polygon one exercise
    turns down (a kind it does not fit) is offered to the later ones before a new one is
    drawn, so the search pays for each polygon's 2-opt once (deterministic: the order is the
    seeded stream's)."""

    def __init__(self, rng: random.Random) -> None:
        self.rng = rng
        self.used: set[str] = set()
        self.kept: dict[tuple[str, int, int], list[_Frame]] = {}

    def frames(self, generator: tuple[str, int, int]) -> Iterator[_Frame]:
        """The unused fitting polygons of ``generator``: the kept ones, then new ones."""
        kept = self.kept.setdefault(generator, [])
        yield from [f for f in kept if f.spec not in self.used]
        for spec in itertools.islice(_specs(self.rng, self.used, generator), MAX_TRIES):
            frame = _frame(spec)
            if frame is not None:
                kept.append(frame)
                yield frame


def _search(pool: _Pool, generator: tuple[str, int, int],
            build: Callable[[_Frame], Exercise | None]) -> Exercise:
    """The first exercise ``build(frame)`` accepts, over the pool's polygons."""
    for frame in pool.frames(generator):
        made = build(frame)
        if made is not None:
            pool.used.add(frame.spec)
            return made
    raise RuntimeError(f"no fitting polygon in {MAX_TRIES} tries")  # never seen in practice


# --- the three kinds ------------------------------------------------------------------------------


def _and(items: list[str]) -> str:
    """``D``, ``D and E``, ``D, E and F``."""
    return items[0] if len(items) == 1 else f"{', '.join(items[:-1])} and {items[-1]}"


def _label(polygon: Polygon, *indices: int) -> str:
    return "".join(polygon.labels[i] for i in indices)


def _reached(polygon: Polygon, heuristic: str) -> tuple[int, list[tuple[str, float]]]:
    """The heuristic's D and each candidate its metaphor reaches, in order (from its log's
    step, as the storyboard computes it: :mod:`story.reach`)."""
    with tracing.record(heuristic=heuristic) as log:
        claim = find_diagonal(polygon, heuristic)
    where = dict(zip(polygon.labels, polygon.points, strict=True))
    entered = {target_of(e): state_of(e) for e in log.events if e.kind == "enter"}
    for e in log.events:
        if e.kind == "return":
            steps = reach_of(log.events[call_of(e)], e, where, polygon.labels, entered.__getitem__)
            if steps is not None:
                return claim.v.index, steps
    return claim.v.index, []


def _pick_reason(heuristic: str, steps: list[tuple[str, float]]) -> str | None:
    """"the clock hand at B, set to A, passes D first: after turning 15.1°, before E at
    25.5°" (an angle said with what it measures), "the water spilled at B reaches D first,
    before E" (a length left unsaid); None when the deciding two values would print alike
    (the tie rule would be the real reason)."""
    lead, measure = _STORY[heuristic]
    printed = [_PRINTED.format(value) for _, value in steps]
    labels = [label for label, _ in steps]
    if heuristic == "scaling-correct":  # the last candidate reached is the pick
        if printed[-1] == printed[-2]:
            return None
        return f"{lead} {_and(labels[:-1])} before {labels[-1]}, so {labels[-1]} stays dry longest"
    if printed[0] == printed[1]:
        return None
    if measure is None:
        return f"{lead} {labels[0]} first, before {_and(labels[1:])}"
    others = _and([f"{label} at {value}°" for label, value in zip(labels[1:], printed[1:],
                                                                   strict=True)])
    return f"{lead} {labels[0]} first: {measure.format(v=printed[0] + '°')}, before {others}"


def _off_line(q: Point, u: Point, v: Point) -> float:
    """How far ``q`` is from the line through ``u`` and ``v``."""
    return abs((v[0] - u[0]) * (q[1] - u[1]) - (v[1] - u[1]) * (q[0] - u[0])) / math.dist(u, v)


def front_gap(polygon: Polygon, triangle: tuple[int, int, int], candidates: Iterable[int],
              heuristic: str, d: int) -> float:
    """How far the metaphor's front, as it reaches the pick ``d``, stays from the other
    candidates (in P's units): the water's circle about B, the clock hand's line (from B, or
    from C), the vertical sweep, the line parallel to AC (the rising water's shore too). A
    near tie would be decided where the class cannot see it. Infinite with one candidate."""
    pts = polygon.points
    a, b, c = (pts[k] for k in triangle)
    at = pts[d]
    gap: dict[str, Callable[[Point], float]] = {
        "scaling": lambda q: abs(math.dist(b, q) - math.dist(b, at)),
        "rotation": lambda q: _off_line(q, b, at),
        "rotation-ccw": lambda q: _off_line(q, b, at),
        "rotation-correct": lambda q: _off_line(q, c, at),
        "translation": lambda q: abs(q[0] - at[0]),
        "translation-correct": lambda q: abs(_off_line(q, a, c) - _off_line(at, a, c)),
        "scaling-correct": lambda q: abs(_off_line(q, a, c) - _off_line(at, a, c)),
    }
    return min((gap[heuristic](pts[k]) for k in candidates if k != d), default=math.inf)


def _lines_of(shape: BaseGeometry) -> list[list[Point]]:
    """The polylines of a shapely intersection (a line, several, or a mix with points)."""
    parts = getattr(shape, "geoms", [shape])
    return [[(x, y) for x, y, *_ in part.coords] for part in parts
            if isinstance(part, LineString) and part.length > 0]


def front(polygon: Polygon, triangle: tuple[int, int, int], heuristic: str,
          d: int) -> list[list[Point]]:
    """The metaphor's front as it reaches the pick ``d``, inside T (in P's units): what the
    answer draws, so that it shows what its reason says (review r567: "the line parallel to
    AC, swept from B, reaches E first" was said over a picture with no line). The water's
    circle about B; the clock hand from B (from C), through the pick; the vertical sweep; the
    line parallel to AC (the rising water's shore too)."""
    pts = polygon.points
    a, b, c = (pts[k] for k in triangle)
    at, region = pts[d], Region([a, b, c])
    reach = 2 * max(math.dist(a, b), math.dist(b, c), math.dist(a, c))  # past T's far side

    def through(u: Point) -> LineString:
        k = reach / math.hypot(*u)
        return LineString([(at[0] - k * u[0], at[1] - k * u[1]),
                           (at[0] + k * u[0], at[1] + k * u[1])])

    def ray(centre: Point) -> LineString:
        k = reach / math.dist(centre, at)
        return LineString([centre, (centre[0] + k * (at[0] - centre[0]),
                                    centre[1] + k * (at[1] - centre[1]))])

    shapes: dict[str, Callable[[], LineString]] = {
        "scaling": lambda: ShapelyPoint(b).buffer(math.dist(b, at), 64).exterior,
        "rotation": lambda: ray(b),
        "rotation-ccw": lambda: ray(b),
        "rotation-correct": lambda: ray(c),
        "translation": lambda: through((0.0, 1.0)),
        "translation-correct": lambda: through((c[0] - a[0], c[1] - a[1])),
        "scaling-correct": lambda: through((c[0] - a[0], c[1] - a[1])),
    }
    return _lines_of(shapes[heuristic]().intersection(region))


def confusions(heuristic: str) -> tuple[str, ...]:
    """The rules a class may apply in place of ``heuristic``: Scaling (the nearest candidate
    to B, what a class guesses with no rule) and the rule's twin of the same metaphor (a
    wrong rule's correction, a correct rule's first wrong one). A pick exercise is fair only
    where each of them picks another vertex: on the old first exercise Correct Translation,
    Translation and Scaling all picked E, and a class using a wrong rule got it right. (Not
    every wrong rule: the two clocks at B always pick apart, so that no candidate but a third
    could differ from both.)

    >>> confusions("translation-correct"), confusions("scaling"), confusions("rotation-ccw")
    (('scaling', 'translation'), ('scaling-correct',), ('scaling', 'rotation-correct'))
    """
    fix = entry(heuristic).correction
    twin = fix or next(h for h in wrong() if entry(h).correction == heuristic)
    return tuple(dict.fromkeys(h for h in ("scaling", twin) if h != heuristic))


def _would_pick(polygon: Polygon, picks: dict[str, int]) -> str:
    """"Scaling and Translation would pick D": the confused rules' picks, said together where
    they agree."""
    by_pick: dict[int, list[str]] = {}
    for h, v in picks.items():
        by_pick.setdefault(v, []).append(spoken(h))
    return "; ".join(f"{_and(names)} would pick {polygon.labels[v]}"
                     for v, names in by_pick.items())


def _pick(number: int, heuristics: list[str]) -> Callable[[_Frame], Exercise | None]:
    """A pick exercise on the frame, for the first of ``heuristics`` (a seeded order) that it
    is fair for: rules that the wrong ones (:func:`confusions`) agree with on most polygons
    (Scaling and Translation pick Correct Translation's vertex on about three polygons in
    four) would make the search for a fixed rule many times longer."""

    def build(frame: _Frame) -> Exercise | None:
        return next((e for h in heuristics if (e := _fair_pick(number, frame, h)) is not None),
                    None)

    return build


def _fair_pick(number: int, frame: _Frame, heuristic: str) -> Exercise | None:
    """"Which vertex does … pick?" on the frame, if its answer tells the rule apart from the
    rules a class may confuse it with, and the pick is ahead by a margin the class can see."""
    p = frame.polygon
    d, steps = _reached(p, heuristic)
    picks = {h: find_diagonal(p, h).v.index for h in confusions(heuristic)}
    if d in picks.values():
        return None  # a class applying a wrong rule would get it right
    reason = _pick_reason(heuristic, steps)
    if reason is None or front_gap(p, frame.triangle, frame.candidates,
                                   heuristic, d) < MIN_CLEARANCE * _scale(p):
        return None  # a tie as printed, or as seen
    return _exercise(number, "pick", frame, heuristic,
                     f"Which vertex does {spoken(heuristic)} pick?", p.labels[d],
                     f"{reason}; {_would_pick(p, picks)}")


def crossed_edges(polygon: Polygon, i: int, j: int) -> list[tuple[tuple[int, int], Point]]:
    """Every edge the segment from vertex ``i`` to ``j`` crosses (at a point inside both),
    with where, in order from ``i``: a diagonal that leaves P and comes back crosses
    several, and the class sees each (review r567: "AC crosses edge L–M" was said, and only
    L–M flashed, of AC's three crossings)."""
    a, b = polygon.points[i], polygon.points[j]
    found = []
    for k, m in polygon.edges():
        c, d = polygon.points[k], polygon.points[m]
        if not {i, j} & {k, m} and segment_contact(a, b, c, d) is Contact.PROPER:
            found.append(((k, m), intersection_point(a, b, c, d)))
    return sorted(found, key=lambda hit: squared_distance(a, hit[1]))


def _not_inner(polygon: Polygon, i: int, j: int, verdict: CheckResult) -> str:
    """Why the diagonal from ``i`` to ``j`` is not inner, naming every edge it crosses."""
    name = _label(polygon, i, j)
    edges = ["–".join(polygon.labels[k] for k in edge) for edge, _ in crossed_edges(polygon, i, j)]
    if verdict.code != "crosses" or len(edges) < 2:
        return why_not_inner(verdict, polygon.labels, name)
    return f"{name} crosses edges {_and(edges)}"


def _claim(number: int, heuristics: list[str], wanted: bool) -> Callable[[_Frame], Exercise | None]:
    def build(frame: _Frame) -> Exercise | None:
        p = frame.polygon
        for heuristic in heuristics:
            claim = find_diagonal(p, heuristic)
            verdict = is_inner_diagonal(p, *claim.pair)
            seen = _clear(p, *claim.pair) if verdict.ok else _visibly_outside(p, *claim.pair)
            if verdict.ok != wanted or not seen:
                continue
            name, said = claim.name, spoken(heuristic)
            answer = f"{'yes' if verdict.ok else 'no'} ({said} claims {name})"
            reason = _not_inner(p, *claim.pair, verdict) if not verdict.ok else _inside(
                p, *claim.pair)
            question = f"Is the claim of {said} an inner diagonal?"
            return _exercise(number, "claim", frame, heuristic, question, answer, reason)
        return None

    return build


def _inside(polygon: Polygon, i: int, j: int) -> str:
    # a diagonal is named XY, an edge X–Y: "BF … B–F" in one sentence read as two things
    return f"{_label(polygon, i, j)} crosses no edge and touches no vertex: " \
        "it runs inside the polygon"


def _inner(number: int) -> Callable[[_Frame], Exercise | None]:
    def build(frame: _Frame) -> Exercise | None:
        p = frame.polygon
        a, b, c = frame.triangle
        options = ((a, c), *((b, d) for d in sorted(frame.candidates, key=p.labels.__getitem__)))
        verdicts = [is_inner_diagonal(p, *pair) for pair in options]
        if all(v.ok for v in verdicts) or not any(v.ok for v in verdicts):
            return None  # not a mix (AC, not inner when T holds a candidate, makes one)
        if not all(_clear(p, *pair) if v.ok else _visibly_outside(p, *pair)
                   for pair, v in zip(options, verdicts, strict=True)):
            return None  # one that looks, on screen, other than it is
        names = [_label(p, *pair) for pair in options]
        yes = [n for n, v in zip(names, verdicts, strict=True) if v.ok]
        reasons = [_not_inner(p, *pair, v)
                   for pair, v in zip(options, verdicts, strict=True) if not v.ok]
        reasons.append(f"{_and(yes)} {'runs' if len(yes) == 1 else 'run'} inside the polygon")
        question = f"Which of these diagonals are inner: {', '.join(names)}?"
        return _exercise(number, "inner", frame, None, question, ", ".join(yes),
                         "; ".join(reasons), options)

    return build


def _exercise(number: int, kind: str, frame: _Frame, heuristic: str | None, question: str,
              answer: str, reason: str, options: Iterable[tuple[int, int]] = ()) -> Exercise:
    return Exercise(number, kind, frame.spec, heuristic, question, answer, reason,
                    frame.triangle, frame.candidates, tuple(options), frame.polygon)


def measured_pairs(log: tracing.Log, labels: Sequence[str]) -> tuple[tuple[int, int], ...]:
    """The vertex pairs a rule of one's own measured, in the order it measured them: each
    call of a function of its own on exactly two of P's vertices (``distance_to_c(C, D)``:
    C and D), not the frame's claim."""
    pairs = []
    for e in log.events:
        refs = [a.get("ref") for a in (e.args or {}).values() if isinstance(a, dict)]
        if e.kind == "call" and e.name != "claim" and len(refs) == len(e.args or {}) == 2 \
                and all(r in labels for r in refs):
            pairs.append((labels.index(str(refs[0])), labels.index(str(refs[1]))))
    return tuple(dict.fromkeys(pairs))


def hunted_exercise(number: int, spec: str, polygon: Polygon, name: str, claim: tuple[int, int],
                    why: str, measured: tuple[tuple[int, int], ...] = ()) -> Exercise:
    """"Is the claim of ``name`` an inner diagonal?" for a rule of one's own on the polygon a
    hunt found (``spec`` names it), its ``claim`` judged here exactly; ``why`` says why it
    claims its vertex, with ``{pick}`` and ``{others}`` for the labels (no number: "E is
    nearer to C than D", not "Distance to C for E: 1"); ``measured``: the pairs the answer
    draws (:func:`measured_pairs`)."""
    t = triangle_at(polygon, leftmost_vertex(polygon))
    candidates = tuple(v.index for v in candidates_in_triangle(polygon, t))
    frame = _Frame(spec, polygon, (t.a.index, t.b.index, t.c.index), candidates)
    verdict = is_inner_diagonal(polygon, *claim)
    pick = claim[1]
    said = why.format(pick=polygon.labels[pick],
                      others=_and([polygon.labels[k] for k in candidates if k != pick]))
    judged = _not_inner(polygon, *claim, verdict) if not verdict.ok else _inside(polygon, *claim)
    answer = f"{'yes' if verdict.ok else 'no'} (it claims {_label(polygon, *claim)})"
    # the amber lines the answer draws, said while drawn (an amber E–C stood unexplained)
    compared = (f" (amber: the lengths it compared, {_and([_label(polygon, *p) for p in measured])})"
                if measured else "")
    made = _exercise(number, "claim", frame, None, f"Is the claim of {name} an inner diagonal?",
                     answer, f"{said}{compared}; {judged}")
    return replace(made, claim=claim, measured=measured)


def checking_time(exercise: Exercise, said: str) -> float:
    """How long the answer ``said`` stays up: read, then each thing it names checked against
    the picture (:data:`LEAST_CHECKING`, :data:`CHECK_EACH`)."""
    return max(LEAST_CHECKING, reading_time(said) + CHECK_EACH * exercise.checks)


def make_exercises(n: int = 6, seed: int = 0) -> list[Exercise]:
    """``n`` exercises, kinds in turn (pick, claim, inner, pick …), polygons from the
    generators in turn, all from ``seed``."""
    if n < 1:
        raise ValueError("need at least one exercise")
    rng = random.Random(seed)
    claims = sum(1 for k in range(n) if KINDS[k % len(KINDS)] == "claim")
    wanted = [k % 2 == 0 for k in range(claims)]  # as many yes as no (±1) …
    rng.shuffle(wanted)  # … in a seeded order
    pool = _Pool(rng)
    out = []
    for k in range(n):
        kind = KINDS[k % len(KINDS)]
        if kind == "pick":
            build = _pick(k + 1, rng.sample(PICKABLE, len(PICKABLE)))
        elif kind == "claim":
            build = _claim(k + 1, rng.sample(wrong(), len(wrong())), wanted.pop())
        else:
            build = _inner(k + 1)
        generator = CLAIM_GENERATOR if kind == "claim" else GENERATORS[k % len(GENERATORS)]
        out.append(_search(pool, generator, build))
    return out


# --- answers.md -----------------------------------------------------------------------------------


def answers_markdown(exercises: list[Exercise], seed: int) -> str:
    """The answer sheet: per exercise its question, polygon, picture, answer and reason."""
    lines = [
        "# Exercises: inner diagonals",
        "",
        f"{len(exercises)} exercises from seed {seed}. B is the left-most vertex (lowest on ties),",
        "A and C its neighbours, T = ABC; the candidates are the other vertices in T.",
        "Each polygon is a sample any `trex` command reads, e.g. "
        f"`trex check {exercises[0].spec}`.",
    ]
    for e in exercises:
        lines += [
            "",
            f"## {e.title}",
            "",
            f"- polygon: `{e.spec}` (picture: `{e.still}`)",
            f"- answer: **{e.answer}**",
            f"- reason: {e.reason}",
        ]
    return "\n".join(lines) + "\n"
