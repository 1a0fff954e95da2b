"""Loading a user's file: ``path/to/file.py:name`` run as a fresh module, ``name`` looked up.

The file runs once, from its syntax tree with ``name``'s returns rewritten
(:func:`usercode.rewriting.instrument`) and compiled under the file's own name, its folder
on ``sys.path`` while it loads (so it may import its neighbours), under the limits of the
user's code (:func:`usercode.limits.users_code`). Any failure is one line naming the file
and, where there is one, the line.
"""

from __future__ import annotations

import ast
import hashlib
import importlib.util
import inspect
import sys
from pathlib import Path
from types import ModuleType
from typing import Any, cast

from usercode.errors import UserHeuristicError, UserHeuristicExit, first_line, line_in, message
from usercode.limits import ending, users_code
from usercode.rewriting import HOOK, answer, instrument

__all__ = ["is_user_spec", "load_attribute"]


def is_user_spec(text: str) -> bool:
    """Whether a heuristic argument names a file of one's own (``file.py:function``).

    >>> is_user_spec("examples/my_heuristic.py:biggest_angle"), is_user_spec("scaling")
    (True, False)
    >>> is_user_spec("examples/my_heuristic.py")  # a file without its function: still meant
    True
    """
    return ".py:" in text or text.endswith(".py")


def load_attribute(spec: str) -> tuple[Path, str, Any]:
    """Run the file of ``path/to/file.py:name`` as a fresh module, ``name``'s returns rewritten
    (see the module docs); its path and ``name``'s value.

    Raises :class:`UserHeuristicError` (one line) for a spec without a name, a missing file, a
    syntax error or an exception while it loads, and a name the file does not define.
    """
    file_part, name = _split(spec)
    path = Path(file_part)
    if not path.exists():
        raise UserHeuristicError(f"{file_part}: no such file")
    if not path.is_file():
        raise UserHeuristicError(f"{file_part}: not a file")
    module = _load_module(path, file_part, name)
    if not hasattr(module, name):
        raise UserHeuristicError(f"{file_part}: no function '{name}'{_defined(module)}")
    return path, name, getattr(module, name)


def _split(spec: str) -> tuple[str, str]:
    """``file.py:name`` as its file and its name; one line when the name is missing or is no
    name."""
    file_part, colon, name = spec.rpartition(":") if ".py:" in spec else (spec, "", "")
    if not colon or not name:
        raise UserHeuristicError(
            f"{spec}: name the function too, as {file_part}:FUNCTION")
    if not name.isidentifier():
        raise UserHeuristicError(
            f"{spec}: '{name}' is not a function name; expected FILE.py:FUNCTION")
    return file_part, name


def _defined(module: ModuleType) -> str:
    """The hint after a missing name: the public functions the file does define."""
    defined = [k for k, v in vars(module).items()
               if inspect.isfunction(v) and v.__module__ == module.__name__
               and not k.startswith("_")]
    return f" (it defines: {', '.join(defined)})" if defined else " (it defines no function)"


def _compiled(path: Path, resolved: Path, shown: str, function: str | None):
    """The file's code, ``function``'s returns rewritten; and whether any were."""
    try:
        source = path.read_bytes()
    except OSError as exc:
        raise UserHeuristicError(f"{shown}: cannot read: {exc.strerror or exc}") from None
    try:
        tree = cast(ast.Module, compile(source, str(resolved), "exec", ast.PyCF_ONLY_AST,
                                        dont_inherit=True))  # PyCF_ONLY_AST: a Module
        rewritten = instrument(tree, function) if function else 0
        return compile(tree, str(resolved), "exec", dont_inherit=True), rewritten
    except SyntaxError as exc:
        where = f"{shown}:{exc.lineno}" if exc.lineno else shown
        said = first_line(exc.msg) or "invalid syntax"
        raise UserHeuristicError(f"{where}: syntax error: {said}") from None
    except ValueError as exc:  # e.g. null bytes
        raise UserHeuristicError(f"{shown}: cannot compile: {first_line(str(exc))}") from None


def _load_module(path: Path, shown: str, function: str | None = None) -> ModuleType:
    """Execute the file as a new module, once, with the returns of ``function`` rewritten;
    any failure becomes one line naming file and line.

    The module's name is the file's stem and a digest of its path, so two files of one name
    never share a module, and a failed load leaves none behind in ``sys.modules``."""
    resolved = path.resolve()
    digest = hashlib.sha1(str(resolved).encode()).hexdigest()[:10]
    module_name = f"_trex_user_{_identifier(path.stem)}_{digest}"
    code, rewritten = _compiled(path, resolved, shown, function)
    spec = importlib.util.spec_from_file_location(module_name, resolved)
    if spec is None:  # never for a file's path; said plainly all the same
        raise UserHeuristicError(f"{shown}: cannot be loaded as a module")
    module = importlib.util.module_from_spec(spec)
    if rewritten:
        setattr(module, HOOK, answer)
    sys.modules[module_name] = module
    folder = str(resolved.parent)
    sys.path.insert(0, folder)  # its neighbours import as they would beside it
    seen: list[int] = []
    try:
        with users_code(f"{shown}: loading", seen):
            exec(code, module.__dict__)
    except UserHeuristicError:
        sys.modules.pop(module_name, None)
        raise
    except BaseException as exc:
        sys.modules.pop(module_name, None)
        _raise_loading(exc, resolved, shown, seen)
    finally:
        if folder in sys.path:
            sys.path.remove(folder)
    return module


def _raise_loading(exc: BaseException, resolved: Path, shown: str, seen: list[int]) -> None:
    """Raise what ``exc``, raised while the file loaded, is to the command: an exit of its own
    (:class:`UserHeuristicExit`), a one-line error, or itself when it is a real interrupt."""
    line = line_in(exc, resolved)
    where = f"{shown}:{line}" if line else shown
    if isinstance(exc, SystemExit | KeyboardInterrupt) and not seen:
        told = ending(exc)
        raise UserHeuristicExit(f"{where}: {told} while loading: a heuristic's file "
                                "defines it, it does not end the program", way=told) from None
    if not isinstance(exc, Exception):
        raise  # a real interrupt, or Python's own (GeneratorExit …)
    raise UserHeuristicError(
        f"{where}: {type(exc).__name__} while loading: {message(exc)}") from None


def _identifier(text: str) -> str:
    return "".join(c if c.isalnum() else "_" for c in text) or "heuristic"
