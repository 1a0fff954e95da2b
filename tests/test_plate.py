"""The fruit's plate holds its slices: every slice's box lies inside the plate's ellipse,
however many slices (the last ones stuck out at the thin right end, issue 22's review)."""

from itertools import pairwise

import pytest

from metaphors.fruit import PLATE_HEIGHT, PLATE_WIDTH, plate_slot


@pytest.mark.parametrize("total", [1, 2, 3, 11, 17, 19, 40])
def test_every_slice_lies_inside_the_plate(total):
    slots = [plate_slot(k, total) for k in range(1, total + 1)]
    for x, width, height in slots:
        for dx in (-width / 2, width / 2):
            for dy in (-height / 2, height / 2):
                corner = ((x + dx) / (PLATE_WIDTH / 2)) ** 2 + (dy / (PLATE_HEIGHT / 2)) ** 2
                assert corner <= 1.0, (total, x, width, height)
    # side by side, in order, none over another
    assert all(a[0] + a[1] / 2 <= b[0] - b[1] / 2 for a, b in pairwise(slots))
