"""The reading rules on ear clipping's fruit can fail: each is tried on a small graph made by
hand with the defect a viewer saw in chapter 4 (the slice count faded in from nothing at
every slice, gone in the fast steps' first frames; prune and search's good part A-B-G-H left
on the board with its slices on the plate and the fruit gone) and on the same graph mended."""

from __future__ import annotations

import math

from tests.reading_rules import (
    delta_e,
    faint_cuts,
    flickering_counts,
    labels_moved_by_cuts,
    labels_on_the_fruit_with_room,
    labels_without_contrast,
    leftover_verdicts,
    placeholders_as_labels,
    polygon_names,
    recoloured_close_ups,
    shifting_tints,
    stale_good_parts,
    stray_vertex_markers,
    unseen_ear_tests,
)
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


# --- chapter 4, review r34: stale test triangles and keyhole cuts, labels under the fruit,
# a sub-polygon named as a vertex ------------------------------------------------------------


def _captioned(*plays: tuple[str, list[dict]]) -> dict:
    return {"plays": [{"animations": anims, "run_time": 1.0, "subcaption": words}
                      for words, anims in plays]}


def _triangle(kind: str, role: str) -> dict:
    return {"type": kind, "mobject": {"name": "ear-triangle", "role": role,
                                      "points": _closed((0, 0), (1, 0), (0, 1))}}


def test_a_red_test_triangle_left_past_its_step_is_found():
    """Prune and search's "Is G an ear? no": its red H-G-F stayed through the gravity step."""
    test = [("Is G an ear? no: G is not convex", []), ("", [_triangle("_MethodAnimation", "rejected")])]
    turn = {"type": "FadeIn", "mobject": {"name": "gravity", "points": _closed((5, 5), (6, 5), (6, 6))}}
    stale = _captioned(*test, ("Turn the polygon", []), ("", [turn]))
    assert leftover_verdicts(stale) == ["play 3: red ear-triangle of play 1"]
    mended = _captioned(*test, ("Turn the polygon", [_triangle("FadeOut", "rejected")]), ("", [turn]))
    assert leftover_verdicts(mended) == []
    # an ear's green triangle stays up through its slice: not a verdict left over
    ear = _captioned(("Is A an ear? yes", []), ("", [_triangle("_MethodAnimation", "result")]),
                     ("Slice MAB", []), ("", [turn]))
    assert leftover_verdicts(ear) == []


def _cut(kind: str) -> dict:
    return {"type": kind, "mobject": {"name": "keyhole:1", "points": [[1, 1, 0], [1, 1, 0],
                                                                      [2, 2, 0], [2, 2, 0]]}}


def test_a_keyhole_cut_over_no_fruit_is_found():
    """Chapter 4's c₁–F cut floated alone once the last slice had taken the fruit."""
    start = [{"type": "Create", "mobject": P}, _cut("FadeIn")]
    left = _graph(start, [_fruit("FadeOut", (0, 0), (4, 0), (4, 4))])
    assert stale_good_parts(left) == ["play 1: keyhole:1 over no fruit"]
    gone = _graph(start, [_fruit("FadeOut", (0, 0), (4, 0), (4, 4)), _cut("FadeOut")])
    assert stale_good_parts(gone) == []


def test_a_keyhole_cut_faint_on_the_fruit_is_found():
    """Chapter 4's cuts, the rind's olive on the orange fruit (1.1 : 1), all but vanished."""
    from metaphors.theme import THEME

    fruit = {"type": "Create", "mobject": {**P, "fill": THEME.fruit, "fill_opacity": 0.75}}

    def cut(colour: str) -> dict:
        return {"type": "FadeIn", "mobject": {"name": "keyhole:1", "stroke": colour,
                                              "points": _closed((1, 1), (2, 2))[:4]}}

    olive = "#7a9e3d"  # the rind's colour then
    assert faint_cuts(_graph([fruit], [cut(olive)])) == ["play 1 keyhole:1 on polygon 1.1 : 1"]
    assert faint_cuts(_graph([fruit], [cut(THEME.background)])) == []


def _label(kind: str) -> dict:
    return {"type": kind, "mobject": {"name": "vertex:M", "submobjects": [
        {"type": "Dot", "points": _closed((1, 1), (1.1, 1), (1.1, 1.1))},
        {"type": "Text", "text": "M", "box": [1.2, 1.2, 1.5, 1.5], "fill": "#E8ECF2",
         "fill_opacity": 1.0, "halo": {"stroke": "#10141C", "stroke_opacity": 1.0,
                                       "stroke_width": 6.0}}]}}


def _orange(kind: str) -> dict:
    return {"type": kind, "mobject": {**P, "fill": "#F4A259", "fill_opacity": 0.75}}


def test_a_label_the_fruit_came_over_is_found():
    """After gravity's close-up the fruit faded back in over M, H and G: light orange on it."""
    start = [{"type": "Create", "mobject": {**P, "fill": "#F4A259", "fill_opacity": 0.75}},
             _label("FadeIn")]
    assert labels_without_contrast(_graph(start)) == []  # a haloed ink label over the fruit
    # the label moves back from the close-up as the fruit fades in
    over = _graph(start, [_orange("FadeOut")], [_orange("FadeIn"), _label("_MethodAnimation")])
    assert labels_without_contrast(over) == ["play 2 M under polygon 1.9 : 1"]


def _rows(*texts: str) -> list[dict]:
    return [{"type": "FadeIn", "mobject": {"name": f"code:{k}", "text": t}}
            for k, t in enumerate(texts, start=1)]


def test_a_sub_polygon_named_as_a_vertex_is_found():
    """Prune and search's pseudocode named the good part G, and G was the vertex tested."""
    marker = {"type": "FadeIn", "mobject": {"name": "vertex:G"}}
    start = [{"type": "Create", "mobject": P}, marker]
    named = _graph([*start, *_rows("G = P (good); while P is more than a triangle:",
                                   "  V = the middle vertex of G: an ear?")])
    assert placeholders_as_labels(named) == ["play 0: G"]
    renamed = _graph([*start, *_rows("Q = P (good); while P is more than a triangle:",
                                     "  V = the middle vertex of Q: an ear?")])
    assert placeholders_as_labels(renamed) == []
    # a vertex a row names by its label (the heuristics' "B = the left-most vertex") is the
    # run's own vertex: not a polygon's name
    assert placeholders_as_labels(_graph([*start, *_rows("G = the left-most vertex")])) == []


def test_no_pseudocode_names_a_polygon_as_a_lecture_vertex():
    """No built-in's pseudocode names a polygon (or a part of one) with a letter a vertex of
    the lecture's polygons has: the lecture polygon's A–M, the keyhole sample's, the
    heuristics' (the exercises are drawn on the counterexample's frame)."""
    from geometry.io import read_any_polygon
    from story.registry import entry, names

    labels = {label for name in ("lecture", "keyhole", "counterexample", "gravity-snag")
              for label in read_any_polygon(name).labels}
    assert {"A", "M", "a₁", "d₂"} <= labels
    clashes = {name: polygon_names([row.text for row in entry(name).pseudocode]) & labels
               for name in names()}
    assert {name: sorted(c) for name, c in clashes.items() if c} == {}


# --- chapter 4, review s34: a sliced-off vertex goes with its slice --------------------------


def _marker(kind: str, label: str, at: tuple[float, float]) -> dict:
    """A vertex marker as the graph writes it: a dot (points round ``at``) and a label."""
    x, y = at
    dot = [[x + dx, y + dy, 0.0] for dx, dy in ((0.06, 0), (0, 0.06), (-0.06, 0), (0, -0.06))]
    return {"type": kind, "mobject": {"name": f"vertex:{label}", "type": "VGroup", "submobjects": [
        {"type": "Dot", "points": dot}, {"type": "FlatText", "text": label,
                                         "box": [x + 0.1, y + 0.1, x + 0.3, y + 0.3]}]}}


def test_a_marker_left_by_its_sliced_off_vertex_is_found():
    whole = ((0, 0), (4, 0), (4, 4), (2, 5), (0, 4))
    left = ((0, 0), (4, 0), (2, 5), (0, 4))  # the fruit once the slice at (4, 4) is cut
    start = [{"type": "Create", "mobject": P},
             *[_marker("FadeIn", "ABCDE"[k], p) for k, p in enumerate(whole)]]
    # the slice cut, the fruit shrinks, C's marker stays up (chapter 4 at 98 s)
    stale = _graph(start, [_fruit("Transform", *left, start=whole)], [_marker("Indicate", "D",
                                                                              (2, 5))])
    assert stray_vertex_markers(stale) == ["play 1 C"]
    # mended: C's marker goes with its slice, and comes back with the whole triangulation
    pieces = [{"type": "FadeIn", "mobject": {"name": "triangulation", "type": "Polygon",
                                             "points": _closed(*t)}}
              for t in (((0, 0), (4, 0), (2, 5)), ((4, 0), (4, 4), (2, 5)),
                        ((0, 0), (2, 5), (0, 4)))]
    mended = _graph(start, [_fruit("Transform", *left, start=whole),
                            _marker("FadeOut", "C", (4, 4))],
                    [_fruit("FadeOut", *left), *pieces, _marker("FadeIn", "C", (4, 4))])
    assert stray_vertex_markers(mended) == []
    # a turn of the picture leaves the places unknown: not judged until drawn again
    turned = _graph(start, [{"type": "Turn", "mobject": P}], [_marker("Indicate", "C", (9, 9))])
    assert stray_vertex_markers(turned) == []


def _c1(kind: str, box: list[float]) -> dict:
    return {"type": kind, "mobject": {"name": "vertex:c₁", "type": "VGroup", "submobjects": [
        {"type": "Dot", "points": [[1.0, 1.0, 0.0]]}, {"type": "FlatText", "text": "c₁", "box": box}]}}


def test_a_label_a_keyhole_cut_moves_is_found():
    """Chapter 4: the second keyhole's cut moved c₁ (its dot where it stood) aside."""
    start = [{"type": "Create", "mobject": P}, _c1("FadeIn", [1.1, 1.1, 1.4, 1.3])]
    cut = {"type": "FadeIn", "mobject": {"name": "keyhole:1", "points": _closed((1, 1), (4, 2))}}
    moved = _graph(start, [cut, _c1("Transform", [1.1, 0.6, 1.4, 0.8])])
    assert labels_moved_by_cuts(moved) == ["play 1 keyhole:1 moves c₁"]
    # placed clear of the cut from the start: it stays
    assert labels_moved_by_cuts(_graph(start, [cut])) == []
    # moved aside by a later line (a knife), not a cut
    knife = {"type": "Create", "mobject": {"name": "knife", "points": _closed((1, 1), (4, 2))}}
    assert labels_moved_by_cuts(_graph(start, [knife, _c1("Transform", [1.1, 0.6, 1.4, 0.8])])) == []


def test_a_label_on_the_fruit_with_room_off_it_is_found():
    """Chapter 4's a₂ stayed on the orange once the slices had cut the fruit away round it."""
    from metaphors.theme import THEME

    def fruit(*corners: tuple[float, float]) -> dict:
        return {"type": "Create", "mobject": {"name": "polygon", "fill": THEME.fruit,
                                              "fill_opacity": 0.75, "points": _closed(*corners)}}

    # a₂'s vertex (1, 1) on the fruit's corner, its label just inside the fruit
    label = _c1("FadeIn", [1.1, 1.1, 1.4, 1.3])
    sliced = _graph([fruit((1, 1), (4, 1), (4, 4), (1, 4)), label])
    assert labels_on_the_fruit_with_room(sliced) == ["play 0 c₁ on the fruit, room off it"]
    # off the fruit, below its corner: nothing to find
    below = _graph([fruit((1, 1), (4, 1), (4, 4), (1, 4)), _c1("FadeIn", [0.6, 0.6, 0.9, 0.8])])
    assert labels_on_the_fruit_with_room(below) == []
    # a hole's vertex in a fruit all round it, the hole too small: no room off it
    whole = _graph([fruit((-3, -3), (5, -3), (5, 5), (-3, 5)), label])
    assert labels_on_the_fruit_with_room(whole) == []


# --- chapter 4, ears4: an ear test answered no shows why; the good sub-polygon's one colour ---


def _pulse(label: str, at: tuple[float, float]) -> dict:
    """A vertex marker pulsing (``Indicate``): its dot a small square round ``at``."""
    x, y = at
    dot = {"name": "Dot", "points": _closed((x - 0.05, y - 0.05), (x + 0.05, y - 0.05),
                                            (x + 0.05, y + 0.05), (x - 0.05, y + 0.05))}
    return {"type": "Indicate", "mobject": {"name": f"vertex:{label}", "submobjects": [dot]}}


def _red(name: str, *corners: tuple[float, float]) -> dict:
    return {"type": "_MethodAnimation",
            "mobject": {"name": name, "role": "rejected", "points": _closed(*corners)},
            "target": {"name": name, "role": "rejected", "points": _closed(*corners)}}


def test_an_ear_test_that_does_not_show_why_is_found():
    """Prune and search's "is H an ear? no" at 96 s: H straight between G and K, its red
    triangle a line; a reflex vertex's red triangle holds no vertex (it lies outside P)."""
    g, h, k = (0.0, 0.0), (1.0, 1.0), (2.5, 2.5)
    flat = _graph([_pulse("H", h), _red("ear-triangle", g, h, k)])
    assert unseen_ear_tests(flat) == ["play 0 H: red triangle 0.00 high"]
    empty = _graph([_pulse("G", (0, 0)), _red("ear-triangle", (2, -1), (0, 0), (2, 1))])
    assert unseen_ear_tests(empty) == ["play 0 G: red triangle, no vertex inside"]
    # mended: the vertex inside pulses in a triangle with room; a not-convex one's angle
    inside = _graph([_pulse("B", (0, 0)), _pulse("G", (1.5, 0.1)),
                     _red("ear-triangle", (2, -1), (0, 0), (2, 1))])
    assert unseen_ear_tests(inside) == []
    arc = [(h[0] + 0.3 * math.cos(math.pi / 4 + math.pi * t / 12),
            h[1] + 0.3 * math.sin(math.pi / 4 + math.pi * t / 12)) for t in range(13)]
    angle = _graph([_pulse("H", h), _red("ear-angle", h, *arc)])
    assert unseen_ear_tests(angle) == []
    # an angle too small to see is no reason shown
    speck = [(h[0] + 0.05 * (x - h[0]) / 0.3, h[1] + 0.05 * (y - h[1]) / 0.3) for x, y in arc]
    assert unseen_ear_tests(_graph([_pulse("H", h), _red("ear-angle", h, *speck)])) == [
        "play 0 H: angle 0.004 wide"]
    # an ear's green triangle, however thin, is no answer of "no"
    assert unseen_ear_tests(_graph([{**_red("ear-triangle", g, h, k),
                                     "target": {"name": "ear-triangle", "role": "result",
                                                "points": _closed(g, h, k)}}])) == []


def _tinted(name: str, fill: str, opacity: float, polygon: str, under: str,
            under_opacity: float) -> list[dict]:
    shape = _closed((0, 0), (4, 0), (4, 4))
    return [{"type": "FadeIn", "mobject": {"name": polygon, "points": shape, "fill": under,
                                           "fill_opacity": under_opacity}},
            {"type": "FadeIn", "mobject": {"name": name, "points": shape, "fill": fill,
                                           "fill_opacity": opacity}}]


def test_a_good_sub_polygon_in_two_colours_is_found():
    """Chapter 4's prune and search card tinted its good sub-polygon teal over P's navy,
    the run blue over the fruit's orange."""
    card = _tinted("figure:smaller", "#2BB5A8", 0.62, "figure:polygon", "#2A3A55", 0.35)
    run = _tinted("good", "#4F8FF7", 0.3, "polygon", "#F4A259", 0.75)
    assert shifting_tints(_graph(card, run)) == [
        "the good sub-polygon: #247d7a (play 0 figure:smaller), #9b837e (play 1 good)"]
    # mended: the card draws the fruit and tints it as the run does
    card = _tinted("figure:good", "#4F8FF7", 0.3, "figure:polygon", "#F4A259", 0.75)
    assert shifting_tints(_graph(card, run)) == []


def _close_up(fill: str, edge: str, width: float) -> dict:
    parts = [{"type": "Polygon", "fill": fill, "fill_opacity": 0.75, "stroke_width": 0.0},
             {"type": "Line", "stroke": edge, "stroke_width": width},
             {"type": "Line", "stroke": "#58C4DD", "stroke_width": 0.0}]  # unseen: not judged
    return {"type": "UpdateFromAlphaFunc", "mobject": {"name": "close-up", "submobjects": parts}}


def test_a_close_up_in_other_colours_is_found():
    """Chapter 4's gravity close-up drew the fruit in P's navy with white edges."""
    fruit = {"type": "Transform", "mobject": {"name": "polygon", "fill": "#F4A259",
                                              "fill_opacity": 0.75, "stroke": "#7A9E3D",
                                              "stroke_width": 6.6}}
    navy = _graph([fruit], [_close_up("#2A3A55", "#E8ECF2", 3.0)])
    assert recoloured_close_ups(navy) == [
        "play 1: fill #2A3A55 0.75, edges #E8ECF2 3.0 (the picture: fill #F4A259 0.75, edges "
        "#7A9E3D 6.6)"]
    assert recoloured_close_ups(_graph([fruit], [_close_up("#F4A259", "#7A9E3D", 6.6)])) == []


# --- the review of ear clipping (panel7) ----------------------------------------------------------


def test_the_rind_has_a_colour_no_role_has():
    """One colour, one meaning (issue 22 item 4): the rind's olive (#7a9e3d) was 29 (CIE76
    ΔE) from the result's green, the "yes" of every ear test drawn round the fruit it
    outlines; it keeps 40 from every role's colour."""
    from metaphors.theme import THEME
    from story.roles import ROLES

    near = {role: round(delta_e(THEME.rind, THEME.role_colour(role))) for role in ROLES}
    assert min(near.values()) >= 40, near


def test_a_vertex_pulse_keeps_its_label_where_it_stands():
    """Ear clipping's pulses grow the dot, not the label: manim's Indicate scaled the whole
    marker about its middle, and G, its label set off its dot clear of the slices, grew to
    1.6 times its size and flew ~45 px off its vertex (25.0 s of the scene)."""
    from manim import Dot, VGroup

    from metaphors.fruit import Indicate
    from rendering.typeset import text

    label = text("G", font="DejaVu Sans", size=22).move_to((0.3, -0.45, 0))
    marker = VGroup(Dot((0, 0, 0), radius=0.06), label)
    target = Indicate(marker, color="#ef4b4b", scale_factor=1.6).create_target()
    assert math.dist(target[1].get_center(), label.get_center()) < 1e-9
    assert math.isclose(target[1].height, label.height)
    assert math.isclose(target[0].width, 1.6 * marker[0].width)
    assert target[1].get_color().to_hex().lower() == "#ef4b4b"
