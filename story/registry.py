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
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType

from geometry.diagonals import HEURISTICS
from geometry.gravity import gravity_at
from geometry.lennes import divide_and_conquer
from geometry.polygon import Polygon
from geometry.results import Triangulation
from geometry.triangulate import RUNNERS, triangulate

__all__ = [
    "HEURISTIC",
    "KINDS",
    "REGISTRY",
    "TRIANGULATION",
    "Entry",
    "correct",
    "entry",
    "heuristics",
    "names",
    "shown",
    "triangulations",
    "wrong",
]

HEURISTIC, TRIANGULATION = "heuristic", "triangulation"
KINDS = (HEURISTIC, TRIANGULATION)


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
    pseudocode : tuple of str
        Its pseudocode in the thesis's words, one line each (empty: not written yet).
    correction : str or None
        For a wrong heuristic, the correct one that mends it (thesis ch. 2.1.2).
    """

    name: str
    kind: str
    function: Callable
    correct: bool
    metaphor: str | None
    shown: str
    source: Callable | None
    polygon: str
    title: str
    pseudocode: tuple[str, ...] = ()
    correction: str | None = None

    @property
    def is_heuristic(self) -> bool:
        """Whether it is a heuristic (else a triangulation).

        >>> entry("gravity").is_heuristic, entry("cdt").is_heuristic
        (True, False)
        """
        return self.kind == HEURISTIC


def _heuristic(name: str, *, correct: bool, metaphor: str, polygon: str, title: str,
               shown: Callable | None = None, correction: str | None = None) -> Entry:
    source = shown or HEURISTICS[name]
    return Entry(name, HEURISTIC, HEURISTICS[name], correct, metaphor, _traced_name(source),
                 source, polygon, title, correction=correction)


def _traced_name(function: Callable) -> str:
    """The name a traced function's calls carry in the log."""
    return function.__trace_spec__.name


def _runner(name: str) -> Callable[..., Triangulation]:
    """``triangulate(polygon, name, heuristic)``, the one place the registry calls it."""

    def run(polygon: Polygon, heuristic: str | None = None) -> Triangulation:
        return triangulate(polygon, name, heuristic)

    run.__name__ = run.__qualname__ = f"triangulate_{name.replace('-', '_')}"
    run.__doc__ = f"Triangulate the polygon with {name} (verified exactly)."
    return run


def _triangulation(name: str, *, metaphor: str | None, title: str,
                   shown: Callable | None = None, polygon: str = "lecture",
                   show_source: bool = True) -> Entry:
    source = shown or RUNNERS[name]
    return Entry(name, TRIANGULATION, _runner(name), True, metaphor, _traced_name(source),
                 source if show_source else None, polygon, title)


_ENTRIES = (
    # --- heuristics (thesis ch. 2.1): the wrong ones, then the corrections -------------------
    _heuristic("scaling", correct=False, metaphor="water", polygon="counterexample",
               title="Scaling: water spilled at B wets the nearest candidate",
               correction="scaling-correct"),
    _heuristic("rotation", correct=False, metaphor="clock", polygon="counterexample",
               title="Rotation: a clock at B, set to A, stops at the first candidate",
               correction="rotation-correct"),
    _heuristic("rotation-ccw", correct=False, metaphor="clock", polygon="counterexample-twin",
               title="Rotation the other way: the clock at B set to C",
               correction="rotation-correct"),
    _heuristic("translation", correct=False, metaphor="sweep", polygon="counterexample",
               title="Translation: a vertical line swept from B",
               correction="translation-correct"),
    _heuristic("translation-correct", correct=True, metaphor="sweep", polygon="counterexample",
               title="Correct translation: a line parallel to AC swept from B"),
    _heuristic("scaling-correct", correct=True, metaphor="water", polygon="counterexample",
               title="Correct scaling: water rises from AC; the last dry candidate"),
    _heuristic("rotation-correct", correct=True, metaphor="clock", polygon="counterexample",
               title="Correct rotation: the clock moves to C, set to B"),
    _heuristic("scaling-walled", correct=True, metaphor="water", polygon="counterexample",
               title="Scaling with walls: water that cannot pass the edges"),
    _heuristic("gravity", correct=True, metaphor="gravity", polygon="gravity-snag",
               title="Gravity: a ball on a rubber band finds a diagonal", shown=gravity_at),
    # --- triangulations (thesis ch. 2.2-2.4) -----------------------------------------------------
    _triangulation("divide-and-conquer", metaphor="pieces", shown=divide_and_conquer,
                   title="Divide and conquer (Lennes): split along inner diagonals"),
    _triangulation("ear-clipping-naive", metaphor="fruit",
                   title="Ear clipping (Meisters): slice the first ear found"),
    _triangulation("ear-clipping", metaphor="fruit",
                   title="Ear clipping with ear status kept up to date"),
    _triangulation("prune-and-search", metaphor="fruit",
                   title="Prune and search: the good sub-polygons shrink"),
    _triangulation("monotone", metaphor="monotone", title="Monotone partition, then the stack"),
    _triangulation("cdt", metaphor=None, title="Constrained Delaunay (shapely)",
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
    'Constrained Delaunay (shapely)'
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
