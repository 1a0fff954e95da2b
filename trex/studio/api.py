"""The studio's JSON API: check, diagonal and triangulate, as the command line computes them.

Every answer is built by the command line's own code (:mod:`trex.run_commands`,
:func:`trex.cli.summary`'s polygon types), so the page and ``trex … --json`` agree.
Bad input is a :class:`BadRequest`, answered 4xx with ``{"error": "one line"}``.
"""

from __future__ import annotations

import json
import math
from typing import Any

from geometry.errors import GeometryError
from geometry.io import Shape, shape_from_rings
from geometry.user_heuristics import UserHeuristic
from story.registry import heuristics, triangulations
from trex.inputs import error_line
from trex.run_commands import diagonal_record, triangulation_record

MAX_VERTICES = 5000
"""Live calls refuse bigger polygons: each answer must come back while one draws."""


class BadRequest(Exception):
    """A request the studio refuses, with the one line that says why and its status."""

    def __init__(self, message: str, status: int = 400) -> None:
        super().__init__(message)
        self.status = status


def parse_body(raw: bytes) -> dict:
    """The request's JSON object; NaN and Infinity are refused as malformed numbers."""

    def no_constant(name: str) -> Any:
        raise BadRequest(f"{name} is not a number")

    try:
        body = json.loads(raw, parse_constant=no_constant)
    except (ValueError, RecursionError) as exc:
        raise BadRequest(f"malformed JSON: {error_line(exc)}") from None
    if not isinstance(body, dict):
        raise BadRequest("the body must be a JSON object")
    return body


def _ring(value: object, what: str) -> list[list[float]]:
    if not isinstance(value, list):
        raise BadRequest(f"{what} must be a list of [x, y] points")
    for k, point in enumerate(value):
        if (not isinstance(point, list) or len(point) != 2
                or not all(isinstance(c, int | float) and not isinstance(c, bool)
                           and math.isfinite(c) for c in point)):
            raise BadRequest(f"{what}: point {k} is not two finite numbers")
    return value


def rings_of(body: dict, *, holes: bool = True) -> list[list[list[float]]]:
    """The outer ring and the holes of a request, checked for shape and size."""
    if "polygon" not in body:
        raise BadRequest("missing field: polygon")
    rings = [_ring(body["polygon"], "polygon")]
    raw_holes = body.get("holes") or []
    if not isinstance(raw_holes, list):
        raise BadRequest("holes must be a list of rings")
    if raw_holes and not holes:
        raise BadRequest("holes are not supported here")
    rings += [_ring(h, f"hole {k + 1}") for k, h in enumerate(raw_holes)]
    total = sum(len(r) for r in rings)
    if total > MAX_VERTICES:
        raise BadRequest(f"{total} vertices: live calls take at most {MAX_VERTICES}", 413)
    return rings


def _shape(rings: list) -> Shape:
    try:
        return shape_from_rings(rings)
    except GeometryError as exc:
        raise BadRequest(f"invalid polygon: {error_line(exc)}", 422) from None


def check(body: dict) -> dict:
    """Whether the polygon is valid (or why not), its labels and reflex vertices, input order."""
    rings = rings_of(body)
    try:
        shape = shape_from_rings(rings)
    except GeometryError as exc:
        return {"valid": False, "why": error_line(exc), "labels": [], "reflex": []}
    labels: list[str | None] = [None] * sum(len(r) for r in rings)
    for i, label in enumerate(shape.labels):
        labels[shape.source[i]] = label
    return {"valid": True, "why": None, "labels": labels,
            "reflex": sorted(shape.source[i] for i in shape.reflex_vertices())}


def _heuristic(name: object, own: dict[str, UserHeuristic]) -> str | UserHeuristic:
    """A built-in's name or one named on the command line; never code sent by the page."""
    if isinstance(name, str) and name in heuristics():
        return name
    if isinstance(name, str) and name in own:
        return own[name]
    known = ", ".join([*heuristics(), *own])
    raise BadRequest(f"unknown heuristic {name!r} (known: {known})")


def diagonal(body: dict, own: dict[str, UserHeuristic]) -> dict:
    """A heuristic's claim on the polygon and the exact verdict, as ``trex diagonal --json``."""
    heuristic = _heuristic(body.get("heuristic"), own)
    shape = _shape(rings_of(body, holes=False))
    try:
        record = diagonal_record("studio", shape, heuristic)
    except (ValueError, GeometryError) as exc:
        raise BadRequest(f"{body.get('heuristic')}: {error_line(exc)}", 422) from None
    return {"diagonal": record["diagonal"], "inner": record["inner"], "why": record["why"],
            "labels": record["labels"]}


def triangulate(body: dict, own: dict[str, UserHeuristic]) -> dict:
    """An algorithm's triangles and their verdict: the fields of ``trex triangulate --json``."""
    algorithm = body.get("algorithm", "divide-and-conquer")
    if algorithm not in triangulations():
        raise BadRequest(f"unknown algorithm {algorithm!r} (known: {', '.join(triangulations())})")
    heuristic = _heuristic(body.get("heuristic", "gravity"), own)
    shape = _shape(rings_of(body))
    try:
        record = triangulation_record("studio", shape, algorithm, heuristic)
    except (ValueError, GeometryError) as exc:
        raise BadRequest(f"{algorithm}: {error_line(exc)}", 422) from None
    record.pop("labels", None)
    return record
