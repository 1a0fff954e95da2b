"""The source the panel shows: a function's lines without decorators, docstring or blanks.

One rule for every function the panel shows, a built-in's (:func:`metaphors.pseudocode.source_of`)
and a heuristic of one's own (whose rows a run records in its log's ``code``, so that a saved
log shows them too: :func:`story.runs.record_user_run`). No manim here.
"""

from __future__ import annotations

import ast
import inspect
import textwrap
from collections.abc import Callable

__all__ = ["shown_source"]


def shown_source(function: Callable[..., object]) -> tuple[tuple[int, str], ...]:
    """(line number, text) of a function as the panel shows it: no decorators, docstring or
    blank lines, tabs as four spaces; empty when its source cannot be read. The panel shows
    built-ins the same way (:func:`metaphors.pseudocode.source_of`). A lambda, or source
    that does not parse on its own, is shown whole.

    >>> [text for _, text in shown_source(shown_source)][:2]
    ['def shown_source(function: Callable[..., object]) -> tuple[tuple[int, str], ...]:', '    try:']
    >>> mine = lambda polygon: (1, 3)
    >>> [text for _, text in shown_source(mine)]
    ['mine = lambda polygon: (1, 3)']
    """
    try:
        lines, first = inspect.getsourcelines(function)
    except (OSError, TypeError):
        return ()
    text = textwrap.dedent("".join(lines)).splitlines()
    hidden = _hidden_lines("\n".join(text))
    return tuple((first + k, line.rstrip().expandtabs(4)) for k, line in enumerate(text)
                 if k + 1 not in hidden and line.strip())


def _hidden_lines(source: str) -> set[int]:
    """The lines (from 1) of a function's decorators and docstring; none if ``source`` is not
    one function that parses (a lambda, a string at column 0 in a nested function)."""
    try:
        tree = ast.parse(source)
    except SyntaxError:
        return set()
    node = tree.body[0] if len(tree.body) == 1 else None
    if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
        return set()
    hidden = set(range(1, node.lineno))  # decorators (a def's line is the ``def``)
    doc = node.body[0]
    if (isinstance(doc, ast.Expr) and isinstance(doc.value, ast.Constant)
            and isinstance(doc.value.value, str) and doc.lineno > node.lineno
            and (len(node.body) == 1 or node.body[1].lineno > (doc.end_lineno or doc.lineno))):
        hidden.update(range(doc.lineno, (doc.end_lineno or doc.lineno) + 1))
    return hidden
