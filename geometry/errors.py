"""The one exception family of the geometry package.

Every message is one short line that names the defect, so the command line can
print it as it is: ``error: <input>: <message>``.

>>> str(SelfIntersectionError("edges C–D and F–G cross at (2, 1.5)"))
'edges C–D and F–G cross at (2, 1.5)'
>>> issubclass(HolesNotSupportedError, PolygonError)
True
"""

from __future__ import annotations


class GeometryError(Exception):
    """Base of every error raised by :mod:`geometry`."""


class InputFormatError(GeometryError):
    """The file or data cannot be read as a polygon (missing, not JSON, bad WKT …)."""


class PolygonError(GeometryError):
    """The data was read but does not describe a valid simple polygon."""


class CoordinateError(PolygonError):
    """A point is not two finite numbers."""


class TooFewPointsError(PolygonError):
    """Fewer than three distinct points."""


class DegenerateError(PolygonError):
    """Zero area: all points collinear."""


class SelfIntersectionError(PolygonError):
    """Edges cross, touch, overlap, fold back, or a vertex repeats (pinch)."""


class HolesNotSupportedError(PolygonError):
    """The input has holes or several parts."""


class UnknownSampleError(GeometryError):
    """No sample or generator of that name."""


class HoleError(PolygonError):
    """A hole crosses or touches another ring, lies outside the polygon or inside another hole."""


class LogFormatError(InputFormatError):
    """A log lacks what reading it needs: a traced function's argument, or a reference."""
