"""manim's Cairo camera with a cheaper way of handing a path to Cairo.

manim hands Cairo each Bézier curve of a ``VMobject`` by indexing a NumPy array six times per
curve and finds the subpaths with a dozen small NumPy calls per mobject; in our frames (text
of thousands of curves, dozens of small markers) that Python work costs more than Cairo's
drawing. :class:`PathCamera` makes the same Cairo calls with the same numbers — so the same
pixels, bit for bit (``tests/test_camera.py`` draws random paths and renders whole scenes with
both cameras) — from one ``tolist()`` per mobject, and skips mobjects whose every colour is
fully transparent (Cairo draws nothing for them).
"""

from __future__ import annotations

from itertools import pairwise

import cairo
import numpy as np
from manim import Camera, VMobject
from manim.camera.camera import CAP_STYLE_MAP, LINE_JOIN_MAP

#: Cubic Bézier curves are 4 points: anchor, handle, handle, anchor.
_CURVE = 4
_RTOL = 1.0e-5  # numpy.isclose's default, as VMobject uses it
#: Paths of up to this many curves find their subpaths in a Python loop, longer ones in NumPy.
_LOOP_UP_TO = 24


class PathCamera(Camera):
    """:class:`manim.Camera`, building each ``VMobject``'s Cairo path with less Python."""

    def display_vectorized(self, vmobject: VMobject, ctx: cairo.Context) -> PathCamera:
        # manim's display_vectorized, apply_fill and apply_stroke in one, with the same calls
        fill = self.get_fill_rgbas(vmobject)
        width, behind = vmobject.get_stroke_width(), vmobject.get_stroke_width(True)
        stroke = self.get_stroke_rgbas(vmobject) if width else None
        if (not fill[:, 3].any() and (stroke is None or not stroke[:, 3].any())
                and (not behind or not self.get_stroke_rgbas(vmobject, True)[:, 3].any())):
            return self  # Cairo would fill and stroke with a clear colour: nothing
        self.set_cairo_context_path(ctx, vmobject)
        if behind:
            self.apply_stroke(ctx, vmobject, background=True)
        self._set_source(ctx, fill, vmobject)
        ctx.fill_preserve()
        if stroke is not None:  # there is a stroke width
            self._set_source(ctx, stroke, vmobject)
            ctx.set_line_width(width * self.cairo_line_width_multiple
                               * (self.frame_width / self.frame_width))  # manim's expression
            ctx.set_line_join(LINE_JOIN_MAP[vmobject.joint_type])
            ctx.set_line_cap(CAP_STYLE_MAP[vmobject.cap_style])
            ctx.stroke_preserve()
        return self

    def _set_source(self, ctx: cairo.Context, rgbas: np.ndarray, vmobject: VMobject) -> None:
        if len(rgbas) == 1:  # one colour; the surface holds it as BGRA
            red, green, blue, alpha = rgbas[0].tolist()
            ctx.set_source_rgba(blue, green, red, alpha)
        else:  # a gradient
            self.set_cairo_context_color(ctx, rgbas, vmobject)

    def set_cairo_context_path(self, ctx: cairo.Context, vmobject: VMobject) -> PathCamera:
        points = vmobject.points
        count = len(points)
        if (count % _CURVE or points.dtype != np.float64
                or type(self).transform_points_pre_display
                is not Camera.transform_points_pre_display):
            # unusual: manim's own way (it compares float32 or integer points in their type)
            return super().set_cairo_context_path(ctx, vmobject)
        if count == 0:
            return self
        if not np.isfinite(points).all():  # manim draws nothing for such a mobject
            ctx.new_path()
            return self
        ctx.new_path()
        # One row per curve: start anchor, two handles, end anchor (x, y each).
        rows = points[:, :2].reshape(-1, 2 * _CURVE).tolist()
        move_to, curve_to, close_path = ctx.move_to, ctx.curve_to, ctx.close_path
        new_sub_path, equal = ctx.new_sub_path, vmobject.consider_points_equals_2d
        for first, last in _subpaths(points, rows, vmobject.tolerance_for_point_equality):
            new_sub_path()
            start = rows[first]
            move_to(start[0], start[1])
            for row in rows[first:last]:
                curve_to(row[2], row[3], row[4], row[5], row[6], row[7])
            end = rows[last - 1]
            if equal((start[0], start[1]), (end[6], end[7])):
                close_path()
        return self


def _subpaths(points: np.ndarray, rows: list[list[float]], atol: float) -> list[tuple[int, int]]:
    """Runs of curves ``[first, last)`` in which each curve starts where the last one ended:
    ``VMobject.get_subpath_split_indices_from_points`` (with ``n_dims=2``) for finite points,
    counted in curves instead of points. ``rows`` are the curves of ``points`` as lists."""
    if len(rows) > _LOOP_UP_TO:  # long paths (text): NumPy over all curve joints at once
        ends, starts = points[_CURVE - 1:-1:_CURVE, :2], points[_CURVE::_CURVE, :2]
        apart = ~(np.abs(ends - starts) <= atol + _RTOL * np.abs(starts)).all(axis=1)
        splits = (np.flatnonzero(apart) + 1).tolist()
    else:  # short ones: a loop costs less than NumPy's calls; most joints are exact
        splits = [k for k, (end, start) in enumerate(pairwise(rows), start=1)
                  if (end[6] != start[0] or end[7] != start[1])
                  and not (abs(end[6] - start[0]) <= atol + _RTOL * abs(start[0])
                           and abs(end[7] - start[1]) <= atol + _RTOL * abs(start[1]))]
    return list(pairwise([0, *splits, len(rows)]))
