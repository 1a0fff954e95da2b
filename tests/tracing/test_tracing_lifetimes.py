"""Lifetimes declared on decorators: traced(consumes=, produces=) and lifetimes()."""

import pytest

import tracing
from tracing.decorators import Lifetimes, lifetimes


def piece(key):
    return tracing.Shape(key, "polygon", points=[])


def kinds_and_keys(log):
    return [(e.kind, e.name if e.kind in ("call", "return") else e.target) for e in log.events]


@tracing.traced(consumes=("whole",), produces=True)
def cut(whole, at):
    return piece(f"{whole.trace_key}<{at}"), piece(f"{whole.trace_key}>{at}")


@lifetimes(consumes=("whole",), produces=True, produced_first=True)
def fill(whole):
    return piece(f"filled {whole.trace_key}")


@lifetimes(produces=True)
def start(key):
    return piece(key)


@lifetimes(consumes=("claim",))
def decide(where, claim=None):
    return where


def test_traced_call_then_exits_then_enters_after_its_return():
    with tracing.record() as log:
        root = start("P")
        cut(root, 3)
    assert kinds_and_keys(log) == [
        ("enter", "P"), ("call", "cut"), ("return", "cut"), ("exit", "P"), ("enter", "P<3"),
        ("enter", "P>3"),
    ]
    call = log.events[1]
    assert call.args == {"whole": {"ref": "P"}, "at": 3}
    assert all(e.depth == 0 and e.call is None for e in log.events if e.kind in ("enter", "exit"))
    assert {e.line for e in log.events[1:]} == {log.events[1].line}  # all at the caller's line
    assert log.state_at(len(log.events) - 1).keys() == {"P<3", "P>3"}


def test_lifetimes_records_no_call_and_lies_inside_the_callers_call():
    @tracing.traced
    def algorithm():
        first = start("P")
        return fill(first).trace_key

    with tracing.record() as log:
        algorithm()
    assert kinds_and_keys(log) == [
        ("call", "algorithm"), ("enter", "P"), ("enter", "filled P"), ("exit", "P"),
        ("return", "algorithm"),
    ]
    assert [e.depth for e in log.events] == [0, 1, 1, 1, 0]
    assert [e.call for e in log.events] == [0, 0, 0, 0, 0]


def test_consumed_by_keyword_by_position_and_by_default():
    claim = piece("BD")
    with tracing.record() as log:
        tracing.enter(claim)
        decide("here", claim)
        tracing.enter(claim)
        decide(where="here", claim=claim)
        decide("here")  # no claim: nothing exits
    assert kinds_and_keys(log) == [("enter", "BD"), ("exit", "BD")] * 2


def test_nothing_without_a_recording_and_nothing_when_raising():
    assert fill(piece("P")).trace_key == "filled P"

    @lifetimes(consumes=("whole",), produces=True)
    def broken(whole):
        raise ValueError("no")

    with tracing.record() as log, pytest.raises(ValueError):
        broken(piece("P"))
    assert log.events == []


def test_wrapped_and_spec_are_kept():
    assert fill.__wrapped__(piece("Q")).trace_key == "filled Q"
    assert isinstance(fill.__trace_spec__, Lifetimes)
    assert cut.__trace_spec__.name == "cut"


def test_bad_declarations_are_errors():
    with pytest.raises(ValueError, match="to consume"):
        lifetimes(consumes=("nope",))(lambda whole: whole)
    with pytest.raises(ValueError, match="to consume"):
        tracing.traced(consumes=("rest",))(lambda *rest: rest)
    with pytest.raises(TypeError, match="parameter names"):
        lifetimes(consumes="whole")(lambda whole: whole)

    def generator(whole):
        yield whole

    with pytest.raises(TypeError, match="generators"):
        lifetimes(produces=True)(generator)
