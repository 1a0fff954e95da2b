"""Interrupted renders exit at once and leave nothing (issue 24 item 13).

Runs ``trex render SCENE -q l`` again and again, ``--parallel`` at a time, beside ``--load``
busy processes, and interrupts each at a random moment of its render: SIGINT and SIGTERM in
turn, sent a random time (uniform over the render's length, measured first under the same
load) after the render began (its temporary ``.NAME.*.render`` directory appeared). Each
interrupt must:

- end the process within ``--deadline`` seconds (5) of the signal;
- exit 128 + the signal (130 for SIGINT, 143 for SIGTERM), saying ``render interrupted``;
- leave nothing in the output's directory (no video, no subtitles, no temporary directory).

Beside the wall time after the signal it prints the CPU time the process spent after it
(from ``/proc``): on a machine whose cores are shared with other work, the wall time says
as much about the others as about the exit; the machine's load average is printed too.

A render that finished before its signal came (its video in place) is not an interrupt: it
is counted apart and run again, until ``--count`` (50) renders were interrupted. A process still running 60 s after
its signal is killed and counted as hung. Prints one line per interrupt and a summary;
exits 1 if any interrupt failed. The moments are drawn from ``--seed``, so a run can be
repeated (the machine's timing still varies).

Run from the repository root: ``python -m bench.interrupts`` (about 4 minutes at the
defaults on two cores).
"""

from __future__ import annotations

import argparse
import os
import random
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: ``trex`` (its entry point, trex.cli:main), with faulthandler dumping every thread's stack
#: on SIGUSR1: what a slow exit was doing is then in its log
TREX = [sys.executable, "-c", "import faulthandler, signal, sys; "
        "faulthandler.register(signal.SIGUSR1, all_threads=True); sys.argv[0] = 'trex'; "
        "from trex.cli import main; main()"]
BUSY = "while True: pass"
HUNG = 60.0  # seconds after the signal: killed, counted as hung
DUMP = 20.0  # seconds after the signal: faulthandler prints every thread's stack to its log
TICK = os.sysconf("SC_CLK_TCK")
POLL = 0.01


@dataclass
class Outcome:
    """One render and its interrupt: ``delay`` after the render began, ``exit_after`` the
    signal (None: it finished before the signal, or hung), what it left behind."""

    signum: int
    delay: float
    status: int | None
    exit_after: float | None
    left: list[str]
    stderr: str
    cpu_after: float | None = None

    @property
    def interrupted(self) -> bool:
        """Whether the signal interrupted the render: not when the render had put its video
        in place first (then a SIGTERM during the process's last moments may still end it
        by the signal's default action, which is right: the video is whole)."""
        return self.status != 0 and "out.mp4" not in self.left

    @property
    def too_slow_only(self) -> bool:
        """Right in all but the time it took to exit."""
        return (self.exit_after is not None and self.status == 128 + self.signum
                and not self.left and "render interrupted; nothing written" in self.stderr)

    def problems(self, deadline: float) -> list[str]:
        if self.exit_after is None:
            return [f"hung: still running {HUNG:.0f} s after the signal"]
        if self.status == -signal.SIGUSR1:  # faulthandler had ended: it was exiting
            return [f"still exiting {DUMP:.0f} s after the signal (ended by the stack request)"]
        found = []
        if self.exit_after > deadline:
            found.append(f"exited {self.exit_after:.2f} s after the signal")
        if self.status != 128 + self.signum:
            found.append(f"exit status {self.status}")
        elif "render interrupted; nothing written" not in self.stderr:
            found.append("no 'render interrupted' line")
        if self.left:
            found.append(f"left {', '.join(self.left)}")
        return found


class Render:
    """One ``trex render`` process writing into a directory of its own."""

    def __init__(self, scene: str, directory: Path) -> None:
        self.directory = directory
        directory.mkdir()
        self.log = directory.with_suffix(".stderr")
        out = directory / "out.mp4"
        with open(self.log, "w") as err:  # a file, not a pipe nobody drains
            self.proc = subprocess.Popen([*TREX, "render", scene, "-q", "l", "-o", str(out)],
                                         cwd=ROOT, stdout=subprocess.DEVNULL, stderr=err)
        self.began: float | None = None

    def poll_began(self) -> bool:
        """Whether the render has begun (its temporary directory is there), noting when."""
        if self.began is None and any(self.directory.glob(".out.mp4.*.render")):
            self.began = time.monotonic()
        return self.began is not None

    def left(self) -> list[str]:
        return sorted(p.name for p in self.directory.iterdir())

    def kill(self) -> None:
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()


def calibrate(scene: str, scratch: Path, parallel: int) -> float:
    """How long a render takes from its beginning to its exit, ``parallel`` at once."""
    renders = [Render(scene, scratch / f"calibrate{k}") for k in range(parallel)]
    lengths = []
    for render in renders:
        while not render.poll_began() and render.proc.poll() is None:
            time.sleep(POLL)
    for render in renders:
        if render.proc.wait() != 0:
            sys.exit(f"error: the uninterrupted render failed: {render.log.read_text()}")
        lengths.append(time.monotonic() - render.began)
    return statistics.median(lengths)


def cpu_seconds(pid: int) -> float | None:
    """CPU seconds (user + system) process ``pid`` has used: also readable for a process that
    has exited and is not yet reaped. None: no such process."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    fields = stat.rsplit(")", 1)[1].split()  # from the state on: utime, stime are 12th, 13th
    return (int(fields[11]) + int(fields[12])) / TICK


class Watch:
    """One render under interrupt: when its signal went, when it ended, its CPU then."""

    def __init__(self, render: Render, signum: int, delay: float) -> None:
        self.render, self.signum, self.delay = render, signum, delay
        self.sent: float | None = None
        self.ended: float | None = None
        self.cpu_sent: float | None = None
        self.cpu_last: float | None = None
        self.dumped = False

    def step(self, now: float) -> None:
        """One poll: note its CPU (before reaping), see if it ended, send what is due."""
        proc = self.render.proc
        self.cpu_last = cpu_seconds(proc.pid) or self.cpu_last
        if proc.poll() is not None:
            self.ended = now
        elif self.sent is None:
            if self.render.poll_began() and now >= self.render.began + self.delay:
                self.cpu_sent = self.cpu_last
                proc.send_signal(self.signum)
                self.sent = time.monotonic()
        elif now - self.sent > HUNG:
            self.render.kill()
            self.ended = now
        elif now - self.sent > DUMP and not self.dumped:
            self.dumped = True
            proc.send_signal(signal.SIGUSR1)  # faulthandler: where it is stuck

    def outcome(self) -> Outcome:
        render, status = self.render, self.render.proc.returncode
        left, log = render.left(), render.log.read_text()
        if self.sent is None:  # it ended before its signal was due
            return Outcome(self.signum, self.delay, status, None, left, log)
        after = None if status == -signal.SIGKILL else self.ended - self.sent
        cpu = (None if self.cpu_sent is None or self.cpu_last is None
               else self.cpu_last - self.cpu_sent)
        return Outcome(self.signum, self.delay, status, after, left, log, cpu)


def interrupt(renders: list[tuple[Render, int, float]]) -> list[Outcome]:
    """Send each render its signal ``delay`` after it began, and note when each ends."""
    watches = [Watch(*r) for r in renders]
    while any(w.ended is None for w in watches):
        now = time.monotonic()
        for watch in watches:
            if watch.ended is None:
                watch.step(now)
        time.sleep(POLL)
    return [w.outcome() for w in watches]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=50, help="interrupts to make")
    parser.add_argument("--parallel", type=int, default=2, help="renders at once")
    parser.add_argument("--load", type=int, default=1, help="busy processes beside them")
    parser.add_argument("--scene", default="scaling")
    parser.add_argument("--deadline", type=float, default=5.0, help="seconds to exit in")
    parser.add_argument("--seed", type=int, default=24)
    args = parser.parse_args(argv)
    draw = random.Random(args.seed)
    busy = [subprocess.Popen([sys.executable, "-c", BUSY]) for _ in range(args.load)]
    scratch = Path(tempfile.mkdtemp(prefix="trex-bench-interrupts-"))
    done: list[Outcome] = []
    finished_first = 0
    try:
        length = calibrate(args.scene, scratch, args.parallel)
        print(f"{args.scene} at -q l, {args.parallel} at once beside {args.load} busy "
              f"process(es): a render takes {length:.1f} s from its beginning to its exit; "
              f"load average {_load()} on {os.cpu_count()} cores")
        signals = (signal.SIGINT, signal.SIGTERM)
        while len(done) < args.count:
            batch = [(Render(args.scene, scratch / f"r{len(done)}-{k}-{finished_first}"),
                      signals[(len(done) + k) % 2], draw.uniform(0, length))
                     for k in range(min(args.parallel, args.count - len(done)))]
            try:
                outcomes = interrupt(batch)
            finally:
                for render, _, _ in batch:
                    render.kill()
            for outcome in outcomes:
                if not outcome.interrupted:
                    finished_first += 1
                    continue
                done.append(outcome)
                _print(len(done), outcome, args.deadline)
    finally:
        for proc in busy:
            proc.kill()
            proc.wait()
        shutil.rmtree(scratch, ignore_errors=True)
    return _summary(done, finished_first, args.deadline)


def _print(n: int, outcome: Outcome, deadline: float) -> None:
    name = signal.Signals(outcome.signum).name
    after = "—" if outcome.exit_after is None else f"{outcome.exit_after:5.2f} s"
    cpu = "" if outcome.cpu_after is None else f" (CPU {outcome.cpu_after:4.2f} s)"
    problems = outcome.problems(deadline)
    verdict = "ok" if not problems else "FAILED: " + "; ".join(problems)
    print(f"{n:3d}  {name:7s} {outcome.delay:5.2f} s into the render  exit {outcome.status}"
          f" after {after}{cpu}  {verdict}", flush=True)
    if problems:  # where it was DUMP s after the signal (faulthandler, on SIGUSR1)
        stacks = [line for line in outcome.stderr.splitlines()
                  if line.startswith(("Thread 0x", "Current thread", "  File"))]
        for line in stacks[:60]:
            print(f"       {line}")


def _load() -> str:
    return " ".join(f"{x:.1f}" for x in os.getloadavg())


def _summary(done: list[Outcome], finished_first: int, deadline: float) -> int:
    failed = [o for o in done if o.problems(deadline)]
    times = [o.exit_after for o in done if o.exit_after is not None]
    for signum in (signal.SIGINT, signal.SIGTERM):
        mine = [o for o in done if o.signum == signum]
        bad = sum(1 for o in mine if o.problems(deadline))
        print(f"{signal.Signals(signum).name}: {len(mine)} interrupts, {len(mine) - bad} ok")
    cpus = [o.cpu_after for o in done if o.cpu_after is not None]
    if times:
        within = sum(1 for t in times if t <= deadline)
        print(f"exit after the signal: median {statistics.median(times):.2f} s, max "
              f"{max(times):.2f} s; {within} of {len(times)} within {deadline:.0f} s")
    if cpus:
        print(f"CPU spent after the signal: median {statistics.median(cpus):.2f} s, "
              f"max {max(cpus):.2f} s")
    print(f"load average now {_load()}")
    print(f"renders that finished before their signal (not counted): {finished_first}")
    slow = sum(1 for o in failed if o.too_slow_only)
    print(f"interrupted renders: {len(done)}, failed: {len(failed)} ({slow} only by the time "
          f"they took, {len(failed) - slow} hung, wrong status or left something)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
