"""trex slides: one render cut into a clip per step, a presenter's page driven in headless
Chromium, and the handout.

The browser tests need Debian's chromium (/usr/bin/chromium, in the Makefile's system
packages; it plays H.264) and the playwright package (the `test` extra); no browser is ever
downloaded.
"""

import io
import itertools
import json
import re
from pathlib import Path

import av
import numpy as np
import pytest
from click.testing import CliRunner
from PIL import Image

from metaphors.catalog import beats as storyboard
from story.runs import run_logged
from story.step_marks import StepMark
from trex import handout
from trex.cli import main
from trex.clips import Marks, cut_clips, step_ranges

CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                 "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync",
                 "--autoplay-policy=no-user-gesture-required"]


def run(*args):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def page_data(folder: Path) -> dict:
    page = (folder / "index.html").read_text()
    return json.loads(re.search(r'<script id="slides-data" type="application/json">(.*?)</script>',
                                page, re.S).group(1))


def frames(path: Path) -> list[np.ndarray]:
    with av.open(str(path)) as container:
        return [f.to_ndarray(format="rgb24") for f in container.decode(video=0)]


def clips_of(folder: Path) -> list[Path]:
    return sorted((folder / "clips").glob("*.mp4"))


@pytest.fixture(scope="module")
def gravity(tmp_path_factory):
    """The real thing, once: scenes/gravity.py on its default polygon, at -ql."""
    out = tmp_path_factory.mktemp("slides") / "gravity"
    code, stdout, stderr = run("slides", "gravity", "-o", str(out))
    assert code == 0, stderr
    lines = stdout.splitlines()
    assert re.fullmatch(r"slides: \d+ steps, \d+\.\d MB, in \d+\.\d s", lines[0])
    assert lines[1] == str(out / "index.html")
    return out


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    """`trex render gravity`: the video the slides must be cut from, frame for frame."""
    out = tmp_path_factory.mktemp("render") / "gravity.mp4"
    code, _, stderr = run("render", "gravity", "-o", str(out))
    assert code == 0, stderr
    return out


def test_one_clip_per_beat_cut_from_the_one_render(gravity, rendered):
    beats = storyboard(run_logged("gravity", "gravity-snag"))
    clips = clips_of(gravity)
    assert [p.name for p in clips] == [f"{k:03d}.mp4" for k in range(1, len(beats) + 1)]
    data = page_data(gravity)
    assert [s["caption"] for s in data["steps"]] == [b.caption for b in beats]
    assert [s["kind"] for s in data["steps"]] == [b.action for b in beats]
    assert [s["clip"] for s in data["steps"]] == [f"clips/{p.name}" for p in clips]
    # the clips, one after another, are the scene's video: the same frames; each but the last
    # ends on the next one's first frame (the first to show its step finished)
    cut = [frames(clip) for clip in clips]
    assert all(np.array_equal(a[-1], b[0]) for a, b in itertools.pairwise(cut))
    joined = [f for shown in cut[:-1] for f in shown[:-1]] + cut[-1]
    whole = frames(rendered)
    assert len(joined) == len(whole)
    assert all(np.array_equal(a, b) for a, b in zip(joined, whole, strict=True))
    # each clip starts where its beat starts (its caption appears in its first frames)
    assert all(len(frames(clip)) >= 2 for clip in clips)
    # the page knows when each clip's last frame shows (15 frames a second)
    assert [s["last"] for s in data["steps"]] == [
        pytest.approx((len(shown) - 1) / 15, abs=0.5 / 15) for shown in cut]
    assert sorted(p.name for p in gravity.iterdir()) == [".trex-slides", "clips", "handout.pdf",
                                                         "index.html"]
    assert [p.name for p in gravity.parent.iterdir()] == ["gravity"]  # nothing left beside


def test_the_page_is_self_contained(gravity):
    page = (gravity / "index.html").read_text()
    assert not re.search(r"(https?:|ftp:|//[a-z])", page, re.I)
    assert not re.search(r"<script[^>]+src=|<link[^>]+stylesheet|@import|url\(", page, re.I)


def page_pictures(pdf: Path) -> list[Image.Image]:
    """The handout's pages: each is one JPEG image in the PDF."""
    data = pdf.read_bytes()
    shown = []
    for match in re.finditer(rb"/DCTDecode.*?stream\r?\n", data, re.S):
        end = data.index(b"endstream", match.end())
        shown.append(Image.open(io.BytesIO(data[match.end():end])).convert("RGB"))
    return shown


def difference(a: Image.Image, b: Image.Image) -> float:
    return float(np.abs(np.asarray(a, dtype=float) - np.asarray(b, dtype=float)).mean())


def test_the_handout_has_the_last_frame_of_every_step(gravity):
    clips = clips_of(gravity)
    lasts = [Image.fromarray(frames(clip)[-1]) for clip in clips]
    pages = page_pictures(gravity / "handout.pdf")
    per_page = handout.COLUMNS * handout.ROWS
    assert len(pages) == -(-len(clips) // per_page)
    for k in range(len(pages) * per_page):
        x, y, width = handout.picture_box(k)
        height = round(width * 480 / 854)
        cell = pages[k // per_page].crop((x + 2, y + 2, x + width - 2, y + height - 2))
        if k >= len(clips):  # no step: blank paper
            assert np.asarray(cell).min() > 240
            continue
        scaled = [last.resize((width, height), Image.Resampling.LANCZOS).crop(
            (2, 2, width - 2, height - 2)) for last in lasts]
        distances = [difference(cell, s) for s in scaled]
        assert distances[k] < 4, (k, distances[k])  # JPEG: close, not equal
        assert distances[k] == min(distances)  # and it is that step's, not another's


def test_the_handout_is_the_same_bytes_for_the_same_frames(tmp_path):
    def write(name):
        sheet = handout.Handout(tmp_path / name, "Title", 9)
        for k in range(9):
            sheet.add(Image.new("RGB", (854, 480), (20 * k, 40, 90)), str(k + 1),
                      "a caption long enough to be wrapped onto a second line " * (k % 3))
        return sheet.close().read_bytes()

    first = write("a.pdf")
    assert first == write("b.pdf")
    assert first.count(b"/Type /Page\n") >= 2 and len(page_pictures(tmp_path / "a.pdf")) == 2


def test_a_step_must_start_on_a_key_frame(gravity, tmp_path):
    clip = clips_of(gravity)[2]
    n = len(frames(clip))
    assert step_ranges(Marks((StepMark(0, "a"), StepMark(n // 2, "b"))), n) == [(0, n // 2),
                                                                         (n // 2, n)]
    with pytest.raises(ValueError, match=r"step 2 of 003\.mp4 does not start on a key frame"):
        cut_clips(clip, Marks((StepMark(0, "a"), StepMark(n // 2, "b"))), tmp_path, ["1.mp4", "2.mp4"])
    with pytest.raises(ValueError, match="after the video's"):
        cut_clips(clip, Marks((StepMark(0, "a"),), n + 5), tmp_path, ["1.mp4"])


# --- the page in headless Chromium ---------------------------------------------------------------


@pytest.fixture
def browser():
    if not CHROMIUM.exists():
        pytest.skip("needs Debian's chromium at /usr/bin/chromium (make system-deps)")
    sync_api = pytest.importorskip("playwright.sync_api",
                                   reason="needs playwright (pip install -e '.[test]')")
    with sync_api.sync_playwright() as pw:
        launched = pw.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        try:
            yield launched
        finally:
            launched.close()


STATE = """() => { const v = document.getElementById('clip');
  return {counter: document.getElementById('counter').textContent, src: v.getAttribute('src'),
          paused: v.paused, ended: v.ended, time: v.currentTime, duration: v.duration,
          ready: v.readyState, caption: document.getElementById('caption').textContent,
          next: document.getElementById('next').textContent}; }"""


def settled(page) -> dict:
    """The state once the clip has stopped on its last frame (played to its end, or shown at
    it: the page seeks into the middle of the last frame, less than 1/15 s before the end)."""
    page.wait_for_function("() => { const v = document.getElementById('clip');"
                           " return v.readyState >= 2 && v.paused && !v.seeking"
                           " && v.currentTime > v.duration - 1 / 15; }", timeout=15000)
    return page.evaluate(STATE)


def test_presenting_in_headless_chromium(gravity, browser):
    data = page_data(gravity)["steps"]
    n = len(data)
    clips = clips_of(gravity)
    requests = []
    page = browser.new_page(viewport={"width": 1000, "height": 900})
    page.on("request", lambda r: requests.append(r.url))
    page.goto((gravity / "index.html").as_uri())

    def playing(src):  # → changed the clip and it plays from its start
        page.wait_for_function(f"() => {{ const v = document.getElementById('clip');"
                               f" return v.getAttribute('src') === '{src}' && !v.paused"
                               f" && v.currentTime > 0; }}", timeout=15000)

    playing("clips/001.mp4")  # step 1 plays when the page opens
    first = settled(page)
    assert (first["counter"], first["src"], first["ended"]) == (f"step 1 / {n}",
                                                                "clips/001.mp4", True)
    page.keyboard.press("ArrowRight")
    playing("clips/002.mp4")
    assert page.evaluate(STATE)["counter"] == f"step 2 / {n}"
    two = settled(page)
    assert two["duration"] == pytest.approx(len(frames(clips[1])) / 15, abs=0.01)
    page.wait_for_timeout(800)  # it stays on its last frame: nothing moves on by itself
    still = page.evaluate(STATE)
    assert (still["counter"], still["src"], still["time"]) == (f"step 2 / {n}",
                                                               "clips/002.mp4", two["time"])
    assert still["caption"] == data[1]["caption"]

    page.keyboard.press("ArrowLeft")  # back: the step before, at its end, not playing
    back = settled(page)
    assert (back["counter"], back["src"]) == (f"step 1 / {n}", "clips/001.mp4")
    assert shown_frame(page, clips[0], "last") == "last"

    page.keyboard.press("End")
    end = settled(page)
    assert (end["counter"], end["src"]) == (f"step {n} / {n}", f"clips/{clips[-1].name}")
    assert shown_frame(page, clips[-1], "last") == "last"
    page.keyboard.press("ArrowRight")  # past the last step: nothing
    assert settled(page)["counter"] == f"step {n} / {n}"
    page.keyboard.press("Home")
    playing("clips/001.mp4")
    settled(page)
    page.evaluate("() => { document.getElementById('clip').currentTime = 0; }")
    page.wait_for_function("() => !document.getElementById('clip').seeking")
    page.wait_for_timeout(200)
    assert shown_frame(page, clips[0], "first") == "first"  # (the comparison tells them apart)
    page.keyboard.press("PageDown")
    playing("clips/002.mp4")
    page.keyboard.press(" ")  # while it plays: on to the next
    playing("clips/003.mp4")
    settled(page)
    page.keyboard.press("PageUp")
    assert settled(page)["counter"] == f"step 2 / {n}"
    page.keyboard.type("5")
    page.keyboard.press("Enter")
    jumped = settled(page)
    assert (jumped["counter"], jumped["src"]) == (f"step 5 / {n}", "clips/005.mp4")
    assert not page.locator("#notes").is_visible()
    page.keyboard.press("f")  # full screen: the video's figure, and back
    page.wait_for_function("() => document.fullscreenElement"
                           " && document.fullscreenElement.id === 'stage'")
    page.keyboard.press("F")
    page.wait_for_function("() => !document.fullscreenElement")
    page.close()
    assert requests, "the page loaded nothing at all?"
    assert all(url.startswith("file://") for url in requests), requests


def shown_frame(page, clip: Path, expected: str | None = None) -> str:
    """Which of the clip's frames the video element shows: "first", "last" or "other"; with
    ``expected``, looked at again (for up to 3 s) until it is that one: a frame just sought
    may not be painted yet."""
    for _ in range(15):
        seen = _shown_frame(page, clip)
        if expected is None or seen == expected:
            break
        page.wait_for_timeout(200)
    return seen


def _shown_frame(page, clip: Path) -> str:
    page.evaluate("() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
    picture = Image.open(io.BytesIO(page.locator("#clip").screenshot())).convert("RGB")
    box = (8, 8, picture.width - 8, picture.height - 8)  # inside the border
    picture = picture.crop(box)
    decoded = frames(clip)
    sized = [Image.fromarray(f).resize((picture.width + 16, picture.height + 16)).crop(
        (8, 8, picture.width + 8, picture.height + 8)) for f in (decoded[0], decoded[-1])]
    first, last = (difference(picture, s) for s in sized)
    if last < first and last < 6:
        return "last"
    return "first" if first < 6 else "other"


# Chromium now and then paints no new frame after a seek (seen under load: the seek done,
# the first frame still shown). Here its first frame callback says so every time.
STALE_PAINTS = """(() => {
  const ask = HTMLVideoElement.prototype.requestVideoFrameCallback;
  let asked = 0;
  window.seeks = [];
  window.presented = [];
  HTMLVideoElement.prototype.requestVideoFrameCallback = function (callback) {
    if (asked++ < STALE) { return ask.call(this, (now, frame) => callback(now, {...frame, mediaTime: 0})); }
    return ask.call(this, (now, frame) => { window.presented.push(frame.mediaTime); callback(now, frame); });
  };
  document.addEventListener("seeking", e => window.seeks.push(e.target.currentTime), true);
})()"""


def test_a_seek_that_paints_no_frame_is_tried_again(gravity, browser):
    n = len(page_data(gravity)["steps"])
    clips = clips_of(gravity)
    page = browser.new_page(viewport={"width": 1000, "height": 900})
    page.add_init_script(STALE_PAINTS.replace("STALE", "1"))  # the first paint is stale
    page.goto((gravity / "index.html").as_uri() + "#1")  # step 1, shown at its end
    page.wait_for_function("() => window.seeks.length >= 2", timeout=15000)
    state = settled(page)
    assert state["counter"] == f"step 1 / {n}"
    assert shown_frame(page, clips[0], "last") == "last"
    seeks = page.evaluate("window.seeks")
    assert 2 <= len(seeks) <= 6 and seeks[0] != seeks[1], seeks  # again, and not forever
    # the frame Chromium ends up presenting has the time the page was told is the last's
    last = page_data(gravity)["steps"][0]["last"]
    page.wait_for_function(f"() => window.presented.length > 0 && Math.abs("
                           f"window.presented[window.presented.length - 1] - {last}) < 2e-3",
                           timeout=15000)
    page.close()


def test_seeking_again_stops_after_five_tries(gravity, browser):
    page = browser.new_page(viewport={"width": 1000, "height": 900})
    page.add_init_script(STALE_PAINTS.replace("STALE", "1e9"))  # every paint stale
    page.goto((gravity / "index.html").as_uri() + "#1")
    page.wait_for_function("() => window.seeks.length >= 6", timeout=20000)
    page.wait_for_timeout(1500)  # more than five times the page's 250 ms wait
    assert len(page.evaluate("window.seeks")) == 6
    assert settled(page)["counter"] == f"step 1 / {len(page_data(gravity)['steps'])}"
    page.close()


def test_the_speaker_view_shows_the_next_caption(gravity, browser):
    data = page_data(gravity)["steps"]
    page = browser.new_page(viewport={"width": 1000, "height": 900})
    page.goto((gravity / "index.html").as_uri() + "?notes#2")
    state = settled(page)
    assert (state["counter"], state["next"]) == (f"step 2 / {len(data)}", data[2]["caption"])
    assert page.locator("#notes").is_visible()
    # S opens it as a second window, which follows the first (and steers it)
    main_page = browser.new_page(viewport={"width": 1000, "height": 900})
    main_page.goto((gravity / "index.html").as_uri() + "#3")
    settled(main_page)
    with main_page.expect_popup() as popup:
        main_page.keyboard.press("s")
    notes = popup.value
    notes.wait_for_load_state()
    assert notes.locator("#notes").is_visible()
    main_page.keyboard.press("ArrowRight")
    notes.wait_for_function(f"() => document.getElementById('counter').textContent"
                            f" === 'step 4 / {len(data)}'", timeout=15000)
    assert notes.locator("#next").inner_text() == data[4]["caption"]
    notes.keyboard.press("ArrowLeft")
    main_page.wait_for_function(f"() => document.getElementById('counter').textContent"
                                f" === 'step 3 / {len(data)}'", timeout=15000)


# --- bad input, atomic output (no rendering) -----------------------------------------------------


@pytest.fixture
def no_render(monkeypatch):
    from trex import render_command

    monkeypatch.setattr(render_command, "render_into",
                        lambda *a, **k: pytest.fail("rendered"))


@pytest.mark.parametrize(("args", "message"), [
    (("slides", "scaling", "--polygon", "triangle"), "error: triangle: a triangle has no diagonal"),
    (("slides", "nonesuch"), "error: nonesuch: unknown scene 'nonesuch'; known: "),
    (("slides", "counterexample", "--log", "x.json"), "error: x.json: "),
    (("slides", "gravity", "-j", "2"), "error: -j: only for `trex slides lecture`"),
    (("slides", "lecture", "--log", "x.json"), "error: --log: the lecture plays many runs"),
    (("slides", "lecture", "--polygon", "[[0, 0], [1, 1]]"), "error: [[0, 0], [1, 1]]: "),
    (("slides", "lecture", "--chapters", "nonesuch"), "error: --chapters nonesuch: unknown "),
])
def test_bad_input_is_one_line_and_writes_nothing(tmp_path, no_render, args, message):
    code, out, err = run(*args, "-o", str(tmp_path / "out"))
    assert code == 2 and out == ""
    assert err.startswith(message) and err.count("\n") == 1, err
    assert list(tmp_path.iterdir()) == []


def test_the_output_must_be_new_empty_or_earlier_slides(tmp_path, no_render):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("keep me")
    code, _, err = run("slides", "gravity", "-o", str(mine))
    assert code == 2
    assert err == (f"error: {mine}: exists and is not earlier slides (no .trex-slides in it); "
                   "give a new or empty directory\n")
    assert [p.name for p in mine.iterdir()] == ["notes.txt"]


def test_a_failing_render_leaves_earlier_slides_as_they_were(gravity, tmp_path, monkeypatch):
    import shutil

    from trex import render_command

    out = tmp_path / "slides"
    shutil.copytree(gravity, out)
    before = sorted(p.relative_to(out) for p in out.rglob("*"))

    def broken(*args, **kwargs):
        raise RuntimeError("the scene broke")

    monkeypatch.setattr(render_command, "render_into", broken)
    code, stdout, err = run("slides", "gravity", "-o", str(out))
    assert code == 1 and stdout == ""
    assert err == "error: gravity: slides failed: RuntimeError: the scene broke\n"
    assert sorted(p.relative_to(out) for p in out.rglob("*")) == before
    assert [p.name for p in tmp_path.iterdir()] == ["slides"]


def test_a_scene_of_several_runs_is_one_clip_per_beat_of_every_run(tmp_path):
    """scenes/counterexample.py plays eight runs on two polygons: one render, a clip for
    every beat it plays — a run going on on the polygon of the run before draws it and picks
    B no more — and one for its ending."""
    from metaphors import catalog
    from metaphors.scene import boards_of
    from trex.render_command import load_scene_class

    cls = load_scene_class(Path(__file__).resolve().parents[1] / "scenes" / "counterexample.py",
                           "Counterexample")
    runs = [catalog.beats(spec.log()) for spec in cls.default_specs()]
    boards = boards_of(runs)
    kinds = [b.action for k, beats in enumerate(runs) for b in beats
             if k == 0 or boards[k] != boards[k - 1] or b.action not in ("polygon", "pick")]
    out = tmp_path / "counterexample"
    code, _, stderr = run("slides", "counterexample", "-o", str(out))
    assert code == 0, stderr
    assert len(clips_of(out)) == len(kinds) + 1
    assert [s["kind"] for s in page_data(out)["steps"]] == [*kinds, "note"]


def test_the_speaker_view_keeps_next_above_the_fold_at_1366x768(tmp_path, browser):
    """A laptop's screen (issue 24 item 12): the next step's caption shows without scrolling,
    as do the video's foot and the buttons. The page alone: its layout needs no clip."""
    from trex.slides_page import Slide, write_slides

    long = "Candidates inside T: D, E, F, G — the water reaches them one after another"
    slides = [Slide(f"clips/{k:03d}.mp4", f"{long} ({k})") for k in range(1, 6)]
    write_slides(tmp_path, slides, "Gravity: the ball drops from B", "gravity on lecture",
                 (854, 480))
    page = browser.new_page(viewport={"width": 1366, "height": 768})
    page.goto((tmp_path / "index.html").as_uri() + "?notes#2")
    page.wait_for_function("() => document.getElementById('next').textContent !== ''")
    assert page.locator("#next").inner_text() == f"{long} (3)"
    for element in ("#notes", "#clip", "#counter", "#caption"):
        box = page.locator(element).bounding_box()
        assert box is not None and box["y"] + box["height"] <= 768, (element, box)
    page.close()


def test_handout_ends_on_the_teachers_notes(tmp_path):
    """Issue 22 item 7: the chapters' notes for the teacher, which the video leaves out, are
    the handout's last page (counted in "page k / n"); the slides carry them for the
    speaker window."""
    from trex.slides_page import Slide

    path = tmp_path / "h.pdf"
    sheet = handout.Handout(path, "Lecture", 3, [("2. Heuristics", ("Metaphors: ask why",)),
                                                 ("3. Gravity", ())])
    for k in range(3):
        sheet.add(Image.new("RGB", (320, 180), (40 * k, 80, 120)), str(k + 1), f"step {k}")
    sheet.close()
    pages = page_pictures(path)
    assert len(pages) == 2 == sheet.count
    ink = np.asarray(pages[1].convert("L")) < 128
    assert ink[handout.MARGIN + handout.HEADER:].sum() > 500  # the notes are written
    blank = handout.Handout(tmp_path / "b.pdf", "Lecture", 3)
    assert blank.count == 1
    assert Slide("c.mp4", "x", notes=("a: b",)).to_dict()["notes"] == ["a: b"]
