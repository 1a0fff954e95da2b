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
    assert slices[-1].action == "last-slice" and slices[-1].data["rest"] == []
    assert all(b.data["total"] == 11 for b in slices)
