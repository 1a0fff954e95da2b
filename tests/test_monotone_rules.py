"""The reading rules on the monotone sweep can fail: each is tried on a small graph made by hand
with the defect a viewer saw (chapter 5's "start" for A nearer L, a kind word faded out at
once, or left up all run; HolesSweep's stack column jumping under "B waits on the stack") and
on the same graph mended."""

from __future__ import annotations

from tests.reading_rules import fleeting_kind_words, jumping_stacks, stray_kind_words


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
    assert stray_kind_words(between) == ["'start' for A nearer L"]
    assert stray_kind_words(far) == ["'start' for A 1.4 away"]
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
