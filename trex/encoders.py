"""Manim's encoder threads, each given its closing message however a render ends.

manim 0.22 encodes each play on a thread of its own (``_PartialMovieEncodeJob``), fed frames
through a bounded queue and stopped by the closing message ``(-1, None)``. The thread is not a
daemon: one left waiting for frames keeps the process alive for ever. An interrupt (Ctrl-C,
SIGTERM: raised in the main thread by :func:`trex.render_command.interrupts_raise`) could
leave one so in two ways:

1. ``seal()`` sets the job's ``_sealed`` *before* it puts the closing message. While the queue
   is full (the encoder is behind: the more encoders in flight on loaded cores, the more often)
   the put blocks, and a signal raising inside it loses the message. manim's own abort (its
   ``except BaseException`` around ``construct``) then calls ``seal()`` again, which sends
   nothing, and joins the thread: for ever (reproduced by
   ``tests/test_render_command.py::test_an_interrupt_inside_a_full_seal_still_exits``).
2. ``open_partial_movie_stream`` starts the thread before the writer keeps the job; a signal
   in between would orphan a thread nobody knows of.

:func:`guard` mends both on one scene's writer, without changing manim: it opens each stream
with signals deferred (2), notes every job opened, and before manim's abort runs, gives each
unfinished job its closing message, put with a short timeout and retried while its thread
lives (1), its queued frames discarded unencoded (the segment is thrown away: the process
exits sooner). The cleanup runs with signals deferred, so a second signal cannot interrupt
it.
"""

from __future__ import annotations

import contextlib
import queue
from collections.abc import Callable
from contextlib import AbstractContextManager
from typing import Any

#: What manim's encoder thread reads as "no more frames" (``_PartialMovieEncodeJob.seal``).
CLOSING = (-1, None)
#: How long one attempt to put the closing message waits: the thread drains its queue
#: meanwhile, so a later attempt finds room (or the thread has ended).
PUT_TIMEOUT = 0.1

Deferring = Callable[[], AbstractContextManager[object]]


def send_closing(job: Any) -> None:
    """Put the closing message on ``job``'s queue, unless or until its thread has ended.

    A blocking put could wait for ever on a queue nobody drains; a put with a timeout,
    retried while the thread lives, cannot. A second closing message, where the first did
    arrive, is harmless: the thread stops at the first one.
    """
    while job.thread.is_alive():
        try:
            job.queue.put(CLOSING, timeout=PUT_TIMEOUT)
            return
        except queue.Full:
            continue


def discard_frames(job: Any) -> None:
    """Take the frames still queued for ``job`` off its queue, unencoded."""
    with contextlib.suppress(queue.Empty):
        while True:
            job.queue.get_nowait()


class EncoderGuard:
    """Every encoder job one writer opened, and their closing (see the module's doc)."""

    def __init__(self, writer: Any, deferred: Deferring) -> None:
        self.writer = writer
        self.deferred = deferred
        self.jobs: list[Any] = []
        self._open = writer.open_partial_movie_stream
        self._abort = writer.abort_encode_jobs
        # patched on this writer only (instance attributes), for this one render
        writer.open_partial_movie_stream = self.open
        writer.abort_encode_jobs = self.abort

    def open(self, *args: Any, **kwargs: Any) -> None:
        """manim's ``open_partial_movie_stream``, never interrupted halfway (way 2)."""
        with self.deferred():
            self._open(*args, **kwargs)
            job = self.writer._current_encode_job
            self.jobs = [j for j in self.jobs if j.thread.is_alive()]  # keep it short
            if job is not None:
                self.jobs.append(job)

    def abort(self, *args: Any, **kwargs: Any) -> None:
        """manim's ``abort_encode_jobs``, after every unfinished job got its closing message
        (way 1); a signal meanwhile is raised once it is done."""
        with self.deferred():
            self.close()
            self._abort(*args, **kwargs)

    def close(self) -> None:
        """Tell every unfinished job to discard its segment, and send it its closing message."""
        for job in self.unfinished():
            job._abort_requested = True  # discard the segment (what manim's job.abort() sets)
            job._sealed = True  # manim's seal() then sends nothing more: it is sent here
            discard_frames(job)  # frames of a discarded segment need no encoding: exit sooner
            send_closing(job)

    def unfinished(self) -> list[Any]:
        """The jobs whose thread still runs."""
        return [job for job in self.jobs if job.thread.is_alive()]

    def stop(self) -> None:
        """After a render that raised: abort as manim does (it did not if the error came
        outside ``construct``), then wait for every thread noted, which now ends. All in one
        deferred block: a signal meanwhile is raised at its end, after the threads ended."""
        with self.deferred():
            with contextlib.suppress(Exception):
                self.abort()
            self.close()  # the abort may have failed before its close: again, harmlessly
            for job in self.jobs:
                job.thread.join()


class _NoEncoders:
    """A scene without manim's video writer (a still, a stand-in): nothing to close."""

    def stop(self) -> None:
        return None


def guard(scene: object, deferred: Deferring) -> EncoderGuard | _NoEncoders:
    """Guard the encoder threads of ``scene``'s writer (call before ``scene.render()``);
    ``deferred`` is a context in which SIGINT/SIGTERM are noted, raised at its end
    (:meth:`trex.render_command.Signals.deferred`)."""
    writer = getattr(getattr(scene, "renderer", None), "file_writer", None)
    if not (callable(getattr(writer, "open_partial_movie_stream", None))
            and callable(getattr(writer, "abort_encode_jobs", None))):
        return _NoEncoders()
    return EncoderGuard(writer, deferred)


__all__ = ["CLOSING", "EncoderGuard", "discard_frames", "guard", "send_closing"]
