"""The user's code runs under limits: a time limit, its prints on stderr, its exits told apart.

The user's code runs in this process (a run being recorded for a video is recorded in the
process that renders), so nothing but these limits keeps a loop that never ends, a print or
a ``sys.exit()`` of its own from becoming the command's.
"""

from __future__ import annotations

import contextlib
import signal
import sys
import threading
import time
from contextvars import ContextVar

from usercode.errors import UserHeuristicError

__all__ = ["DEFAULT_CALL_TIMEOUT", "call_timeout", "ending", "set_call_timeout", "users_code"]

#: Seconds a user's function (and the loading of its file) may take, by default.
DEFAULT_CALL_TIMEOUT = 5.0

_CALL_TIMEOUT: ContextVar[float | None] = ContextVar("trex_call_timeout",
                                                     default=DEFAULT_CALL_TIMEOUT)


def set_call_timeout(seconds: float | None) -> None:
    """Limit each call of a user's function (and each load of a file) to ``seconds``; None or
    0: no limit. The commands' ``--call-timeout`` sets it."""
    _CALL_TIMEOUT.set(seconds if seconds and seconds > 0 else None)


def call_timeout() -> float | None:
    """The limit in force (seconds), None for none."""
    return _CALL_TIMEOUT.get()


class _Stopped(BaseException):
    """Raised in the user's code by SIGALRM when the time is up (a BaseException, so that the
    user's own ``except Exception`` does not swallow it)."""


def _on_main_thread() -> bool:
    """Signals reach, and handlers can be set in, the main thread only."""
    return threading.current_thread() is threading.main_thread()


@contextlib.contextmanager
def _time_limit(what: str):
    """Stop the block after :func:`call_timeout` seconds with a one-line
    :class:`UserHeuristicError` saying so.

    SIGALRM in the main thread (``signal.setitimer``). Off the main thread, or where there is
    no ``setitimer``, there is no limit. A previous alarm (a limit around a limit) is restored
    afterwards, less the time spent.
    """
    seconds = call_timeout()
    if seconds is None or not hasattr(signal, "setitimer") or not _on_main_thread():
        yield
        return

    def stop(_signum, _frame):
        raise _Stopped

    previous = signal.signal(signal.SIGALRM, stop)
    started = time.monotonic()
    outer, _ = signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    except _Stopped:
        raise UserHeuristicError(
            f"{what} did not finish within {seconds:g} s: stopped "
            "(a loop that never ends? --call-timeout sets the limit)", way="timeout") from None
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        if outer:
            signal.setitimer(signal.ITIMER_REAL, max(outer - (time.monotonic() - started), 1e-3))


@contextlib.contextmanager
def _signals_noted(seen: list[int]):
    """Note in ``seen`` each SIGINT/SIGTERM that arrives during the block, then let the handler
    in force act on it as before (Python's own raises ``KeyboardInterrupt``; a command's may
    raise its own interrupt). A ``KeyboardInterrupt`` with nothing noted was raised by the
    user's code itself. A signal with no Python handler (SIGTERM by default) ends the process
    as it would have; off the main thread no signal can raise, so nothing needs noting."""
    if not _on_main_thread():
        yield
        return
    previous = {}
    for signum in (signal.SIGINT, signal.SIGTERM):
        handler = signal.getsignal(signum)
        if callable(handler):
            def note(number, frame, handler=handler):
                seen.append(number)
                handler(number, frame)
            previous[signum] = signal.signal(signum, note)
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)


@contextlib.contextmanager
def users_code(what: str, seen: list[int]):
    """Run the user's code: within the time limit (:func:`_time_limit`, ``what`` names it in
    the message), its prints on stderr (a command's stdout may be one JSON line), real
    interrupts noted in ``seen``.

    The prints are moved in the main thread only, where the commands run: ``sys.stdout`` is
    one for all threads, and two threads swapping it at once (a server's) could leave it
    swapped for good."""
    main = _on_main_thread()
    prints = contextlib.redirect_stdout(sys.stderr) if main else contextlib.nullcontext()
    with _time_limit(what), _signals_noted(seen), prints:
        yield


def ending(exc: SystemExit | KeyboardInterrupt) -> str:
    """What the user's code did to end the program.

    >>> ending(SystemExit(3)), ending(SystemExit()), ending(KeyboardInterrupt())
    ('called sys.exit(3)', 'called sys.exit()', 'raised KeyboardInterrupt')
    """
    if isinstance(exc, SystemExit):
        return f"called sys.exit({'' if exc.code is None else repr(exc.code)})"
    return f"raised {type(exc).__name__}"
