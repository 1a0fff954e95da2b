"""The registry of algorithms and heuristics (story/registry.py) against what geometry runs."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import pytest

import tracing
from geometry.check import is_inner_diagonal, verify_triangulation
from geometry.diagonals import HEURISTICS, find_diagonal
from geometry.errors import GeometryError
from geometry.io import read_polygon
from geometry.lennes import divide_and_conquer
from geometry.triangulate import ALGORITHMS
from story import registry
from story.pseudocode import PseudocodeRow
from story.registry import (
    REGISTRY,
    TRIANGULATION,
    correct,
    entry,
    heuristics,
    names,
    shown,
    triangulations,
    wrong,
)
from story.runs import run_logged

EARCUT = Path(__file__).parent / "data" / "earcut"
#: Outer rings of the earcut corpus up to this many vertices (larger ones take seconds each).
QUICK_RING = 250


def test_its_heuristics_are_exactly_the_ones_geometry_runs():
    """The same names in the same order, and each entry runs the heuristic of its own name:
    the first call its run traces is that heuristic (not another one's function)."""
    assert heuristics() == tuple(HEURISTICS)
    for name in heuristics():
        p = read_polygon(entry(name).polygon)
        with tracing.record() as log, tracing.alive(p):
            entry(name).function(p)
        first = next(e for e in log.events if e.kind == "call")
        assert first.name == name


def test_its_triangulations_are_exactly_the_ones_geometry_runs():
    assert triangulations() == tuple(ALGORITHMS)
    assert all(entry(n).correct for n in triangulations())


def test_names_are_heuristics_then_triangulations_spelled_as_the_command_line():
    assert names() == heuristics() + triangulations() == tuple(REGISTRY)
    assert all(re.fullmatch(r"[a-z]+(-[a-z]+)*", n) for n in names()), names()


def test_the_thesis_says_which_heuristics_are_correct():
    """Thesis ch. 2.1: the four first heuristics are wrong, their corrections and gravity
    correct; every triangulation is correct."""
    assert wrong() == ("scaling", "rotation", "rotation-ccw", "translation")
    assert correct() == ("translation-correct", "scaling-correct", "rotation-correct",
                         "scaling-walled", "gravity")
    assert correct(None) == correct() + triangulations()
    assert wrong(TRIANGULATION) == ()


#: the heuristics' names in the thesis (ch. 2.1; headings and text): its Correct Scaling is
#: both water that respects the edges and the water rising from AC
THESIS_NAMES = ("Scaling", "Rotation", "Translation", "Correct Translation", "Correct Scaling",
                "Correct Rotation", "Gravity")


@pytest.mark.parametrize("name", heuristics())
def test_every_heuristic_is_spoken_of_by_the_thesis_name(name):
    """A title says the thesis's name: "Scaling with walls" is none (the thesis calls the
    water that respects the edges Correct Scaling). Rotation the other way is the thesis's
    Rotation from C, counter-clockwise."""
    said = registry.spoken(name)
    assert said in (*THESIS_NAMES, "Rotation the other way"), said
    assert entry(name).title.startswith(f"{said}: ")


def test_the_mapping_and_entries_are_read_only():
    with pytest.raises(TypeError):
        REGISTRY["magic"] = REGISTRY["scaling"]  # type: ignore[index]  # on purpose: it must raise
    with pytest.raises(AttributeError):
        entry("scaling").correct = True  # type: ignore[misc]  # on purpose: it must raise


def test_unknown_name_is_one_line_listing_the_known_ones():
    with pytest.raises(KeyError) as info:
        entry("magic")
    message = info.value.args[0]
    assert message == f"unknown algorithm 'magic'; expected one of {', '.join(REGISTRY)}"
    assert "\n" not in message
    with pytest.raises(ValueError, match="unknown kind"):
        names("algorithm")


@pytest.mark.parametrize("name", list(REGISTRY))
def test_every_entry_is_complete(name):
    e = entry(name)
    if e.metaphor is not None:  # a module of metaphors/ that reads and performs its steps
        module = importlib.import_module(f"metaphors.{e.metaphor}")
        assert module.READS and module.PERFORMS
    assert e.title and "\n" not in e.title
    assert isinstance(e.pseudocode, tuple) and all(isinstance(s, PseudocodeRow) for s in e.pseudocode)
    assert shown(name) == e.shown
    read_polygon(e.polygon)  # a sample every command reads


@pytest.mark.parametrize("name", list(REGISTRY))
def test_the_shown_function_is_traced_in_a_run(name):
    log = run_logged(name, entry(name).polygon)
    assert log.meta["shown"] == entry(name).shown
    assert any(e.kind == "call" and e.name == entry(name).shown for e in log.events), name


@pytest.mark.parametrize("name", heuristics())
def test_a_heuristics_default_polygon_shows_whether_it_is_correct(name):
    """A wrong heuristic fails on its default polygon; a correct one does not."""
    p = read_polygon(entry(name).polygon)
    verdict = is_inner_diagonal(p, *find_diagonal(p, name).pair)
    assert bool(verdict) == entry(name).correct, (name, verdict.why)


def test_each_wrong_heuristic_has_a_correction_with_its_metaphor():
    for name in wrong():
        mend = entry(name).correction
        assert mend in correct() and entry(mend).metaphor == entry(name).metaphor, name
    assert all(entry(n).correction is None for n in correct(None))


@pytest.mark.parametrize("name", triangulations())
def test_every_triangulation_runs_through_its_function(name):
    p = read_polygon(entry(name).polygon)
    result = entry(name).function(p, "gravity")
    assert result.valid and verify_triangulation(p, result.triangles)


def _quick_rings() -> list:
    rings = []
    for path in sorted(EARCUT.glob("*.json")):
        try:
            polygon = read_polygon(path, ignore_holes=True)
        except GeometryError:  # the invalid outer rings (and earcut's table of counts)
            continue
        if polygon.n <= QUICK_RING:
            rings.append(pytest.param(polygon, id=path.stem))
    return rings


@pytest.mark.parametrize("polygon", _quick_rings())
def test_every_correct_heuristic_triangulates_the_earcut_rings(polygon):
    for name in correct():
        if polygon.n > 3:  # a triangle has no diagonal
            assert is_inner_diagonal(polygon, *find_diagonal(polygon, name).pair), name
        result = divide_and_conquer(polygon, name)
        assert result.valid and verify_triangulation(polygon, result.triangles), name


def test_the_module_lists_its_api():
    assert set(registry.__all__) <= set(vars(registry))
