"""The sample behind scenes/gravity.py really shows a snag: the band bends at a vertex."""

import tracing
from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.polygon import Polygon
from geometry.predicates import orient
from geometry.samples import make_sample
from metaphors.catalog import beats


def _run(name: str):
    polygon = Polygon.from_points(make_sample(name))
    with tracing.record() as log:
        diagonal = find_diagonal(polygon, "gravity")
    return polygon, diagonal, log


def _beat(log, action: str):
    return next(b for b in beats(log) if b.action == action)


def test_gravity_snag_band_bends_at_a_vertex():
    polygon, diagonal, log = _run("gravity-snag")
    snag = _beat(log, "snag")
    v, y, x = snag.band.corners
    assert snag.snagged == "H" and snag.band.snagged
    assert orient(v, y, x) != 0  # really bent, not a vertex lying on the straight band
    assert diagonal.name == "CH"
    assert is_inner_diagonal(polygon, *diagonal.pair)
    # the ball slid to X = G; the straight band C–G is not a diagonal
    assert tuple(x) == polygon.points[polygon.labels.index("G")]
    assert not is_inner_diagonal(polygon, polygon.labels.index("C"), polygon.labels.index("G"))


def test_gravity_snag_turns_the_picture_and_slides():
    _, _, log = _run("gravity-snag")
    turn = next(e.result for e in log.events if e.kind == "return" and e.name == "gravity_direction")
    assert 30 < abs(turn["turn_picture"]) < 150
    hit, slid = _beat(log, "drop").drop.hit, _beat(log, "slide").slide
    assert slid is not None and slid.to != hit  # it hits an edge, then slides along it


def test_gravity_scene_defaults_to_the_snag():
    from scenes.gravity import Gravity

    assert Gravity.polygon == "gravity-snag"
