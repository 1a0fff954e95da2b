"""The cards' figures (issue 22 items 2, 7 and 8): what each draws is the geometry's."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from geometry.polygon import Polygon
from geometry.predicates import orient
from metaphors.drawing import Frame
from metaphors.figures import BOX, KINDS, Figure, ear_tests, figure_mobjects
from metaphors.tags import tag
from usercode.heuristic import run_heuristic


def named(mobjects, prefix: str) -> list:
    return [m for m in mobjects if m.name.startswith(prefix)]


def label(mobjects) -> str:
    """The words of a figure's caption, its rows joined (a caption is a group of rows)."""
    return " ".join(row.original_text for row in named(mobjects, "figure:label")[0])


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
    assert label(drawn) == f"n = {p.n}: {p.n - 2} triangles, {p.n - 3} inner diagonals"


def test_the_ears_are_the_convex_vertices_whose_neighbours_see_each_other():
    p = read_polygon("lecture")
    n = p.n
    ears = [p.labels[v] for v in range(n)
            if orient(p.points[v - 1], p.points[v], p.points[(v + 1) % n]) > 0
            and is_inner_diagonal(p, (v - 1) % n, (v + 1) % n)]
    drawn = figure_mobjects(Figure("ears"), "lecture")
    assert len(ears) >= 2 and len(named(drawn, "figure:ear")) == len(ears)
    assert label(drawn).startswith(f"the ears of P: {', '.join(ears)} ")


def test_the_ears_card_draws_two_ears_that_do_not_overlap():
    """Review s34: the card says "two ears that do not overlap"; all seven ears in one green
    overlapped (E and F, I and J). Two of them are drawn strong, named, and do not overlap."""
    from shapely.geometry import Polygon as Region

    drawn = figure_mobjects(Figure("ears"), "lecture")
    two = [Region([tuple(p[:2]) for p in t.get_vertices()])
           for t in named(drawn, "figure:two-ears")]
    assert len(two) == 2 and two[0].intersection(two[1]).area < 1e-6
    said = label(drawn).partition("two that do not overlap: ")[2]
    assert len(said.split(" and ")) == 2


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


def test_the_growth_plot_says_what_its_numbers_are():
    """Chapter 4's "How fast": 10, 60 and 235 were never said to be vertices and ear tests."""
    from metaphors.figures import GROWTH_SIZES
    from tests.reading_rules import unnamed_axes

    drawn = figure_mobjects(Figure("growth"), "lecture")
    (across,), (up,) = named(drawn, "figure:x-name"), named(drawn, "figure:y-name")
    assert across.original_text == "vertices n" and "ear tests (is V an ear?)" in up.original_text
    assert f"ear tests at n = {GROWTH_SIZES[-1]}" in label(drawn)
    shown = {"plays": [{"animations": [{"type": "FadeIn", "mobject": {"name": m.name}}
                                       for m in drawn]}]}
    assert unnamed_axes(shown) == []
    unnamed = {"plays": [{"animations": [{"type": "FadeIn", "mobject": {"name": m.name}}
                                         for m in drawn if not m.name.endswith("-name")]}]}
    assert unnamed_axes(unnamed) == ["play 0 figure:x-name missing", "play 0 figure:y-name missing"]


def test_an_unknown_kind_is_refused():
    with pytest.raises(ValueError, match="a figure is one of"):
        Figure("pie")


@pytest.mark.parametrize(("heuristic", "colour", "said"), [
    ("scaling", "water", "the water from B wets D first"),
    ("rotation", "hand", "the hand at B passes D first"),
    ("translation", "sweep", "the line from B touches D first"),
])
def test_a_metaphor_is_drawn_on_its_way_without_the_red(heuristic, colour, said):
    """Issue 22 item 4: the card of a wrong heuristic draws its tool at B on the counterexample,
    on its way, what it swept in the one swept colour; where it stops (the pick) and that it
    leaves P (the red) are for the pass that follows, not the card: drawn on to its pick,
    the pass showed the same run twice."""
    import shapely
    from manim import ManimColor

    from metaphors.theme import THEME

    p = read_polygon("counterexample")
    from metaphors.drawing import Frame
    from metaphors.figure_metaphors import metaphor_parts
    from metaphors.figures import FIGURE_CENTER, FIGURE_HEIGHT, FIGURE_WIDTH

    drawn = figure_mobjects(Figure("metaphor", "counterexample", heuristic=heuristic), "x")
    # the words are the bullets' (one at a time), not a line under the figure beside them
    assert not named(drawn, "figure:label")
    frame = Frame(read_polygon("counterexample").points, FIGURE_CENTER, FIGURE_WIDTH,
                  FIGURE_HEIGHT)
    assert metaphor_parts(heuristic, "counterexample", frame, THEME)[2] == said
    (tool,) = named(drawn, "figure:tool")
    parts = {m.name: m for m in tool.submobjects}
    assert parts["swept"].submobjects  # a region, not the empty placeholder
    assert parts["swept"][0].get_fill_color() == ManimColor(THEME.swept)
    assert parts["tool"][0].get_stroke_color() == ManimColor(getattr(THEME, colour))
    colours = {m.get_fill_color().to_hex().lower() for m in tool.family_members_with_points()}
    assert THEME.rejected not in colours
    # no pick marked, and the tool short of every candidate (D and E), which keep their
    # pink marks: the water's edge, the hand or the line passes through neither
    assert not named(drawn, "figure:pick")
    marks = named(drawn, "figure:candidate")
    assert len(marks) == 2 and {m.get_color() for m in marks} == {ManimColor(THEME.candidate)}
    drawn_tool = shapely.union_all([shapely.LineString([q[:2] for q in m.get_anchors()])
                                    for m in parts["tool"].family_members_with_points()])
    for label in ("D", "E"):
        at = figure_frame(p).to_scene(p.points[p.labels.index(label)])
        assert drawn_tool.distance(shapely.Point(at[:2])) > 0.05, label


def figure_frame(p):
    from metaphors.drawing import Frame
    from metaphors.figures import FIGURE_CENTER, FIGURE_HEIGHT, FIGURE_WIDTH

    return Frame(p.points, FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT)


def test_a_metaphor_needs_a_tool():
    with pytest.raises(ValueError, match="gravity: no water, clock hand or sweep line"):
        figure_mobjects(Figure("metaphor", "counterexample", heuristic="gravity"), "x")


# --- the methods' figures (metaphors/method_figures.py) ---------------------------------------


def said(mobject) -> str:
    """A caption's words, its rows joined."""
    return " ".join(row.original_text for row in mobject)


def ends(line) -> tuple[tuple[float, float], tuple[float, float]]:
    start, end = line.get_start(), line.get_end()
    return (round(start[0], 6), round(start[1], 6)), (round(end[0], 6), round(end[1], 6))


def on_screen(frame, point) -> tuple[float, float]:
    x, y, _ = frame.to_scene(point)
    return round(x, 6), round(y, 6)


def test_gravity_draws_its_rule_turned_not_its_runs_answer():
    """grav7: the card draws P turned so that gravity points down and the ball hanging at V,
    not the run's fall, slide, band and claim: it drew the finished picture and said "claim
    CH" before the run played the same example (chapter 3: told three times)."""
    from geometry import gravity as g
    from metaphors.method_figures import TurnedFrame

    p = read_polygon("gravity-snag")
    v = g.reflex_vertex(p)
    frame = TurnedFrame(p.points, g.gravity_direction(p, v).turn_picture, *BOX)
    drawn = figure_mobjects(Figure("gravity", "gravity-snag"), "lecture")
    assert not any(named(drawn, name) for name in ("figure:claim", "figure:fall",
                                                   "figure:slide", "figure:band"))
    ball = named(drawn, "figure:ball")[0].get_center()
    assert on_screen(frame, v.point) == (round(ball[0], 6), round(ball[1], 6))
    words = said(named(drawn, "figure:label")[0])
    assert words == f"V = {v.label}: the ball hangs here" and "claim" not in words
    (x0, y0), (x1, y1) = ends(named(drawn, "figure:gravity")[0][0])
    assert abs(x1 - x0) < 1e-6 and y1 < y0  # the arrow points down on screen


def test_prune_poses_its_question_without_the_answer():
    """The card marks the first round's middle vertex and draws no diagonal, no good
    sub-polygon and no ear: the run shows them once (the card drew GB and E's ear, and the
    run drew them again, chapter 4)."""
    from metaphors.method_figures import prune_rounds

    p = read_polygon("lecture")
    drawn = figure_mobjects(Figure("prune"), "lecture")
    for part in ("figure:diagonal", "figure:good", "figure:ear", "figure:cut"):
        assert named(drawn, part) == [], part
    g, v, _ = prune_rounds(p)[0]
    marked = named(drawn, "figure:step")[0].get_center()
    assert on_screen(Frame(p.points, *BOX), p.points[v]) == (round(marked[0], 6),
                                                            round(marked[1], 6))
    assert g.vertex_at(g.middle()).index == v


def test_the_keyhole_card_marks_each_holes_rightmost_vertex_and_cuts_nothing():
    """The card marks where each cut starts, a hole's right-most vertex, and draws no bridge:
    the run cuts them (the card drew both, and the run cut them again, chapter 4)."""
    from manim import ManimColor

    from geometry.io import read_any_polygon
    from metaphors.theme import THEME

    shape = read_any_polygon("keyhole")
    rings = [shape.points[a:b] for a, b in zip(shape.starts, shape.starts[1:], strict=False)]
    # the outer ring drawn on its own keeps the shape's labels
    outer = Polygon.from_points(rings[0])
    assert outer.labels == shape.labels[:shape.starts[1]]
    drawn = figure_mobjects(Figure("keyhole", "keyhole"), "lecture")
    assert named(drawn, "figure:bridge:") == []
    frame = Frame(outer.points, *BOX)
    marked = {tuple(round(x, 6) for x in m.get_center()[:2]) for m in named(drawn, "figure:step")}
    rightmost = {on_screen(frame, max(ring)) for ring in rings[1:]}
    assert marked == rightmost and len(marked) == shape.hole_count
    (fruit,) = named(drawn, "figure:polygon")
    assert fruit.get_fill_color() == ManimColor(THEME.fruit)


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


# --- the faster algorithms' cards and the recap (metaphors/figure_faster.py) -------------------


def _higher(p, i):
    """The monotone sweep's order: larger y, then smaller x."""
    x, y = p.points[i]
    return (y, -x)


def _y_monotone(p, ids) -> bool:
    """Whether the closed chain ``ids`` goes down once and up once in the sweep's order: one
    local top and one local bottom."""
    keys = [_higher(p, i) for i in ids]
    k = len(keys)
    tops = sum(1 for j in range(k) if keys[j] > keys[j - 1] and keys[j] > keys[(j + 1) % k])
    bottoms = sum(1 for j in range(k) if keys[j] < keys[j - 1] and keys[j] < keys[(j + 1) % k])
    return tops == bottoms == 1


def _vertices(mobject):
    import numpy as np

    return np.round(np.asarray(mobject.get_vertices())[:, :2], 6).tolist()


def _scene(frame, points):
    import numpy as np

    return np.round(np.asarray(frame.many(points))[:, :2], 6).tolist()


@pytest.mark.parametrize("polygon", ["lecture", "counterexample", "random-2opt:30:4"])
def test_the_monotone_pieces_are_y_monotone_and_cover_p(polygon):
    import numpy as np
    import shapely

    from geometry.check import is_inner_diagonal
    from geometry.predicates import signed_area2
    from metaphors.drawing import Frame
    from metaphors.figure_faster import monotone_partition
    from metaphors.figures import FIGURE_CENTER, FIGURE_HEIGHT, FIGURE_WIDTH

    p = read_polygon(polygon)
    cut = monotone_partition(p)
    assert all(_y_monotone(p, piece) for piece in cut.pieces)
    assert all(is_inner_diagonal(p, u, w) for u, w in cut.diagonals)
    # the pieces tile P: their areas add up to P's, exactly, and there is one more piece
    # than there are diagonals
    assert sum(signed_area2([p.points[k] for k in piece]) for piece in cut.pieces) \
        == signed_area2(list(p.points))
    assert len(cut.pieces) == len(cut.diagonals) + 1
    # the split and merge vertices, found again from the definition (both neighbours lower,
    # or both higher, and reflex)
    n = p.n
    reflex = [v for v in range(n) if orient(p.points[v - 1], p.points[v], p.points[(v + 1) % n]) < 0]
    lower = [v for v in reflex if _higher(p, v) > max(_higher(p, v - 1), _higher(p, (v + 1) % n))]
    upper = [v for v in reflex if _higher(p, v) < min(_higher(p, v - 1), _higher(p, (v + 1) % n))]
    assert sorted(cut.split) == lower and sorted(cut.merge) == upper
    drawn = figure_mobjects(Figure("monotone-pieces"), polygon)
    frame = Frame(p.points, FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT)
    pieces = named(drawn, "figure:piece")
    assert [_vertices(m) for m in pieces] == [_scene(frame, [p.points[k] for k in piece])
                                              for piece in cut.pieces]
    assert len(named(drawn, "figure:diagonal")) == len(cut.diagonals)
    # mono5: no kind of vertex marked (the card named split and merge 12 s before the run
    # taught them), never the red of what fails; what y-monotone means is drawn instead: a
    # horizontal line meeting P in two segments or more, each inside P, and meeting each
    # piece in one segment at most
    assert not named(drawn, "figure:kink")
    assert not [m for m in drawn if getattr(m, "trex_role", None) == "rejected"]
    (_,), segments = named(drawn, "figure:level-line"), named(drawn, "figure:level-segment")
    assert len(segments) >= 2
    region = shapely.Polygon(frame.many(p.points))
    for segment in segments:
        a, b = (tuple(np.asarray(end)[:2]) for end in (segment.get_start(), segment.get_end()))
        assert a[1] == pytest.approx(b[1])
        assert region.buffer(1e-6).contains(shapely.LineString([a, b]))
    y = float(np.asarray(segments[0].get_start())[1])
    across = shapely.LineString([(-20, y), (20, y)])
    for piece in cut.pieces:
        met = across.intersection(shapely.Polygon(frame.many([p.points[k] for k in piece])))
        assert len(getattr(met, "geoms", [met])) <= 1 or met.is_empty


def test_the_lecture_polygon_needs_diagonals_at_its_split_and_merge_vertices():
    drawn = figure_mobjects(Figure("monotone-pieces"), "lecture")
    caption = named(drawn, "figure:label")[0]
    assert [line.original_text for line in caption] == [
        "This line meets P in 2 segments:", "P is not y-monotone"]


def _profiled_sign_tests(run) -> int:
    """The sign tests counted another way: every call watched (sys.setprofile), the tests
    known by their code, the monotone sweep's bisection replayed from its result."""
    import sys

    from geometry import batch, predicates, validate
    from geometry.sweep_status import SweepStatus

    one = {f.__code__ for f in (predicates.orient, predicates.dot_sign,
                                predicates.compare_distance, predicates.compare_line_distance,
                                predicates.compare_angle)}
    many = {batch.orient_many.__code__: "xs", batch.dot_sign_many.__code__: "starts",
            validate.orient_array.__code__: "c"}
    total, depth = 0, 0

    def watch(frame, event, arg):
        nonlocal total, depth
        code = frame.f_code
        if event == "call" and (code in one or code in many):
            total += (1 if code in one else len(frame.f_locals[many[code]])) if not depth else 0
            depth += 1
        elif event == "return" and (code in one or code in many):
            depth -= 1
        elif event == "return" and code is SweepStatus.find.__code__ and not depth:
            total += frame.f_locals["self"].tests_made(frame.f_locals["own"], arg)

    sys.setprofile(watch)
    try:
        run()
    finally:
        sys.setprofile(None)
    return total


@pytest.mark.parametrize("algorithm", ["divide-and-conquer", "ear-clipping", "monotone",
                                       "ear-clipping-naive", "prune-and-search"])
@pytest.mark.parametrize("polygon", ["lecture", "random-2opt:40:2", "comb"])
def test_sign_tests_are_counted_alike_by_watching_every_call(algorithm, polygon):
    """The predicates' own count misses no test: every call watched finds as many."""
    from story.sign_tests import ALGORITHMS, count_sign_tests

    p = read_polygon(polygon)
    run = ALGORITHMS[algorithm]
    counted = count_sign_tests(lambda: run(p.sub_polygon(range(p.n))))
    assert counted == _profiled_sign_tests(lambda: run(p.sub_polygon(range(p.n)))) > 0


def test_a_sign_test_is_one_orientation_or_one_point_of_a_batch():
    import numpy as np

    import geometry.ears
    from geometry import batch, predicates
    from story.sign_tests import count_sign_tests

    a, b, c = (0.0, 0.0), (4.0, 0.0), (0.0, 4.0)
    assert count_sign_tests(lambda: predicates.orient(a, b, c)) == 1
    # a test made of tests: its own four orientations (the triangle's turn, then three)
    assert count_sign_tests(lambda: predicates.in_triangle((1.0, 1.0), a, b, c)) == 4
    xs, ys = np.array([0.1, 2.0, 0.3, 2.0]), np.array([0.1, 0.0, 0.3, 1e-300])
    # four points, one on the edge and one decided exactly: four tests, none counted twice
    assert count_sign_tests(lambda: batch.orient_many(a, b, xs, ys)) == 4
    assert count_sign_tests(lambda: batch.in_triangle_many(a, b, c, xs, ys)) >= 4
    # nothing is rebound: the geometry calls the predicates themselves, counting or not
    assert geometry.ears.orient is predicates.orient and batch.orient is predicates.orient
    # closed, nothing counts any more
    with predicates.counting_sign_tests() as tests:
        pass
    predicates.orient(a, b, c)
    assert tests.total == 0 and predicates.counts_open == 0


def test_a_count_of_sign_tests_is_of_its_own_thread_only():
    """A count open in one thread takes none of another thread's tests, counted or not,
    and a run counted while another thread counts counts as it does alone. The threads take
    turns by events, so the tests of both fall inside the other's count every time."""
    import threading

    from geometry import predicates
    from story.sign_tests import ALGORITHMS, count_sign_tests

    p = read_polygon("random-2opt:40:2")
    alone = count_sign_tests(lambda: ALGORITHMS["monotone"](p.sub_polygon(range(p.n))))
    a, b, c = (0.0, 0.0), (4.0, 0.0), (0.0, 4.0)
    opened, done = threading.Event(), threading.Event()
    other: list[int] = []

    def counting_beside() -> None:  # one test, then the main thread's turn, then one more
        with predicates.counting_sign_tests() as tests:
            predicates.orient(a, b, c)
            opened.set()
            done.wait(timeout=60)
            predicates.orient(a, b, c)
        other.append(tests.total)

    beside = threading.Thread(target=counting_beside)
    beside.start()
    try:
        opened.wait(timeout=60)
        ALGORITHMS["monotone"](p.sub_polygon(range(p.n)))  # not counted: in no count
        counted = count_sign_tests(lambda: ALGORITHMS["monotone"](p.sub_polygon(range(p.n))))
    finally:
        done.set()
        beside.join()
    assert (counted, other) == (alone, [2])


def _corners(line):
    """The points a line through corners (``set_points_as_corners``) was drawn through."""
    import numpy as np

    return np.vstack([line.get_start_anchors(), line.get_end_anchors()[-1:]])


def _plotted_counts(drawn, prefix):
    """The counts a log-log plot draws, read back from its lines and its axes: the corner
    is (first size, the decade below the least count), the y axis ends at the top count."""
    import math

    import numpy as np

    from metaphors.figure_faster import measured_series
    from metaphors.theme import THEME

    series = measured_series(THEME)
    top = max(max(s.counts) for s in series)
    low = 10.0 ** math.floor(math.log10(min(min(s.counts) for s in series)))
    _, y_axis = named(drawn, "figure:axis")
    y0, y1 = np.asarray(y_axis.get_start())[1], np.asarray(y_axis.get_end())[1]
    read = {}
    for line in named(drawn, prefix):
        ys = _corners(line)[:, 1]
        read[line.name[len(prefix):]] = [round(low * (top / low) ** ((y - y0) / (y1 - y0)))
                                         for y in ys]
    return read


def test_the_measured_plot_draws_the_sign_tests_counted_in_real_runs():
    from metaphors.figure_faster import MEASURED_RUNS, MEASURED_SHAPE, MEASURED_SIZES
    from story.sign_tests import ALGORITHMS, SEEDS, count_sign_tests, measured

    drawn = figure_mobjects(Figure("measured"), "lecture")
    plotted = _plotted_counts(drawn, "figure:measured:")
    assert plotted == {name: [measured(name, n, MEASURED_SHAPE) for n in MEASURED_SIZES]
                       for name in MEASURED_RUNS}
    # a count on random polygons (said on the card) is a mean over runs: one counted again
    # here; on a half disc, its one run
    polygons = [read_polygon(f"random-2opt:20:{seed}") for seed in SEEDS]
    runs = [count_sign_tests(lambda p=p: ALGORITHMS["monotone"](p)) for p in polygons]
    assert measured("monotone", 20) == round(sum(runs) / len(runs))
    disc = read_polygon("half-disc:20")
    assert measured("ear-clipping", 20, "half-disc") == count_sign_tests(
        lambda: ALGORITHMS["ear-clipping"](disc))
    # measured lines only, solid: no bound drawn (their shapes crowded the plot)
    assert not named(drawn, "figure:bound:")
    assert all(type(m).__name__ != "DashedVMobject" for m in named(drawn, "figure:measured:"))
    # the axes named in plain words (r567: unnamed)
    (across,), (up,) = named(drawn, "figure:x-name"), named(drawn, "figure:y-name")
    assert across.original_text == "vertices n" and up.original_text.startswith("steps (")
    assert "sign tests" not in label(drawn)
    # each line wears its own marks, one at each size
    points = named(drawn, "figure:point")
    assert len(points) == len(MEASURED_RUNS) * len(MEASURED_SIZES)
    assert len({type(m).__name__ for m in points}) == len(MEASURED_RUNS)


def test_the_measured_plot_names_each_line_beside_it_in_no_roles_colour():
    """Teacher review (faster9): the plot's six lines (two algorithms on two kinds of polygon,
    two dashed bounds) and its legend table were crowded, and its lines took the palette's
    teal and tan (the pieces' tints) and a blue by the called blue. Now two lines, the half
    discs', in the ink, each named beside itself (nearer its own line than the other's, and
    crossing neither), the ticks in the ink, what was counted said under the axis with the
    half disc drawn."""
    import numpy as np
    from shapely.geometry import LineString
    from shapely.geometry import box as rectangle

    from metaphors.figure_faster import MEASURED_RUNS
    from metaphors.layout import area_of
    from metaphors.theme import THEME
    from story.registry import spoken

    drawn = figure_mobjects(Figure("measured"), "lecture")
    lines = {m.name.removeprefix("figure:measured:"): LineString(_corners(m)[:, :2])
             for m in named(drawn, "figure:measured:")}
    assert all(m.get_stroke_color().to_hex().lower() == THEME.ink.lower()
               for m in named(drawn, "figure:measured:"))
    names = {m.original_text: rectangle(*area_of(m)) for m in named(drawn, "figure:series-name")}
    assert set(names) == {spoken(name) for name in MEASURED_RUNS}
    for name in MEASURED_RUNS:
        own, other = lines[name], next(v for k, v in lines.items() if k != name)
        shape = names[spoken(name)]
        assert not shape.intersects(own) and not shape.intersects(other), name
        assert shape.distance(own) < 0.3 < shape.distance(other), name
    ticks = named(drawn, "figure:tick")
    assert ticks and all(np.allclose(t.get_fill_color().to_rgb(), np.array(
        [int(THEME.ink[k:k + 2], 16) / 255 for k in (1, 3, 5)]), atol=0.01) for t in ticks)
    assert named(drawn, "figure:icon") and named(drawn, "figure:counted-on")


def test_the_measured_plot_shows_what_its_card_says():
    """mono5: the card sets faster ear clipping's O(n²) against monotone partition's
    O(n log n), and its plot showed both at about 700 steps at n = 160, slope 1 (random
    polygons only, unsaid). Now, on the half discs it names, ear clipping's count grows
    about fourfold when n doubles and monotone partition's about twofold; the plot and the
    card's words name the polygons counted, and the card says the random polygons' result is
    not drawn."""
    from metaphors.figure_faster import MEASURED_SIZES
    from metaphors.lecture import Card
    from story.sign_tests import measured
    from trex.chapters import lecture_chapters
    from trex.render_command import load_scene_class

    def growth(name: str, shape: str) -> float:
        return measured(name, MEASURED_SIZES[-1], shape) / measured(name, MEASURED_SIZES[-2], shape)

    assert growth("ear-clipping", "half-disc") > 3.5
    assert growth("monotone", "half-disc") < 2.5 and growth("monotone", "random-2opt") < 2.5
    drawn = figure_mobjects(Figure("measured"), "lecture")
    (counted,) = named(drawn, "figure:counted-on")
    assert "half discs" in counted.original_text
    chapter = next(c for c in lecture_chapters() if c.slug == "faster")
    cls = load_scene_class(Path(__file__).resolve().parents[1] / chapter.scene_file,
                           chapter.scene_class)
    card = next(s for s in cls.__new__(cls).chapter_segments()
                if isinstance(s, Card) and s.figure == Figure("measured"))
    words = " ".join(card.lines)
    assert all(said in words for said in ("dented half discs", "random polygons, not drawn",
                                           "n²", "n log n"))
    assert "dashed" not in words  # no bound drawn


def test_the_growth_plot_still_counts_ear_tests_after_sharing_its_plot():
    from metaphors.figures import GROWTH_RUNS, GROWTH_SIZES

    drawn = figure_mobjects(Figure("growth"), "lecture")
    top = max(ear_tests(name, n) for name, _ in GROWTH_RUNS for n in GROWTH_SIZES)
    _, y_axis = named(drawn, "figure:axis")
    y0, y1 = y_axis.get_start()[1], y_axis.get_end()[1]
    for name, _ in GROWTH_RUNS:
        (line,) = [m for m in drawn if m.name == f"figure:growth:{name}"]
        drawn_counts = [round(top * (y - y0) / (y1 - y0)) for y in _corners(line)[:, 1]]
        assert drawn_counts == [ear_tests(name, n) for n in GROWTH_SIZES]


@pytest.mark.parametrize("polygon", ["lecture", "counterexample", "comb", "random-2opt:25:7"])
def test_every_constrained_delaunay_circle_holds_no_vertex_seen_from_its_triangle(polygon):
    """The card's words, checked on every triangle: a vertex inside a triangle's circle
    is hidden from the whole triangle by P's edges."""
    from fractions import Fraction

    import shapely

    from geometry.cdt import constrained_delaunay
    from geometry.visibility import visible_region
    from metaphors.figure_faster import circumcircle

    p = read_polygon(polygon)
    for t in constrained_delaunay(p):
        circle = circumcircle(p, t)
        cx, cy = circle.centre
        assert all((Fraction(x) - cx) ** 2 + (Fraction(y) - cy) ** 2 == circle.radius2
                   for x, y in (p.points[k] for k in t))
        triangle = shapely.Polygon([p.points[k] for k in t])
        for k in circle.inside:
            assert visible_region(p, k).intersection(triangle).area < 1e-9 * triangle.area, \
                (polygon, t, k)


def test_the_delaunay_figure_draws_the_circle_of_one_triangle_and_what_it_holds():
    import numpy as np

    from geometry.cdt import constrained_delaunay
    from metaphors.figure_faster import shown_circle
    from metaphors.theme import THEME

    p = read_polygon("lecture")
    circle = shown_circle(p, THEME, BOX).circle
    assert circle.triangle in constrained_delaunay(p)
    drawn = figure_mobjects(Figure("delaunay-circle"), "lecture")
    (ring,) = named(drawn, "figure:circumcircle")
    (chosen,) = named(drawn, "figure:delaunay")
    corners = chosen.get_vertices()
    centre = ring.get_center()
    radii = [np.linalg.norm(corner - centre) for corner in corners]
    assert max(radii) - min(radii) < 1e-6 and abs(radii[0] - ring.width / 2) < 1e-3
    hidden = named(drawn, "figure:hidden")
    assert len(hidden) == len(circle.inside)
    assert all(np.linalg.norm(m.get_center() - centre) < radii[0] for m in hidden)
    assert len(named(drawn, "figure:triangle")) == p.n - 2
    name = "".join(p.labels[k] for k in circle.triangle)
    caption = " ".join(line.original_text for line in named(drawn, "figure:label")[0])
    assert name in caption and all(p.labels[k] in caption for k in circle.inside)


def labels_on_lines(markers, ring, triangles) -> list[str]:
    """The vertex labels of the Delaunay figure nearer than the labels' margin
    (:data:`metaphors.labels.EDGE_MARGIN`) to its circle or to a triangle's side, as
    ``"K × circle"``, ``"G × triangle"``."""
    import shapely

    from metaphors.labels import EDGE_MARGIN

    circle = shapely.Point(ring.get_center()[:2]).buffer(ring.width / 2, 256).exterior
    sides = [shapely.LinearRing([v[:2] for v in t.get_vertices()]) for t in triangles]
    found = []
    for marker in markers:
        text = marker[1]
        box = shapely.box(*text.get_corner([-1, -1, 0])[:2], *text.get_corner([1, 1, 0])[:2])
        name = text.original_text
        found += [f"{name} × circle"] * (box.distance(circle) < EDGE_MARGIN - 1e-6)
        found += [f"{name} × triangle"] * any(box.distance(s) < EDGE_MARGIN - 1e-6
                                               for s in sides)
    return found


def test_the_delaunay_figure_s_labels_keep_clear_of_its_circle_and_triangles(monkeypatch):
    """Review s567: "K" stood on the circle, "G" on edge G–C and "F" touched the circle: the
    labels were placed clear of P's edges only (the old placement, below, is seen); and a
    circle whose labels find no clear place is passed over (HKM's ran along M's label)."""
    import metaphors.figure_faster as faster
    from metaphors.labels import placed_vertex_markers
    from metaphors.theme import THEME

    drawn = figure_mobjects(Figure("delaunay-circle"), "lecture")
    (ring,) = named(drawn, "figure:circumcircle")
    triangles = named(drawn, "figure:triangle")
    (vertices,) = named(drawn, "figure:vertices")
    assert labels_on_lines(vertices, ring, triangles) == []
    # the circle of DFG, drawn before review s35, its labels placed clear of edges only
    monkeypatch.setattr(faster, "clear_of_rim", lambda polygon, circle: True)
    monkeypatch.setattr(faster, "_labels_clear", lambda polygon, figure: True)
    old_figure = figure_mobjects(Figure("delaunay-circle"), "lecture")
    (old_ring,) = named(old_figure, "figure:circumcircle")
    circle = faster.shown_circle(read_polygon("lecture"), THEME, BOX)
    old = placed_vertex_markers(read_polygon("lecture"), circle.frame, THEME)
    assert {"K × circle", "G × triangle"} <= set(labels_on_lines(old, old_ring, triangles))
    # and M, whose mark sat on the line, was said to be only just inside
    assert "M (just)" in label(old_figure)
    # the circle drawn now is the first whose labels find clear places, each by its own dot:
    # on the lecture polygon in general position, HKM's
    monkeypatch.undo()
    shown = figure_mobjects(Figure("delaunay-circle"), "lecture")
    assert label(shown).startswith("the circle of HKM")
    (rim,) = named(shown, "figure:circumcircle")
    (marks,) = named(shown, "figure:vertices")
    assert labels_on_lines(marks, rim, named(shown, "figure:triangle")) == []
    assert labels_by_other_dots(marks) == []
    # CDG's, drawn before: no room by G on its rim, G's label stood above H's dot (chapter 5
    # at 154 s: "the circle of CDG" named a G the viewer found at H)
    p = read_polygon("lecture")
    cdg = next(c for c in faster.ranked_circles(p)
               if "".join(p.labels[k] for k in c.triangle) == "CDG")
    assert "G" in labels_by_other_dots(faster.circle_figure(p, cdg, THEME, BOX).markers)


def labels_by_other_dots(markers) -> list[str]:
    """The labels (without a leader) nearer another vertex's dot than their own."""
    import shapely

    dots = [shapely.Point(*marker[0].get_center()[:2]) for marker in markers]
    found = []
    for k, marker in enumerate(markers):
        text = marker[1]
        box = shapely.box(*text.get_corner([-1, -1, 0])[:2], *text.get_corner([1, 1, 0])[:2])
        if len(marker) == 2 and any(box.distance(dot) < box.distance(dots[k])
                                    for j, dot in enumerate(dots) if j != k):
            found.append(text.original_text)
    return found


def dots_near_the_rim(drawn) -> list[str]:
    """The vertex dots of the Delaunay figure, off its triangle, nearer its circle than
    :data:`metaphors.figure_faster.CLEAR_OF_RIM` of its radius, as ``"M 0.05 inside"``: a dot
    on the line is read as neither in nor out."""
    import numpy as np

    from metaphors.figure_faster import CLEAR_OF_RIM

    (ring,) = named(drawn, "figure:circumcircle")
    (chosen,) = named(drawn, "figure:delaunay")
    (vertices,) = named(drawn, "figure:vertices")
    centre, r = ring.get_center(), ring.width / 2
    corners = chosen.get_vertices()
    found = []
    for marker in vertices:
        at = marker[0].get_center()
        if min(np.linalg.norm(at - c) for c in corners) < 1e-3:
            continue
        off = float(np.linalg.norm(at - centre)) / r - 1
        if abs(off) < CLEAR_OF_RIM:
            found.append(f"{marker[1].original_text} {abs(off):.2f} "
                         f"{'inside' if off < 0 else 'outside'}")
    return found


def test_the_delaunay_figure_s_vertices_stand_clear_inside_or_outside_its_circle(monkeypatch):
    """Review s35: M's dot lay on the circle of DFG, 5 % of its radius inside; every vertex
    shown stands 15 % of the radius in or out (the old choice, forced below, is seen)."""
    import metaphors.figure_faster as faster

    assert dots_near_the_rim(figure_mobjects(Figure("delaunay-circle"), "lecture")) == []
    monkeypatch.setattr(faster, "clear_of_rim", lambda polygon, circle: True)
    assert dots_near_the_rim(figure_mobjects(Figure("delaunay-circle"), "lecture")) == [
        "M 0.05 inside"]


def test_the_recap_draws_each_algorithm_s_own_triangulation_under_the_bound_its_line_says():
    from pathlib import Path

    from geometry.check import verify_triangulation
    from metaphors.figure_faster import RECAPPED, recap_triangulations
    from metaphors.lecture import Card
    from story.registry import spoken
    from trex.chapters import lecture_chapters
    from trex.render_command import load_scene_class

    p = read_polygon("lecture")
    results = recap_triangulations(p)
    assert [(name, bound) for name, bound, _ in results] == list(RECAPPED)
    assert all(len(t) == p.n - 2 and verify_triangulation(p, t) for _, _, t in results)
    # three different pictures: no triangulation is shown twice
    assert len({tuple(sorted(t)) for _, _, t in results}) == len(results)
    drawn = figure_mobjects(Figure("three-triangulations"), "lecture")
    for name, _, triangles in results:
        assert len(named(drawn, f"figure:triangle:{name}")) == len(triangles)
    # over each picture its count, nothing more: the name and the bound are its line's
    counts = [m.original_text for m in named(drawn, "figure:count")]
    assert counts == [f"{p.n - 2} triangles"] * len(RECAPPED)
    # each bound is the one the line under its picture gives, once
    chapter = next(c for c in lecture_chapters() if c.slug == "recap")
    cls = load_scene_class(Path(__file__).resolve().parents[1] / chapter.scene_file,
                           chapter.scene_class)
    card = next(s for s in cls.__new__(cls).chapter_segments()
                if isinstance(s, Card) and s.figure == Figure("three-triangulations"))
    for line, (name, bound) in zip(card.lines, RECAPPED, strict=True):
        assert line.rstrip(".").endswith(bound) or f"{bound}." in line
        # and by the name its picture's legend gives it ("Faster ear clipping" in the legend
        # was "Ear clipping with ear status kept" in the words, review r567)
        assert line.startswith(spoken(name, start=True)), line


@pytest.mark.parametrize("polygon", ["lecture", "counterexample", "triangle"])
def test_the_recap_s_row_of_triangulations_stays_under_the_title(polygon):
    """The three pictures side by side across the frame, each with its count over it, under
    the card's title and over the words' row, none of them overlapping."""
    from metaphors.figures import WIDE_BOX

    drawn = figure_mobjects(Figure("three-triangulations"), polygon)
    (x, y), width, height = WIDE_BOX
    for m in drawn:
        (left, bottom, _), (right, top, _) = m.get_corner([-1, -1, 0]), m.get_corner([1, 1, 0])
        assert left >= x - width / 2 - 1e-6 and right <= x + width / 2 + 1e-6, m.name
        assert bottom >= y - height / 2 - 1e-6 and top <= min(2.9, y + height / 2 + 1e-6), m.name
    pictures = sorted(named(drawn, "figure:polygon"), key=lambda m: m.get_x())
    assert all(a.get_right()[0] < b.get_left()[0] for a, b in itertools.pairwise(pictures))


@pytest.mark.parametrize("kind", ["monotone-pieces", "measured", "delaunay-circle"])
@pytest.mark.parametrize("polygon", ["lecture", "counterexample", "triangle"])
def test_a_faster_figure_stays_in_its_half_and_its_words_do_not_overlap(kind, polygon):
    """Left of the card's words, below its title, above the frame's bottom; no two of its
    texts overlapping; every text at least 2.5 % of the frame's height."""
    from metaphors.lecture import FIGURED_WIDTH, FIGURED_WORDS_X
    from tests.reading_rules import LEAST_LINE

    drawn = figure_mobjects(Figure(kind), polygon)
    words_left = FIGURED_WORDS_X - FIGURED_WIDTH / 2
    for m in drawn:
        (left, bottom, _), (right, top, _) = m.get_corner([-1, -1, 0]), m.get_corner([1, 1, 0])
        assert left >= -7.1 and right <= words_left and bottom >= -4.0 and top <= 2.9, m.name
    texts = [t for m in drawn for t in ([*m] if m.name == "figure:label" else [m])
             if hasattr(t, "original_text")]
    texts += [t for m in named(drawn, "figure:vertices") for group in m for t in group
              if hasattr(t, "original_text")]
    assert all(t.height >= LEAST_LINE for t in texts), [
        (t.original_text, t.height) for t in texts if t.height < LEAST_LINE]
    boxes = [(t.get_left()[0], t.get_bottom()[1], t.get_right()[0], t.get_top()[1], t.original_text)
             for t in texts]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            apart = a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1]
            assert apart, (a[4], b[4])


def test_the_triangulation_marks_one_inner_diagonal():
    """Issue 22 item 2: the card that first says "inner diagonal" draws one: the longest
    diagonal of the triangulation shown, in green, and an inner diagonal of P."""
    from manim import Line

    p = read_polygon("lecture")
    drawn = figure_mobjects(Figure("triangulation"), "lecture")
    [line] = named(drawn, "figure:inner-diagonal")
    assert isinstance(line, Line) and line.trex_role == "result"
    ends = {tuple(round(c, 6) for c in line.get_start()[:2]),
            tuple(round(c, 6) for c in line.get_end()[:2])}
    shown = named(drawn, "figure:vertices")[0]
    at = {tuple(round(c, 6) for c in marker[0].get_center()[:2]): k
          for k, marker in enumerate(shown)}
    i, j = (at[e] for e in ends)
    assert is_inner_diagonal(p, i, j)


def test_the_frame_marks_a_convex_and_a_reflex_vertex_outside_p():
    """Issue 22 item 2: the frame's card marks B convex and a reflex vertex, each a ring on
    the vertex and its word beside it, outside P."""
    import shapely

    from metaphors.drawing import Frame
    from metaphors.figures import FIGURE_CENTER, FIGURE_HEIGHT, FIGURE_WIDTH

    p = read_polygon("lecture")
    drawn = figure_mobjects(Figure("frame"), "lecture")
    frame = Frame(p.points, FIGURE_CENTER, FIGURE_WIDTH, FIGURE_HEIGHT)
    outline = shapely.Polygon([frame.to_scene(q)[:2] for q in p.points])
    for word, sign in (("convex", 1), ("reflex", -1)):
        [mark] = named(drawn, f"figure:{word}")
        ring, text = mark
        v = min(range(p.n), key=lambda k: float(
            ((frame.to_scene(p.points[k]) - ring.get_center()) ** 2).sum()))
        assert orient(p.points[v - 1], p.points[v], p.points[(v + 1) % p.n]) == sign, word
        assert text.original_text == word.capitalize()
        (x0, y0), (x1, y1) = text.get_corner([-1, -1, 0])[:2], text.get_corner([1, 1, 0])[:2]
        assert not shapely.box(x0, y0, x1, y1).intersects(outline), word
    b = min(range(p.n), key=lambda k: p.points[k])
    ring = named(drawn, "figure:convex")[0][0]
    assert abs(ring.get_center() - frame.to_scene(p.points[b])).max() < 1e-9  # B, the left-most


def test_the_frame_s_words_keep_clear_of_its_labels_as_drawn(monkeypatch):
    """The frame card's Convex and Reflex words are checked against the labels the figure
    draws (clear of T's sides and the pick's line), not against labels placed without
    them: two placements could drift apart, a word over a label. Here every label the
    figure draws stands a little under its dot, where Convex would go under B; the words
    find another side."""
    import numpy as np

    import metaphors.figures as figures

    drawn_vertices = figures._vertices

    def lowered(polygon, frame, theme, parts):
        vertices = drawn_vertices(polygon, frame, theme, parts)
        for marker in vertices.submobjects:
            marker[1].move_to(marker[0].get_center() + np.array([0.0, -0.5, 0.0]))
        return vertices

    monkeypatch.setattr(figures, "_vertices", lowered)
    drawn = figure_mobjects(Figure("frame"), "lecture")
    (vertices,) = named(drawn, "figure:vertices")
    labels = [figures._box(marker[1], pad=0.0) for marker in vertices.submobjects]
    words = [figures._box(mark[1], pad=0.0) for word in ("convex", "reflex")
             for mark in named(drawn, f"figure:{word}")]
    assert len(words) == 2
    assert [w for w in words if any(figures._overlap(w, b) for b in labels)] == []


_FIRST_MARKS = {"convex": r"(?i)\bconvex\b", "reflex": r"(?i)\breflex\b",
                "ear": r"(?i)\bears?\b", "inner-diagonal": r"(?i)\binner diagonals?\b",
                "candidate": r"(?i)\bcandidates?\b", "T": r"\bT\b"}


def test_each_taught_word_is_first_said_with_its_mark_on_the_picture():
    """Issue 22 item 2: where the lecture (chapters in order, their dry-run graphs) first
    says convex, reflex, ear, inner diagonal, candidate or T — in a caption or any text on
    screen — a figure's mark of that name (``figure:reflex`` …) is on screen."""
    import re

    from tests.reading_rules import INCOMING, OUTGOING, animation_nodes
    from tests.test_lecture import _chapter_class
    from trex.chapters import lecture_chapters
    from trex.snapshot import build

    left, missing = dict(_FIRST_MARKS), []
    for chapter in lecture_chapters():
        on_screen: set[str] = set()
        for k, play in enumerate(build(_chapter_class(chapter).handed()).data["plays"]):
            for anim in play["animations"]:
                name = anim.get("mobject", {}).get("name")
                if anim["type"] in INCOMING:
                    on_screen.add(name)
                elif anim["type"] in OUTGOING:
                    on_screen.discard(name)
            texts = [play["subcaption"] or "", *(n["text"] for a in play["animations"]
                                                 for n in animation_nodes(a) if n.get("text"))]
            for word, pattern in list(left.items()):
                if any(re.search(pattern, t) for t in texts):
                    del left[word]
                    if f"figure:{word}" not in on_screen:
                        missing.append(f"{word}: {chapter.slug} play {k}")
        if not left:
            break
    assert not left, f"never said: {sorted(left)}"
    assert missing == []


def _extent(node: dict, into: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Every point a graph node (and its parts) draws: its outline's points, its text's box."""
    into += [(p[0], p[1]) for p in node.get("points") or ()]
    if node.get("box"):
        x0, y0, x1, y1 = node["box"]
        into += [(x0, y0), (x1, y1)]
    for child in node.get("submobjects", ()):
        _extent(child, into)
    return into


def caption_problems(play: dict, shown: list[dict] | None = None) -> list[str]:
    """What is wrong with the figure captions a play brings on (dry-run graph): a caption
    not wholly below everything else of its figure, out of the frame, or a row of it under
    2.5 % of the frame's height. ``shown``: the figure's parts on screen as the play begins
    (a caption that comes with a later line: the overview's count), else the play's own."""
    from tests.reading_rules import INCOMING, LEAST_LINE, mobject_nodes

    half_width, half_height = 8 * 16 / 9 / 2, 4.0  # manim's frame, 16:9
    parts = [a["mobject"] for a in play["animations"] if a["type"] in INCOMING
             and a.get("mobject", {}).get("name", "").startswith("figure:")]
    parts += [m for m in shown or () if m["name"] != "figure:label"]
    problems = []
    for caption in (m for m in parts if m["name"] == "figure:label"):
        rows = [n for n in mobject_nodes(caption) if n.get("text") and n.get("box")]
        said = " / ".join(r["text"] for r in rows)
        x0, y0 = min(r["box"][0] for r in rows), min(r["box"][1] for r in rows)
        x1, y1 = max(r["box"][2] for r in rows), max(r["box"][3] for r in rows)
        drawn = [p for m in parts if m is not caption for p in _extent(m, [])]
        lowest = min(y for _, y in drawn)
        if y1 >= lowest:
            problems.append(f"{said!r}: its top {y1:.2f} not below the figure ({lowest:.2f})")
        if x0 < -half_width or x1 > half_width or y0 < -half_height or y1 > half_height:
            problems.append(f"{said!r}: out of the frame ({x0:.2f}, {y0:.2f}, {x1:.2f}, {y1:.2f})")
        problems += [f"{r['text']!r}: {r['box'][3] - r['box'][1]:.3f} high" for r in rows
                     if r["box"][3] - r["box"][1] < LEAST_LINE]
    return problems


def _captioned_cards(cls) -> int:
    """How many captions the figures of a chapter's cards draw (each comes in a play of its
    own: the overview's cut counts its vertices, then the count for this P takes its place)."""
    from metaphors.lecture import Card, Hunted

    figures = [s.figure for s in cls.__new__(cls).chapter_segments()
               if isinstance(s, Card | Hunted) and s.figure is not None]
    return sum(len(named(figure_mobjects(f, "lecture"), "figure:label")) for f in figures)


def _lecture_chapters():
    from trex.chapters import lecture_chapters

    return [pytest.param(c, id=c.slug) for c in lecture_chapters()]


@pytest.mark.parametrize("chapter", _lecture_chapters())
def test_every_figure_caption_lies_below_its_figure_inside_the_frame(chapter):
    """On the chapter's dry-run graph, every card figure's caption is below all of its figure
    (its polygon, the vertices' labels, its marks and legends: nothing of it over the
    picture), inside the frame, and every row of it readable (2.5 % of the frame's height);
    and every card whose figure has a caption was seen."""
    from tests.reading_rules import INCOMING
    from tests.test_lecture import _chapter_class
    from trex.snapshot import build

    cls = _chapter_class(chapter)
    plays = build(cls.handed()).data["plays"]
    captioned = [k for k, play in enumerate(plays) if any(
        a["type"] in INCOMING and a.get("mobject", {}).get("name") == "figure:label"
        for a in play["animations"])]
    assert len(captioned) == _captioned_cards(cls)
    assert [p for k in captioned for p in caption_problems(plays[k], _figure_on_screen(
        plays, k))] == []


def _figure_on_screen(plays: list[dict], k: int) -> list[dict]:
    """The parts of a card's figure on screen as play ``k`` begins: brought since the card's
    title, not taken off since."""
    from tests.reading_rules import INCOMING, OUTGOING

    shown: dict[str, dict] = {}
    for play in plays[:k]:
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            name = node.get("name") or ""
            if name == "card:title" and anim["type"] in INCOMING:
                shown = {}
            if name.startswith("figure:"):
                key = f"{name}:{id(node)}"
                if anim["type"] in INCOMING:
                    shown[key] = node
                elif anim["type"] in OUTGOING:
                    shown = {k2: n for k2, n in shown.items() if n.get("points") != node.get(
                        "points") or n.get("name") != name}
    return list(shown.values())


def test_a_caption_over_its_figure_is_caught():
    """The check above can fail: a caption moved up onto its figure, or down out of the
    frame, is reported."""
    from metaphors.figure_caption import GAP

    drawn = figure_mobjects(Figure("monotone-pieces"), "lecture")

    def play(shift: float) -> dict:
        from trex.scene_graph import mobject_graph

        caption = named(drawn, "figure:label")[0].copy().shift((0, shift, 0))
        caption.name = "figure:label"
        others = [m for m in drawn if m.name != "figure:label"]
        return {"animations": [{"type": "FadeIn", "mobject": mobject_graph(m)}
                               for m in [*others, caption]]}

    assert caption_problems(play(0.0)) == []
    assert any("not below the figure" in p for p in caption_problems(play(GAP + 0.3)))
    assert any("out of the frame" in p for p in caption_problems(play(-1.5)))


def test_labels_on_edges_finds_the_old_fixed_step_labels_on_the_lecture_polygon():
    """The rule can fail: the lecture polygon's figure with its labels a fixed step from the
    centre (the old :func:`metaphors.drawing.vertex_markers`) has K on edge L–K; placed by
    measuring (:func:`metaphors.labels.placed_vertex_markers`) every label keeps clear."""
    from metaphors.drawing import polygon_mobject, vertex_markers
    from metaphors.labels import placed_vertex_markers
    from tests.reading_rules import labels_on_edges
    from trex.scene_graph import mobject_graph

    p = read_polygon("lecture")
    frame = Frame(p.points, *BOX)

    def shown(markers):
        return {"plays": [{"animations": [
            {"type": "FadeIn", "mobject": {**mobject_graph(m), "name": name}}
            for m, name in ((polygon_mobject(p, frame), "figure:polygon"),
                            (markers, "figure:vertices"))]}]}

    old = labels_on_edges(shown(vertex_markers(p, frame)))
    assert any(f.startswith("play 0 K 0.0") for f in old), old
    assert labels_on_edges(shown(placed_vertex_markers(p, frame))) == []


@pytest.mark.parametrize("kind", ["triangulation", "diagonal"])
def test_a_card_s_labels_stand_inside_one_piece_of_its_fill(kind):
    """Over3 item 1: a label with no room outside P (M in its notch, G in its) stands inside
    one piece of the figure's fill, off the lines that cut it. The rule can fail: the same
    figure with its labels placed as before, clear of P's edges only, had G on the
    triangulation's side B–E, M by the diagonal BM and G on the diagonal DG's half."""
    from manim import DL, UR
    from shapely.geometry import Point, box

    from metaphors.labels import placed_vertex_markers
    from tests.reading_rules import labels_across_fills
    from trex.scene_graph import mobject_graph

    drawn = figure_mobjects(Figure(kind), "lecture")

    def shown(parts):
        return {"plays": [{"animations": [{"type": "FadeIn", "mobject": mobject_graph(m)}
                                          for m in parts]}]}

    p = read_polygon("lecture")
    old = tag(placed_vertex_markers(p, Frame(p.points, *BOX)), "idle", "figure:vertices")
    before = [old if m.name == "figure:vertices" else m for m in drawn]
    assert any(" G on " in f for f in labels_across_fills(shown(before))), kind
    assert labels_across_fills(shown(drawn)) == [], kind
    # and each label nearer its own dot than any other (ear clipping's fan left G no place
    # inside one triangle, and its label went by H), but one with a leader to its dot (M,
    # beside P: the leader says whose it is)
    markers = next(m for m in drawn if m.name == "figure:vertices")
    dots = [Point(*marker[0].get_center()[:2]) for marker in markers]
    for k, marker in enumerate(markers):
        if len(marker.submobjects) > 2:
            continue
        label = box(*marker[1].get_corner(DL)[:2], *marker[1].get_corner(UR)[:2])
        gaps = [label.distance(dot) for dot in dots]
        assert gaps[k] < min(g for j, g in enumerate(gaps) if j != k), (kind, p.labels[k])


def test_a_label_with_no_room_outside_p_by_its_dot_stands_beside_p_with_a_leader():
    """Chapter 5: M, in the lecture polygon's notch between A and L, stood over P's fill (a
    place outside P by its dot was nearer A's). With leaders (a run's board that never
    turns, a card's figure), it stands beside P, off every edge, and a thin line runs from
    by its dot to by its letter; every other label is placed as before."""
    import shapely
    from manim import Line

    from metaphors.board import METAPHOR
    from metaphors.labels import EDGE_MARGIN, LEADER_END, measured_markers
    from metaphors.theme import THEME

    p = read_polygon("lecture")
    frame = Frame(p.points, METAPHOR.center, METAPHOR.width, METAPHOR.height)
    region = shapely.Polygon([frame.to_scene(q)[:2] for q in p.points])
    plain = dict(measured_markers(p, (), frame, THEME))
    led = dict(measured_markers(p, (), frame, THEME, leaders=True))

    def box(marker):
        (x0, y0), (x1, y1) = marker[1].get_corner([-1, -1, 0])[:2], marker[1].get_corner([1, 1, 0])[:2]
        return shapely.box(x0, y0, x1, y1)

    assert box(plain["M"]).intersection(region).area > 1e-3  # without: over P's fill
    m = led["M"]
    assert len(m.submobjects) == 3 and isinstance(m[2], Line)
    assert box(m).intersection(region).area == 0.0
    assert box(m).distance(region.exterior) >= EDGE_MARGIN
    dot = shapely.Point(m[0].get_center()[:2])
    start, end = shapely.Point(m[2].get_start()[:2]), shapely.Point(m[2].get_end()[:2])
    assert abs(start.distance(dot) - (THEME.dot_radius + LEADER_END)) < 1e-6
    assert abs(end.distance(box(m)) - LEADER_END) < 1e-3
    # the labels with room beside their dot stand where they stood
    assert {name for name in led if len(led[name].submobjects) == 2
            and not box(led[name]).equals(box(plain[name]))} == set()
