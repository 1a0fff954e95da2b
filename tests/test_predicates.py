"""Exactness of the predicates, on the inputs where floating point lies."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geometry.batch import dot_sign_many
from geometry.predicates import (
    Contact,
    compare_angle,
    compare_distance,
    compare_line_distance,
    cross_sign,
    dot_sign,
    in_triangle,
    orient,
    orient_det,
    segment_contact,
)


def naive_orient(a, b, c):
    det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (det > 0) - (det < 0)


def exact_orient(a, b, c):
    det = orient_det(a, b, c)
    return (det > 0) - (det < 0)


def kettner_grid():
    """Kettner et al.'s classroom example: p walks a 64×64 grid of ulps near (0.5, 0.5)."""
    ulp = 2.0**-53
    q, r = (12.0, 12.0), (24.0, 24.0)
    for i in range(64):
        for j in range(64):
            yield (0.5 + i * ulp, 0.5 + j * ulp), q, r


def test_orient_is_exact_where_floats_fail():
    triples = list(kettner_grid())
    wrong_naive = sum(naive_orient(*t) != exact_orient(*t) for t in triples)
    assert wrong_naive > 100, "the grid must contain cases plain floats get wrong"
    assert all(orient(*t) == exact_orient(*t) for t in triples)


finite = st.floats(allow_nan=False, allow_infinity=False, width=64)
point = st.tuples(finite, finite)


@settings(max_examples=500)
@given(point, point, point)
def test_orient_matches_exact_on_any_finite_floats(a, b, c):
    assert orient(a, b, c) == exact_orient(a, b, c)


@given(point, point, point)
def test_orient_antisymmetric(a, b, c):
    assert orient(a, b, c) == -orient(b, a, c) == orient(b, c, a)


@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1.0, 1e150, 1e300])
def test_orient_huge_and_tiny(scale):
    a, b = (0.0, 0.0), (3 * scale, 3 * scale)
    assert orient(a, b, (scale, scale)) == 0
    assert orient(a, b, (scale, scale * (1 + 2**-52))) == 1
    assert orient(a, b, (scale * (1 + 2**-52), scale)) == -1


def test_orient_overflowing_products_go_exact():
    a, b, c = (-1e308, -1e308), (1e308, 1e308), (0.0, 1e-300)
    assert orient(a, b, c) == 1


def test_compare_distance_exact_where_rounding_blurs_a_tie():
    origin = (0.1, 0.2)
    p = (0.1 + 3.0, 0.2 + 4.0)
    q = (0.1 + 5.0, 0.2)
    dp = (Fraction(p[0]) - Fraction(origin[0])) ** 2 + (Fraction(p[1]) - Fraction(origin[1])) ** 2
    dq = (Fraction(q[0]) - Fraction(origin[0])) ** 2 + (Fraction(q[1]) - Fraction(origin[1])) ** 2
    assert compare_distance(origin, p, q) == (dp > dq) - (dp < dq)


@given(point, point, point)
def test_compare_distance_matches_fractions(o, p, q):
    def d(x):
        return (Fraction(x[0]) - Fraction(o[0])) ** 2 + (Fraction(x[1]) - Fraction(o[1])) ** 2

    assert compare_distance(o, p, q) == (d(p) > d(q)) - (d(p) < d(q))


def test_compare_angle():
    apex, ref = (0, 0), (1, 0)
    assert compare_angle(apex, ref, (1, 1), (0, 1)) == -1
    assert compare_angle(apex, ref, (-1, 1), (0, 1)) == 1
    assert compare_angle(apex, ref, (3, 3), (1, 1)) == 0
    assert compare_angle(apex, ref, (1, -1), (1, 1)) == 0  # unsigned angles
    with pytest.raises(ValueError):
        compare_angle(apex, ref, apex, (1, 1))


def test_compare_line_distance():
    assert compare_line_distance((0, 0), (4, 0), (1, 3), (9, -3)) == 0
    assert compare_line_distance((0, 0), (4, 0), (1, 2), (9, -3)) == -1


def test_in_triangle_closed_and_open():
    tri = ((0, 0), (4, 0), (0, 4))
    assert in_triangle((2, 2), *tri)
    assert not in_triangle((2, 2), *tri, closed=False)
    assert in_triangle((1, 1), *tri, closed=False)
    assert in_triangle((1, 1), tri[0], tri[2], tri[1], closed=False)  # either orientation
    with pytest.raises(ValueError):
        in_triangle((1, 1), (0, 0), (1, 1), (2, 2))


@pytest.mark.parametrize(
    ("seg1", "seg2", "contact"),
    [
        (((0, 0), (2, 2)), ((0, 2), (2, 0)), Contact.PROPER),
        (((0, 0), (2, 0)), ((1, 0), (1, 5)), Contact.TOUCH),
        (((0, 0), (2, 0)), ((2, 0), (5, 5)), Contact.TOUCH),
        (((0, 0), (2, 0)), ((1, 0), (3, 0)), Contact.OVERLAP),
        (((0, 0), (2, 0)), ((2, 0), (3, 0)), Contact.TOUCH),
        (((0, 0), (2, 0)), ((3, 0), (4, 0)), Contact.NONE),
        (((0, 0), (0, 2)), ((0, 1), (0, 3)), Contact.OVERLAP),
        (((0, 0), (2, 2)), ((3, 3), (4, 5)), Contact.NONE),
        (((0, 0), (1, 1e-17)), ((0.5, -1), (0.5, 1)), Contact.PROPER),
    ],
)
def test_segment_contact(seg1, seg2, contact):
    assert segment_contact(*seg1, *seg2) is contact
    assert segment_contact(*seg2, *seg1) is contact


def exact_dot(d, p, q):
    value = sum((Fraction(q[k]) - Fraction(p[k])) * Fraction(d[k]) for k in (0, 1))
    return (value > 0) - (value < 0)


@settings(max_examples=500)
@given(point, point, point)
def test_dot_and_cross_sign_match_fractions_on_any_finite_floats(d, p, q):
    assert dot_sign(d, p, q) == exact_dot(d, p, q)
    assert cross_sign(d, p, q) == -exact_dot((d[1], -d[0]), p, q)


def test_dot_sign_where_floats_fail():
    """Kettner's grid again: p ± 1 ulp across a direction at right angles to q − p."""
    ulp = 2.0**-53
    d = (1.0, -1.0)
    cases = [((0.5 + i * ulp, 0.5 + j * ulp), (24.0, 24.0)) for i in range(32) for j in range(32)]
    naive = sum(((q[0] - p[0]) * d[0] + (q[1] - p[1]) * d[1] > 0) - (
        (q[0] - p[0]) * d[0] + (q[1] - p[1]) * d[1] < 0) != exact_dot(d, p, q) for p, q in cases)
    assert naive > 0, "the grid must contain cases plain floats get wrong"
    assert all(dot_sign(d, p, q) == exact_dot(d, p, q) for p, q in cases)
    starts, ends = np.array([p for p, _ in cases]), np.array([q for _, q in cases])
    assert dot_sign_many(d, starts, ends).tolist() == [exact_dot(d, p, q) for p, q in cases]


def test_cross_sign_is_orient_along_a_direction():
    assert cross_sign((0.0, -1.0), (2.0, 3.0), (1.0, -7.0)) == orient((2, 3), (2, 2), (1, -7)) == -1
    assert cross_sign((3.0, 1.0), (0.0, 0.0), (6.0, 2.0)) == 0
