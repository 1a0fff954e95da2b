"""Divide and conquer hands a heuristic every piece in the piece's own frame (issue 24
items 8 and 11).

A piece keeps its parent's labels (the video draws them), but a heuristic of one's own reads
the polygon it is handed as the thesis does: B its left-most vertex, A and C B's neighbours,
the rest in order; what it returns (labels, indices or vertices) is read in that frame. The
captions name the run's own vertices, not the thesis's A, B, C.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from click.testing import CliRunner

from geometry.io import read_polygon
from geometry.polygon import Polygon, vertex_label
from geometry.samples import make_sample, sample_names
from geometry.triangulate import triangulate
from metaphors.catalog import beats as storyboard
from story.runs import run_logged
from trex.cli import main
from usercode.heuristic import load_user_heuristic

#: the thesis's correct translation, answered in labels read from the polygon handed
IN_LABELS = textwrap.dedent('''
    from geometry.predicates import in_triangle


    def deepest(polygon):
        """AC if T holds no other vertex, else B and the candidate farthest from AC."""
        labels, points = polygon.labels, polygon.points
        a, b, c = (points[labels.index(x)] for x in "ABC")
        inside = [k for k in range(polygon.n)
                  if labels[k] not in ("A", "B", "C") and in_triangle(points[k], a, b, c)]
        if not inside:
            return "A", "C"

        def depth(k):
            x, y = points[k]
            return abs((c[0] - a[0]) * (y - a[1]) - (c[1] - a[1]) * (x - a[0]))

        return "B", labels[max(inside, key=depth)]


    def always_ac(polygon):
        return "A", "C"


    SEEN = []


    def recording(polygon):
        SEEN.append((polygon.labels, polygon.points))
        return deepest(polygon)
''')


@pytest.fixture(scope="module")
def heuristics(tmp_path_factory):
    path = tmp_path_factory.mktemp("own") / "labels.py"
    path.write_text(IN_LABELS)
    return path


def simple_samples() -> list[str]:
    return [name for name in sample_names() if name != "triangle"]


@pytest.mark.parametrize("name", simple_samples())
def test_a_correct_heuristic_answering_in_labels_triangulates_every_sample(name, heuristics):
    polygon = Polygon.from_points(make_sample(name))
    result = triangulate(polygon, "divide-and-conquer",
                         load_user_heuristic(f"{heuristics}:deepest").function)
    assert result.valid, (name, result.failure)
    assert len(result.triangles) == polygon.n - 2


def test_each_piece_is_handed_in_its_own_frame(heuristics):
    own = load_user_heuristic(f"{heuristics}:recording")
    result = triangulate(read_polygon("lecture"), "divide-and-conquer", own.function)
    assert result.valid
    seen = own.raw.__globals__["SEEN"]
    assert len(seen) == 10  # 13 vertices: 10 diagonals, each claimed on a piece
    for labels, points in seen:  # each read as a whole polygon would be: B left-most …
        assert labels == tuple(vertex_label(k) for k in range(len(points)))
        assert points == Polygon.from_points(list(points)).points


def test_the_cli_triangulates_with_labels_where_it_failed(heuristics):
    result = CliRunner().invoke(main, ["triangulate", "lecture", "star", "--heuristic",
                                       f"{heuristics}:deepest"])
    assert result.exit_code == 0, result.stderr
    assert result.stdout == ("lecture: divide-and-conquer: 11 triangles, valid\n"
                             "star: divide-and-conquer: 8 triangles, valid\n")


def test_one_triangle_is_said_in_the_singular(heuristics):
    result = CliRunner().invoke(main, ["triangulate", "spiral", "--heuristic",
                                       f"{heuristics}:always_ac"])
    assert "spiral: divide-and-conquer: stopped after 1 triangle: " in result.stdout


def test_a_pieces_trace_keeps_its_parents_labels():
    """The example heuristic traces T with geometry.frame's helpers, on pieces in their own
    frame: the log still names the vertices as the board labels them."""
    example = Path(__file__).resolve().parent.parent / "examples" / "my_heuristic.py"
    log = run_logged("divide-and-conquer", "lecture", f"{example}:biggest_angle")
    labels = set(read_polygon("lecture").labels)
    claims = [e.result["ref"] for e in log.events if e.kind == "return" and e.name == "claim"]
    triangles = [e.state["labels"] for e in log.events
                 if e.kind == "enter" and e.target.startswith("T(")]
    assert len(claims) >= 3 and len(triangles) == len(claims)
    for claim in claims:  # each claim names two of the whole polygon's vertices
        assert any(claim == u + v for u in labels for v in labels), claim
    assert all(set(t) <= labels for t in triangles)
    assert any(t != ["A", "B", "C"] for t in triangles)  # a piece's own corners, not ABC


@pytest.mark.parametrize("heuristic", ["translation-correct", "scaling-correct"])
def test_captions_name_the_pieces_own_vertices(heuristic):
    captions = [b.caption for b in storyboard(run_logged("divide-and-conquer", "lecture",
                                                         heuristic))]
    empty = [k for k, c in enumerate(captions) if c.startswith("No vertex inside T: ")]
    shown = [k for k in empty if not captions[k].startswith("Diagonals")]
    assert shown, captions
    for k in shown:
        named = captions[k].removeprefix("No vertex inside T: ").split()[0]
        claim = next(c for c in captions[k:] if c.startswith("Claim: "))
        assert claim == f"Claim: {named} is an inner diagonal", (captions[k], claim)
    for caption in captions:
        if caption.startswith("T = "):
            corners = caption.removeprefix("T = ").split(":")[0]
            assert caption.endswith(f": {corners[1]} and its two neighbours"), caption
