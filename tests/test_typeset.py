"""rendering.typeset: the fast typesetting gives manim's ``Text`` outline, point for point, and
one merged path draws the same picture as the glyphs did."""

from __future__ import annotations

import itertools
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
import svgelements as se
from hypothesis import given, settings
from hypothesis import strategies as st
from manim import BOLD, ITALIC, NORMAL, Text, Write, config, tempconfig
from manim.camera.camera import Camera
from manim.mobject.svg.svg_mobject import VMobjectFromSVGPath

from rendering import typeset
from rendering.typeset import FlatText, GlyphText, glyphs, text

SANS, MONO = "DejaVu Sans", "DejaVu Sans Mono"
ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(autouse=True)
def _media(tmp_path):
    with tempconfig({"media_dir": str(tmp_path / "media"), "quality": "low_quality"}):
        yield


def manim_points(string: str, font: str, size: float, slant=NORMAL, weight=NORMAL) -> np.ndarray:
    """What ``Text`` builds, its glyphs' points one after another."""
    glyphs = Text(string, font=font, font_size=size, slant=slant, weight=weight)
    parts = [g.points for g in glyphs.family_members_with_points()]
    return np.concatenate(parts) if parts else np.zeros((0, 3))


def fast_points(string: str, font: str, size: float, slant=NORMAL, weight=NORMAL) -> np.ndarray:
    """The fast path alone (no fallback to ``Text``)."""
    root = typeset._svg(string, font, size, slant, weight, config["pixel_width"],
                        config["pixel_height"])
    placed = typeset._placed_glyphs(root)
    assert placed is not None, f"the fast path gave up on {string!r}"
    return typeset._compose(placed)[0]


def assert_same_outline(string, font, size, slant=NORMAL, weight=NORMAL):
    expected = manim_points(string, font, size, slant, weight)
    got = fast_points(string, font, size, slant, weight)
    assert got.shape == expected.shape, string
    if len(expected):
        # the same numbers up to rounding (Text flips y by a rotation, leaving z ≈ 1e-17)
        assert np.abs(got - expected).max() < 1e-9, string


@pytest.mark.parametrize(("string", "font", "size"), [
    ("B", SANS, 22),
    ("nearest_to(B, [D, E]) → E", MONO, 20),
    ("    while todo:", MONO, 11),
    ("The ball slides down to X; the band snags Y.", SANS, 26),
    ("fi fl ffi AV To Wa", SANS, 30),  # ligatures and kerning: Pango's, as Text has them
    ("✓", SANS, 48),
    ("✗", SANS, 48),
    ("3 / 7 slices", SANS, 22),
    ("Ünïcödé — ½ ≤ ∞", SANS, 24),
    ("a  b", SANS, 26),  # two spaces
    (" ", SANS, 26),  # nothing drawn
])
def test_outline_is_texts_outline(string, font, size):
    assert_same_outline(string, font, float(size))


@pytest.mark.parametrize(("slant", "weight"), [(ITALIC, NORMAL), (NORMAL, BOLD), (ITALIC, BOLD)])
def test_slant_and_weight(slant, weight):
    assert_same_outline("g = 9.81 m/s²", SANS, 26.0, slant, weight)


@settings(max_examples=25)
@given(st.text(st.characters(codec="latin-1", categories=("L", "N", "P", "S", "Zs")),
               min_size=1, max_size=24),
       st.sampled_from([SANS, MONO]), st.sampled_from([11.0, 15.0, 22.0, 26.0, 48.0]))
def test_outline_is_texts_outline_for_any_line(string, font, size):
    assert_same_outline(string, font, size)


def test_text_falls_back_to_manim_for_several_lines():
    got = typeset.outline("two\nlines", SANS, 20.0)
    assert np.array_equal(got, manim_points("two\nlines", SANS, 20.0))


def test_anything_but_placed_glyphs_is_left_to_text(tmp_path):
    glyph = ('<symbol id="glyph0-1"><path d="M 0 0 L 1 0 L 1 -1 Z"/></symbol>')
    head = ('<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">'
            f"<defs><g>{glyph}</g></defs>")
    cases = {
        "plain": '<g><use xlink:href="#glyph0-1" x="3" y="4"/></g>',
        "rect": '<g><use xlink:href="#glyph0-1" x="3" y="4"/><rect width="1" height="1"/></g>',
        "transform": '<g transform="scale(2)"><use xlink:href="#glyph0-1" x="3" y="4"/></g>',
        "loose path": '<g><use xlink:href="#glyph0-1" x="3" y="4"/><path d="M 0 0 L 2 2"/></g>',
        "unknown glyph": '<g><use xlink:href="#glyph9-9" x="3" y="4"/></g>',
    }
    read = {}
    for name, body in cases.items():
        path = tmp_path / f"{name}.svg"
        path.write_text(head + body + "</svg>")
        read[name] = typeset._placed_glyphs(ET.parse(path).getroot())
    assert read.pop("plain") == [("M 0 0 L 1 0 L 1 -1 Z", 3.0, 4.0)]
    assert read == dict.fromkeys(read)  # every other one: None


def test_open_subpaths_are_closed_as_text_closes_them():
    # a square drawn as an open path of three lines: Text adds the fourth, back to the start
    closed = typeset._glyph("M 0 0 L 1 0 L 1 1 L 0 1")
    anchors = closed.reshape(-1, 4, 3)[:, [0, 3], :2]
    assert anchors.tolist() == [[[0, 0], [1, 0]], [[1, 0], [1, 1]], [[1, 1], [0, 1]],
                                [[0, 1], [0, 0]]]


def manims_reader(d: str) -> np.ndarray:
    return VMobjectFromSVGPath(se.Path(d)).points


@pytest.mark.parametrize(("font", "slant", "weight"), [(SANS, NORMAL, NORMAL), (MONO, NORMAL, NORMAL),
                                                       (SANS, ITALIC, BOLD)])
def test_cairo_paths_read_as_manim_reads_them(font, slant, weight):
    """Every glyph of Latin-1 and the symbols the scenes use: the same points, exactly."""
    string = "".join(chr(c) for c in range(33, 256) if chr(c).isprintable()) + "✓✗→≤∞½—…"
    root = typeset._svg(string, font, 26.0, slant, weight, 4000, 400)
    outlines = {d for d, _, _ in typeset._placed_glyphs(root)}
    assert len(outlines) > 150
    for d in outlines:
        assert np.array_equal(typeset._cairo_path(d), manims_reader(d)), d


number = st.floats(-50, 50).map(lambda v: f"{v:.6f}")


@st.composite
def cairo_paths(draw) -> str:
    """Path data as Cairo writes it: subpaths of M, L and C, each closed (Z) or not, and
    maybe a last move that draws nothing."""
    parts = []
    for _ in range(draw(st.integers(1, 3))):
        x, y = draw(number), draw(number)
        parts.append(f"M {x} {y}")
        for _ in range(draw(st.integers(0, 4))):
            if draw(st.booleans()):
                parts.append(f"L {draw(number)} {draw(number)}")
            else:
                parts.append("C " + " ".join(draw(number) for _ in range(6)))
        if draw(st.booleans()):  # back to the start, a hair away from it, or not at all
            gap = draw(st.sampled_from([0.0, 0.00005, 0.0002, 1.0]))
            parts.append(f"L {float(x) + gap:.6f} {y}")
        if draw(st.booleans()):
            parts.append("Z")
    if draw(st.booleans()):  # the empty move Cairo ends a path with
        parts.append(f"M {draw(number)} {draw(number)}")
    return " ".join(parts)


@settings(max_examples=200)
@given(cairo_paths())
def test_any_cairo_path_reads_as_manim_reads_it(d):
    assert np.array_equal(typeset._cairo_path(d), manims_reader(d))


def test_text_copies_the_cached_outline():
    a, b = text("D", size=22), text("D", size=22)
    a.shift([1, 0, 0])
    assert not np.array_equal(a.points, b.points)
    assert np.array_equal(b.points, typeset.outline("D", SANS, 22.0))  # the theme's font
    assert isinstance(a, FlatText) and a.original_text == "D"


def pixels(mobject) -> np.ndarray:
    camera = Camera()
    camera.background_color = "#000000"
    camera.reset()
    camera.capture_mobject(mobject)
    return np.asarray(camera.get_image()).astype(int)


@pytest.mark.parametrize("string", ["nearest_to(B, [D, E]) → E", "Gravity: a ball ✓"])
def test_one_path_draws_what_the_glyphs_drew(string):
    glyphs = Text(string, font=MONO, font_size=30, color="#e8ecf2").shift([0.5, 0.3, 0])
    flat = text(string, font=MONO, size=30, colour="#e8ecf2").shift([0.5, 0.3, 0])
    before, after = pixels(glyphs), pixels(flat)
    assert (before > 0).any()  # something was drawn
    differ = (before != after).any(axis=2)
    # anti-aliasing where two glyphs' edges meet may differ by a few levels, nothing more
    assert np.abs(before - after).max() <= 8
    assert differ.sum() <= 0.002 * differ.size


def test_glyph_text_is_texts_glyphs():
    """Written text (titles) keeps manim's glyphs apart, so Write writes glyph by glyph."""
    string = "Gravity: a ball"
    manim_glyphs = Text(string, font=SANS, font_size=30).family_members_with_points()
    ours = glyphs(string, size=30, font=SANS, colour="#e8ecf2")
    assert isinstance(ours, GlyphText) and ours.original_text == string
    assert len(ours.submobjects) == len(manim_glyphs) == len(string.replace(" ", ""))
    for mine, theirs in zip(ours.submobjects, manim_glyphs, strict=True):
        assert np.abs(mine.points - theirs.points).max() < 1e-9
    assert np.array_equal(np.concatenate([g.points for g in ours]),
                          typeset.outline(string, SANS, 30.0))
    write = Write(ours)
    assert write.lag_ratio > 0  # one glyph after another


def test_a_broken_svg_is_typeset_again():
    """A kept SVG that does not parse (cut short by a crash) is typeset again, not trusted."""
    string = "broken?"
    typeset.outline(string, SANS, 20.0)
    written = list(config.get_dir("text_dir").glob("trex-*.svg"))
    assert written
    for path in written:
        path.write_text("<svg")
    typeset.forget()
    again = typeset.outline(string, SANS, 20.0)
    assert np.abs(again - manim_points(string, SANS, 20.0)).max() < 1e-9


def test_processes_sharing_a_media_directory(tmp_path):
    """Four processes typesetting the same strings into one media directory at once: every
    one succeeds, and every file left behind is whole."""
    code = (
        "import sys; from manim import tempconfig; from rendering import typeset\n"
        "with tempconfig({'media_dir': sys.argv[1]}):\n"
        "    for k in range(120):\n"
        "        typeset.text(f'line {k} of the race', size=20)\n"
        "print('ok')\n")
    media = tmp_path / "shared"
    runs = [subprocess.Popen([sys.executable, "-c", code, str(media)], cwd=ROOT,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            for _ in range(4)]
    for run in runs:
        out, err = run.communicate(timeout=300)
        assert run.returncode == 0 and out.strip() == "ok", err[-2000:]
    files = list((media / "texts").glob("trex-*.svg"))
    assert len(files) == 120 + 1  # and the capital each text's letters are measured by
    for path in files:
        ET.parse(path)  # whole
    assert not list((media / "texts").glob(".trex-*"))  # no scratch file left


# --- subtitles and card lines: two balanced lines, never shrunk ---------------------------------


@given(st.lists(st.sampled_from(["the", "band", "snags", "at", "Y:", "a", "reflex", "vertex,",
                                 "BD", "crosses", "edge", "E–A"]), min_size=1, max_size=24),
       st.sampled_from(["", " "]))
@settings(max_examples=40, deadline=None)
def test_a_long_caption_takes_two_lines_at_its_size(words, pad):
    caption = " ".join(words)
    shown = typeset.balanced(pad + caption + pad, size=28, width=6.0)  # spaces round it: no line
    natural = text(caption, size=28)
    if natural.width <= 6.0:
        assert isinstance(shown, FlatText) and shown.original_text == caption
        return
    if len(words) == 1:  # a word alone (never wider than 6 here): nowhere to break it
        pytest.fail("a single sampled word fits")
    first, second = shown
    assert f"{first.original_text} {second.original_text}" == caption
    for line in shown:  # each line at the caption's size, unless it alone cannot fit
        alone = text(line.original_text, size=28)
        assert line.height == pytest.approx(min(alone.height, alone.height * 6.0 / alone.width))
    # balanced: no other break makes the longer line shorter by more than a punctuation's worth
    longer = max(len(first.original_text), len(second.original_text))
    breaks = [k for k, c in enumerate(caption) if c == " "]
    assert longer <= min(max(k, len(caption) - k - 1) for k in breaks) + 8
    assert first.get_center()[0] == pytest.approx(second.get_center()[0])  # centred


def test_wrapped_lines_stand_one_pitch_apart_by_their_baselines():
    """The lecture's answers: lines arranged by their ink stood unevenly, a line with no
    descender ("Answer: E — the") 2 px at 480p nearer the next than the others were; by their
    baselines they stand one pitch apart, left-aligned."""
    said = "Answer: E — the line parallel to AC, swept from B, reaches E first, before D"
    lines = typeset.wrapped(said, size=28, width=3.8, font=SANS)
    assert len(lines) >= 4
    baselines = [line.get_top()[1] - typeset._above_baseline(line.original_text, SANS, 28,
                                                               NORMAL, NORMAL)
                 for line in lines]
    steps = [a - b for a, b in itertools.pairwise(baselines)]
    assert max(steps) - min(steps) < 1e-6, steps
    assert len({round(line.get_left()[0], 6) for line in lines}) == 1
