"""The reading rules on the metaphors' moving tools can fail: each is tried on a small graph
made by hand with the defect a viewer saw (a note crossed by the sweep, the clock's face over
B, a line through a label, Correct Scaling's water outside P, a card's swept blue outside P)
and on the same graph mended."""

from __future__ import annotations

import math

from tests.reading_rules import (
    labels_under_faces,
    labels_under_tools,
    notes_over_fills,
    notes_under_moving_tools,
    swept_outside_polygon,
    water_outside_polygon,
)


def _closed(*corners: tuple[float, float]) -> list[list[float]]:
    """The points of a closed polygon as manim writes them: one cubic segment per edge."""
    points = []
    for (x0, y0), (x1, y1) in zip(corners, (*corners[1:], corners[0]), strict=True):
        points += [[x0, y0, 0.0], [x0, y0, 0.0], [x1, y1, 0.0], [x1, y1, 0.0]]
    return points


def _line(a: tuple[float, float], b: tuple[float, float]) -> list[list[float]]:
    return [[a[0], a[1], 0.0], [a[0], a[1], 0.0], [b[0], b[1], 0.0], [b[0], b[1], 0.0]]


POLYGON = {"name": "polygon", "type": "Polygon", "points": _closed((0, 0), (4, 0), (4, 4), (0, 4))}
LABEL_B = {"name": "vertex:B", "submobjects": [{"type": "Dot"}, {"text": "B",
                                                                 "box": [-0.4, -0.1, -0.2, 0.1]}]}


def _graph(*plays: list[dict]) -> dict:
    return {"plays": [{"animations": anims, "run_time": 1.0} for anims in plays]}


def _note(kind: str, box: list[float]) -> dict:
    return {"type": kind, "mobject": {"name": "astray:note", "text": "outside P, inside T",
                                      "box": box}}


def _sweep(x0: float, x1: float) -> dict:
    return {"type": "_MethodAnimation", "mobject": {"name": "sweep", "points": _line((x0, -50), (x0, 50))},
            "target": {"name": "sweep", "points": _line((x1, -50), (x1, 50))}}


def test_a_note_the_line_will_sweep_over_is_found():
    seen = [{"type": "Create", "mobject": POLYGON}]
    crossed = _graph(seen, [_note("FadeIn", [1.2, 1.0, 3.0, 1.3])], [_sweep(1.0, 2.0)])
    beside = _graph(seen, [_note("FadeIn", [-1.8, 1.0, 0.8, 1.3])], [_sweep(1.0, 2.0)])
    gone = _graph(seen, [_note("FadeIn", [1.2, 1.0, 3.0, 1.3])],
                  [_note("FadeOut", [1.2, 1.0, 3.0, 1.3])], [_sweep(1.0, 2.0)])
    # beyond the picture's box the line is not drawn
    far = _graph(seen, [_note("FadeIn", [1.2, 6.0, 3.0, 6.3])], [_sweep(1.0, 2.0)])
    assert notes_under_moving_tools(crossed) == ["'outside P, inside T' under the sweep"]
    assert notes_under_moving_tools(beside) == notes_under_moving_tools(gone) \
        == notes_under_moving_tools(far) == []


def test_a_note_or_a_legend_over_the_picture_is_found():
    """Issue 22, no text over the picture: Translation's "outside P, inside T" stood inside P,
    over its fill; a legend entry beside the picture, or a note gone before P comes, is not."""
    seen = [{"type": "Create", "mobject": POLYGON}]
    triangle = {"type": "Create", "mobject": {"name": "T", "type": "Polygon",
                                              "points": _closed((4, 0), (6, 0), (4, 2))}}

    def entry(kind: str, left: float, bottom: float) -> dict:
        return {"type": kind, "mobject": {"name": "legend:astray", "submobjects": [
            {"type": "Square", "points": _closed((left, bottom), (left + 0.3, bottom),
                                                 (left + 0.3, bottom + 0.3),
                                                 (left, bottom + 0.3))},
            {"text": "outside P, in T", "box": [left + 0.48, bottom, left + 2.6, bottom + 0.3]}]}}

    over = _graph(seen, [_note("FadeIn", [1.0, 1.0, 3.0, 1.5])])
    assert notes_over_fills(over) == ["play 1 'outside P, inside T': 1.00 over the picture"]
    # T's fill counts as the picture too
    assert notes_over_fills(_graph(seen, [triangle], [entry("FadeIn", 4.1, 0.1)])) \
        == ["play 2 'outside P, in T': 0.50 over the picture"]
    assert notes_over_fills(_graph(seen, [triangle], [entry("FadeIn", -3.0, 5.0)])) == []
    # going off over the picture is no text coming in over it; nor one before any picture
    assert notes_over_fills(_graph(seen, [_note("FadeOut", [1.0, 1.0, 3.0, 1.5])])) == []
    assert notes_over_fills(_graph([_note("FadeIn", [1.0, 1.0, 3.0, 1.5])])) == []


def test_a_note_the_hand_will_turn_over_is_found():
    hand = {"type": "Rotate", "mobject": {"name": "hand", "points": _line((0, 0), (4, 0))}}
    ring = {"type": "FadeIn", "mobject": {"name": "lit:E", "points": [[3, 3, 0], [3, 3, 0]]}}
    seen = [{"type": "Create", "mobject": POLYGON}]
    crossed = _graph(seen, [_note("FadeIn", [2.0, 0.5, 3.0, 0.8])], [hand], [ring])
    behind = _graph(seen, [_note("FadeIn", [2.0, -0.8, 3.0, -0.5])], [hand], [ring])
    assert notes_under_moving_tools(crossed) == ["'outside P, inside T' under the hand"]
    assert notes_under_moving_tools(behind) == []


def test_a_face_over_a_label_is_found():
    seen = [{"type": "Create", "mobject": POLYGON}, {"type": "FadeIn", "mobject": LABEL_B}]
    disk = {"name": "dial", "points": _closed((-0.55, -0.55), (0.55, -0.55), (0.55, 0.55),
                                              (-0.55, 0.55))}
    fan = {"name": "dial", "points": _closed((0, 0), (0.55, 0), (0.39, 0.39))}
    assert labels_under_faces(_graph(seen, [{"type": "FadeIn", "mobject": disk}])) \
        == ["the dial covers B"]
    assert labels_under_faces(_graph(seen, [{"type": "FadeIn", "mobject": fan}])) == []


def test_a_line_through_a_label_is_found():
    seen = [{"type": "Create", "mobject": POLYGON}, {"type": "FadeIn", "mobject": LABEL_B}]

    def drawn(*pieces):
        return {"type": "FadeOut", "mobject": {"name": "VGroup", "submobjects": [
            {"name": "sweep:outside", "submobjects": [
                {"points": _line(a, b), "stroke_opacity": 1.0} for a, b in pieces]}]}}

    through = drawn(((-1.0, 0.0), (1.0, 0.0)))
    around = drawn(((-1.0, 0.0), (-0.44, 0.0)), ((-0.16, 0.0), (1.0, 0.0)))
    assert labels_under_tools(_graph(seen, [through])) == ["the sweep runs through B"]
    assert labels_under_tools(_graph(seen, [around])) == []


WATER, SWEPT, RED = "#3AA0FF", "#8FC1FF", "#EF4B4B"  # metaphors.theme.THEME's, as written


def _filled(name: str, colour: str, *corners: tuple[float, float]) -> dict:
    return {"name": name, "fill": colour, "fill_opacity": 0.3, "points": _closed(*corners)}


def test_water_outside_the_polygon_is_found_whatever_its_name():
    """The old chapter 2's rising water was an analysis's region whose placeholder line had
    become it (``become`` keeps the type and name): a "Line" in a group "swept", in water
    colour, recorded as it faded out; a rule matching the name "flood" missed it."""
    seen = [{"type": "Create", "mobject": POLYGON}]

    def fading(shape: dict) -> dict:
        return {"type": "FadeOut", "mobject": {"name": "analysis:tool", "submobjects": [
            {"name": "swept", "submobjects": [shape]}]}}

    astray = fading(_filled("Line", WATER, (3, 3), (5, 3), (5, 5), (3, 5)))  # 3 of 4 outside
    inside = fading(_filled("Line", WATER, (1, 1), (3, 1), (3, 3)))
    grown = {"type": "Transform", "mobject": {"name": "flood", "points": []},
             "target": _filled("flood", WATER, (3, 3), (5, 3), (5, 5), (3, 5))}
    assert water_outside_polygon(_graph(seen, [astray])) == ["play 1 FadeOut Line: 3.00 outside P"]
    assert water_outside_polygon(_graph(seen, [grown])) == ["play 1 Transform flood: 3.00 outside P"]
    assert water_outside_polygon(_graph(seen, [inside])) == []
    # not water: another colour; the legend's swatch beside the picture
    red = fading(_filled("Line", RED, (3, 3), (5, 3), (5, 5)))
    assert water_outside_polygon(_graph(seen, [red])) == []
    swatch = {"type": "FadeIn", "mobject": {"name": "legend:water", "submobjects": [
        _filled("Square", WATER, (6, 6), (6.3, 6), (6.3, 6.3), (6, 6.3))]}}
    assert water_outside_polygon(_graph(seen, [swatch])) == []


def test_water_spilt_at_a_vertex_spreads_over_the_edges():
    """Scaling's disk round B is its metaphor (the analysis turns its part outside P red);
    a disk round a point that is no vertex of P is judged."""
    def disk(x: float, y: float) -> dict:
        corners = [(x + 2 * math.cos(k * math.pi / 32), y + 2 * math.sin(k * math.pi / 32))
                   for k in range(64)]
        return {"type": "FadeOut", "mobject": _filled("water", WATER, *corners)}

    seen = [{"type": "Create", "mobject": POLYGON}]
    assert water_outside_polygon(_graph(seen, [disk(0, 0)])) == []
    assert water_outside_polygon(_graph(seen, [disk(0.5, 0.5)])) \
        == ["play 1 FadeOut water: 7.18 outside P"]


def test_a_swept_region_outside_p_must_turn_red():
    """A card's figure shaded what the hand swept in the swept blue, outside P too; the
    analysis shows that part red once the tool stops."""
    card = [{"type": "FadeIn", "mobject": {**POLYGON, "name": "figure:polygon"}}]
    swept = {"type": "FadeIn", "mobject": {"name": "figure:tool", "submobjects": [
        _filled("Polygon", SWEPT, (3, 3), (5, 3), (5, 5), (3, 5))]}}
    red = {"type": "FadeIn", "mobject": _filled("analysis:outside", RED, (4, 3), (5, 3), (5, 5),
                                                  (3, 5), (3, 4), (4, 4))}
    clipped = {"type": "FadeIn", "mobject": {"name": "figure:tool", "submobjects": [
        _filled("Polygon", SWEPT, (3, 3), (4, 3), (4, 4), (3, 4))]}}
    assert swept_outside_polygon(_graph(card, [swept])) \
        == ["play 0 figure:polygon: 3.00 outside P"]
    assert swept_outside_polygon(_graph(card, [clipped])) == []
    # an analysis: the part outside P turned red, all of it or not
    seen = [{"type": "FadeIn", "mobject": {**POLYGON, "name": "analysis:polygon"}}]
    assert swept_outside_polygon(_graph(seen, [swept], [red])) == []
    half = {"type": "FadeIn", "mobject": _filled("analysis:outside", RED, (4, 3), (5, 3),
                                                   (5, 5), (4, 5))}
    assert swept_outside_polygon(_graph(seen, [swept], [half])) \
        == ["play 0 analysis:polygon: 1.00 outside P"]
