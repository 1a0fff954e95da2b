"""The words on screen (issue 22 item 1): what a viewer reads is spoken language, not the
command line's or the code's.

A crossing is named by its edge, not by where it is (:func:`why_not_inner`; the command
line keeps :mod:`geometry.check`'s text with coordinates); no number has more than one
decimal (:func:`number`); a traced function's name is said as words (:func:`said`). The
names of the algorithms are :data:`story.registry.SPOKEN`'s.

No manim here.

>>> number(2.86087), number(6.0), number(-0.04), number(12)
('2.9', '6', '0', '12')
>>> said("distance_to_c"), said("nearestTo")
('distance to c', 'nearest to')
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from geometry.check import CheckResult

__all__ = ["named_together", "number", "said", "why_not_inner"]


def named_together(labels: Sequence[str]) -> str:
    """A diagonal or a triangle named by its corners' labels: run together as geometry
    writes it (``MAB``), or, when one has a subscript, a space between them (``a₂ b₂ H``:
    "a₂b₂H" reads as one word).

    >>> named_together(["M", "A", "B"]), named_together(["a₂", "b₂", "H"])
    ('MAB', 'a₂ b₂ H')
    """
    return "".join(labels) if all(len(c) == 1 for c in labels) else " ".join(labels)


def number(value: float) -> str:
    """A number as the screen shows it: at most one decimal, none when it is whole (after
    rounding), never ``-0``."""
    shown = f"{round(float(value), 1):.1f}".removesuffix(".0")
    return "0" if shown == "-0" else shown


def said(name: str) -> str:
    """A function's name read aloud: its words, lower case (``distance_to_c`` → ``distance
    to c``, ``nearestTo`` → ``nearest to``)."""
    spaced = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", " ", name)
    return " ".join(part for part in re.split(r"[_\s]+", spaced) if part).lower()


def _edge(labels: Sequence[str], edge: tuple[int, int]) -> str:
    return "–".join(labels[k] for k in edge)


def why_not_inner(verdict: CheckResult, labels: Sequence[str], claim: str) -> str:
    """Why the claim ``claim`` (``BD``) is not an inner diagonal, in the picture's words:
    the edge it crosses, the vertex it passes through, the vertex near which it leaves the
    polygon — no coordinates. ``labels``: the polygon's, by vertex index.

    >>> why_not_inner(CheckResult(False, "…", "crosses", edge=(4, 0)), "ABCDE", "BD")
    'BD crosses edge E–A'
    >>> why_not_inner(CheckResult(False, "…", "through-vertex", vertex=3), "ABCDE", "BE")
    'BE passes through vertex D'
    >>> why_not_inner(CheckResult(False, "…", "outside", vertex=1), "ABCDE", "BD")
    'BD runs outside the polygon near B'
    >>> why_not_inner(CheckResult(False, "BC is an edge (adjacent vertices)", "adjacent"), "ABC", "BC")
    'BC is an edge (adjacent vertices)'
    """
    if verdict.code == "crosses" and verdict.edge is not None:
        return f"{claim} crosses edge {_edge(labels, verdict.edge)}"
    if verdict.code == "through-vertex" and verdict.vertex is not None:
        return f"{claim} passes through vertex {labels[verdict.vertex]}"
    if verdict.code == "outside" and verdict.vertex is not None:
        return f"{claim} runs outside the polygon near {labels[verdict.vertex]}"
    return str(verdict.why)
