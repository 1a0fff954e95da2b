"""The source listing as the panel shows it: each line wrapped into rows that fit the panel's
width at a readable size, and the window of lines shown when the rows are more than fit its
height. Plain data (no manim): :class:`metaphors.panel.Panel` draws it.

A line's rows keep its indentation, one cell for every two spaces (a level of four spaces is
two cells: the structure stays, the width goes to the code); its continuation rows are
indented :data:`CONTINUATION` cells more, two levels, so that they cannot be taken for the
block under it.

>>> [(r.name, r.indent, r.text) for r in wrap_line(6, "        return claim(t.b, d)", 22)]
[('code:7', 4, 'return claim(t.b,'), ('code:7.2', 8, 'd)')]
>>> window_for((1, 2, 1, 1, 3, 1), capacity=4, lit=4)
Window(first=3, end=5)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

#: how many cells further a line's continuation rows are indented than its first row
CONTINUATION = 4
#: the fewest characters a row holds, however deep the line is indented
NARROWEST = 12
#: a window that moves shows about this share of its rows above the lit line, for context
CONTEXT = 0.25


@dataclass(frozen=True)
class Row:
    """One row of the listing as shown: part ``part`` (1 for the first) of line ``line``
    (counted from 0), ``indent`` cells from the left."""

    line: int
    part: int
    indent: int
    text: str

    @property
    def name(self) -> str:
        """``code:N`` for line N's first row (N from 1, by place in the listing, as the
        pseudocode's rows are named), ``code:N.2``, ``code:N.3`` … for its continuations."""
        return f"code:{self.line + 1}" + (f".{self.part}" if self.part > 1 else "")


def wrap_line(line: int, text: str, columns: int, most: int | None = None) -> list[Row]:
    """The rows of one line of source in rows of ``columns`` cells, each broken where
    :func:`_break_at` says; at most ``most`` rows, the last of them then ending in ``…``
    (a line taller than the panel is shown cut, not over what is below it).

    >>> [r.text for r in wrap_line(0, "x = f(alpha, beta)", 10)]
    ['x = f(', 'alpha,', 'beta)']
    >>> [r.text for r in wrap_line(0, "arm.update(points=[b.point, c.point])", 22)]
    ['arm.update(points=[', 'b.point, c.point])']
    >>> [r.text for r in wrap_line(0, "abcdefghijklmnopqrstuvwxyz", 20)]
    ['abcdefghijklmnopqrst', 'uvwxyz']
    >>> [r.text for r in wrap_line(0, "x = f(alpha, beta)", 10, most=2)]
    ['x = f(', 'alpha, be…']
    """
    body = text.strip()
    indent = min((len(text) - len(text.lstrip(" "))) // 2, max(0, columns - NARROWEST))
    rows: list[Row] = []
    while True:
        here = indent if not rows else min(indent + CONTINUATION, max(0, columns - NARROWEST))
        width = max(1, columns - here)
        if len(body) <= width:
            rows.append(Row(line, len(rows) + 1, here, body))
            return rows
        if most is not None and len(rows) + 1 >= most:
            rows.append(Row(line, len(rows) + 1, here, body[:width - 1].rstrip() + "…"))
            return rows
        cut = _break_at(body, width)
        rows.append(Row(line, len(rows) + 1, here, body[:cut].rstrip()))
        body = body[cut:].lstrip()


def _break_at(body: str, width: int) -> int:
    """Where a row of at most ``width`` characters of ``body`` ends (``body`` is longer): at
    its last space, unless that leaves the row under a third full and a ``,``, ``(`` or
    ``[`` comes later (the row ends after it); else after its last ``.``, else where it is
    full."""
    space = body.rfind(" ", 1, width + 1)
    if not body[:max(space, 0)].strip():
        space = -1
    mark = max(body.rfind(c, 0, width) for c in ",([") + 1
    cut = space if space >= width / 3 else max(space, mark)
    if cut > 0:
        return cut
    dot = body.rfind(".", 0, width)
    return dot + 1 if dot >= 0 else width


def listing_rows(lines: Sequence[str], columns: int, most: int | None = None) -> tuple[Row, ...]:
    """Every line's rows, in order (at most ``most`` for a line)."""
    return tuple(row for k, text in enumerate(lines)
                 for row in wrap_line(k, text, columns, most))


@dataclass(frozen=True)
class Window:
    """The lines ``first`` to ``end - 1`` (counted from 0), shown whole."""

    first: int
    end: int

    def holds(self, line: int) -> bool:
        return self.first <= line < self.end


def window_for(counts: Sequence[int], capacity: int, lit: int,
               current: Window | None = None) -> Window:
    """The window of whole lines (line k takes ``counts[k]`` rows, none more than
    ``capacity``; at most ``capacity`` in all) that shows line ``lit``: the ``current`` one if it does, else a new one with about
    :data:`CONTEXT` of its rows above the lit line (fewer at the top of the listing), then as
    many lines below as fit, then, if there is still room (at the listing's end, or before a
    line too long for what is left), more lines above."""
    if current is not None and current.holds(lit):
        return current
    first, above = lit, 0
    context = min(int(capacity * CONTEXT), capacity - counts[lit])
    while first > 0 and above + counts[first - 1] <= context:
        first -= 1
        above += counts[first]
    end, used = first, 0
    while end < len(counts) and (end <= lit or used + counts[end] <= capacity):
        used += counts[end]
        end += 1
    while first > 0 and used + counts[first - 1] <= capacity:  # room left: more above
        first -= 1
        used += counts[first]
    return Window(first, end)
