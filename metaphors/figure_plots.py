"""A line plot of counts against n, drawn in a card's figure box: one for every plot.

The cards plot what runs measured (:mod:`metaphors.figures`' ear tests, the sign tests of
:mod:`metaphors.figure_faster`), never a bound passed off as a measurement: a series
``dashed`` is a bound, and its legend says so. Axes are linear from 0, or logarithmic
(``log``) from the first size and the decade below the least count; the plot gives its
mobjects and the point on screen of any ``(n, count)``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from manim import (
    DOWN,
    LEFT,
    DashedVMobject,
    Dot,
    Line,
    ManimColor,
    Mobject,
    Square,
    Triangle,
    VMobject,
)

from metaphors.tags import tag
from metaphors.theme import Theme
from rendering import typeset

Point3 = tuple[float, float, float]


@dataclass(frozen=True)
class Series:
    """One line of a plot: its ``counts`` at the plot's sizes, its mobject's ``name``, its
    colour; ``dashed``: a bound drawn for comparison, not a measurement."""

    name: str
    counts: tuple[float, ...]
    colour: str
    dashed: bool = False
    #: the mark at each count (one of :data:`MARKS`), or none: two lines that run together
    #: are told apart by their marks (faster ear clipping and monotone partition, from n = 40)
    mark: str | None = None
    #: a hollow mark filled in its colour: the same algorithm on another kind of polygon
    filled: bool = False


@dataclass(frozen=True)
class Area:
    """Where the axes go: their corner (``left``, ``bottom``) and their lengths."""

    left: float
    bottom: float
    width: float
    height: float


#: the marks a line's counts may wear: a filled dot, a hollow square, a hollow triangle
MARKS = ("dot", "square", "triangle")


def point_mark(kind: str, colour: str, at: Point3, theme: Theme, filled: bool = False) -> Mobject:
    """One of :data:`MARKS` at ``at`` in ``colour`` (the plot's and its legend's); a hollow
    one ``filled`` in its colour."""
    if kind == "dot":
        shape: Mobject = Dot(radius=0.07, color=colour)
    elif kind == "square":
        shape = Square(side_length=0.15, color=colour, stroke_width=theme.thin_stroke * 1.5)
    elif kind == "triangle":
        shape = Triangle(color=colour, stroke_width=theme.thin_stroke * 1.5).scale(0.1)
    else:
        raise ValueError(f"unknown mark {kind!r}; expected one of {', '.join(MARKS)}")
    # hollow marks are filled with the background's dark: a line does not run through them
    if kind != "dot":
        shape.set_fill(colour if filled else theme.background, opacity=1.0)
    return shape.move_to(at)


def _tick(words: str, theme: Theme, colour: str | None = None) -> Mobject:
    return typeset.text(words, font=theme.font, size=theme.label_size,
                        colour=colour or theme.idle)


def spoken_count(count: float) -> str:
    """A count as a tick says it: thousands apart by a space (``10 000``).

    >>> spoken_count(100), spoken_count(10000)
    ('100', '10 000')
    """
    return f"{round(count):,}".replace(",", " ")


def line_plot(sizes: Sequence[int], series: Sequence[Series], area: Area, theme: Theme, *,
              log: bool = False, ticks: str | None = None
              ) -> tuple[list[Mobject], Callable[[float, float], Point3]]:
    """The axes, their ticks and one line per series (back to front), and ``at(n, count)``,
    the point on screen of a count; ``ticks``: the ticks' colour (the idle grey unless
    given: the ink reads better on a card's dark). Linear: the first and last size ticked, and the top
    count. Logarithmic: every size ticked, and every power of ten above the least count's
    decade up to the top count."""
    top = max(max(s.counts) for s in series)
    a = area
    if log:
        low = 10.0 ** math.floor(math.log10(min(min(s.counts) for s in series)))
        first, span_n, span_c = sizes[0], math.log(sizes[-1] / sizes[0]), math.log(top / low)

        def at(n: float, count: float) -> Point3:
            return (a.left + a.width * math.log(n / first) / span_n,
                    a.bottom + a.height * math.log(count / low) / span_c, 0.0)

        corner, ticked = (first, low), list(sizes)
        # the powers of ten above the corner (the corner's would sit on the first size's tick)
        marks = [10.0 ** k for k in range(round(math.log10(low)) + 1,
                                          math.floor(math.log10(top)) + 1)]
    else:
        def at(n: float, count: float) -> Point3:
            return (a.left + a.width * n / sizes[-1], a.bottom + a.height * count / top, 0.0)

        corner, ticked, marks = (0, 0), [sizes[0], sizes[-1]], [top]
    axes = [tag(Line(at(*corner), at(sizes[-1], corner[1]), color=theme.idle,
                     stroke_width=theme.thin_stroke), None, "figure:axis"),
            tag(Line(at(*corner), at(corner[0], top), color=theme.idle,
                     stroke_width=theme.thin_stroke), None, "figure:axis")]
    words = [tag(_tick(str(n), theme, ticks).next_to(at(n, corner[1]), direction=DOWN, buff=0.12),
                 None, "figure:tick") for n in ticked]
    words += [tag(_tick(spoken_count(c), theme, ticks).next_to(at(corner[0], c), direction=LEFT,
                                                        buff=0.12), None, "figure:tick")
              for c in marks]
    lines: list[Mobject] = []
    for s in series:
        line = VMobject(color=s.colour, stroke_width=theme.stroke).set_points_as_corners(
            [at(n, c) for n, c in zip(sizes, s.counts, strict=True)])
        if s.dashed:
            line = DashedVMobject(line, num_dashes=24, color=ManimColor(s.colour))
        lines.append(tag(line, None, s.name))
        if s.mark is not None:
            lines += [tag(point_mark(s.mark, s.colour, at(n, c), theme, s.filled), None,
                          "figure:point")
                      for n, c in zip(sizes, s.counts, strict=True)]
    return [*axes, *lines, *words], at


def axis_names(area: Area, across: str, up: str, theme: Theme) -> list[Mobject]:
    """The axes' names in plain words: ``across`` under the size ticks, centred on the x
    axis; ``up`` (a line or more) over the y axis, its left at the count ticks' (a reader
    asked what the numbers count)."""
    x_name = typeset.text(across, font=theme.font, size=theme.label_size, colour=theme.ink)
    x_name.move_to((area.left + area.width / 2, area.bottom - 0.62, 0))
    y_name = typeset.text(up, font=theme.font, size=theme.label_size, colour=theme.ink)
    y_name.move_to((area.left - 0.9 + y_name.width / 2,
                    area.bottom + area.height + 0.15 + y_name.height / 2, 0))
    return [tag(x_name, None, "figure:x-name"), tag(y_name, None, "figure:y-name")]


__all__ = ["MARKS", "Area", "Series", "axis_names", "line_plot", "point_mark", "spoken_count"]
