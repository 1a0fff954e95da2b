"""The pytest plugin of Triangulation Explained: scene graphs in any project's tests.

Installed with the package (entry point ``pytest11``, named ``trex.pytest_plugin``), so it
is on in every pytest session of an environment that has ``triangulation-explained``
(``-p no:trex.pytest_plugin`` turns it off). It gives:

- the fixture ``scene_graph``: ``scene_graph(scene, polygon=None, log=None)`` builds a scene
  in a dry run and returns its :class:`trex.snapshot.SceneGraph`. ``scene`` is a Scene class
  or a SCENE string (``"my_scene.py:Mine"``, ``"scenes/gravity.py:Gravity"``, a name from
  ``scenes/``); relative paths are looked up beside the test file, then in the rootdir, then
  in the working directory. ``log`` is a saved log, or a list of them (one per run);
- comparison with syrupy's ``snapshot``: ``assert scene_graph("my_scene.py:Mine") ==
  snapshot`` stores ``__snapshots__/<test file>/<test>.json``, the text ``trex snapshot``
  writes (``trex.snapshot.SceneGraphExtension``), and a failure lists the differences in
  words, play by play;
- :func:`assert_same_graph` (``trex.snapshot``'s) for a stored file of one's own:
  ``assert_same_graph(scene_graph(Mine), "tests/mine.json")``.

Importing the plugin imports neither manim nor syrupy: a session that builds no graph pays
nothing.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

import pytest

from trex.graph_diff import report
from trex.snapshot import (
    SceneGraph,
    as_graph,
    assert_same_graph,
    count,
    data_of,
    graph_of,
    is_snapshot,
)

__all__ = ["SceneGraph", "assert_same_graph", "scene_graph"]


@pytest.fixture
def scene_graph(request: pytest.FixtureRequest) -> Callable[..., SceneGraph]:
    """``scene_graph(scene, polygon=None, log=None) -> SceneGraph``: the scene graph of a
    scene (a Scene class or ``"FILE.py:Class"``), built in a dry run (no video)."""
    search = [Path(request.path).parent, Path(request.config.rootpath)]

    def build(scene: str | type, polygon: str | None = None,
              log: str | os.PathLike | Iterable[str | os.PathLike] | None = None) -> SceneGraph:
        return graph_of(scene, polygon, log, search=search)

    return build


def _explain(left: Any, right: Any) -> list[str] | None:
    """The differences in words of a failed ``graph == other`` (or ``other == graph``)."""
    graph, other = (left, right) if isinstance(left, SceneGraph) else (right, left)
    if not isinstance(graph, SceneGraph):
        return None
    if is_snapshot(other):
        results = other.executions
        last = results.get(other.num_executions - 1)
        if last is None or last.exception is not None or last.recalled_data is None:
            return None  # no snapshot yet, or syrupy's own error: syrupy says it
        data = data_of(str(last.recalled_data))
        if not isinstance(data, dict):
            return None  # not JSON: syrupy's diff of the texts says more
        stored = SceneGraph(data)  # of another schema too: its "schema" line says so
        heading = f"the scene graph differs from the snapshot {last.snapshot_name}"
    else:
        try:
            stored = as_graph(other)
        except ValueError:
            return None
        heading = "the scene graphs differ"
    if graph is right:  # `expected == graph`: the stored one is on the left
        graph, stored = stored, graph
    lines = report(stored.data, graph.data)
    if not lines:
        return None
    return [f"{heading} ({count(lines)}):", *(f"  {line}" for line in lines)]


@pytest.hookimpl(wrapper=True)
def pytest_assertrepr_compare(config: pytest.Config, op: str, left: Any,
                              right: Any) -> Any:
    # A wrapper, so that the words come before syrupy's own diff whatever the plugins' order
    # (pytest shows the first explanation it gets).
    explanations = yield
    if op != "==":
        return explanations
    ours = _explain(left, right)
    return [ours, *(explanations or [])] if ours else explanations
