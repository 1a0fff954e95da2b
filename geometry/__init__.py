"""Exact geometry: predicates, the validated Polygon, readers, checks, algorithms.

Never imports manim.
"""

from geometry.errors import GeometryError, InputFormatError, PolygonError
from geometry.polygon import Polygon, vertex_label

__all__ = ["GeometryError", "InputFormatError", "Polygon", "PolygonError", "vertex_label"]
