"""The storyboard reads the log only: a saved and reloaded log gives the very same beats."""

import pytest

import tracing
from metaphors.catalog import beats as storyboard
from story.runs import run_logged

RUNS = [
    ("scaling", "counterexample", None),
    ("rotation-ccw", "counterexample-twin", None),
    ("translation-correct", "lecture", None),
    ("scaling-walled", "counterexample", None),
    ("gravity", "gravity-snag", None),
    ("divide-and-conquer", "lecture", "gravity"),
    ("ear-clipping-naive", "lecture", None),
    ("ear-clipping", "lecture", None),
]


@pytest.mark.parametrize(("algorithm", "polygon", "heuristic"), RUNS)
def test_replayed_log_gives_the_same_beats(algorithm, polygon, heuristic):
    log = run_logged(algorithm, polygon, heuristic)
    again = tracing.Log.from_json(log.to_json())
    assert [b.to_dict() for b in storyboard(again)] == [b.to_dict() for b in storyboard(log)]


def test_call_lines_keep_argument_order_after_replay():
    log = tracing.Log.from_json(run_logged("gravity", "gravity-snag").to_json())
    calls = [b.call for b in storyboard(log) if b.action == "drop"]
    assert calls and calls[0].startswith("drop_ball(P, C, ")


def test_fruit_beats_count_every_slice():
    beats = storyboard(run_logged("ear-clipping-naive", "lecture"))
    slices = [b for b in beats if b.action in ("clip", "last-slice")]
    assert [b.data["k"] for b in slices] == list(range(1, 12))
    assert slices[-1].action == "last-slice" and slices[-1].data["rest"] == ()
    assert all(b.data["total"] == 11 for b in slices)


@pytest.mark.parametrize("algorithm", ["ear-clipping-naive", "ear-clipping", "prune-and-search"])
@pytest.mark.parametrize("polygon", ["lecture", "comb", "random-2opt:12:7", "random-comb:14:3"])
def test_a_vertex_that_is_no_ear_shows_why(algorithm, polygon):
    """Issue 22 item 5: "Is B an ear? no" names a vertex in B's triangle (which the fruit
    scene pulses inside the triangle drawn), or says B is not convex and how wide its angle
    is (the scene draws the angle); checked exactly."""
    from geometry.batch import in_closed_triangle
    from geometry.io import read_polygon
    from geometry.predicates import orient

    p = read_polygon(polygon)
    where = dict(zip(p.labels, p.points, strict=True))
    tests = [b for b in storyboard(run_logged(algorithm, polygon)) if b.action == "ear-test"]
    assert any(not b.data["ear"] for b in tests)
    for b in tests:
        if b.data["ear"]:
            # an ear's triangle is drawn too (green, empty, until its slice takes it)
            a, v, c = (tuple(q) for q in b.data["triangle"])
            assert v == where[b.data["vertex"]] and b.data["inside"] is None
            assert orient(a, v, c) > 0
            continue
        a, v, c = (tuple(q) for q in b.data["triangle"])
        assert v == where[b.data["vertex"]]
        inside = b.data["inside"]
        if inside is None:  # its angle, drawn, is said: 180° exactly when straight
            assert orient(a, v, c) <= 0
            said = f"is not convex, its angle is {'180°' if orient(a, v, c) == 0 else 'over 180°'}"
        else:
            assert orient(a, v, c) > 0 and where[inside] not in (a, v, c)
            assert in_closed_triangle(where[inside], a, v, c), b.caption
            said = f"{inside} lies in its triangle"
        # a beat played fast, several under one caption ("Slices 3–7: …"), says no more
        assert b.caption.endswith(said) or not b.caption.startswith("Is "), b.caption
