"""Decorators that record calls: :func:`traced` for functions, :func:`traced_class` for classes.

A traced function appends a ``call`` event (encoded arguments, caller's line) before it
runs and a ``return`` event (encoded result, or ``{"raised": name}``) after. With no
recording open, the wrapper costs one ``ContextVar.get`` before calling through.
The undecorated function stays reachable as ``wrapper.__wrapped__``.

A call can also end and start object lifetimes: ``consumes`` names the arguments that
exit the log when it returns, ``produces`` lets its result enter. :func:`traced` takes
both options; :func:`lifetimes` records only the lifetimes, no call. So an algorithm
that turns objects into others needs no explicit ``enter``/``exit``.
"""

from __future__ import annotations

import functools
import inspect
import sys
from collections.abc import Callable, Iterable
from typing import Any, TypeVar, overload

from tracing.encoding import encode, trace_key_of
from tracing.recorder import ACTIVE_RECORDER, Recorder

__all__ = ["CallSpec", "Lifetimes", "lifetimes", "traced", "traced_class"]

F = TypeVar("F", bound=Callable[..., Any])
C = TypeVar("C", bound=type)

_POSITIONAL_OR_KEYWORD = inspect.Parameter.POSITIONAL_OR_KEYWORD
_POSITIONAL = (inspect.Parameter.POSITIONAL_ONLY, _POSITIONAL_OR_KEYWORD)


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


class Lifetimes:
    """Which objects a call ends and starts in the log, worked out once when it is decorated.

    When the call returns, the objects passed as the ``consumes`` parameters exit
    and, with ``produces``, the result enters: a tuple or list result item by item,
    any other result as it is. ``None`` (an optional argument left out, nothing
    made) stands for no object. A call that raises ends and starts nothing.

    Parameters
    ----------
    func : callable
        The undecorated function.
    name : str
        Its name, for error messages.
    consumes : iterable of str
        Parameters whose objects exit the log when the call returns.
    produces : bool
        Whether the result enters the log then.
    produced_first : bool
        Whether the result enters before the consumed objects exit (something that
        takes an object's place on screen without a gap); by default they exit first
        (a whole goes, then its parts come).

    Examples
    --------
    >>> def split(piece, at): ...
    >>> lives = Lifetimes(split, "split", ("piece",), True, False)
    >>> lives.consumed(("P", 3), {}), lives.consumed((), {"piece": "P", "at": 3})
    (['P'], ['P'])
    >>> lives.produced(("P1", "P2")), lives.produced("P1"), lives.produced(None)
    (['P1', 'P2'], ['P1'], [])
    """

    __slots__ = ("_defaults", "_names", "_positions", "produced_first", "produces")

    def __init__(
        self,
        func: Callable[..., Any],
        name: str,
        consumes: Iterable[str],
        produces: bool,
        produced_first: bool,
    ) -> None:
        if isinstance(consumes, str):
            raise TypeError(f"{name}(): consumes takes parameter names, e.g. ({consumes!r},)")
        params = inspect.signature(func).parameters
        self._names = tuple(consumes)
        named = (*_POSITIONAL, inspect.Parameter.KEYWORD_ONLY)  # not *args or **kwargs
        unknown = sorted(n for n in self._names if n not in params or params[n].kind not in named)
        if unknown:
            raise ValueError(f"{name}() has no named parameter(s) {unknown} to consume")
        order = list(params)
        self._positions = tuple(
            order.index(n) if params[n].kind in _POSITIONAL else None for n in self._names
        )
        self._defaults = tuple(
            None if params[n].default is inspect.Parameter.empty else params[n].default
            for n in self._names
        )
        self.produces = produces
        self.produced_first = produced_first

    def consumed(self, args: tuple[Any, ...], kwargs: dict[str, Any]) -> list[Any]:
        """The objects passed as the consumed parameters (``None`` left out)."""
        found = []
        for name, position, default in zip(
            self._names, self._positions, self._defaults, strict=True
        ):
            if name in kwargs:
                value = kwargs[name]
            elif position is not None and position < len(args):
                value = args[position]
            else:
                value = default
            if value is not None:
                found.append(value)
        return found

    def produced(self, value: Any) -> list[Any]:
        """The objects a result stands for (``None`` left out)."""
        items = value if isinstance(value, tuple | list) else (value,)
        return [item for item in items if item is not None]

    def record(self, recorder: Recorder, gone: list[Any], value: Any, line: int) -> None:
        """Append the exits of ``gone`` and the enters of what ``value`` stands for."""
        made = self.produced(value) if self.produces else []
        if self.produced_first:
            for obj in made:
                recorder.enter(obj, line)
        for obj in gone:
            recorder.exit(obj, line)
        if not self.produced_first:
            for obj in made:
                recorder.enter(obj, line)


@overload
def traced(func: F, /) -> F: ...


@overload
def traced(
    func: None = None,
    /,
    *,
    name: str | None = None,
    exclude_args: Iterable[str] = (),
    result: bool = True,
    consumes: Iterable[str] = (),
    produces: bool = False,
    produced_first: bool = False,
) -> Callable[[F], F]: ...


def traced(
    func: F | None = None,
    /,
    *,
    name: str | None = None,
    exclude_args: Iterable[str] = (),
    result: bool = True,
    consumes: Iterable[str] = (),
    produces: bool = False,
    produced_first: bool = False,
) -> Any:
    """Record every call of a function while a recording is open.

    Use bare (``@traced``) or with options (``@traced(name=..., exclude_args=..., result=...)``).
    A function defined in a class whose first parameter is ``self`` or ``cls`` is a
    method: that argument is not recorded; its ``trace_key`` (or ``None``) is the target.
    With ``consumes`` or ``produces`` the call also ends and starts lifetimes (see
    :class:`Lifetimes`): their ``exit`` and ``enter`` events follow the ``return``.

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
    consumes : iterable of str
        Parameters whose objects exit the log when the call returns.
    produces : bool
        Let the result (each item of a tuple or list) enter the log when the call returns.
    produced_first : bool
        Enter the result before the consumed objects exit, not after.

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

    A call that cuts one object into two: the whole exits, then the halves enter.

    >>> @traced(consumes=("whole",), produces=True)
    ... def halve(whole):
    ...     key = whole.trace_key
    ...     return tracing.Shape(key + "1", "point"), tracing.Shape(key + "2", "point")
    >>> whole = tracing.Shape("S", "point")
    >>> with tracing.record() as log:
    ...     tracing.enter(whole)
    ...     parts = halve(whole)
    >>> [(e.kind, e.name if e.kind in ("call", "return") else e.target) for e in log.events]
    ... # doctest: +NORMALIZE_WHITESPACE
    [('enter', 'S'), ('call', 'halve'), ('return', 'halve'), ('exit', 'S'), ('enter', 'S1'),
     ('enter', 'S2')]
    """

    def decorate(function: F) -> F:
        function_name = name or function.__name__
        is_method = _looks_like_method(function)
        lives = None
        if consumes or produces:
            lives = Lifetimes(function, function_name, consumes, produces, produced_first)
        return _wrap(function, function_name, exclude_args, result, is_method, lives)

    return decorate if func is None else decorate(func)


@overload
def lifetimes(func: F, /) -> F: ...


@overload
def lifetimes(
    func: None = None,
    /,
    *,
    consumes: Iterable[str] = (),
    produces: bool = False,
    produced_first: bool = False,
) -> Callable[[F], F]: ...


def lifetimes(
    func: F | None = None,
    /,
    *,
    consumes: Iterable[str] = (),
    produces: bool = False,
    produced_first: bool = False,
) -> Any:
    """Let a function's calls end and start object lifetimes, without recording the calls.

    For the steps of an algorithm that make, finish or replace drawn objects but
    are not steps of their own in the story. When a call returns (with a
    recording open), the objects passed as ``consumes`` exit and, with
    ``produces``, the result enters (see :class:`Lifetimes`); the events carry
    the caller's line and lie inside the caller's call.

    Parameters
    ----------
    func : callable, optional
        The function, when used bare (then it changes nothing).
    consumes : iterable of str
        Parameters whose objects exit the log when the call returns.
    produces : bool
        Let the result (each item of a tuple or list) enter the log when the call returns.
    produced_first : bool
        Enter the result before the consumed objects exit, not after.

    Returns
    -------
    callable
        The wrapper (``__wrapped__`` is the function), or a decorator.

    Examples
    --------
    >>> import tracing
    >>> @lifetimes(consumes=("seed",), produces=True, produced_first=True)
    ... def sprout(seed):
    ...     return tracing.Shape("plant", "point")
    >>> seed = tracing.Shape("seed", "point")
    >>> with tracing.record() as log:
    ...     tracing.enter(seed)
    ...     plant = sprout(seed)
    >>> [(e.kind, e.target, e.depth) for e in log.events]
    [('enter', 'seed', 0), ('enter', 'plant', 0), ('exit', 'seed', 0)]
    """

    def decorate(function: F) -> F:
        if inspect.isgeneratorfunction(function) or inspect.iscoroutinefunction(function):
            raise TypeError(f"{function.__name__}(): generators and coroutines have no result")
        lives = Lifetimes(function, function.__name__, consumes, produces, produced_first)
        current_recorder = ACTIVE_RECORDER.get
        get_frame = sys._getframe

        @functools.wraps(function)
        def lifetime_call(*args: Any, **kwargs: Any) -> Any:
            recorder = current_recorder()
            if recorder is None:
                return function(*args, **kwargs)
            line = get_frame(1).f_lineno
            gone = lives.consumed(args, kwargs)
            value = function(*args, **kwargs)
            lives.record(recorder, gone, value, line)
            return value

        lifetime_call.__trace_spec__ = lives  # type: ignore[attr-defined]  # an attribute of the wrapper function, read by story.registry and the tests
        return lifetime_call  # type: ignore[return-value]  # functools.wraps keeps the signature of F, which mypy cannot see

    return decorate if func is None else decorate(func)


@overload
def traced_class(cls: C, /) -> C: ...


@overload
def traced_class(cls: None = None, /, *, exclude: Iterable[str] = ()) -> Callable[[C], C]: ...


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


def _wrap(
    func: F,
    name: str,
    exclude_args: Iterable[str],
    keep_result: bool,
    is_method: bool,
    lives: Lifetimes | None = None,
) -> F:
    """Build the recording wrapper around ``func``; ``lives``: the lifetimes its calls change."""
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
        gone = lives.consumed(args, kwargs) if lives is not None else None
        seq = recorder.open_call(name, target, encoded, line)
        try:
            value = func(*args, **kwargs)
        except BaseException as error:
            recorder.close_call(seq, name, target, {"raised": type(error).__name__}, line)
            raise
        recorder.close_call(seq, name, target, encode(value) if keep_result else None, line)
        if lives is not None and gone is not None:  # gone is None exactly when lives is
            lives.record(recorder, gone, value, line)
        return value

    traced_call.__trace_spec__ = spec  # type: ignore[attr-defined]  # an attribute of the wrapper function, read by story.registry and the tests
    return traced_call  # type: ignore[return-value]  # functools.wraps keeps the signature of F, which mypy cannot see
