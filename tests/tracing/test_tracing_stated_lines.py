"""Code that records on behalf of someone else's function: ``tracing.at_line`` states the
line of the events made in its block, ``tracing.events_so_far`` reads the log so far."""

import threading
from pathlib import Path

import pytest

import tracing
from tracing.recorder import ACTIVE_RECORDER


def line_of(marker: str) -> int:
    """Line number of the single line of this file ending in ``# <marker>``."""
    lines = Path(__file__).read_text(encoding="utf-8").splitlines()
    hits = [n for n, text in enumerate(lines, 1) if text.endswith(f"# {marker}")]
    assert len(hits) == 1, marker
    return hits[0]


@tracing.traced
def claim(key):
    with tracing.Shape(key, "segment", points=[[0, 0], [1, 1]]):  # inside claim
        tracing.note("claimed", key=key)  # note in claim
    return key


@tracing.traced
def wrapper(key, line):
    with tracing.at_line(line):
        return claim(key)


def test_without_a_recording_nothing_happens():
    before = ACTIVE_RECORDER.get()
    with tracing.at_line(12):
        assert ACTIVE_RECORDER.get() is before is None
        assert claim("AB") == "AB"
    assert tracing.events_so_far() == ()


def test_the_stated_line_goes_to_the_events_at_the_blocks_depth_only():
    with tracing.record() as log:
        wrapper("BE", 39)  # the call of wrapper
    assert [(e.kind, e.name, e.depth, e.line) for e in log.events] == [
        ("call", "wrapper", 0, line_of("the call of wrapper")),
        ("call", "claim", 1, 39),
        ("enter", "segment", 2, line_of("inside claim")),
        ("note", "claimed", 2, line_of("note in claim")),
        ("exit", "segment", 2, line_of("inside claim")),
        ("return", "claim", 1, 39),
        ("return", "wrapper", 0, line_of("the call of wrapper")),
    ]
    assert ACTIVE_RECORDER.get() is None


def test_the_stated_line_goes_to_lifetimes_and_notes_made_in_the_block():
    shape = tracing.Shape("S", "point", at=[0, 0])
    with tracing.record() as log:
        with tracing.at_line(7):
            tracing.enter(shape)
            shape.update(at=[1, 1])
            with tracing.alive(tracing.Shape("T", "point", at=[2, 2])):
                tracing.note("seen")
            tracing.exit(shape)
        tracing.note("after")  # not stated
    assert [(e.kind, e.target or e.name, e.line) for e in log.events] == [
        ("enter", "S", 7), ("change", "S", 7), ("enter", "T", 7), ("note", "seen", 7),
        ("exit", "T", 7), ("exit", "S", 7), ("note", "after", line_of("not stated")),
    ]  # fmt: skip


def test_none_states_nothing():
    with tracing.record() as log, tracing.at_line(None):
        claim("AC")  # unstated call
    assert [e.line for e in log.events if e.name == "claim"] == [line_of("unstated call")] * 2


def test_a_call_that_raises_in_the_block_returns_on_the_stated_line():
    @tracing.traced
    def fails():
        raise ValueError("no")

    with tracing.record() as log:
        with pytest.raises(ValueError), tracing.at_line(5):
            fails()
        tracing.note("later")  # after the failed block
    assert [(e.kind, e.result, e.line) for e in log.events] == [
        ("call", None, 5), ("return", {"raised": "ValueError"}, 5),
        ("note", None, line_of("after the failed block")),
    ]  # fmt: skip
    assert ACTIVE_RECORDER.get() is None


def test_blocks_nest_and_an_inner_recording_is_its_own():
    with tracing.record() as outer, tracing.at_line(10):
        tracing.note("ten")
        with tracing.at_line(20):
            tracing.note("twenty")
            with tracing.record() as inner:
                tracing.note("inner")  # inner's own line
        tracing.note("ten again")
    assert [(e.name, e.line) for e in outer.events] == [
        ("ten", 10), ("twenty", 20), ("ten again", 10),
    ]  # fmt: skip
    assert [(e.name, e.line) for e in inner.events] == [("inner", line_of("inner's own line"))]


def test_events_so_far_is_a_snapshot_of_the_innermost_recording():
    with tracing.record() as outer:
        claim("AB")
        seen = tracing.events_so_far()
        with tracing.record():
            assert tracing.events_so_far() == ()
        tracing.note("later")
    assert isinstance(seen, tuple)
    assert [e.seq for e in seen] == [0, 1, 2, 3, 4]
    assert list(seen) == outer.events[:5] and len(outer.events) == 6


def test_a_thread_does_not_see_another_threads_stated_line():
    lines = []

    def other():
        with tracing.record() as log:
            tracing.note("there")  # the other thread's line
        lines.append(log.events[0].line)

    with tracing.record() as log, tracing.at_line(3):
        thread = threading.Thread(target=other)
        thread.start()
        thread.join()
        tracing.note("here")
    assert lines == [line_of("the other thread's line")]
    assert log.events[0].line == 3

