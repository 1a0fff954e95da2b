"""The source shown in the panel: the real code of the traced function that runs.

The log's line numbers are source lines of the algorithm, so the lit line is exact.

>>> [text for _, text in source_of("scaling")][:3]  # doctest: +NORMALIZE_WHITESPACE
['def heuristic(polygon: Polygon) -> Diagonal:', '    _check_size(polygon)',
 '    t = triangle_at(polygon, leftmost_vertex(polygon))']
"""

from __future__ import annotations

from functools import cache

from story.registry import REGISTRY
from story.source import shown_source


def _functions() -> dict:
    """The shown function of each registry entry by its traced name, unwrapped."""
    return {e.shown: e.source.__wrapped__ for e in REGISTRY.values() if e.source is not None}  # type: ignore[attr-defined]  # the shown functions are tracing's wrappers


@cache
def source_of(name: str) -> tuple[tuple[int, str], ...]:
    """(source line number, text) for each shown line: no decorators, docstring or blank lines
    (:func:`story.source.shown_source`). Empty for an unknown name (the panel then
    shows no code).

    >>> [text for _, text in source_of("divide_and_conquer")][2]  # past the docstring
    '    find = heuristic if callable(heuristic) else HEURISTICS[heuristic]'
    """
    function = _functions().get(name)
    return () if function is None else shown_source(function)
