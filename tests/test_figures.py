"""The cards' figures (issue 22 items 2, 7 and 8): what each draws is the geometry's."""

from __future__ import annotations

from pathlib import Path

import pytest

from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from geometry.polygon import Polygon
from geometry.predicates import orient
from metaphors.drawing import Frame
from metaphors.figures import BOX, KINDS, Figure, ear_tests, figure_mobjects
from usercode.heuristic import run_heuristic


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


# --- the methods' figures (metaphors/method_figures.py) ---------------------------------------


def said(mobject) -> str:
    """A label's words, on one row or wrapped on several."""
    rows = [mobject] if hasattr(mobject, "original_text") else list(mobject)
    return " ".join(row.original_text for row in rows)


def ends(line) -> tuple[tuple[float, float], tuple[float, float]]:
    start, end = line.get_start(), line.get_end()
    return (round(start[0], 6), round(start[1], 6)), (round(end[0], 6), round(end[1], 6))


def on_screen(frame, point) -> tuple[float, float]:
    x, y, _ = frame.to_scene(point)
    return round(x, 6), round(y, 6)


def test_gravity_draws_its_run_turned_so_that_the_ball_falls_down():
    from geometry import gravity as g
    from metaphors.method_figures import TurnedFrame

    p = read_polygon("gravity-snag")
    v = g.reflex_vertex(p)
    frame = TurnedFrame(p.points, g.gravity_direction(p, v).turn_picture, *BOX)
    drawn = figure_mobjects(Figure("gravity", "gravity-snag"), "lecture")
    diagonal = g.gravity(p)
    i, j = diagonal.pair
    assert ends(named(drawn, "figure:claim")[0]) == (on_screen(frame, p.points[i]),
                                                     on_screen(frame, p.points[j]))
    assert is_inner_diagonal(p, i, j).ok and named(drawn, "figure:claim")[0].trex_role == "result"
    (x0, y0), (x1, y1) = ends(named(drawn, "figure:fall")[0])
    assert abs(x1 - x0) < 1e-6 and y1 < y0  # the turn makes gravity point down on screen
    assert said(named(drawn, "figure:label")[0]).endswith(f"claim {diagonal.name}")
    assert "Y = " in said(named(drawn, "figure:label")[0])  # gravity-snag: the band snags


def test_prune_draws_an_inner_diagonal_that_keeps_at_most_half_and_one():
    from metaphors.method_figures import prune_rounds

    p = read_polygon("lecture")
    drawn = figure_mobjects(Figure("prune"), "lecture")
    scene = {on_screen(Frame(p.points, *BOX), q): k for k, q in enumerate(p.points)}
    a, b = (scene[q] for q in ends(named(drawn, "figure:diagonal")[0]))
    assert is_inner_diagonal(p, a, b).ok
    good, smaller = (len(named(drawn, n)[0].get_vertices()) for n in ("figure:good",
                                                                       "figure:smaller"))
    assert smaller <= good // 2 + 1
    g, v, _ = prune_rounds(p)[0]
    marked = named(drawn, "figure:candidate")[0].get_center()
    assert on_screen(Frame(p.points, *BOX), p.points[v]) == (round(marked[0], 6),
                                                            round(marked[1], 6))
    assert g.vertex_at(g.middle()).index == v


def test_every_bridge_joins_a_holes_rightmost_vertex_to_a_vertex_it_sees():
    from shapely.geometry import LineString
    from shapely.geometry import Polygon as Region

    from geometry.io import read_shape

    shape = read_shape("keyhole")
    rings = [shape.points[a:b] for a, b in zip(shape.starts, shape.starts[1:], strict=False)]
    region = Region(rings[0], rings[1:])
    # the outer ring drawn on its own keeps the shape's labels, which the bridges name
    outer = Polygon.from_points(rings[0])
    assert outer.labels == shape.labels[:shape.starts[1]]
    drawn = figure_mobjects(Figure("keyhole", "keyhole"), "lecture")
    bridges = named(drawn, "figure:bridge:")
    assert len(bridges) == shape.hole_count
    points = {shape.labels[k]: shape.points[k] for k in range(shape.n)}
    rightmost = {max(ring)[0] for ring in rings[1:]}
    for bridge in bridges:
        p, m = bridge.name.removeprefix("figure:bridge:").split("–")
        assert points[p][0] in rightmost and shape.ring_of(shape.labels.index(p)) > 0
        assert region.contains(LineString([points[p], points[m]]))  # P sees M, inside P


def test_the_rule_is_drawn_with_its_claim_green_when_inner_red_when_not():
    path = Path(__file__).resolve().parents[1] / "examples" / "nearest_to_c.py"
    rule = f"{path}:nearest_to_c"
    lecture = figure_mobjects(Figure("rule", heuristic=rule), "lecture")
    p = read_polygon("lecture")
    i, j = run_heuristic(p, rule).pair
    assert named(lecture, "figure:claim")[0].trex_role == (
        "result" if is_inner_diagonal(p, i, j).ok else "rejected")
    assert said(named(lecture, "figure:label")[0]).startswith(
        f"On this P the rule claims {p.labels[i]}{p.labels[j]}")
    wrong = figure_mobjects(Figure("rule", "counterexample", heuristic="scaling"), "x")
    assert named(wrong, "figure:claim")[0].trex_role == "rejected"
    assert len(named(wrong, "figure:edge:")) == 1
