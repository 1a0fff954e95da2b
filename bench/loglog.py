"""A small log-log line chart drawn with pycairo (installed with manim; no matplotlib needed).

>>> import tempfile, pathlib
>>> panel = Panel("demo", {"a": [(100, 0.01), (1000, 0.1)], "b": [(100, 0.02), (1000, 2.0)]})
>>> out = pathlib.Path(tempfile.mkdtemp()) / "demo.png"
>>> draw_panels([panel], out, columns=1)
>>> out.stat().st_size > 1000
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import cairo

# Colour-blind-friendly (Okabe–Ito, then greys), assigned to series in order of first use.
PALETTE = [
    (0.90, 0.62, 0.00), (0.34, 0.71, 0.91), (0.00, 0.62, 0.45), (0.94, 0.89, 0.26),
    (0.00, 0.45, 0.70), (0.84, 0.37, 0.00), (0.80, 0.47, 0.65), (0.0, 0.0, 0.0),
    (0.55, 0.55, 0.55), (0.55, 0.30, 0.10), (0.45, 0.25, 0.65), (0.20, 0.55, 0.20),
]
WIDTH, HEIGHT = 620, 440  # one panel
MARGIN = (70, 20, 40, 60)  # left, right, top, bottom of the plotting area


@dataclass
class Panel:
    """A title and named series of (n, seconds) points."""

    title: str
    series: dict[str, list[tuple[float, float]]]


def draw_panels(panels: list[Panel], path: Path, columns: int = 2) -> None:
    """Draw the panels in a grid with one shared legend below, and write a PNG."""
    names: list[str] = []
    for panel in panels:
        names += [name for name in panel.series if name not in names]
    colour = {name: PALETTE[k % len(PALETTE)] for k, name in enumerate(names)}
    rows = math.ceil(len(panels) / columns)
    legend_height = 24 * math.ceil(len(names) / 2) + 20
    surface = cairo.ImageSurface(cairo.FORMAT_ARGB32, WIDTH * columns, HEIGHT * rows + legend_height)
    ctx = cairo.Context(surface)
    ctx.set_source_rgb(1, 1, 1)
    ctx.paint()
    ctx.select_font_face("DejaVu Sans")
    for k, panel in enumerate(panels):
        ctx.save()
        ctx.translate(WIDTH * (k % columns), HEIGHT * (k // columns))
        _panel(ctx, panel, colour)
        ctx.restore()
    _legend(ctx, names, colour, HEIGHT * rows, WIDTH * columns)
    surface.write_to_png(str(path))


def _decades(values: list[float]) -> tuple[int, int]:
    return math.floor(math.log10(min(values))), math.ceil(math.log10(max(values)))


def _panel(ctx: cairo.Context, panel: Panel, colour: dict) -> None:
    points = [p for series in panel.series.values() for p in series]
    (x0, x1), (y0, y1) = _decades([p[0] for p in points]), _decades([p[1] for p in points])
    left, right, top, bottom = MARGIN
    w, h = WIDTH - left - right, HEIGHT - top - bottom

    def at(n: float, t: float) -> tuple[float, float]:
        fx = (math.log10(n) - x0) / max(x1 - x0, 1)
        fy = (math.log10(t) - y0) / max(y1 - y0, 1)
        return left + fx * w, top + (1 - fy) * h

    ctx.set_font_size(11)
    ctx.set_line_width(1)
    for e in range(y0, y1 + 1):  # horizontal grid and seconds labels
        _, y = at(10**x0, 10.0**e)
        ctx.set_source_rgb(0.88, 0.88, 0.88)
        ctx.move_to(left, y)
        ctx.line_to(left + w, y)
        ctx.stroke()
        ctx.set_source_rgb(0.2, 0.2, 0.2)
        ctx.move_to(8, y + 4)
        ctx.show_text(_seconds(10.0**e))
    for e in range(x0, x1 + 1):  # vertical grid and n labels
        x, _ = at(10.0**e, 10.0**y0)
        ctx.set_source_rgb(0.88, 0.88, 0.88)
        ctx.move_to(x, top)
        ctx.line_to(x, top + h)
        ctx.stroke()
        ctx.set_source_rgb(0.2, 0.2, 0.2)
        label = f"{10**e:,}"
        ctx.move_to(x - 3.2 * len(label), top + h + 18)
        ctx.show_text(label)
    ctx.set_font_size(14)
    ctx.move_to(left, top - 12)
    ctx.show_text(panel.title)
    ctx.set_font_size(11)
    ctx.move_to(left + w / 2 - 30, HEIGHT - 14)
    ctx.show_text("vertices n")
    for name, series in panel.series.items():
        ctx.set_source_rgb(*colour[name])
        ctx.set_line_width(2.2)
        for k, (n, t) in enumerate(sorted(series)):
            x, y = at(n, t)
            ctx.line_to(x, y) if k else ctx.move_to(x, y)
        ctx.stroke()
        for n, t in series:
            x, y = at(n, t)
            ctx.arc(x, y, 3.2, 0, 2 * math.pi)
            ctx.fill()


def _seconds(t: float) -> str:
    if t >= 1:
        return f"{t:g} s"
    if t >= 1e-3:
        return f"{t * 1e3:g} ms"
    return f"{t * 1e6:g} µs"


def _legend(ctx: cairo.Context, names: list[str], colour: dict, y0: float, width: float) -> None:
    ctx.set_font_size(12)
    for k, name in enumerate(names):
        x = 20 + (k % 2) * width / 2
        y = y0 + 16 + 24 * (k // 2)
        ctx.set_source_rgb(*colour[name])
        ctx.rectangle(x, y - 9, 22, 8)
        ctx.fill()
        ctx.set_source_rgb(0.1, 0.1, 0.1)
        ctx.move_to(x + 30, y)
        ctx.show_text(name)
