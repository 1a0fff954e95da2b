"""trex slides lecture: the chapters' steps (a card's title and each line, a run's beats) as
one presentation, reusing what `trex lecture` rendered when it was made the same way."""

import textwrap

import pytest

from metaphors.catalog import beats as storyboard
from story.runs import run_logged
from tests.test_lecture import frame_sums
from tests.test_slides import page_data, run
from trex import chapter_pool
from trex.chapter_command import render_settings
from trex.chapters import pick_chapters, scene_path
from trex.clips import marks_path, read_marks
from trex.slides_command import reusable

CHAPTER = textwrap.dedent("""
    from metaphors.lecture import Card, LectureScene, Run

    class Tiny(LectureScene):
        chapter_title = "1. Tiny"

        def chapter_segments(self):
            return (Card("A card", ("the first line", "the second line")),
                    Run("scaling", "counterexample", "Scaling"))
""")


@pytest.fixture(scope="module")
def chapters(tmp_path_factory) -> str:
    path = tmp_path_factory.mktemp("scenes") / "tiny.py"
    path.write_text(CHAPTER)
    return f"polygon,{path}:Tiny"


@pytest.fixture(scope="module")
def rendered(tmp_path_factory, chapters):
    """Slides of two chapters rendered now (no lecture to reuse)."""
    out = tmp_path_factory.mktemp("slides") / "lecture"
    code, stdout, stderr = run("slides", "lecture", "--chapters", chapters, "--lecture",
                               str(out.parent / "none"), "-o", str(out))
    assert code == 0, stderr
    assert "reused" not in stdout
    return out


def test_every_card_line_and_beat_is_a_step(rendered):
    steps = page_data(rendered)["steps"]
    beats = storyboard(run_logged("scaling", "counterexample"))
    assert [(s["kind"], s["caption"]) for s in steps[:4]] == [
        ("chapter", "1. Polygon"), ("card", "A card"), ("card-line", "the first line"),
        ("card-line", "the second line")]
    assert [s["caption"] for s in steps[4:]] == [b.caption for b in beats]
    assert [s["chapter"] for s in steps] == ["1. Polygon"] + ["2. Tiny (Tiny)"] * (3 + len(beats))
    clips = sorted((rendered / "clips").glob("*.mp4"))
    assert len(clips) == len(steps) == 4 + len(beats)
    assert sorted(p.name for p in rendered.iterdir()) == [".trex-slides", "clips", "handout.pdf",
                                                          "index.html"]


def test_the_chapters_of_trex_lecture_are_reused(rendered, chapters, tmp_path, monkeypatch):
    lecture = tmp_path / "lecture"
    code, _, stderr = run("lecture", "--chapters", chapters, "-o", str(lecture))
    assert code == 0, stderr
    videos = sorted((lecture / "chapters").glob("*.mp4"))
    assert all(marks_path(v).is_file() for v in videos)  # trex lecture keeps the marks
    monkeypatch.setattr(chapter_pool, "render_chapters",
                        lambda *a, **k: pytest.fail("rendered again"))
    out = tmp_path / "slides"
    code, stdout, stderr = run("slides", "lecture", "--chapters", chapters, "--lecture",
                               str(lecture), "-o", str(out))
    assert code == 0, stderr
    assert stdout.count(": reused ") == 2
    assert (out / "index.html").read_bytes() == (rendered / "index.html").read_bytes()
    ours, theirs = (sorted((d / "clips").glob("*.mp4")) for d in (out, rendered))
    assert [frame_sums(p) for p in ours] == [frame_sums(p) for p in theirs]


def test_a_chapter_made_otherwise_is_not_reused(rendered, chapters, tmp_path):
    lecture = tmp_path / "lecture"
    code, _, stderr = run("lecture", "--chapters", "polygon", "-o", str(lecture))
    assert code == 0, stderr
    video = next((lecture / "chapters").glob("*.mp4"))
    chapter = pick_chapters("polygon", ())[0]
    settings = render_settings(str(scene_path(chapter)), chapter.scene_class, "l", None, None)
    assert reusable(video, settings) == read_marks(video)
    assert reusable(video, {**settings, "quality": "m"}) is None
    assert reusable(video, {**settings, "polygon": "star"}) is None
    assert reusable(video, {**settings, "source": "other code"}) is None
    marks_path(video).unlink()
    assert reusable(video, settings) is None
