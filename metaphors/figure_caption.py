"""A card figure's words, below its box: one place, one size and one way of breaking lines
for every figure (:mod:`metaphors.figures`, :mod:`metaphors.method_figures`,
:mod:`metaphors.figure_faster`), so that no figure's words sit lower, smaller or over it.

A caption is one or more lines, each in its own colour (what it says: green what holds,
ink the rest). A line too wide for the box wraps onto more rows at the same size, never
shrunk (each row at least 2.5 % of the frame's height), and the rows are centred under the
figure, the first one's top always :data:`GAP` below the box.

>>> from metaphors.theme import THEME
>>> caption = figure_caption(((-3.5, -0.1), 6.2, 4.6), THEME, ("one short line", THEME.ink))
>>> [row.original_text for row in caption], float(round(caption.get_top()[1], 6))
(['one short line'], -2.95)
"""

from __future__ import annotations

from manim import DOWN, UP, Mobject, VGroup, VMobject

from metaphors.tags import tag
from metaphors.theme import Theme
from rendering import typeset

Box = tuple[tuple[float, float], float, float]  # a figure's centre, width and height
Line = tuple[str, str]  # a caption line's words and their colour

#: the first row's top, this far below the figure's box: clear of the labels of its lowest
#: vertices (0.32 out, about 0.25 high), and of a word set beside a vertex
GAP = 0.55
#: between two rows
ROW_GAP = 0.12


def caption_size(theme: Theme) -> float:
    """The size every figure caption is set in: a step above the vertices' labels."""
    return theme.label_size + 2


def figure_caption(box: Box, theme: Theme, *lines: Line) -> Mobject:
    """The figure's words below ``box``: each of ``lines`` (words, colour) on as many rows
    as it needs, centred, tagged ``figure:label`` (a group of its rows, each a text)."""
    (x, y), width, height = box
    rows = [row for words, colour in lines for row in _rows(words, colour, width, theme)]
    caption = VGroup(*rows).arrange(DOWN, buff=ROW_GAP)
    caption.move_to((x, y - height / 2 - GAP, 0), aligned_edge=UP)
    return tag(caption, None, "figure:label")


def _rows(words: str, colour: str, width: float, theme: Theme) -> list[VMobject]:
    """``words`` on the rows they need at the caption's size: filled row by row, but two
    rows broken where they read best (near the middle, after a colon, comma or semicolon
    if one is close), as a subtitle is, both fitting unshrunk.

    >>> from metaphors.theme import THEME
    >>> said = "n = 13: 11 triangles, 10 inner diagonals"
    >>> [row.original_text for row in _rows(said, THEME.ink, 6.2, THEME)]
    ['n = 13: 11 triangles,', '10 inner diagonals']
    """
    font, size = theme.font, caption_size(theme)
    filled = typeset.wrapped(words, font=font, size=size, colour=colour, width=width)
    if not isinstance(filled, VGroup):
        return [filled]
    if len(filled) != 2:
        return list(filled)
    k = _best_break(words, width, font, size)
    return [typeset.text(part, font=font, size=size, colour=colour)
            for part in (words[:k], words[k + 1:])]


#: a break never falls beside one of these: ``n − 2`` stays on one row
_OPERATORS = frozenset("−+·×=")


def _best_break(words: str, width: float, font: str, size: float) -> int:
    """Where two rows of ``words`` read best: of the spaces both of whose sides fit
    ``width``, the one that makes the longer row shortest, a break after punctuation worth
    8 characters (as :func:`rendering.typeset.balanced`); the rows filled in (which fit)
    give one such space."""
    spaces = [k for k, c in enumerate(words) if c == " " and 0 < k < len(words) - 1
              and words[k - 1] not in _OPERATORS and words[k + 1] not in _OPERATORS]
    fitting = [k for k in spaces if typeset.natural_width(words[:k], font, size) <= width
               and typeset.natural_width(words[k + 1:], font, size) <= width]
    return min(fitting, key=lambda k: max(k, len(words) - k - 1) - 8 * (words[k - 1] in ":,;"))


__all__ = ["GAP", "ROW_GAP", "Box", "Line", "caption_size", "figure_caption"]
