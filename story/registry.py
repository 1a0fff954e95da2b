"""The registry: every heuristic and triangulation algorithm by name, with what we know of it.

One :class:`Entry` per name, spelled as the command line spells it: its kind (a heuristic
claims one inner diagonal, a triangulation cuts the polygon into triangles), the function
that runs it, whether it is correct, its metaphor, the traced function whose source the
panel shows, its pseudocode, its default polygon and its title. Everything that lists the
algorithms (the command line's choices, the exercises, the lecture, the storyboard) reads
them here; geometry runs them (:data:`geometry.diagonals.HEURISTICS`,
:func:`geometry.triangulate.triangulate`) and knows nothing of this table.

Examples
--------
>>> heuristics()
('scaling', 'rotation', 'rotation-ccw', 'translation', 'translation-correct', 'scaling-correct', 'rotation-correct', 'scaling-walled', 'gravity')
>>> wrong()
('scaling', 'rotation', 'rotation-ccw', 'translation')
>>> triangulations()
('divide-and-conquer', 'ear-clipping-naive', 'ear-clipping', 'prune-and-search', 'monotone', 'cdt')
>>> e = entry("rotation-ccw")
>>> e.kind, e.correct, e.metaphor, e.polygon, e.correction
('heuristic', False, 'clock', 'counterexample-twin', 'rotation-correct')
>>> entry("gravity").shown
'gravity_at'
>>> for step in entry("scaling").pseudocode:
...     print(f"{step.text:44} {', '.join(step.calls)}")
B = the left-most vertex (lowest on ties)    leftmost_vertex
A, C = its neighbours; T = triangle ABC      triangle_at
candidates = the other vertices inside T     candidates_in_triangle
none: claim AC is an inner diagonal          claim
else: D = the candidate closest to B         pick, nearest_to
  claim BD is an inner diagonal              claim
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from geometry.diagonals import HEURISTICS
from geometry.gravity import gravity_at
from geometry.lennes import divide_and_conquer
from geometry.polygon import Polygon
from geometry.results import Triangulation
from geometry.triangulate import RUNNERS, triangulate
from story.pseudocode import RESULT, PseudocodeRow
from usercode.heuristic import UserHeuristic, diagonal_rule

__all__ = [
    "HEURISTIC",
    "KINDS",
    "REGISTRY",
    "SPOKEN",
    "TRIANGULATION",
    "Entry",
    "Spoken",
    "correct",
    "entry",
    "heuristics",
    "introduced",
    "names",
    "pseudocode",
    "shown",
    "spoken",
    "triangulations",
    "wrong",
]

HEURISTIC, TRIANGULATION = "heuristic", "triangulation"
KINDS = (HEURISTIC, TRIANGULATION)


@dataclass(frozen=True)
class Spoken:
    """What a viewer hears and reads for an algorithm: its ``name`` as the thesis says it
    (ch. 2: "Scaling", "Correct Translation"; the command line's slugs never reach the
    screen), and its ``picture``, the metaphor said with the name the first time (None: the
    name says it all)."""

    name: str
    picture: str | None = None

    @property
    def introduced(self) -> str:
        """The name with its picture, for its first appearance: ``Scaling (spilled water)``."""
        return f"{self.name} ({self.picture})" if self.picture else self.name


#: The one table of spoken names: every title, caption and card that names an algorithm
#: takes its words from here (thesis ch. 2; the pictures after Forišek and Steinová).
SPOKEN: Mapping[str, Spoken] = MappingProxyType({
    "scaling": Spoken("Scaling", "spilled water"),
    "rotation": Spoken("Rotation", "the clock hand"),
    "rotation-ccw": Spoken("Rotation the other way", "the clock hand set to C"),
    "translation": Spoken("Translation", "the sweeping line"),
    "translation-correct": Spoken("Correct Translation", "the line parallel to AC"),
    "scaling-correct": Spoken("Correct Scaling", "water rising from AC"),
    "rotation-correct": Spoken("Correct Rotation", "the clock at C"),
    # the thesis's first Correct Scaling (ch. 2.1.2: "make the water respect the edges"),
    # before "another correct variant", the water rising from AC: both its name
    "scaling-walled": Spoken("Correct Scaling", "water that respects the edges"),
    "gravity": Spoken("Gravity", "the ball on a rubber band"),
    "divide-and-conquer": Spoken("divide and conquer", "cut along inner diagonals"),
    "ear-clipping-naive": Spoken("ear clipping", "slicing fruit"),
    "ear-clipping": Spoken("faster ear clipping", "slicing fruit"),
    "prune-and-search": Spoken("prune and search", "slicing fruit"),
    "monotone": Spoken("monotone partition", "a line swept down"),
    "cdt": Spoken("constrained Delaunay"),
})


def spoken(name: str, *, first: bool = False, start: bool = False) -> str:
    """How the screen names ``name``: the thesis's word (with its picture when ``first``,
    capitalised when it ``start``s a sentence). A name not in the table (a heuristic of
    one's own) is said as it is.

    >>> spoken("scaling-correct"), spoken("scaling", first=True)
    ('Correct Scaling', 'Scaling (spilled water)')
    >>> spoken("ear-clipping-naive", start=True), spoken("biggest_angle")
    ('Ear clipping', 'biggest_angle')
    """
    known = SPOKEN.get(name)
    if known is None:
        return name
    said = known.introduced if first else known.name
    return said[:1].upper() + said[1:] if start else said


def introduced(name: str) -> str:
    """``name`` said for the first time, with its picture: ``spoken(name, first=True)``."""
    return spoken(name, first=True)


@dataclass(frozen=True)
class Entry:
    """What the project knows of one heuristic or triangulation algorithm.

    Attributes
    ----------
    name : str
        The name as the command line spells it (``rotation-ccw``, ``ear-clipping``).
    kind : str
        :data:`HEURISTIC` (claims one inner diagonal) or :data:`TRIANGULATION`.
    function : callable
        What runs it. A heuristic: ``function(polygon) -> Diagonal``, the traced function
        of :data:`geometry.diagonals.HEURISTICS`. A triangulation:
        ``function(polygon, heuristic=None) -> Triangulation``, which is
        :func:`geometry.triangulate.triangulate` with this name (``heuristic`` only
        matters to divide and conquer).
    correct : bool
        Whether it is always right: a heuristic's claim is always an inner diagonal, a
        triangulation's triangles always triangulate the polygon (divide and conquer: with
        a correct heuristic).
    metaphor : str or None
        The physical picture the video plays, as the module of :mod:`metaphors` that reads
        and performs its steps: ``water``, ``clock``, ``sweep``, ``gravity``, ``fruit``,
        ``monotone``, ``pieces`` (divide and conquer's split; each diagonal plays its
        heuristic's metaphor); None for the reference triangulation, drawn plainly.
    shown : str
        The traced function whose source the panel shows (a name the log carries).
    source : callable or None
        That function (traced; its ``__wrapped__`` is the source the panel may show); None
        when the panel shows none (the reference triangulation).
    polygon : str
        The sample it plays on by default. A wrong heuristic's default polygon is one on
        which it fails.
    title : str
        One line naming it and its idea, for titles.
    pseudocode : tuple of PseudocodeRow
        Its pseudocode in the thesis's words (ch. 2), at most about ten short rows, each a
        :class:`story.pseudocode.PseudocodeRow`: its text (two leading spaces a level) and the traced
        names of the calls it covers, which light it as the log runs. Empty for the
        reference triangulation (the panel shows nothing).
    correction : str or None
        For a wrong heuristic, the correct one that mends it (thesis ch. 2.1.2).
    """

    name: str
    kind: str
    function: Callable[..., object]
    correct: bool
    metaphor: str | None
    shown: str
    source: Callable[..., object] | None
    polygon: str
    title: str
    pseudocode: tuple[PseudocodeRow, ...] = ()
    correction: str | None = None

    @property
    def is_heuristic(self) -> bool:
        """Whether it is a heuristic (else a triangulation).

        >>> entry("gravity").is_heuristic, entry("cdt").is_heuristic
        (True, False)
        """
        return self.kind == HEURISTIC


def _title(name: str, idea: str) -> str:
    """A title: the spoken name (:data:`SPOKEN`), then its idea."""
    return f"{spoken(name, start=True)}: {idea}"


def _heuristic(name: str, *, correct: bool, metaphor: str, polygon: str, idea: str,
               pseudocode: tuple[PseudocodeRow, ...], shown: Callable[..., Any] | None = None,
               correction: str | None = None) -> Entry:
    source = shown or HEURISTICS[name]
    return Entry(name, HEURISTIC, HEURISTICS[name], correct, metaphor, _traced_name(source),
                 source, polygon, _title(name, idea), pseudocode, correction)


def _frame(rule: str, *calls: str, inside: tuple[PseudocodeRow, ...] = ()) -> tuple[PseudocodeRow, ...]:
    """The pseudocode every triangle heuristic shares (thesis ch. 2.1), around its rule for D:
    ``else: D = <rule>``, covering the traced ``pick`` and the rule's own ``calls`` (with the
    rows ``inside`` the rule, if any)."""
    return (
        PseudocodeRow("B = the left-most vertex (lowest on ties)", ("leftmost_vertex",)),
        PseudocodeRow("A, C = its neighbours; T = triangle ABC", ("triangle_at",)),
        PseudocodeRow("candidates = the other vertices inside T", ("candidates_in_triangle",)),
        PseudocodeRow("none: claim AC is an inner diagonal", ("claim",)),
        PseudocodeRow(f"else: D = {rule}", ("pick", *calls)),
        *inside,
        # the rule's claim, not a fact: lit while the verdict refutes it ("✗ BD is not an
        # inner diagonal"), "BD is an inner diagonal" read as the panel contradicting the
        # caption (review of the scenes' renders)
        PseudocodeRow("  claim BD is an inner diagonal", ("claim",)),
    )


def _traced_name(function: Callable[..., Any]) -> str:
    """The name a traced function's calls carry in the log."""
    name: str = function.__trace_spec__.name  # type: ignore[attr-defined]  # tracing's decorators set it on their wrappers
    return name


def _runner(name: str) -> Callable[..., Triangulation]:
    """``triangulate(polygon, name, heuristic)``, the one place the registry calls it; a
    heuristic of one's own goes to geometry as its traced run
    (:func:`usercode.heuristic.diagonal_rule`)."""

    def run(polygon: Polygon, heuristic: str | UserHeuristic | None = None) -> Triangulation:
        return triangulate(polygon, name, diagonal_rule(heuristic))

    run.__name__ = run.__qualname__ = f"triangulate_{name.replace('-', '_')}"
    run.__doc__ = f"Triangulate the polygon with {name} (verified exactly)."
    return run


def _triangulation(name: str, *, metaphor: str | None, idea: str,
                   pseudocode: tuple[PseudocodeRow, ...] = (), shown: Callable[..., Any] | None = None,
                   polygon: str = "lecture", show_source: bool = True) -> Entry:
    source = shown or RUNNERS[name]
    return Entry(name, TRIANGULATION, _runner(name), True, metaphor, _traced_name(source),
                 source if show_source else None, polygon, _title(name, idea), pseudocode)


#: The traced names of the heuristics (divide and conquer calls one of them on each piece).
_HEURISTICS_TRACED = tuple(_traced_name(f) for f in HEURISTICS.values())

#: The rows of gravity (thesis ch. 2.1.2, after Forišek and Steinová), also inside the others.
_GRAVITY = (
    PseudocodeRow("B = the left-most vertex", ("leftmost_vertex",)),
    PseudocodeRow("V = the first reflex vertex after B", ("reflex_vertex", "straight_vertex")),
    # "edge", as the captions and the card say (the rows said "side": two words, one thing)
    PseudocodeRow("turn P: V's edges point up, no edge level", ("gravity_direction",)),
    PseudocodeRow("drop a ball on a band at V: it hits an edge", ("drop_ball",)),
    PseudocodeRow("it slides down the edge to a vertex X", ("slide_to_vertex",)),
    # "(if any)": lit under "The rubber band stays straight", the row said a Y there was
    # (chapter 3)
    PseudocodeRow("Y = the first vertex the band snags (if any)", ("band_snag",)),
    PseudocodeRow("claim VY, or VX if the band stays straight", ("claim",)),
    PseudocodeRow("no reflex or straight vertex: claim AC", ("triangle_at", "claim")),
)


#: The last row of a listing that slices ears: what the whole triangulation drawn at its end is.
_SLICES = PseudocodeRow("the slices together: the triangulation of P", (RESULT,))


_ENTRIES = (
    # --- heuristics (thesis ch. 2.1): the wrong ones, then the corrections -------------------
    _heuristic("scaling", correct=False, metaphor="water", polygon="counterexample",
               idea="water spilled at B wets the nearest candidate",
               pseudocode=_frame("the candidate closest to B", "nearest_to"),
               correction="scaling-correct"),
    _heuristic("rotation", correct=False, metaphor="clock", polygon="counterexample",
               idea="a clock at B, set to A, stops at the first candidate",
               pseudocode=_frame("first hit of a hand at B set to A", "first_hit_rotating"),
               correction="rotation-correct"),
    _heuristic("rotation-ccw", correct=False, metaphor="clock", polygon="counterexample-twin",
               idea="the clock at B set to C",
               pseudocode=_frame("first hit of a hand at B set to C", "first_hit_rotating"),
               correction="rotation-correct"),
    _heuristic("translation", correct=False, metaphor="sweep", polygon="counterexample",
               idea="a vertical line swept from B",
               pseudocode=_frame("the left-most candidate", "first_hit_sweeping"),
               correction="translation-correct"),
    _heuristic("translation-correct", correct=True, metaphor="sweep", polygon="counterexample",
               idea="a line parallel to AC swept from B",
               pseudocode=_frame("first hit of a line ∥ AC from B", "first_hit_sweeping")),
    _heuristic("scaling-correct", correct=True, metaphor="water", polygon="counterexample",
               idea="water rises from AC; the last dry candidate",
               pseudocode=_frame("the candidate farthest from AC", "last_dry")),
    _heuristic("rotation-correct", correct=True, metaphor="clock", polygon="counterexample",
               idea="the clock moves to C, set to B",
               pseudocode=_frame("first hit of a hand at C set to B", "first_hit_rotating")),
    _heuristic("scaling-walled", correct=True, metaphor="water", polygon="counterexample",
               idea="water that respects the edges",
               pseudocode=_frame("the nearest vertex that B sees", "nearest_visible",
                                 inside=(PseudocodeRow("  B sees V if BV runs inside P", ("sees",)),))),
    _heuristic("gravity", correct=True, metaphor="gravity", polygon="gravity-snag",
               idea="a ball on a rubber band finds a diagonal", shown=gravity_at,
               pseudocode=_GRAVITY),
    # --- triangulations (thesis ch. 2.2-2.4) -----------------------------------------------------
    _triangulation("divide-and-conquer", metaphor="pieces", shown=divide_and_conquer,
                   idea="Lennes splits along inner diagonals",
                   pseudocode=(
                       PseudocodeRow("if P is a triangle, we are done", ("done",)),
                       # no name "d" for the diagonal: beside the vertex D it read as D
                       # (the diagonal split along first is DG; case_twin_names)
                       PseudocodeRow("else find an inner diagonal of P", _HEURISTICS_TRACED),
                       PseudocodeRow("divide P along it into P1 and P2", ("split",)),
                       PseudocodeRow("triangulate P1 and P2 the same way", ("next_part",)),
                       PseudocodeRow("their union is the triangulation of P", (RESULT,)),
                   )),
    _triangulation("ear-clipping-naive", metaphor="fruit",
                   idea="Meisters slices the first ear found",
                   pseudocode=(
                       PseudocodeRow("while P has more than 3 vertices:"),
                       PseudocodeRow("  for each vertex V, from the first:"),
                       PseudocodeRow("    is V an ear: convex, its triangle empty?", ("is_ear",)),
                       PseudocodeRow("    yes: slice V's triangle off, start again", ("clip_ear",)),
                       PseudocodeRow("the triangle left is the last slice", ("ear-clipping-naive",)),
                       _SLICES,
                   )),
    _triangulation("ear-clipping", metaphor="fruit",
                   idea="only the neighbours of a slice change",
                   pseudocode=(
                       # a vertex is tested once, until a slice beside it: its "no, go on"
                       # and its neighbours' retest are said on the rows lit as they happen
                       # (rows of their own covered no call and never lit: "else go on to the
                       # next vertex" stayed dark under "Is C an ear? no", review)
                       PseudocodeRow("walk round P while it has over 3 vertices:"),
                       PseudocodeRow("  V untested: is V an ear? if not, go on", ("is_ear",)),
                       PseudocodeRow("  an ear: slice it; retest its neighbours", ("clip_ear",)),
                       PseudocodeRow("the triangle left is the last slice", ("ear-clipping",)),
                       _SLICES,
                   )),
    _triangulation("prune-and-search", metaphor="fruit",
                   idea="the good sub-polygons shrink",
                   pseudocode=(
                       # Q = P at first, good (no cutting edge: the chapter's card says so); one
                       # row, room for the result's (at most 8 rows fit at the least size of text).
                       # Q, not G: G is a vertex of the lecture polygon, the one tested first
                       # ("Is G an ear? no"), and a sub-polygon of the same name read as it
                       PseudocodeRow("Q = P (good); while P is more than a triangle:"),
                       PseudocodeRow("  V = the middle vertex of Q: an ear?", ("is_ear",)),
                       PseudocodeRow("  yes: slice the ear V off, go on in Q", ("clip_ear",)),
                       PseudocodeRow("  no: find an inner diagonal V–W of Q", ("diagonal_at",)),
                       PseudocodeRow("    convex: Correct Translation, else Gravity",
                                     ("sweep_at", "gravity_at")),
                       PseudocodeRow("    Q = the good part beyond V–W", ("good_subpolygon",)),
                       PseudocodeRow("the triangle left is the last slice", ("prune-and-search",)),
                       _SLICES,
                   )),
    _triangulation("monotone", metaphor="monotone", idea="y-monotone pieces, then the stack",
                   pseudocode=(
                       PseudocodeRow("sweep a line down P, vertex by vertex:", ("make_monotone",)),
                       PseudocodeRow("  v is start, end, split, merge or regular", ("classify_vertex",)),
                       # a regular vertex on P's right side helps too (geometry.monotone);
                       # the helper is said on the picture the first time it is set
                       PseudocodeRow("  split, merge, or regular with P to its left:"),
                       PseudocodeRow("    v becomes helper of the edge on its left",
                                     ("set_helper",)),
                       # end, regular and merge vertices add one too (geometry.monotone)
                       PseudocodeRow("  split, or v ends or replaces a merge helper:"),
                       PseudocodeRow("    add the diagonal v–helper", ("add_diagonal",)),
                       PseudocodeRow("cut P into y-monotone pieces; each, top down:",
                            ("monotone_pieces", "triangulate_monotone_piece")),
                       PseudocodeRow("  push v: it waits on the stack", ("push",)),
                       PseudocodeRow("  v sees past the top: cut off, pop", ("cut_off",)),
                       PseudocodeRow("their triangles: the triangulation of P", (RESULT,)),
                   )),
    _triangulation("cdt", metaphor=None, idea="the reference, by shapely",
                   show_source=False),
)

#: Every entry by name, heuristics first, in the order the command line lists them.
REGISTRY: Mapping[str, Entry] = MappingProxyType({e.name: e for e in _ENTRIES})


def entry(name: str) -> Entry:
    """The entry of ``name``.

    Raises
    ------
    KeyError
        For an unknown name, with a one-line message listing the known ones.

    Examples
    --------
    >>> entry("cdt").title
    'Constrained Delaunay: the reference, by shapely'
    >>> entry("magic")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    KeyError: "unknown algorithm 'magic'; expected one of scaling, rotation, ..., monotone, cdt"
    """
    try:
        return REGISTRY[name]
    except KeyError:
        raise KeyError(f"unknown algorithm {name!r}; expected one of "
                       f"{', '.join(REGISTRY)}") from None


def names(kind: str | None = None) -> tuple[str, ...]:
    """Every name (of one kind, if given), in registry order.

    >>> names(TRIANGULATION)[:2]
    ('divide-and-conquer', 'ear-clipping-naive')
    >>> len(names()) == len(heuristics()) + len(triangulations())
    True
    """
    if kind is not None and kind not in KINDS:
        raise ValueError(f"unknown kind {kind!r}; expected one of {', '.join(KINDS)}")
    return tuple(e.name for e in REGISTRY.values() if kind is None or e.kind == kind)


def heuristics() -> tuple[str, ...]:
    """The heuristics' names: those :data:`geometry.diagonals.HEURISTICS` runs, in its order."""
    return names(HEURISTIC)


def triangulations() -> tuple[str, ...]:
    """The triangulation algorithms' names, as :func:`geometry.triangulate.triangulate` takes
    them."""
    return names(TRIANGULATION)


def correct(kind: str | None = HEURISTIC) -> tuple[str, ...]:
    """The names of the correct heuristics (of ``kind``; None: of every kind).

    >>> correct()
    ('translation-correct', 'scaling-correct', 'rotation-correct', 'scaling-walled', 'gravity')
    """
    return tuple(n for n in names(kind) if REGISTRY[n].correct)


def wrong(kind: str | None = HEURISTIC) -> tuple[str, ...]:
    """The names of the wrong heuristics (of ``kind``; None: of every kind).

    >>> wrong(None) == wrong()
    True
    """
    return tuple(n for n in names(kind) if not REGISTRY[n].correct)


def shown(name: str) -> str:
    """The traced function whose source the panel shows for ``name``; any other name (a
    heuristic of one's own) shows itself.

    >>> shown("divide-and-conquer"), shown("scaling"), shown("biggest_angle")
    ('divide_and_conquer', 'scaling', 'biggest_angle')
    """
    known = REGISTRY.get(name)
    return known.shown if known is not None else name


#: Rows put before an algorithm's own when it runs on a polygon with holes (the log's meta
#: carries the whole listing, so a simple polygon's run shows what it always showed).
_HOLE_ROWS = {
    "ear-clipping": (PseudocodeRow("cut a keyhole from each hole to the rind", ("join_hole",)),),
}


def hole_pseudocode(name: str) -> tuple[PseudocodeRow, ...]:
    """The pseudocode of ``name`` on a polygon with holes: the bridges first, for ear clipping.

    >>> [step.text for step in hole_pseudocode("ear-clipping")[:2]]
    ['cut a keyhole from each hole to the rind', 'walk round P while it has over 3 vertices:']
    >>> hole_pseudocode("monotone") == pseudocode("monotone")
    True
    """
    return (*_HOLE_ROWS.get(name, ()), *pseudocode(name))


def pseudocode(name: str) -> tuple[PseudocodeRow, ...]:
    """The pseudocode of ``name``; none for any other name (a heuristic of one's own carries
    its own in its log, if its docstring has it).

    >>> pseudocode("gravity")[1].text, pseudocode("cdt"), pseudocode("biggest_angle")
    ('V = the first reflex vertex after B', (), ())
    """
    known = REGISTRY.get(name)
    return known.pseudocode if known is not None else ()
