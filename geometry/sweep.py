"""Plane-sweep test for contacts between the edges of a ring: O(n log n), exact.

Shamos–Hoey: a sweep line visits the vertices in lexicographic (x, y) order
(a vertical line tilted a hair counter-clockwise, so points with equal x are
met bottom to top and a vertical edge runs from its lower end to its upper
end). The *status* holds the edges that cross the sweep line, bottom to top.
Until the first contact the active edges are disjoint (adjacent edges share
only their common end point), so their order never changes and every
comparison made while searching the status is consistent. Each edge is tested
only against the edges it becomes a neighbour of: when it is inserted, and
when an edge between two others is removed. The left-most contact is then
always found (if two edges meet first at a point that is no vertex, they are
neighbours just before it; if the point is a vertex, the search for that
vertex in the status finds every edge through it).

Edge ``i`` runs from ``points[i]`` to ``points[i + 1]`` (the last edge closes
the ring). Edges adjacent in the ring share an end point; that point is not a
contact. Every sign comes from :func:`geometry.predicates.orient` (a float
filter, then exact rational arithmetic), so the answer is exact for all finite
floats.

The status is a chunked sorted list: a list of sorted chunks of at most
``2 * _LOAD`` edges, searched by bisection first over the chunks' last edges,
then inside one chunk. Insertion and deletion cost O(chunk + number of chunks)
element moves, done by ``list`` in C, so the whole sweep is O(n log n)
comparisons plus cheap moves.

Examples
--------
>>> first_contact([(0, 0), (2, 0), (2, 2), (0, 2)]) is None
True
>>> first_contact([(0, 0), (2, 2), (2, 0), (0, 2)])  # a bow tie: edges 0 and 2 cross
(0, 2)
>>> first_contact([(0, 0), (4, 0), (4, 4), (2, 0), (0, 4)])  # vertex 3 touches edge 0
(0, 3)
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from typing import Generic, TypeVar

from geometry.predicates import Contact, Point, orient, segment_contact

__all__ = ["ChunkedList", "first_contact"]

_LOAD = 64

# An edge in the status: (left end, right end, edge index), left < right lexicographically.
Segment = tuple[Point, Point, int]
# A position in a ChunkedList: (chunk index, index inside the chunk).
Position = tuple[int, int]


T = TypeVar("T")


class ChunkedList(Generic[T]):
    """A sorted sequence kept as a list of short sorted lists (chunks).

    The order is given by the caller: :meth:`bisect` takes a predicate that is
    true on a prefix of the sequence. A :class:`Position` ``(k, i)`` names the
    slot before item ``i`` of chunk ``k``; the end of the sequence is
    ``(last chunk, its length)``. Positions are only valid until the next change.

    >>> items = ChunkedList(load=2)
    >>> items.insert(items.bisect(lambda x: x < 5), [1, 5, 9])
    >>> items.insert(items.bisect(lambda x: x < 7), [6, 7, 8])
    >>> items.chunks
    [[1, 5, 6], [7, 8, 9]]
    >>> pos = items.bisect(lambda x: x < 7)
    >>> items.before(pos), items.at(pos)
    (6, 7)
    >>> items.pop(pos)
    7
    >>> list(items)
    [1, 5, 6, 8, 9]
    """

    def __init__(self, load: int) -> None:
        self.load = load
        self.chunks: list[list[T]] = []

    def __iter__(self) -> Iterator[T]:
        for chunk in self.chunks:
            yield from chunk

    def __len__(self) -> int:
        return sum(map(len, self.chunks))

    def bisect(self, is_before: Callable[[T], bool]) -> Position:
        """Position of the first item for which ``is_before`` is false (or the end)."""
        chunks = self.chunks
        lo, hi = 0, len(chunks)
        while lo < hi:
            mid = (lo + hi) // 2
            if is_before(chunks[mid][-1]):
                lo = mid + 1
            else:
                hi = mid
        if lo == len(chunks):
            return self._end()
        chunk = chunks[lo]
        left, right = 0, len(chunk) - 1  # the chunk's last item is known not to be before
        while left < right:
            mid = (left + right) // 2
            if is_before(chunk[mid]):
                left = mid + 1
            else:
                right = mid
        return lo, left

    def _end(self) -> Position:
        return (len(self.chunks) - 1, len(self.chunks[-1])) if self.chunks else (0, 0)

    def at(self, pos: Position) -> T | None:
        """The item at ``pos``, or None at the end."""
        k, i = pos
        return self.chunks[k][i] if k < len(self.chunks) and i < len(self.chunks[k]) else None

    def before(self, pos: Position) -> T | None:
        """The item just before ``pos``, or None at the start."""
        k, i = pos
        if i > 0:
            return self.chunks[k][i - 1]
        return self.chunks[k - 1][-1] if k > 0 else None

    def pop(self, pos: Position) -> T:
        """Remove and return the item at ``pos``; ``pos`` then names the item after it."""
        k, i = pos
        chunk = self.chunks[k]
        item = chunk.pop(i)
        if not chunk:
            del self.chunks[k]
        return item

    def normalise(self, pos: Position) -> Position:
        """The same slot, written as the start of the next chunk if it ends one.

        >>> items = ChunkedList(load=1)
        >>> items.insert((0, 0), [1, 2, 3])
        >>> items.chunks, items.normalise((0, 1)), items.normalise((1, 2))
        ([[1], [2, 3]], (1, 0), (1, 2))
        """
        k, i = pos
        chunks = self.chunks
        if k >= len(chunks):
            return self._end()
        if i == len(chunks[k]) and k + 1 < len(chunks):
            return k + 1, 0
        return pos

    def insert(self, pos: Position, items: list[T]) -> None:
        """Insert ``items`` (already in order) at ``pos``; split the chunk if it grows long."""
        if not items:
            return
        if not self.chunks:
            self.chunks.append([])
        k, i = pos
        chunk = self.chunks[k]
        chunk[i:i] = items
        if len(chunk) > 2 * self.load:
            half = len(chunk) // 2
            self.chunks[k : k + 1] = [chunk[:half], chunk[half:]]


def _end_kinds(points: Sequence[Point], v: int) -> tuple[list[int], list[int]]:
    """Edges at vertex v that end there and that start there (in the sweep order)."""
    n = len(points)
    q = points[v]
    ending: list[int] = []
    starting: list[int] = []
    for edge, other in (((v - 1) % n, points[v - 1]), (v, points[(v + 1) % n])):
        (ending if other < q else starting).append(edge)
    return ending, starting


def _pair(i: int, j: int) -> tuple[int, int]:
    return (i, j) if i < j else (j, i)


def _adjacent(i: int, j: int, n: int) -> bool:
    return (i - j) % n in (1, n - 1)


def _segments(points: Sequence[Point]) -> list[Segment]:
    """Each edge as (left end, right end, index), ends in lexicographic order."""
    n = len(points)
    segments = []
    for i in range(n):
        a, b = points[i], points[(i + 1) % n]
        if a == b:
            raise ValueError(f"edge {i} has length zero: points {i} and {(i + 1) % n} are equal")
        segments.append((a, b, i) if a < b else (b, a, i))
    return segments


def _fold_back(points: Sequence[Point], v: int) -> tuple[int, int]:
    """Contact forced by edges v-1 and v leaving vertex v along the same ray.

    The nearer far end lies on the longer edge, and the edge beyond it touches
    that edge there.
    """
    n = len(points)
    if points[(v + 1) % n] <= points[v - 1]:  # same ray: lexicographic order is distance
        return _pair((v - 1) % n, (v + 1) % n)
    return _pair((v - 2) % n, v)


def _order_starting(segments: list[Segment], starting: list[int]) -> list[int] | None:
    """Edges starting at one point, bottom to top; None if they overlap (a fold-back)."""
    if len(starting) < 2:
        return starting
    first, second = segments[starting[0]], segments[starting[1]]
    turn = orient(first[0], first[1], second[1])  # common left end, two right ends
    if turn == 0:
        return None
    return starting if turn > 0 else starting[::-1]


def _side(s: Segment, q: Point) -> int:
    """Where q lies from edge s: 1 above (left of left→right), -1 below, 0 on its line.

    An end point of s is on it: no arithmetic then (the exact fallback would be needed).
    """
    if q == s[1] or q == s[0]:
        return 0
    return orient(s[0], s[1], q)


def _meet(s: Segment, t: Segment, n: int) -> bool:
    """Whether two non-adjacent edges of the status meet (adjacent ones never count)."""
    if _adjacent(s[2], t[2], n):
        return False
    return segment_contact(s[0], s[1], t[0], t[1]) is not Contact.NONE


def _repeated_vertex(points: Sequence[Point], order: list[int], k: int) -> tuple[int, int] | None:
    """For ``order[k]``, a vertex with the same point earlier in ``order``, as an edge pair."""
    if k > 0 and points[order[k - 1]] == points[order[k]]:
        return _pair(order[k - 1], order[k])
    return None


def first_contact(points: Sequence[Point]) -> tuple[int, int] | None:
    """The first pair (i, j), i < j, of non-adjacent ring edges that meet, or None.

    "Meet" is any common point: a crossing, a vertex on another edge, shared
    vertices (a repeated point) or collinear overlap. A fold-back (edges i-1 and
    i running back along each other at vertex i) shows as the contact it forces
    between non-adjacent edges. The pair found is the first one the sweep meets
    (near the left-most contact), not the one with the smallest indices.

    Parameters
    ----------
    points : sequence of (float, float)
        The ring, without a closing point; consecutive points must differ.

    Returns
    -------
    tuple of int or None
        Edge indices ``(i, j)``; edge ``i`` joins ``points[i]`` and ``points[i + 1]``.

    Raises
    ------
    ValueError
        If two consecutive points are equal (an edge of length zero).

    Examples
    --------
    >>> square = [(0, 0), (1, 0), (1, 1), (0, 1)]
    >>> first_contact(square) is None
    True
    >>> first_contact([(0, 0), (2, 0), (2, 1), (1, 0), (0, 1)])  # vertex 3 on edge 0
    (0, 3)
    >>> first_contact([(0, 0), (3, 0), (1, 0), (1, 1)])  # edges 0 and 1 fold back
    (0, 2)
    >>> first_contact([(0, 0), (1, 1), (2, 0), (2, 2), (1, 1), (0, 2)])  # a pinch at (1, 1)
    (0, 4)
    """
    n = len(points)
    segments = _segments(points)
    if n < 4:  # every pair of edges of a triangle is adjacent
        return None
    order = sorted(range(n), key=points.__getitem__)
    status: ChunkedList[Segment] = ChunkedList(_LOAD)
    for k, v in enumerate(order):
        contact = _repeated_vertex(points, order, k) or _visit(points, segments, status, v)
        if contact:
            return contact
    return None


def _visit(
    points: Sequence[Point], segments: list[Segment], status: ChunkedList[Segment], v: int
) -> tuple[int, int] | None:
    """Sweep past vertex v: remove the edges ending there, insert those starting there."""
    n = len(points)
    q = points[v]
    ending, starting = _end_kinds(points, v)
    pos = status.bisect(lambda s: _side(s, q) > 0)  # edges below q come first
    while (s := status.at(pos)) is not None and _side(s, q) == 0:
        if s[2] not in ending:  # q lies inside edge s: it meets both edges at q
            partner = v if _adjacent(s[2], (v - 1) % n, n) else (v - 1) % n
            return _pair(s[2], partner)
        status.pop(pos)
        ending.remove(s[2])
        pos = status.normalise(pos)
    if ending:
        raise AssertionError(f"sweep status lost edges {ending} at vertex {v}")
    new = _order_starting(segments, starting)
    if new is None:
        return _fold_back(points, v)
    below, above = status.before(pos), status.at(pos)
    status.insert(pos, [segments[e] for e in new])
    pairs = [(below, segments[new[0]]), (segments[new[-1]], above)] if new else [(below, above)]
    for s, t in pairs:
        if s is not None and t is not None and _meet(s, t, n):
            return _pair(s[2], t[2])
    return None
