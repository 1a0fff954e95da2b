"""PathCamera draws what manim's Camera draws, bit for bit: it only hands Cairo the same path
with less Python."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from manim import BLUE, RED, Camera, Circle, Square, VMobject, tempconfig
from manim.renderer.cairo_renderer import CairoRenderer

from rendering.camera import PathCamera
from rendering.typeset import text
from tests.test_redraw import frames, scene_class


def pixels(camera_class, mobjects) -> np.ndarray:
    camera = camera_class()
    camera.capture_mobjects(mobjects)
    return camera.pixel_array


def same_pixels(*mobjects) -> bool:
    return np.array_equal(pixels(Camera, mobjects), pixels(PathCamera, mobjects))


coordinate = st.one_of(st.floats(-8, 8), st.sampled_from([0.0, 1e-9, -1e-9, 1e6, -1e6]))
point = st.tuples(coordinate, coordinate, st.just(0.0))


@st.composite
def vmobjects(draw) -> VMobject:
    """A VMobject of a few subpaths, some closed, some sharing anchors only nearly."""
    mobject = VMobject(stroke_width=draw(st.sampled_from([0, 1, 4])),
                       fill_opacity=draw(st.sampled_from([0.0, 0.5, 1.0])))
    mobject.set_stroke(opacity=draw(st.sampled_from([0.0, 0.7, 1.0])))
    for _ in range(draw(st.integers(1, 4))):
        corners = draw(st.lists(point, min_size=2, max_size=9))
        start = np.array(corners[0])
        mobject.start_new_path(start)
        for corner in corners[1:]:
            if draw(st.booleans()):
                mobject.add_line_to(np.array(corner))
            else:
                mobject.add_cubic_bezier_curve_to(start + 0.3, np.array(corner) - 0.2,
                                                  np.array(corner))
        if draw(st.booleans()):
            mobject.close_path()
        elif draw(st.booleans()):  # ends a hair away from where it started
            mobject.add_line_to(start + draw(st.sampled_from([1e-9, 1e-7, 1e-3])))
    return mobject


@settings(max_examples=60, deadline=None)
@given(st.lists(vmobjects(), min_size=1, max_size=3))
def test_random_paths_give_the_same_pixels(mobjects):
    assert same_pixels(*mobjects)


def test_shapes_text_gradients_and_bad_points_give_the_same_pixels():
    shapes = [Circle(radius=2, fill_opacity=0.4), Square(2).set_color([BLUE, RED]),
              text("Gravity: the ball drops", size=40).shift(2 * np.array([0, 1, 0]))]
    broken = Square(1, fill_opacity=1)
    broken.points[3] = np.nan  # manim draws nothing for it
    clear = Square(3, fill_opacity=0, stroke_opacity=0)  # nor for this one
    odd = VMobject().set_points(np.array([[0, 0, 0], [1, 1, 0], [2, 0, 0.0]]))  # 3 points
    assert same_pixels(*shapes, broken, clear, odd)
    assert pixels(PathCamera, shapes).any()  # it did draw something


def test_float32_points_are_split_as_manim_splits_them():
    """manim compares float32 points in float32: two anchors 1e-6 apart are one joint there,
    and two subpaths in float64."""
    start, end = np.float32(3.623742e-06), np.float32(4.6237783e-06)
    points = np.array([[-3, -2, 0], [-3, 2, 0], [-1, 3, 0], [end, 1, 0],
                       [start, 1, 0], [3, 2, 0], [3, -3, 0], [-3, -2, 0]], dtype=np.float32)
    mobject = VMobject(fill_opacity=1, stroke_width=12).set_points(points)
    assert mobject.points.dtype == np.float32
    assert same_pixels(mobject)


@pytest.mark.parametrize(("file", "name"), [("gravity", "Gravity"), ("ears", "Ears")])
def test_whole_scene_renders_the_same_frames(tmp_path, file, name):
    cls = scene_class(file, name)
    ours = frames(lambda: cls(renderer=CairoRenderer(camera_class=PathCamera)),
                  str(tmp_path / "ours"))
    manims = frames(lambda: cls(renderer=CairoRenderer(camera_class=Camera)),
                    str(tmp_path / "manim"))
    assert len(ours) > 40 and ours == manims


def test_scenes_use_it():
    with tempconfig({"dry_run": True}):
        scene = scene_class("gravity", "Gravity")()
    assert type(scene.renderer.camera) is PathCamera
