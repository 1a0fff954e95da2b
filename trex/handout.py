"""The slides' handout: the last frame of every step with its caption, several to a page, as
one PDF.

Pillow draws the pages (A4 portrait at 150 dpi, two columns of four pictures) and writes
them as a multi-page PDF, each page one JPEG image; no other PDF library is needed, and
Pillow is already there (manim draws with it). The PDF carries no date, so the same frames
give the same bytes.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from PIL import Image, ImageDraw, ImageFont

PAGE = (1240, 1754)  # A4 at 150 dpi
DPI = 150
COLUMNS, ROWS = 2, 4
MARGIN, GAP = 70, 40
HEADER = 90  # the title and page number above the pictures
CAPTION_LINES = 3
FONT = Path("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf")  # fonts-dejavu-core
INK, IDLE, PAPER = (20, 24, 32), (110, 116, 128), (255, 255, 255)


@dataclass(frozen=True)
class Item:
    """One step on the handout: its picture, its number (``"7"``) and its caption."""

    picture: Image.Image
    number: str
    caption: str


def _font(size: int) -> ImageFont.ImageFont | ImageFont.FreeTypeFont:
    if FONT.is_file():
        return ImageFont.truetype(str(FONT), size)
    return ImageFont.load_default(size)


def wrap(text: str, font, width: float, lines: int = CAPTION_LINES) -> list[str]:
    """``text`` in at most ``lines`` lines no wider than ``width`` (the last one cut with …).

    >>> wrap("one two three four", _font(20), 1e9)
    ['one two three four']
    >>> len(wrap("word " * 100, _font(20), 300))
    3
    """
    out: list[str] = []
    for word in text.split():
        if out and font.getlength(f"{out[-1]} {word}") <= width:
            out[-1] = f"{out[-1]} {word}"
        else:
            out.append(word)
    if len(out) > lines:
        out = out[:lines]
        while out[-1] and font.getlength(out[-1] + " …") > width:
            out[-1] = out[-1].rsplit(" ", 1)[0] if " " in out[-1] else out[-1][:-1]
        out[-1] += " …"
    return out


def _layout() -> tuple[int, int]:
    cell_w = (PAGE[0] - 2 * MARGIN - (COLUMNS - 1) * GAP) // COLUMNS
    cell_h = (PAGE[1] - 2 * MARGIN - HEADER - (ROWS - 1) * GAP) // ROWS
    return cell_w, cell_h


def page(items: Sequence[Item], title: str, number: int, count: int) -> Image.Image:
    """Page ``number`` of ``count``: up to ``COLUMNS × ROWS`` steps under a header with the
    title and the page's number."""
    cell_w, cell_h = _layout()
    head, small, body = _font(30), _font(20), _font(21)
    line_h = 27
    drawn = Image.new("RGB", PAGE, PAPER)
    draw = ImageDraw.Draw(drawn)
    draw.text((MARGIN, MARGIN), wrap(title, head, PAGE[0] - 2 * MARGIN - 160, 1)[0],
              font=head, fill=INK)
    draw.text((PAGE[0] - MARGIN, MARGIN + 8), f"{number} / {count}", font=small, fill=IDLE,
              anchor="ra")
    for k, item in enumerate(items):
        x = MARGIN + (k % COLUMNS) * (cell_w + GAP)
        y = MARGIN + HEADER + (k // COLUMNS) * (cell_h + GAP)
        drawn.paste(item.picture, (x, y))
        draw.rectangle((x, y, x + item.picture.width - 1, y + item.picture.height - 1),
                       outline=IDLE)
        y += item.picture.height + 8
        label = f"{item.number}."
        draw.text((x, y), label, font=body, fill=IDLE)
        indent = round(body.getlength(label + " "))
        for line in wrap(item.caption, body, cell_w - indent):
            draw.text((x + indent, y), line, font=body, fill=INK)
            y += line_h
    return drawn


def picture_box(k: int) -> tuple[int, int, int]:
    """Where item ``k`` (from 0) of a page has its picture: ``(x, y, width)``."""
    cell_w, cell_h = _layout()
    k %= COLUMNS * ROWS
    return (MARGIN + (k % COLUMNS) * (cell_w + GAP),
            MARGIN + HEADER + (k // COLUMNS) * (cell_h + GAP), cell_w)


class Handout:
    """A handout written page by page (one page in memory at a time): :meth:`add` each
    step, then :meth:`close`. ``steps`` is how many there will be (for "page 2 / 5")."""

    def __init__(self, path: Path, title: str, steps: int,
                 notes: Sequence[tuple[str, Sequence[str]]] = ()) -> None:
        self.path, self.title = path, title
        self.notes = [(chapter, tuple(lines)) for chapter, lines in notes if lines]
        self.count = max(1, -(-steps // (COLUMNS * ROWS))) + (1 if self.notes else 0)
        self.items: list[Item] = []
        self.written = 0

    def add(self, picture: Image.Image, number: str, caption: str) -> None:
        """The step's picture (scaled to the cell now) and caption."""
        width = _layout()[0]
        shown = picture.convert("RGB")
        small = shown.resize((width, round(width * shown.height / shown.width)),
                             Image.Resampling.LANCZOS)
        self.items.append(Item(small, number, caption))
        if len(self.items) == COLUMNS * ROWS:
            self._flush()

    def close(self) -> Path:
        """The last page of steps, then the teacher's notes (a page of their own)."""
        if self.items or not self.written:
            self._flush()
        if self.notes:
            self._save(notes_page(self.notes, self.title, self.written + 1, self.count))
        return self.path

    def _save(self, drawn: Image.Image) -> None:
        options = {"append": True} if self.written else {
            "title": self.title, "creationDate": None, "modDate": None,
            "producer": "trex slides"}
        drawn.save(self.path, "PDF", resolution=DPI, quality=85, **options)
        self.written += 1

    def _flush(self) -> None:
        self._save(page(self.items, self.title, self.written + 1, self.count))
        self.items = []


def notes_page(notes: Sequence[tuple[str, Sequence[str]]], title: str, number: int,
               count: int) -> Image.Image:
    """The page of notes for the teacher: per chapter its lines (``"Topic: what to do"``),
    wrapped; what does not fit is cut with …."""
    head, small, body = _font(30), _font(20), _font(21)
    drawn = Image.new("RGB", PAGE, PAPER)
    draw = ImageDraw.Draw(drawn)
    draw.text((MARGIN, MARGIN), wrap(f"{title}: teacher notes", head,
                                     PAGE[0] - 2 * MARGIN - 160, 1)[0], font=head, fill=INK)
    draw.text((PAGE[0] - MARGIN, MARGIN + 8), f"{number} / {count}", font=small, fill=IDLE,
              anchor="ra")
    y, width, bottom = MARGIN + HEADER, PAGE[0] - 2 * MARGIN, PAGE[1] - MARGIN
    for chapter, lines in notes:
        if y + 60 > bottom:
            break
        draw.text((MARGIN, y), chapter, font=head, fill=INK)
        y += 50
        for line in lines:
            for row in wrap("• " + line, body, width):
                if y + 27 > bottom:
                    return drawn
                draw.text((MARGIN, y), row, font=body, fill=INK)
                y += 27
            y += 6
        y += 24
    return drawn
