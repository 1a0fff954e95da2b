"""Every dataclass field of the project's packages says what it holds (issue 23).

The walk imports each module of the packages, takes every dataclass defined there and reads
its fields' resolved types (``dataclasses.fields`` + ``typing.get_type_hints``). A field fails
when its type

- is or holds ``Any`` (the type is known: name it; JSON data is :data:`tracing.JSON`);
- is a bare container (``list``, ``dict``, ``tuple``, ``Mapping`` … without parameters);
- is or holds a ``list``, ``dict`` or ``set``: a record holds tuples (of records, of
  NamedTuples, of points) and read-only ``Mapping``s, so it stays what it was made as, and
  ``list[list[float]]`` or ``list[dict]`` cannot stand in for a record.

A callable field's signature counts only for ``Any``: the field holds the function. ``ALLOWED``
names the fields that truly are free-form or mutable, each with its reason.
"""

from __future__ import annotations

import collections.abc as cabc
import dataclasses
import importlib
import pkgutil
import typing
from types import ModuleType

import pytest

PACKAGES = ("tracing", "geometry", "usercode", "story", "rendering", "metaphors", "trex")

#: field → why it may hold what the rules refuse
ALLOWED: dict[str, str] = {
    "trex.scene_graph.Play.animations": "manim's animations as Scene.play took them (live)",
    "tracing.events.Log.events": "appended to while a run is recorded",
    "tracing.events.Log.meta": "written while a run is recorded (story.runs adds what it showed)",
}

_BARE = (list, dict, set, frozenset, tuple, cabc.Mapping, cabc.MutableMapping, cabc.Sequence,
         cabc.MutableSequence, cabc.Iterable, cabc.Collection, cabc.Set)
_MUTABLE = {list: "list", dict: "dict", set: "set"}


def faults(t: object, inside_callable: bool = False) -> list[str]:
    """What is wrong with a field of type ``t`` (nothing: an empty list). In a callable's
    signature only ``Any`` counts: the field holds the function, not its values."""
    if t is typing.Any:
        return ["Any"]
    if inside_callable:
        found = []
    elif t in _BARE:
        found = [f"bare {getattr(t, '__name__', t)}"]
    elif (origin := typing.get_origin(t)) in _MUTABLE:
        found = [f"a {_MUTABLE[origin]}"]
    else:
        found = []
    callable_ = inside_callable or typing.get_origin(t) is cabc.Callable
    for a in typing.get_args(t):
        for part in a if isinstance(a, list) else [a]:  # a Callable's parameter list
            if part is not Ellipsis:
                found += faults(part, callable_)
    return found


def _modules() -> list[ModuleType]:
    found = []
    for name in PACKAGES:
        package = importlib.import_module(name)
        found.append(package)
        for info in pkgutil.walk_packages(package.__path__, f"{name}."):
            if info.name.rsplit(".", 1)[-1] == "__main__":
                continue  # runs the command line when imported
            found.append(importlib.import_module(info.name))
    return found


def _dataclasses() -> list[tuple[type, dict[str, object]]]:
    modules = _modules()
    names: dict[str, object] = {}
    for module in modules:  # what TYPE_CHECKING blocks import, for the string annotations
        for key, value in vars(module).items():
            names.setdefault(key, value)
    found = []
    for module in modules:
        for value in vars(module).values():
            if (isinstance(value, type) and dataclasses.is_dataclass(value)
                    and value.__module__ == module.__name__):
                found.append((value, typing.get_type_hints(value, localns=names)))
    return found


#: every field where its class declares it (an inherited field is its base's)
FIELDS = [(cls, f.name, hints[f.name]) for cls, hints in _dataclasses()
          for f in dataclasses.fields(cls) if f.name in vars(cls).get("__annotations__", {})]


def _name(cls: type, field: str) -> str:
    return f"{cls.__module__}.{cls.__qualname__}.{field}"


def test_the_walk_finds_the_fields() -> None:
    names = {_name(cls, field) for cls, field, _ in FIELDS}
    assert {"story.beats.Beat.roles", "tracing.events.Event.args",
            "geometry.results.Triangulation.triangles"} <= names
    assert len(FIELDS) > 300, len(FIELDS)


def test_every_field_says_what_it_holds() -> None:
    bad = [f"{_name(cls, field)}: {str(hint)[:120]} ({'; '.join(faults(hint))})"
           for cls, field, hint in FIELDS
           if _name(cls, field) not in ALLOWED and faults(hint)]
    assert not bad, "\n".join(["fields that do not say what they hold:", *bad])


def test_the_allow_list_names_only_fields_that_need_it() -> None:
    fields = {_name(cls, field): faults(hint) for cls, field, hint in FIELDS}
    stale = [name for name in ALLOWED if not fields.get(name)]
    assert not stale, f"allowed but gone or fine: {stale}"


@pytest.mark.parametrize(("hint", "expected"), [
    (typing.Any, ["Any"]),
    (list, ["bare list"]),
    (tuple, ["bare tuple"]),
    (dict[str, typing.Any] | None, ["a dict", "Any"]),
    (list[list[float]], ["a list", "a list"]),
    (tuple[dict[str, int], ...], ["a dict"]),
    (cabc.Mapping[str, list[int]], ["a list"]),
    (list[str], ["a list"]),
    (cabc.Callable[..., typing.Any], ["Any"]),
    (cabc.Callable[[int], list[int]], []),
    (tuple[tuple[float, float], ...], []),
    (cabc.Mapping[str, str], []),
    (tuple[int, int] | None, []),
])
def test_the_rules(hint: object, expected: list[str]) -> None:
    assert faults(hint) == expected
