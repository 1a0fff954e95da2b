"""The cards' figures (issue 22 items 2, 7 and 8): what each draws is the geometry's."""

from __future__ import annotations

import pytest

from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from geometry.predicates import orient
from metaphors.figures import KINDS, Figure, ear_tests, figure_mobjects


def named(mobjects, prefix: str) -> list:
    return [m for m in mobjects if m.name.startswith(prefix)]


def label(mobjects) -> str:
    return named(mobjects, "figure:label")[0].original_text


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("polygon", ["lecture", "counterexample", "triangle"])
def test_every_kind_draws_on_any_polygon(kind, polygon):
    """A polygon handed to the lecture may be anything valid, a triangle too."""
    heuristic = "rotation" if kind == "metaphor" else "gravity"  # a metaphor needs a tool
    drawn = figure_mobjects(Figure(kind, heuristic=heuristic, heuristics=("scaling",)), polygon)
    assert drawn and all(m.name.startswith("figure:") for m in drawn)


def test_the_triangulation_has_n_minus_2_triangles():
    p = read_polygon("lecture")
    drawn = figure_mobjects(Figure("triangulation"), "lecture")
    assert len(named(drawn, "figure:triangle")) == p.n - 2
    assert label(drawn) == f"n = {p.n}: {p.n - 2} triangles, {p.n - 3} diagonals"


def test_the_ears_are_the_convex_vertices_whose_neighbours_see_each_other():
    p = read_polygon("lecture")
    n = p.n
    ears = [p.labels[v] for v in range(n)
            if orient(p.points[v - 1], p.points[v], p.points[(v + 1) % n]) > 0
            and is_inner_diagonal(p, (v - 1) % n, (v + 1) % n)]
    drawn = figure_mobjects(Figure("ears"), "lecture")
    assert len(ears) >= 2 and len(named(drawn, "figure:ear")) == len(ears)
    assert label(drawn) == f"the ears of P: {', '.join(ears)}"


def test_claims_are_green_when_inner_and_red_with_their_crossed_edge():
    p = read_polygon("counterexample")
    wrong = figure_mobjects(Figure("claims", "counterexample", heuristics=("scaling",)), "x")
    right = figure_mobjects(Figure("claims", "counterexample",
                                   heuristics=("scaling-correct", "rotation-correct")), "x")
    verdict = is_inner_diagonal(p, *find_diagonal(p, "scaling").pair)
    edge = "–".join(p.labels[k] for k in verdict.edge)
    assert [m.trex_role for m in named(wrong, "figure:claim")] == ["rejected"]
    assert [m.name for m in named(wrong, "figure:edge")] == [f"figure:edge:{edge}"]
    # the corrections claim the same diagonal: it is drawn once, in green
    assert [m.trex_role for m in named(right, "figure:claim")] == ["result"]
    assert named(right, "figure:edge") == []


def test_the_growth_plot_counts_ear_tests_in_the_logs():
    from story.runs import run_logged

    log = run_logged("ear-clipping-naive", "random-2opt:10:1")
    assert ear_tests("ear-clipping-naive", 10) >= 1
    assert len(log.find(kind="call", name="is_ear")) >= 1
    assert ear_tests("ear-clipping-naive", 60) > ear_tests("prune-and-search", 60)


def test_an_unknown_kind_is_refused():
    with pytest.raises(ValueError, match="a figure is one of"):
        Figure("pie")


@pytest.mark.parametrize(("heuristic", "colour", "said"), [
    ("scaling", "water", "the water from B wets D first"),
    ("rotation", "hand", "the hand at B passes D first"),
    ("translation", "sweep", "the line from B touches D first"),
])
def test_a_metaphor_is_drawn_stopped_at_its_pick_without_the_red(heuristic, colour, said):
    """Issue 22 item 4: the card of a wrong heuristic draws its tool at B on the counterexample,
    stopped at the vertex it picks, what it swept in the one swept colour; that it leaves P
    (the red) is for the pass that follows, not the card."""
    from manim import ManimColor

    from metaphors.theme import THEME

    p = read_polygon("counterexample")
    drawn = figure_mobjects(Figure("metaphor", "counterexample", heuristic=heuristic), "x")
    assert label(drawn) == said
    (tool,) = named(drawn, "figure:tool")
    parts = {m.name: m for m in tool.submobjects}
    assert parts["swept"].submobjects  # a region, not the empty placeholder
    assert parts["swept"][0].get_fill_color() == ManimColor(THEME.swept)
    assert parts["tool"][0].get_stroke_color() == ManimColor(getattr(THEME, colour))
    colours = {m.get_fill_color().to_hex().lower() for m in tool.family_members_with_points()}
    assert THEME.rejected not in colours
    # the pick is marked over its vertex, where the run says the tool stops
    (pick,) = named(drawn, "figure:candidate")
    d = figure_frame(p).to_scene(p.points[p.labels.index("D")])
    assert abs(pick.get_center() - d).max() < 1e-6
    assert drawn[-1] is pick  # over the vertices' dots


def figure_frame(p):
    from metaphors.drawing import Frame
    from metaphors.figures import FIGURE_CENTER, FIGURE_HEIGHT, FIGURE_WIDTH

    return Frame(p.points, FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT)


def test_a_metaphor_needs_a_tool():
    with pytest.raises(ValueError, match="gravity: no water, clock hand or sweep line"):
        figure_mobjects(Figure("metaphor", "counterexample", heuristic="gravity"), "x")
