"""The overhead bench's harness: unwrapping for the baseline, and a tiny measured run."""

import importlib.util
import sys
from pathlib import Path

import tracing

BENCH = Path(__file__).resolve().parents[2] / "bench" / "trace_overhead.py"


def load_bench():
    spec = importlib.util.spec_from_file_location("trace_overhead_bench", BENCH)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up while it loads
    spec.loader.exec_module(module)
    return module


def test_untraced_swaps_functions_and_methods_then_restores():
    bench = load_bench()

    @tracing.traced_class
    class Walker:
        def walk(self):
            return "walk"

        @staticmethod
        def stop():
            return "stop"

    namespace = {"is_ear": bench.is_ear, "Walker": Walker, "other": 3}
    traced_walk, traced_stop = Walker.__dict__["walk"], Walker.__dict__["stop"]
    with bench.untraced([namespace]):
        assert namespace["is_ear"] is bench.is_ear.__wrapped__
        assert Walker.__dict__["walk"] is traced_walk.__wrapped__
        assert Walker.stop is traced_stop.__func__.__wrapped__
        with tracing.record() as log:
            assert Walker().walk() == "walk"
            assert Walker.stop() == "stop"
        assert log.events == []
    assert namespace == {"is_ear": bench.is_ear, "Walker": Walker, "other": 3}
    assert Walker.__dict__["walk"] is traced_walk


def test_clip_ears_triangulates_and_measure_reports():
    bench = load_bench()
    polygon = bench.star_polygon(40, seed=3)
    triangles = bench.clip_ears(polygon)
    assert len(triangles) == 38
    assert len({v for t in triangles for v in t}) == 40
    with tracing.record() as log:
        assert bench.clip_ears(polygon) == triangles
    assert [e.target for e in log.find(kind="enter")] == [f"T{i}" for i in range(37)]
    assert {e.name for e in log.find(kind="call")} == {"is_ear"}
    result = bench.measure(bench.clip_ears, polygon, repeats=1)
    assert result.events == len(log.events)
    assert result.json_bytes == len(log.to_json())
