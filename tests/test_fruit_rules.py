"""The reading rules on ear clipping's fruit can fail: each is tried on a small graph made by
hand with the defect a viewer saw in chapter 4 (the slice count faded in from nothing at
every slice, gone in the fast steps' first frames; prune and search's good part A-B-G-H left
on the board with its slices on the plate and the fruit gone) and on the same graph mended."""

from __future__ import annotations

from tests.reading_rules import flickering_counts, stale_good_parts
from tests.test_tool_rules import _closed, _graph


def _count(kind: str, k: int) -> dict:
    return {"type": kind, "mobject": {"name": "counter", "text": f"{k} / 3 slices",
                                      "box": [-1.0, -2.0, 1.0, -1.7]}}


def _whole(kind: str) -> dict:
    return {"type": kind, "mobject": {"name": "counter", "text": "n − 2 = 5 − 2 = 3 triangles",
                                      "box": [-1.0, -2.0, 1.0, -1.7]}}


P = {"name": "polygon", "type": "Polygon", "points": _closed((0, 0), (4, 0), (4, 4), (2, 5), (0, 4))}


def test_a_count_faded_in_where_a_count_stood_is_found():
    start = [{"type": "Create", "mobject": P}, _count("FadeIn", 0)]
    faded = _graph(start, [_count("FadeIn", 1)], [_count("FadeIn", 2)], [_whole("FadeIn")])
    cut = _graph(start, [_count("Replace", 1)], [_count("Replace", 2)], [_whole("Replace")])
    assert flickering_counts(faded) == [
        "play 1: FadeIn '1 / 3 slices' after '0 / 3 slices'",
        "play 2: FadeIn '2 / 3 slices' after '1 / 3 slices'",
        "play 3: FadeIn 'n − 2 = 5 − 2 = 3 triangles' after '2 / 3 slices'"]
    assert flickering_counts(cut) == []
    # an Add: the one before taken off unseen, maybe plays before (11 / 11 before its wait)
    added = _graph(start, [_count("Add", 1)])
    assert flickering_counts(added) == ["play 1: Add '1 / 3 slices' after '0 / 3 slices'"]
    # a count faded out and another faded in later: absent between two of its values
    gone = _graph(start, [{**_count("FadeOut", 0)}], [_count("FadeIn", 1)])
    assert flickering_counts(gone) == ["play 2: FadeIn '1 / 3 slices' after '0 / 3 slices'"]
    # a new run's first count may fade in
    again = _graph(start, [_count("Replace", 1)], [{"type": "Create", "mobject": P}],
                   [_count("FadeIn", 0)])
    assert flickering_counts(again) == []


def _fruit(kind: str, *corners: tuple[float, float], start: tuple | None = None) -> dict:
    anim: dict = {"type": kind, "mobject": {"name": "polygon", "type": "Polygon",
                                            "points": _closed(*(start or corners))}}
    if kind == "Transform":
        anim["target"] = {"name": "polygon", "type": "Polygon", "points": _closed(*corners)}
    return anim


def _good(kind: str, *corners: tuple[float, float], start: tuple | None = None) -> dict:
    anim = _fruit(kind, *corners, start=start)
    for node in (anim["mobject"], anim.get("target", {})):
        node["name"] = "good"
    return anim


def test_a_good_part_over_no_fruit_is_found():
    whole = ((0, 0), (4, 0), (4, 4), (2, 5), (0, 4))
    good = ((4, 0), (4, 4), (2, 5))  # cut off by the diagonal from (4, 0) to (2, 5)
    left = ((0, 0), (4, 0), (2, 5), (0, 4))  # the fruit once the slice at (4, 4) is cut
    start = [{"type": "Create", "mobject": P}, _good("FadeIn", *good)]
    # the slice cut, the fruit shrinks, the tint stays (chapter 4), then the fruit goes
    stale = _graph(start, [_fruit("Transform", *left, start=whole)], [_fruit("FadeOut", *left)])
    assert stale_good_parts(stale) == ["play 1: 4.00 off the fruit", "play 2: over no fruit"]
    # mended: the tint goes with the slice that leaves it its cutting edge alone
    mended = _graph(start, [_fruit("Transform", *left, start=whole), _good("FadeOut", *good)],
                    [_fruit("FadeOut", *left)])
    assert stale_good_parts(mended) == []
    # a turn of the picture leaves the places unknown: not judged until drawn again
    turned = _graph(start, [{"type": "Turn", "mobject": P},
                            {"type": "Turn", "mobject": {"name": "good",
                                                         "points": _closed(*good)}}],
                    [_good("FadeOut", *good), _good("FadeIn", (9, 9), (10, 9), (9, 10))])
    assert stale_good_parts(turned) == []
