"""Monotone partition + stack triangulation: vertex kinds, known pieces, monotone pieces, valid."""

from __future__ import annotations

import functools
import json
from dataclasses import replace

import pytest
from hypothesis import given, settings

import tracing
from geometry.check import is_inner_diagonal
from geometry.monotone import Sweep, classify_vertex, make_monotone, monotone
from geometry.monotone_pieces import MonotonePiece, monotone_pieces, triangulate_monotone_piece
from geometry.polygon import Polygon
from geometry.samples import make_sample
from geometry.triangulate import triangulate
from story.refs import ref
from tests.strategies import generated_polygons
from tests.test_ears import CORPUS, NAMED, assert_valid, collinear_polygons

# A rectangle with a notch up from the bottom (split vertex D) and one down from the top
# (merge vertex I). Stored counter-clockwise from A = (0, 6), so B = (0, 0) is left-most.
NOTCHED = Polygon.from_points(
    [(0, 0), (2, 0), (3, 2), (4, 0), (6, 0), (6, 6), (4, 6), (3, 4), (2, 6), (0, 6)]
)


def height_rank(p: Polygon) -> dict[int, int]:
    """0 for the highest vertex: larger y first, then smaller x (the sweep's order)."""
    order = sorted(range(p.n), key=lambda i: (-p.points[i][1], p.points[i][0]))
    return {v: r for r, v in enumerate(order)}


def is_y_monotone(p: Polygon, ids: tuple[int, ...]) -> bool:
    """Going round, heights change direction exactly twice (once at the top, once at the bottom)."""
    rank = height_rank(p)
    k = len(ids)
    down = [rank[ids[(i + 1) % k]] > rank[ids[i]] for i in range(k)]
    return sum(down[i] != down[i - 1] for i in range(k)) == 2


def labels(p: Polygon, ids) -> str:
    return "".join(p.labels[i] for i in ids)


def cyclic_sets(p: Polygon, pieces: list[MonotonePiece]) -> set[str]:
    return {"".join(sorted(labels(p, piece.ids))) for piece in pieces}


# --- known answers -------------------------------------------------------------------------------


def test_vertex_kinds_of_the_notched_rectangle():
    p = NOTCHED
    assert labels(p, range(p.n)) == "ABCDEFGHIJ"
    kinds = {p.labels[i]: classify_vertex(Sweep(p), p.vertex(i)) for i in range(p.n)}
    assert kinds == {
        "A": "start", "B": "regular", "C": "end", "D": "split", "E": "regular",
        "F": "end", "G": "regular", "H": "start", "I": "merge", "J": "regular",
    }


def test_equal_heights_are_ordered_left_first():
    # The bottom side B–C is level: B (left) counts as higher, so C is an end vertex and
    # B a regular one; the top side J–A likewise makes A a start vertex.
    p = NOTCHED
    sweep = Sweep(p)
    assert labels(p, sweep.order) == "AJHGIDBCEF"


def test_split_and_merge_are_joined_into_two_known_pieces():
    p = NOTCHED
    with tracing.record() as log:
        diagonals = make_monotone(p)
    assert [labels(p, d) for d in diagonals] == ["DI"]
    (call,) = log.find(kind="call", name="add_diagonal")
    assert (ref(call, "u"), ref(call, "w")) == ("D", "I")
    pieces = monotone_pieces(p, diagonals)
    assert cyclic_sets(p, pieces) == {"ABCDIJ", "DEFGHI"}
    assert all(is_y_monotone(p, piece.ids) for piece in pieces)
    assert_valid(p, monotone(p))


def test_lecture_pieces_are_monotone_and_cut_by_inner_diagonals():
    p = Polygon.from_points(make_sample("lecture"))
    diagonals = make_monotone(p)
    assert diagonals
    for u, w in diagonals:
        assert is_inner_diagonal(p, u, w), labels(p, (u, w))
    pieces = monotone_pieces(p, diagonals)
    assert len(pieces) == len(diagonals) + 1
    assert sum(len(piece.ids) for piece in pieces) == p.n + 2 * len(diagonals)
    assert all(is_y_monotone(p, piece.ids) for piece in pieces)


def test_stack_triangulation_of_a_zigzag():
    # Already monotone: left chain A…E goes down in steps, the right chain is one edge.
    p = Polygon.from_points([(0, 10), (-1, 8), (0, 6), (-1, 4), (0, 2), (-1, 0), (3, 5)])
    assert make_monotone(p) == []
    (piece,) = monotone_pieces(p, [])
    triangles = triangulate_monotone_piece(p, piece)
    assert len(triangles) == p.n - 2
    assert_valid(p, monotone(p))


def test_collinear_chain_gives_no_flat_triangle():
    # A straight left side of five vertices and a straight bottom: the stack must wait at
    # straight angles instead of cutting off a zero-area triangle.
    p = Polygon.from_points([(0, 0), (4, 0), (8, 0), (8, 1), (0, 4), (0, 3), (0, 2), (0, 1)])
    assert_valid(p, monotone(p))


def test_traced_steps():
    p = NOTCHED
    with tracing.record() as log:
        result = triangulate(p, "monotone")
    assert_valid(p, result)
    assert len(log.find(kind="call", name="classify_vertex")) == p.n
    kinds = [e.result for e in log.find(kind="return", name="classify_vertex")]
    assert kinds.count("split") == kinds.count("merge") == 1
    assert len(log.find(kind="call", name="triangulate_monotone_piece")) == 2
    assert not log.find(kind="enter", target="sweep")  # the line is the storyboard's to draw


# --- every input --------------------------------------------------------------------------------


@pytest.mark.parametrize("sample", NAMED)
def test_named_samples(sample):
    p = Polygon.from_points(make_sample(sample))
    assert_valid(p, monotone(p))


@pytest.mark.parametrize("polygon", CORPUS)
def test_earcut_corpus(polygon):
    assert_valid(polygon, triangulate(polygon, "monotone"))


@settings(max_examples=2000)
@given(generated_polygons(max_n=30))
def test_generated_polygons(p):
    diagonals = make_monotone(p)
    pieces = monotone_pieces(p, diagonals)
    assert len(pieces) == len(diagonals) + 1
    assert all(is_y_monotone(p, piece.ids) for piece in pieces)
    assert_valid(p, monotone(p))


@settings(max_examples=300)
@given(collinear_polygons())
def test_collinear_runs(p):
    assert_valid(p, monotone(p))


# --- one colour, one meaning (issue 22 item 4) ---------------------------------------------------


def test_vertex_kinds_have_colours_of_their_own():
    """Split and merge are kinds of vertex, not verdicts: never the red of "fails" nor the
    green of a result, and not one another's."""
    from metaphors.theme import THEME

    kinds = [THEME.role_colour("split"), THEME.role_colour("merge")]
    verdicts = {THEME.rejected.lower(), THEME.result.lower()}
    assert len({c.lower() for c in kinds}) == 2
    assert not {c.lower() for c in kinds} & verdicts
    assert THEME.stack.lower() not in verdicts


def _monotone_graphs():
    from scenes.holes import HolesSweep
    from trex.chapters import lecture_chapters

    faster = next(c for c in lecture_chapters() if c.slug == "faster")
    return [pytest.param(HolesSweep, id="holes-sweep"),
            pytest.param(faster, id="lecture-faster")]


def _vertex_nodes(data):
    """Every node of a vertex: its marker (on the board, in the panel) and the kind written
    beside it, with their parts."""
    from tests.reading_rules import graph_nodes, mobject_nodes

    for top in graph_nodes(data):
        name = top.get("name") or ""
        if (name.startswith(("vertex:", "panel:")) and name != "panel:call") or name == "kind":
            yield from mobject_nodes(top)


@pytest.mark.parametrize("scene", _monotone_graphs())
def test_the_monotone_sweep_never_gives_a_vertex_the_red_of_fails(scene):
    from metaphors.theme import THEME
    from tests.test_lecture import _chapter_class
    from trex.snapshot import build

    cls = scene if isinstance(scene, type) else _chapter_class(scene).handed()
    data = build(cls).data
    nodes = list(_vertex_nodes(data))
    red = THEME.rejected.upper()
    assert [n.get("name") for n in nodes
            if n.get("role") == "rejected" or red in (n.get("stroke"), n.get("fill"))] == []
    # not vacuous: the split and merge vertices are there, in their own colours
    colours = {c for n in nodes for c in (n.get("stroke"), n.get("fill"))}
    assert {THEME.split.upper(), THEME.merge.upper()} <= colours
    roles = {n.get("role") for n in nodes}
    assert {"split", "merge"} <= roles


@functools.cache
def _graph(scene):
    """The scene graph of a monotone scene or of the lecture's chapter (built once)."""
    from tests.test_lecture import _chapter_class
    from trex.snapshot import build

    return build(scene if isinstance(scene, type) else _chapter_class(scene).handed()).data


def test_a_summarys_fast_steps_each_last_long_enough_to_see():
    """r567: under "Vertices H, B, G and F: the same steps, faster" each vertex was current
    for 0.2 s, then the screen stood on the last one for 2 s. The steps share the caption's
    reading time: each at least half a second, the caption's hold after them short."""
    from story.reading import reading_time

    runs = _fast_steps(_graph(_monotone_graphs()[1].values[0]))
    assert runs and all(len(steps) >= 2 for _, steps in runs)
    for said, steps in runs:
        assert min(steps) >= 0.5, (said, steps)
        assert sum(steps) >= reading_time(said) - 0.5, (said, steps)  # no long hold after


def _fast_steps(data) -> list[tuple[str, list[float]]]:
    """Each stretch of a summary's fast steps (one caption, shown once): its caption and the
    run times of the plays that pulse a vertex under it."""
    runs: list[tuple[str, list[float]]] = []
    for play in data["plays"]:
        if play.get("subcaption"):
            runs.append((play["subcaption"], []))
        pulsed = [a for a in play["animations"] if a.get("type") == "Indicate"
                  and (a.get("mobject") or {}).get("name", "").startswith("vertex:")]
        if runs and "the same steps, faster" in runs[-1][0] and pulsed:
            runs[-1][1].append(play["run_time"])
    return [(said, steps) for said, steps in runs if steps]


def test_a_summary_said_again_later_shares_its_time_only_within_its_own_stretch():
    """Board.shares counted a caption over the whole run: a summary whose words came back
    later (here the lecture's last one, "Vertices E and C", reworded as the first) had each
    step of its first stretch cut to its reading time over all six steps (0.45 s, and 1.8 s
    for a caption of 2.7 s). Each stretch shares its caption's reading time among its own."""
    from metaphors.scene import TraceScene
    from story.reading import reading_time
    from trex.snapshot import build

    class SaidTwice(TraceScene):
        algorithm = "monotone"
        # two summaries apart (the lecture's polygon has one since F's step, whose helper a
        # diagonal joins, and E's, the first end vertex, are their own)
        polygon = "random-2opt:14:5"

        def beats(self, log):
            beats = super().beats(log)
            first, last = (next(b.caption for b in order if "faster" in b.caption)
                           for order in (beats, beats[::-1]))
            assert first != last  # two summaries, each its own stretch
            return [replace(b, caption=first) if b.caption == last else b for b in beats]

    runs = _fast_steps(build(SaidTwice.handed()).data)
    assert len(runs) == 2 and runs[0][0] == runs[1][0]
    for said, steps in runs:
        assert min(steps) >= 0.5, (said, steps)
        assert sum(steps) >= reading_time(said) - 0.5, (said, steps)


def _legend() -> dict[str, str]:
    """The theme's one legend: every colour it names (name → hex)."""
    import dataclasses

    from metaphors.theme import THEME

    return {f.name: value for f in dataclasses.fields(THEME)
            if isinstance(value := getattr(THEME, f.name), str) and value.startswith("#")}


def test_a_vertex_colour_that_changes_meaning_is_found():
    """The rule itself, on a hand-made graph with both defects the reviewer saw (r567): B
    pulsed in manim's yellow, in no legend, and K, shown as a merge vertex, then blue."""
    from metaphors.theme import THEME
    from tests.reading_rules import shifting_vertex_colours

    def recolour(label, colour):
        return {"type": "_MethodAnimation", "mobject": {"name": f"vertex:{label}"},
                "target": {"name": f"vertex:{label}", "stroke": colour}}

    plays = [{"animations": [recolour("K", THEME.merge)]},
             {"animations": [recolour("K", THEME.called),
                             {"type": "Indicate", "color": "#FFFF00",
                              "mobject": {"name": "vertex:B"}}]}]
    found = shifting_vertex_colours({"plays": plays}, _legend(), ("split", "merge"),
                                    THEME.called)
    assert found == [f"play 1 K {THEME.called.upper()}: merge, then called",
                     "play 1 B Indicate #FFFF00: in no legend"]


@pytest.mark.parametrize("scene", _monotone_graphs())
def test_every_vertex_keeps_one_colour_per_meaning(scene):
    """Every colour a vertex is given, its pulses' too, is the legend's
    (:mod:`metaphors.theme`), and a split or merge vertex never turns the blue of the vertex
    looked at (r567: the fast run pulsed B, F and E yellow while the panel showed them blue;
    K, a merge vertex, turned blue as it took over from M)."""
    from metaphors.theme import THEME
    from tests.reading_rules import shifting_vertex_colours

    data = _graph(scene)
    assert shifting_vertex_colours(data, _legend(), ("split", "merge"), THEME.called) == []
    # not vacuous: the sweep's vertices pulse, in their colours
    pulses = {a.get("color") for p in data["plays"] for a in p["animations"]
              if a.get("type") == "Indicate"}
    assert {THEME.called.upper(), THEME.merge.upper()} <= pulses


# --- the lecture's steps (issue 22 item 5) ----------------------------------------------------------


def _lecture_beats():
    from metaphors import catalog
    from story.runs import run_logged
    from story.storyboard import Pacing

    return catalog.beats(run_logged("monotone", "lecture"), Pacing(full=2, fast=0.35))


def test_every_split_and_merge_vertex_and_diagonal_is_a_step_of_its_own():
    """Never fast-forwarded: full pace, a caption naming the vertex (and the diagonal), and
    the lit row the one running (a diagonal added at a regular or end vertex lights the row
    of the diagonal, not the merge vertex's)."""
    from metaphors.monotone import Classify, MonotoneDiagonal
    from story.registry import pseudocode

    rows = pseudocode("monotone")
    beats = _lecture_beats()
    key = [b for b in beats if isinstance(b, Classify) and b.kind in ("split", "merge")]
    diagonals = [b for b in beats if isinstance(b, MonotoneDiagonal)]
    assert {b.kind for b in key} == {"split", "merge"} and len(diagonals) >= 3
    for b in key:
        assert b.pace == 1.0 and b.caption.startswith(f"{b.vertex}: ") and b.kind in b.caption
        assert "add_diagonal" not in rows[b.row].calls and "classify_vertex" in rows[b.row].calls
    for b in diagonals:
        assert b.pace == 1.0 and b.caption.startswith(f"Diagonal {''.join(b.labels)}: ")
        assert ("split vertex" in b.caption) != ("merge vertex" in b.caption), b.caption
        assert rows[b.row].calls == ("add_diagonal",)
    # what is fast-forwarded holds no split or merge vertex
    fast = [b for b in beats if "the same steps, faster" in b.caption]
    assert fast and all(not isinstance(b, MonotoneDiagonal)
                        and getattr(b, "kind", None) not in ("split", "merge") for b in fast)


def test_the_stack_drawn_is_the_stack_of_the_log():
    """Each step's chain follows from the one before by one push or one cut off (the triangle
    cut holds the top and the vertex it was cut for), and the triangles cut, with the pieces
    that are triangles already, are the run's triangulation."""
    from metaphors.monotone import Stack, StackStep

    beats = _lecture_beats()
    steps = [b for b in beats if isinstance(b, StackStep)]
    assert max(len(b.chain) for b in steps) >= 3
    before: tuple[str, ...] = ()
    cut = []
    for b in steps:
        if b.cut:
            assert b.chain == before[:-1] and before[-1] in b.cut, b.caption
            assert set(b.cut) - set(before) and len(set(b.cut)) == 3
            cut.append(frozenset(b.cut))
        else:  # a push: on the chain so far, or a new chain of two (the other chain)
            assert b.chain[:-1] in (before, before[-1:], ()) or len(b.chain) == 2, b.caption
        before = b.chain
    last = next(b for b in reversed(beats) if isinstance(b, Stack))
    p = Polygon.from_points(make_sample("lecture"))
    whole = {frozenset(p.labels[i] for i in t) for t in monotone(p).triangles}
    assert len(last.triangulation) == p.n - 2
    assert set(cut) <= whole and len(cut) + sum(len(b.triangles) for b in beats
                                                if isinstance(b, Stack)) == p.n - 2


# --- the stack's place (issue 22 item 5: the stack drawn, clear of everything else) -----------------


def _box_of(node) -> tuple[float, float, float, float] | None:
    """A graph node's box: its texts' boxes and its other parts' points, with all its parts."""
    from tests.reading_rules import box_of_parts

    return box_of_parts(node, points_of=None)


def stack_collisions(data) -> list[str]:
    """The stack's columns (each drawn) that overlap or touch P's region, a vertex's marker
    or label, the title, the panel (its polygon, labels, code, lights, call line) or a
    subtitle, as ``"stack 'A M K' × vertex:J"``."""
    from shapely.geometry import Polygon as Region
    from shapely.geometry import box

    from tests.reading_rules import INCOMING, graph_nodes, mobject_nodes

    columns, others = [], {}
    for play in data["plays"]:
        for anim in play["animations"]:
            for key in ("mobject", "target"):
                node = anim.get(key) or {}
                name = node.get("name") or ""
                if name == "stack:column" and (anim["type"] in INCOMING or key == "target"):
                    columns.append(node)
    for node in graph_nodes(data):
        name = node.get("name") or ""
        if name == "polygon" and node.get("points"):
            others.setdefault(name, Region([p[:2] for p in node["points"]]))
        elif (name.startswith(("vertex:", "panel", "code")) or name in ("title", "subtitle")) \
                and (b := _box_of(node)) is not None:
            others.setdefault(f"{name} {b}", box(*b))
    assert columns and "polygon" in others  # not vacuous: a stack drawn beside a polygon
    found = []
    for column in columns:
        words = " ".join(p["text"] for p in mobject_nodes(column) if p.get("text"))
        here = box(*_box_of(column))
        found += [f"stack {words!r} × {name}" for name, shape in others.items()
                  if here.distance(shape) < 0.1]
    return sorted(set(found))


def _sweep_scene(tmp_path, points, panel):
    from metaphors.scene import TraceScene

    class Sweep(TraceScene):
        algorithm = "monotone"
        polygon = "lecture"
        title = "Monotone partition, then the stack"

    path = tmp_path / "polygon.json"
    path.write_text(json.dumps([list(p) for p in points]))
    cls = Sweep.handed(polygon=str(path))
    return cls.with_panel(panel) if panel else cls


#: the lecture polygon turned over left to right: its vertices D and J and their labels stand
#: at the frame's left, where the stack stood before (x −6.97 … −6.03, from y 2.9 down)
MIRRORED = [(-x, y) for x, y in make_sample("lecture")]


@pytest.mark.parametrize("panel", [None, "source"])
@pytest.mark.parametrize("points", [make_sample("lecture"), MIRRORED], ids=["lecture", "mirrored"])
def test_the_stack_keeps_clear_of_the_polygon_its_labels_the_panel_and_the_captions(
        tmp_path, points, panel):
    from trex.snapshot import build

    data = build(_sweep_scene(tmp_path, points, panel)).data
    assert stack_collisions(data) == []


@pytest.mark.parametrize("panel", [None, "source"])
def test_the_lectures_stack_keeps_clear_too(panel):
    from tests.test_lecture import _chapter_class
    from trex.chapters import lecture_chapters
    from trex.snapshot import build

    faster = _chapter_class(next(c for c in lecture_chapters() if c.slug == "faster"))
    data = build((faster.with_panel(panel) if panel else faster).handed()).data
    assert stack_collisions(data) == []
    from tests.reading_rules import crowded_counts

    assert crowded_counts(data) == []  # the count n − 2, clear of C's label and the subtitle


@pytest.mark.parametrize("panel", [None, "source"])
@pytest.mark.parametrize("points", [make_sample("lecture"), MIRRORED], ids=["lecture", "mirrored"])
def test_the_count_n_minus_2_stands_clear_of_the_labels_and_the_subtitle(tmp_path, points, panel):
    """The whole triangulation's count is not written over a vertex label or the subtitle
    (it stood under P, on the lecture's C and its caption "The whole triangulation: …"):
    beside P, or, where a panel of source leaves no room, not at all (the caption says it)."""
    from tests.reading_rules import crowded_counts, graph_nodes
    from trex.snapshot import build

    data = build(_sweep_scene(tmp_path, points, panel)).data
    counts = {n["text"] for n in graph_nodes(data) if n.get("name") == "counter"}
    assert counts <= {"n − 2 = 13 − 2 = 11 triangles", "n − 2 = 13 − 2\n= 11 triangles"}
    assert len(counts) == (1 if panel is None else len(counts)) and len(counts) <= 1, counts
    assert crowded_counts(data) == []


def test_pieces_that_are_triangles_already_are_counted_not_called_this_piece():
    """The lecture's three pieces that are triangles already are drawn in a moment under one
    caption: it says there are three ("This piece …" named none of them)."""
    from metaphors.monotone import Stack

    captions = [b.caption for b in _lecture_beats() if isinstance(b, Stack)]
    assert captions == ["This piece is done: 8 triangles", *["3 pieces are triangles already"] * 3]


def test_the_comparison_shows_each_count_with_its_picture_and_the_labels():
    """r567: the captions said "Faster ear clipping: 11 triangles" and "Constrained
    Delaunay: 11 triangles" while no count was on screen, and the two polygons had no labels
    though the note says "different diagonals". Each count now comes with its triangles,
    under the caption that says it, and each polygon's vertices are labelled."""
    data = _graph(_monotone_graphs()[1].values[0])
    said = [(k, p["subcaption"]) for k, p in enumerate(data["plays"])
            if (p.get("subcaption") or "").startswith(("Faster ear clipping:",
                                                          "Constrained Delaunay:"))]
    assert [s for _, s in said] == ["Faster ear clipping: 11 triangles",
                                    "Constrained Delaunay: 11 triangles"]
    for k, _ in said:
        counts = [a["mobject"].get("text") for a in data["plays"][k]["animations"]
                  if (a.get("mobject") or {}).get("name") == "compare:count"]
        assert counts == ["11 triangles"]
        labels = {a["mobject"]["name"] for a in data["plays"][k - 1]["animations"]
                  if (a.get("mobject") or {}).get("name", "").startswith("compare:vertex:")}
        assert len(labels) == 13
