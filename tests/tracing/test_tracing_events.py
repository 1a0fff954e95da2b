"""Log and Event: JSON round trip, schema check, save/load, state_at, calls, find."""

import json

import pytest

import tracing
from tracing import Event, Log
from tracing.replay import CHECKPOINT_EVERY


def sample_log() -> Log:
    return Log(
        {"algorithm": "scaling", "polygon": "counterexample", "seed": 7},
        [
            Event(0, "call", "nearest_to", None, {"b": {"ref": "B"}, "d": [0.1, 1e-300]},
                  line=10, depth=0, call=0),
            Event(1, "enter", "circle", "W(B)", state={"kind": "circle", "center": [1.0, 4.5],
                  "radius": 0.0}, line=11, depth=1, call=0),
            Event(2, "change", "circle", "W(B)", state={"kind": "circle", "center": [1.0, 4.5],
                  "radius": 2.3}, line=12, depth=1, call=0),
            Event(3, "note", "wet", None, {"who": "É", "x": -0.0, "big": 2**70}, line=13,
                  depth=1, call=0),
            Event(4, "exit", "circle", "W(B)", line=11, depth=1, call=0),
            Event(5, "return", "nearest_to", None, result={"ref": "E"}, line=10, depth=0, call=0),
        ],
    )  # fmt: skip


def test_round_trip_is_exact():
    log = sample_log()
    text = log.to_json()
    again = Log.from_json(text)
    assert again == log
    assert again.events == log.events
    assert again.to_json() == text
    assert again.events[0].args["d"] == [0.1, 1e-300]
    assert str(again.events[3].args["x"]) == "-0.0"
    assert again.events[3].args["big"] == 2**70


def test_json_document_layout():
    document = json.loads(sample_log().to_json())
    assert list(document) == ["schema", "meta", "events"]
    assert document["schema"] == "trex-log/1"
    assert document["events"][4] == {
        "seq": 4, "kind": "exit", "name": "circle", "target": "W(B)", "line": 11,
        "depth": 1, "call": 0,
    }  # fmt: skip
    assert document["events"][5]["result"] == {"ref": "E"}


def test_json_keeps_written_order_and_is_compact():
    text = sample_log().to_json()
    assert text.startswith('{"schema":"trex-log/1","meta":')
    first = json.loads(text)["events"][0]
    assert list(first) == [k for k in ("seq", "kind", "name", "target", "args", "result",
                                       "state", "line", "depth", "call") if k in first]
    assert ", " not in text


def test_arguments_keep_signature_order_through_json():
    """A replayed log must show the same call line: (zeta, alpha), not sorted (alpha, zeta)."""
    import tracing

    @tracing.traced
    def f(zeta, alpha):
        return zeta

    with tracing.record() as log:
        f(1, 2)
    again = Log.from_json(log.to_json())
    assert list(again.events[0].args) == ["zeta", "alpha"]
    assert again.to_json() == log.to_json()


def test_indented_json_reads_back():
    log = sample_log()
    text = log.to_json(indent=2)
    assert text.splitlines()[1] == '  "schema": "trex-log/1",'
    assert Log.from_json(text) == log


def test_return_of_none_round_trips():
    log = Log({}, [Event(0, "call", "f", args={}, call=0), Event(1, "return", "f", call=0)])
    assert Log.from_json(log.to_json()).events == log.events


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('{"meta": {}, "events": []}', "unsupported log schema None; expected 'trex-log/1'"),
        ('{"schema": "trex-log/2", "events": []}', "unsupported log schema 'trex-log/2'"),
        ("[1, 2]", "unsupported log schema None"),
    ],
)
def test_wrong_schema_is_rejected(text, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(")):
        Log.from_json(text)


def test_unknown_event_field_is_rejected():
    text = '{"schema": "trex-log/1", "meta": {}, "events": [{"seq": 0, "kind": "note", "x": 1}]}'
    with pytest.raises(ValueError, match=r"unknown event field\(s\) \['x'\]"):
        Log.from_json(text)


def test_unknown_event_kind_is_rejected():
    event = '{"seq": 0, "kind": "jump", "name": "x"}'
    text = '{"schema": "trex-log/1", "meta": {}, "events": [' + event + "]}"
    with pytest.raises(ValueError, match="unknown event kind 'jump'"):
        Log.from_json(text)


@pytest.mark.parametrize(
    ("events", "message"),
    [
        ('[{"kind": "note", "name": "x"}]', r"lacks field\(s\) \['seq'\]"),
        ("[[0, 1]]", "an event must be a JSON object"),
        ('{"seq": 0}', "its events a list"),
    ],
)
def test_malformed_events_are_rejected(events, message):
    with pytest.raises(ValueError, match=message):
        Log.from_json('{"schema": "trex-log/1", "meta": {}, "events": ' + events + "}")


def test_nan_cannot_sneak_into_json():
    log = Log({"bad": float("nan")})
    with pytest.raises(ValueError, match="Out of range float"):
        log.to_json()


def test_save_and_load(tmp_path):
    log = sample_log()
    path = tmp_path / "run.json"
    log.save(path)
    assert path.read_text(encoding="utf-8") == log.to_json() + "\n"
    assert Log.load(path) == log


def test_state_at_small_log():
    log = sample_log()
    circle = {"kind": "circle", "center": [1.0, 4.5], "radius": 0.0}
    assert log.state_at(-1) == {}
    assert log.state_at(0) == {}
    assert log.state_at(1) == {"W(B)": circle}
    assert log.state_at(2) == {"W(B)": dict(circle, radius=2.3)}
    assert log.state_at(3) == {"W(B)": dict(circle, radius=2.3)}
    assert log.state_at(4) == {}
    assert log.state_at(5) == {}
    with pytest.raises(IndexError):
        log.state_at(6)
    with pytest.raises(IndexError):
        log.state_at(-2)


def test_state_at_ignores_change_of_object_not_alive():
    log = Log({}, [Event(0, "change", "point", "P", state={"kind": "point"})])
    assert log.state_at(0) == {}


def test_state_at_result_is_a_fresh_dict():
    log = sample_log()
    log.state_at(1).clear()
    assert list(log.state_at(1)) == ["W(B)"]


def _many_events(count: int) -> list[Event]:
    """Points entering, moving and leaving in a fixed pseudo-random pattern."""
    events, alive = [], []
    for seq in range(count):
        key = f"P{(seq * 7) % 97}"
        if key in alive and seq % 3 == 0:
            events.append(Event(seq, "exit", "point", key))
            alive.remove(key)
        elif key in alive:
            events.append(Event(seq, "change", "point", key, state={"kind": "point", "at": seq}))
        else:
            events.append(Event(seq, "enter", "point", key, state={"kind": "point", "at": seq}))
            alive.append(key)
    return events


def _naive_states(events: list[Event]) -> list[dict]:
    states, live = [], {}
    for event in events:
        if event.kind in ("enter", "change"):
            live[event.target] = event.state
        elif event.kind == "exit":
            del live[event.target]
        states.append(dict(live))
    return states


def test_state_at_matches_naive_replay_across_checkpoints():
    events = _many_events(5 * CHECKPOINT_EVERY + 17)
    log = Log({}, events)
    expected = _naive_states(events)
    for step in [len(events) - 1, 0, CHECKPOINT_EVERY - 1, CHECKPOINT_EVERY, 3 * CHECKPOINT_EVERY]:
        assert log.state_at(step) == expected[step], step
    for step in range(len(events)):
        assert log.state_at(step) == expected[step]


def test_state_at_keeps_checkpoints_linear():
    events = [Event(i, "enter", "point", f"P{i}", state={"kind": "point"}) for i in range(5000)]
    log = Log({}, events)
    assert len(log.state_at(4999)) == 5000
    snapshots = log._live._snapshots
    assert sum(len(snapshot) for snapshot in snapshots) <= 2 * len(events)


def test_state_at_follows_appended_events():
    log = Log({}, [Event(0, "enter", "point", "A", state={"kind": "point"})])
    assert list(log.state_at(0)) == ["A"]
    log.events.append(Event(1, "exit", "point", "A"))
    assert log.state_at(1) == {}
    log.events = [Event(0, "enter", "point", "B", state={"kind": "point"})]
    assert list(log.state_at(0)) == ["B"]


def test_calls_pairs_each_call_with_its_return():
    log = Log({}, [
        Event(0, "call", "outer", args={}, call=0),
        Event(1, "call", "inner", args={}, depth=1, call=1),
        Event(2, "return", "inner", result=1, depth=1, call=1),
        Event(3, "call", "open", args={}, depth=1, call=3),
        Event(4, "return", "outer", result=2, call=0),
    ])  # fmt: skip
    pairs = [(c.seq, None if r is None else r.seq) for c, r in log.calls()]
    assert pairs == [(0, 4), (1, 2), (3, None)]


def test_find_filters_by_kind_name_and_target():
    log = sample_log()
    assert [e.seq for e in log.find(kind="call")] == [0]
    assert [e.seq for e in log.find(name="circle")] == [1, 2, 4]
    assert [e.seq for e in log.find(kind="change", target="W(B)")] == [2]
    assert [e.seq for e in log.find(name="nope")] == []
    assert len(log.find()) == 6


def test_events_are_frozen():
    event = Event(0, "note", "x")
    with pytest.raises(AttributeError):
        event.seq = 1  # type: ignore[misc]  # on purpose: it must raise


def test_schema_constant():
    assert tracing.SCHEMA == "trex-log/1"
    assert tracing.EVENT_KINDS == ("call", "return", "enter", "change", "exit", "note")
