"""``trex snapshot`` and the pytest plugin, as a user outside the repository meets them: a
scene of one's own snapshotted, checked unchanged (exit 0), checked after a colour change
(exit 1, the mobject and both colours named), from the command and from a pytest test in
another folder that uses only the fixture and syrupy; bad input as one line and exit 2;
the graph does not move when an algorithm's code moves in its file.

Every build is a dry run (about a second for these scenes)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

# Imported before pytester runs a session in this process: it forgets the modules that session
# imported, and manim does not import twice.
import manim  # noqa: F401
import pytest
from click.testing import CliRunner

import metaphors.scene  # noqa: F401
import story.runs  # noqa: F401
import trex.player_command
import trex.render_command
import trex.scene_graph
from trex.cli import main
from trex.snapshot import SceneGraph, assert_same_graph, build, graph_of

pytest_plugins = ["pytester"]

ROOT = Path(__file__).resolve().parents[1]

SCENE = """\
from manim import Circle, Create, FadeIn, Scene, Square, Text


class Mine(Scene):
    def construct(self):
        claim = Circle(radius=1, color="{colour}", name="claim")
        self.play(Create(claim), run_time=1.0)
        self.play(FadeIn(Square(side_length=0.5, name="box")), FadeIn(Text("hello")))
        self.wait(0.5)
"""

GREEN, RED = "#83C167", "#FC6255"


def write_scene(folder: Path, colour: str = GREEN) -> Path:
    path = folder / "my_scene.py"
    path.write_text(SCENE.format(colour=colour), encoding="utf-8")
    return path


def invoke(*args: str):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def trex(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    """The command line in a process of its own, this tree's code, run from ``cwd``."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run([sys.executable, "-m", "trex.cli", *args], capture_output=True,
                          text=True, cwd=cwd, env=env, timeout=300)


# --- the command, as the "Done when" ----------------------------------------------------


def test_snapshot_check_and_a_colour_change_from_the_command(tmp_path):
    write_scene(tmp_path)
    made = trex("snapshot", "my_scene.py:Mine", "-o", "mine.json", cwd=tmp_path)
    assert made.returncode == 0, made.stderr
    stored = json.loads((tmp_path / "mine.json").read_text())
    assert stored["schema"] == "trex-scene-graph/1" and len(stored["plays"]) == 3

    same = trex("snapshot", "my_scene.py:Mine", "--check", "mine.json", cwd=tmp_path)
    assert (same.returncode, same.stdout) == (0, "mine.json: unchanged (3 plays)\n"), same.stderr

    write_scene(tmp_path, RED)
    changed = trex("snapshot", "my_scene.py:Mine", "--check", "mine.json", cwd=tmp_path)
    assert changed.returncode == 1, changed.stderr
    assert f'play 1 (Create claim): mobject "claim" stroke {GREEN} → {RED}' in changed.stdout
    assert f'final: mobject "claim" stroke {GREEN} → {RED}' in changed.stdout
    assert "Traceback" not in changed.stdout + changed.stderr


def test_stdout_is_the_file_and_update_rewrites_it(tmp_path):
    scene = write_scene(tmp_path)
    out = tmp_path / "mine.json"
    code, printed, _ = invoke("snapshot", f"{scene}:Mine")
    assert code == 0
    assert invoke("snapshot", f"{scene}:Mine", "-o", str(out))[:2] == (0, f"{out}\n")
    assert out.read_text() == printed  # stdout is the file's text, newline included
    write_scene(tmp_path, RED)
    code, printed, _ = invoke("snapshot", f"{scene}:Mine", "--check", str(out), "--update")
    assert code == 0 and printed.startswith(f"{out}: updated; the scene graph differs (")
    assert invoke("snapshot", f"{scene}:Mine", "--check", str(out))[0] == 0
    fresh = tmp_path / "new" / "fresh.json"
    fresh.parent.mkdir()
    code, printed, _ = invoke("snapshot", f"{scene}:Mine", "--check", str(fresh), "--update")
    assert (code, printed) == (0, f"{fresh}: written (3 plays)\n")


def test_a_project_scene_by_name_matches_its_own_snapshot():
    stored = ROOT / "tests/__snapshots__/test_scenes/test_scene_graph_matches_snapshot[gravity.Gravity].json"
    code, printed, err = invoke("snapshot", "gravity", "--check", str(stored))
    assert code == 0, printed + err


@pytest.mark.parametrize(("args", "message"), [
    (["nonesuch"], "error: nonesuch: unknown scene 'nonesuch'; known: "),
    (["{scene}:Other"], "error: {scene}:Other: {file}: no function 'Other'"),
    (["{scene}:Mine", "--polygon", "counterexample"],
     "error: {scene}:Mine: Mine is a plain manim Scene: it takes no --polygon"),
    (["gravity", "--polygon", "no-such.json"], "error: no-such.json: "),
    (["gravity", "--log", "missing.json"], "error: missing.json: cannot read: "),
    (["gravity", "--log", "{scene}"], "error: {scene}: not a trex log: "),
    (["gravity", "--check", "missing.json"],
     "error: missing.json: no such file (write it with -o, or --update)"),
    (["gravity", "--check", "{scene}"], "error: {scene}: not JSON: "),
    (["gravity", "--update"], "error: --update rewrites the file of --check: give --check FILE"),
    (["gravity", "-o", "a.json", "--check", "b.json"], "error: -o and --check: give one of them"),
    (["gravity", "--polygon", "star", "--log", "x.json"], "error: --polygon and --log: "),
    (["scaling", "--polygon", "triangle"], "error: triangle: a triangle has no diagonal"),
])
def test_bad_input_is_one_line_and_exit_2(tmp_path, monkeypatch, args, message):
    monkeypatch.chdir(tmp_path)
    scene = write_scene(tmp_path)
    fill = {"scene": str(scene), "file": str(scene)}
    code, printed, err = invoke("snapshot", *[a.format(**fill) for a in args])
    assert code == 2, printed + err
    assert printed == "" and "Traceback" not in err
    assert len(err.splitlines()) == 1 and err.startswith(message.format(**fill)), err


def test_a_scene_that_fails_is_one_line_naming_its_line(tmp_path):
    scene = tmp_path / "broken.py"
    scene.write_text(textwrap.dedent("""\
        from manim import Scene


        class Broken(Scene):
            def construct(self):
                self.wait()
                1 / 0
        """), encoding="utf-8")
    code, printed, err = invoke("snapshot", f"{scene}:Broken")
    assert (code, printed) == (2, "")
    assert err == (f"error: {scene}:Broken: the scene failed while it was built: "
                   "ZeroDivisionError: division by zero (broken.py:7)\n")


def test_a_saved_log_replays_as_the_live_run(tmp_path):
    log = tmp_path / "run.json"
    assert CliRunner().invoke(main, ["log", "scaling", "counterexample",
                                     "-o", str(log)]).exit_code == 0
    live = tmp_path / "live.json"
    assert invoke("snapshot", "scaling", "-o", str(live))[0] == 0
    code, printed, err = invoke("snapshot", "scaling", "--log", str(log), "--check", str(live))
    assert code == 0, printed + err


# --- the graph as a value -----------------------------------------------------------------------


def test_graphs_compare_as_values_and_fail_in_words(tmp_path):
    scene = write_scene(tmp_path)
    green = graph_of(f"{scene}:Mine")
    again = graph_of(f"{scene}:Mine")
    assert green == again and green == again.data and green == again.text
    write_scene(tmp_path, RED)
    red = graph_of(f"{scene}:Mine")
    assert red != green
    stored = green.write(tmp_path / "green.json")
    with pytest.raises(AssertionError) as failure:
        assert_same_graph(red, stored)
    assert str(failure.value).startswith(f"the scene graph differs from {stored} (")
    assert f'mobject "claim" stroke {GREEN} → {RED}' in str(failure.value)


# --- the pytest plugin in a project of its own --------------------------------------------------

USER_TEST = """\
def test_mine(scene_graph, snapshot):
    assert scene_graph("my_scene.py:Mine") == snapshot
"""


def test_the_fixture_beside_syrupy_in_another_folder(pytester):
    write_scene(pytester.path)
    pytester.makepyfile(test_mine=USER_TEST)
    plugin = ["-p", "trex.pytest_plugin", "-p", "no:cacheprovider"]

    first = pytester.runpytest_inprocess(*plugin, "--snapshot-update")
    first.assert_outcomes(passed=1)
    stored = pytester.path / "__snapshots__" / "test_mine" / "test_mine.json"
    code, printed, err = invoke("snapshot", f"{pytester.path / 'my_scene.py'}:Mine")
    assert code == 0, err
    assert stored.read_text() == printed  # the same JSON as `trex snapshot`

    pytester.runpytest_inprocess(*plugin).assert_outcomes(passed=1)

    write_scene(pytester.path, RED)
    changed = pytester.runpytest_inprocess(*plugin)
    changed.assert_outcomes(failed=1)
    changed.stdout.fnmatch_lines([
        "*the scene graph differs from the snapshot test_mine (2 differences):",
        f'*play 1 (Create claim): mobject "claim" stroke {GREEN} → {RED}, fill {GREEN} → {RED}',
        f'*final: mobject "claim" stroke {GREEN} → {RED}, fill {GREEN} → {RED}',
    ])


def test_a_missing_snapshot_is_syrupys_to_report(pytester):
    write_scene(pytester.path)
    pytester.makepyfile(test_mine=USER_TEST)
    missing = pytester.runpytest_inprocess("-p", "trex.pytest_plugin", "-p", "no:cacheprovider")
    missing.assert_outcomes(failed=1)
    missing.stdout.fnmatch_lines(["*Snapshot 'test_mine' does not exist!*"])


# --- what a viewer sees, not where code sits ----------------------------------------------------


def test_moving_a_heuristic_down_its_file_changes_nothing(tmp_path):
    source = (ROOT / "examples" / "my_heuristic.py").read_text(encoding="utf-8")
    first, moved = tmp_path / "a" / "mine.py", tmp_path / "b" / "mine.py"
    for path, text in ((first, source), (moved, "# five lines\n\n\n\n\n" + source)):
        path.parent.mkdir()
        path.write_text(text, encoding="utf-8")
    before = graph_of(f"{first}:biggest_angle")
    assert '"name": "code:1"' in before.text
    assert_same_graph(graph_of(f"{moved}:biggest_angle"), before)


def test_moving_a_built_in_algorithm_down_its_file_changes_nothing(tmp_path, monkeypatch):
    """Its source lines and the lines the log names both shift by seven: the same graph."""
    from metaphors import panel
    from metaphors.pseudocode import source_of
    from trex.render_command import load_scene_class, resolve_scene

    cls = load_scene_class(*resolve_scene("scaling"))
    live = build(cls.handed())
    log = json.loads(cls.default_spec().log().to_json())
    for event in log["events"]:
        if event.get("line") is not None:
            event["line"] += 7
    saved = tmp_path / "moved.json"
    saved.write_text(json.dumps(log), encoding="utf-8")
    monkeypatch.setattr(panel, "source_of",
                        lambda name: tuple((n + 7, text) for n, text in source_of(name)))
    assert_same_graph(build(cls.handed(saved=[str(saved)])), live)


def test_a_graph_reads_back_as_itself(tmp_path):
    graph = SceneGraph({"schema": "trex-scene-graph/1", "plays": [], "final": []})
    assert SceneGraph.read(graph.write(tmp_path / "g.json")) == graph
