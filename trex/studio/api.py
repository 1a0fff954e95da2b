"""The studio's live JSON answers: check, diagonal, claims, triangulate, load.

Every answer is built by the command line's own code (the polygon types of
:mod:`geometry`, :func:`trex.run_commands.triangulation_record`, the exact checks of
:mod:`geometry.check`), so the page and ``trex … --json`` agree; every index is into the
request's own points (the rings concatenated, outer first), even where cleaning drops a
repeated or closing point. Bad input is a :class:`BadRequest`, answered 4xx with
``{"error": "one line"}``. One's own heuristics are passed in by the worker that runs them
(:mod:`trex.studio.own`); the server calls these functions with the built-ins only.
"""

from __future__ import annotations

import itertools
import json
import math
import secrets
import time
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any, cast

from geometry.check import is_inner_diagonal
from geometry.errors import GeometryError
from geometry.frame import candidates_in_triangle, leftmost_vertex, triangle_at
from geometry.hole_samples import HOLE_SAMPLES
from geometry.holes import PolygonWithHoles
from geometry.io import AnyPolygon, any_polygon_from_rings, polygon_to_json_points, read_rings
from geometry.polygon import Polygon
from geometry.predicates import Point
from geometry.samples import is_sample, parse_spec, sample_from_spec, sample_names
from geometry.validate import kept_indices
from story.registry import heuristics, triangulations
from trex.inputs import error_line
from trex.run_commands import triangulation_record
from trex.studio.edges import offending_edges
from usercode.heuristic import UserHeuristic, run_heuristic

READ_SUFFIXES = (".json", ".geojson", ".wkt", ".dat")
"""The formats the command line reads (:func:`geometry.io.read_rings`)."""

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


def _finite(c: object) -> bool:
    """A JSON number that is a finite float (an integer too big for one is not)."""
    if isinstance(c, bool) or not isinstance(c, int | float):
        return False
    try:
        return math.isfinite(float(c))
    except OverflowError:
        return False


def _ring(value: object, what: str) -> list[list[float]]:
    if not isinstance(value, list):
        raise BadRequest(f"{what} must be a list of [x, y] points")
    if len(value) > MAX_VERTICES:  # before looking at each point
        raise BadRequest(f"{len(value)} vertices: live calls take at most {MAX_VERTICES}", 413)
    for k, point in enumerate(value):
        if not isinstance(point, list) or len(point) != 2 or not all(map(_finite, point)):
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


def checked_polygon(rings: list) -> AnyPolygon:
    """The valid polygon of the rings, or a 422 saying why not."""
    return _polygon_of(rings)


def _polygon_of(rings: list) -> AnyPolygon:
    try:
        return any_polygon_from_rings(rings)
    except GeometryError as exc:
        raise BadRequest(f"invalid polygon: {error_line(exc)}", 422) from None


def _raw_index(rings: list) -> list[int]:
    """For each cleaned vertex (the rings concatenated, as ``polygon.source`` counts them),
    its index in the request's own rings: cleaning drops repeated and closing points."""
    out, offset = [], 0
    for ring in rings:
        out += [offset + i for i in kept_indices(cast("list[Point]", [tuple(map(float, p)) for p in ring]))]  # pairs
        offset += len(ring)
    return out


def _frame(polygon: AnyPolygon, raw: list[int]) -> tuple[list[int] | None, list[int]]:
    """T = ABC at the left-most vertex B and the candidates in it, input indices; none with
    holes (the heuristics take simple polygons)."""
    if polygon.hole_count:
        return None, []
    simple = cast(Polygon, polygon)  # no holes
    t = triangle_at(simple, leftmost_vertex(simple))
    to_raw = [raw[polygon.source[v.index]] for v in (t.a, t.b, t.c)]
    return to_raw, [raw[polygon.source[v.index]] for v in candidates_in_triangle(simple, t)]


def check(body: dict) -> dict:
    """Whether the polygon is valid, or why not and which edges are at fault; its labels,
    reflex vertices, T and candidates; every index into the request's own order."""
    rings = rings_of(body)
    total = sum(len(r) for r in rings)
    try:
        polygon = any_polygon_from_rings(rings)
    except GeometryError as exc:
        return {"valid": False, "why": error_line(exc), "labels": [], "reflex": [],
                "edges": offending_edges(rings), "triangle": None, "candidates": []}
    raw = _raw_index(rings)
    labels: list[str | None] = [None] * total
    for i, label in enumerate(polygon.labels):
        labels[raw[polygon.source[i]]] = label
    triangle, candidates = _frame(polygon, raw)
    return {"valid": True, "why": None, "labels": labels,
            "reflex": sorted(raw[polygon.source[i]] for i in polygon.reflex_vertices()),
            "edges": [], "triangle": triangle, "candidates": candidates}


def rings_of_polygon(polygon: AnyPolygon) -> dict:
    """A valid polygon as a request's ``polygon`` and ``holes``, in its (cleaned) input order."""
    points = polygon_to_json_points(polygon.input_points())
    starts = polygon.starts if isinstance(polygon, PolygonWithHoles) else (0, polygon.n)
    sizes = [b - a for a, b in itertools.pairwise(starts)]
    rings, at = [], 0
    for size in sizes:
        rings.append(points[at:at + size])
        at += size
    return {"polygon": rings[0], "holes": rings[1:]}


def check_heuristic(name: object, own: Iterable[str]) -> None:
    """Refuse a name that is neither a built-in nor one named on the command line."""
    own = list(own)
    if not isinstance(name, str) or (name not in heuristics() and name not in own):
        raise BadRequest(f"unknown heuristic {name!r} (known: {', '.join([*heuristics(), *own])})")


def _heuristic(name: object, own: dict[str, UserHeuristic]) -> str | UserHeuristic:
    """A built-in's name or one named on the command line; never code sent by the page."""
    check_heuristic(name, own)
    known = cast(str, name)  # check_heuristic let only a name through
    return own.get(known, known)


def _claim(polygon: AnyPolygon, raw: list[int], heuristic: str | UserHeuristic, name: str) -> dict:
    """The claim and its exact verdict as ``trex diagonal --json`` gives them, plus what the
    page draws: the edge the claim crosses (``crossed``) or the vertex it passes through
    (``through``), request indices."""
    try:
        simple = cast(Polygon, polygon)  # rings_of(body, holes=False): the outer ring only
        claim = run_heuristic(simple, heuristic)
        verdict = is_inner_diagonal(simple, *claim.pair)
    except (ValueError, GeometryError) as exc:
        raise BadRequest(f"{name}: {error_line(exc)}", 422) from None
    to_raw = [raw[s] for s in polygon.source]
    return {"diagonal": [to_raw[i] for i in claim.pair], "inner": verdict.ok,
            "why": verdict.why, "labels": [claim.u.label, claim.v.label],
            "crossed": [to_raw[i] for i in verdict.edge] if verdict.edge else None,
            "through": to_raw[verdict.vertex] if verdict.vertex is not None else None}


def diagonal(body: dict, own: dict[str, UserHeuristic]) -> dict:
    """A heuristic's claim on the polygon and the exact verdict, as ``trex diagonal --json``."""
    heuristic = _heuristic(body.get("heuristic"), own)
    rings = rings_of(body, holes=False)
    return _claim(_polygon_of(rings), _raw_index(rings), heuristic, str(body.get("heuristic")))


def failed_claim(name: str, error: str) -> dict:
    """A row of the table for a rule that gave no claim."""
    return {"name": name, "error": error, "diagonal": None, "inner": None, "why": None,
            "labels": None, "crossed": None, "through": None}


def claims(body: dict, own: dict[str, UserHeuristic],
           names: Iterable[str] | None = None) -> list[dict]:
    """Every rule's claim and verdict (``names``; default the built-ins, then one's own), for
    the page's table; a rule that fails on this polygon has its ``error``."""
    rings = rings_of(body, holes=False)
    polygon, raw = _polygon_of(rings), _raw_index(rings)
    out = []
    for name in [*heuristics(), *own] if names is None else names:
        try:
            out.append({"name": name, "error": None,
                        **_claim(polygon, raw, _heuristic(name, own), name)})
        except BadRequest as exc:
            out.append(failed_claim(name, str(exc)))
    return out


def triangulate(body: dict, own: dict[str, UserHeuristic]) -> dict:
    """An algorithm's triangles and their verdict: the fields of ``trex triangulate --json``,
    with ``vertices`` the request's own points (rings concatenated) that the triangles index,
    and ``seconds``, how long the algorithm took."""
    algorithm = body.get("algorithm", "divide-and-conquer")
    if algorithm not in triangulations():
        raise BadRequest(f"unknown algorithm {algorithm!r} (known: {', '.join(triangulations())})")
    heuristic = _heuristic(body.get("heuristic", "gravity"), own)
    rings = rings_of(body)
    polygon, raw = _polygon_of(rings), _raw_index(rings)
    started = time.perf_counter()
    try:
        record = triangulation_record("studio", polygon, algorithm, heuristic)
    except (ValueError, GeometryError) as exc:
        raise BadRequest(f"{algorithm}: {error_line(exc)}", 422) from None
    seconds = time.perf_counter() - started
    record.pop("labels", None)
    record["vertices"] = [p for ring in rings for p in ring]
    record["triangles"] = [[raw[i] for i in t] for t in record["triangles"]]
    record["seconds"] = round(seconds, 4)
    return record


def samples() -> list[str]:
    """The names the page offers: the samples, then those with holes."""
    return [*sample_names(), *HOLE_SAMPLES]


def load(body: dict, uploads: Path) -> dict:
    """A sample by name (``NAME[:N[:SEED]]``) or a file's text as the command line reads it,
    as ``polygon`` and ``holes``. A file is read from ``uploads`` (the work directory's):
    never a path the page names."""
    if isinstance(body.get("sample"), str):
        return _sample(body["sample"])
    file = body.get("file")
    if not isinstance(file, dict) or not isinstance(file.get("name"), str) \
            or not isinstance(file.get("text"), str):
        raise BadRequest('expected {"sample": NAME} or {"file": {"name": ..., "text": ...}}')
    suffix = Path(file["name"]).suffix.lower()
    if suffix not in READ_SUFFIXES:
        raise BadRequest(f"{file['name']}: unknown format {suffix or '(none)'!r}; "
                         f"expected {', '.join(READ_SUFFIXES)}")
    uploads.mkdir(parents=True, exist_ok=True)
    path = uploads / f"upload-{secrets.token_hex(4)}{suffix}"
    path.write_text(file["text"], encoding="utf-8")
    try:
        rings = read_rings(path)
    except GeometryError as exc:
        raise BadRequest(f"{file['name']}: {error_line(exc)}", 422) from None
    finally:
        path.unlink(missing_ok=True)
    return _request_of(rings, file["name"])


def _sample(spec: str) -> dict:
    if spec in HOLE_SAMPLES:
        return _request_of(HOLE_SAMPLES[spec], spec)
    if not is_sample(spec):
        raise BadRequest(f"unknown sample {spec!r}")
    try:
        _, n, _ = parse_spec(spec)
        if n is not None and n > MAX_VERTICES:  # refused before it is made
            raise BadRequest(f"{spec}: {n} vertices: live calls take at most {MAX_VERTICES}", 413)
        return _request_of([sample_from_spec(spec)], spec)
    except GeometryError as exc:
        raise BadRequest(f"{spec}: {error_line(exc)}") from None


def _request_of(rings: Sequence[Sequence[Any]], what: str) -> dict:
    """Rings read from a file or made by a sample, checked as a request's."""
    try:
        body = {"polygon": [list(p) for p in rings[0]] if rings else [],
                "holes": [[list(p) for p in ring] for ring in rings[1:]]}
    except TypeError:
        raise BadRequest(f"{what}: not a list of rings of points") from None
    rings_of(body)
    return body
