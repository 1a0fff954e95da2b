"""The exit statuses every ``trex`` command keeps (README, "Exit statuses"): one place.

0 fine; 1 a finding (a wrong claim, a counterexample, a stopped triangulation, a snapshot that
differs, a chapter that failed to render); 2 bad input or a failing function of one's own
(click's usage errors are 2 as well); 130 interrupted by Ctrl-C, as a shell reports SIGINT.

>>> INTERRUPTED == 128 + 2
True
"""

from __future__ import annotations

import signal

OK = 0
FINDING = 1
INVALID = 2
#: 128 + the signal's number is how a shell reports a process a signal ended.
SIGNALLED = 128
INTERRUPTED = SIGNALLED + signal.SIGINT


def worst(*statuses: int) -> int:
    """The status of several results together: bad input outweighs a finding, which
    outweighs fine.

    >>> worst(OK, FINDING, OK), worst(FINDING, INVALID), worst()
    (1, 2, 0)
    """
    return max(statuses, default=OK)
