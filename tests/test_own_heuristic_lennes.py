"""Your own heuristic in divide and conquer (issue 13): ``trex triangulate --algorithm
divide-and-conquer --heuristic FILE.py:FUNCTION`` runs Lennes with it on each piece, to a
verified triangulation or to its first wrong claim; the log treats it as a heuristic."""

import json
import textwrap

import pytest
from click.testing import CliRunner

from geometry.check import is_inner_diagonal, verify_triangulation
from geometry.polygon import Polygon
from geometry.samples import make_sample
from story.spec import RunSpec
from story.storyboard import storyboard
from trex.cli import main

MINE = '''
from geometry.diagonals import HEURISTICS
from geometry.frame import candidates_in_triangle, leftmost_vertex, triangle_at


def like_gravity(polygon):
    """Gravity, by another name."""
    return HEURISTICS["gravity"](polygon)


def nearest_to_c(polygon):
    """Claim BD for the candidate D nearest to C."""
    b = leftmost_vertex(polygon)
    t = triangle_at(polygon, b)
    candidates = candidates_in_triangle(polygon, t)
    if not candidates:
        return t.a, t.c
    cx, cy = t.c.point
    return b, min(candidates, key=lambda d: (d.point[0] - cx) ** 2 + (d.point[1] - cy) ** 2)


def raises(polygon):
    return 1 / 0


def forever(polygon):
    while True:
        pass
'''


@pytest.fixture
def mine(tmp_path):
    path = tmp_path / "mine.py"
    path.write_text(textwrap.dedent(MINE))
    return str(path)


def run(*args):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_a_right_heuristic_of_ones_own_triangulates(mine):
    code, out, _ = run("triangulate", "lecture", "random-2opt:25:3", "gravity-snag",
                       "--algorithm", "divide-and-conquer",
                       "--heuristic", f"{mine}:like_gravity", "--json")
    assert code == 0
    for line in out.splitlines():
        record = json.loads(line)
        assert record["valid"] is True and record["why"] is None
        p = Polygon.from_points(record["vertices"])
        local = [tuple(p.source.index(k) for k in t) for t in record["triangles"]]
        assert len(local) == p.n - 2 and verify_triangulation(p, local)


def test_a_wrong_heuristic_of_ones_own_stops_at_its_first_wrong_claim(mine):
    code, out, _ = run("triangulate", "counterexample-twin", "--heuristic",
                       f"{mine}:nearest_to_c", "--json")
    assert code == 1  # as for a wrong built-in: a finding (the run stopped), the input was fine
    record = json.loads(out)
    assert record["valid"] is False and record["triangles"] == []
    assert record["why"] == "B–E crosses edge C–D at (3.52414, -3.36782)"
    code, out, _ = run("triangulate", "counterexample-twin", "--heuristic",
                       f"{mine}:nearest_to_c")
    assert out.strip() == ("counterexample-twin: divide-and-conquer: stopped after 0 "
                           "triangles: B–E crosses edge C–D at (3.52414, -3.36782)")


def test_the_readmes_example_fails_like_a_wrong_builtin():
    code, out, _ = run("triangulate", "counterexample", "counterexample-twin", "--heuristic",
                       "examples/my_heuristic.py:biggest_angle")
    assert code == 1  # the twin stopped: a finding
    right, wrong = out.splitlines()
    assert right == "counterexample: divide-and-conquer: 3 triangles, valid"
    assert wrong.endswith("stopped after 0 triangles: B–E crosses edge C–D at "
                          "(3.52414, -3.36782)")
    p = Polygon.from_points(make_sample("counterexample-twin"))
    assert not is_inner_diagonal(p, p.labels.index("B"), p.labels.index("E"))


@pytest.mark.parametrize(("function", "message"), [
    ("raises", "raises raised ZeroDivisionError"),
    ("nothing", "no function 'nothing'"),
])
def test_a_broken_heuristic_is_one_line_and_exit_2(mine, function, message):
    code, _, err = run("triangulate", "lecture", "--heuristic", f"{mine}:{function}")
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and message in lines[0] and "Traceback" not in err


def test_a_looping_heuristic_is_stopped(mine):
    code, _, err = run("triangulate", "lecture", "--heuristic", f"{mine}:forever",
                       "--call-timeout", "0.3")
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "forever did not finish within 0.3 s" in lines[0]


def test_the_storyboard_judges_its_claims_on_each_piece(mine):
    log = RunSpec("divide-and-conquer", "counterexample-twin",
                  heuristic=f"{mine}:nearest_to_c").log()
    assert log.meta["heuristic_function"] == "nearest_to_c"
    beats = storyboard(log)
    verdicts = [b for b in beats if b.action == "verdict"]
    assert len(verdicts) == 1 and not verdicts[0].ok
    assert verdicts[0].edge == ("C", "D")
    rows = [b.row for b in beats if b.action in ("claim", "verdict")]
    assert rows == [1, 1]  # "else find an inner diagonal of P"
    right = storyboard(RunSpec("divide-and-conquer", "lecture",
                               heuristic=f"{mine}:like_gravity").log())
    assert sum(b.action == "verdict" and b.ok for b in right) == 10
