"""What trex asks of a scene class is a protocol (story/scene_kinds.py), checked with
isinstance; what a scene notes while it renders is declared state (metaphors/recorded.py),
set up in ``__init__``, with nothing stashed on the Scene by name."""

from __future__ import annotations

import tempfile

import pytest
from manim import Scene, tempconfig

from metaphors.lecture import LectureScene
from metaphors.recorded import (
    Recorded,
    captions_of,
    end_steps,
    lead_in,
    mark_step,
    recorded_steps,
    steps_end,
)
from metaphors.scene import SequenceScene, TraceScene
from scenes.counterexample import Counterexample
from scenes.polygon import PolygonScene
from scenes.scaling import Scaling
from story.scene_kinds import (
    ChapterScene,
    Handed,
    SeveralRuns,
    WithHeuristic,
    WithPanel,
    algorithm_of,
    heuristic_of,
    plays_one,
    plays_several,
)
from trex.render_command import scene_input, with_heuristic
from trex.snapshot import plays_own_polygons, takes_input


class Plain(Scene):
    """A user's own manim Scene: trex hands it nothing."""

    def construct(self) -> None:
        pass


# --- the protocols ---------------------------------------------------------------------------


def test_a_one_run_scene_meets_the_protocols_of_one_run():
    assert isinstance(Scaling, Handed) and isinstance(Scaling, WithPanel)
    assert isinstance(Scaling, WithHeuristic) and not isinstance(Scaling, SeveralRuns)
    assert plays_one(Scaling) and not plays_several(Scaling)
    assert algorithm_of(Scaling) == "scaling" and heuristic_of(Scaling) is None


def test_a_scene_of_several_runs_names_its_polygons():
    assert isinstance(Counterexample, SeveralRuns) and plays_several(Counterexample)
    assert not plays_one(Counterexample) and plays_own_polygons(Counterexample)
    assert not plays_several(SequenceScene)  # no runs of its own: nothing to play


def test_a_scene_that_is_handed_a_polygon_but_has_no_panel():
    assert isinstance(PolygonScene, Handed) and not isinstance(PolygonScene, WithPanel)
    assert algorithm_of(PolygonScene) == "cdt" and takes_input(PolygonScene)


def test_a_plain_scene_meets_none_and_is_played_as_it_is():
    for protocol in (Handed, SeveralRuns, WithPanel, WithHeuristic, ChapterScene):
        assert not isinstance(Plain, protocol), protocol
    assert algorithm_of(Plain) is None and heuristic_of(Plain) is None
    assert not takes_input(Plain) and scene_input(Plain, None, "source") is Plain
    with pytest.raises(ValueError, match="takes no heuristic"):
        with_heuristic(Plain, "scaling")


def test_handing_goes_through_the_protocol():
    handed = scene_input(Scaling, "star", "source")
    assert handed.spec.polygon == "star" and handed.panel == "source"
    assert issubclass(handed, Scaling) and isinstance(handed, Handed)


def test_a_chapter_is_a_chapter_scene():
    from scenes.chapters.ch3_gravity import Gravity

    assert isinstance(Gravity, ChapterScene) and Gravity.chapter_title.startswith("3.")
    assert isinstance(LectureScene, ChapterScene) and not isinstance(Scaling, ChapterScene)


def test_a_lecture_chapter_is_named_by_its_class_slug(tmp_path, monkeypatch):
    """The class's ``slug`` names the chapter; a file named otherwise, or a class that is no
    chapter, is said in one line."""
    from trex import chapters

    monkeypatch.setattr(chapters, "CHAPTERS_DIR", tmp_path)
    monkeypatch.setattr(chapters, "REPO", tmp_path)
    chapter = ("from metaphors.lecture import LectureScene\n\n"
               "class Gravity(LectureScene):\n"
               "    chapter_title = '3. Gravity'\n    slug = '{slug}'\n")
    (tmp_path / "ch3_gravity.py").write_text(chapter.format(slug="gravity"))
    assert [(c.number, c.slug, c.title) for c in chapters.lecture_chapters()] == [
        (3, "gravity", "Gravity")]
    (tmp_path / "ch3_gravity.py").write_text(chapter.format(slug="falling"))
    with pytest.raises(ValueError, match=r"slug is 'falling'; name the file ch3_falling\.py"):
        chapters.lecture_chapters()
    (tmp_path / "ch3_gravity.py").write_text(chapter.format(slug=""))
    with pytest.raises(ValueError, match="Gravity is no chapter"):
        chapters.lecture_chapters()


# --- the state a scene records ------------------------------------------------------------------


def _settings() -> dict:
    return {"dry_run": True, "disable_caching": True, "verbosity": "WARNING",
            "progress_bar": "none", "media_dir": tempfile.mkdtemp(prefix="trex-test-")}


def test_the_state_is_declared_and_set_up_in_init():
    with tempconfig(_settings()):
        one, two = Scaling(skip_animations=True), Scaling(skip_animations=True)
    assert isinstance(one, Recorded) and issubclass(TraceScene, Recorded)
    for scene in (one, two):
        assert scene.step_marks == [] and scene.lead_in_frame is None
        assert scene.steps_end_frame is None and scene.caption_track is None
        assert scene.played_beats == [] and scene.played_board is None
        assert scene.frames_seen == set()
    assert one.step_marks is not two.step_marks and one.frames_seen is not two.frames_seen


def test_a_render_records_marks_captions_beats_and_board_and_stashes_nothing():
    with tempconfig(_settings()):
        scene = Scaling.handed()(skip_animations=True)
        before = set(vars(scene))
        scene.render()
    stashed = sorted(k for k in set(vars(scene)) - before if k.startswith("trex"))
    assert stashed == []  # nothing by name: every key it keeps was set up in __init__
    assert [m.caption for m in recorded_steps(scene)] == [b.caption for b in scene.played_beats]
    assert scene.played_board is not None and scene.caption_track is captions_of(scene)
    assert scene.played_board.captions is scene.caption_track
    assert steps_end(scene) is None  # a scene that is no lecture ends its steps at its end


def test_lead_in_opens_the_next_step_and_end_steps_closes_them():
    with tempconfig(_settings()):
        scene = Scaling.handed()(skip_animations=True)
        scene.renderer.time = 2.0  # 2 s in: frame 2 × frame rate
        lead_in(scene)
        scene.renderer.time = 3.0
        lead_in(scene)  # the lead-in noted first stays
        mark_step(scene, "first")
        mark_step(scene, "second", kind="card")
        end_steps(scene)
    rate = scene.camera.frame_rate
    assert [(m.frame, m.caption, m.kind) for m in recorded_steps(scene)] == [
        (round(2 * rate), "first", "beat"), (round(3 * rate), "second", "card")]
    assert steps_end(scene) == round(3 * rate) and scene.lead_in_frame is None


def test_a_plain_scene_records_nothing():
    with tempconfig(_settings()):
        scene = Plain()
    assert recorded_steps(scene) == [] and steps_end(scene) is None
