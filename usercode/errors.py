"""The errors of a user's heuristic, each one line, and the words that tell what it raised.

Every problem with the user's code (a missing file, a syntax error, an exception it raised, a
wrong answer, a time limit passed) is a :class:`UserHeuristicError`, a ``ValueError`` with a
one-line message, so that the commands print it as they print bad input.
"""

from __future__ import annotations

import traceback
from pathlib import Path

__all__ = ["UserHeuristicError", "UserHeuristicExit", "first_line", "line_in", "message"]


class UserHeuristicError(ValueError):
    """A user's heuristic cannot be loaded or run; the message is one line.

    ``way`` tells failures apart without their particulars (``raised ZeroDivisionError at
    line 5``, ``timeout``, ``answer: label`` …): a hunt shrinks a polygon on which the function
    fails while it still fails the same way. By default the message itself.
    """

    def __init__(self, message: str, way: str | None = None) -> None:
        super().__init__(message)
        self.way = way if way is not None else message


class UserHeuristicExit(UserHeuristicError):
    """The user's code called ``sys.exit()`` or raised ``KeyboardInterrupt`` itself: it tried
    to end the program, which no polygon explains (``trex hunt`` reports it as bad input, not
    as a finding)."""


def first_line(text: str) -> str:
    """The first non-blank line of ``text``, stripped (a message must stay one line).

    >>> first_line("\\n  bad value\\nmore")
    'bad value'
    """
    lines = str(text).strip().splitlines()
    return lines[0].strip() if lines else ""


def message(exc: BaseException) -> str:
    """An exception's message in one line, its type's name when it has none."""
    return first_line(str(exc)) or type(exc).__name__


def line_in(exc: BaseException, path: Path) -> int | None:
    """The last line of ``path`` in the exception's traceback, if any: where in the user's
    own file it went wrong (the frames of our code around it are not the user's)."""
    found = None
    for frame in traceback.extract_tb(exc.__traceback__):
        if Path(frame.filename) == path:
            found = frame.lineno
    return found
