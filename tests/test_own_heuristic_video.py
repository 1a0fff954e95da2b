"""``trex render divide_and_conquer --heuristic FILE.py:FUNCTION``: Lennes' video with one's
own heuristic, ending on its first wrong claim's red ✗ and the crossed edge (issue 13).
Built in dry run, as tests/test_scenes.py builds every scene."""

import importlib.util
from pathlib import Path

import pytest
from click.testing import CliRunner

from tests.test_scenes import nodes
from trex.cli import main
from trex.render_command import with_heuristic
from trex.snapshot import build

ROOT = Path(__file__).resolve().parent.parent
WRONG = "examples/my_heuristic.py:biggest_angle"  # wrong on counterexample-twin: B–E × C–D


def divide_and_conquer():
    spec = importlib.util.spec_from_file_location("_dc_scene",
                                                  ROOT / "scenes" / "divide_and_conquer.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.DivideAndConquer


def test_the_video_ends_on_the_first_wrong_claim():
    cls = with_heuristic(divide_and_conquer(), WRONG)
    assert cls.heuristic == WRONG and "biggest_angle" in cls.title
    scene_class = cls.handed("counterexample-twin")
    assert scene_class.spec.heuristic == WRONG
    built = build(scene_class)
    final = list(nodes(built, final_only=True))
    rejected = {n["name"] for n in nodes(built)
                if n["name"].startswith("edge:") and n["role"] == "rejected"}
    assert rejected == {"edge:C–D"}
    assert any(n["name"] == "edge:C–D" and n["role"] == "rejected" for n in final)
    assert any(n.get("text") == "✗" and n["role"] == "rejected" for n in final)


def test_a_right_heuristic_of_ones_own_plays_to_the_end():
    scene_class = with_heuristic(divide_and_conquer(), WRONG).handed("counterexample")
    built = build(scene_class)
    assert not any(n["role"] == "rejected" for n in nodes(built, final_only=True))
    # it ends on the whole triangulation, n − 2 = 3 triangles (issue 22 item 5)
    final = [n["name"].split(":")[0] for n in nodes(built, final_only=True)]
    assert final.count("triangulation") == 3


@pytest.mark.parametrize(("args", "message"), [
    (["scaling", "--heuristic", WRONG], "takes no heuristic"),
    (["divide_and_conquer", "--heuristic", "nonesuch"], "unknown heuristic 'nonesuch'"),
    (["divide_and_conquer", "--heuristic", "examples/my_heuristic.py:nope"],
     "no function 'nope'"),
])
def test_bad_heuristic_is_one_line(args, message, tmp_path):
    result = CliRunner().invoke(main, ["render", *args, "-o", str(tmp_path / "x.mp4")])
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], result.stderr
    assert not (tmp_path / "x.mp4").exists()
