"""The chapters rendered in processes of their own, at most ``jobs`` at a time
(``trex lecture``, ``trex slides lecture``).

Each chapter is the hidden command ``trex chapter`` (:mod:`trex.chapter_command`) in its own
session, its output in a log file. The pool looks at the running processes every
:data:`POLL` seconds; the first that fails stops the others (SIGTERM: each removes its own
temporary files; killed after :data:`STOP_WAIT` seconds) and is reported, in one line, by the
last line its log holds.
"""

from __future__ import annotations

import signal
import subprocess
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from trex.chapter_command import chapter_command_line
from trex.chapters import Chapter, ChapterFailed, chapter_label, chapter_stem, scene_path
from trex.inputs import EXIT_INVALID, error_line, first_line
from trex.render_command import EXIT_FAILED
from usercode.limits import call_timeout

__all__ = ["POLL", "STOP_WAIT", "render_chapters"]

POLL = 0.05  # seconds between looks at the running renders
STOP_WAIT = 20.0  # seconds a stopped render may take to clean up before it is killed

#: ``done(k, chapter, video, seconds)``: told as chapter ``k`` finishes
Done = Callable[[int, Chapter, object, float], None]


@dataclass
class _Render:
    k: int
    chapter: Chapter
    process: subprocess.Popen
    log: Path
    output: Path
    began: float


def _start(k: int, chapter: Chapter, folder: Path, logs: Path, quality: str,
           polygon: str | None, panel: str | None = None) -> _Render:
    output = folder / f"{chapter_stem(chapter)}.mp4"
    log = logs / f"{chapter_stem(chapter)}.log"
    # with this command's --call-timeout, for the functions of one's own the chapter runs
    command = chapter_command_line(scene_path(chapter), chapter.scene_class, output, quality,
                                   polygon, panel, call_timeout())
    with open(log, "wb") as sink:
        # its own session: Ctrl-C at the terminal reaches only us, and we stop it
        process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=sink,
                                   stderr=subprocess.STDOUT, start_new_session=True)
    return _Render(k, chapter, process, log, output, time.monotonic())


def _reason(render: _Render, code: int) -> str:
    """Why a chapter's process failed: the last line it said, and the signal that killed it."""
    try:
        lines = render.log.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        lines = []
    said = next((first_line(line) for line in reversed(lines) if line.strip()), "")
    if said.startswith("error: "):
        said = said[len("error: "):]
    if code < 0:
        killed = f"render process killed by {signal.Signals(-code).name}"
        return f"{killed}: {said}" if said else killed
    return said or f"render process exited with status {code}"


def _stop(renders: Sequence[_Render]) -> None:
    """Stop running renders (SIGTERM: each removes its own temporary files), then wait."""
    for render in renders:
        if render.process.poll() is None:
            render.process.terminate()
    deadline = time.monotonic() + STOP_WAIT
    for render in renders:
        try:
            render.process.wait(max(0.0, deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            render.process.kill()
            render.process.wait()


def _finished(render: _Render, n: int):
    """The video of a render whose process ended well; :class:`ChapterFailed` otherwise."""
    from trex.assemble import probe

    code = render.process.returncode
    label = chapter_label(render.k, n, render.chapter)
    if code != 0:
        raise ChapterFailed(f"{label}: {_reason(render, code)}",
                            EXIT_INVALID if code == EXIT_INVALID else EXIT_FAILED)
    try:
        return probe(render.output)
    except (OSError, ValueError, RuntimeError) as exc:  # av errors are OSErrors
        raise ChapterFailed(f"{label}: unreadable video: {error_line(exc)}") from None


def render_chapters(chapters: Sequence[Chapter], folder: Path, logs: Path, quality: str,
                    jobs: int, polygon: str | None, done: Done | None = None,
                    panel: str | None = None) -> list:
    """Render every chapter to ``folder/NN-slug.mp4`` (+ .srt), ``jobs`` at a time, their
    panels showing ``panel`` (None: each scene's own).

    Returns the chapters' :class:`trex.assemble.Video` in chapter order; calls ``done`` as
    each one finishes. The first failure stops the others and raises
    :class:`trex.chapters.ChapterFailed`; an exception here (an interrupt) stops them too.
    """
    pending = list(enumerate(chapters))
    running: list[_Render] = []
    videos: list = [None] * len(chapters)
    try:
        while pending or running:
            while pending and len(running) < jobs:
                k, chapter = pending.pop(0)
                running.append(_start(k, chapter, folder, logs, quality, polygon, panel))
            time.sleep(POLL)
            for render in [r for r in running if r.process.poll() is not None]:
                running.remove(render)
                videos[render.k] = video = _finished(render, len(chapters))
                if done is not None:
                    done(render.k, render.chapter, video, time.monotonic() - render.began)
    finally:
        _stop(running)
    return videos
