"""Every triangulation algorithm by name, for :func:`geometry.triangulate.triangulate`.

The algorithms import :mod:`geometry.triangulate` (for the result type), so
``triangulate()`` imports this table on first use rather than at load time.

>>> sorted(RUNNERS)
['cdt', 'ear-clipping', 'ear-clipping-naive', 'monotone', 'prune-and-search']
"""

from __future__ import annotations

from collections.abc import Callable

import tracing
from geometry.cdt import constrained_delaunay
from geometry.ears import ear_clipping, ear_clipping_naive
from geometry.monotone import monotone
from geometry.polygon import Polygon
from geometry.prune_search import prune_and_search
from geometry.triangles import finished
from geometry.triangulate import Triangulation


@tracing.traced(name="cdt")
def cdt(polygon: Polygon) -> Triangulation:
    """The reference: shapely's (GEOS) constrained Delaunay triangulation."""
    return finished(constrained_delaunay(polygon))


RUNNERS: dict[str, Callable[[Polygon], Triangulation]] = {
    "ear-clipping-naive": ear_clipping_naive,
    "ear-clipping": ear_clipping,
    "prune-and-search": prune_and_search,
    "monotone": monotone,
    "cdt": cdt,
}
