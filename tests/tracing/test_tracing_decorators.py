"""traced and traced_class: arguments, results, methods, exclusions, exceptions."""

import asyncio
from pathlib import Path

import pytest

import tracing


def line_of(marker: str) -> int:
    """Line number of the single line of this file ending in ``# <marker>``."""
    lines = Path(__file__).read_text(encoding="utf-8").splitlines()
    hits = [n for n, text in enumerate(lines, 1) if text.endswith(f"# {marker}")]
    assert len(hits) == 1, marker
    return hits[0]


def calls_and_returns(log):
    return [(e.kind, e.name, e.target, e.args, e.result) for e in log.events]


class Vertex:
    def __init__(self, label):
        self.trace_key = label

    def trace_state(self):
        return {"kind": "point", "at": [0, 0]}


@tracing.traced(name="nearest_to", exclude_args=("polygon",))
def closest(polygon, b, candidates, scale=1.0, *, strict=False):
    return candidates[-1]


def test_arguments_in_signature_order_with_defaults():
    b, d, e = Vertex("B"), Vertex("D"), Vertex("E")
    with tracing.record() as log:
        result = closest(object(), candidates=[d, e], b=b, strict=True)
    assert result is e
    assert calls_and_returns(log) == [
        ("call", "nearest_to", None,
         {"b": {"ref": "B"}, "candidates": [{"ref": "D"}, {"ref": "E"}], "scale": 1.0,
          "strict": True}, None),
        ("return", "nearest_to", None, None, {"ref": "E"}),
    ]  # fmt: skip
    assert list(log.events[0].args) == ["b", "candidates", "scale", "strict"]


def test_positional_fast_path_gives_same_args():
    @tracing.traced
    def f(a, b=2):
        return a

    with tracing.record() as log:
        f(1, 2)
        f(1)
        f(b=2, a=1)
    assert [e.args for e in log.find(kind="call")] == [{"a": 1, "b": 2}] * 3


def test_var_args_and_kwargs():
    @tracing.traced
    def f(a, *rest, key=None, **extra):
        return len(rest)

    with tracing.record() as log:
        f(1, 2, 3, z=4)
    assert log.events[0].args == {"a": 1, "rest": [2, 3], "key": None, "extra": {"z": 4}}
    assert log.events[1].result == 2


def test_result_false_records_none():
    @tracing.traced(result=False)
    def big():
        return list(range(1000))

    with tracing.record() as log:
        assert len(big()) == 1000
    assert log.events[1].kind == "return"
    assert log.events[1].result is None


def test_bare_and_called_forms_and_wrapped():
    @tracing.traced()
    def f(x):
        return x + 1

    assert f.__name__ == "f"
    assert f.__wrapped__(1) == 2
    with tracing.record() as log:
        f(1)
    assert log.events[0].name == "f"


def test_unknown_excluded_argument_is_an_error():
    with pytest.raises(ValueError, match=r"g\(\) has no parameter\(s\) \['nope'\]"):

        @tracing.traced(exclude_args=("nope",))
        def g(x):
            return x


def test_generators_are_refused():
    with pytest.raises(TypeError, match="generators and coroutines are not supported"):

        @tracing.traced
        def gen():
            yield 1


def test_wrong_arguments_raise_the_functions_own_error_and_record_nothing():
    with tracing.record() as log, pytest.raises(TypeError, match="missing 1 required"):
        closest(None, 1)
    assert log.events == []


def test_exception_propagates_unchanged_and_log_stays_consistent():
    error = ValueError("no reflex vertex")

    @tracing.traced
    def inner(x):
        raise error

    @tracing.traced
    def outer(x):
        return inner(x)

    @tracing.traced
    def after():
        return "ok"

    with tracing.record() as log:
        with pytest.raises(ValueError) as caught:
            outer(1)
        after()
    assert caught.value is error
    assert [(e.seq, e.kind, e.name, e.result, e.depth, e.call) for e in log.events] == [
        (0, "call", "outer", None, 0, 0),
        (1, "call", "inner", None, 1, 1),
        (2, "return", "inner", {"raised": "ValueError"}, 1, 1),
        (3, "return", "outer", {"raised": "ValueError"}, 0, 0),
        (4, "call", "after", None, 0, 4),
        (5, "return", "after", "ok", 0, 4),
    ]
    assert [(c.seq, r.seq) for c, r in log.calls()] == [(0, 3), (1, 2), (4, 5)]


def test_method_decorated_with_traced_uses_self_as_target():
    class Clock:
        trace_key = "clock(B)"

        @tracing.traced
        def turn(self, angle):
            return angle * 2

        @tracing.traced
        def keyless(self):
            return None

    class NoKey:
        @tracing.traced
        def run(self, n):
            return n

    with tracing.record() as log:
        Clock().turn(0.5)
        NoKey().run(3)
    calls = log.find(kind="call")
    assert [(e.name, e.target, e.args) for e in calls] == [
        ("turn", "clock(B)", {"angle": 0.5}), ("run", None, {"n": 3}),
    ]  # fmt: skip
    assert log.events[1].target == "clock(B)"


def test_plain_function_with_self_parameter_is_not_a_method():
    @tracing.traced
    def helper(self, x):
        return x

    with tracing.record() as log:
        helper("me", 1)
    assert (log.events[0].target, log.events[0].args) == (None, {"self": "me", "x": 1})


@tracing.traced_class(exclude=("helper",))
class Sweep:
    """A sweep line moving right; its key is its name."""

    def __init__(self, key, x=0.0):
        self.trace_key = key
        self.x = x

    def trace_state(self):
        return {"kind": "line", "x": self.x}

    def advance(self, to):
        self.x = self.helper(to)  # helper-line
        self._private()
        return self.x

    def helper(self, to):
        return float(to)

    def _private(self):
        return None

    @staticmethod
    def make(key):
        return Sweep(key)

    @classmethod
    def named(cls, key):
        return cls(key)

    @property
    def position(self):
        return self.x

    @tracing.traced(name="custom", result=False)
    def already(self, v):
        return v


def test_traced_class_wraps_public_methods_minus_exclusions():
    with tracing.record() as log:
        sweep = Sweep.make("L1")  # make-line
        sweep.advance(2)  # advance-line
        assert sweep.position == 2.0
        Sweep.named("L2").already(5)
    assert [(e.kind, e.name, e.target, e.args, e.result, e.line) for e in log.events] == [
        ("call", "make", None, {"key": "L1"}, None, line_of("make-line")),
        ("return", "make", None, None, {"ref": "L1"}, line_of("make-line")),
        ("call", "advance", "L1", {"to": 2}, None, line_of("advance-line")),
        ("return", "advance", "L1", None, 2.0, line_of("advance-line")),
        ("call", "named", None, {"key": "L2"}, None, log.events[4].line),
        ("return", "named", None, None, {"ref": "L2"}, log.events[4].line),
        ("call", "custom", "L2", {"v": 5}, None, log.events[4].line),
        ("return", "custom", "L2", None, None, log.events[4].line),
    ]
    assert Sweep.helper.__name__ == "helper"
    assert not hasattr(Sweep.helper, "__wrapped__")
    assert not hasattr(Sweep._private, "__wrapped__")
    assert Sweep.advance.__wrapped__.__name__ == "advance"


def test_traced_class_bare_and_unknown_exclusion():
    @tracing.traced_class
    class Ball:
        trace_key = "ball"

        def drop(self, height):
            return height / 2

        def path(self):  # generators are left alone
            yield 1

    with tracing.record() as log:
        Ball().drop(3)
        assert list(Ball().path()) == [1]
    assert calls_and_returns(log) == [
        ("call", "drop", "ball", {"height": 3}, None),
        ("return", "drop", "ball", None, 1.5),
    ]
    with pytest.raises(ValueError, match=r"Ball has no attribute\(s\) \['nope'\]"):
        tracing.traced_class(exclude=("nope",))(Ball)


def test_async_tasks_record_independently():
    @tracing.traced
    def step(label, i):
        return f"{label}{i}"

    async def run(label):
        with tracing.record(task=label) as log:
            for i in range(3):
                step(label, i)
                await asyncio.sleep(0)
        return log

    async def main():
        return await asyncio.gather(run("a"), run("b"))

    log_a, log_b = asyncio.run(main())
    assert [e.result for e in log_a.find(kind="return")] == ["a0", "a1", "a2"]
    assert [e.result for e in log_b.find(kind="return")] == ["b0", "b1", "b2"]
    assert [e.seq for e in log_b.events] == list(range(6))
