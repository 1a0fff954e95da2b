"""Scene graphs as values: build the graph of a SCENE as ``trex snapshot`` does, compare two,
and fail with the differences in words.

:func:`graph_of` builds a scene (a class, or a SCENE as ``trex render`` takes it: a name from
``scenes/``, ``FILE.py[:Class]``, a heuristic of one's own ``FILE.py:function``) in a dry run
and returns a :class:`SceneGraph`. A graph equals another graph, its dict, its JSON text, or
(under pytest with syrupy) a ``snapshot``: then it is stored as one JSON file, the text
``trex snapshot`` writes, through :data:`SceneGraphExtension`. :func:`assert_same_graph`
fails with :func:`trex.graph_diff.report`'s lines.

Importing this module imports neither manim nor syrupy (the pytest plugin imports it in every
session); building a graph imports manim, comparing with a snapshot uses syrupy.

>>> a = SceneGraph({"schema": SCHEMA, "plays": [], "final": []})
>>> a == SceneGraph.from_text(a.text)
True
>>> b = SceneGraph({"schema": SCHEMA, "plays": [], "final": [{"type": "Dot", "name": "x"}]})
>>> assert_same_graph(b, a)
Traceback (most recent call last):
...
AssertionError: the scene graph differs (1 difference):
  final: 1 mobject added (x)
"""

from __future__ import annotations

import json
import os
import tempfile
import warnings
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from story.scene_kinds import Handed, algorithm_of, plays_several
from trex.graph_diff import report
from trex.graph_format import SCHEMA, read_graph, to_json

if TYPE_CHECKING:
    from geometry.io import AnyPolygon


class SnapshotError(ValueError):
    """Bad input for a scene graph (the scene, its polygon or logs, a stored graph): one line."""


# --- the graph as a value -----------------------------------------------------------------------


class SceneGraph:
    """A scene graph (docs/scene-graph.md): ``data`` (plain JSON data) and ``text`` (the
    stable JSON :func:`trex.graph_format.to_json` writes; a file adds a final newline).

    ``graph == other`` compares data with another SceneGraph, a dict, JSON text, or a syrupy
    ``snapshot`` (stored with :data:`SceneGraphExtension`, whatever the session's default).
    """

    __slots__ = ("data",)
    __hash__ = None  # type: ignore[assignment]  # compared by value, and mutable

    def __init__(self, data: dict[str, Any]) -> None:
        self.data = data

    @classmethod
    def from_text(cls, text: str) -> SceneGraph:
        """The graph in JSON text. Raises ValueError (one line)."""
        return cls(read_graph(text))

    @classmethod
    def read(cls, path: str | os.PathLike) -> SceneGraph:
        """The graph stored at ``path``. Raises :class:`SnapshotError` (one line)."""
        try:
            text = Path(path).read_text(encoding="utf-8")
        except FileNotFoundError:
            raise SnapshotError("no such file") from None
        except (OSError, UnicodeDecodeError) as exc:
            raise SnapshotError(f"cannot read: {getattr(exc, 'strerror', None) or exc}") from None
        try:
            return cls.from_text(text)
        except ValueError as exc:
            raise SnapshotError(str(exc)) from None

    @property
    def text(self) -> str:
        return to_json(self.data)

    def file_text(self) -> str:
        """The text of a stored graph: :attr:`text` and a newline."""
        return self.text + "\n"

    def write(self, path: str | os.PathLike) -> Path:
        """Store the graph at ``path`` (written beside it and renamed into place)."""
        target = Path(path)
        handle, temp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp",
                                        dir=target.parent)
        try:
            with os.fdopen(handle, "w", encoding="utf-8") as out:
                out.write(self.file_text())
            os.chmod(temp, 0o644)
            os.replace(temp, target)
        except BaseException:
            Path(temp).unlink(missing_ok=True)
            raise
        return target

    def differences(self, expected: Any) -> list[str]:
        """What changed from ``expected`` (a graph as :func:`as_graph` takes it) to this one,
        in words (at most :data:`trex.graph_diff.LIMIT` lines, then a count)."""
        return report(as_graph(expected).data, self.data)

    def __eq__(self, other: object) -> bool:
        if is_snapshot(other):
            return _assert_snapshot(self, other)
        data = data_of(other)
        return NotImplemented if data is None else self.data == data

    def __repr__(self) -> str:
        plays, final = self.data.get("plays") or [], self.data.get("final") or []
        return f"<SceneGraph: {len(plays)} plays, {len(final)} mobjects at the end>"

    def __str__(self) -> str:
        return self.text


def data_of(other: object) -> Any:
    """The plain data of a graph, its dict or its JSON text (None for anything else)."""
    if isinstance(other, SceneGraph):
        return other.data
    if isinstance(other, dict):
        return other
    if isinstance(other, str):
        try:
            return json.loads(other)
        except ValueError:
            return None
    return None


def as_graph(value: Any) -> SceneGraph:
    """A graph from a SceneGraph, its dict, its JSON text (starting with ``{``), or the path
    of a stored one. Raises :class:`SnapshotError` (one line)."""
    if isinstance(value, SceneGraph):
        return value
    if isinstance(value, dict):
        return SceneGraph(value)
    if isinstance(value, str) and value.lstrip().startswith("{"):
        try:
            return SceneGraph.from_text(value)
        except ValueError as exc:
            raise SnapshotError(str(exc)) from None
    if isinstance(value, str | os.PathLike):
        try:
            return SceneGraph.read(value)
        except SnapshotError as exc:
            raise SnapshotError(f"{os.fspath(value)}: {exc}") from None
    raise SnapshotError(f"not a scene graph: {type(value).__name__}")


def assert_same_graph(actual: Any, expected: Any) -> None:
    """Fail (AssertionError) unless the two graphs are equal, with their differences in words
    (``expected``, the stored one, first: ``play 12 (Create claim): run_time 1.0 → 1.5``).

    Each is a :class:`SceneGraph`, its dict, its JSON text, or the path of a stored graph.
    """
    __tracebackhide__ = True
    try:
        expected_graph = as_graph(expected)
    except SnapshotError as exc:
        raise AssertionError(f"no stored scene graph to compare with: {exc}") from None
    actual_graph = as_graph(actual)
    if actual_graph.data == expected_graph.data:
        return
    lines = report(expected_graph.data, actual_graph.data)
    raise AssertionError(explanation(lines, expected))


def explanation(lines: list[str], expected: Any = None) -> str:
    """The message of a failed comparison: a heading, then the differences indented."""
    where = f" from {os.fspath(expected)}" if isinstance(expected, os.PathLike) or (
        isinstance(expected, str) and not expected.lstrip().startswith("{")) else ""
    return f"the scene graph differs{where} ({count(lines)}):\n  " + "\n  ".join(lines)


def count(lines: list[str]) -> str:
    """``3 differences``: how many lines :func:`trex.graph_diff.report` gave (and counted)."""
    total = len(lines)
    if lines and lines[-1].startswith("… and "):
        total = len(lines) - 1 + int(lines[-1].split()[2])
    return f"{total} difference{'s' if total != 1 else ''}"


# --- building --------------------------------------------------------------------------------------


def load_scene(scene: str) -> type:
    """The Scene class SCENE names, as ``trex render`` takes it (imports manim and the file).
    Raises ValueError (one line)."""
    from trex.render_command import load_scene_class, resolve_scene

    if ".py:" in scene:
        from metaphors.scene import scene_for_heuristic

        return scene_for_heuristic(scene)
    return load_scene_class(*resolve_scene(scene))


def takes_input(cls: type) -> bool:
    """Whether the scene is handed its run (this project's scenes), or is a plain Scene."""
    return isinstance(cls, Handed)


def plays_own_polygons(cls: type) -> bool:
    """A scene of several runs: each names its polygon, a handed one is not played."""
    return plays_several(cls)


def hand(cls: type, polygon: str | None = None, logs: Sequence[str] = (),
         polygon_read: AnyPolygon | None = None) -> type:
    """The scene class handed its input: its default run, on ``polygon``, or replaying saved
    ``logs`` (one per run). No environment variable counts: a graph is its arguments' alone.
    A scene of one run is handed the polygon read once and checked by its run's rule
    (:meth:`story.spec.RunSpec.read`; ``polygon_read``: ``polygon`` read already). Raises
    :class:`SnapshotError` (one line) for input the scene cannot take."""
    logs = tuple(os.fspath(p) for p in logs)
    if not isinstance(cls, Handed):  # takes_input(cls), said so that the checker narrows cls
        if polygon is not None or logs:
            given = "--polygon" if polygon is not None else "--log"
            raise SnapshotError(f"{cls.__name__} is a plain manim Scene: it takes no {given}")
        return cls
    if polygon is not None and logs:
        raise SnapshotError("a polygon and saved logs: give one of them (a saved log has its "
                            "own polygon)")
    for path in logs:
        _check_log(cls, path, len(logs))
    if polygon is not None:
        one_run = not plays_own_polygons(cls)  # cls is Handed: it has with_spec
        spec = _read(polygon, polygon_read, cls.default_spec() if one_run else None)
        if spec is not None:
            return cls.with_spec(spec)
    try:
        return cls.handed(polygon, logs)
    except ValueError as exc:
        raise SnapshotError(str(exc)) from None


def _read(polygon: str, polygon_read: AnyPolygon | None, default=None):
    """``polygon`` read (``polygon_read``: read already) and, for a scene of one run, its
    ``default`` run on it, checked by that run's rule (None for a scene of several runs,
    which plays its own polygons: the polygon is only read). A polygon that cannot be read,
    is invalid, or is one the run cannot take raises :class:`SnapshotError` (one line)."""
    from geometry.io import read_any_polygon
    from trex.inputs import READ_ERRORS, error_line

    try:
        polygon_read = read_any_polygon(polygon) if polygon_read is None else polygon_read
        return default.on(polygon).read(polygon_read) if default is not None else None
    except READ_ERRORS as exc:
        raise SnapshotError(f"{polygon}: {error_line(exc)}") from None


def _check_log(cls: type, path: str, runs: int) -> None:
    from trex.scene_inputs import check_log, read_log

    try:
        log = read_log(path)
        if runs == 1 and not plays_own_polygons(cls) and algorithm_of(cls) is not None:
            check_log(cls, log)
    except ValueError as exc:
        raise SnapshotError(f"{path}: {exc}") from None


def graph_of(scene: str | type, polygon: str | None = None,
             log: str | os.PathLike | Iterable[str | os.PathLike] | None = None,
             *, search: Sequence[Path] = ()) -> SceneGraph:
    """The scene graph of ``scene`` (a Scene class, or a SCENE string) on its default run, on
    ``polygon``, or replaying ``log`` (a saved log, or one per run), built in a dry run.

    Relative paths (the scene's file, the polygon's, the logs') are looked up in the
    ``search`` folders in turn, then taken as they are (from the working directory).
    Bad input raises :class:`SnapshotError` (one line); an error of the scene itself while it
    builds propagates as it is.
    """
    logs = () if log is None else (log,) if isinstance(log, str | os.PathLike) else tuple(log)
    if isinstance(scene, str):
        try:
            cls = load_scene(_found_scene(scene, search))
        except ValueError as exc:
            raise SnapshotError(f"{scene}: {exc}") from None
    elif isinstance(scene, type):
        cls = scene
    else:
        raise SnapshotError(f"not a scene: {scene!r} (give a Scene class or 'FILE.py:Class')")
    if polygon is not None and plays_own_polygons(cls):
        warnings.warn(f"{cls.__name__} plays its own polygons; the polygon {polygon} is ignored",
                      stacklevel=2)
    handed = hand(cls, None if polygon is None else _found(str(polygon), search),
                  [_found(os.fspath(p), search) for p in logs])
    return build(handed)


def build(handed: type) -> SceneGraph:
    """The graph of a scene class as it is (already handed its input), built in a dry run."""
    from trex.scene_graph import build as build_scene
    from trex.scene_graph import scene_graph

    scene, plays = build_scene(handed)
    return SceneGraph(scene_graph(plays, scene))


def _found(path: str, search: Sequence[Path]) -> str:
    """``path`` in the first search folder that has it (else as it is)."""
    if os.path.isabs(path):
        return path
    for folder in search:
        candidate = Path(folder) / path
        if candidate.exists():
            return str(candidate)
    return path


def _found_scene(scene: str, search: Sequence[Path]) -> str:
    """A SCENE string with its file looked up in the search folders."""
    if ".py:" in scene:
        file_part, _, name = scene.rpartition(":")
        return f"{_found(file_part, search)}:{name}"
    target, colon, name = scene.partition(":")
    if target.endswith(".py") or "/" in target or os.sep in target:
        return f"{_found(target, search)}{colon}{name}"
    return scene


# --- syrupy -------------------------------------------------------------------------------------


def is_snapshot(other: object) -> bool:
    """A syrupy ``SnapshotAssertion`` (known without importing syrupy)."""
    kind = type(other)
    return kind.__name__ == "SnapshotAssertion" and kind.__module__.startswith("syrupy")


def _assert_snapshot(graph: SceneGraph, snapshot: Any) -> bool:
    """``graph == snapshot``: asserted with :data:`SceneGraphExtension`, in the snapshot's own
    series (a test's second assertion is its second snapshot)."""
    extension = _extension()
    if isinstance(snapshot.extension, extension):
        return bool(snapshot == graph)  # the session's default, or chosen by the test
    snapshot.use_extension(extension)  # registered: syrupy finds this extension's files
    return bool(snapshot(extension_class=extension) == graph)


_EXTENSION: type | None = None


def _extension() -> type:
    """The syrupy extension storing a scene graph as one JSON file (built on first use)."""
    global _EXTENSION
    if _EXTENSION is not None:
        return _EXTENSION
    from syrupy.extensions.single_file import SingleFileSnapshotExtension, WriteMode

    class SceneGraphExtension(SingleFileSnapshotExtension):
        """One ``.json`` file per snapshot, the text ``trex snapshot`` writes; graphs compared
        as data, their differences reported in words."""

        file_extension = "json"
        _write_mode = WriteMode.TEXT

        def serialize(self, data, *, exclude=None, include=None, matcher=None):
            if isinstance(data, str):
                return data if data.endswith("\n") else data + "\n"
            return as_graph(data).file_text()

        def matches(self, *, serialized_data, snapshot_data) -> bool:
            a, b = data_of(str(serialized_data)), data_of(str(snapshot_data))
            if a is None or b is None:
                return serialized_data == snapshot_data
            return a == b

        def diff_lines(self, serialized_data, snapshot_data):
            new, old = data_of(str(serialized_data)), data_of(str(snapshot_data))
            if not (isinstance(new, dict) and isinstance(old, dict)):
                yield from super().diff_lines(serialized_data, snapshot_data)
                return
            yield from report(old, new)

    SceneGraphExtension.__module__ = __name__
    SceneGraphExtension.__qualname__ = "SceneGraphExtension"
    _EXTENSION = SceneGraphExtension
    return _EXTENSION


def __getattr__(name: str) -> Any:
    # ``trex.snapshot.SceneGraphExtension`` (for ``--snapshot-default-extension`` and
    # ``snapshot.use_extension``) exists once asked for: defining it imports syrupy.
    if name == "SceneGraphExtension":
        return _extension()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["SCHEMA", "SceneGraph", "SnapshotError", "as_graph",
           "assert_same_graph", "build", "graph_of", "hand", "load_scene"]
