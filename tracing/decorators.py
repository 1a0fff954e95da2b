"""Decorators that record calls: :func:`traced` for functions, :func:`traced_class` for classes.

A traced function appends a ``call`` event (encoded arguments, caller's line) before it
runs and a ``return`` event (encoded result, or ``{"raised": name}``) after. With no
recording open, the wrapper costs one ``ContextVar.get`` before calling through.
The undecorated function stays reachable as ``wrapper.__wrapped__``.
"""

from __future__ import annotations

import functools
import inspect
import sys
from collections.abc import Callable, Iterable
from typing import Any, TypeVar

from tracing.encoding import encode, trace_key_of
from tracing.recorder import ACTIVE_RECORDER

__all__ = ["CallSpec", "traced", "traced_class"]

F = TypeVar("F", bound=Callable[..., Any])
C = TypeVar("C", bound=type)

_POSITIONAL_OR_KEYWORD = inspect.Parameter.POSITIONAL_OR_KEYWORD


class CallSpec:
    """What a traced function records, worked out once when it is decorated.

    Parameters
    ----------
    func : callable
        The undecorated function.
    name : str
        Name written into its events.
    exclude_args : iterable of str
        Parameters left out of ``args``.
    keep_result : bool
        Whether return events carry the encoded result.
    is_method : bool
        Whether the first parameter is ``self``/``cls`` (recorded as ``target``).

    Examples
    --------
    >>> def scale(self, factor, origin=(0, 0), *, clamp=False): ...
    >>> spec = CallSpec(scale, "scale", ("clamp",), True, is_method=True)
    >>> spec.encode_args(("shape", 2.0), {})
    {'factor': 2.0, 'origin': [0, 0]}
    >>> spec.encode_args(("shape",), {}) is None  # missing argument: cannot bind
    True
    """

    __slots__ = (
        "_fast",
        "_kept",
        "_signature",
        "_simple",
        "_size",
        "is_method",
        "keep_result",
        "name",
    )

    def __init__(
        self,
        func: Callable[..., Any],
        name: str,
        exclude_args: Iterable[str],
        keep_result: bool,
        is_method: bool,
    ) -> None:
        self.name = name
        self.keep_result = keep_result
        self.is_method = is_method
        self._signature = inspect.signature(func)
        params = list(self._signature.parameters.values())
        names = [param.name for param in params]
        excluded = set(exclude_args)
        unknown = sorted(excluded - set(names))
        if unknown:
            raise ValueError(f"{name}() has no parameter(s) {unknown} to exclude")
        first = 1 if is_method else 0
        self._kept = frozenset(names[first:]) - excluded
        self._fast = tuple((i, n) for i, n in enumerate(names) if i >= first and n in self._kept)
        self._simple = all(param.kind is _POSITIONAL_OR_KEYWORD for param in params)
        self._size = len(params)

    def encode_args(self, args: tuple[Any, ...], kwargs: dict[str, Any]) -> dict[str, Any] | None:
        """Return the encoded arguments in signature order, or ``None`` if they do not bind."""
        if not kwargs and self._simple and len(args) == self._size:
            return {name: encode(args[i]) for i, name in self._fast}
        try:
            bound = self._signature.bind(*args, **kwargs)
        except TypeError:
            return None
        bound.apply_defaults()
        kept = self._kept
        return {name: encode(value) for name, value in bound.arguments.items() if name in kept}


def traced(
    func: F | None = None,
    /,
    *,
    name: str | None = None,
    exclude_args: Iterable[str] = (),
    result: bool = True,
) -> Any:
    """Record every call of a function while a recording is open.

    Use bare (``@traced``) or with options (``@traced(name=..., exclude_args=..., result=...)``).
    A function defined in a class whose first parameter is ``self`` or ``cls`` is a
    method: that argument is not recorded; its ``trace_key`` (or ``None``) is the target.

    Parameters
    ----------
    func : callable, optional
        The function, when used bare.
    name : str, optional
        Name for the events; defaults to ``func.__name__``.
    exclude_args : iterable of str
        Parameters not to record (big inputs such as the whole polygon).
    result : bool
        Record the encoded return value (``False`` records ``None``).

    Returns
    -------
    callable
        The wrapper, or a decorator when called with options only.

    Examples
    --------
    >>> import tracing
    >>> @traced(exclude_args=("table",))
    ... def lookup(table, key):
    ...     return table[key]
    >>> with tracing.record() as log:
    ...     lookup({"a": 1}, "a")
    1
    >>> [(e.kind, e.name, e.args, e.result) for e in log.events]
    [('call', 'lookup', {'key': 'a'}, None), ('return', 'lookup', None, 1)]
    >>> lookup.__wrapped__({"b": 2}, "b")  # the undecorated function
    2
    """

    def decorate(function: F) -> F:
        is_method = _looks_like_method(function)
        return _wrap(function, name or function.__name__, exclude_args, result, is_method)

    return decorate if func is None else decorate(func)


def traced_class(cls: C | None = None, /, *, exclude: Iterable[str] = ()) -> Any:
    """Trace every public method of a class (the thesis's ``transform_into_logger``).

    Methods (including static and class methods) whose names do not start with ``_``
    are wrapped with :func:`traced`, except those in ``exclude``, methods already
    traced, and generator or coroutine functions. The instance's ``trace_key``
    becomes the events' target. The class is changed in place and returned.

    Parameters
    ----------
    cls : type, optional
        The class, when used bare.
    exclude : iterable of str
        Method names to leave alone.

    Examples
    --------
    >>> import tracing
    >>> @traced_class(exclude=("helper",))
    ... class Counter:
    ...     trace_key = "counter"
    ...     def __init__(self):
    ...         self.n = 0
    ...     def bump(self, by=1):
    ...         self.n += self.helper(by)
    ...         return self.n
    ...     def helper(self, by):
    ...         return by
    >>> with tracing.record() as log:
    ...     Counter().bump()
    1
    >>> [(e.kind, e.name, e.target, e.args) for e in log.events]
    [('call', 'bump', 'counter', {'by': 1}), ('return', 'bump', 'counter', None)]
    """

    def decorate(klass: C) -> C:
        exclude_set = set(exclude)
        missing = sorted(n for n in exclude_set if not hasattr(klass, n))
        if missing:
            raise ValueError(f"{klass.__name__} has no attribute(s) {missing} to exclude")
        for attr, member in list(vars(klass).items()):
            if attr.startswith("_") or attr in exclude_set:
                continue
            wrapped = _trace_member(member, attr)
            if wrapped is not None:
                setattr(klass, attr, wrapped)
        return klass

    return decorate if cls is None else decorate(cls)


def _trace_member(member: Any, attr: str) -> Any:
    """Return the traced version of a class member, or ``None`` to leave it alone."""
    if isinstance(member, staticmethod | classmethod):
        function = member.__func__
        if not _can_trace(function):
            return None
        is_method = isinstance(member, classmethod)
        return type(member)(_wrap(function, attr, (), True, is_method))
    if inspect.isfunction(member) and _can_trace(member):
        return _wrap(member, attr, (), True, True)
    return None


def _can_trace(function: Callable[..., Any]) -> bool:
    """Return whether ``function`` is a plain, not yet traced function."""
    return not (
        hasattr(function, "__trace_spec__")
        or inspect.isgeneratorfunction(function)
        or inspect.iscoroutinefunction(function)
        or inspect.isasyncgenfunction(function)
    )


def _looks_like_method(function: Callable[..., Any]) -> bool:
    """Return whether ``function`` is defined in a class body with ``self``/``cls`` first."""
    parts = getattr(function, "__qualname__", "").split(".")
    if len(parts) < 2 or parts[-2] == "<locals>":
        return False
    params = list(inspect.signature(function).parameters)
    return bool(params) and params[0] in ("self", "cls")


def _wrap(func: F, name: str, exclude_args: Iterable[str], keep_result: bool, is_method: bool) -> F:
    """Build the recording wrapper around ``func``."""
    if inspect.isgeneratorfunction(func) or inspect.iscoroutinefunction(func):
        raise TypeError(f"cannot trace {name}(): generators and coroutines are not supported")
    spec = CallSpec(func, name, exclude_args, keep_result, is_method)
    encode_args, keep_result, is_method = spec.encode_args, spec.keep_result, spec.is_method
    current_recorder = ACTIVE_RECORDER.get
    get_frame = sys._getframe

    @functools.wraps(func)
    def traced_call(*args: Any, **kwargs: Any) -> Any:
        recorder = current_recorder()
        if recorder is None:
            return func(*args, **kwargs)
        line = get_frame(1).f_lineno
        encoded = encode_args(args, kwargs)
        if encoded is None:  # the arguments do not fit: let the function raise its TypeError
            return func(*args, **kwargs)
        target = trace_key_of(args[0]) if is_method and args else None
        seq = recorder.open_call(name, target, encoded, line)
        try:
            value = func(*args, **kwargs)
        except BaseException as error:
            recorder.close_call(seq, name, target, {"raised": type(error).__name__}, line)
            raise
        recorder.close_call(seq, name, target, encode(value) if keep_result else None, line)
        return value

    traced_call.__trace_spec__ = spec  # type: ignore[attr-defined]
    return traced_call  # type: ignore[return-value]
