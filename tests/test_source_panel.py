"""The source in the panel (``--panel source``): long lines wrap into rows at a readable size,
and a listing taller than the panel shows a window of whole lines holding the lit one
(metaphors/listing.py, metaphors/panel.py). The scenes' source graphs are checked in
tests/test_scenes.py."""

from __future__ import annotations

from itertools import pairwise

import pytest
from hypothesis import given
from hypothesis import strategies as st
from manim import FadeIn, FadeOut, VGroup, tempconfig

from metaphors.layout import PANEL_CALL_Y, PANEL_SOURCE
from metaphors.listing import CONTINUATION, Window, listing_rows, window_for, wrap_line
from metaphors.panel import SOURCE_PITCH, Panel
from tests.reading_rules import LEAST_LINE

WORDS = st.text(alphabet="abcxyz_([,.)]:=+", min_size=1, max_size=30)


@given(indent=st.integers(0, 24), words=st.lists(WORDS, min_size=1, max_size=12),
       columns=st.integers(20, 40))
def test_a_long_line_wraps_into_rows_that_fit(indent, words, columns):
    text = " " * indent + " ".join(words)
    rows = wrap_line(4, text, columns)
    assert all(row.indent + len(row.text) <= columns for row in rows)
    # nothing lost or added but the spaces it broke at
    assert "".join(r.text for r in rows).replace(" ", "") == text.replace(" ", "")
    assert [r.name for r in rows] == ["code:5", *(f"code:5.{k}" for k in range(2, len(rows) + 1))]
    assert rows[0].indent == min(indent // 2, columns - 12)
    assert all(r.indent == min(rows[0].indent + CONTINUATION, columns - 12) for r in rows[1:])
    assert all(r.text.strip() == r.text and r.text for r in rows)


@given(words=st.lists(WORDS, min_size=1, max_size=40), most=st.integers(1, 6))
def test_a_line_taller_than_the_panel_is_cut(words, most):
    text = " ".join(words)
    whole, cut = wrap_line(0, text, 20), wrap_line(0, text, 20, most=most)
    if len(whole) <= most:
        assert cut == whole
        return
    assert len(cut) == most and cut[:-1] == whole[:most - 1]
    assert cut[-1].text.endswith("…") and cut[-1].indent + len(cut[-1].text) <= 20
    shown = "".join(r.text for r in cut)[:-1].replace(" ", "")
    assert text.replace(" ", "").startswith(shown)


def test_a_line_that_fits_is_one_row_and_keeps_its_level():
    assert [(r.name, r.indent, r.text) for r in wrap_line(0, "        if angle > widest:", 35)] \
        == [("code:1", 4, "if angle > widest:")]
    rows = listing_rows(["def f(polygon):", "    return a_rather_long_name(polygon, other)"], 26)
    assert [(r.name, r.indent, r.text) for r in rows] == [
        ("code:1", 0, "def f(polygon):"), ("code:2", 2, "return"),
        ("code:2.2", 6, "a_rather_long_name("), ("code:2.3", 6, "polygon, other)")]


@given(counts=st.lists(st.integers(1, 14), min_size=1, max_size=30), capacity=st.integers(1, 14),
       lits=st.lists(st.integers(0, 29), max_size=40))
def test_the_window_holds_the_lit_line_and_moves_only_when_it_must(counts, capacity, lits):
    counts = [min(c, capacity) for c in counts]  # no line has more rows (wrap_line's most)
    window = window_for(counts, capacity, 0)
    assert window.first == 0
    for lit in (k % len(counts) for k in lits):
        new = window_for(counts, capacity, lit, window)
        assert new.holds(lit) and sum(counts[new.first:new.end]) <= capacity
        if window.holds(lit):
            assert new == window
        else:  # a new window is as full as it can be: no line above it would fit
            assert new.first == 0 or sum(counts[new.first - 1:new.end]) > capacity
        window = new


def test_a_moved_window_shows_the_lines_before_the_lit_one():
    assert window_for([1] * 30, 12, 20, Window(0, 12)) == Window(17, 29)
    assert window_for([1] * 30, 12, 27, Window(0, 12)) == Window(18, 30)  # full at the end
    assert window_for([1] * 30, 12, 1, Window(18, 30)) == Window(0, 12)


# --- the panel --------------------------------------------------------------------------------

#: a listing of 30 lines, some too long for a row
LONG = [(100 + k, "    " * (k % 3) + (f"value_{k} = compute(first_argument, second_argument, {k})"
                                      if k % 4 == 0 else f"x{k} = {k}")) for k in range(30)]


@pytest.fixture
def panel(tmp_path) -> Panel:
    with tempconfig({"media_dir": str(tmp_path)}):
        panel = Panel([(0, 0), (4, 0), (2, 3)], ["A", "B", "C"], None)
        panel.show_code(LONG)
        yield panel


def _rows(panel) -> list:
    return [m for m in panel.code if m.name.startswith("code:")]


def test_the_source_is_read_at_its_size_in_the_panels_box(panel):
    rows = _rows(panel)
    assert rows and panel.window is not None and panel.window.first == 0
    bottom = PANEL_SOURCE.y - PANEL_SOURCE.height / 2
    for mobject in panel.code:
        assert mobject.height >= LEAST_LINE, mobject.original_text
        assert mobject.get_bottom()[1] >= bottom > PANEL_CALL_Y
        assert mobject.get_right()[0] <= PANEL_SOURCE.x + PANEL_SOURCE.width / 2
    assert [m.name for m in panel.code][-1] == "panel:below"  # and nothing above
    assert panel.code[-1].original_text == f"⋮ {30 - panel.window.end} lines below"
    assert "panel:above" not in {m.name for m in panel.code}
    # the rows are one pitch apart, whatever their glyphs
    middles = [y for ys in panel.slot_y.values() for y in ys]
    assert [round(a - b, 6) for a, b in pairwise(middles)] == [SOURCE_PITCH] * (
        len(middles) - 1)


def test_a_wrapped_line_is_lit_whole(panel):
    anims = panel._light_line(100)  # line 1: long, wrapped
    index, light, copy = panel.lit
    rows = panel.shown[0]
    assert index == 0 and len(rows) > 1 and isinstance(copy, VGroup)
    assert [c.name for c in copy] == [r.name for r in rows] == ["code:1", "code:1.2"]
    for row, lit in zip(rows, copy, strict=True):
        assert (row.points == lit.points).all()
        assert light.get_bottom()[1] < row.get_bottom()[1] < row.get_top()[1] < light.get_top()[1]
    assert [type(a) for a in anims] == [FadeIn, FadeIn]  # the light and the copy: no new window


def test_the_window_moves_only_when_the_lit_line_leaves_it(panel):
    first = panel.code
    for number in (100, 103, 105):
        anims = panel._light_line(number)
        assert panel.code is first and not any(a.mobject is first for a in anims)
    anims = panel._light_line(125)
    assert panel.code is not first and panel.window.holds(25)
    assert [type(a) for a in anims[:2]] == [FadeOut, FadeIn]
    assert anims[0].mobject is first and anims[1].mobject is panel.code
    above = [m for m in panel.code if m.name == "panel:above"]
    assert above and above[0].original_text == f"⋮ {panel.window.first} lines above"
    lit = panel.lit[2]
    shown = {m.name for m in _rows(panel)}
    assert {c.name for c in lit} <= shown and lit[0].name == "code:26"
    assert panel._light_line(125) == []  # lit already: nothing changes
    back = panel._light_line(101)
    assert panel.window.holds(1) and back[0].mobject is not first  # a new window, built again


def test_a_line_of_more_rows_than_the_panel_holds_is_cut_there(tmp_path):
    """One's own listing with a long literal: 20 rows' worth in one line, lit, first and
    later (it crashed the panel)."""
    items = ", ".join(f"item_{k}" for k in range(60))
    code = [(10, "def mine(polygon):"), (11, f"    table = [{items}]"), (12, "    return table")]
    with tempconfig({"media_dir": str(tmp_path)}):
        for lit in (11, 12, 10, 11):
            panel = Panel([(0, 0), (4, 0), (2, 3)], ["A", "B", "C"], None)
            panel.show_code(code[1:] if lit == 11 else code)  # the long line first, too
            panel._light_line(lit)
            rows = _rows(panel)
            assert len(rows) <= panel._slots() and panel.lit is not None
            assert any(r.original_text.endswith("…") for r in rows)


def test_a_source_that_cannot_be_read_leaves_the_polygon_in_the_panel(tmp_path):
    with tempconfig({"media_dir": str(tmp_path)}):
        panel = Panel([(0, 0), (4, 0), (2, 3)], ["A", "B", "C"], None)  # no code at all
        assert panel.outline in panel.mobjects() and panel.shows_polygon
        panel.show_code(LONG)
        assert panel.outline not in panel.mobjects()


def _module(path, source: str) -> dict:
    """The names a module of this source defines, its source readable by inspect."""
    import linecache

    path.write_text(source)
    namespace: dict = {}
    exec(compile(source, str(path), "exec"), namespace)
    linecache.updatecache(str(path))
    return namespace


def test_the_source_shown_leaves_out_the_docstring_only(tmp_path):
    from story.source import shown_source

    namespace = _module(tmp_path / "mine.py", (
        'import functools\n\n\n@functools.cache\ndef mine(polygon):\n'
        '\tr"""A raw docstring,\n\ton two lines."""\n'
        '\tnote = """not a docstring"""\n'
        '\tif polygon:\n\t\treturn note\n\t"""\n\ta string, said alone\n\t"""\n'))
    assert shown_source(namespace["mine"].__wrapped__) == (
        (5, "def mine(polygon):"), (8, '    note = """not a docstring"""'),
        (9, "    if polygon:"), (10, "        return note"), (11, '    """'),
        (12, "    a string, said alone"), (13, '    """'))


def test_a_lambda_or_a_source_that_does_not_parse_alone_is_shown_whole(tmp_path):
    from story.source import shown_source

    namespace = _module(tmp_path / "odd.py", (
        'first_and_third = lambda polygon: (1, 3)\n\n\ndef outer():\n'
        '    def inner(polygon):\n        note = """two\nlines"""\n'
        '        return (0, 2)\n    return inner\n\n\n'
        'def short(p): "doc"; return p\n'))
    assert shown_source(namespace["first_and_third"]) == (
        (1, "first_and_third = lambda polygon: (1, 3)"),)
    assert [n for n, _ in shown_source(namespace["outer"]())] == [5, 6, 7, 8]
    assert shown_source(namespace["short"]) == ((12, 'def short(p): "doc"; return p'),)


def test_a_listing_of_one_tall_line_that_fits_is_not_cut(tmp_path):
    with tempconfig({"media_dir": str(tmp_path)}):
        panel = Panel([(0, 0), (4, 0), (2, 3)], ["A", "B", "C"], None)
        slots, columns = panel._slots(), panel._columns()
        # one line of exactly as many rows as the panel has slots
        line = next(line for line in (", ".join(f"item_{k}" for k in range(n))
                                      for n in range(1, 200))
                    if len(wrap_line(0, line, columns)) == slots)
        panel.show_code([(1, line)])
        rows = _rows(panel)
        assert len(rows) == slots and panel.window is None
        assert not any(r.original_text.endswith("…") for r in rows)


# --- the panel's small polygon: its labels readable (issue 22: the lecture's M and K) -------------


@pytest.mark.parametrize("sample", ["lecture", "counterexample", "counterexample-twin",
                                    "gravity-snag", "two-ears", "keyhole"])
def test_the_panels_polygon_keeps_every_label_apart_off_its_edges_and_readable(sample):
    """Each label of the panel's P: kept (none dropped for want of room), at least 2.5 % of
    the frame's height, 0.03 clear of every edge and every other label, nearer its own dot
    than any other, within the panel's polygon area (under the title, over the code)."""
    from shapely.geometry import LineString, Point, box

    from metaphors.layout import PANEL_LABELS
    from story.runs import run_logged
    from story.storyboard import storyboard
    from tests.reading_rules import LABEL_ROOM

    shown = storyboard(run_logged("ear-clipping", sample))[0]
    panel = Panel(shown.points, shown.labels, None, holes=shown.holes)
    rings = [panel.frame.many(shown.points),
             *(panel.frame.many(h.points) for h in shown.holes)]
    edges = [LineString([*(p[:2] for p in ring), ring[0][:2]]) for ring in rings]
    area = box(PANEL_LABELS.x - PANEL_LABELS.width / 2, PANEL_LABELS.y - PANEL_LABELS.height / 2,
               PANEL_LABELS.x + PANEL_LABELS.width / 2, PANEL_LABELS.y + PANEL_LABELS.height / 2)
    assert all(len(m.submobjects) == 2 for m in panel.markers.values())  # no label dropped
    boxes = {k: box(*m[1].get_corner([-1, -1, 0])[:2], *m[1].get_corner([1, 1, 0])[:2])
             for k, m in panel.markers.items()}
    dots = {k: Point(*m[0].get_center()[:2]) for k, m in panel.markers.items()}
    for label, shape in boxes.items():
        assert panel.markers[label][1].height >= LEAST_LINE, label
        assert area.contains(shape), label
        assert min(shape.distance(e) for e in edges) >= LABEL_ROOM, label
        assert all(shape.distance(other) >= LABEL_ROOM
                   for k, other in boxes.items() if k != label), label
        assert min(dots, key=lambda k: shape.distance(dots[k])) == label, label
