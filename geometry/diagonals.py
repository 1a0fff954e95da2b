"""The inner-diagonal heuristics of the thesis (ch. 2.1), wrong and correct, all traced.

Frame shared by the triangle heuristics: B = the left-most vertex (lowest on
ties), A and C its neighbours, T = the closed triangle ABC. Candidates are the
other vertices lying in T. No candidate: AC is the claim. Otherwise the rule
picks D and the claim is BD. A heuristic returns its claim; it never checks it
(:func:`geometry.check.is_inner_diagonal` does).

Tie rule (every heuristic): among candidates equal under the rule, the one
nearest to the metaphor's origin (B; C for ``rotation-correct``) wins, then
the one that comes first counter-clockwise after B. Every comparison is exact.

Each step is a traced call a scene maps to its metaphor: ``leftmost_vertex``,
``triangle_at``, ``candidates_in_triangle``, ``nearest_to`` (water),
``first_hit_rotating`` (clock), ``first_hit_sweeping`` (sweep line),
``last_dry`` (water rising from the shore), ``nearest_visible`` /
``sees`` (water that respects walls), and for gravity ``reflex_vertex``,
``gravity_direction``, ``drop_ball``, ``slide_to_vertex``, ``band_snag``.
Each logs its arguments and its pick, nothing drawn: how far the water, the
hand or the line travels to each candidate is the storyboard's to compute
(:mod:`story.reach`).

Examples
--------
>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
>>> {name: find_diagonal(p, name).name for name in HEURISTICS}  # doctest: +NORMALIZE_WHITESPACE
{'scaling': 'BD', 'rotation': 'BD', 'rotation-ccw': 'BE', 'translation': 'BD',
 'translation-correct': 'BE', 'scaling-correct': 'BE', 'rotation-correct': 'BE',
 'scaling-walled': 'BE', 'gravity': 'EC'}
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cmp_to_key

import tracing
from geometry.check import is_inner_diagonal
from geometry.frame import (
    Diagonal,
    Triangle,
    candidates_in_triangle,
    claim,
    leftmost_vertex,
    triangle_at,
)
from geometry.gravity import gravity, gravity_at
from geometry.polygon import Polygon, Vertex
from geometry.predicates import (
    Point,
    compare_angle,
    compare_distance,
    compare_line_distance,
)

__all__ = [
    "HEURISTICS",
    "Diagonal",
    "Triangle",
    "find_diagonal",
    "gravity_at",
    "sweep_at",
]


def _ranked(
    candidates: list[Vertex], rule: Callable[[Vertex, Vertex], int], origin: Vertex, b: int
) -> list[Vertex]:
    """Candidates sorted by the rule, then by distance from origin, then ccw order after B.

    Counter-clockwise after B: the vertices after B's index first, then those before it,
    each in index order (what ``(index - b) % n`` orders, without asking for n: the traced
    picks take only what their call line shows, so that the call line is the real call).

    >>> from geometry.polygon import Polygon
    >>> p = Polygon.from_points([(0, 0), (2, 0), (2, 2), (0, 2)])
    >>> [v.index for v in _ranked([p.vertex(k) for k in range(4)], lambda u, v: 0, p.vertex(0), 2)]  # 1, 3 tie
    [0, 3, 1, 2]
    """

    def after_b(u: Vertex) -> tuple[bool, int]:
        return u.index < b, u.index

    def compare(u: Vertex, v: Vertex) -> int:
        return (
            rule(u, v)
            or compare_distance(origin.point, u.point, v.point)
            or (after_b(u) > after_b(v)) - (after_b(u) < after_b(v))
        )

    return sorted(candidates, key=cmp_to_key(compare))


# --- water: scaling ------------------------------------------------------------------------------


@tracing.traced
def nearest_to(b: Vertex, candidates: list[Vertex]) -> Vertex:
    """Water spilled at B spreads as a growing circle; the first candidate it wets is D."""
    return _ranked(candidates, lambda u, v: 0, b, b.index)[0]


@tracing.traced
def last_dry(t: Triangle, candidates: list[Vertex]) -> Vertex:
    """Water rises from the shore AC towards B; the last candidate to get wet is D."""

    def rule(u: Vertex, v: Vertex) -> int:  # farther from AC first
        return -compare_line_distance(t.a.point, t.c.point, u.point, v.point)

    return _ranked(candidates, rule, t.b, t.b.index)[0]


@tracing.traced
def sees(polygon: Polygon, b: Vertex, v: Vertex) -> bool:
    """Whether the segment Bv is an inner diagonal (v is visible from B, through the inside)."""
    return bool(is_inner_diagonal(polygon, b.index, v.index))


@tracing.traced
def nearest_visible(polygon: Polygon, t: Triangle) -> Vertex:
    """Water that respects the walls: the vertex nearest to B among those B sees (not A, C)."""
    b, n = t.b, polygon.n
    others = [polygon.vertex((b.index + k) % n) for k in range(2, n - 1)]
    for v in _ranked(others, lambda u, v: 0, b, b.index):
        if sees(polygon, b, v):
            return v
    raise AssertionError("a convex vertex with candidates always sees one")  # thesis, lemma 2


# --- clock: rotation -----------------------------------------------------------------------------


@tracing.traced
def first_hit_rotating(centre: Vertex, start: Vertex, candidates: list[Vertex]) -> Vertex:
    """A clock hand at `centre`, set to `start`, turns; the first candidate it passes is D."""

    def rule(u: Vertex, v: Vertex) -> int:
        return compare_angle(centre.point, start.point, u.point, v.point)

    return _ranked(candidates, rule, centre, centre.index)[0]


# --- sweep: translation --------------------------------------------------------------------------


@tracing.traced
def first_hit_sweeping(
    b: Vertex, direction: list[float], candidates: list[Vertex], shore: Triangle | None
) -> Vertex:
    """A line through B, along `direction`, moves across T; the first candidate it touches is D.

    ``shore`` None: the vertical line moved rightwards (left-most candidate). Otherwise the
    line is parallel to AC and moves from B towards AC (farthest candidate from AC).
    """
    if shore is None:
        def rule(u: Vertex, v: Vertex) -> int:
            return (u.point[0] > v.point[0]) - (u.point[0] < v.point[0])
    else:
        def rule(u: Vertex, v: Vertex) -> int:
            return -compare_line_distance(shore.a.point, shore.c.point, u.point, v.point)

    return _ranked(candidates, rule, b, b.index)[0]


# --- the heuristics ------------------------------------------------------------------------------


def _triangle_heuristic(
    pick: Callable[[Polygon, Triangle, list[Vertex]], Vertex],
) -> Callable[[Polygon], Diagonal]:
    """Build a heuristic from its rule: the frame, then AC or B–pick (T lives meanwhile)."""

    def heuristic(polygon: Polygon) -> Diagonal:
        _check_size(polygon)
        t = triangle_at(polygon, leftmost_vertex(polygon))
        with tracing.alive(t):
            candidates = candidates_in_triangle(polygon, t)
            if not candidates:
                return claim(t.a, t.c)
            d = pick(polygon, t, candidates)
            return claim(t.b, d)

    return heuristic


def _check_size(polygon: Polygon) -> None:
    if polygon.n < 4:
        raise ValueError("a triangle has no diagonal")


def _direction(p: Point, q: Point) -> list[float]:
    return [q[0] - p[0], q[1] - p[1]]


_PICKS: dict[str, Callable[[Polygon, Triangle, list[Vertex]], Vertex]] = {
    "scaling": lambda p, t, cs: nearest_to(t.b, cs),
    "rotation": lambda p, t, cs: first_hit_rotating(t.b, t.a, cs),
    "rotation-ccw": lambda p, t, cs: first_hit_rotating(t.b, t.c, cs),
    "translation": lambda p, t, cs: first_hit_sweeping(t.b, [0.0, 1.0], cs, None),
    "translation-correct": lambda p, t, cs: first_hit_sweeping(
        t.b, _direction(t.a.point, t.c.point), cs, t
    ),
    "scaling-correct": lambda p, t, cs: last_dry(t, cs),
    "rotation-correct": lambda p, t, cs: first_hit_rotating(t.c, t.b, cs),
    "scaling-walled": lambda p, t, cs: nearest_visible(p, t),
}


def _named(name: str, function: Callable[[Polygon], Diagonal]) -> Callable[[Polygon], Diagonal]:
    return tracing.traced(name=name)(function)


# The pick is traced too, so the log shows the line of the heuristic that asked for it.
_pick = tracing.traced(name="pick", exclude_args=("p",))
HEURISTICS: dict[str, Callable[[Polygon], Diagonal]] = {
    name: _named(name, _triangle_heuristic(_pick(pick))) for name, pick in _PICKS.items()
}
HEURISTICS["gravity"] = gravity
# Which of them are correct, their metaphors and titles: story.registry (geometry runs them).


def find_diagonal(polygon: Polygon, heuristic: str) -> Diagonal:
    """Run the named heuristic; raises KeyError naming the known ones for an unknown name."""
    if heuristic not in HEURISTICS:
        raise KeyError(f"unknown heuristic {heuristic!r}; expected one of {', '.join(HEURISTICS)}")
    with tracing.alive(polygon):
        return HEURISTICS[heuristic](polygon)


@tracing.traced
def sweep_at(polygon: Polygon, b: Vertex) -> Diagonal | None:
    """The correct sweep at any strictly convex vertex b: AC, or b to the farthest candidate.

    Used by prune-and-search ear finding; None when T holds no candidate (b is an ear).
    """
    t = triangle_at(polygon, b)
    with tracing.alive(t):
        candidates = candidates_in_triangle(polygon, t)
        if not candidates:
            return None
        return claim(b, _PICKS["translation-correct"](polygon, t, candidates))
