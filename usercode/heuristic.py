"""A heuristic of one's own, ``path/to/file.py:function``: loaded, checked and run like ours.

A user's heuristic is a function that takes a :class:`~geometry.polygon.Polygon` and returns
the diagonal it claims (an answer :func:`usercode.checking.endpoints` reads), all read in the
frame of the polygon it is handed: B its left-most vertex, A and C B's neighbours, the rest in
order, also for a piece of divide and conquer, which keeps its parent's labels otherwise
(:meth:`~geometry.polygon.Polygon.own_frame`). It may use the shared logger
(``@tracing.traced`` on its helpers, ``tracing.Shape`` for what it wants drawn);
:func:`load_user_heuristic` wraps it so that, like the built-in heuristics, the whole run is
one traced call named after the function and its answer is entered into the log by
:func:`geometry.frame.claim`, stated (``tracing.at_line``) on the line of the ``return`` the
function left by (:mod:`usercode.rewriting`), which the panel then lights.

Every problem is a :class:`~usercode.errors.UserHeuristicError` with a one-line message. A
``sys.exit()`` or a ``KeyboardInterrupt`` raised by the user's code itself is a
:class:`~usercode.errors.UserHeuristicExit`: an error of that function, never the end of the
command; a real Ctrl-C passes through as the interrupt it is (:mod:`usercode.limits`).

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
usercode.errors.UserHeuristicError: .../mine.py: no function 'nothing' (it defines: first_and_third)
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import tracing
from geometry.diagonals import find_diagonal
from geometry.frame import Diagonal, claim
from geometry.polygon import Polygon
from usercode.checking import claimed, endpoints
from usercode.errors import UserHeuristicError, UserHeuristicExit, line_in, message
from usercode.limits import ending, users_code
from usercode.loading import is_user_spec, load_attribute
from usercode.rewriting import returns_recorded

__all__ = ["UserHeuristic", "as_heuristic", "diagonal_rule", "load_user_heuristic",
           "run_heuristic"]


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
        The user's function as loaded, returns rewritten (undecorated if it was traced); the
        panel shows its source (:func:`story.source.shown_source`).
    function : callable
        ``polygon -> Diagonal``: the traced run, answer claimed and entered into the log.
    """

    spec: str
    name: str
    path: Path
    raw: Callable[[Polygon], object]
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


def load_user_heuristic(spec: str) -> UserHeuristic:
    """Load ``path/to/file.py:function`` and wrap the function (see the module docs).

    The file runs as a fresh module (:func:`usercode.loading.load_attribute`). Raises
    :class:`UserHeuristicError` with a one-line message.
    """
    return as_heuristic(spec, *load_attribute(spec))


def as_heuristic(spec: str, path: Path, name: str, value: Any) -> UserHeuristic:
    """Check that ``value`` (``name`` in the file ``path``) is a heuristic, and wrap it."""
    shown = spec.rpartition(":")[0] or str(path)
    if isinstance(value, type) or not callable(value):
        kind = "class" if isinstance(value, type) else type(value).__name__
        article = "an" if kind[:1].lower() in "aeiou" else "a"
        raise UserHeuristicError(f"{shown}: '{name}' is {article} {kind}, not a function")
    # a traced function is run undecorated: the wrapper makes the one traced call of the run
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


def diagonal_rule(heuristic: str | UserHeuristic | None):
    """What divide and conquer calls on each piece, as :func:`geometry.triangulate.triangulate`
    takes it: a built-in's name (None: gravity, geometry's default), or the traced run of a
    heuristic of one's own (loaded now if given as ``file.py:function``).

    >>> diagonal_rule("scaling"), diagonal_rule(None)
    ('scaling', None)
    """
    if isinstance(heuristic, UserHeuristic):
        return heuristic.function
    if heuristic is not None and is_user_spec(heuristic):
        return load_user_heuristic(heuristic).function
    return heuristic


def _wrap(raw: Callable[[Polygon], Any], name: str, path: Path) -> Callable[[Polygon], Diagonal]:
    """The traced run of the user's function: its answer claimed (entered into the log) on the
    line of the user's ``return`` that ran (the last line its rewritten returns recorded in
    this run), so the panel lights that line for the claim and its verdict as it does for our
    heuristics."""

    def heuristic(polygon: Polygon) -> Diagonal:
        start = len(tracing.events_so_far())
        # the function reads the polygon in its own frame (B its left-most vertex), as the
        # thesis does: a piece of divide and conquer keeps its parent's labels otherwise
        framed = polygon.own_frame()
        answer, lines = _call(raw, framed, name, path)
        u, v = endpoints(framed, answer, name)  # the answer, read in that frame
        if framed is not polygon:  # … is claimed in the polygon's own vertices
            u, v = (polygon.vertex(framed.source[w.index]) for w in (u, v))
        if claimed(tracing.events_so_far()[start:], f"{u.label}{v.label}"):
            return Diagonal(u, v)  # it called claim() itself: the log has it already
        with tracing.at_line(lines[-1] if lines else None):
            return claim(u, v)

    heuristic.__name__ = heuristic.__qualname__ = name
    heuristic.__doc__ = raw.__doc__
    return tracing.traced(name=name)(heuristic)


def _call(raw: Callable[[Polygon], Any], framed: Polygon, name: str,
          path: Path) -> tuple[Any, list[int | None]]:
    """The user's answer on ``framed`` and the lines of the returns it ran, under the limits
    of the user's code; whatever it raised, as one line (an exit of its own as
    :class:`UserHeuristicExit`; a real interrupt passes through)."""
    seen: list[int] = []
    with returns_recorded() as lines:
        try:
            with users_code(name, seen):
                return raw(framed), lines
        except UserHeuristicError:
            raise
        except (SystemExit, KeyboardInterrupt) as exc:
            if seen:
                raise  # a real Ctrl-C (or SIGTERM): the command's, not the function's
            line, told = line_in(exc, path), ending(exc)
            where = f" ({path.name}, line {line})" if line else ""
            raise UserHeuristicExit(f"{name} {told}{where}: a heuristic returns its claim, it "
                                    "does not end the program", way=told) from None
        except Exception as exc:
            line = line_in(exc, path)
            where = f" ({path.name}, line {line})" if line else ""
            raise UserHeuristicError(
                f"{name} raised {type(exc).__name__}: {message(exc)}{where}",
                way=f"raised {type(exc).__name__} at line {line}") from None
