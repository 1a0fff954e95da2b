"""Differences between scene graphs in words (trex.graph_diff): play by play, naming the
mobject and both values, plays added or removed counted, never "equal" when they are not."""

import copy
import json
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from trex import graph_diff
from trex.graph_diff import differences, malformed, report

SNAPSHOTS = Path(__file__).parent / "__snapshots__"
GRAVITY = SNAPSHOTS / "test_scenes" / "test_scene_graph_matches_snapshot[gravity.Gravity].json"
FALLBACK = "graph is not a scene graph ("


def line(name="claim", stroke="#83C167", points=((0.0, 0.0, 0.0), (1.0, 0.0, 0.0))):
    return {"type": "Line", "role": "result", "name": name, "stroke": stroke,
            "fill": None, "stroke_width": 4.0, "points": [list(p) for p in points]}


def play(*animations, run_time=1.0, subcaption=None):
    return {"run_time": run_time, "subcaption": subcaption, "animations": list(animations)}


def create(mobject, run_time=1.0):
    return {"type": "Create", "run_time": run_time, "mobject": mobject}


def wait(run_time=1.0):
    return {"type": "Wait", "run_time": run_time,
            "mobject": {"type": "Mobject", "role": None, "name": "Mobject", "points": []}}


def graph(*plays, final=()):
    return {"schema": "trex-scene-graph/1", "plays": list(plays), "final": list(final)}


def test_equal_graphs_have_no_differences():
    g = graph(play(create(line())), play(wait()), final=[line()])
    assert differences(g, copy.deepcopy(g)) == []


def test_run_time_of_a_play():
    old = graph(*[play(wait()) for _ in range(11)], play(create(line())))
    new = copy.deepcopy(old)
    new["plays"][11] = play(create(line(), run_time=1.5), run_time=1.5)
    assert differences(old, new) == ["play 12 (Create claim): run_time 1.0 → 1.5"]


def test_a_colour_names_the_mobject_and_both_colours():
    old = graph(play(wait()), play(create(line())), final=[line()])
    new = graph(play(wait()), play(create(line(stroke="#FC6255"))),
                final=[line(stroke="#FC6255")])
    assert differences(old, new) == [
        'play 2 (Create claim): mobject "claim" stroke #83C167 → #FC6255',
        'final: mobject "claim" stroke #83C167 → #FC6255',
    ]


def test_plays_added_and_removed_are_counted_and_the_rest_still_compared():
    old = graph(*[play(create(line(f"m{k}"))) for k in range(25)])
    new = copy.deepcopy(old)
    new["plays"][20:20] = [play(wait()), play(wait()), play(wait())]
    new["plays"][22 + 3]["run_time"] = 2.0  # old play 23, now 26
    assert differences(old, new) == [
        "3 plays added after play 20: Wait, Wait, Wait",
        "play 23 (Create m22, now play 26): run_time 1.0 → 2.0",
    ]
    del new["plays"][2:4]
    assert differences(old, new)[0] == "plays 3–4 removed: Create m2, Create m3"


def test_a_change_in_many_plays_is_said_once():
    old = graph(*[play(create(line()), create(line("other"))) for _ in range(6)])
    new = copy.deepcopy(old)
    for k in (1, 2, 3, 5):
        new["plays"][k]["animations"][1]["mobject"]["stroke"] = "#FFFFFF"
    assert differences(old, new) == [
        'plays 2–4, 6 (4 plays): mobject "other" stroke #83C167 → #FFFFFF']


def test_parts_that_change_with_their_mobject_are_counted():
    dot = {"type": "Dot", "role": "idle", "name": "Dot", "stroke": "#8A93A3", "points": []}
    label = {"type": "Text", "role": "idle", "name": "Text", "stroke": "#8A93A3", "text": "B",
             "box": [0.0, 0.0, 0.2, 0.2]}
    group = {"type": "VGroup", "role": "idle", "name": "vertex:B", "stroke": "#8A93A3",
             "points": [], "submobjects": [dot, label]}
    old = graph(final=[group])
    new = copy.deepcopy(old)
    for node in (new["final"][0], *new["final"][0]["submobjects"]):
        node["stroke"] = "#4CC46B"
    assert differences(old, new) == [
        'final: mobject "vertex:B" stroke #8A93A3 → #4CC46B (its 2 parts too)']
    new["final"][0]["submobjects"][1]["text"] = "C"
    new["final"][0]["submobjects"][1]["box"] = [0.0, 0.0, 0.25, 0.2]
    assert differences(old, new) == [
        'final: mobject "vertex:B" stroke #8A93A3 → #4CC46B (its part too)',
        'final: mobject "vertex:B" › Text "B" stroke #8A93A3 → #4CC46B, text "B" → "C", '
        "box moved by up to 0.05",
    ]


def test_text_subcaption_points_and_final_mobjects():
    old = graph(play(create(line()), subcaption="B is the left-most vertex"), final=[line()])
    new = graph(play(create(line(points=((0, 0, 0), (1, 0.25, 0)))), subcaption="B, left-most"),
                final=[line(), line("tick")])
    assert differences(old, new) == [
        'play 1 (Create claim): subcaption "B is the left-most vertex" → "B, left-most"',
        'play 1 (Create claim): mobject "claim" points moved by up to 0.25',
        "final: 1 mobject added (tick)",
    ]


def test_report_stops_after_its_limit():
    old = graph(*[play(create(line(f"m{k}"))) for k in range(50)])
    new = copy.deepcopy(old)
    for p in new["plays"]:
        p["animations"][0]["mobject"]["role"] = "rejected"
    lines = report(old, new, limit=10)
    assert len(lines) == 11 and lines[-1] == "… and 40 more differences"
    assert lines[0] == 'play 1 (Create m0): mobject "m0" role result → rejected'


def _leaves(node, path=()):
    if isinstance(node, dict):
        for key, value in node.items():
            yield from _leaves(value, (*path, key))
    elif isinstance(node, list) and node:
        for k, value in enumerate(node):
            yield from _leaves(value, (*path, k))
    else:
        yield path


LEAVES = list(_leaves(json.loads(GRAVITY.read_text())))


@given(st.sampled_from(LEAVES), st.integers(0, 12),
       st.sampled_from([None, 0.5, "#123456", "x", [1.0], {"type": "Dot"}, [], True]))
def test_any_change_to_a_real_graph_is_reported(path, cut, value):
    """A leaf changed, or (``cut``) a whole node replaced by anything, as a file edited by hand
    might be: never "equal", never an exception."""
    path = path[:max(1, len(path) - cut)]
    old = json.loads(GRAVITY.read_text())
    new = copy.deepcopy(old)
    node = new
    for key in path[:-1]:
        node = node[key]
    if node[path[-1]] == value:
        return
    node[path[-1]] = value
    found = differences(old, new)
    assert found and all(len(line) < 400 for line in found), (path, found)
    assert (FALLBACK in found[0]) == (malformed(new) is not None), (path, found)


@pytest.mark.parametrize("cut", [0, 5, 23])
def test_a_removed_play_of_a_real_graph_is_one_line(cut):
    old = json.loads(GRAVITY.read_text())
    new = copy.deepcopy(old)
    del new["plays"][cut]
    found = differences(old, new)
    assert found[0].startswith(f"play {cut + 1} removed: "), found


def test_every_stored_graph_is_shaped_as_the_format_says():
    stored = sorted(SNAPSHOTS.rglob("*.json"))
    assert stored
    assert [(p.name, malformed(json.loads(p.read_text()))) for p in stored] == [
        (p.name, None) for p in stored]


def test_a_malformed_graph_is_compared_field_by_field_and_says_so():
    old = graph(play(create(line()), run_time=1.0))
    new = copy.deepcopy(old)
    new["plays"][0]["run_time"] = 1.5
    new["plays"][0]["animations"][0]["mobject"]["points"] = [[0.0, 0.0]]
    assert differences(old, new) == [
        "the new graph is not a scene graph (plays[0].animations[0].mobject.points is not a "
        "list of [x, y, z]): compared field by field",
        "plays[0].animations[0].mobject.points: [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]] → "
        "[[0.0, 0.0]]",
        "plays[0].run_time: 1.0 → 1.5"]
    assert differences(new, old)[0].startswith("the stored graph is not a scene graph (")


def test_a_bug_in_the_comparison_is_not_hidden(monkeypatch):
    """Two well-formed graphs: an error inside the comparison raises, rather than turning
    into a field-by-field diff that looks like an answer."""
    def broken(old, new):
        raise TypeError("a bug in the differ")

    monkeypatch.setattr(graph_diff, "_play_changes", broken)
    old = graph(play(create(line())))
    new = graph(play(create(line(stroke="#FC6255"))))
    with pytest.raises(TypeError, match="a bug in the differ"):
        differences(old, new)
