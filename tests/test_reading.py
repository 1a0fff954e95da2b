"""Issue 12's captions of repeated steps (story.reading): a summary never hides a failing
verdict, and "the frame as before" is said only of a frame the viewer saw."""

from __future__ import annotations

import pytest

from metaphors import catalog
from story.beats import Candidates, Verdict
from story.reading import frame_key, frame_summarised, summarised
from story.spec import RunSpec
from tests.test_scenes import SCENES_DIR
from trex.render_command import load_scene_class
from trex.snapshot import build


def _beats(algorithm: str, polygon: str):
    return catalog.beats(RunSpec(algorithm, polygon).log())


def test_a_frame_is_the_same_only_on_the_same_polygon():
    water, clock = _beats("scaling", "counterexample"), _beats("rotation", "counterexample")
    twin = _beats("rotation-ccw", "counterexample-twin")
    assert frame_key(water) == frame_key(clock) is not None
    assert frame_key(twin) != frame_key(water)


def test_only_the_first_frame_of_a_run_is_summarised():
    beats = _beats("scaling", "counterexample")
    shown = frame_summarised(beats)
    first = next(k for k, b in enumerate(beats) if isinstance(b, Candidates))
    assert {b.caption for b in shown[:first + 1]} == {"The frame as before: candidates D, E"}
    assert [b.caption for b in shown[first + 1:]] == [b.caption for b in beats[first + 1:]]


def test_the_counterexample_scene_says_each_frame_once():
    """Eight runs on two polygons (the counterexample and its mirror image): each polygon's
    first run draws it under what the scene says of it (its point; the mirror image), the
    runs after it go on on it, their T and candidates said in one caption naming the rule
    ("Correct Scaling, on the same polygon: …"); nothing is "as before" (it was said as the
    mirror image gave way to the polygon)."""
    cls = load_scene_class(SCENES_DIR / "counterexample.py", "Counterexample")
    cues = [c["text"] for c in build(cls.handed()).data["cues"]]
    going_on = [c for c in cues if ", on the same " in c]
    assert len(going_on) == len(cls.runs) - 2 == len(set(going_on))
    assert [c for c in cues if c.startswith(("One ", "Its mirror image"))] == [
        cues[0], next(c for c in cues if c.startswith("Its mirror image"))]
    assert not any("as before" in c for c in cues)


@pytest.mark.parametrize("failing_at", [2, 4])
def test_a_failing_verdict_keeps_its_caption(failing_at):
    verdicts = [Verdict(caption=f"verdict {k}", seq=k, ok=k != failing_at, labels=("B", "D"),
                        why="", code="")
                for k in range(6)]
    shown = summarised(verdicts, list(range(6)), 1, "diagonal")  # verdict k made at k claims
    assert shown[failing_at].caption == f"verdict {failing_at}"
    assert all(b.caption == f"verdict {k}" for k, b in enumerate(shown) if k >= failing_at)
    assert shown[0].caption == "verdict 0"  # before the summaries start
