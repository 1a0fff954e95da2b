"""Reading polygons from files or sample names, and writing them back.

Formats, chosen by extension:

========================  ==========================================================
``.json``                 a list of [x, y] points; earcut rings (outer ring, then
                          holes); or a GeoJSON object
``.geojson``              GeoJSON Polygon, Feature, or FeatureCollection of one
``.wkt``                  WKT ``POLYGON`` (parsed by shapely)
``.dat``, ``.txt``        one ``x y`` per line; blank lines and ``#`` comments skipped
========================  ==========================================================

Every failure is a :class:`geometry.errors.GeometryError` with a one-line
message. The points go to :meth:`Polygon.from_points` in input order, which
cleans, validates and orients them. Writers never leave half a file behind.

Examples
--------
>>> read_polygon("counterexample").labels
('A', 'B', 'C', 'D', 'E')
>>> polygon_to_json_points([(0, 0), (1.5, 0), (0, 1)])
[[0, 0], [1.5, 0], [0, 1]]
>>> to_wkt([(0, 0), (1.5, 0), (0, 1)])
'POLYGON ((0 0, 1.5 0, 0 1, 0 0))'
>>> round(read_polygon("counterexample").area, 2)
12.52
"""

from __future__ import annotations

import contextlib
import json
import os
import secrets
import stat
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import shapely
import shapely.errors
import shapely.wkt

from geometry.errors import HolesNotSupportedError, InputFormatError
from geometry.hole_samples import HOLE_SAMPLES
from geometry.holes import PolygonWithHoles
from geometry.polygon import Polygon
from geometry.predicates import Point
from geometry.samples import is_sample, sample_from_spec

__all__ = [
    "AnyPolygon",
    "any_polygon_from_rings",
    "check_format",
    "polygon_from_rings",
    "polygon_to_json_points",
    "read_any_polygon",
    "read_polygon",
    "read_rings",
    "to_dat",
    "to_geojson",
    "to_wkt",
    "write_json",
    "write_polygon",
]

_FORMATS = ".json, .geojson, .wkt or .dat"
#: The largest polygon file read, in bytes (16 MiB): a file is refused above it before
#: it is parsed, so reading costs memory in proportion to a bounded input.
MAX_FILE_BYTES = 16 * 1024 * 1024
#: The most vertices (all rings together) a polygon file may hold; refused before validation.
MAX_VERTICES = 500_000
Ring = Sequence[object]
#: A polygon as read, with or without holes (a file may hold either)
AnyPolygon = Polygon | PolygonWithHoles

# --- reading -----------------------------------------------------------------


def read_polygon(arg: str | os.PathLike[str], *, ignore_holes: bool = False) -> Polygon:
    """The simple polygon in file ``arg``, or the sample it names (``NAME[:N[:SEED]]``).

    An existing path wins over a sample of the same name. Holes are validated
    (a defect is named), then refused: use :func:`read_any_polygon` where they are welcome.

    Parameters
    ----------
    arg : str or path
        A polygon file, or a sample name from :func:`geometry.samples.sample_names`.
    ignore_holes : bool
        Keep the outer ring and drop holes instead of rejecting them.

    Raises
    ------
    GeometryError
        :class:`InputFormatError` when the input cannot be read,
        :class:`PolygonError` when it is not a valid simple polygon.

    Examples
    --------
    >>> read_polygon("random-star:8:2").n
    8
    >>> read_polygon("no/such.json")
    Traceback (most recent call last):
    ...
    geometry.errors.InputFormatError: no such file or sample: no/such.json
    """
    path = _argument_path(arg)
    if not path.exists() and str(arg) in HOLE_SAMPLES:
        return polygon_from_rings(HOLE_SAMPLES[str(arg)], ignore_holes=ignore_holes)
    if not path.exists() and is_sample(str(arg)):
        return Polygon.from_points(sample_from_spec(str(arg)))
    return polygon_from_rings(read_rings(path), ignore_holes=ignore_holes)


def read_any_polygon(arg: str | os.PathLike[str]) -> AnyPolygon:
    """Like :func:`read_polygon`, but a polygon with holes is returned as one (also the
    samples of :data:`geometry.hole_samples.HOLE_SAMPLES`).

    >>> read_any_polygon("counterexample").n, read_any_polygon("keyhole").hole_count
    (5, 2)
    """
    path = _argument_path(arg)
    if not path.exists() and str(arg) in HOLE_SAMPLES:
        return any_polygon_from_rings(HOLE_SAMPLES[str(arg)])
    if not path.exists() and is_sample(str(arg)):
        return Polygon.from_points(sample_from_spec(str(arg)))
    return any_polygon_from_rings(read_rings(path))


def _argument_path(arg: str | os.PathLike[str]) -> Path:
    """``arg`` as a path; an empty string (``Path("")`` is the current directory) is refused.

    >>> _argument_path("")
    Traceback (most recent call last):
    ...
    geometry.errors.InputFormatError: empty argument; expected a polygon file or a sample name
    """
    if not str(arg).strip():
        raise InputFormatError("empty argument; expected a polygon file or a sample name")
    return Path(arg)


def any_polygon_from_rings(rings: Sequence[Ring]) -> AnyPolygon:
    """A :class:`Polygon` for one ring, a validated :class:`PolygonWithHoles` for more.

    >>> any_polygon_from_rings([[[0, 0], [4, 0], [0, 4]], [[1, 1], [1, 2], [2, 1]]]).hole_count
    1
    """
    if len(rings) > 1:
        return PolygonWithHoles.from_rings(rings)
    return Polygon.from_points(rings[0] if rings else [])


def polygon_from_rings(rings: Sequence[Ring], *, ignore_holes: bool = False) -> Polygon:
    """Validate the outer ring of ``rings``; valid holes are an error unless ignored.

    >>> polygon_from_rings([[[0, 0], [4, 0], [0, 4]], [[1, 1], [2, 1], [1, 2]]])
    Traceback (most recent call last):
    ...
    geometry.errors.HolesNotSupportedError: polygon has 1 hole; holes are not supported here
    """
    holes = len(rings) - 1
    if holes > 0 and not ignore_holes:
        PolygonWithHoles.from_rings(rings)  # a defect of the rings is named first
        plural = "s" if holes > 1 else ""
        raise HolesNotSupportedError(
            f"polygon has {holes} hole{plural}; holes are not supported here"
        )
    return Polygon.from_points(rings[0] if rings else [])


def read_rings(path: str | os.PathLike[str]) -> list[Ring]:
    """The rings in a polygon file (outer ring first, then holes), not yet validated.

    >>> read_rings("no/such.wkt")
    Traceback (most recent call last):
    ...
    geometry.errors.InputFormatError: no such file or sample: no/such.wkt
    """
    path = Path(path)
    if not path.exists():
        raise InputFormatError(f"no such file or sample: {path}")
    if path.is_dir():
        raise InputFormatError("is a directory, not a polygon file")
    reader = _READERS.get(path.suffix.lower())
    if reader is None:
        raise InputFormatError(f"unknown format '{path.suffix}'; expected {_FORMATS}")
    rings = reader(_read_text(path))
    vertices = sum(len(ring) for ring in rings if isinstance(ring, list | tuple))
    if vertices > MAX_VERTICES:
        raise InputFormatError(
            f"{vertices:,} points; a polygon file holds at most {MAX_VERTICES:,}")
    return rings


def _read_text(path: Path) -> str:
    try:
        data = _read_regular(path)
    except FileNotFoundError:
        raise InputFormatError(f"no such file or sample: {path}") from None
    except OSError as exc:
        raise InputFormatError(f"cannot read file: {exc.strerror or exc}") from None
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputFormatError(
            f"not UTF-8 text: byte 0x{data[exc.start]:02x} at offset {exc.start}"
        ) from None
    if not text.strip():
        raise InputFormatError("file is empty")
    return text


def _read_regular(path: Path) -> bytes:
    """The bytes of a regular file of at most :data:`MAX_FILE_BYTES`.

    Opened without blocking (a FIFO would wait for a writer) and checked on the open
    file: a FIFO, a device (a link to ``/dev/zero``) or a socket never ends, so it is
    refused, and at most one byte past the limit is read.
    """
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise InputFormatError("not a regular file (a FIFO, device or socket)")
        if info.st_size > MAX_FILE_BYTES:
            raise InputFormatError(_too_big(info.st_size))
        with os.fdopen(fd, "rb", closefd=False) as handle:
            data = handle.read(MAX_FILE_BYTES + 1)
    finally:
        os.close(fd)
    if len(data) > MAX_FILE_BYTES:  # it grew while being read
        raise InputFormatError(_too_big(len(data)))
    return data


def _too_big(size: int) -> str:
    return f"file has {size:,} bytes; a polygon file has at most {MAX_FILE_BYTES:,}"


def _parse_int(digits: str) -> int | float:
    # A huge integer becomes inf (and then a clear coordinate error) instead of
    # overflowing float() later or tripping Python's int-string length limit.
    return int(digits) if len(digits) <= 300 else float(digits)


def _load_json(text: str) -> object:
    """Parse JSON (accepting NaN and Infinity, which validation then rejects)."""
    try:
        return json.loads(text, parse_int=_parse_int)
    except json.JSONDecodeError as exc:
        where = f"line {exc.lineno} column {exc.colno}"
        if exc.pos >= len(text.rstrip()):
            raise InputFormatError(f"truncated JSON: input ends early at {where}") from None
        raise InputFormatError(f"not valid JSON: {exc.msg} at {where}") from None
    except RecursionError:
        raise InputFormatError("not valid JSON: nested too deeply") from None


def _is_ring_list(data: object) -> bool:
    """Earcut rings: a list whose first item is a list of lists."""
    return (
        isinstance(data, list)
        and bool(data)
        and isinstance(data[0], list)
        and bool(data[0])
        and isinstance(data[0][0], list)
    )


def _json_rings(text: str) -> list[Ring]:
    data = _load_json(text)
    if isinstance(data, dict):
        return _geojson_rings(data)
    if _is_ring_list(data):
        return data  # type: ignore[return-value]  # JSON data: _is_ring_list saw a list of rings; their points are checked later
    return [data]  # type: ignore[list-item]  # JSON data, one ring; its points are checked later


def _geojson_text_rings(text: str) -> list[Ring]:
    data = _load_json(text)
    if not isinstance(data, dict):
        raise InputFormatError(f"expected a GeoJSON object, got a JSON {_json_kind(data)}")
    return _geojson_rings(data)


def _json_kind(value: object) -> str:
    kinds = {list: "array", str: "string", bool: "boolean", type(None): "null"}
    return kinds.get(type(value), "number")


def _geojson_rings(obj: dict[str, Any]) -> list[Ring]:
    """Rings of a GeoJSON Polygon, a Feature holding one, or a FeatureCollection of one."""
    kind = obj.get("type")
    if kind == "FeatureCollection":
        features = obj.get("features")
        if not isinstance(features, list) or len(features) != 1:
            count = len(features) if isinstance(features, list) else "no"
            raise InputFormatError(
                f"GeoJSON FeatureCollection has {count} features; expected exactly one"
            )
        return _geojson_rings(_expect_object(features[0], "feature"))
    if kind == "Feature":
        geometry = obj.get("geometry")
        if geometry is None:
            raise InputFormatError("GeoJSON Feature has no geometry")
        return _geojson_rings(_expect_object(geometry, "geometry"))
    if kind is None:
        raise InputFormatError(
            "JSON object has no 'type'; expected [x, y] points, rings or a GeoJSON Polygon"
        )
    if kind == "MultiPolygon":
        return _single_polygon(obj.get("coordinates"))
    if kind != "Polygon":
        raise InputFormatError(f"GeoJSON {kind} is not supported; expected a Polygon")
    rings = obj.get("coordinates")
    if not isinstance(rings, list) or (rings and not _is_ring_list(rings)):
        raise InputFormatError("GeoJSON Polygon 'coordinates' must be a list of rings")
    return rings


def _single_polygon(polygons: object) -> list[Ring]:
    """The rings of a GeoJSON MultiPolygon's one polygon (more are refused)."""
    if not isinstance(polygons, list) or len(polygons) != 1:
        count = len(polygons) if isinstance(polygons, list) else "no"
        raise InputFormatError(
            f"GeoJSON MultiPolygon has {count} polygons; expected exactly one")
    return _geojson_rings({"type": "Polygon", "coordinates": polygons[0]})


def _expect_object(value: object, what: str) -> dict[str, Any]:
    if not isinstance(value, dict):
        raise InputFormatError(f"GeoJSON {what} is a JSON {_json_kind(value)}, not an object")
    return value


def _wkt_rings(text: str) -> list[Ring]:
    # GEOS warns (RuntimeWarning) on NaN or overflowing numbers; validation names them.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        try:
            geom = shapely.wkt.loads(text)
        except (shapely.errors.ShapelyError, ValueError) as exc:
            raise InputFormatError(f"malformed WKT: {_short_reason(exc)}") from None
        except NotImplementedError:  # shapely has no class for curves (CURVEPOLYGON …)
            kind = text.strip().split("(", 1)[0].split()[0].upper() if text.strip() else "?"
            raise InputFormatError(f"WKT {kind} is not supported; expected a POLYGON") from None
        if geom.geom_type == "MultiPolygon" and len(geom.geoms) == 1:
            geom = geom.geoms[0]
        if geom.geom_type != "Polygon":
            raise InputFormatError(
                f"WKT {geom.geom_type.upper()} is not supported; expected a POLYGON")
        if geom.is_empty:
            return [[]]
        return [list(geom.exterior.coords), *(list(r.coords) for r in geom.interiors)]


def _short_reason(exc: Exception) -> str:
    """GEOS says ``ParseException: Expected word but encountered end of stream``."""
    first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
    return first.split("Exception: ", 1)[-1]


def _dat_rings(text: str) -> list[Ring]:
    points = []
    for number, line in enumerate(text.splitlines(), start=1):
        content = line.split("#", 1)[0].replace(",", " ").split()
        if not content:
            continue
        try:
            if len(content) != 2:
                raise ValueError
            points.append((float(content[0]), float(content[1])))
        except ValueError:
            raise InputFormatError(
                f"line {number}: expected two numbers 'x y', got {line.strip()[:40]!r}"
            ) from None
    return [points]


_READERS = {
    ".json": _json_rings,
    ".geojson": _geojson_text_rings,
    ".wkt": _wkt_rings,
    ".dat": _dat_rings,
    ".txt": _dat_rings,
}

# --- writing -----------------------------------------------------------------


def _points_of(polygon: Polygon | Sequence[Point]) -> list[Point]:
    """A polygon's points in its input order (ccw for sub-polygons), or the points given."""
    if not isinstance(polygon, Polygon):
        return [(p[0], p[1]) for p in polygon]
    if sorted(polygon.source) == list(range(polygon.n)):
        return polygon.input_points()
    return list(polygon.points)


def _number(x: float) -> float | int:
    # Integral values are written as integers; floats keep their shortest exact repr.
    return int(x) if float(x).is_integer() and abs(x) < 2**53 else float(x)


def polygon_to_json_points(polygon: Polygon | Sequence[Point]) -> list[list[float | int]]:
    """``[[x, y], …]`` in input order, integral coordinates as ints.

    >>> polygon_to_json_points(Polygon.from_points([(0, 0), (0, 1), (1.5, 0)]))
    [[0, 0], [0, 1], [1.5, 0]]
    """
    return [[_number(x), _number(y)] for x, y in _points_of(polygon)]


def to_json(polygon: Polygon | Sequence[Point]) -> str:
    """JSON text: one point per line, so diffs stay readable.

    >>> print(to_json([(0, 0), (1, 0), (0, 1)]))
    [
      [0, 0],
      [1, 0],
      [0, 1]
    ]
    """
    rows = ",\n".join(f"  {json.dumps(p)}" for p in polygon_to_json_points(polygon))
    return f"[\n{rows}\n]"


def to_wkt(polygon: Polygon | Sequence[Point]) -> str:
    """WKT ``POLYGON``, exact.

    Written by hand: shapely's writer prints at most 16–17 significant digits
    and does not round-trip every float, while Python's shortest repr does.

    >>> to_wkt([(0, 0), (0.1, 0), (0, 1e-07)])
    'POLYGON ((0 0, 0.1 0, 0 1e-07, 0 0))'
    """
    points = polygon_to_json_points(polygon)
    ring = ", ".join(f"{x!r} {y!r}" for x, y in [*points, points[0]])
    return f"POLYGON (({ring}))"


def to_geojson(polygon: Polygon | Sequence[Point]) -> str:
    """GeoJSON Polygon geometry.

    >>> to_geojson([(0, 0), (1, 0), (0, 1)])
    '{"type":"Polygon","coordinates":[[[0.0,0.0],[1.0,0.0],[0.0,1.0],[0.0,0.0]]]}'
    """
    text: str = shapely.to_geojson(shapely.Polygon(_points_of(polygon)))
    return text


def to_dat(polygon: Polygon | Sequence[Point]) -> str:
    """One ``x y`` per line (exact: shortest float repr).

    >>> print(to_dat([(0, 0), (1.5, 0), (0, 1)]), end="")
    0 0
    1.5 0
    0 1
    """
    return "".join(f"{x} {y}\n" for x, y in polygon_to_json_points(polygon))


_WRITERS = {
    ".json": to_json,
    ".geojson": to_geojson,
    ".wkt": to_wkt,
    ".dat": to_dat,
    ".txt": to_dat,
}


def write_json(polygon: Polygon | Sequence[Point], path: str | os.PathLike[str]) -> None:
    """Write the points as JSON to ``path``, atomically."""
    write_atomic(Path(path), to_json(polygon) + "\n")


def write_polygon(polygon: Polygon | Sequence[Point], path: str | os.PathLike[str]) -> None:
    """Write in the format of ``path``'s extension, atomically.

    >>> write_polygon([(0, 0), (1, 0), (0, 1)], "out.xyz")
    Traceback (most recent call last):
    ...
    geometry.errors.InputFormatError: unknown format '.xyz'; expected .json, .geojson, .wkt or .dat
    """
    path = Path(path)
    check_format(path)
    text = _WRITERS[path.suffix.lower()](polygon)
    write_atomic(path, text if text.endswith("\n") else text + "\n")


def check_format(path: str | os.PathLike[str]) -> None:
    """Raise :class:`InputFormatError` unless ``path``'s extension names a format
    :func:`write_polygon` writes (checked before any work, so a long search is not lost).

    >>> check_format("ce.wkt")
    >>> check_format("ce")
    Traceback (most recent call last):
    ...
    geometry.errors.InputFormatError: no extension to name the format; expected .json, .geojson, .wkt or .dat
    """
    suffix = Path(path).suffix
    if suffix.lower() in _WRITERS:
        return
    named = f"unknown format '{suffix}'" if suffix else "no extension to name the format"
    raise InputFormatError(f"{named}; expected {_FORMATS}")


def write_atomic(path: Path, text: str) -> None:
    """Write a temp file next to ``path``, then rename it over ``path``.

    A crash or error at any point leaves either the old file or the new one,
    never a partial one; the temp file is removed on failure.
    """
    temp = path.with_name(f".{path.name}.{secrets.token_hex(4)}.tmp")
    try:
        # Exclusive create honours the umask, as a plain open() of a new file would.
        with open(temp, "x", encoding="utf-8") as handle:
            handle.write(text)
            handle.flush()
            os.fsync(handle.fileno())
        with contextlib.suppress(FileNotFoundError):
            os.chmod(temp, path.stat().st_mode & 0o7777)  # keep an existing file's mode
        os.replace(temp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temp)
        raise
