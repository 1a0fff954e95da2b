"""Which ``return`` ran: the user's function loaded with its returns rewritten to note their line.

The claim of a heuristic of one's own is stated (``tracing.at_line``) on the line of the
``return`` the function left by, which the panel then lights. That line is recorded, not
guessed, and with no tracer: in the file's syntax tree the function's own ``return``
statements (not those of functions, lambdas or classes nested in it) become ``return
__trex_answer__(<line>, <value>)``, as pytest rewrites asserts; the hook notes the line for
the run in progress and hands the value back unchanged. Only the body is rewritten, before
the module runs (once), so decorators apply to it as written; locations are kept and the tree
is compiled under the file's own name, so every other line number is the file's own. Nothing
rewritten (a callable object, a ``functools.partial`` …): nothing is recorded.

>>> tree = ast.parse("def f(p):\\n    return 1, 3\\n")
>>> _ = instrument(tree, "f")
>>> namespace = {HOOK: answer}
>>> exec(compile(tree, "mine.py", "exec"), namespace)
>>> with returns_recorded() as lines:
...     namespace["f"](None)
(1, 3)
>>> lines
[2]
"""

from __future__ import annotations

import ast
import contextlib
from contextvars import ContextVar
from typing import Any

__all__ = ["HOOK", "answer", "instrument", "returns_recorded"]

#: The global the rewritten returns call; set in the user's module before it runs.
HOOK = "__trex_answer__"

#: The record of the run in progress: the lines of the returns handed over, in order.
_RETURN_LINES: ContextVar[list[int | None] | None] = ContextVar("trex_return_lines", default=None)


@contextlib.contextmanager
def returns_recorded():
    """Open the record of one run: the list of the lines the rewritten returns hand over in
    it. A ``ContextVar``, so threads never mix and a run inside a run has its own; the last
    line is the ``return`` whose value the call returned (a recursive call's returns come
    before; a ``return`` in ``finally`` after the one it overrides)."""
    lines: list[int | None] = []
    token = _RETURN_LINES.set(lines)
    try:
        yield lines
    finally:
        _RETURN_LINES.reset(token)


def answer(line: int | None, value: Any) -> Any:
    """The hook of a rewritten ``return``: note its line for the run in progress (if any), and
    hand the value back unchanged."""
    lines = _RETURN_LINES.get()
    if lines is not None:
        lines.append(line)
    return value


def instrument(tree: ast.Module, name: str) -> int:
    """Rewrite, in place, the returns of each module-level definition of ``name`` (also under a
    module-level ``if``/``try``/``with`` …, never inside another function or class); how many
    definitions were rewritten.

    In a ``def name(...)``, each of its own ``return <value>`` becomes ``return
    __trex_answer__(<line of the return>, <value>)`` and a bare ``return`` hands over ``None``;
    returns of functions, lambdas and classes nested in it are untouched, and so are its
    decorators, defaults and annotations (they are not its body), so ``@tracing.traced`` or any
    other decorator applies to the rewritten function. A body that can fall off the end gets a
    last ``return __trex_answer__(None, None)`` with no location, like Python's own implicit
    return (no line event of its own): no ``return`` ran. For ``name = lambda polygon: <body>``
    the body is handed over on its own line. The new nodes take the location of the value they
    wrap (of the ``return``, for a bare one) and the values keep theirs, so tracebacks, the
    lines of traced calls and shapes made in a ``return`` expression, the line events a
    debugger or coverage sees and every other line are the file's own.

    A heuristic bound under another name (``mine = _impl``), imported from another file, a
    callable object or a ``functools.partial`` has nothing rewritten: nothing is recorded and
    its claim carries the line of the wrapper's call of ``claim``.

    >>> tree = ast.parse("def f(p):\\n    if p:\\n        return 1, 3\\n    g = lambda: 0\\n")
    >>> instrument(tree, "f"), instrument(ast.parse("x = 1"), "f")
    (1, 0)
    >>> print(ast.unparse(tree))
    def f(p):
        if p:
            return __trex_answer__(3, (1, 3))
        g = lambda: 0
        return __trex_answer__(None, None)
    """
    count = 0
    todo: list[ast.AST] = list(tree.body)
    while todo:
        node = todo.pop()
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            if node.name == name:
                _rewrite_function(node)
                count += 1
            continue
        if isinstance(node, ast.ClassDef):
            continue
        if _is_lambda_named(node, name):
            node.value.body = _handed(  # type: ignore[attr-defined]  # an Assign of a lambda
                node.value.body.lineno, node.value.body, node.value.body)  # type: ignore[attr-defined]
            count += 1
            continue
        todo.extend(child for child in ast.iter_child_nodes(node)
                    if isinstance(child, ast.stmt | ast.excepthandler | ast.match_case))
    return count


def _is_lambda_named(node: ast.AST, name: str) -> bool:
    """Whether ``node`` is ``name = lambda …`` (or ``name: T = lambda …``)."""
    targets = (node.targets if isinstance(node, ast.Assign)
               else [node.target] if isinstance(node, ast.AnnAssign) else [])
    return isinstance(getattr(node, "value", None), ast.Lambda) and any(
        isinstance(t, ast.Name) and t.id == name for t in targets)


def _rewrite_function(function: ast.FunctionDef | ast.AsyncFunctionDef) -> None:
    """Hand the function's own returns to the hook; a body that can fall off the end gets a
    last ``return`` of ``None`` with no line and no location (like Python's implicit one: no
    line event of its own). Decorators, defaults and annotations are not its body: untouched."""
    todo: list[ast.AST] = list(function.body)
    while todo:
        node = todo.pop()
        if isinstance(node, ast.Return):
            node.value = _handed(node.lineno, node.value, node.value or node)
        if not isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda | ast.ClassDef):
            todo.extend(ast.iter_child_nodes(node))
    if not isinstance(function.body[-1], ast.Return | ast.Raise):
        last = ast.Return(_handed(None, None, None))
        for node in ast.walk(last):
            # every node of a Return statement has a position
            node.lineno = node.end_lineno = node.col_offset = node.end_col_offset = -1  # type: ignore[attr-defined]
        function.body.append(last)


def _handed(line: int | None, value: ast.expr | None, where: ast.AST | None) -> ast.Call:
    """``__trex_answer__(line, value)``, the new nodes placed where ``where`` is (``value``
    keeps its own place). At the value's place, a multi-line ``return (\\n f(x))`` makes no line
    event on the ``return`` line before ``f(x)`` runs, as it makes none without the hook."""
    new = [ast.Name(HOOK, ast.Load()), ast.Constant(line)]
    if value is None:
        value = ast.Constant(None)
        new.append(value)
    call = ast.Call(new[0], [new[1], value], [])
    if where is not None:
        for node in (call, *new):
            ast.copy_location(node, where)
    return call
