"""Heuristics of your own: ``path/to/file.py:function``, loaded, checked and run like ours.

A user's heuristic is a function that takes a :class:`~geometry.polygon.Polygon` and returns
the diagonal it claims: a :class:`~geometry.frame.Diagonal`, or a pair of vertices given as
indices (``polygon.points[i]``), labels (``"B"``) or :class:`~geometry.polygon.Vertex`
objects. It may use the shared logger (``@tracing.traced`` on its helpers,
``tracing.Shape`` for what it wants drawn); :func:`load_user_heuristic` wraps it so that,
like the built-in heuristics, the whole run is one traced call named after the function
and its answer is entered into the log by :func:`geometry.frame.claim`, stated
(``tracing.at_line``) on the line of the function's ``return``, which the panel then lights.

Every problem is a :class:`UserHeuristicError` (a ``ValueError``) with a one-line message:
a missing file, a syntax error in it, a missing or non-callable function, an exception the
function raised, an answer that is not two vertices of the polygon.

No manim here.

Examples
--------
>>> import tempfile, textwrap, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> _ = (folder / "mine.py").write_text(textwrap.dedent('''
...     def first_and_third(polygon):
...         return 1, 3
... '''))
>>> h = load_user_heuristic(f"{folder}/mine.py:first_and_third")
>>> h.name
'first_and_third'
>>> from geometry.polygon import Polygon
>>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
>>> h.run(p).name
'BD'
>>> load_user_heuristic(f"{folder}/mine.py:nothing")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
geometry.user_heuristics.UserHeuristicError: .../mine.py: no function 'nothing' (it defines: first_and_third)
"""

from __future__ import annotations

import ast
import hashlib
import importlib.util
import inspect
import operator
import sys
import textwrap
import traceback
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import tracing
from geometry.diagonals import find_diagonal
from geometry.frame import Diagonal, claim
from geometry.polygon import Polygon, Vertex

__all__ = [
    "UserHeuristic",
    "UserHeuristicError",
    "as_heuristic",
    "is_user_spec",
    "load_attribute",
    "load_user_heuristic",
    "run_heuristic",
]


class UserHeuristicError(ValueError):
    """A user's heuristic cannot be loaded or run; the message is one line."""


def is_user_spec(text: str) -> bool:
    """Whether a heuristic argument names a file of one's own (``file.py:function``).

    >>> is_user_spec("examples/my_heuristic.py:biggest_angle"), is_user_spec("scaling")
    (True, False)
    >>> is_user_spec("examples/my_heuristic.py")  # a file without its function: still meant
    True
    """
    return ".py:" in text or text.endswith(".py")


@dataclass(frozen=True)
class UserHeuristic:
    """A loaded heuristic of one's own.

    Attributes
    ----------
    spec : str
        As given: ``path/to/file.py:function``.
    name : str
        The function's name; the traced call of the whole run carries it.
    path : Path
        The file, resolved.
    raw : callable
        The user's function (undecorated if it was traced).
    function : callable
        ``polygon -> Diagonal``: the traced run, answer claimed and entered into the log.
    """

    spec: str
    name: str
    path: Path
    raw: Callable[[Polygon], Any]
    function: Callable[[Polygon], Diagonal]

    def __str__(self) -> str:
        return self.spec

    def run(self, polygon: Polygon) -> Diagonal:
        """Run it on a polygon (alive in the log meanwhile, as :func:`find_diagonal` does)."""
        with tracing.alive(polygon):
            return self.function(polygon)

    @property
    def title(self) -> str:
        """``name: first line of its docstring`` (just the name without a docstring)."""
        doc = inspect.getdoc(self.raw) or ""
        first = doc.strip().splitlines()[0].strip() if doc.strip() else ""
        return f"{self.name}: {first}" if first else self.name

    def source(self) -> tuple[tuple[int, str], ...]:
        """(line number, text) of the function as the panel shows it: no decorators,
        docstring or blank lines (the same rule as :func:`metaphors.pseudocode.source_of`)."""
        try:
            lines, first = inspect.getsourcelines(self.raw)
        except (OSError, TypeError):
            return ()
        text = textwrap.dedent("".join(lines)).splitlines()
        kept: list[tuple[int, str]] = []
        in_doc = False
        for number, line in ((first + k, line.rstrip()) for k, line in enumerate(text)):
            stripped = line.strip()
            if stripped.startswith("@") and not kept:
                continue
            if in_doc:
                in_doc = not any(stripped.endswith(q) for q in ('"""', "'''"))
                continue
            if stripped.startswith(('"""', "'''")):
                quote = stripped[:3]
                in_doc = stripped.count(quote) < 2
                continue
            if stripped:
                kept.append((number, line))
        return tuple(kept)


def load_user_heuristic(spec: str) -> UserHeuristic:
    """Load ``path/to/file.py:function`` and wrap the function (see the module docs).

    The file runs as a fresh module (its folder is on ``sys.path`` while it loads, so it may
    import its neighbours). Raises :class:`UserHeuristicError` with a one-line message.
    """
    return as_heuristic(spec, *load_attribute(spec))


def load_attribute(spec: str) -> tuple[Path, str, Any]:
    """Run the file of ``path/to/file.py:name`` as a fresh module; its path and ``name``'s value.

    Raises :class:`UserHeuristicError` (one line) for a spec without a name, a missing file, a
    syntax error or an exception while it loads, and a name the file does not define.
    """
    file_part, colon, name = spec.rpartition(":") if ".py:" in spec else (spec, "", "")
    if not colon or not name:
        raise UserHeuristicError(
            f"{spec}: name the function too, as {file_part}:FUNCTION")
    if not name.isidentifier():
        raise UserHeuristicError(
            f"{spec}: '{name}' is not a function name; expected FILE.py:FUNCTION")
    path = Path(file_part)
    if not path.exists():
        raise UserHeuristicError(f"{file_part}: no such file")
    if not path.is_file():
        raise UserHeuristicError(f"{file_part}: not a file")
    module = _load_module(path, file_part)
    if not hasattr(module, name):
        defined = [k for k, v in vars(module).items()
                   if inspect.isfunction(v) and v.__module__ == module.__name__
                   and not k.startswith("_")]
        hint = f" (it defines: {', '.join(defined)})" if defined else " (it defines no function)"
        raise UserHeuristicError(f"{file_part}: no function '{name}'{hint}")
    return path, name, getattr(module, name)


def as_heuristic(spec: str, path: Path, name: str, value: Any) -> UserHeuristic:
    """Check that ``value`` (``name`` in the file ``path``) is a heuristic, and wrap it."""
    shown = spec.rpartition(":")[0] or str(path)
    if isinstance(value, type) or not callable(value):
        kind = "class" if isinstance(value, type) else type(value).__name__
        article = "an" if kind[:1].lower() in "aeiou" else "a"
        raise UserHeuristicError(f"{shown}: '{name}' is {article} {kind}, not a function")
    raw = getattr(value, "__wrapped__", value) if hasattr(value, "__trace_spec__") else value
    try:
        inspect.signature(raw).bind(None)
    except TypeError:
        raise UserHeuristicError(
            f"{shown}: {name}() must take one argument, the polygon") from None
    except ValueError:  # no signature to inspect (a builtin): let the call tell
        pass
    return UserHeuristic(spec, name, path.resolve(), raw, _wrap(raw, name, path.resolve()))


def run_heuristic(polygon: Polygon, heuristic: str | UserHeuristic) -> Diagonal:
    """Run a built-in heuristic by name, or one of one's own (a spec or a loaded one)."""
    if isinstance(heuristic, UserHeuristic):
        return heuristic.run(polygon)
    if is_user_spec(heuristic):
        return load_user_heuristic(heuristic).run(polygon)
    return find_diagonal(polygon, heuristic)


# --- loading ---------------------------------------------------------------------------------------


def _load_module(path: Path, shown: str):
    """Execute the file as a new module; any failure becomes one line naming file and line."""
    resolved = path.resolve()
    digest = hashlib.sha1(str(resolved).encode()).hexdigest()[:10]
    module_name = f"_trex_user_{_identifier(path.stem)}_{digest}"
    try:
        source = path.read_bytes()
    except OSError as exc:
        raise UserHeuristicError(f"{shown}: cannot read: {exc.strerror or exc}") from None
    try:
        code = compile(source, str(resolved), "exec", dont_inherit=True)
    except SyntaxError as exc:
        where = f"{shown}:{exc.lineno}" if exc.lineno else shown
        message = _first_line(exc.msg) or "invalid syntax"
        raise UserHeuristicError(f"{where}: syntax error: {message}") from None
    except ValueError as exc:  # e.g. null bytes
        raise UserHeuristicError(f"{shown}: cannot compile: {_first_line(str(exc))}") from None
    spec = importlib.util.spec_from_file_location(module_name, resolved)
    module = importlib.util.module_from_spec(spec)
    sys.modules[module_name] = module
    folder = str(resolved.parent)
    sys.path.insert(0, folder)
    try:
        exec(code, module.__dict__)
    except BaseException as exc:
        sys.modules.pop(module_name, None)
        if not isinstance(exc, Exception):
            raise
        line = _line_in(exc, resolved)
        where = f"{shown}:{line}" if line else shown
        raise UserHeuristicError(
            f"{where}: {type(exc).__name__} while loading: {_message(exc)}") from None
    finally:
        if folder in sys.path:
            sys.path.remove(folder)
    return module


def _identifier(text: str) -> str:
    return "".join(c if c.isalnum() else "_" for c in text) or "heuristic"


def _first_line(text: str) -> str:
    lines = str(text).strip().splitlines()
    return lines[0].strip() if lines else ""


def _message(exc: BaseException) -> str:
    return _first_line(str(exc)) or type(exc).__name__


def _line_in(exc: BaseException, path: Path) -> int | None:
    """The last line of ``path`` in the exception's traceback, if any."""
    found = None
    for frame in traceback.extract_tb(exc.__traceback__):
        if Path(frame.filename) == path:
            found = frame.lineno
    return found


# --- running -----------------------------------------------------------------------------------------


def _wrap(raw: Callable[[Polygon], Any], name: str, path: Path) -> Callable[[Polygon], Diagonal]:
    """The traced run of the user's function: its answer claimed (entered into the log) on the
    line of the user's ``return`` (see :func:`_return_line`), so the panel lights that line
    for the claim and its verdict as it does for our heuristics."""
    returns, span = _returns_of(raw)

    def heuristic(polygon: Polygon) -> Diagonal:
        start = len(tracing.events_so_far())
        try:
            answer = raw(polygon)
        except Exception as exc:
            line = _line_in(exc, path)
            where = f" ({path.name}, line {line})" if line else ""
            raise UserHeuristicError(
                f"{name} raised {type(exc).__name__}: {_message(exc)}{where}") from None
        u, v = endpoints(polygon, answer, name)
        logged = tracing.events_so_far()[start:]
        if _claimed(logged, f"{u.label}{v.label}"):
            return Diagonal(u, v)  # it called claim() itself: the log has it already
        with tracing.at_line(_return_line(returns, span, logged)):
            return claim(u, v)

    heuristic.__name__ = heuristic.__qualname__ = name
    heuristic.__doc__ = raw.__doc__
    return tracing.traced(name=name)(heuristic)


def _returns_of(function: Callable[..., Any]) -> tuple[tuple[int, ...], range]:
    """File lines where the function's own ``return`` statements start (not nested ones), in
    order, and the range of the function's lines; nothing when its source cannot be read."""
    try:
        lines, first = inspect.getsourcelines(function)
        tree = ast.parse(textwrap.dedent("".join(lines)))
    except (OSError, TypeError, SyntaxError, ValueError):
        return (), range(0)
    defs = [n for n in tree.body if isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef)]
    if not defs:
        return (), range(0)
    found, todo = set(), list(defs[0].body)
    while todo:
        node = todo.pop()
        if isinstance(node, ast.Return):
            found.add(node.lineno + first - 1)
        if not isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda | ast.ClassDef):
            todo.extend(ast.iter_child_nodes(node))
    return tuple(sorted(found)), range(first, first + len(lines))


def _return_line(
    returns: tuple[int, ...], span: range, logged: Sequence[tracing.Event]
) -> int | None:
    """The line of the ``return`` the function left by, as far as its source and the events
    it logged tell (``None``: no return statement to name).

    Which return ran is not in the log, and we do not trace the user's lines. With one
    ``return``, that one. With several, the first at or below the last line of the function
    that logged something itself (a traced call, a shape, a note: the run's shallowest
    events; not the exit of a ``with``, which carries the ``with`` line), else the last one.
    That is right for an early return after a check (the example's ``if not candidates``);
    it is a guess when a loop with a ``return`` in it runs out, or when the function logs
    nothing. A function that returns ``claim(u, v)`` itself has its line recorded exactly.

    >>> from tracing import Event
    >>> logged = [Event(5, "call", "candidates", line=28, depth=1, call=5),
    ...           Event(6, "return", "candidates", line=28, depth=1, call=5),
    ...           Event(7, "exit", "polygon", "T(ABC)", line=27, depth=1, call=1)]
    >>> _return_line((30, 39), range(23, 40), logged), _return_line((30, 39), range(23, 40), [])
    (30, 39)
    """
    if len(returns) < 2:
        return returns[0] if returns else None
    depth = min((e.depth for e in logged), default=0)
    lines = [e.line for e in logged
             if e.depth == depth and e.kind != "exit" and e.line is not None and e.line in span]
    if lines:
        below = [line for line in returns if line >= lines[-1]]
        if below:
            return below[0]
    return returns[-1]


def _claimed(events, key: str) -> bool:
    return any(e.kind == "return" and e.name == "claim" and e.result == {"ref": key}
               for e in events)


def endpoints(polygon: Polygon, answer: Any, name: str = "the heuristic") -> tuple[Vertex, Vertex]:
    """The two vertices of an answer: a Diagonal, or a pair of indices, labels or Vertex objects.

    >>> p = Polygon.from_points([(1, 4.5), (9, 2), (3, 6.5), (4.6, 4.1), (1.6, 8)])
    >>> [v.label for v in endpoints(p, ("B", 4))]
    ['B', 'E']
    >>> endpoints(p, ("B", "Q"), "mine")
    Traceback (most recent call last):
    ...
    geometry.user_heuristics.UserHeuristicError: mine returned ('B', 'Q'): 'Q' is not a vertex label (A … E)
    """
    if isinstance(answer, Diagonal):
        pair: Any = (answer.u, answer.v)
    else:
        pair = answer
    try:
        items = list(pair) if not isinstance(pair, str | bytes | dict) else None
    except TypeError:
        items = None
    if items is None or len(items) != 2:
        raise UserHeuristicError(
            f"{name} returned {_short(answer)}: expected a Diagonal or a pair of vertices "
            "(indices, labels or Vertex objects)")
    return _vertex(polygon, items[0], answer, name), _vertex(polygon, items[1], answer, name)


def _vertex(polygon: Polygon, item: Any, answer: Any, name: str) -> Vertex:
    n = polygon.n
    if isinstance(item, Vertex):
        if 0 <= item.index < n and polygon.points[item.index] == item.point:
            return polygon.vertex(item.index)
        raise UserHeuristicError(
            f"{name} returned {_short(answer)}: vertex {item.label} is not a vertex of this polygon")
    if isinstance(item, str):
        if item in polygon.labels:
            return polygon.vertex(polygon.labels.index(item))
        raise UserHeuristicError(
            f"{name} returned {_short(answer)}: {item!r} is not a vertex label "
            f"({polygon.labels[0]} … {polygon.labels[-1]})")
    if not isinstance(item, bool):
        try:
            index = operator.index(item)
        except TypeError:
            index = None
        if index is not None:
            if 0 <= index < n:
                return polygon.vertex(index)
            raise UserHeuristicError(
                f"{name} returned {_short(answer)}: index {index} is out of range 0…{n - 1}")
    raise UserHeuristicError(
        f"{name} returned {_short(answer)}: {_short(item)} is not a vertex "
        "(give an index, a label or a Vertex)")


def _short(value: Any) -> str:
    text = " ".join(repr(value).split())
    return text if len(text) <= 60 else text[:57] + "..."
