"""trex diagonal / triangulate / log: JSON lines in input order, bad input as one line, exit 2."""

import json
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

import tracing
from geometry.check import is_inner_diagonal, verify_triangulation
from geometry.polygon import Polygon
from geometry.samples import make_sample
from trex.cli import main

CE = make_sample("counterexample")


def run(*args):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_diagonal_json_in_input_order():
    code, out, _ = run("diagonal", "counterexample", "counterexample-twin", "--heuristic",
                       "scaling", "--json")
    assert code == 1  # a finding: the claims are not inner diagonals
    first, second = (json.loads(line) for line in out.splitlines())
    assert first["polygon"] == "counterexample"
    assert first["vertices"] == [list(map(float, p)) for p in CE]
    assert first["inner"] is False
    assert first["why"].startswith("B–D crosses edge E–A")
    # Independent check in input indices: the claim joins input points 0 and 2.
    assert sorted(first["diagonal"]) == [0, 2]
    p = Polygon.from_points(first["vertices"])
    i, j = (p.source.index(k) for k in first["diagonal"])
    assert not is_inner_diagonal(p, i, j)
    assert second["polygon"] == "counterexample-twin" and second["inner"] is False


@pytest.mark.parametrize("heuristic", ["gravity", "translation-correct", "scaling-walled"])
def test_correct_heuristics_through_the_cli(heuristic):
    code, out, _ = run("diagonal", "lecture", "random-2opt:30:4", "--heuristic", heuristic,
                       "--json")
    assert code == 0
    for line in out.splitlines():
        record = json.loads(line)
        assert record["inner"] is True and record["why"] is None


def test_triangulate_json_is_valid_in_input_order():
    code, out, _ = run("triangulate", "random-2opt:25:3", "--algorithm", "divide-and-conquer",
                       "--heuristic", "rotation-correct", "--json")
    assert code == 0
    record = json.loads(out)
    p = Polygon.from_points(record["vertices"])
    local = [tuple(p.source.index(k) for k in t) for t in record["triangles"]]
    assert record["valid"] is True and record["why"] is None
    assert verify_triangulation(p, local)


def test_triangulate_stops_with_a_wrong_heuristic():
    code, out, _ = run("triangulate", "counterexample", "--heuristic", "translation", "--json")
    assert code == 1  # a finding: it stopped early
    record = json.loads(out)
    assert record["valid"] is False and record["triangles"] == []
    assert record["why"].startswith("B–D crosses edge E–A")


def test_human_lines():
    code, out, _ = run("triangulate", "lecture", "counterexample", "--heuristic", "rotation")
    assert code == 1  # one of them stopped
    assert out.splitlines() == [
        "lecture: divide-and-conquer: 11 triangles, valid",
        "counterexample: divide-and-conquer: stopped after 0 triangles: "
        "B–D crosses edge E–A at (3.52414, 3.36782)",
    ]


@pytest.mark.parametrize(("args", "code"), [
    (["diagonal", "lecture", "--heuristic", "gravity"], 0),
    (["diagonal", "counterexample", "--heuristic", "scaling"], 1),
    (["diagonal", "lecture", "counterexample", "--heuristic", "scaling"], 1),
    (["diagonal", "counterexample", "nosuch.json", "--heuristic", "scaling"], 2),
    (["triangulate", "lecture", "--heuristic", "rotation-correct"], 0),
    (["triangulate", "counterexample", "--heuristic", "rotation"], 1),
    (["triangulate", "counterexample", "tests/data/bad/bow-tie.json", "--heuristic",
      "rotation"], 2),
])
def test_exit_status_says_what_was_found(args, code):
    """Issue 24 item 9: 0 fine, 1 a finding (a claim that is not an inner diagonal, a stopped
    triangulation), 2 bad input (outweighing a finding)."""
    assert run(*args)[0] == code


def test_one_triangle_is_said_in_the_singular():
    code, out, _ = run("triangulate", "triangle", "square", "--algorithm", "ear-clipping")
    assert code == 0
    assert out.splitlines() == ["triangle: ear-clipping: 1 triangle, valid",
                                "square: ear-clipping: 2 triangles, valid"]


@pytest.mark.parametrize("args", [
    ["triangulate", "lecture", "--algorithm", "ear-clipping", "--heuristic", "rotation"],
    ["triangulate", "lecture", "--algorithm", "monotone", "--heuristic", "gravity"],
    ["log", "ear-clipping", "lecture", "--heuristic", "rotation", "-o", "/tmp/never.json"],
])
def test_a_heuristic_for_an_algorithm_that_takes_none_is_refused(args):
    """Issue 24 item 9: it was silently ignored; refused as trex render refuses it."""
    code, out, err = run(*args)
    algorithm = args[args.index("--algorithm") + 1] if "--algorithm" in args else args[1]
    assert code == 2 and out == ""
    assert err == (f"error: --heuristic: {algorithm} takes no heuristic (only "
                   "divide-and-conquer does)\n")


@pytest.mark.parametrize(("args", "line"), [
    (["diagonal", "lecture", "--heuristic", "gravty"],
     "error: unknown heuristic 'gravty'; did you mean 'gravity'? (try 'main diagonal --help')"),
    (["hunt", "magic"], "error: unknown heuristic 'magic' (try 'main hunt --help')"),
    (["triangulate", "lecture", "--algorithm", "ear"],
     "error: unknown algorithm 'ear'; did you mean one of ear-clipping-naive, ear-clipping? "
     "(try 'main triangulate --help')"),
    (["diagonal", "lecture", "--heuristic", "nope.py:f"], "error: nope.py: no such file"),
])
def test_a_bad_heuristic_argument_is_one_short_line(args, line):
    """Issue 24 item 12: no 150-character 'Invalid value for '[scaling|rotation|…]'' first."""
    code, out, err = run(*args)
    assert code == 2 and out == "" and err == line + "\n"
    assert "Invalid value" not in err


def test_log_round_trips_and_is_deterministic(tmp_path):
    a, b = tmp_path / "a.json", tmp_path / "b.json"
    for path in (a, b):
        code, out, _ = run("log", "gravity", "counterexample", "-o", str(path))
        assert code == 0 and out.startswith(str(path))
    assert a.read_bytes() == b.read_bytes()
    log = tracing.Log.load(a)
    assert log.meta == {"algorithm": "gravity", "polygon": "counterexample", "shown": "gravity_at"}
    assert "drop_ball" in {e.name for e in log.events}
    code, _, _ = run("log", "divide-and-conquer", "lecture", "--heuristic", "gravity", "-o",
                     str(a))
    assert code == 0 and tracing.Log.load(a).meta["heuristic"] == "gravity"


@pytest.mark.parametrize(("args", "live"), [
    (["gravity", "gravity-snag"], ("gravity", "gravity-snag")),
    (["scaling", "counterexample"], ("scaling", "counterexample")),
    (["divide-and-conquer", "lecture", "--heuristic", "rotation-correct"],
     ("divide-and-conquer", "lecture", "rotation-correct")),
])
def test_log_is_the_log_a_scene_records(tmp_path, args, live):
    """A scene replaying a `trex log` file (TREX_LOG) plays exactly what its live run plays."""
    from story.runs import run_logged

    path = tmp_path / "run.json"
    code, _, _ = run("log", *args, "-o", str(path))
    assert code == 0
    assert path.read_text() == run_logged(*live).to_json()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["diagonal", "triangle", "--heuristic", "scaling"], "triangle: a triangle has no diagonal"),
        (["diagonal", "nosuch.json", "--heuristic", "scaling"], "nosuch.json"),
        (["diagonal", "counterexample", "--heuristic", "magic"], "magic"),
        (["triangulate", "tests/data/bad/bow-tie.json"], "cross"),
        (["log", "gravity", "tests/data/bad/bow-tie.json", "-o", "/tmp/never.json"], "cross"),
        (["log", "gravity", "triangle", "-o", "/tmp/never.json"], "no diagonal"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args, message):
    proc = subprocess.run([sys.executable, "-m", "trex", *args], capture_output=True, text=True)
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error:") and message in lines[0]
    assert "Traceback" not in proc.stderr


def test_a_bad_log_run_leaves_no_file(tmp_path):
    out = tmp_path / "log.json"
    code, _, _ = run("log", "gravity", "triangle", "-o", str(out))
    assert code == 2 and not out.exists() and not list(tmp_path.iterdir())


def test_log_of_divide_and_conquer_with_a_heuristic_of_ones_own(tmp_path):
    """`trex log --heuristic FILE.py:FUNCTION`, as `trex render --heuristic` takes it: the log
    names the heuristic and its traced function, so a scene replays it as its own."""
    examples = Path(__file__).resolve().parents[1] / "examples"
    spec = f"{examples / 'my_heuristic.py'}:biggest_angle"
    out = tmp_path / "run.json"
    code, _, err = run("log", "divide-and-conquer", "lecture", "--heuristic", spec, "-o",
                       str(out))
    assert code == 0, err
    meta = json.loads(out.read_text())["meta"]
    assert (meta["heuristic"], meta["heuristic_function"]) == (spec, "biggest_angle")
    bad = tmp_path / "bad.json"
    code, _, err = run("log", "divide-and-conquer", "lecture", "--heuristic",
                       f"{examples / 'nope.py'}:x", "-o", str(bad))
    assert code == 2 and err.count("\n") == 1 and "no such file" in err
    assert not bad.exists()


def test_run_commands_do_not_import_manim():
    code = ("import sys; from click.testing import CliRunner; from trex.cli import main; "
            "r = CliRunner().invoke(main, ['triangulate', 'lecture']); "
            "assert r.exit_code == 0, r.output; assert 'manim' not in sys.modules; print('ok')")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.stdout.strip() == "ok", proc.stderr
