"""The scene graph as a document (``trex-scene-graph/1``, docs/scene-graph.md): its schema,
its stable JSON text, and reading it back. Plain data: no manim.

>>> graph = {"schema": SCHEMA, "plays": [], "final": []}
>>> print(to_json(graph))
{
 "final": [],
 "plays": [],
 "schema": "trex-scene-graph/1"
}
>>> read_graph(to_json(graph)) == graph
True
>>> read_graph('{"plays": []}')
Traceback (most recent call last):
...
ValueError: not a trex scene graph (no "schema"; this trex reads trex-scene-graph/1)
"""

from __future__ import annotations

import json
import re
from collections.abc import Mapping
from typing import Any

#: The version of the document. A change that an old reader would misread (a renamed or
#: reinterpreted field) gets a new number; docs/scene-graph.md lists what changed.
SCHEMA = "trex-scene-graph/1"

_NUMBER = r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?"
_FLAT_LIST = re.compile(r"\[\s*(" + _NUMBER + r"(?:,\s*" + _NUMBER + r")*)\s*\]")


def to_json(graph: Mapping[str, Any]) -> str:
    """Stable JSON text: sorted keys, one-space indent, each list of numbers on one line.

    A file holds this text and a final newline (``trex snapshot -o``, the pytest plugin).

    >>> print(to_json({"b": [1.0, 2.5], "a": None}))
    {
     "a": null,
     "b": [1.0, 2.5]
    }
    """
    text = json.dumps(graph, sort_keys=True, indent=1, ensure_ascii=False, allow_nan=False)
    return _FLAT_LIST.sub(lambda m: "[" + re.sub(r",\s+", ", ", m.group(1)) + "]", text)


def read_graph(text: str) -> dict[str, Any]:
    """The graph in ``text``. Raises ValueError (one line) for text that is not JSON, not a
    scene graph, or a scene graph of another schema."""
    try:
        data = json.loads(text)
    except (ValueError, RecursionError) as exc:
        raise ValueError(f"not JSON: {exc}") from None
    if not isinstance(data, dict) or not isinstance(data.get("plays"), list):
        raise ValueError(f"not a trex scene graph (no list of \"plays\"; this trex reads "
                         f"{SCHEMA})")
    schema = data.get("schema")
    if schema is None:
        raise ValueError(f"not a trex scene graph (no \"schema\"; this trex reads {SCHEMA})")
    if schema != SCHEMA:
        raise ValueError(f"a scene graph of schema {schema!r}; this trex reads {SCHEMA}")
    return data
