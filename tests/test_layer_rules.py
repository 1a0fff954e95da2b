"""The drawing-order rules can fail: each is tried on a small graph made by hand with the
defect a viewer saw (chapter 1's whole triangulation drawn over the labels M and G, which
it tinted) and on the same graph mended."""

from __future__ import annotations

from tests.reading_rules import fills_over_labels, shifting_colours
from tests.test_tool_rules import POLYGON, _closed, _graph

LABEL_M = {"name": "vertex:M", "submobjects": [{"type": "Dot"}, {"text": "M",
                                                                 "box": [1.0, 1.0, 1.3, 1.3]}]}
#: a triangle of the whole triangulation, its fill over M's label
TRIANGLE = {"name": "triangulation", "type": "Polygon", "fill": "#8E6CF0",
            "fill_opacity": 0.35, "points": _closed((0, 0), (3, 0), (0, 3))}


def _on_top(node: dict, z: float) -> dict:
    """``node`` and its parts at z-index ``z``."""
    return {**node, "z": z, "submobjects": [{**p, "z": z} for p in node.get("submobjects", ())]}


def test_a_fill_that_comes_after_a_label_it_covers_is_found():
    graph = _graph([{"type": "Create", "mobject": POLYGON}, {"type": "FadeIn", "mobject": LABEL_M}],
                   [{"type": "FadeIn", "mobject": TRIANGLE}])
    assert fills_over_labels(graph) == ["play 1 triangulation over M"]


def test_a_label_over_the_fill_or_clear_of_it_passes():
    on_top = _graph([{"type": "FadeIn", "mobject": _on_top(LABEL_M, 5)}],
                    [{"type": "FadeIn", "mobject": TRIANGLE}])
    under = _graph([{"type": "FadeIn", "mobject": LABEL_M}],
                   [{"type": "FadeIn", "mobject": _on_top(TRIANGLE, -1)}])
    clear = _graph([{"type": "FadeIn", "mobject": LABEL_M}],
                   [{"type": "FadeIn", "mobject": {**TRIANGLE, "points": _closed((3, 3), (4, 3),
                                                                                 (4, 4))}}])
    assert fills_over_labels(on_top) == fills_over_labels(under) == fills_over_labels(clear) == []


def test_a_fill_that_came_before_the_label_passes():
    graph = _graph([{"type": "FadeIn", "mobject": TRIANGLE}], [{"type": "FadeIn", "mobject": LABEL_M}])
    assert fills_over_labels(graph) == []


def _marker(vertex: str, role: str, kind: str = "_MethodAnimation") -> dict:
    return {"type": kind, "mobject": {"name": f"vertex:{vertex}", "role": role}}


def _said(caption: str, *anims: dict) -> dict:
    return {"animations": list(anims), "run_time": 1.0, "subcaption": caption}


def test_a_candidate_in_a_claims_colour_before_its_time_is_found():
    """Chapter 2's run: the candidates lit green, the first wetted green and the one not hit
    amber, before any claim."""
    plays = [_said("Candidates inside T: E, F", _marker("E", "result"), _marker("F", "result")),
             _said("Water spilled at B spreads; the first candidate it wets is E",
                   _marker("E", "result"), _marker("F", "argument")),
             _said("Claim: BE is an inner diagonal", _marker("E", "argument")),
             _said("✓ BE is an inner diagonal", _marker("E", "result"))]
    assert shifting_colours({"plays": plays}) == [
        "play 0 E green before a verdict", "play 0 F green before a verdict",
        "play 1 F amber, not picked"]


def test_candidates_neutral_the_pick_amber_and_green_once_judged_pass():
    plays = [_said("Candidates inside T: E, F", _marker("E", "candidate"),
                   _marker("F", "candidate")),
             _said("Water spilled at B spreads; the first candidate it wets is E",
                   _marker("E", "argument"), _marker("F", "candidate")),
             _said("Claim: BE is an inner diagonal", _marker("E", "argument")),
             _said("✓ BE is an inner diagonal", _marker("E", "result"))]
    assert shifting_colours({"plays": plays}) == []


def _pulse(vertex: str, colour: str) -> dict:
    return {"type": "Indicate", "color": colour,
            "mobject": {"name": f"vertex:{vertex}", "role": "candidate"}}


def test_candidates_pulsed_in_the_claims_amber_are_found():
    """Review s567: a run of one's own pulsed its candidates amber ("Candidates inside T: D,
    E", the claim's colour) while the panel showed them pink; the pulse's colour is in the
    animation, not in its mobject. Pulsed pink, they pass."""
    from metaphors.theme import THEME

    def plays(colour: str) -> list[dict]:
        return [_said("Candidates inside T: D, E", _pulse("D", colour), _pulse("E", colour)),
                _said("Distance to C for D: 2.2", _marker("D", "argument")),
                _said("Claim: BE is an inner diagonal", _marker("E", "argument"))]

    assert shifting_colours({"plays": plays(THEME.argument)}) == [
        "play 0 D amber, not picked", "play 0 E amber, not picked"]
    assert shifting_colours({"plays": plays(THEME.candidate)}) == []


def test_a_vertex_turned_grey_unsaid_is_found_and_said_passes():
    """Over3 item 2: chapter 1's split left the diagonal's ends grey, never explained."""
    from tests.reading_rules import unexplained_grey

    def greyed(caption: str) -> dict:
        target = {"name": "vertex:D", "fill": "#8A93A3"}
        return _said(caption, {"type": "_MethodAnimation",
                               "mobject": {"name": "vertex:D"}, "target": target})

    split = "Split along the diagonal into two smaller polygons"
    assert unexplained_grey({"plays": [greyed(split)]}) == ["play 0 D grey, unsaid"]
    said = "Find an inner diagonal of this polygon: grey vertices are not in it"
    assert unexplained_grey({"plays": [_said(said), greyed(split)]}) == []
