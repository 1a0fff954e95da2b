"""Hypothesis strategies shared by the property tests: polygons from every random generator."""

from hypothesis import strategies as st

from geometry.polygon import Polygon
from geometry.samples import _FAMILIES, make_sample

GENERATORS = ("random-star", "random-2opt", "random-orthogonal", "random-spiral", "random-comb")


@st.composite
def generated_polygons(draw, max_n: int = 28, generators=GENERATORS) -> Polygon:
    """A valid polygon from a seeded generator: star, 2-opt, orthogonal grid, spiral, comb."""
    name = draw(st.sampled_from(generators))
    low = max(_FAMILIES[name].minimum, 4)  # a triangle has no diagonal
    n = draw(st.integers(low, max(low, max_n)))
    seed = draw(st.integers(0, 10**6))
    return Polygon.from_points(make_sample(name, n, seed))
