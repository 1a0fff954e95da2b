"""Suite-wide settings: reproducible hypothesis runs, and slow tests only on request."""

import ast
import functools
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

# Derandomized: CI and every developer see the same examples, so a red run reproduces.
settings.register_profile(
    "trex", derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.load_profile("trex")


def pytest_addoption(parser):
    parser.addoption("--runslow", action="store_true", help="also run tests marked slow")
    parser.addoption("--fast", action="store_true",
                     help="only the tracing, geometry, usercode and story tests (make test-fast)")
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


ROOT = Path(__file__).resolve().parent.parent
#: the packages whose doctests are fast
LOWER = ("tracing", "geometry", "usercode", "story")
#: what a fast test module may not import: the layers above story, manim, or a process
ABOVE = frozenset({"trex", "metaphors", "rendering", "scenes", "manim", "subprocess"})


@functools.cache
def _imports(path: Path) -> frozenset[str]:
    """The top-level names ``path`` imports, anywhere in it, with those of the ``tests.``
    helpers it imports (followed)."""
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        modules = ([a.name for a in node.names] if isinstance(node, ast.Import)
                   else [node.module] if isinstance(node, ast.ImportFrom) and node.module
                   else [])
        for module in modules:
            names.add(module.partition(".")[0])
            helper = ROOT / (module.replace(".", "/") + ".py")
            if module.startswith("tests.") and helper.is_file():
                names |= _imports(helper)
    return frozenset(names)


def is_fast(path: Path) -> bool:
    """Whether a test file belongs to ``make test-fast``: a module of tracing, geometry,
    usercode or story (its doctests), or a test module importing nothing above story and
    starting no process."""
    try:
        parts = path.resolve().relative_to(ROOT).parts
    except ValueError:  # outside the repository
        return False
    if parts[0] in LOWER:
        return True
    return parts[0] == "tests" and not (_imports(path.resolve()) & ABOVE)


def _leave_out_property_sweeps(config, items):
    """--fast leaves out the hypothesis tests (hundreds to thousands of generated polygons
    each: most of the lower layers' time); `make test` runs them."""
    swept = [item for item in items
             if getattr(getattr(item, "obj", None), "is_hypothesis_test", False)]
    if swept:
        config.hook.pytest_deselected(items=swept)
        items[:] = [item for item in items if item not in swept]


def pytest_ignore_collect(collection_path, config):
    # Decided from the file's text, before importing it: the upper layers' modules (and manim)
    # are never loaded, which is most of the time the whole suite spends collecting.
    if (config.getoption("--fast") and collection_path.suffix == ".py"
            and collection_path.name != "conftest.py" and not is_fast(collection_path)):
        return True
    return None


def pytest_collection_modifyitems(config, items):
    if config.getoption("--fast"):
        _leave_out_property_sweeps(config, items)
    if config.getoption("--runslow"):
        return
    skip = pytest.mark.skip(reason="slow: run with --runslow")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(skip)
