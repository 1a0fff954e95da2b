"""The size rule measures what a viewer reads a text's size by: its letters' height as drawn
(``cap`` in the scene graph), not its box over its lines, which holds descenders, brackets
and the gaps between lines (main's pseudocode rows passed at 2.4 %, their capitals' height)."""

from __future__ import annotations

from itertools import pairwise

import pytest
from manim import tempconfig

from metaphors.layout import PANEL_CODE, code_floor
from metaphors.panel import Panel
from metaphors.theme import THEME
from rendering import typeset
from story.pseudocode import PseudocodeRow
from tests.reading_rules import LEAST_LINE, small_texts
from trex.scene_graph import mobject_graph


@pytest.fixture(autouse=True)
def _media(tmp_path):
    with tempconfig({"media_dir": str(tmp_path / "media"), "quality": "low_quality"}):
        yield


def _graph(*nodes: dict) -> dict:
    return {"plays": [], "final": list(nodes)}


def _text(text: str, box: list[float], **more) -> dict:
    return {"type": "FlatText", "name": "code:1", "text": text, "box": box,
            "fill_opacity": 1.0, **more}


def test_a_text_is_measured_by_its_letters_not_its_box():
    # two lines 0.55 high: 0.275 a line by the old measure, but capitals 0.19 high
    two_lines = _text("n − 2 = 13 − 2\n= 11 triangles", [0, 0, 3, 0.55], cap=0.19)
    assert (two_lines["box"][3] - two_lines["box"][1]) / 2 >= LEAST_LINE  # the old rule passed
    assert small_texts(_graph(two_lines)) == ["code:1 'n − 2 = 13 − 2\\n= 11 triangles' 0.190"]
    assert small_texts(_graph({**two_lines, "cap": 0.2})) == []


def test_a_text_whose_letters_are_not_measured_is_reported():
    assert small_texts(_graph(_text("B", [0, 0, 1, 0.3]))) == ["code:1 'B' no cap"]


def test_the_graph_writes_the_letters_of_a_text_as_drawn():
    """main's gravity row: typeset at 20, shrunk to 0.935 to fit 8 rows (capitals 0.190)."""
    row = typeset.text("B = the left-most vertex (lowest on ties)", size=20)
    assert mobject_graph(row)["cap"] == pytest.approx(0.203, abs=1e-3)
    assert small_texts(_graph({**mobject_graph(row), "name": "code:1"})) == []
    shrunk = {**mobject_graph(row.scale(0.935)), "name": "code:1"}
    assert shrunk["cap"] == pytest.approx(0.190, abs=1e-3)
    assert small_texts(_graph(shrunk)) == [
        "code:1 'B = the left-most vertex (lowest on ties)' 0.190"]


def test_lower_case_words_are_measured_by_their_x_height():
    """The sweep's kind word 'merge' (no letter above the x-height) at the labels' size + 2
    was 0.187 high; 'start', by its t's, 0.234, nearly the capitals' 0.243."""
    size = THEME.label_size + 2
    assert typeset.text("merge", size=size).cap_height() == pytest.approx(0.187, abs=1e-3)
    assert typeset.text("start", size=size).cap_height() == pytest.approx(0.234, abs=1e-3)
    assert typeset.letter_height("H", size=size) == pytest.approx(0.243, abs=1e-3)
    assert typeset.text("merge", size=size + 2).cap_height() >= LEAST_LINE


def _long_panel(rows: int, calls: bool) -> Panel:
    """A panel showing ``rows`` rows of the monotone sweep's width (its widest, 6.4 wide)."""
    panel = Panel([(0, 0), (4, 0), (4, 3), (2, 4), (0, 3)], "ABCDE", None)
    panel.shows_calls = calls
    wide = "    split, or v ends or replaces a merge helper:"
    panel.show_pseudocode([PseudocodeRow(wide if k == 4 else f"row {k}: B is convex")
                           for k in range(rows)])
    return panel


@pytest.mark.parametrize("calls", [False, True])
def test_a_long_pseudocode_keeps_its_size_and_its_rows_apart(calls):
    panel = _long_panel(10, calls)
    assert panel.code_scale == 1.0
    caps = [row.cap_height() for row in panel.code]
    assert min(caps) >= LEAST_LINE
    boxes = sorted((row.get_bottom()[1], row.get_top()[1]) for row in panel.code)
    assert all(upper[0] > lower[1] for lower, upper in pairwise(boxes))  # rows apart
    assert boxes[0][0] >= panel.code_box.rect[1] >= code_floor(calls, 1)  # the last row above
    if calls:  # the code reaches below a call's two lines: a long call keeps to one, cut
        panel._call_line("triangulate_monotone_piece(P, [A, B, C, D, E, F]) → [ABC, ACD, ADE]")
        assert panel.call.original_text.endswith("…")
        assert panel.call.get_top()[1] < panel.code.get_bottom()[1]
    assert panel.code.get_left()[0] >= PANEL_CODE.rect[0] - 1e-6
    assert panel.code.get_right()[0] <= PANEL_CODE.rect[2] + 1e-6
