"""Running a course's tasks on Dask distributed, resumable, with a progress line.

By default a :class:`distributed.LocalCluster` of one single-threaded worker process per
core (manim is not thread-safe); ``scheduler`` names an existing cluster's instead. Tasks
whose outputs are there with the same fingerprint are not submitted (``reused``); the
others go to the scheduler with their dependencies (a lecture's join waits for its
chapters), each retried ``retries`` times when it fails. A worker that dies mid-task has
its task run again elsewhere by the scheduler. Every task's record goes into the manifest
as it finishes; a failure does not stop the others.
"""

from __future__ import annotations

import logging
import os
import shutil
import sys
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from trex.course.manifest import read_manifest, record, reusable, write_manifest
from trex.course.tasks import Task
from trex.course.work import TEMP_SUFFIXES, Done, run_task
from trex.inputs import error_line

REPO = Path(__file__).resolve().parent.parent.parent
CONNECT_TIMEOUT = 10.0  # seconds an unreachable --scheduler is tried


def probe(address: str, seconds: float) -> None:
    """Connect to ``address`` and exchange Dask's handshake, within ``seconds`` and as many
    again for the handshake: an OSError if nothing answers. (Dask's own connect tries
    for ``seconds``, then waits for ever for a handshake from a port that accepts and says
    nothing.)"""
    import asyncio

    from distributed.comm import connect

    async def shake_hands() -> None:
        comm = await connect(address, timeout=seconds)
        await comm.close()

    try:
        asyncio.run(asyncio.wait_for(shake_hands(), 2 * seconds))
    except TimeoutError:  # (asyncio's own, here; connect says "Timed out trying …" itself)
        raise ConnectionError(f"connected, but no Dask handshake came in {2 * seconds:.0f} s "
                              "(not a Dask scheduler?)") from None


@contextmanager
def client_for(workers: int, scheduler: str | None) -> Iterator[Any]:
    """A Dask client: of ``scheduler``'s cluster, else of a local one of ``workers``
    single-threaded worker processes, which sees this checkout's code first."""
    from distributed import Client, LocalCluster

    from story.environment import inherited

    # manim's rich handler on the root logger would print every scheduler event
    logging.getLogger("distributed").setLevel(logging.ERROR)
    if scheduler is not None:
        try:  # no answer, a refused or unknown address: an OSError already
            probe(scheduler, CONNECT_TIMEOUT)
            client = Client(scheduler, timeout=f"{CONNECT_TIMEOUT}s")
        except OSError:
            raise
        except Exception as exc:  # something else answered (Dask reads its bytes as a frame)
            raise ConnectionError(f"did not answer as a Dask scheduler ({type(exc).__name__}: "
                                  f"{error_line(exc)})") from None
        with client:
            yield client
        return
    path = os.pathsep.join(p for p in (str(REPO), inherited().get("PYTHONPATH", "")) if p)
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                           dashboard_address=":0", silence_logs=logging.ERROR,
                           env={"PYTHONPATH": path})
    try:
        with Client(cluster) as client:
            yield client
    finally:
        cluster.close()


def sweep(tasks: Sequence[Task], out_dir: Path) -> int:
    """Remove what a task stopped mid-way left beside its outputs (a temporary file or
    directory named after one, ``.NAME.XXXX.render`` …); the number removed. Only when no
    task of this course runs."""
    removed = 0
    for folder, names in _output_names(tasks, out_dir).items():
        if not folder.is_dir():
            continue
        for entry in folder.iterdir():
            if not entry.name.startswith(".") or not entry.name.endswith(TEMP_SUFFIXES):
                continue
            if entry.name.split(".")[1] in names:
                shutil.rmtree(entry) if entry.is_dir() else entry.unlink()
                removed += 1
    return removed


def _output_names(tasks: Sequence[Task], out_dir: Path) -> dict[Path, set[str]]:
    """For each folder that receives outputs, the first dotted part of each name written
    there (``lecture``, ``01-overview``, ``student-3``: temporary names start with it)."""
    names: dict[Path, set[str]] = {}
    for task in tasks:
        for file in task.files:
            path = out_dir / file
            for part in (path, *path.parents):
                if part == out_dir:
                    break
                names.setdefault(part.parent, set()).add(part.name.split(".")[0])
    return names


class Progress:
    """``course: [#######.............] 3/8 tasks, 25.3 s of video, ETA 0:31; ID done``: one
    line per finished task (stderr)."""

    def __init__(self, total: int, reused: int, echo: Callable[[str], None]) -> None:
        self.total, self.done, self.seconds, self.echo = total, reused, 0.0, echo
        self.began, self.reused = time.monotonic(), reused

    def finished(self, task: Task, rec: dict[str, Any]) -> None:
        self.done += 1
        rendered_now = rec["status"] == "done" and task.kind != "join"  # a join renders none
        self.seconds += rec["video_seconds"] if rendered_now else 0.0
        rendered = self.done - self.reused
        left = self.total - self.done
        elapsed = time.monotonic() - self.began
        eta = f"ETA {_clock(elapsed / rendered * left)}" if rendered and left else "—"
        said = rec["status"] if rec["status"] != "failed" else f"FAILED: {rec['error']}"
        self.echo(f"course: [{bar(self.done, self.total)}] {self.done}/{self.total} tasks, "
                  f"{self.seconds:.1f} s of video, {eta}; {task.id} {said}")


def bar(done: int, total: int, width: int = 20) -> str:
    """``#####...............``: ``done`` of ``total`` as a bar of ``width`` characters.

    >>> bar(1, 4, 8)
    '##......'
    """
    filled = round(width * done / total) if total else width
    return "#" * filled + "." * (width - filled)


def _clock(seconds: float) -> str:
    minutes, secs = divmod(round(seconds), 60)
    return f"{minutes}:{secs:02d}"


def run_tasks(tasks: Sequence[Task], out_dir: Path, title: str, *, workers: int,
              scheduler: str | None, retries: int,
              echo: Callable[[str], None]) -> list[dict[str, Any]]:
    """Do every task (or reuse it); the manifest's records, in the tasks' order. An
    interrupt (from ``interrupts_raise``) cancels what runs and leaves what finished,
    recorded, in place."""
    previous = read_manifest(out_dir)
    records: dict[str, dict[str, Any]] = {}
    for task in tasks:
        old = reusable(task, previous, out_dir)
        if old is not None:
            records[task.id] = record(task, "reused", files=tuple(old["files"]),
                                      video_seconds=old.get("video_seconds") or 0.0,
                                      worker=old.get("worker"))
    sweep(tasks, out_dir)
    progress = Progress(len(tasks), len(records), echo)
    pending = [t for t in tasks if t.id not in records]
    if not pending:
        _write(out_dir, title, tasks, records)
        return _ordered(tasks, records)
    finished_cleanly = False
    try:
        with client_for(workers, scheduler) as client:
            echo(f"dashboard: {client.dashboard_link}")
            if scheduler is not None:
                _say_of_workers(client.nthreads(), scheduler, echo)
            _submit_and_wait(client, pending, records, out_dir, title, tasks, retries,
                             progress)
            finished_cleanly = True
    finally:
        if finished_cleanly or scheduler is None:  # no task of ours still writes
            sweep(tasks, out_dir)
        if records:  # (none: the cluster could not even be reached)
            _write(out_dir, title, tasks, records)
    return _ordered(tasks, records)


def _say_of_workers(threads: dict[str, int], address: str,
                    echo: Callable[[str], None]) -> None:
    """A line if the cluster at ``address`` has no worker yet (its tasks wait for one) or
    has workers of more than one thread (manim is not thread-safe); ``threads``: each
    worker's, by address.

    >>> _say_of_workers({}, "tcp://h:8786", print)
    course: no worker at tcp://h:8786 yet; the tasks wait for one (dask worker tcp://h:8786 --nthreads 1)
    >>> _say_of_workers({"tcp://a:1": 1, "tcp://b:2": 4}, "tcp://h:8786", print)
    warning: 1 of the 2 workers at tcp://h:8786 run several threads (4): manim is not thread-safe; start them with --nthreads 1
    """
    if not threads:
        echo(f"course: no worker at {address} yet; the tasks wait for one "
             f"(dask worker {address} --nthreads 1)")
    several = [n for n in threads.values() if n > 1]
    if several:
        echo(f"warning: {len(several)} of the {len(threads)} workers at {address} run several "
             f"threads ({max(several)}): manim is not thread-safe; start them with "
             "--nthreads 1")


def _submit_and_wait(client, pending: Sequence[Task], records: dict, out_dir: Path,
                     title: str, tasks: Sequence[Task], retries: int,
                     progress: Progress) -> None:
    from distributed import as_completed

    futures: dict[str, Any] = {}
    for task in pending:
        args = [futures[d] if d in futures else _done_of(records[d]) for d in task.deps]
        futures[task.id] = client.submit(run_task, task, str(out_dir), *args,
                                         key=f"{task.id}-{task.fingerprint[:12]}",
                                         retries=retries, pure=False)
    by_key = {f.key: t for t, f in zip(pending, futures.values(), strict=True)}
    try:
        for future in as_completed(list(futures.values())):
            task = by_key[future.key]
            records[task.id] = _record_of(task, future, futures)
            progress.finished(task, records[task.id])
            _write(out_dir, title, tasks, records)
    except BaseException:
        client.cancel(list(futures.values()), force=True)
        raise


def _done_of(rec: dict[str, Any]) -> Done:
    return Done(tuple(rec["files"]), rec.get("video_seconds") or 0.0, 0.0, rec.get("worker")
                or "")


def _record_of(task: Task, future, futures: dict[str, Any]) -> dict[str, Any]:
    if future.status == "finished":
        done: Done = future.result()
        return record(task, "done", files=done.files, video_seconds=done.video_seconds,
                      wall_seconds=done.wall_seconds, worker=done.worker)
    failed = [d for d in task.deps if d in futures and futures[d].status == "error"]
    if failed:
        return record(task, "failed", error=f"not run: {', '.join(failed)} failed")
    return record(task, "failed", error=_error_line(future))


def _error_line(future) -> str:
    from distributed import KilledWorker

    exc = future.exception()
    if isinstance(exc, KilledWorker):
        return "its worker died each time it ran it (KilledWorker)"
    text = str(exc).strip().splitlines()
    return text[0] if text else type(exc).__name__


def _ordered(tasks: Sequence[Task], records: dict) -> list[dict[str, Any]]:
    return [records[t.id] for t in tasks if t.id in records]


def _write(out_dir: Path, title: str, tasks: Sequence[Task], records: dict) -> None:
    write_manifest(out_dir, title, _ordered(tasks, records))


def stderr_echo(line: str) -> None:
    print(line, file=sys.stderr, flush=True)
