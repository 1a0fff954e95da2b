"""A non-geometry algorithm traced end to end: binary search with its [lo, hi] interval."""

from pathlib import Path

import tracing


def line_of(marker: str) -> int:
    """Line number of the single line of this file ending in ``# <marker>``."""
    lines = Path(__file__).read_text(encoding="utf-8").splitlines()
    hits = [n for n, text in enumerate(lines, 1) if text.endswith(f"# {marker}")]
    assert len(hits) == 1, marker
    return hits[0]


@tracing.traced(exclude_args=("items",))
def compare(items, mid, target):
    """Three-way comparison of ``items[mid]`` with ``target``."""
    return (items[mid] > target) - (items[mid] < target)


@tracing.traced(exclude_args=("items",))
def binary_search(items, target):
    """Index of ``target`` in the sorted ``items``, or None."""
    lo, hi = 0, len(items) - 1
    with tracing.Shape("interval", "band", lo=lo, hi=hi) as interval:  # open-interval
        while lo <= hi:
            mid = (lo + hi) // 2
            order = compare(items, mid, target)  # compare
            if order == 0:
                return mid
            if order < 0:
                lo = mid + 1
            else:
                hi = mid - 1
            interval.update(lo=lo, hi=hi)  # update
        tracing.note("absent", target=target, lo=lo, hi=hi)  # absent
        return None


ITEMS = [1, 3, 5, 7, 9, 11, 13]


def band(lo, hi):
    return {"kind": "band", "lo": lo, "hi": hi}


def test_found_after_narrowing():
    with tracing.record(algorithm="binary_search") as log:
        assert binary_search(ITEMS, 11) == 5  # search
    search, open_, compare_, update = (
        line_of(m) for m in ("search", "open-interval", "compare", "update")
    )
    assert [(e.seq, e.kind, e.name, e.target, e.args, e.result, e.state, e.line, e.depth,
             e.call) for e in log.events] == [
        (0, "call", "binary_search", None, {"target": 11}, None, None, search, 0, 0),
        (1, "enter", "band", "interval", None, None, band(0, 6), open_, 1, 0),
        (2, "call", "compare", None, {"mid": 3, "target": 11}, None, None, compare_, 1, 2),
        (3, "return", "compare", None, None, -1, None, compare_, 1, 2),
        (4, "change", "band", "interval", None, None, band(4, 6), update, 1, 0),
        (5, "call", "compare", None, {"mid": 5, "target": 11}, None, None, compare_, 1, 5),
        (6, "return", "compare", None, None, 0, None, compare_, 1, 5),
        (7, "exit", "band", "interval", None, None, None, open_, 1, 0),
        (8, "return", "binary_search", None, None, 5, None, search, 0, 0),
    ]  # fmt: skip
    assert [log.state_at(step) for step in (0, 1, 4, 7)] == [
        {}, {"interval": band(0, 6)}, {"interval": band(4, 6)}, {},
    ]  # fmt: skip


def test_absent_value_ends_with_a_note():
    with tracing.record() as log:
        assert binary_search(ITEMS, 4) is None
    summary = [(e.kind, e.name, e.args if e.kind != "return" else e.result) for e in log.events]
    assert summary == [
        ("call", "binary_search", {"target": 4}),
        ("enter", "band", None),
        ("call", "compare", {"mid": 3, "target": 4}), ("return", "compare", 1),
        ("change", "band", None),
        ("call", "compare", {"mid": 1, "target": 4}), ("return", "compare", -1),
        ("change", "band", None),
        ("call", "compare", {"mid": 2, "target": 4}), ("return", "compare", 1),
        ("change", "band", None),
        ("note", "absent", {"target": 4, "lo": 2, "hi": 1}),
        ("exit", "band", None),
        ("return", "binary_search", None),
    ]  # fmt: skip
    assert [e.state for e in log.find(kind="change")] == [band(0, 2), band(2, 2), band(2, 1)]
    assert log.find(kind="note")[0].line == line_of("absent")
    assert tracing.Log.from_json(log.to_json()) == log


def test_untraced_run_gives_the_same_answers():
    assert [binary_search(ITEMS, t) for t in (1, 13, 0, 14)] == [0, 6, None, None]
