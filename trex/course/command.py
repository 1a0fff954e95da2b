"""The ``trex course`` command: check the course file, plan, run, report.

Bad input (the course file, an item's field, a scene or polygon it names, the output
directory) is one line naming it and exit status 2, before anything is submitted. A task
that fails after its retries is a finding: every other task still completes, the failures
are listed, exit status 1. Ctrl-C or SIGTERM cancels what runs and keeps what finished
(exit 128 + the signal).
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import click

from trex.course.manifest import MANIFEST, read_manifest, reusable
from trex.course.run import run_tasks, stderr_echo
from trex.course.schema import Course, CourseError, read_course
from trex.course.tasks import Task, plan
from trex.inputs import error_line, fail
from trex.render_command import EXIT_FAILED
from trex.signals import EXIT_SIGNAL, Interrupted, interrupts_raise


def _check_output(out_dir: Path, tasks: list[Task]) -> None:
    """The output directory, and each slides folder in it: new or earlier slides."""
    from trex.output_dir import check_output
    from trex.slides_command import MARKER

    if out_dir.exists() and not out_dir.is_dir():
        fail(f"{out_dir}: exists and is not a directory")
    existing = next(p for p in (out_dir, *out_dir.resolve().parents) if p.exists())
    if not existing.is_dir() or not os.access(existing, os.W_OK | os.X_OK):
        fail(f"{out_dir}: cannot write to {existing}")  # created only when the course runs
    for task in tasks:
        folder = out_dir / Path(task.files[0]).parent
        if task.kind == "slides" and folder.exists():  # (check_output would create DIR)
            try:
                check_output(folder, MARKER, "earlier slides")
            except ValueError as exc:
                fail(f"{task.item}: {folder}: {exc}")


SCHEMES = ("tcp", "tls", "ws", "wss", "ucx")  # how a cluster of other processes is reached


def check_scheduler(address: str) -> str:
    """``address`` as Dask reaches it (``HOST:PORT`` gets ``tcp://``); a message naming
    what is wrong with it (a scheme, a port) raises ValueError, before anything is checked
    or written."""
    from distributed.comm.addressing import parse_address, parse_host_port

    scheme, location = parse_address(address)
    if scheme not in SCHEMES:
        raise ValueError(f"unknown scheme {scheme!r}; known: {', '.join(SCHEMES)} "
                         "(tcp://HOST:8786)")
    try:
        host, port = parse_host_port(location)  # no port, not a number, IPv6 unbracketed
    except ValueError:
        host, port = "", 0
    if not host or not 0 < port < 65536:
        raise ValueError("needs a host and a port from 1 to 65535 (tcp://HOST:8786)")
    return f"{scheme}://{location}"


def code_fingerprint() -> str:
    """What every task's output depends on besides its own settings: the code that renders
    (the project's sources, manim's version) and the ``TREX_*`` environment a scene reads
    when it is handed no polygon."""
    import json

    from story.environment import environment_values
    from trex import chapter_command as cc

    return cc.source_fingerprint() + json.dumps(environment_values(), sort_keys=True)


def _planned(course_file: str) -> tuple[Course, list[Task]]:
    try:
        course = read_course(Path(course_file))
        return course, plan(course, code_fingerprint())
    except CourseError as exc:
        fail(f"{course_file}: {exc}")


def _dry_run(tasks: list[Task], out_dir: Path) -> None:
    previous = read_manifest(out_dir)
    reused = 0
    for task in tasks:
        again = reusable(task, previous, out_dir) is not None
        reused += again
        after = f" (after {', '.join(task.deps)})" if task.deps and len(task.deps) < 4 else (
            f" (after {len(task.deps)} tasks)" if task.deps else "")
        click.echo(f"{task.id}: {task.kind} of {task.item}, "
                   f"{'reused' if again else 'to render'}{after}")
    click.echo(f"course: {len(tasks)} tasks, {len(tasks) - reused} to render, {reused} reused "
               "(dry run: nothing rendered)")


@click.command()
@click.argument("course_file", metavar="COURSE.toml")
@click.option("-o", "--output", "out_dir", required=True, metavar="DIR",
              help="Directory of the course's files and course.json (storage every worker "
                   "sees, with --scheduler).")
@click.option("--workers", type=click.IntRange(min=1), default=None,
              help="Worker processes of the local cluster (default: one per core).")
@click.option("--scheduler", metavar="ADDRESS",
              help="Use this running Dask scheduler (tcp://HOST:8786) instead of a local "
                   "cluster.")
@click.option("--dry-run", is_flag=True, help="List the tasks; render nothing.")
@click.option("--retries", type=click.IntRange(min=0), default=1, show_default=True,
              help="Times a failing task is run again before it counts as failed.")
def course(course_file: str, out_dir: str, workers: int | None, scheduler: str | None,
           dry_run: bool, retries: int) -> None:
    """Render the course COURSE.toml into DIR on Dask: lectures, scenes, slides and
    exercises, as tasks. A task already done with the same settings, inputs and code is
    reused; DIR/course.json lists every task.
    """
    if workers is not None and scheduler is not None:
        fail("--workers: the cluster at --scheduler has its own workers")
    if scheduler is not None:
        try:
            scheduler = check_scheduler(scheduler)
        except ValueError as exc:
            fail(f"--scheduler {scheduler}: {error_line(exc)}")
    with interrupts_raise():  # checking loads every scene and runs every polygon: a while
        try:
            course_, tasks = _planned(course_file)
        except Interrupted as exc:
            click.echo("error: course interrupted while checking; nothing written", err=True)
            raise click.exceptions.Exit(EXIT_SIGNAL + exc.signum) from None
    target = Path(out_dir)
    _check_output(target, tasks)
    if dry_run:
        _dry_run(tasks, target)
        return
    created = not target.exists()
    target.mkdir(parents=True, exist_ok=True)
    began = time.monotonic()
    with interrupts_raise() as signals:
        try:
            # the directory as every worker sees it, wherever it started
            records = run_tasks(tasks, target.resolve(), course_.title,
                                workers=workers or _cores(), scheduler=scheduler,
                                retries=retries, echo=stderr_echo)
            signals.done = True
        except Interrupted as exc:
            click.echo(f"error: course interrupted; the finished tasks are in {out_dir} "
                       f"({MANIFEST} lists them)", err=True)
            raise click.exceptions.Exit(EXIT_SIGNAL + exc.signum) from None
        except OSError as exc:  # the scheduler cannot be reached, DIR cannot be written
            signals.check()
            if created and not any(target.iterdir()):
                target.rmdir()  # nothing was done: leave no trace
            fail(f"{scheduler or out_dir}: {error_line(exc)}")
    _report(records, target, time.monotonic() - began)


def _cores() -> int:
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (
        os.cpu_count() or 1)


def _report(records: list[dict], target: Path, seconds: float) -> None:
    count = {s: sum(r["status"] == s for r in records) for s in ("done", "reused", "failed")}
    video = sum(r["video_seconds"] for r in records
                if r["status"] == "done" and r["kind"] != "join")  # a join renders nothing
    click.echo(f"course: {count['done']} done, {count['reused']} reused, {count['failed']} "
               f"failed; {video:.1f} s of video in {seconds:.1f} s")
    click.echo(str(target / MANIFEST))
    failed = [r for r in records if r["status"] == "failed"]
    for rec in failed:
        click.echo(f"error: {rec['id']} ({rec['item']}): {rec['error']}", err=True)
    if failed:
        raise click.exceptions.Exit(EXIT_FAILED)


COMMANDS = (course,)
