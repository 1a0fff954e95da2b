"""The exit statuses of the trex commands, in one place (the README's "Exit status").

0 fine, 1 a finding (a wrong claim, a counterexample, a failed render), 2 bad input or a
failing user function, and 128 + N for a command stopped by signal N, as a shell reports
it: 130 for Ctrl-C (SIGINT), 143 for SIGTERM.
"""

from __future__ import annotations

import signal

OK = 0
FINDING = 1
BAD_INPUT = 2
SIGNALLED = 128  # + the signal's number


def interrupted(signum: int) -> int:
    """The status of a command stopped by signal ``signum``.

    >>> interrupted(signal.SIGINT), interrupted(signal.SIGTERM)
    (130, 143)
    """
    return SIGNALLED + int(signal.Signals(signum))


__all__ = ["BAD_INPUT", "FINDING", "OK", "SIGNALLED", "interrupted"]
