"""``trex hunt --render``: the heuristic's video on the counterexample found, its mp4's path
printed (issue 13). The render itself is trex render's machinery (``render_into``), stubbed
here; the scene handed to it is built in dry run and checked."""

import json

import pytest
from click.testing import CliRunner

import trex.render_command as render_command
from tests.test_scenes import nodes
from trex.cli import main
from trex.snapshot import build


@pytest.fixture
def rendered(monkeypatch):
    handed = []

    def fake_render_into(make_scene, output, fmt, quality, **_):
        handed.append((make_scene, output, fmt, quality))
        output.write_bytes(b"mp4")
        return output

    monkeypatch.setattr(render_command, "render_into", fake_render_into)
    return handed


@pytest.mark.parametrize(("heuristic", "name"), [
    ("scaling", "scaling"),
    ("examples/my_heuristic.py:biggest_angle", "biggest_angle"),
])
def test_hunt_render_renders_the_video_on_the_counterexample(rendered, tmp_path, monkeypatch,
                                                             heuristic, name):
    monkeypatch.chdir(tmp_path)
    if "/" in heuristic:
        heuristic = str(render_command.SCENES_DIR.parent / heuristic)
    polygon = tmp_path / "found.json"
    result = CliRunner().invoke(main, ["hunt", heuristic, "--budget", "400", "-o",
                                       str(polygon), "--render"])
    assert result.exit_code == 1, result.output
    lines = result.stdout.strip().splitlines()
    assert lines[-1] == f"media/hunt-{name}.mp4"
    assert (tmp_path / "media" / f"hunt-{name}.mp4").read_bytes() == b"mp4"
    (make_scene, _, fmt, quality), = rendered
    assert fmt == "mp4" and quality == "low_quality"
    assert make_scene.spec.polygon == str(polygon)
    final = list(nodes(build(make_scene), final_only=True))
    assert any(n.get("text") == "✗" and n["role"] == "rejected" for n in final)


def test_hunt_render_with_json_keeps_stdout_one_line(rendered, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ["hunt", "scaling", "--budget", "400", "--json",
                                       "--render"])
    assert result.exit_code == 1
    record = json.loads(result.stdout)
    assert record["found"] is True
    assert result.stderr.strip().splitlines()[-1] == "media/hunt-scaling.mp4"
    assert json.loads((tmp_path / "media" / "hunt-scaling.json").read_text())


def test_hunt_render_of_a_crash_renders_nothing_and_says_so(rendered, tmp_path, monkeypatch):
    """A function that raises on the polygon found has no run to show: the finding stands
    (exit 1, the polygon written), and a note says why no video was made."""
    monkeypatch.chdir(tmp_path)
    mine = tmp_path / "mine.py"
    mine.write_text("def bad(polygon):\n    return 1 / 0\n")
    result = CliRunner().invoke(main, ["hunt", f"{mine}:bad", "--budget", "20", "-o",
                                       str(tmp_path / "found.json"), "--render", "--json"])
    assert result.exit_code == 1, result.output
    assert json.loads(result.stdout)["error"].startswith("bad raised ZeroDivisionError")
    assert result.stderr == "note: --render: no video of a run that does not end in a claim\n"
    assert rendered == [] and (tmp_path / "found.json").is_file()


def test_hunt_render_takes_a_path(rendered, tmp_path, monkeypatch):
    """Issue 24 item 12: ``--render FILE.mp4`` writes there (the polygon beside it)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "out").mkdir()
    result = CliRunner().invoke(main, ["hunt", "scaling", "--budget", "400", "--render",
                                       "out/ce.mp4"])
    assert result.exit_code == 1, result.output
    assert result.stdout.strip().splitlines()[-1] == "out/ce.mp4"
    assert (tmp_path / "out" / "ce.mp4").read_bytes() == b"mp4"
    assert json.loads((tmp_path / "out" / "ce.json").read_text())
    assert not (tmp_path / "media").exists()


@pytest.mark.parametrize(("target", "said"), [
    ("ce.gif", "--render writes an mp4"),
    ("no/such/dir/ce.mp4", "no such directory"),
])
def test_hunt_render_path_is_checked_before_the_search(rendered, tmp_path, monkeypatch,
                                                       target, said):
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ["hunt", "scaling", "--budget", "400", "--render",
                                       target])
    assert result.exit_code == 2
    assert result.stdout == "" and rendered == []  # no search, no render
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and said in lines[0] and target in lines[0]


@pytest.mark.parametrize(("algorithm", "base"), [("prune-and-search", "Ears"),
                                                 ("cdt", "TraceScene")])
def test_an_algorithm_with_no_scene_of_its_own_still_has_a_video(algorithm, base):
    """The studio's Video (and ``heuristic_video``) for an algorithm no file in scenes/ plays:
    the scene of its metaphor (prune and search slices fruit as ear clipping does), else a
    plain one; it plays that algorithm's run."""
    from trex.hunt_command import heuristic_video

    cls = heuristic_video(algorithm)
    assert cls.algorithm == algorithm and cls.__mro__[1].__name__ == base
    handed = cls.handed("lecture")
    assert handed.spec.algorithm == algorithm and build(handed).data["plays"]
