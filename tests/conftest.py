"""Suite-wide settings: reproducible hypothesis runs, and slow tests only on request."""

import sys

import pytest
from hypothesis import HealthCheck, settings

# Derandomized: CI and every developer see the same examples, so a red run reproduces.
settings.register_profile(
    "trex", derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.load_profile("trex")


def pytest_addoption(parser):
    parser.addoption("--runslow", action="store_true", help="also run tests marked slow")
    # Read by manim's frames_comparison (tests/test_render.py).
    parser.addoption("--set_test", action="store_true",
                     help="write manim's control frames to tests/control_data/")
    parser.addoption("--show_diff", action="store_true", help="show manim's frame differences")


def pytest_configure(config):
    # Under `-n N` (xdist's default --dist load), still keep tests marked xdist_group on one
    # worker: tests/test_scenes.py groups a scene's tests so its builds are cached, not redone.
    if getattr(config.option, "dist", "no") == "load":
        config.option.dist = "loadgroup"


def pytest_runtest_setup(item):
    # manim's frames_comparison skips on cairo < 1.18; Debian's 1.16 renders our frames fine.
    frames = sys.modules.get("manim.utils.testing.frames_comparison")
    if frames is not None:
        frames.MIN_CAIRO_VERSION = 11600


def pytest_collection_modifyitems(config, items):
    if config.getoption("--runslow"):
        return
    skip = pytest.mark.skip(reason="slow: run with --runslow")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(skip)
