"""The reading rules on the monotone sweep can fail: each is tried on a small graph made by hand
with the defect a viewer saw (chapter 5's "start" for A nearer L, a kind word faded out at
once, or left up all run; HolesSweep's stack column jumping under "B waits on the stack") and
on the same graph mended."""

from __future__ import annotations

from itertools import pairwise

from tests.reading_rules import (
    fleeting_kind_words,
    jumping_stacks,
    labels_beside_the_sweep,
    stray_kind_words,
)


def _dot(x: float, y: float) -> dict:
    """A dot as manim writes it: points round its centre."""
    return {"type": "Dot", "points": [[x - 0.06, y, 0.0], [x, y + 0.06, 0.0],
                                      [x + 0.06, y, 0.0], [x, y - 0.06, 0.0]]}


def _vertex(label: str, x: float, y: float) -> dict:
    return {"name": f"vertex:{label}", "type": "VGroup", "submobjects": [
        _dot(x, y), {"type": "FlatText", "text": label,
                     "box": [x - 0.35, y - 0.1, x - 0.15, y + 0.1]}]}


A, L = _vertex("A", 0.0, 0.0), _vertex("L", 1.2, 0.0)
SHOWN = [{"type": "FadeIn", "mobject": A}, {"type": "FadeIn", "mobject": L}]


def _kind(kind: str, box: list[float], text: str = "start") -> dict:
    return {"type": kind, "mobject": {"name": "kind", "text": text, "box": box}}


def _graph(*plays: tuple[list[dict], str | None, float]) -> dict:
    return {"plays": [{"animations": anims, "subcaption": said, "run_time": time}
                      for anims, said, time in plays]}


def test_a_kind_word_nearer_another_vertex_or_far_from_its_own_is_found():
    flash = {"type": "Indicate", "mobject": A}
    between = _graph((SHOWN, None, 1.0), ([_kind("FadeIn", [0.3, 0.1, 0.9, 0.3]), flash],
                                          "A: a start vertex", 1.0))
    # A alone: far from its own vertex, nearer no other
    far = _graph((SHOWN[:1], None, 1.0), ([_kind("FadeIn", [-0.3, 1.4, 0.3, 1.6]), flash],
                                      "A: a start vertex", 1.0))
    beside = _graph((SHOWN, None, 1.0), ([_kind("FadeIn", [-0.5, 0.25, 0.1, 0.45]), flash],
                                         "A: a start vertex", 1.0))
    assert stray_kind_words(between) == ["'start' for A 0.32 from it", "'start' for A nearer L"]
    assert stray_kind_words(far) == ["'start' for A 1.30 from it", "'start' for A 1.4 away"]
    assert stray_kind_words(beside) == []


def test_a_kind_word_gone_before_its_caption_is_read_or_left_up_is_found():
    box, other = [-0.5, 0.25, 0.1, 0.45], [0.9, 0.25, 1.5, 0.45]
    flash_a, flash_l = {"type": "Indicate", "mobject": A}, {"type": "Indicate", "mobject": L}
    fleeting = _graph(([_kind("FadeIn", box), flash_a], "A: a start vertex", 0.3),
                      ([_kind("FadeOut", box)], None, 0.1), ([], None, 2.5))
    kept = _graph(([_kind("FadeIn", box), flash_a], "A: a start vertex", 0.3),
                  ([], None, 2.5), ([_kind("FadeOut", box)], "L: a start vertex", 0.1),
                  ([_kind("FadeIn", other), flash_l], None, 0.3))
    # faded out before it came: it stays all run
    left = _graph(([_kind("FadeOut", box)], "A: a start vertex", 0.1),
                  ([_kind("FadeIn", box), flash_a], None, 0.3), ([], None, 2.5),
                  ([_kind("FadeOut", other)], "L: a start vertex", 0.1),
                  ([_kind("FadeIn", other), flash_l], None, 0.3))
    # a summary's fast steps: a word there flashes by as fast as its step, unread
    summary = _graph(([_kind("FadeIn", box), flash_a], "Vertices A and L: the same steps", 0.2),
                     ([_kind("FadeOut", box)], None, 0.1))
    assert fleeting_kind_words(fleeting) == ["'start' up 0.30 s"]
    assert fleeting_kind_words(left) == ["'start' left over"]
    assert fleeting_kind_words(summary) == ["'start' up 0.20 s"]
    assert fleeting_kind_words(kept) == []


def _column(kind: str, *labels: str) -> dict:
    texts = [{"text": t} for t in ("stack", *labels)]
    node = {"name": "stack:column", "submobjects": texts}
    return {"type": kind, "mobject": node, "target": node} if kind == "Transform" else {
        "type": kind, "mobject": node}


def test_a_stack_that_changes_unsaid_is_found():
    start = [([_column("FadeIn", "A")], "A waits on the stack", 1.0),
             ([_column("Transform", "b₁", "A")], "b₁ waits on the stack", 1.0),
             ([_column("Transform", "A")], "Triangle ABb₁ cut off: b₁ leaves", 1.0)]
    jumped = _graph(*start, ([_column("Transform", "B", "b₁")], "B waits on the stack", 1.0))
    said = _graph(*start, ([_column("Transform", "B", "b₁")],
                           "A is done: b₁ and B wait on the stack", 1.0))
    assert jumping_stacks(jumped) == ["'B waits on the stack': A went, b₁ came"]
    assert jumping_stacks(said) == []


def _square(name: str, x0: float, y0: float, x1: float, y1: float) -> dict:
    """A closed polygon node, each side a curve of four points (as manim writes it)."""
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
    points = [[*(p if k < 2 else q), 0.0] for p, q in pairwise(corners)
              for k in range(4)]
    return {"name": name, "type": "Polygon", "points": points}


def test_a_kind_word_or_a_label_over_the_polygon_s_fill_is_found():
    """Review s35: "merge" beside M and "split" beside D stood on P's fill, and so did the
    labels G and M; a word outside P, off its fill, is not found."""
    from tests.reading_rules import texts_over_the_picture, words_over_the_picture

    polygon = {"type": "FadeIn", "mobject": _square("polygon", -1.0, -2.0, 2.0, 2.0)}
    inside = _graph(([polygon, *SHOWN], None, 1.0),
                    ([_kind("FadeIn", [0.2, 0.5, 1.0, 0.8], "merge")], "M: merge", 1.0))
    outside = _graph(([polygon], None, 1.0),
                     ([_kind("FadeIn", [2.2, 0.5, 3.0, 0.8], "merge")], "M: merge", 1.0))
    # A's label stands at x −0.35 … −0.15, inside the square from −1; L's inside too
    assert words_over_the_picture(inside) == ["play 1 'merge' 0.24 over P"]
    assert texts_over_the_picture(inside) == ["play 0 A 0.04 over P", "play 0 L 0.04 over P",
                                              "play 1 'merge' 0.24 over P"]
    assert texts_over_the_picture(outside) == []


def _sweep(*dashes: tuple[float, float, float]) -> dict:
    """The monotone sweep line: its dashes, each (left, right, height)."""
    return {"name": "sweep", "type": "VGroup", "submobjects": [
        {"name": "sweep:line", "type": "DashedLine", "stroke_opacity": 1.0,
         "points": [[x0, y, 0.0], [x1, y, 0.0]]} for x0, x1, y in dashes]}


def test_a_sweep_line_that_runs_up_to_a_label_is_found():
    """Chapter 5 at 28 s: the sweep's dashes stopped 0.04 short of M's and K's letters, at
    their height, and read as striking them through; 0.12 off, they do not."""
    from tests.reading_rules import labels_struck_by_the_sweep

    # A's label: x −0.35 … −0.15, y −0.1 … 0.1
    near = _graph((SHOWN[:1], None, 1.0),
                  ([{"type": "Create", "mobject": _sweep((-2.0, -0.39, 0.0), (-0.11, 2.0, 0.0))}],
                   None, 1.0))
    moved = _graph((SHOWN[:1], None, 1.0),
                   ([{"type": "Transform", "mobject": _sweep((-2.0, 2.0, 1.0)),
                      "target": _sweep((-2.0, -0.39, 0.0), (-0.11, 2.0, 0.0))}], None, 1.0))
    clear = _graph((SHOWN[:1], None, 1.0),
                   ([{"type": "Create", "mobject": _sweep((-2.0, -0.75, 0.0), (0.25, 2.0, 0.0))}],
                    None, 1.0))
    # 0.12 beside it at its height (K and M at 22.7–30 s), and 0.12 over its top (A at 16 s)
    beside = _graph((SHOWN[:1], None, 1.0),
                    ([{"type": "Create", "mobject": _sweep((-2.0, -0.47, 0.0), (-0.03, 2.0, 0.0))}],
                     None, 1.0))
    over = _graph((SHOWN[:1], None, 1.0),
                  ([{"type": "Create", "mobject": _sweep((-2.0, 2.0, 0.22))}], None, 1.0))
    assert labels_struck_by_the_sweep(near) == ["the sweep 0.04 from A"]
    assert labels_struck_by_the_sweep(moved) == ["the sweep 0.04 from A"]
    assert labels_struck_by_the_sweep(over) == ["the sweep 0.12 from A"]
    assert labels_beside_the_sweep(beside) == ["the sweep 0.12 beside A"]
    assert labels_beside_the_sweep(over) == []
    assert labels_struck_by_the_sweep(clear) == labels_beside_the_sweep(clear) == []


def test_a_vertex_that_comes_back_onto_the_stack_unsaid_is_found():
    """Chapter 5 at 72–77 s: "Triangle ABH cut off: H leaves", then "A is done: H and B wait
    on the stack", the column drawing H popped and pushed back: said to come back, it reads."""
    from tests.reading_rules import stack_returns_unsaid

    def plays(said: str) -> dict:
        return _graph(([_column("FadeIn", "H", "A")], "H waits on the stack", 1.0),
                      ([_column("Transform", "A")], "Triangle ABH cut off: H leaves", 1.0),
                      ([_column("Transform", "B", "H")], said, 1.0))

    assert stack_returns_unsaid(plays("A is done: H and B wait on the stack")) == [
        "'A is done: H and B wait on the stack': H left, comes back unsaid"]
    assert stack_returns_unsaid(plays("A is done: H goes back on the stack, B on top")) == []
