"""``trex course`` with 1 and with 2 local workers, and the plan of a 200-student course.

Runs the real command (``python -m trex course COURSE -o <temp> --workers N``) on a small
course written here (a lecture of two short subtitled chapters, the polygon scene on two
polygons, exercises for 3 students with a video each), timed from start to exit, and prints
the speed-up. Then, from the 1-worker run's manifest (each task's measured wall time), it
plans on paper a course of 200 students (the example course's exercises: 3 stills and a
video each) with the lecture at ``-q k``, and estimates its wall time at 1, 8 and 64
workers by list scheduling (longest task first; the join after its chapters).

The lecture at ``-q k`` is an estimate, said as one: its chapters cannot be rendered at 4K
within a bench here. It starts from the lecture's measured ``-q h`` time (issue 21: 760 s of
video in 800 s with ``-j 2`` on 2 cores, so 2.1 CPU seconds per second of video at 1080p60)
times 4, the ratio of pixels (2160p over 1080p, both 60 fps), spread over the 7 chapters by
length (taken equal). The join, a remux, is timed here at ``-q l`` and scaled by the same
pixel ratio from ``-q l`` (an upper bound: bytes grow slower than pixels).
The load average at start and end says whether the machine was idle meanwhile; a
``--dry-run`` is timed too, the check every run pays before its first task.
Run from the repository root: ``python -m bench.course``.
"""

from __future__ import annotations

import heapq
import json
import os
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
TINY = textwrap.dedent("""
    from manim import BLUE, Circle, Create, FadeOut, Scene, Square

    class Cues(Scene):
        def construct(self):
            square = Square(color=BLUE)
            self.play(Create(square), subcaption="a square", run_time=1.5)
            self.wait(1)
            self.play(FadeOut(square), subcaption="gone", run_time=1)

    class MoreCues(Scene):
        def construct(self):
            self.play(Create(Circle()), subcaption="a circle", run_time=1.5)
            self.wait(1)
""")
COURSE = textwrap.dedent("""
    [course]
    title = "bench"
    [[lecture]]
    chapters = ["tiny.py:Cues", "tiny.py:MoreCues"]
    [[scene]]
    scene = "polygon"
    polygons = ["counterexample", "random-star:12:3"]
    [[exercises]]
    students = 3
    n = 3
    seed = 7
    video = true
""")
LECTURE_SECONDS = 760.0  # the lecture's length (issue 21)
CHAPTERS = 7
H_RATE = 2 * 800 / 760  # CPU seconds per second of video at -q h (issue 21, -j 2 on 2 cores)
PIXEL_RATE = (3840 * 2160 * 60) / (854 * 480 * 15)  # -q k over -q l, pixels per second
STUDENTS = 200


def run(course: Path, out: Path, *options: str) -> float:
    """Wall seconds of ``trex course COURSE -o OUT OPTIONS…``, from start to exit."""
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    began = time.perf_counter()
    result = subprocess.run([sys.executable, "-m", "trex", "course", str(course), "-o",
                             str(out), *options], capture_output=True, text=True, env=env,
                            cwd=REPO)
    seconds = time.perf_counter() - began
    if result.returncode != 0:
        sys.exit(f"bench: trex course {' '.join(options)} failed: {result.stderr.strip()}")
    return seconds


def makespan(durations: list[float], workers: int, after: float = 0.0) -> float:
    """List scheduling, longest first, of ``durations`` on ``workers``; ``after`` (the
    join) runs when all are done."""
    free = [0.0] * workers
    for d in sorted(durations, reverse=True):
        heapq.heappush(free, heapq.heappop(free) + d)
    return max(free) + after


def load() -> str:
    """The machine's load average over 1, 5 and 15 minutes, and its cores: whether the
    timings were taken on an idle machine."""
    one, five, fifteen = os.getloadavg()
    return f"{one:.2f} {five:.2f} {fifteen:.2f} (1, 5, 15 min) on {os.cpu_count()} cores"


def main() -> None:
    print(f"load at start: {load()}", flush=True)
    with tempfile.TemporaryDirectory(prefix="bench-course-") as temp:
        folder = Path(temp)
        (folder / "tiny.py").write_text(TINY)
        (folder / "course.toml").write_text(COURSE)
        # what every run pays before a task starts: the course checked, every polygon run
        check = run(folder / "course.toml", folder / "none", "--dry-run")
        walls = {n: run(folder / "course.toml", folder / f"out-{n}", "--workers", str(n))
                 for n in (1, 2)}
        tasks = json.loads((folder / "out-1" / "course.json").read_text())["tasks"]
    print(f"load at end:   {load()}")
    by_kind: dict[str, list[dict]] = {}
    for task in tasks:
        by_kind.setdefault(task["kind"], []).append(task)
    print(f"course: {len(tasks)} tasks; 1 worker {walls[1]:.1f} s (baseline), 2 workers "
          f"{walls[2]:.1f} s; speed-up {walls[1] / walls[2]:.2f}x (ideal 2.00x on 2 idle "
          "cores)")
    after = {n: walls[n] - check for n in walls}
    print(f"  without the check ({check:.1f} s, --dry-run): 1 worker {after[1]:.1f} s, "
          f"2 workers {after[2]:.1f} s; speed-up {after[1] / after[2]:.2f}x (the cluster's "
          "start and the tasks)")
    for kind, done in by_kind.items():
        wall = sum(t["wall_seconds"] for t in done)
        video = sum(t["video_seconds"] for t in done)
        print(f"  {kind:8} {len(done)} tasks, {wall:6.1f} s, {video:5.1f} s of video")
    chapter_k = LECTURE_SECONDS / CHAPTERS * H_RATE * 4  # 2160p60 has 4x 1080p60's pixels
    student = sum(t["wall_seconds"] for t in by_kind["student"]) / len(by_kind["student"])
    # a remux copies bytes, which grow no faster than pixels: an upper bound
    join = max(t["wall_seconds"] for t in by_kind["join"]) * LECTURE_SECONDS / max(
        t["video_seconds"] for t in by_kind["join"]) * PIXEL_RATE
    count = CHAPTERS + 1 + STUDENTS
    print(f"plan: {STUDENTS} students and the lecture at -q k: {count} tasks "
          f"({CHAPTERS} chapters ~{chapter_k:.0f} s each, a join ~{join:.0f} s, {STUDENTS} "
          f"students ~{student:.0f} s each)")
    durations = [chapter_k] * CHAPTERS + [student] * STUDENTS
    for workers in (1, 8, 64):
        print(f"  {workers:2} workers: ~{makespan(durations, workers, join) / 3600:.1f} h")


if __name__ == "__main__":
    main()
