"""Every triangulation algorithm on 10,000-vertex stars, spirals and combs (slow: --runslow).

Divide and conquer is left to its own tests; the naive ear clipping is O(n³) in
the worst case and takes minutes here, which is why these are opt-in.
"""

from __future__ import annotations

import pytest

from geometry.check import verify_triangulation
from geometry.polygon import Polygon
from geometry.prune_search import find_an_ear
from geometry.samples import make_sample
from geometry.triangulate import triangulate
from story.registry import triangulations
from tests.test_ears import is_ear_by_definition

N = 10_000
SHAPES = ["star", "spiral", "comb"]
#: every triangulation but divide and conquer, the naive ear clipping (the slowest) last
ALGORITHMS = sorted((a for a in triangulations() if a != "divide-and-conquer"),
                    key=lambda a: a == "ear-clipping-naive")

_POLYGONS: dict[str, Polygon] = {}


def polygon(shape: str) -> Polygon:
    """Each large polygon is validated once for the whole module."""
    if shape not in _POLYGONS:
        _POLYGONS[shape] = Polygon.from_points(make_sample(shape, N))
    return _POLYGONS[shape]


@pytest.mark.slow
@pytest.mark.parametrize("algorithm", ALGORITHMS)
@pytest.mark.parametrize("shape", SHAPES)
def test_large(shape, algorithm):
    p = polygon(shape)
    result = triangulate(p, algorithm)  # verifies exactly; a bad answer comes back not valid
    assert result.valid, result.failure
    assert len(result.triangles) == N - 2
    assert verify_triangulation(p, result.triangles)


@pytest.mark.slow
@pytest.mark.parametrize("shape", SHAPES)
def test_large_find_an_ear(shape):
    p = polygon(shape)
    ear = find_an_ear(p)
    assert is_ear_by_definition(p, ear.index)

