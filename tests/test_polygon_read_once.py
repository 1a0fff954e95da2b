"""A polygon given by ``--polygon`` is read once, by one rule, and handed to the scene.

Issue 24 item 1: ``trex render holes:HolesSweep --polygon my-holes.json`` refused every
polygon with holes, because the command read the polygon under one rule and the scene read
its path again under another. Now the command reads it (holes allowed only for the
algorithms that take them: :func:`story.runs.fit_for`) and hands the scene a
:class:`story.spec.RunSpec` that carries it. Each test removes the file once the command has
checked it: a scene that read it again would fail.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

from geometry.errors import HolesNotSupportedError
from story.spec import RunSpec
from trex import player_command, render_command, slides_command
from trex import snapshot as snapshot_module
from trex.cli import main

HOLES = Path(__file__).parent / "data" / "holes" / "two-holes.json"
HOLES_SCENE = "holes:HolesSweep"  # the monotone sweep: it takes holes


def run(*args):
    result = CliRunner().invoke(main, [str(a) for a in args])
    return result.exit_code, result.stdout, result.stderr


@pytest.fixture
def holed(tmp_path) -> Path:
    """A polygon with two holes, in a file of the test's own (the tests remove it)."""
    path = tmp_path / "my-holes.json"
    shutil.copy(HOLES, path)
    return path


def assert_plays_the_holes(cls: type, polygon: Path) -> None:
    """``cls`` was handed the polygon read, and plays it with the file gone."""
    polygon.unlink()
    spec = cls.spec
    assert spec.polygon == str(polygon) and spec.polygon_read.hole_count == 2
    log = spec.log()  # reads no file: it is gone
    assert log.meta["polygon"] == str(polygon)
    assert log.meta["algorithm"] == "monotone" and "pseudocode" in log.meta  # the holes' rows


def test_a_spec_read_once_plays_without_its_file(holed):
    spec = RunSpec("monotone", str(holed)).read()
    holed.unlink()
    assert spec.polygon_read.hole_count == 2
    assert spec.log().meta["polygon"] == str(holed)


def test_the_one_rule_refuses_holes_for_a_run_that_cannot_take_them(holed):
    with pytest.raises(HolesNotSupportedError, match="gravity needs a simple polygon and this "
                                                     "one has 2 holes"):
        RunSpec("gravity", str(holed)).read()


def test_render_takes_a_polygon_with_holes(holed, tmp_path, monkeypatch):
    seen = []

    def fake_render(make_scene, output, fmt, quality, **kw):
        assert_plays_the_holes(make_scene, holed)
        seen.append(make_scene)
        output.write_bytes(b"x")
        return output

    monkeypatch.setattr(render_command, "render_into", fake_render)
    out = tmp_path / "holes.mp4"
    code, stdout, stderr = run("render", HOLES_SCENE, "--polygon", holed, "-o", out)
    assert (code, stderr) == (0, "")
    assert stdout == f"{out}\n" and len(seen) == 1


def test_render_takes_one_from_the_environment_too(holed, tmp_path, monkeypatch):
    monkeypatch.setattr(render_command, "render_into",
                        lambda cls, output, *a, **k: assert_plays_the_holes(cls, holed))
    monkeypatch.setenv("TREX_POLYGON", str(holed))
    code, _, stderr = run("render", HOLES_SCENE, "-o", tmp_path / "x.mp4")
    assert (code, stderr) == (0, "")


def test_render_refuses_holes_for_a_scene_that_cannot_take_them(holed, tmp_path, monkeypatch):
    monkeypatch.setattr(render_command, "render_into", lambda *a, **k: pytest.fail("rendered"))
    code, _, stderr = run("render", "gravity", "--polygon", holed, "-o", tmp_path / "x.mp4")
    assert code == 2
    assert stderr == (f"error: {holed}: gravity needs a simple polygon and this one has 2 "
                      "holes; ear-clipping, monotone and cdt triangulate polygons with holes\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == [holed.name]


def test_snapshot_takes_a_polygon_with_holes(holed, tmp_path, monkeypatch):
    built = snapshot_module.build

    def build_without_the_file(handed):
        assert_plays_the_holes(handed, holed)
        return built(handed)  # the real graph, with the file gone

    monkeypatch.setattr(snapshot_module, "build", build_without_the_file)
    out = tmp_path / "graph.json"
    code, stdout, stderr = run("snapshot", HOLES_SCENE, "--polygon", holed, "-o", out)
    assert (code, stderr) == (0, "")
    assert stdout == f"{out}\n" and '"plays"' in out.read_text()


def test_player_takes_a_polygon_with_holes(holed, tmp_path, monkeypatch):
    def fake_build(cls, log, subtitle, target):
        assert_plays_the_holes(cls, holed)
        assert subtitle == f"Monotone partition on {holed}" and log.meta["polygon"] == str(holed)
        target.mkdir()
        (target / "index.html").write_text("page")
        return target / "index.html"

    monkeypatch.setattr(player_command, "_build", fake_build)
    out = tmp_path / "player"
    code, stdout, stderr = run("player", HOLES_SCENE, "--polygon", holed, "-o", out)
    assert (code, stderr) == (0, "")
    assert stdout == f"{out / 'index.html'}\n"


def test_slides_take_a_polygon_with_holes(holed, tmp_path, monkeypatch):
    def fake_slides(cls, quality, subtitle, target):
        assert_plays_the_holes(cls, holed)
        assert subtitle == f"Monotone partition on {holed}"
        target.mkdir()
        return []

    monkeypatch.setattr(slides_command, "_scene_slides", fake_slides)
    out = tmp_path / "slides"
    code, stdout, stderr = run("slides", HOLES_SCENE, "--polygon", holed, "-o", out)
    assert (code, stderr) == (0, "")
    assert stdout.endswith(f"{out / 'index.html'}\n")


def test_log_takes_a_polygon_with_holes(holed, tmp_path):
    out = tmp_path / "run.json"
    code, stdout, stderr = run("log", "monotone", holed, "-o", out)
    assert (code, stderr) == (0, "")
    assert stdout.startswith(f"{out}: ")
    code, _, stderr = run("log", "gravity", holed, "-o", tmp_path / "never.json")
    assert code == 2 and "gravity needs a simple polygon and this one has 2 holes" in stderr
    assert not (tmp_path / "never.json").exists()


# --- the checks before rendering: one run_once, on the polygon read (issue 23) ---------------------


def test_scene_run_is_the_scenes_run_on_the_polygon_read(tmp_path):
    from geometry.io import read_any_polygon
    from scenes.divide_and_conquer import DivideAndConquer
    from scenes.scaling import Scaling
    from trex.render_command import run_once, scene_run

    path = tmp_path / "star.json"
    path.write_text("[[0, 0], [4, 1], [8, 0], [7, 4], [8, 8], [4, 7], [0, 8], [1, 4]]")
    spec = scene_run(Scaling, str(path), read_any_polygon(path))
    path.unlink()  # the run reads no file: it plays the shape handed
    assert (spec.algorithm, spec.heuristic) == ("scaling", None)
    assert run_once(spec).meta["polygon"] == str(path)
    assert scene_run(DivideAndConquer, "star").heuristic == DivideAndConquer.heuristic
    assert scene_run(type("Plain", (), {}), "star") is None  # a scene that runs nothing


def test_a_chapter_is_checked_on_the_polygon_the_command_read(tmp_path, capsys):
    """``check_chapters`` with the shape read: a scene played as a chapter runs on it, and a
    polygon it rejects is one line and exit 2, naming the polygon."""
    import click

    from geometry.io import read_any_polygon
    from trex.chapters import check_chapters, pick_chapters

    path = tmp_path / "triangle.json"
    path.write_text("[[0, 0], [4, 0], [0, 4]]")
    shape = read_any_polygon(path)
    path.unlink()
    with pytest.raises(click.exceptions.Exit) as stopped:
        check_chapters(pick_chapters("scaling", None), str(path), shape)
    assert stopped.value.exit_code == 2
    assert capsys.readouterr().err == f"error: {path}: a triangle has no diagonal\n"
    check_chapters(pick_chapters("scaling", None), "counterexample", read_any_polygon("counterexample"))
