"""SIGINT and SIGTERM while a command writes its output: raised as :class:`Interrupted`, so
that the command's cleanup runs, then only recorded, so that the cleanup is not interrupted in
turn; deferred or held while files are moved into place.

``trex render``, ``trex exercises``, ``trex lecture`` (and each chapter's process),
``trex hunt`` and the commands that build a directory (:mod:`trex.output_dir`) use them; an
interrupted command exits with :data:`EXIT_SIGNAL` + the signal's number.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading
from collections.abc import Callable, Iterator

from trex.exit_status import SIGNALLED

__all__ = ["EXIT_SIGNAL", "Interrupted", "Signals", "interrupts_raise", "signals_held"]

EXIT_SIGNAL = SIGNALLED  # + the signal's number, as a shell reports it (trex.exit_status)
_CAUGHT = (signal.SIGINT, signal.SIGTERM)
#: seconds an interrupted render has to end before it is stopped outright: a thread left
#: waiting inside manim (:mod:`trex.encoders` mends the known ways) must not keep a signalled
#: process alive for ever (seen once in CI, as a SIGTERM'd render that never exited)
STUCK_SECONDS = 20.0


class Interrupted(KeyboardInterrupt):
    """Ctrl-C or SIGTERM during a render (``signum`` says which)."""

    def __init__(self, signum: int = signal.SIGINT) -> None:
        super().__init__(signal.Signals(signum).name)
        self.signum = signum


class Signals:
    """What :func:`interrupts_raise` has seen: ``signum`` of the first SIGINT/SIGTERM, or None."""

    def __init__(self) -> None:
        self.signum: int | None = None
        self.done = False  # the output is in place: a signal now interrupts nothing
        self.deferring = 0  # inside :meth:`deferred`: a signal is noted, raised at its end
        self.said = ""  # the line an interrupted command says (:func:`interrupts_raise`)
        self.cleanups: list[Callable[[], None]] = []  # what :meth:`stuck_cleanup` registered
        self.watchdog: threading.Timer | None = None  # armed by the first signal
        self.over = False  # :func:`interrupts_raise` has ended: the watchdog has nothing to do

    @contextlib.contextmanager
    def stuck_cleanup(self, cleanup: Callable[[], None]) -> Iterator[None]:
        """While inside, a signal whose command has not ended :data:`STUCK_SECONDS` later
        runs ``cleanup`` (so nothing is left half-written), says the command's line and exits
        with :data:`EXIT_SIGNAL` + the signal."""
        self.cleanups.append(cleanup)
        try:
            yield
        finally:
            self.cleanups.remove(cleanup)

    def check(self) -> None:
        """Raise :class:`Interrupted` if a signal came (its exception may have been swallowed
        where Python ignores exceptions, such as a finalizer: this is the second chance)."""
        if self.signum is not None and not self.done:
            raise Interrupted(self.signum)

    @contextlib.contextmanager
    def deferred(self) -> Iterator[None]:
        """A signal during the block raises at its end, not inside it. (Blocking the signal in
        the main thread would not do: the kernel hands it to another thread, and Python still
        runs the handler in the main thread at once.)"""
        self.deferring += 1
        try:
            yield
        finally:
            self.deferring -= 1
            if not self.deferring:
                self.check()  # a signal came: interrupted, even if the block failed too


def _stop_if_stuck(seen: Signals, signum: int) -> None:
    """The watchdog's end: the command is still alive long after its signal."""
    if seen.done or seen.over:  # the command got out (a test in pytest's process, too)
        return
    stuck_inside = bool(seen.cleanups)  # else it ended its work and said so, then hung
    for cleanup in list(seen.cleanups):
        with contextlib.suppress(Exception):
            cleanup()
    if stuck_inside and seen.said:
        print(seen.said, file=sys.stderr, flush=True)
    os._exit(EXIT_SIGNAL + signum)


def _watch(seen: Signals, signum: int) -> None:
    """Start the watchdog of a signalled command that registered a cleanup."""
    if seen.cleanups and not seen.done:
        timer = threading.Timer(STUCK_SECONDS, _stop_if_stuck, (seen, signum))
        timer.daemon = True  # a command that ends in time ends it too
        seen.watchdog = timer
        timer.start()


@contextlib.contextmanager
def interrupts_raise(said: str = "") -> Iterator[Signals]:
    """SIGINT and SIGTERM raise :class:`Interrupted` (so cleanup runs) while inside; later
    signals are only recorded, so the cleanup is not interrupted in turn. ``said``: the line
    the command says when interrupted, said by the watchdog if the command is stuck
    (:meth:`Signals.stuck_cleanup`)."""
    seen = Signals()
    seen.said = said
    if threading.current_thread() is not threading.main_thread():
        yield seen
        return

    def handler(signum, _frame):
        if seen.signum is None:
            seen.signum = signum
            _watch(seen, signum)
            if not seen.done and not seen.deferring:
                raise Interrupted(signum)

    previous = {s: signal.signal(s, handler) for s in _CAUGHT}
    try:
        yield seen
    finally:
        seen.over = True
        if seen.watchdog is not None:
            seen.watchdog.cancel()
        for s, h in previous.items():
            signal.signal(s, h)


@contextlib.contextmanager
def signals_held() -> Iterator[None]:
    """SIGINT and SIGTERM wait (blocked) until the block ends: the moves happen together."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    before = signal.pthread_sigmask(signal.SIG_BLOCK, set(_CAUGHT))
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, before)
