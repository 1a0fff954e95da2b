"""The rubber band is always inside P (review r34 item 1): sampled through the slide from the
pieces :func:`story.analysis.wraps` gives, as :func:`story.analysis.band_at` has it at each
time, its segments never leave the polygon. :func:`metaphors.gravity.slide` draws the band
in every frame from these two (one play per piece, the ball moving linearly), so what is
sampled here is what is drawn. The old drawing, the band straight from V to the ball until
the snag beat bent it, crossed edge A–H of the lecture's polygon and lay outside P for two
seconds."""

import pytest
import shapely

import tracing
from geometry.diagonals import find_diagonal
from geometry.polygon import Polygon
from geometry.samples import make_sample
from metaphors.catalog import beats
from story.analysis import band_at, lies_inside, wraps

#: the samples the lecture's chapter 3 runs gravity on
SAMPLES = ("gravity-snag", "counterexample")


def _slide(name: str):
    """The polygon's points, V, the hit and X of gravity's run on sample ``name``."""
    polygon = Polygon.from_points(make_sample(name))
    with tracing.record() as log:
        find_diagonal(polygon, "gravity")
    run = {b.action: b for b in reversed(beats(log))}
    where = dict(zip(polygon.labels, polygon.points, strict=True))
    drop, slid = run["drop"].drop, run["slide"].slide
    return polygon.points, where[drop.vertex], drop.hit, slid.to if slid else drop.hit


def bands_outside(points, draw, samples: int = 200) -> list[str]:
    """The times of the slide (``draw(t)``: the band's corners at ``t``) at which the band
    leaves the polygon ``points``, beyond float slack."""
    return [f"t={k / samples:.3f}" for k in range(samples + 1)
            if not lies_inside(shapely.LineString(draw(k / samples)), points)]


@pytest.mark.parametrize("name", SAMPLES)
def test_the_band_never_leaves_p(name):
    points, v, hit, x = _slide(name)
    pieces = wraps(v, hit, x, points)
    assert bands_outside(points, lambda t: band_at(pieces, hit, x, t)) == []


def test_the_straight_band_of_the_old_drawing_leaves_p():
    """The rule can fail: the band drawn straight to the ball through the slide (main before
    review r34) leaves P on the lecture's polygon, and bends there once it is taut."""
    points, v, hit, x = _slide("gravity-snag")

    def straight(t):
        return [v, (hit[0] + t * (x[0] - hit[0]), hit[1] + t * (x[1] - hit[1]))]

    assert len(bands_outside(points, straight)) > 20
    assert len(wraps(v, hit, x, points)) == 2  # it wraps H on the way
