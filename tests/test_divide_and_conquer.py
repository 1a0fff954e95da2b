"""Lennes' divide and conquer: valid with every correct heuristic, a clean stop with a wrong one."""

import pytest
from hypothesis import given, settings

import tracing
from geometry.check import verify_triangulation
from geometry.diagonals import HEURISTICS
from geometry.lennes import divide_and_conquer
from geometry.polygon import Polygon
from geometry.samples import make_sample
from geometry.triangulate import triangulate
from story.registry import correct, wrong
from tests.strategies import generated_polygons

CORRECT, WRONG = correct(), wrong()

NAMED = ["counterexample", "counterexample-twin", "comb", "spiral", "star", "two-ears", "square",
         "lecture"]


@pytest.mark.parametrize("sample", NAMED)
@pytest.mark.parametrize("heuristic", CORRECT)
def test_named_samples(sample, heuristic):
    p = Polygon.from_points(make_sample(sample))
    result = divide_and_conquer(p, heuristic)
    assert result.valid
    assert len(result.triangles) == p.n - 2
    assert verify_triangulation(p, result.triangles)


@settings(max_examples=2000)
@given(generated_polygons(max_n=24))
def test_correct_heuristics_triangulate_generated_polygons(p):
    for heuristic in CORRECT:
        result = divide_and_conquer(p, heuristic)
        assert result.valid, (heuristic, result.failure)
        assert verify_triangulation(p, result.triangles), heuristic


@settings(max_examples=300)
@given(generated_polygons(max_n=24))
def test_wrong_heuristics_never_loop_or_crash(p):
    for heuristic in WRONG:
        result = triangulate(p, "divide-and-conquer", heuristic)
        if result.valid:
            assert verify_triangulation(p, result.triangles)
        else:
            assert result.failure.code in {"crosses", "through-vertex", "outside"}
            assert result.steps <= p.n - 3


def test_counterexample_failure_names_the_crossed_edge():
    p = Polygon.from_points(make_sample("counterexample"))
    with tracing.record() as log:
        result = divide_and_conquer(p, "scaling")
    assert not result.valid
    assert [p.labels[k] for k in result.claim] == ["B", "D"]
    assert [p.labels[k] for k in result.failure.edge] == ["E", "A"]
    assert result.failure.why == "B–D crosses edge E–A at (3.52414, 3.36782)"
    (note,) = log.find(kind="note")
    assert note.name == "bad-diagonal" and note.args["diagonal"] == ["B", "D"]


@pytest.mark.parametrize(
    ("generator", "seed", "heuristic", "claim", "edge"),
    [
        ("random-2opt", 4, "rotation", "D–G", "H–I"),
        ("random-comb", 0, "rotation", "B1–S", "Y–Z"),
        ("random-star", 2, "rotation-ccw", "K–T", "N–O"),
    ],
)
def test_failure_in_a_piece_maps_back_to_the_whole_polygon(generator, seed, heuristic, claim, edge):
    """A wrong claim deep in the recursion is reported in the whole polygon's indices."""
    p = Polygon.from_points(make_sample(generator, 30, seed))
    result = divide_and_conquer(p, heuristic)
    assert not result.valid and result.steps > 1
    assert "–".join(p.labels[k] for k in result.claim) == claim
    assert "–".join(p.labels[k] for k in result.failure.edge) == edge
    assert result.failure.why.startswith(f"{claim} crosses edge {edge} at")
    assert verify_triangulation(p, result.triangles).code == "count"  # stopped part-way


def test_splits_are_traced_and_pieces_shrink():
    p = Polygon.from_points(make_sample("lecture"))
    with tracing.record() as log:
        result = divide_and_conquer(p, "gravity")
    splits = [e for e in log.events if e.kind == "call" and e.name == "split"]
    assert len(splits) == p.n - 3
    triangles = [e for e in log.events if e.kind == "enter" and e.target.startswith("△")]
    assert len(triangles) == len(result.triangles) == p.n - 2
    assert log.state_at(len(log.events) - 1).keys() >= {e.target for e in triangles}


def test_log_is_deterministic_and_round_trips():
    p = Polygon.from_points(make_sample("random-orthogonal", 20, 3))
    texts = []
    for _ in range(2):
        with tracing.record(algorithm="divide-and-conquer", heuristic="gravity") as log:
            divide_and_conquer(p, "gravity")
        texts.append(log.to_json())
    assert texts[0] == texts[1]
    assert tracing.Log.from_json(texts[0]).to_json() == texts[0]


def test_unknown_algorithm():
    p = Polygon.from_points(make_sample("square"))
    with pytest.raises(KeyError, match="expected one of"):
        triangulate(p, "magic")


def test_every_heuristic_name_is_usable():
    """Each name runs its own heuristic, once per diagonal (no other heuristic, no default),
    and on the lecture's polygon every one of them triangulates it."""
    p = Polygon.from_points(make_sample("lecture"))
    for heuristic in HEURISTICS:
        with tracing.record() as log:
            result = triangulate(p, "divide-and-conquer", heuristic)
        called = [e.name for e in log.events if e.kind == "call" and e.name in HEURISTICS]
        assert called == [heuristic] * (p.n - 3), heuristic
        assert result.valid and verify_triangulation(p, result.triangles), heuristic


def test_a_black_box_shows_only_the_question_and_the_diagonal_out():
    """Divide and conquer with its heuristic a black box: per piece, the question, the claim
    that comes out and its verdict, then the split; none of the heuristic's own steps, and
    the same diagonals in the same order as the run shown in full."""
    from story.registry import pseudocode
    from story.runs import run_logged
    from story.storyboard import storyboard

    log = run_logged("divide-and-conquer", "lecture", "gravity")
    boxed = storyboard(log, black_box=True)
    actions = [b.action for b in boxed]
    assert set(actions) == {"polygon", "find", "claim", "verdict"}  # split: pieces' reading
    assert actions.count("find") == actions.count("claim") == 10
    full = [b.labels for b in storyboard(log) if b.action == "claim"]
    assert [b.labels for b in boxed if b.action == "claim"] == full
    asked = boxed[1].row  # the question lights divide and conquer's own row
    assert asked is not None
    assert "find an inner diagonal" in pseudocode("divide-and-conquer")[asked].text
