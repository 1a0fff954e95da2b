"""The studio's jobs: hunts, videos and slides, each in a process of its own.

A job is a ``trex`` command (:mod:`trex.studio.children`) started in its own process group
under the work directory; a thread waits for it and reads its answer. Hunts start at once;
videos and slides wait their turn, one render at a time (each already uses a core and
more). A crashing or hanging heuristic of one's own ends its job (``--call-timeout`` in the
child), never the server. Cancelling, or the studio stopping, ends the process group and
removes the job's files.

States: ``queued`` → ``running`` → ``done`` | ``failed`` | ``cancelled``.
"""

from __future__ import annotations

import contextlib
import json
import os
import queue
import secrets
import shutil
import signal
import subprocess
import sys
import threading
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from story.environment import inherited
from trex.inputs import first_line

RENDERS = ("video", "slides")
STOP_GRACE_SECONDS = 5.0
"""How long a cancelled job may take to clean up after SIGTERM before it is killed."""


@dataclass
class Job:
    """One job: what it runs, where, and how it is doing."""

    id: str
    kind: str
    argv: tuple[str, ...]
    folder: Path
    finish: Callable[[Job, str], object]
    state: str = "queued"
    result: object = None
    error: str | None = None
    process: subprocess.Popen | None = None
    ended: threading.Event = field(default_factory=threading.Event)

    def progress(self) -> float:
        """0..1: what the child wrote in its progress file (1 once done)."""
        if self.state == "done":
            return 1.0
        try:
            told = json.loads((self.folder / "progress.json").read_text())
            return min(max(told["done"] / told["total"], 0.0), 1.0)
        except (OSError, ValueError, KeyError, TypeError, ZeroDivisionError):
            return 0.0

    def status(self) -> dict:
        return {"state": self.state, "progress": round(self.progress(), 4),
                "result": self.result, "error": self.error}


def _error_of(stderr: str, code: int) -> str:
    """The child's last ``error:`` line, without the prefix; else a plain account."""
    lines = [line for line in stderr.splitlines() if line.strip()]
    errors = [line for line in lines if line.startswith("error: ")]
    if errors:
        return errors[-1].removeprefix("error: ")
    return first_line(lines[-1]) if lines else f"the job ended with status {code}"


class Jobs:
    """Every job of one studio, under ``work/jobs``."""

    def __init__(self, work: Path, python: str = sys.executable) -> None:
        self.root = work / "jobs"
        self.python = python
        self.jobs: dict[str, Job] = {}
        self.lock = threading.Lock()
        self.renders: queue.Queue[Job | None] = queue.Queue()
        self.closed = False
        self.render_worker: threading.Thread | None = None

    def submit(self, kind: str, args: list[str], finish: Callable[[Job, str], object],
               prepare: Callable[[Path], None] | None = None) -> Job:
        """Start (a hunt) or queue (a render) ``trex ARGS``; ``prepare(folder)`` first
        writes its input. ``finish(job, stdout)`` turns a successful run into its result."""
        job_id = secrets.token_hex(6)
        folder = self.root / job_id
        folder.mkdir(parents=True)
        if prepare is not None:
            prepare(folder)
        argv = (self.python, "-m", "trex", *[a.replace("{folder}", str(folder)) for a in args])
        job = Job(job_id, kind, argv, folder, finish)
        with self.lock:
            if self.closed:
                raise RuntimeError("the studio is stopping")
            self.jobs[job_id] = job
        if kind in RENDERS:
            self._start_render_worker()
            self.renders.put(job)
        else:
            threading.Thread(target=self._run, args=(job,), daemon=True).start()
        return job

    def get(self, job_id: str) -> Job | None:
        return self.jobs.get(job_id)

    def _start_render_worker(self) -> None:
        with self.lock:
            if self.render_worker is None:
                self.render_worker = threading.Thread(target=self._render_loop, daemon=True)
                self.render_worker.start()

    def _render_loop(self) -> None:
        while (job := self.renders.get()) is not None:
            self._run(job)

    def _run(self, job: Job) -> None:
        """Run the job's process to its end and record how it went."""
        try:
            with self.lock:
                if job.state != "queued":
                    return  # cancelled while it waited
                job.process = subprocess.Popen(
                    job.argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                    start_new_session=True, cwd=Path(__file__).resolve().parents[2],
                    # its scratch files too go under the job's folder: the studio writes
                    # only under its work directory
                    env=inherited(TQDM_DISABLE="1", TMPDIR=str(job.folder)))
                job.state = "running"
            stdout, stderr = job.process.communicate()
            with self.lock:
                if job.state == "cancelled":
                    return
                code = job.process.returncode
                if code == 0:
                    job.result, job.state = job.finish(job, stdout), "done"
                else:
                    job.error, job.state = _error_of(stderr, code), "failed"
        except Exception as exc:  # the job fails, never the server
            job.error, job.state = f"{type(exc).__name__}: {exc}", "failed"
        finally:
            job.ended.set()

    def cancel(self, job_id: str) -> bool:
        """End a job (its process group, then its files); False if there is no such job."""
        job = self.jobs.get(job_id)
        if job is None:
            return False
        with self.lock:
            if job.state in ("done", "failed", "cancelled"):
                return True
            job.state = "cancelled"
            process = job.process
        if process is not None:
            _stop(process)
            job.ended.wait(STOP_GRACE_SECONDS)
        shutil.rmtree(job.folder, ignore_errors=True)
        return True

    def close(self) -> None:
        """End every job (the studio is stopping)."""
        with self.lock:
            self.closed = True
        for job_id in list(self.jobs):
            self.cancel(job_id)
        self.renders.put(None)


def _stop(process: subprocess.Popen) -> None:
    """SIGTERM to the job's process group (the child cleans up: nothing half written), then
    SIGKILL if it has not ended within the grace period."""
    with contextlib.suppress(ProcessLookupError):
        os.killpg(process.pid, signal.SIGTERM)
    try:
        process.wait(STOP_GRACE_SECONDS)
    except subprocess.TimeoutExpired:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGKILL)
        process.wait()
