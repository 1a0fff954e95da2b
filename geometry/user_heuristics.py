"""Heuristics of your own: ``path/to/file.py:function``, loaded, checked and run like ours.

A user's heuristic is a function that takes a :class:`~geometry.polygon.Polygon` and returns
the diagonal it claims: a :class:`~geometry.frame.Diagonal`, or a pair of vertices given as
indices (``polygon.points[i]``), labels (``"B"``) or :class:`~geometry.polygon.Vertex`
objects, all read in the frame of the polygon it is handed: B its left-most vertex, A and C
B's neighbours, the rest in order, also for a piece of divide and conquer, which keeps its
parent's labels otherwise (:meth:`~geometry.polygon.Polygon.own_frame`). It may use the shared logger (``@tracing.traced`` on its helpers,
``tracing.Shape`` for what it wants drawn); :func:`load_user_heuristic` wraps it so that,
like the built-in heuristics, the whole run is one traced call named after the function
and its answer is entered into the log by :func:`geometry.frame.claim`, stated
(``tracing.at_line``) on the line of the ``return`` the function left by, which the panel
then lights.

That line is recorded, not guessed, and with no tracer: the file is loaded from its syntax
tree, in which the function's own ``return`` statements (not those of functions, lambdas or
classes nested in it) become ``return __trex_answer__(<line>, <value>)``, as pytest rewrites
asserts; the hook notes the line for the run in progress and hands the value back unchanged
(details: :func:`_instrument`). Only the body is rewritten, before the module runs (once), so
decorators apply to it as written; locations are kept and the tree is compiled under the
file's own name, so every other line number is the file's own. Nothing rewritten (a callable
object, a ``functools.partial`` …): the claim keeps the line of the wrapper's call.

Every problem is a :class:`UserHeuristicError` (a ``ValueError``) with a one-line message:
a missing file, a syntax error in it, a missing or non-callable function, an exception the
function raised, an answer that is not two vertices of the polygon. A ``sys.exit()`` or a
``KeyboardInterrupt`` raised by the user's code itself is a :class:`UserHeuristicExit` (one of
them): an error of that function, never the end of the command; a real Ctrl-C (SIGINT, or
SIGTERM where a handler of ours raises) passes through as the interrupt it is. Whatever the
user's code prints goes to stderr, so a command's stdout (``--json``) stays its own.

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
import contextlib
import hashlib
import importlib.util
import inspect
import operator
import signal
import sys
import textwrap
import threading
import time
import traceback
from collections.abc import Callable
from contextvars import ContextVar
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import tracing
from geometry.diagonals import find_diagonal
from geometry.frame import Diagonal, claim
from geometry.polygon import Polygon, Vertex

__all__ = [
    "DEFAULT_CALL_TIMEOUT",
    "UserHeuristic",
    "UserHeuristicError",
    "UserHeuristicExit",
    "as_heuristic",
    "call_timeout",
    "is_user_spec",
    "load_attribute",
    "load_user_heuristic",
    "run_heuristic",
    "set_call_timeout",
]


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


# --- the time limit --------------------------------------------------------------------------------

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


@contextlib.contextmanager
def _time_limit(what: str):
    """Stop the block after :func:`call_timeout` seconds with a one-line
    :class:`UserHeuristicError` saying so.

    SIGALRM in the main thread (``signal.setitimer``): the user's code runs in this process,
    so a run being recorded for a video is recorded here, in the process that renders. Off
    the main thread, or where there is no ``setitimer``, there is no limit. A previous alarm
    (a limit around a limit) is restored afterwards, less the time spent.
    """
    seconds = call_timeout()
    if (seconds is None or not hasattr(signal, "setitimer")
            or threading.current_thread() is not threading.main_thread()):
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
    if threading.current_thread() is not threading.main_thread():
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
def _users_code(what: str, seen: list[int]):
    """Run the user's code: within the time limit (:func:`_time_limit`), its prints on stderr
    (a command's stdout may be one JSON line), real interrupts noted in ``seen``.

    The prints are moved in the main thread only, where the commands run: ``sys.stdout`` is
    one for all threads, and two threads swapping it at once (a server's) could leave it
    swapped for good."""
    main = threading.current_thread() is threading.main_thread()
    prints = contextlib.redirect_stdout(sys.stderr) if main else contextlib.nullcontext()
    with _time_limit(what), _signals_noted(seen), prints:
        yield


def _ending(exc: SystemExit | KeyboardInterrupt) -> str:
    """What the user's code did to end the program: ``called sys.exit(3)``."""
    if isinstance(exc, SystemExit):
        return f"called sys.exit({'' if exc.code is None else repr(exc.code)})"
    return f"raised {type(exc).__name__}"


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
        The user's function as loaded, returns rewritten (undecorated if it was traced).
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
        """(line number, text) of the function as the panel shows it (:func:`shown_source`)."""
        return shown_source(self.raw)


def shown_source(function) -> tuple[tuple[int, str], ...]:
    """(line number, text) of a function as the panel shows it: no decorators, docstring or
    blank lines, tabs as four spaces; empty when its source cannot be read. The panel shows
    built-ins the same way (:func:`metaphors.pseudocode.source_of`). A lambda, or source
    that does not parse on its own, is shown whole.

    >>> [text for _, text in shown_source(shown_source)][:2]
    ['def shown_source(function) -> tuple[tuple[int, str], ...]:', '    try:']
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


def is_user_spec(text: str) -> bool:
    """Whether a heuristic argument names a file of one's own (``file.py:function``).

    >>> is_user_spec("examples/my_heuristic.py:biggest_angle"), is_user_spec("scaling")
    (True, False)
    >>> is_user_spec("examples/my_heuristic.py")  # a file without its function: still meant
    True
    """
    return ".py:" in text or text.endswith(".py")


def load_user_heuristic(spec: str) -> UserHeuristic:
    """Load ``path/to/file.py:function`` and wrap the function (see the module docs).

    The file runs as a fresh module (its folder is on ``sys.path`` while it loads, so it may
    import its neighbours). Raises :class:`UserHeuristicError` with a one-line message.
    """
    return as_heuristic(spec, *load_attribute(spec))


def load_attribute(spec: str) -> tuple[Path, str, Any]:
    """Run the file of ``path/to/file.py:name`` as a fresh module, ``name``'s returns rewritten
    (see the module docs); its path and ``name``'s value.

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
    module = _load_module(path, file_part, name)
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


def _load_module(path: Path, shown: str, function: str | None = None):
    """Execute the file as a new module, once, with the returns of ``function`` rewritten
    (:func:`_instrument`); any failure becomes one line naming file and line."""
    resolved = path.resolve()
    digest = hashlib.sha1(str(resolved).encode()).hexdigest()[:10]
    module_name = f"_trex_user_{_identifier(path.stem)}_{digest}"
    try:
        source = path.read_bytes()
    except OSError as exc:
        raise UserHeuristicError(f"{shown}: cannot read: {exc.strerror or exc}") from None
    try:
        tree: ast.Module = compile(source, str(resolved), "exec", ast.PyCF_ONLY_AST, dont_inherit=True)  # type: ignore[assignment]  # with PyCF_ONLY_AST and "exec", compile returns an ast.Module
        rewritten = _instrument(tree, function) if function else 0
        code = compile(tree, str(resolved), "exec", dont_inherit=True)
    except SyntaxError as exc:
        where = f"{shown}:{exc.lineno}" if exc.lineno else shown
        message = _first_line(exc.msg) or "invalid syntax"
        raise UserHeuristicError(f"{where}: syntax error: {message}") from None
    except ValueError as exc:  # e.g. null bytes
        raise UserHeuristicError(f"{shown}: cannot compile: {_first_line(str(exc))}") from None
    spec = importlib.util.spec_from_file_location(module_name, resolved)
    module = importlib.util.module_from_spec(spec)  # type: ignore[arg-type]  # a file path ending in .py always has a spec
    if rewritten:
        setattr(module, _HOOK, _answer)
    sys.modules[module_name] = module
    folder = str(resolved.parent)
    sys.path.insert(0, folder)
    seen: list[int] = []
    try:
        with _users_code(f"{shown}: loading", seen):
            exec(code, module.__dict__)
    except UserHeuristicError:
        sys.modules.pop(module_name, None)
        raise
    except BaseException as exc:
        sys.modules.pop(module_name, None)
        line = _line_in(exc, resolved)
        where = f"{shown}:{line}" if line else shown
        if isinstance(exc, SystemExit | KeyboardInterrupt) and not seen:
            told = _ending(exc)
            raise UserHeuristicExit(f"{where}: {told} while loading: a heuristic's file "
                                    "defines it, it does not end the program", way=told) from None
        if not isinstance(exc, Exception):
            raise  # a real interrupt, or Python's own (GeneratorExit …)
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


# --- which return ran ------------------------------------------------------------------------------

#: The global the rewritten returns call; set in the user's module before it runs.
_HOOK = "__trex_answer__"

#: The record of the run in progress: the lines of the returns handed over, in order.
_RETURN_LINES: ContextVar[list[int | None] | None] = ContextVar("trex_return_lines", default=None)


def _answer(line: int | None, value: Any) -> Any:
    """The hook of a rewritten ``return``: note its line for the run in progress (if any), and
    hand the value back unchanged."""
    lines = _RETURN_LINES.get()
    if lines is not None:
        lines.append(line)
    return value


def _instrument(tree: ast.Module, name: str) -> int:
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

    At run time the hook (:func:`_answer`) appends the line to the record of the run in
    progress, a list the wrapper opens per run in a ``ContextVar`` (threads never mix, a run
    inside a run has its own); the last line recorded is the ``return`` whose value the call
    returned (a recursive call's returns come before; a ``return`` in ``finally`` after the
    one it overrides). A heuristic bound under another name (``mine = _impl``), imported from
    another file, a callable object or a ``functools.partial`` has nothing rewritten: nothing
    is recorded and its claim carries the line of the wrapper's call of ``claim``.

    >>> tree = ast.parse("def f(p):\\n    if p:\\n        return 1, 3\\n    g = lambda: 0\\n")
    >>> _instrument(tree, "f"), _instrument(ast.parse("x = 1"), "f")
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
        targets = (node.targets if isinstance(node, ast.Assign)
                   else [node.target] if isinstance(node, ast.AnnAssign) else [])
        value = getattr(node, "value", None)
        if isinstance(value, ast.Lambda) and any(
                isinstance(t, ast.Name) and t.id == name for t in targets):
            value.body = _handed(value.body.lineno, value.body, value.body)
            count += 1
            continue
        todo.extend(child for child in ast.iter_child_nodes(node)
                    if isinstance(child, ast.stmt | ast.excepthandler | ast.match_case))
    return count


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
            node.lineno = node.end_lineno = node.col_offset = node.end_col_offset = -1  # type: ignore[attr-defined]  # the nodes of a return statement, which all have positions
        function.body.append(last)


def _handed(line: int | None, value: ast.expr | None, where: ast.AST | None) -> ast.Call:
    """``__trex_answer__(line, value)``, the new nodes placed where ``where`` is (``value``
    keeps its own place). At the value's place, a multi-line ``return (\n f(x))`` makes no line
    event on the ``return`` line before ``f(x)`` runs, as it makes none without the hook."""
    new = [ast.Name(_HOOK, ast.Load()), ast.Constant(line)]
    if value is None:
        value = ast.Constant(None)
        new.append(value)
    call = ast.Call(new[0], [new[1], value], [])
    if where is not None:
        for node in (call, *new):
            ast.copy_location(node, where)
    return call


# --- running -----------------------------------------------------------------------------------------


def _wrap(raw: Callable[[Polygon], Any], name: str, path: Path) -> Callable[[Polygon], Diagonal]:
    """The traced run of the user's function: its answer claimed (entered into the log) on the
    line of the user's ``return`` that ran (the last line its rewritten returns recorded in
    this run; see the module docs), so the panel lights that line for the claim and its
    verdict as it does for our heuristics."""

    def heuristic(polygon: Polygon) -> Diagonal:
        start = len(tracing.events_so_far())
        lines: list[int | None] = []
        seen: list[int] = []
        token = _RETURN_LINES.set(lines)
        # the function reads the polygon in its own frame (B its left-most vertex), as the
        # thesis does: a piece of divide and conquer keeps its parent's labels otherwise
        framed = polygon.own_frame()
        try:
            with _users_code(name, seen):
                answer = raw(framed)
        except UserHeuristicError:
            raise
        except (SystemExit, KeyboardInterrupt) as exc:
            if seen:
                raise  # a real Ctrl-C (or SIGTERM): the command's, not the function's
            line, told = _line_in(exc, path), _ending(exc)
            where = f" ({path.name}, line {line})" if line else ""
            raise UserHeuristicExit(f"{name} {told}{where}: a heuristic returns its claim, it "
                                    "does not end the program", way=told) from None
        except Exception as exc:
            line = _line_in(exc, path)
            where = f" ({path.name}, line {line})" if line else ""
            raise UserHeuristicError(
                f"{name} raised {type(exc).__name__}: {_message(exc)}{where}",
                way=f"raised {type(exc).__name__} at line {line}") from None
        finally:
            _RETURN_LINES.reset(token)
        u, v = endpoints(framed, answer, name)  # the answer, read in that frame
        if framed is not polygon:  # … is claimed in the polygon's own vertices
            u, v = (polygon.vertex(framed.source[w.index]) for w in (u, v))
        if _claimed(tracing.events_so_far()[start:], f"{u.label}{v.label}"):
            return Diagonal(u, v)  # it called claim() itself: the log has it already
        with tracing.at_line(lines[-1] if lines else None):
            return claim(u, v)

    heuristic.__name__ = heuristic.__qualname__ = name
    heuristic.__doc__ = raw.__doc__
    return tracing.traced(name=name)(heuristic)


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
            "(indices, labels or Vertex objects)", way="answer: not a pair")
    return _vertex(polygon, items[0], answer, name), _vertex(polygon, items[1], answer, name)


def _vertex(polygon: Polygon, item: Any, answer: Any, name: str) -> Vertex:
    n = polygon.n
    if isinstance(item, Vertex):
        if 0 <= item.index < n and polygon.points[item.index] == item.point:
            return polygon.vertex(item.index)
        raise UserHeuristicError(
            f"{name} returned {_short(answer)}: vertex {item.label} is not a vertex of this polygon",
            way="answer: a vertex of another polygon")
    if isinstance(item, str):
        if item in polygon.labels:
            return polygon.vertex(polygon.labels.index(item))
        raise UserHeuristicError(
            f"{name} returned {_short(answer)}: {item!r} is not a vertex label "
            f"({polygon.labels[0]} … {polygon.labels[-1]})", way="answer: not a label")
    if not isinstance(item, bool):
        try:
            index = operator.index(item)
        except TypeError:
            index = None
        if index is not None:
            if 0 <= index < n:
                return polygon.vertex(index)
            raise UserHeuristicError(
                f"{name} returned {_short(answer)}: index {index} is out of range 0…{n - 1}",
                way="answer: index out of range")
    raise UserHeuristicError(
        f"{name} returned {_short(answer)}: {_short(item)} is not a vertex "
        "(give an index, a label or a Vertex)", way="answer: not a vertex")


def _short(value: Any) -> str:
    text = " ".join(repr(value).split())
    return text if len(text) <= 60 else text[:57] + "..."
