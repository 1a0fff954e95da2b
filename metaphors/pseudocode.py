"""The source shown in the panel: the real code of the traced function that runs.

The log's line numbers are source lines of the algorithm, so the lit line is exact.

>>> [text for _, text in source_of("scaling")][:3]  # doctest: +NORMALIZE_WHITESPACE
['def heuristic(polygon: Polygon) -> Diagonal:', '    _check_size(polygon)',
 '    t = triangle_at(polygon, leftmost_vertex(polygon))']
"""

from __future__ import annotations

import inspect
import textwrap
from functools import cache

from story.registry import REGISTRY


def _functions() -> dict:
    """The shown function of each registry entry by its traced name, unwrapped."""
    return {e.shown: e.source.__wrapped__ for e in REGISTRY.values() if e.source is not None}


@cache
def source_of(name: str) -> tuple[tuple[int, str], ...]:
    """(source line number, text) for each shown line: no decorators, docstring or blank lines.

    Empty for an unknown name (the panel then shows no code).
    """
    function = _functions().get(name)
    if function is None:
        return ()
    lines, first = inspect.getsourcelines(function)
    text = textwrap.dedent("".join(lines)).splitlines()
    numbered = [(first + k, line.rstrip()) for k, line in enumerate(text)]
    kept, in_doc = [], False
    for number, line in numbered:
        stripped = line.strip()
        if stripped.startswith("@") and not kept:
            continue
        if stripped.startswith('"""'):
            in_doc = stripped.count('"""') != 2
            continue
        if in_doc:
            in_doc = '"""' not in stripped
            continue
        if stripped:
            kept.append((number, line))
    return tuple(kept)
