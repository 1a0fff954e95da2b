"""Text for the scenes: manim's ``Text``, typeset faster and drawn as one path.

A ``Text`` is a group of glyphs, one ``VMobject`` each, and that is what makes a text-heavy scene
slow: every play deep-copies the glyphs of every text it animates (a panel row, a caption),
every frame draws each glyph as its own Cairo path, and manim's cache hashes them one by one.
:class:`FlatText` holds the same outline — the same points, in the same order — in one
``VMobject``, so a copy is one array copy and a frame draws one path per text. Its glyph
subpaths stay apart (the pen lifts between glyphs), so it fills as the glyphs did.

Typesetting is the other cost. ``Text`` asks Pango for an SVG (under a millisecond) and then
parses the whole SVG with svgelements (tens of milliseconds). :func:`outline` asks Pango for the
same SVG, reads where each glyph goes with the standard library's XML parser, and converts each
distinct glyph outline once per process, reading Cairo's plain path data with manim's own
arithmetic (:func:`_cairo_path`; any other path goes to manim's reader); the text's outline is
those glyphs moved into place, with the transform ``Text`` applies (y flipped, centred, scaled
to manim units). ``tests/test_typeset.py`` checks it point for point against ``Text``. An
SVG with anything but glyphs placed by ``<use>`` is read by ``Text`` itself.

>>> a = text("B", size=22, colour="#e8ecf2")
>>> b = text("B", size=22, colour="#4cc46b")
>>> a.original_text, a.get_fill_color().to_hex(), b.get_fill_color().to_hex()
('B', '#E8ECF2', '#4CC46B')
>>> bool((a.points == b.points).all()) and a.points is not b.points
True
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import tempfile
import xml.etree.ElementTree as ET
from functools import lru_cache

import manimpango
import numpy as np
import svgelements as se
from manim import DOWN, NORMAL, ORIGIN, RIGHT, UP, Text, VGroup, VMobject, config
from manim.constants import START_X, START_Y
from manim.mobject.svg.svg_mobject import VMobjectFromSVGPath
from manim.mobject.text.text_mobject import (
    DEFAULT_LINE_SPACING_SCALE,
    TEXT2SVG_ADJUSTMENT_FACTOR,
    TEXT_MOB_SCALE_FACTOR,
)

#: the face and colour of a text when the caller names none (the theme's own defaults)
DEFAULT_FONT = "DejaVu Sans"
DEFAULT_INK = "#e8ecf2"


_SVG = "{http://www.w3.org/2000/svg}"
_HREF = "{http://www.w3.org/1999/xlink}href"


class Lettered:
    """A text that knows how tall its letters stand, as drawn: what a viewer reads its size by
    (not its box, which holds descenders, and for several lines the gaps between them).
    :func:`text` and :func:`glyphs` measure it as they typeset (:func:`letter_height`)."""

    #: its letters' height and its ink's height as typeset (0: not measured)
    set_letters = 0.0
    set_height = 0.0
    height: float  # the ink's height now (manim's Mobject)

    def cap_height(self) -> float | None:
        """Its letters' height now: as typeset, scaled with the text since (None: not
        measured). The scene graph writes it (``cap``, docs/scene-graph.md)."""
        if self.set_height <= 0:
            return None
        return self.set_letters * self.height / self.set_height


class FlatText(Lettered, VMobject):
    """A line of text as one ``VMobject``: the outline of manim's ``Text`` with its glyphs
    merged into one path. ``original_text`` is the string (scene-graph snapshots read it)."""

    def __init__(self, original_text: str, points: np.ndarray, **kwargs):
        kwargs.setdefault("fill_opacity", 1.0)
        kwargs.setdefault("stroke_width", 0)
        super().__init__(**kwargs)
        self.original_text = original_text
        if len(points):
            self.set_points(points)


class GlyphText(Lettered, VGroup):
    """A line of text as a group of glyphs, as manim's ``Text`` is, so that ``Write`` writes
    it glyph after glyph. For the few texts that are written (titles); the same outline as
    :class:`FlatText`, cut where one glyph ends and the next begins."""

    def __init__(self, original_text: str, points: np.ndarray, ends: tuple[int, ...],
                 colour: str):
        glyphs = [VMobject(fill_color=colour, fill_opacity=1.0, stroke_width=0)
                  .set_points(points[start:end])
                  for start, end in zip((0, *ends[:-1]), ends, strict=True) if end > start]
        super().__init__(*glyphs)
        self.original_text = original_text


def text(string: str, *, size: float, colour: str | None = None, font: str = DEFAULT_FONT,
         slant: str = NORMAL, weight: str = NORMAL, width: float | None = None) -> FlatText:
    """A :class:`FlatText` of ``string`` in ``font`` at ``size`` (manim's ``font_size``), filled
    with ``colour`` (default: the theme's ink); shrunk to ``width`` if it is wider."""
    points = outline(string, font, float(size), slant, weight)
    flat = _measured(FlatText(string, points.copy(), color=colour or DEFAULT_INK),
                     font, float(size), slant, weight)
    return _fit(flat, width)


def glyphs(string: str, *, size: float, colour: str | None = None, font: str = DEFAULT_FONT,
           slant: str = NORMAL, weight: str = NORMAL, width: float | None = None) -> GlyphText:
    """A :class:`GlyphText` of ``string``: for text that is written with ``Write``."""
    points, ends, _ = _typeset(string, font, float(size), slant, weight)
    written = _measured(GlyphText(string, points.copy(), ends, colour or DEFAULT_INK),
                        font, float(size), slant, weight)
    return _fit(written, width)


def _measured(mobject, font: str, size: float, slant: str, weight: str):
    """The text, told its letters' height and its ink's height as typeset."""
    mobject.set_letters = letter_height(mobject.original_text, font, size, slant, weight)
    mobject.set_height = mobject.height if mobject.has_points() or mobject.submobjects else 0.0
    return mobject


#: the letter whose height is a font's capitals' height
CAPITAL = "H"


def letter_height(string: str, font: str = DEFAULT_FONT, size: float = 48.0,
                  slant: str = NORMAL, weight: str = NORMAL) -> float:
    """How tall the letters of ``string`` stand, set in ``font`` at ``size``: the height of
    its ink above the baseline, no more than a capital's (:data:`CAPITAL`: an ``f`` or a
    bracket reaching above the capitals does not make a text read larger). Its capitals'
    height, then, or its tallest glyphs' where they are shorter (``a₂``, ``ears``: the
    x-height; a ``✓``, which stands off the baseline: its own). A text of several lines: its
    shortest line's. What a viewer reads its size by: no descenders, no gaps between lines.

    >>> capital = letter_height("H", size=20)
    >>> letter_height("B = the left-most vertex (lowest on ties)", size=20) == capital
    True
    >>> round(letter_height("a₂", size=26) / letter_height("A", size=26), 2)  # the x-height
    0.77
    >>> letter_height("n − 2 = 13 − 2\\n= 11 triangles", size=26) == letter_height("H", size=26)
    True
    """
    capital = _above_baseline(CAPITAL, font, size, slant, weight) or 0.0
    heights = [_above_baseline(line, font, size, slant, weight)
               for line in string.split("\n") if line.strip()]
    return min([capital, *(h for h in heights if h is not None)])


def _above_baseline(line: str, font: str, size: float, slant: str, weight: str) -> float | None:
    """The height of the part of one line's ink above its baseline (None: a line typeset by
    ``Text``, whose baseline this module does not read)."""
    points, _, baseline = _typeset(line, font, size, slant, weight)
    if baseline is None or not len(points):
        return None
    ys = points[:, 1]
    return float(ys.max() - max(baseline, ys.min()))


_OPERATORS = frozenset("−+·×=")


def _unbreakable(words: list[str]) -> list[str]:
    """The words, an operator glued to its neighbours: ``["n", "−", "2"]`` → ``["n − 2"]``."""
    out: list[str] = []
    glue = False
    for word in words:
        if out and (glue or word in _OPERATORS):
            out[-1] = f"{out[-1]} {word}"
        else:
            out.append(word)
        glue = word in _OPERATORS
    return out


def wrapped(string: str, *, size: float, width: float, colour: str | None = None,
            font: str = DEFAULT_FONT, gap: float = 0.1) -> FlatText | VGroup:
    """``string`` in as many lines as it needs to fit ``width`` at ``size`` (broken at
    spaces, left-aligned), each line a :class:`FlatText` (one line: that text alone): a long
    text wraps instead of shrinking below its size. Only a word wider than ``width`` on its
    own is shrunk.

    >>> group = wrapped("nearest_to(B, [D, E]) → D", size=20, width=2.5)
    >>> [line.original_text for line in group]
    ['nearest_to(B, [D,', 'E]) → D']

    A formula's short operands stay on one line (``n − 2`` is never broken):

    >>> [line.original_text for line in wrapped("so n − 2 triangles", size=20, width=0.9)]
    ['so', 'n − 2', 'triangles']
    """
    lines: list[str] = []
    for word in _unbreakable(string.split(" ")):
        trial = f"{lines[-1]} {word}" if lines else word
        if lines and natural_width(trial, font, size) <= width:
            lines[-1] = trial
        else:
            lines.append(word)
    parts = [text(line, size=size, colour=colour, font=font, width=width) for line in lines]
    if len(parts) == 1:
        return parts[0]
    return _by_baselines(parts, font, size, gap)


#: a line with a capital's height and a descender: the ink a line's pitch is measured by
_TALL_AND_DEEP = "Hg"


def _by_baselines(parts: list[FlatText], font: str, size: float, gap: float) -> VGroup:
    """Lines left-aligned, their baselines one pitch apart (the ink of ``Hg`` and ``gap``):
    arranged by their ink, a line with no descender ("Answer: E — the") stood nearer the
    next than the others did (2 px at 480p), and the lines read unevenly spaced."""
    pitch = text(_TALL_AND_DEEP, size=size, font=font).height + gap
    left, top = parts[0].get_left()[0], parts[0].get_top()[1]
    first = None
    for k, part in enumerate(parts):
        above = _above_baseline(part.original_text, font, size, NORMAL, NORMAL)
        scale = part.height / part.set_height if part.set_height > 0 else 1.0
        if above is None:  # typeset by Text: no baseline read, its ink's top stands for it
            above = 0.0
        rise = above * scale  # from the baseline to the ink's top
        if first is None:
            first = top - rise  # the first line's baseline, where the first line stands
        part.shift((left - part.get_left()[0]) * RIGHT
                   + (first - k * pitch + rise - part.get_top()[1]) * UP)
    return VGroup(*parts)


def balanced(string: str, *, size: float, width: float, colour: str | None = None,
             font: str = DEFAULT_FONT, gap: float = 0.1, aligned_edge=ORIGIN,
             lead: str = "") -> FlatText | VGroup:
    """``lead + string`` on one line, or on two lines (centred, or aligned by
    ``aligned_edge``) when one would not fit ``width`` at ``size``: ``string`` broken near
    the middle (after a colon, comma or full stop if one is close), the way a subtitle reads,
    ``lead`` (a bullet) before the first. Only a line that does
    not fit even so is shrunk.

    >>> balanced("the ball falls", size=28, width=13.4).original_text
    'the ball falls'
    >>> caption = "V is reflex: its sides point up, so the band snags at Y"
    >>> [line.original_text for line in balanced(caption, size=28, width=6)]
    ['V is reflex: its sides point up,', 'so the band snags at Y']
    >>> [line.original_text for line in balanced("Ears: slice one at a time", size=28, width=4,
    ...                                         lead="• ")]
    ['• Ears:', 'slice one at a time']
    """
    string = string.strip()
    spaces = [k for k, c in enumerate(string) if c == " " and string[k - 1] != " "]
    if not spaces or natural_width(lead + string, font, size) <= width:
        return text(lead + string, size=size, colour=colour, font=font, width=width)
    # the longer line as short as can be, a break after punctuation worth 8 characters
    k = min(spaces, key=lambda k: max(k, len(string) - k - 1) - 8 * (string[k - 1] in ":,.;"))
    lines = [text(part, size=size, colour=colour, font=font, width=width)
             for part in (lead + string[:k], string[k + 1:].lstrip())]
    return VGroup(*lines).arrange(DOWN, buff=gap, aligned_edge=aligned_edge)


def natural_width(string: str, font: str, size: float) -> float:
    """The width of the ink of ``string`` set in ``font`` at ``size``, not shrunk."""
    points = outline(string, font, float(size))
    return float(np.ptp(points[:, 0])) if len(points) else 0.0


def _fit(mobject, width: float | None):
    if width is not None and mobject.width > width:
        mobject.scale_to_fit_width(width)
    return mobject


def outline(string: str, font: str, size: float, slant: str = NORMAL,
            weight: str = NORMAL) -> np.ndarray:
    """The points of ``Text(string, font=font, font_size=size, …)``, its glyphs one after
    another, centred at the origin as ``Text`` centres itself (read only: :func:`text` copies
    it). One line of text: a newline or a tab is typeset by ``Text``."""
    return _typeset(string, font, size, slant, weight)[0]


def _typeset(string: str, font: str, size: float, slant: str,
             weight: str) -> tuple[np.ndarray, tuple[int, ...], float | None]:
    """:func:`_layout` at the pixel size of the current configuration."""
    return _layout(string, font, size, slant, weight, config["pixel_width"],
                   config["pixel_height"])


def forget() -> None:
    """Empty the caches of this process (typeset strings, converted glyphs), so that the next
    text is typeset from scratch, as in a fresh process: for benchmarks."""
    _layout.cache_clear()
    _glyph.cache_clear()


@lru_cache(maxsize=4096)
def _layout(string: str, font: str, size: float, slant: str, weight: str, width: int,
            height: int) -> tuple[np.ndarray, tuple[int, ...], float | None]:
    """(points, ends, baseline): the outline, the index where each glyph's points end, and the
    height of the baseline in the outline's units (None: typeset by ``Text``, which does not
    say). ``width`` and ``height`` are the pixel size Pango lays the text out in (it wraps at
    the width)."""
    placed = None
    if "\n" not in string and "\t" not in string:
        placed = _placed_glyphs(_svg(string, font, size, slant, weight, width, height))
    baseline: float | None = None
    if placed is None:
        points, ends = _from_text(string, font, size, slant, weight)
    else:
        points, ends, baseline = _compose(placed)
    points.setflags(write=False)
    return points, ends, baseline


# --- the fast path: Pango's SVG, glyphs read once ---------------------------------------------------


def _svg(string: str, font: str, size: float, slant: str, weight: str, width: int,
         height: int):
    """The root element of Pango's SVG of the string, as ``Text`` asks for it. Kept in manim's
    text directory; written under a name of its own and then renamed into place, so that
    several processes sharing a media directory never read a half-written file, and a file
    that does not parse (say, cut short by a crash) is written again."""
    folder = config.get_dir("text_dir")
    folder.mkdir(parents=True, exist_ok=True)
    key = repr((string, font, size, slant, weight, width, height, manimpango.__version__))
    path = folder / f"trex-{hashlib.sha256(key.encode()).hexdigest()[:20]}.svg"
    if path.exists():
        with contextlib.suppress(ET.ParseError, OSError):
            return ET.parse(path).getroot()
    handle, scratch = tempfile.mkstemp(prefix=".trex-", suffix=".svg", dir=folder)
    os.close(handle)
    try:
        spacing = (size + size * DEFAULT_LINE_SPACING_SCALE) / TEXT2SVG_ADJUSTMENT_FACTOR
        setting = manimpango.TextSetting(0, len(string), font, slant, weight, line_num=0,
                                         color="#FFFFFF")
        manimpango.text2svg([setting], size / TEXT2SVG_ADJUSTMENT_FACTOR, spacing, False,
                            scratch, START_X, START_Y, width, height, string)
        # (Text also deletes each path's last, empty "M x y"; a move draws nothing, so the
        # readers below give the same points with it: one write of the file saved)
        root = ET.parse(scratch).getroot()
        os.replace(scratch, path)
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(scratch)
    return root


def _placed_glyphs(root) -> list[tuple[str, float, float]] | None:
    """[(glyph outline, x, y)] in document order; None when the SVG holds anything else, or a
    transform, that this reader does not follow. (Like ``Text``, it ignores the root's size and
    viewBox: manim re-roots the SVG before parsing it.)"""
    glyphs: dict[str, str] = {}
    uses: list[tuple[str, float, float]] = []
    paths = 0
    for element in root.iter():
        tag = element.tag.removeprefix(_SVG)
        if tag not in ("svg", "defs", "g", "symbol", "path", "use") or "transform" in element.attrib:
            return None
        if tag == "path":
            paths += 1
        elif tag == "use":
            uses.append((element.get(_HREF, "").removeprefix("#"),
                         float(element.get("x", 0)), float(element.get("y", 0))))
        elif tag in ("symbol", "g") and element.get("id"):
            inner = element.findall(f"{_SVG}path")
            if len(inner) == 1 and len(element) == 1 and inner[0].get("d") is not None:
                glyphs[element.get("id")] = inner[0].get("d")
    if any(href not in glyphs for href, _, _ in uses):
        return None
    if paths != len(glyphs):
        return None  # a path outside the glyph definitions
    return [(glyphs[href], x, y) for href, x, y in uses]


@lru_cache(maxsize=4096)
def _glyph(d: str) -> np.ndarray:
    """One glyph's outline in SVG units at its origin, as ``Text`` keeps it: manim's SVG path
    reader, then every open subpath closed with a straight line."""
    points = _cairo_path(d)
    if points is None:  # not the plain path Cairo writes: manim's reader
        points = VMobjectFromSVGPath(se.Path(d)).points
    points = _closed(points) if len(points) else points
    points.setflags(write=False)
    return points


def _cairo_path(d: str) -> np.ndarray | None:
    """The points manim's SVG path reader (``VMobjectFromSVGPath``) makes of a path written by
    Cairo — absolute ``M``, ``L``, ``C`` and ``Z``, each command followed by its numbers — with
    the same arithmetic, without parsing it into svgelements objects first; None for any
    other path data.

    >>> _cairo_path("M 0 0 L 3 0 C 3 1 2 2 0 2 Z").reshape(-1, 4, 3)[:, :, :2].tolist()[0]
    [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]
    >>> _cairo_path("M 0 0 l 3 0") is None  # relative: not Cairo's
    True
    >>> _cairo_path("M 0 0 L nan 1") is None  # float() reads more than SVG numbers
    True
    """
    if any(c in d for c in "_nNiI"):  # nan, inf, 1_0: numbers float() takes and SVG does not
        return None
    tokens = d.split()
    rows: list[list[float]] = []
    pen = start = None  # manim's last_move and last_true_move

    def line(a: list[float], b: list[float]) -> None:
        rows.extend((a, [(a[0] + a[0] + b[0]) / 3, (a[1] + a[1] + b[1]) / 3, 0.0],
                     [(a[0] + b[0] + b[0]) / 3, (a[1] + b[1] + b[1]) / 3, 0.0], b))

    k = 0
    try:
        while k < len(tokens):
            command, k = tokens[k], k + 1
            if command == "M":
                pen = start = [float(tokens[k]), float(tokens[k + 1]), 0.0]
                k += 2
            elif command == "L" and pen is not None:
                end = [float(tokens[k]), float(tokens[k + 1]), 0.0]
                line(pen, end)
                pen, k = end, k + 2
            elif command == "C" and pen is not None:
                c1, c2, end = ([float(tokens[j]), float(tokens[j + 1]), 0.0]
                               for j in range(k, k + 6, 2))
                rows.extend((pen, c1, c2, end))
                pen, k = end, k + 6
            elif command == "Z" and pen is not None and start is not None:  # (set together)
                if np.linalg.norm(np.subtract(pen, start)) > 0.0001:  # as manim decides it
                    line(pen, start)
                    pen = start
                if k < len(tokens) and tokens[k] != "M":
                    return None  # drawing on from a closed subpath: leave it to svgelements
            else:
                return None
    except (IndexError, ValueError):
        return None
    return np.array(rows, dtype=float).reshape(-1, 3)


def _closed(points: np.ndarray) -> np.ndarray:
    """``Text``'s closing of a glyph: where a curve ends away from the next curve's start, and
    after the last curve, a line back to the start of the current subpath."""
    curves = points.reshape(-1, 4, 3)
    out, start = [], curves[0, 0]
    for k, curve in enumerate(curves):
        out.append(curve)
        last = k == len(curves) - 1
        if last or (curve[3] != curves[k + 1, 0]).any():
            end = curve[3]
            out.append(np.array([end, (end + end + start) / 3, (end + start + start) / 3, start]))
            if not last:
                start = curves[k + 1, 0]
    return np.concatenate(out)


def _compose(glyphs: list[tuple[str, float, float]]
             ) -> tuple[np.ndarray, tuple[int, ...], float | None]:
    """The glyphs moved into place, then ``Text``'s transform: y up, centred, scaled to manim
    units; where each glyph's points end; and the line's baseline, transformed alike (a glyph
    is placed by its origin, on the baseline: one line's glyphs share its height)."""
    points, ends = _joined([_glyph(d) + np.array([x, y, 0.0]) for d, x, y in glyphs])
    if not ends:
        return points, ends, None
    points = points * (1.0, -1.0, 0.0)
    centre = (points.min(axis=0) + points.max(axis=0)) / 2
    baseline = (-glyphs[0][2] - centre[1]) * TEXT_MOB_SCALE_FACTOR
    return (points - centre) * TEXT_MOB_SCALE_FACTOR, ends, float(baseline)


def _from_text(string: str, font: str, size: float, slant: str, weight: str
               ) -> tuple[np.ndarray, tuple[int, ...]]:
    """The slow path: manim's ``Text``, its glyphs' points one after another."""
    typeset = Text(string, font=font, font_size=size, slant=slant, weight=weight)
    return _joined([g.points for g in typeset.family_members_with_points()])


def _joined(parts: list[np.ndarray]) -> tuple[np.ndarray, tuple[int, ...]]:
    """The glyphs' points one after another, and the index where each glyph's points end
    (glyphs without points, such as spaces, left out)."""
    parts = [p for p in parts if len(p)]
    if not parts:
        return np.zeros((0, 3)), ()
    return np.concatenate(parts), tuple(int(n) for n in np.cumsum([len(p) for p in parts]))
