"""SIGINT and SIGTERM while a command writes its output: raised as :class:`Interrupted`, so
that the command's cleanup runs, then only recorded, so that the cleanup is not interrupted in
turn; deferred or held while files are moved into place.

``trex render``, ``trex exercises``, ``trex lecture`` (and each chapter's process),
``trex hunt`` and the commands that build a directory (:mod:`trex.output_dir`) use them; an
interrupted command exits with :data:`EXIT_SIGNAL` + the signal's number.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator

from trex.exit_status import SIGNALLED

__all__ = ["EXIT_SIGNAL", "Interrupted", "Signals", "interrupts_raise", "signals_held"]

EXIT_SIGNAL = SIGNALLED  # + the signal's number, as a shell reports it (trex.exit_status)
_CAUGHT = (signal.SIGINT, signal.SIGTERM)


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


@contextlib.contextmanager
def interrupts_raise() -> Iterator[Signals]:
    """SIGINT and SIGTERM raise :class:`Interrupted` (so cleanup runs) while inside; later
    signals are only recorded, so the cleanup is not interrupted in turn."""
    seen = Signals()
    if threading.current_thread() is not threading.main_thread():
        yield seen
        return

    def handler(signum, _frame):
        if seen.signum is None:
            seen.signum = signum
            if not seen.done and not seen.deferring:
                raise Interrupted(signum)

    previous = {s: signal.signal(s, handler) for s in _CAUGHT}
    try:
        yield seen
    finally:
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
