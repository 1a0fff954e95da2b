"""Pseudocode: the rows of an algorithm in the thesis's words, each tied to the traced calls
it covers, and which of them is lit as a log runs.

A :class:`PseudocodeRow` is one row of the panel: a short text (two leading spaces per level of
indentation) and the traced names it covers (``calls``). The registry writes the pseudocode
of every built-in algorithm (:attr:`story.registry.Entry.pseudocode`); a heuristic of one's
own may carry its own in its docstring (:func:`from_docstring`). The storyboard lights, for
each beat, the row covering the innermost running call (:func:`lit_row`).

The panel shows the pseudocode or the real source: :data:`PANELS`, :data:`PSEUDOCODE`
(the default; the source when a run has no pseudocode) and :data:`SOURCE`.

No manim here.

>>> rows = (PseudocodeRow("B = the left-most vertex", ("leftmost_vertex",)),
...         PseudocodeRow("none: claim AC is an inner diagonal", ("claim",)),
...         PseudocodeRow("else: D = the candidate closest to B", ("pick", "nearest_to")),
...         PseudocodeRow("  claim BD is an inner diagonal", ("claim",)))
>>> lit_row(rows, ["scaling", "pick", "nearest_to"], lit=0)
2
>>> lit_row(rows, ["scaling", "claim"], lit=2), lit_row(rows, ["scaling", "claim"], lit=0)
(3, 1)
>>> lit_row(rows, ["scaling"], lit=2) is None
True
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from story.refs import listed
from tracing import JSON

__all__ = [
    "PANELS",
    "PSEUDOCODE",
    "RESULT",
    "SOURCE",
    "PseudocodeRow",
    "bound",
    "from_docstring",
    "from_json",
    "lit_row",
    "named",
    "result_row",
    "to_json",
]

#: The panel's modes: the pseudocode (default) or the real source of the shown function.
PSEUDOCODE, SOURCE = "pseudocode", "source"
PANELS = (PSEUDOCODE, SOURCE)


@dataclass(frozen=True)
class PseudocodeRow:
    """One row of pseudocode.

    Attributes
    ----------
    text : str
        What the row says, with two leading spaces per level of indentation.
    calls : tuple of str
        The traced names it covers (the log's call names); a row covering none is never lit.
    """

    text: str
    calls: tuple[str, ...] = ()

    @property
    def depth(self) -> int:
        """Its level of indentation (two spaces each).

        >>> PseudocodeRow("    Q = the good part").depth
        2
        """
        return (len(self.text) - len(self.text.lstrip(" "))) // 2


def lit_row(pseudocode: Sequence[PseudocodeRow], running: Sequence[str], lit: int | None) -> int | None:
    """The row lit while the calls ``running`` (outermost first) run: the row covering the
    innermost of them that a row covers; None if none is covered.

    Several rows may cover one name (the claim of AC and the claim of BD): the first of them at
    or after the row ``lit`` so far wins (the program goes on from where it was), else the
    first of them (it went round a loop).
    """
    for name in reversed(running):
        rows = [k for k, row in enumerate(pseudocode) if name in row.calls]
        if rows:
            later = [k for k in rows if lit is not None and k >= lit]
            return later[0] if later else rows[0]
    return None


#: What a row covers that says the run's result (the whole triangulation, drawn at the end):
#: no traced call has this name, so the walk never lights the row; the ending lights it
#: (:func:`result_row`), not the row of the last step, which no longer says what is on screen.
RESULT = "(result)"


def result_row(pseudocode: Sequence[PseudocodeRow]) -> int | None:
    """The row saying the run's result (covering :data:`RESULT`); None if none does.

    >>> result_row((PseudocodeRow("divide P along it", ("split",)),
    ...             PseudocodeRow("their union is the triangulation of P", (RESULT,))))
    1
    >>> result_row((PseudocodeRow("divide P along it", ("split",)),)) is None
    True
    """
    return next((k for k, row in enumerate(pseudocode) if RESULT in row.calls), None)


# --- the picture's own vertices -----------------------------------------------------------------

#: A name in a row: a run of capitals (``B``, ``AC``, ``ABC``).
_NAME = re.compile(r"\b[A-Z]+\b")


def named(pseudocode: Sequence[PseudocodeRow], vertices: dict[str, str],
          labels: Iterable[str]) -> tuple[PseudocodeRow, ...]:
    """The rows speaking of the picture's own vertices (issue 22): where a placeholder
    (``D``) is also a label on screen (``labels``) and the run gave it another vertex
    (``vertices``: placeholder → label, ``{"D": "E"}``), the rows name that vertex instead
    — the screen's D is not the rule's D. Every name made only of placeholders is rewritten
    letter by letter, all at once (``BD`` → ``BE``); other capitals (``P``, ``T``) stay.

    >>> rows = (PseudocodeRow("else: D = the candidate closest to B", ("pick",)),
    ...         PseudocodeRow("  claim BD is an inner diagonal", ("claim",)))
    >>> [s.text for s in named(rows, {"B": "B", "D": "E"}, "ABCDE")]
    ['else: E = the candidate closest to B', '  claim BE is an inner diagonal']
    >>> [s.text for s in named(rows, {"B": "D", "D": "B"}, "ABCDE")]
    ['else: B = the candidate closest to D', '  claim DB is an inner diagonal']
    >>> named(rows, {"D": "E"}, "ABC") == rows  # no D on screen: the rule's D is no one else
    True
    """
    shown = set(labels)
    swap = {k: v for k, v in vertices.items() if k in shown and v != k}
    if not swap:
        return tuple(pseudocode)

    def rename(found: re.Match[str]) -> str:
        word = found.group()
        return "".join(swap.get(c, c) for c in word) if set(word) <= set(vertices) else word

    return tuple(PseudocodeRow(_NAME.sub(rename, row.text), row.calls) for row in pseudocode)


def _tie(text: str, placeholder: str, label: str) -> str:
    """``text`` with its first ``placeholder`` tied to ``label``: ``V = …`` → ``V = C, …``,
    ``… X`` → ``… X = G``."""
    def tied(found: re.Match[str]) -> str:
        return f"{placeholder} = {label}, " if found.group(1) else f"{placeholder} = {label}"

    return re.sub(rf"\b{placeholder}\b( = )?", tied, text, count=1)


def bound(pseudocode: Sequence[PseudocodeRow], vertices: Mapping[str, str],
          defined: Mapping[str, str], labels: Iterable[str],
          claim: tuple[str, str] | None = None) -> tuple[PseudocodeRow, ...]:
    """The rows tying a placeholder that is no label on screen (gravity's V, X, Y) to the
    vertex the run gave it (``vertices``: placeholder → label), in the row that gives it
    (the row covering the call ``defined[placeholder]``): ``V = the first…`` says ``V = C,
    the first…``, ``to a vertex X`` says ``to a vertex X = G``; and the row covering the
    ``claim`` (its two labels, once made) ties the name of the claim to it, ``claim VY = CH``.
    The card and the rows say V, X, Y; the picture says C, G, H: the rows said only the
    letters, never which vertex each was (chapter 3). Placeholders on screen are
    :func:`named`'s.

    >>> rows = (PseudocodeRow("V = the first reflex vertex", ("reflex_vertex",)),
    ...         PseudocodeRow("it slides to a vertex X", ("slide_to_vertex",)),
    ...         PseudocodeRow("claim VY, or VX if straight", ("claim",)))
    >>> got = bound(rows, {"V": "E", "X": "C"}, {"V": "reflex_vertex", "X": "slide_to_vertex"},
    ...             "ABCDE", ("E", "C"))
    >>> [r.text for r in got]
    ['V = E, the first reflex vertex', 'it slides to a vertex X = C', 'claim VY, or VX = EC if straight']
    """
    shown = set(labels)
    tied = {k: v for k, v in vertices.items() if k not in shown and k in defined}
    out = []
    for row in pseudocode:
        text = row.text
        for placeholder, label in tied.items():
            if defined[placeholder] not in row.calls:
                continue
            text = _tie(text, placeholder, label)
        if claim is not None and "claim" in row.calls:
            def tie(found: re.Match[str]) -> str:
                name = found.group()
                ends = tuple(tied.get(c, c if c in shown else "") for c in name)
                return f"{name} = {''.join(claim)}" if ends == claim and len(name) == 2 else name
            text = _NAME.sub(tie, text, count=0)
        out.append(PseudocodeRow(text, row.calls))
    return tuple(out)


# --- a heuristic of one's own: pseudocode in its docstring ------------------------------------

#: The line of a docstring after which its pseudocode rows come.
HEADING = "Pseudocode:"
_CALLS = re.compile(r"^(?P<text>.*?)\s*\[(?P<calls>[^\[\]]*)\]\s*$")


def from_docstring(doc: str | None) -> tuple[PseudocodeRow, ...]:
    """The pseudocode rows of a docstring: the lines after a line ``Pseudocode:``, up to the
    first blank line (or the end). A row may end in the traced names it covers, in brackets:
    ``text  [name, other_name]`` (``[]``: none; a row ending in no brackets covers none).
    Indentation beyond the least indented row is kept, two spaces a level.

    >>> doc = '''Claim BD for the candidate D with the largest angle ABD.
    ...
    ... Pseudocode:
    ...     B = the left-most vertex       [leftmost_vertex]
    ...     for each candidate D:
    ...       the angle ABD                [angle_at_b]
    ...     claim BD for the widest        [claim]
    ...
    ... More text.'''
    >>> for row in from_docstring(doc):
    ...     print(repr(row.text), row.calls)
    'B = the left-most vertex' ('leftmost_vertex',)
    'for each candidate D:' ()
    '  the angle ABD' ('angle_at_b',)
    'claim BD for the widest' ('claim',)
    >>> from_docstring("No pseudocode here."), from_docstring(None)
    ((), ())
    """
    lines = (doc or "").expandtabs().splitlines()
    start = next((k + 1 for k, line in enumerate(lines) if line.strip() == HEADING), None)
    if start is None:
        return ()
    rows: list[str] = []
    for line in lines[start:]:
        if not line.strip():
            if rows:
                break
            continue
        rows.append(line.rstrip())
    margin = min((len(r) - len(r.lstrip(" ")) for r in rows), default=0)
    return tuple(_parse_row(row[margin:]) for row in rows)


def _parse_row(row: str) -> PseudocodeRow:
    found = _CALLS.match(row)
    if found is None:
        return PseudocodeRow(row)
    calls = tuple(name.strip() for name in found["calls"].split(",") if name.strip())
    return PseudocodeRow(found["text"], calls)


# --- in a log's meta ------------------------------------------------------------------------------


def to_json(pseudocode: Iterable[PseudocodeRow]) -> list[list[Any]]:
    """Rows as a log's meta carries them: ``[[text, [calls…]], …]``."""
    return [[row.text, list(row.calls)] for row in pseudocode]


def from_json(rows: JSON) -> tuple[PseudocodeRow, ...]:
    """Rows from a log's meta (:func:`to_json`).

    >>> from_json(to_json([PseudocodeRow("claim BD", ("claim",))]))
    (PseudocodeRow(text='claim BD', calls=('claim',)),)
    """
    what = "the log's meta 'pseudocode'"
    return tuple(PseudocodeRow(str(text), tuple(str(c) for c in listed(calls, what)))
                 for text, calls in (listed(row, what) for row in listed(rows, what)))
