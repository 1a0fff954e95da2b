"""The recorder: no-op without a recording, nesting, lifetimes, notes, line numbers."""

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


class Untouchable:
    """A traceable whose state must not be asked for when nothing records."""

    trace_key = "U"

    def trace_state(self):
        raise AssertionError("trace_state called without a recording")


@tracing.traced
def double(x):
    return 2 * x


def test_everything_is_a_no_op_without_a_recording():
    obj = Untouchable()
    assert ACTIVE_RECORDER.get() is None
    assert double(4) == 8
    assert tracing.enter(obj) is None
    assert tracing.change(obj) is None
    assert tracing.exit(obj) is None
    assert tracing.note("x", a=object()) is None
    with tracing.alive(obj) as same:
        assert same is obj
    shape = tracing.Shape("S", "circle", radius=1)
    with shape as entered:
        entered.update(radius=2)
    assert shape.fields == {"radius": 2}
    assert ACTIVE_RECORDER.get() is None


def test_recording_collects_and_then_stops():
    with tracing.record(algorithm="demo", sizes=(1, 2), when=float("inf")) as log:
        double(1)
    double(2)
    assert isinstance(log, tracing.Log)
    assert log.meta == {"algorithm": "demo", "sizes": [1, 2], "when": "inf"}
    assert [(e.seq, e.kind, e.args, e.result) for e in log.events] == [
        (0, "call", {"x": 1}, None),
        (1, "return", None, 2),
    ]
    assert ACTIVE_RECORDER.get() is None


def test_a_recording_opens_only_once():
    recording = tracing.record()
    with recording:
        pass
    with pytest.raises(RuntimeError, match="opened only once"), recording:
        pass


def test_nested_recordings_take_turns():
    with tracing.record(name="a") as a:
        tracing.note("a1")
        with tracing.record(name="b") as b:
            tracing.note("b1")
            double(3)
        tracing.note("a2")
    assert [(e.seq, e.name) for e in a.events] == [(0, "a1"), (1, "a2")]
    assert [(e.seq, e.kind, e.name) for e in b.events] == [
        (0, "note", "b1"), (1, "call", "double"), (2, "return", "double"),
    ]  # fmt: skip


def test_inner_recording_inside_a_traced_call():
    @tracing.traced
    def outer():
        with tracing.record() as inner:
            double(5)
        return inner

    with tracing.record() as log:
        inner = outer()
    assert [(e.kind, e.name, e.depth, e.call) for e in log.events] == [
        ("call", "outer", 0, 0), ("return", "outer", 0, 0),
    ]  # fmt: skip
    assert [(e.kind, e.name, e.depth, e.call) for e in inner.events] == [
        ("call", "double", 0, 0), ("return", "double", 0, 0),
    ]  # fmt: skip


def test_recording_is_closed_after_an_exception():
    with pytest.raises(KeyError), tracing.record():
        raise KeyError("x")
    assert ACTIVE_RECORDER.get() is None


def test_lifetime_events_and_state():
    point = tracing.Shape("P", "point", at=(1, 2))
    with tracing.record() as log:
        tracing.enter(point)
        point.fields["at"] = [3.5, 4]
        tracing.change(point)
        tracing.exit(point)
    assert [(e.seq, e.kind, e.name, e.target, e.state) for e in log.events] == [
        (0, "enter", "point", "P", {"kind": "point", "at": [1, 2]}),
        (1, "change", "point", "P", {"kind": "point", "at": [3.5, 4]}),
        (2, "exit", "point", "P", None),
    ]
    assert [log.state_at(i) for i in range(3)] == [
        {"P": {"kind": "point", "at": [1, 2]}}, {"P": {"kind": "point", "at": [3.5, 4]}}, {},
    ]  # fmt: skip


def test_recorded_state_is_a_snapshot():
    shape = tracing.Shape("poly", "polygon", points=[[0, 0], [1, 0], [0, 1]])
    with tracing.record() as log:
        tracing.enter(shape)
        shape.fields["points"].append([5, 5])
    assert log.events[0].state == {"kind": "polygon", "points": [[0, 0], [1, 0], [0, 1]]}


def test_state_without_kind_is_named_object():
    class Blob:
        trace_key = "blob"

        def trace_state(self):
            return {"size": 3}

    with tracing.record() as log:
        tracing.enter(Blob())
        tracing.exit(Blob())
    assert [(e.kind, e.name) for e in log.events] == [("enter", "object"), ("exit", "object")]


def test_exit_without_enter_asks_for_the_kind():
    with tracing.record() as log:
        tracing.exit(tracing.Shape("R", "ray"))
    assert (log.events[0].kind, log.events[0].name) == ("exit", "ray")


def test_bad_trace_state_is_an_error():
    class Bad:
        trace_key = "bad"

        def trace_state(self):
            return ["not", "a", "dict"]

    with pytest.raises(TypeError, match=r"Bad.trace_state\(\) must return a dict"), \
            tracing.record():  # fmt: skip
        tracing.enter(Bad())


def test_shape_rejects_kind_field():
    with pytest.raises(ValueError, match="kind is its second argument"):
        tracing.Shape("S", "circle", kind="ray")
    with pytest.raises(ValueError, match="kind is its second argument"):
        tracing.Shape("S", "circle").update(kind="ray")


def test_note_data_is_encoded():
    with tracing.record() as log:
        tracing.note("fallback", reason="convex", diagonal=("A", "C"), kind="k", w=object())
    event = log.events[0]
    assert (event.kind, event.name, event.target) == ("note", "fallback", None)
    assert event.args == {"reason": "convex", "diagonal": ["A", "C"], "kind": "k",
                          "w": {"type": "object"}}  # fmt: skip


def test_depth_and_call_of_events_inside_calls():
    @tracing.traced
    def outer():
        tracing.note("in-outer")
        inner()

    @tracing.traced
    def inner():
        tracing.note("in-inner")

    with tracing.record() as log:
        tracing.note("top")
        outer()
    assert [(e.seq, e.kind, e.name, e.depth, e.call) for e in log.events] == [
        (0, "note", "top", 0, None),
        (1, "call", "outer", 0, 1),
        (2, "note", "in-outer", 1, 1),
        (3, "call", "inner", 1, 3),
        (4, "note", "in-inner", 2, 3),
        (5, "return", "inner", 1, 3),
        (6, "return", "outer", 0, 1),
    ]


def test_line_numbers_of_lifetime_and_note_events():
    water = tracing.Shape("W", "circle", radius=0.0)
    point = tracing.Shape("P", "point", at=[0, 0])
    with tracing.record() as log:
        with water:  # with-water
            water.update(radius=1.0)  # update-water
            tracing.enter(point)  # enter-point
            tracing.change(point)  # change-point
            tracing.note("hi")  # note-hi
            tracing.exit(point)  # exit-point
        with tracing.alive(  # alive-point
            point,
        ):
            pass
    assert [(e.kind, e.target, e.line) for e in log.events] == [
        ("enter", "W", line_of("with-water")),
        ("change", "W", line_of("update-water")),
        ("enter", "P", line_of("enter-point")),
        ("change", "P", line_of("change-point")),
        ("note", None, line_of("note-hi")),
        ("exit", "P", line_of("exit-point")),
        ("exit", "W", line_of("with-water")),
        ("enter", "P", line_of("alive-point")),
        ("exit", "P", line_of("alive-point")),
    ]


def test_exit_line_is_the_with_line_even_on_exception():
    with tracing.record() as log:
        try:
            with tracing.Shape("S", "segment"):  # with-raises
                raise ValueError
        except ValueError:
            pass
    assert [(e.kind, e.line) for e in log.events] == [
        ("enter", line_of("with-raises")), ("exit", line_of("with-raises")),
    ]  # fmt: skip


def test_line_numbers_of_calls():
    @tracing.traced
    def inner(x):
        return x

    @tracing.traced
    def outer(x):
        return inner(x + 1)  # inner-call

    with tracing.record() as log:
        outer(1)  # outer-call
    assert [(e.kind, e.name, e.line) for e in log.events] == [
        ("call", "outer", line_of("outer-call")),
        ("call", "inner", line_of("inner-call")),
        ("return", "inner", line_of("inner-call")),
        ("return", "outer", line_of("outer-call")),
    ]
