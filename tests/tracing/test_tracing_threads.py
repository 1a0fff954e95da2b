"""Recordings in different threads never mix; runs are deterministic."""

import subprocess
import sys
import threading
from pathlib import Path

import tracing


@tracing.traced
def step(label, i):
    with tracing.Shape(f"{label}-{i}", "point", at=[i, i]):
        pass
    return i


def _worker(label, count, barrier, logs):
    barrier.wait()
    with tracing.record(worker=label) as log:
        barrier.wait()
        for i in range(count):
            step(label, i)
    logs[label] = log


def test_two_threads_recording_at_once_never_mix():
    old = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)
    try:
        barrier, logs = threading.Barrier(3), {}
        threads = [
            threading.Thread(target=_worker, args=(label, 300, barrier, logs)) for label in "ab"
        ]
        with tracing.record(worker="main") as main_log:
            for thread in threads:
                thread.start()
            barrier.wait()
            barrier.wait()
            step("main", 0)
            for thread in threads:
                thread.join()
    finally:
        sys.setswitchinterval(old)
    assert [e.target for e in main_log.events if e.kind == "enter"] == ["main-0"]
    for label in "ab":
        log = logs[label]
        assert log.meta == {"worker": label}
        assert len(log.events) == 300 * 4
        assert [e.seq for e in log.events] == list(range(1200))
        assert [e.args["label"] for e in log.find(kind="call")] == [label] * 300
        assert [e.result for e in log.find(kind="return")] == list(range(300))
        assert all(e.target.startswith(f"{label}-") for e in log.find(kind="enter"))


def test_a_thread_does_not_inherit_the_callers_recording():
    seen = []
    with tracing.record() as log:
        thread = threading.Thread(target=lambda: seen.append(step("t", 0)))
        thread.start()
        thread.join()
    assert seen == [0]
    assert log.events == []


SCRIPT = """
import tracing

@tracing.traced
def pick(options):
    return sorted(options)[0]

with tracing.record(kind="demo", tags=["x", "y"]) as log:
    with tracing.Shape("S", "polygon", points=[(0.1, 0.2), (1 / 3, 2.5e-8)]):
        pick({"b", "a", "c"})
        pick(["q", "p"])
print(log.to_json())
"""


def test_same_run_gives_byte_identical_json_across_processes():
    root = Path(__file__).resolve().parents[2]
    outputs = {
        subprocess.run(
            [sys.executable, "-c", SCRIPT],
            cwd=root,
            env={"PYTHONHASHSEED": seed, "PYTHONPATH": str(root)},
            capture_output=True,
            text=True,
            check=True,
        ).stdout
        for seed in ("1", "2")
    }
    assert len(outputs) == 1
    text = outputs.pop()
    assert '"args":{"options":{"type":"set"}}' in text
    assert "[0.1,0.2],[0.3333333333333333,2.5e-08]" in text
    assert "0x" not in text
