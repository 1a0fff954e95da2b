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
    drawn = figure_mobjects(Figure(kind, heuristics=("scaling",)), polygon)
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
