"""Load on ``trex studio``: many concurrent ``/api/check`` calls on big polygons.

Starts the real command (``trex studio --no-browser --port 0``) in a process of its own on
127.0.0.1, sends CALLS ``POST /api/check`` requests at once (one thread each, a fresh
connection each) on N-vertex random star polygons (``random-star:N:SEED``, a different seed
per call), checks every answer (valid, N labels, B among them, the reflex vertices exactly
those the command line's polygon has) and prints the latency's p50, p95 and max, and the
wall time of the whole burst. Then stops the studio with SIGINT. Bounded: every request has
a timeout and the burst a deadline. Prints numbers only, e.g. ::

    /api/check, 200 concurrent calls on 500-vertex polygons: all 200 correct;
    latency p50 1.23 s, p95 2.01 s, max 2.10 s; burst 2.2 s (91 calls/s)

Run from the repository root: ``python -m bench.studio [--calls 200] [-n 500]``.
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import statistics
import subprocess
import sys
import threading
import time
import urllib.request
from pathlib import Path

from geometry.polygon import Polygon
from geometry.samples import make_sample

ROOT = Path(__file__).resolve().parent.parent
TIMEOUT_S = 120


def start() -> tuple[subprocess.Popen, str]:
    process = subprocess.Popen(
        [sys.executable, "-m", "trex", "studio", "--no-browser", "--port", "0"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT,
        env={**os.environ, "PYTHONPATH": str(ROOT)})
    line = process.stdout.readline()
    if not line.startswith("studio: "):
        process.kill()
        sys.exit(f"the studio did not start: {line!r} {process.stderr.read()}")
    return process, line.split(" ", 1)[1].strip()


def expected(points: list) -> tuple[int, list[int]]:
    """What a correct answer says: the vertex count and the reflex vertices (input order)."""
    polygon = Polygon.from_points(points)
    return polygon.n, sorted(polygon.source[i] for i in polygon.reflex_vertices())


def call(url: str, points: list) -> tuple[float, dict]:
    body = json.dumps({"polygon": points}).encode()
    request = urllib.request.Request(url, data=body, headers={"Content-Type": "application/json"})
    began = time.perf_counter()
    with urllib.request.urlopen(request, timeout=TIMEOUT_S) as answer:
        data = json.loads(answer.read())
    return time.perf_counter() - began, data


def burst(url: str, polygons: list[list]) -> tuple[list[float], int, float]:
    """Every call at once (released together); latencies, correct answers, wall time."""
    latencies: list[float] = []
    correct = [0]
    lock, gate = threading.Lock(), threading.Event()

    def one(points: list, want: tuple[int, list[int]]) -> None:
        gate.wait()
        seconds, data = call(url + "api/check", points)
        ok = (data["valid"] and sum(label is not None for label in data["labels"]) == want[0]
              and "B" in data["labels"] and data["reflex"] == want[1])
        with lock:
            latencies.append(seconds)
            correct[0] += ok

    threads = [threading.Thread(target=one, args=(p, expected(p)), daemon=True) for p in polygons]
    for t in threads:
        t.start()
    began = time.perf_counter()
    gate.set()
    for t in threads:
        t.join(TIMEOUT_S)
    return latencies, correct[0], time.perf_counter() - began


def percentile(values: list[float], q: float) -> float:
    return statistics.quantiles(values, n=100, method="inclusive")[q - 1] if len(values) > 1 \
        else values[0]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, default=200)
    parser.add_argument("-n", type=int, default=500, help="vertices per polygon")
    args = parser.parse_args()
    polygons = [[list(p) for p in make_sample("random-star", args.n, seed)]
                for seed in range(args.calls)]
    process, url = start()
    try:
        call(url + "api/check", polygons[0])  # warm: the first answer imports numpy paths
        latencies, correct, wall = burst(url, polygons)
    finally:
        process.send_signal(signal.SIGINT)
        process.communicate(timeout=30)
    if len(latencies) != args.calls:
        sys.exit(f"only {len(latencies)} of {args.calls} calls were answered")
    print(f"/api/check, {args.calls} concurrent calls on {args.n}-vertex polygons: "
          f"{correct} of {args.calls} correct; latency p50 {percentile(latencies, 50):.2f} s, "
          f"p95 {percentile(latencies, 95):.2f} s, max {max(latencies):.2f} s; "
          f"burst {wall:.1f} s ({args.calls / wall:.0f} calls/s)")
    if correct != args.calls:
        sys.exit(1)


if __name__ == "__main__":
    main()
