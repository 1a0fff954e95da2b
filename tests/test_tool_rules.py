"""The reading rules on the metaphors' moving tools can fail: each is tried on a small graph
made by hand with the defect a viewer saw (a note crossed by the sweep, the clock's face over
B, a line through a label, Correct Scaling's water outside P) and on the same graph mended."""

from __future__ import annotations

from tests.reading_rules import (
    labels_under_faces,
    labels_under_tools,
    notes_under_moving_tools,
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


def test_rising_water_outside_the_polygon_is_found():
    seen = [{"type": "Create", "mobject": POLYGON}]

    def water(*corners):
        return {"type": "Transform", "mobject": {"name": "flood", "points": []},
                "target": {"name": "flood", "points": _closed(*corners)}}

    spilt = water((3, 3), (5, 3), (5, 5), (3, 5))  # 3 of its 4 square units outside P
    inside = water((1, 1), (3, 1), (3, 3))
    assert water_outside_polygon(_graph(seen, [spilt])) == ["flood: 3.00 outside P"]
    assert water_outside_polygon(_graph(seen, [inside])) == []
