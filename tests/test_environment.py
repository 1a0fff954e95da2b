"""A run is a value: one module reads TREX_POLYGON and TREX_LOG, everything else is handed a
RunSpec (story/spec.py, story/environment.py, metaphors.scene.SpecScene)."""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from story.environment import (
    LOG,
    POLYGON,
    environment_values,
    spec_from_environment,
    specs_from_environment,
)
from story.spec import RunSpec
from trex import chapter_pool, chapters, render_command
from trex.chapter_command import chapter
from trex.cli import main
from trex.render_command import load_scene_class, scene_input
from usercode.limits import call_timeout, set_call_timeout

ROOT = Path(__file__).resolve().parents[1]
#: The packages of the library, and the scene files.
LIBRARY = ("tracing", "geometry", "story", "rendering", "metaphors", "trex", "scenes")
ADAPTER = "story/environment.py"
READS_ENVIRONMENT = re.compile(r"\benviron\b|\b(?:get|put|unset)env\b")


def scene(file: str, name: str | None = None) -> type:
    return load_scene_class(ROOT / "scenes" / f"{file}.py", name)


def instance(cls: type):
    """The scene object without building it (its run is a question for the class)."""
    return cls.__new__(cls)


@pytest.fixture
def environment(monkeypatch):
    """TREX_POLYGON and TREX_LOG unset; the test sets what it needs."""
    for name in (POLYGON, LOG):
        monkeypatch.delenv(name, raising=False)
    return monkeypatch


# --- one reader ------------------------------------------------------------------------------------


def test_only_the_adapter_reads_the_environment():
    readers = sorted(
        path.relative_to(ROOT).as_posix()
        for package in LIBRARY for path in (ROOT / package).rglob("*.py")
        if READS_ENVIRONMENT.search(path.read_text(encoding="utf-8")))
    assert readers == [ADAPTER]


def test_the_adapter_reads_both_variables(environment):
    environment.setenv(POLYGON, "star")
    environment.setenv(LOG, "")  # empty counts as unset
    assert environment_values() == {POLYGON: "star"}
    environment.setenv(LOG, "run.json")
    spec = spec_from_environment(RunSpec("gravity", "gravity-snag"))
    assert (spec.polygon, spec.saved) == ("star", "run.json")


def test_several_runs_read_one_log_each(environment):
    runs = (RunSpec("scaling", "counterexample"), RunSpec("rotation", "counterexample"))
    assert specs_from_environment(runs) == runs
    environment.setenv(POLYGON, "star")  # the runs name their own polygons
    assert specs_from_environment(runs) == runs
    environment.setenv(LOG, os.pathsep.join(["a.json", "b.json"]))
    assert [s.saved for s in specs_from_environment(runs)] == ["a.json", "b.json"]
    assert [s.polygon for s in specs_from_environment(runs)] == ["counterexample"] * 2
    environment.setenv(LOG, "a.json")
    with pytest.raises(ValueError, match="TREX_LOG lists 1 logs; this scene plays 2 runs"):
        specs_from_environment(runs)


# --- RunSpec ---------------------------------------------------------------------------------------


def test_a_saved_log_replays_the_live_run(tmp_path):
    live = RunSpec("divide-and-conquer", "lecture", heuristic="rotation-correct")
    path = tmp_path / "run.json"
    live.log().save(path)
    assert live.replaying(str(path)).log().to_json() == live.log().to_json()
    assert live.replaying(str(path)).on("star").saved is None


def test_a_spec_is_a_frozen_value():
    spec = RunSpec("scaling", "counterexample")
    assert spec == RunSpec("scaling", "counterexample") and hash(spec) == hash(spec.on(spec.polygon))
    with pytest.raises(AttributeError):
        spec.polygon = "star"  # type: ignore[misc]  # on purpose: it must raise
    with pytest.raises(TypeError):
        RunSpec("scaling", "counterexample", None)  # type: ignore[misc]  # keywords after two


# --- scenes: handed a spec, or (plain manim) the environment --------------------------------------


def test_a_scene_handed_nothing_reads_the_environment(environment):
    gravity, counterexample = scene("gravity"), scene("counterexample")
    assert instance(gravity).run_spec() == gravity.default_spec() == RunSpec("gravity",
                                                                            "gravity-snag")
    environment.setenv(POLYGON, "star")
    assert instance(gravity).run_spec() == RunSpec("gravity", "star")
    assert instance(scene("polygon")).run_spec().polygon == "star"
    assert instance(scene("chapters/ch1_overview")).lecture_polygon() == "star"
    assert instance(counterexample).run_specs() == counterexample.default_specs()
    environment.setenv(LOG, "run.json")
    assert instance(gravity).run_spec().saved == "run.json"


def test_a_handed_scene_reads_no_environment(environment):
    environment.setenv(POLYGON, "star")
    environment.setenv(LOG, "run.json")
    gravity = scene("gravity")
    handed = gravity.handed()
    assert handed.__name__ == "Gravity" and issubclass(handed, gravity)
    assert instance(handed).run_spec() == gravity.default_spec()
    assert instance(gravity.handed("two-ears")).run_spec() == RunSpec("gravity", "two-ears")
    assert instance(gravity.handed(saved=["a.json"])).run_spec().saved == "a.json"
    chapter = scene("chapters/ch1_overview").handed()
    assert instance(chapter).lecture_polygon() == "lecture"
    counterexample = scene("counterexample")
    assert instance(counterexample.handed("star")).run_specs() == counterexample.default_specs()
    saved = [f"{k}.json" for k in range(len(counterexample.runs))]
    assert [s.saved for s in instance(counterexample.handed(saved=saved)).run_specs()] == saved
    with pytest.raises(ValueError, match="1 saved logs handed"):
        counterexample.handed(saved=["a.json"])


def test_trex_hands_the_polygon_or_what_the_environment_says(environment):
    gravity = scene("gravity")
    assert scene_input(gravity, "star").spec == RunSpec("gravity", "star")
    assert scene_input(gravity, None).spec == gravity.default_spec()
    environment.setenv(POLYGON, "two-ears")
    assert scene_input(gravity, None).spec == RunSpec("gravity", "two-ears")
    assert scene_input(gravity, "star").spec == RunSpec("gravity", "star")
    from manim import Scene

    assert scene_input(Scene, "star") is Scene  # takes no run: as it is


def test_trex_render_hands_the_spec_and_sets_no_variable(tmp_path, environment):
    seen = {}

    def fake_render(cls, output, fmt, quality, **kw):
        seen.update(spec=cls.spec, env={k: os.environ.get(k) for k in (POLYGON, LOG)})
        output.write_bytes(b"x")
        return output

    environment.setattr(render_command, "render_into", fake_render)
    environment.setenv(LOG, "run.json")
    result = CliRunner().invoke(main, ["render", "gravity", "--polygon", "star", "-o",
                                       str(tmp_path / "g.mp4")])
    assert result.exit_code == 0, result.output
    assert seen == {"spec": RunSpec("gravity", "star"), "env": {POLYGON: None, LOG: "run.json"}}


def test_a_lecture_chapter_gets_the_polygon_as_an_argument(tmp_path, environment):
    started = {}

    class Process:
        def __init__(self, command, **kwargs):
            started.update(command=command, kwargs=kwargs)

    environment.setattr(chapter_pool.subprocess, "Popen", Process)
    one = chapters.Chapter(1, "gravity", "Gravity", "scenes/gravity.py", None)
    before = call_timeout()
    set_call_timeout(2.5)  # as the lecture's --call-timeout 2.5 sets it
    try:
        chapter_pool._start(0, one, tmp_path, tmp_path, "l", "star")
    finally:
        set_call_timeout(before)
    assert started["command"][2:4] == ["trex", "chapter"]
    given = chapter.make_context("chapter", started["command"][4:]).params
    assert (given["quality"], given["polygon"], given["panel"]) == ("l", "star", None)
    # the lecture's time limit on functions of one's own is a named option, not a variable
    assert started["command"][-1] == "--call-timeout=2.5"
    assert "env" not in started["kwargs"]  # the child inherits ours, untouched
