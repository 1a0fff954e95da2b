"""trex player: an offline page stepping through a run; driven in headless Chromium.

The browser test needs Debian's chromium (/usr/bin/chromium, in the Makefile's system
packages) and the playwright package (the `test` extra); it never downloads a browser.
"""

import json
import re
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

from metaphors.catalog import beats as storyboard
from story.runs import run_logged
from trex import player_steps as player_module
from trex.cli import main

CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                 "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]
ROOT = Path(__file__).resolve().parent.parent


def run(*args):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


@pytest.fixture(scope="module")
def scaling_player(tmp_path_factory):
    """The real thing, once: scenes/scaling.py on its counterexample."""
    out = tmp_path_factory.mktemp("player") / "scaling"
    code, stdout, stderr = run("player", "scaling", "-o", str(out))
    assert code == 0, stderr
    assert stdout == f"{out / 'index.html'}\n"
    return out


def test_one_picture_per_beat_and_a_self_contained_page(scaling_player):
    beats = storyboard(run_logged("scaling", "counterexample"))
    pictures = sorted((scaling_player / "steps").glob("*.png"))
    assert [p.name for p in pictures] == [f"{k:03d}.png" for k in range(1, len(beats) + 1)]
    assert len({p.read_bytes() for p in pictures}) == len(pictures)  # every step looks different
    assert (scaling_player / ".trex-player").is_file()
    assert leftovers(scaling_player.parent) == []
    page = (scaling_player / "index.html").read_text()
    data = json.loads(re.search(r'<script id="player-data" type="application/json">(.*?)</script>',
                                page, re.S).group(1))
    assert [s["caption"] for s in data["steps"]] == [b.caption for b in beats]
    assert data["steps"][-1]["caption"].startswith("✗ BD is not an inner diagonal")
    assert data["steps"][-1]["call"] == "claim(B, D) → BD"
    # nothing from elsewhere: no URLs with a scheme, no external scripts, styles or fonts
    assert not re.search(r"(https?:|ftp:|//[a-z])", page, re.I)
    assert not re.search(r"<script[^>]+src=|<link[^>]+stylesheet|@import|url\(", page, re.I)


@pytest.mark.skipif(not CHROMIUM.exists(),
                    reason="needs Debian's chromium at /usr/bin/chromium (make system-deps)")
def test_stepping_through_in_headless_chromium(scaling_player):
    sync_api = pytest.importorskip("playwright.sync_api",
                                   reason="needs playwright (pip install -e '.[test]')")
    n = len(list((scaling_player / "steps").glob("*.png")))
    requests = []
    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        try:
            page = browser.new_page(viewport={"width": 1000, "height": 900})
            page.on("request", lambda r: requests.append(r.url))
            page.goto((scaling_player / "index.html").as_uri())
            counter, picture = page.locator("#counter"), page.locator("#picture")

            def state():
                page.wait_for_function("document.getElementById('picture').complete")
                return (counter.inner_text(), picture.get_attribute("src"),
                        page.evaluate("document.getElementById('picture').naturalWidth"))

            assert state() == (f"step 1 / {n}", "steps/001.png", 854)
            first_shot = picture.screenshot()
            page.keyboard.press("ArrowLeft")  # nothing before the first step
            assert state()[0] == f"step 1 / {n}"
            page.keyboard.press("ArrowRight")
            assert state() == (f"step 2 / {n}", "steps/002.png", 854)
            assert picture.screenshot() != first_shot  # the picture changed on screen
            assert page.locator("#call").inner_text() == "leftmost_vertex(P) → B"
            page.keyboard.press("End")
            assert state() == (f"step {n} / {n}", f"steps/{n:03d}.png", 854)
            assert page.locator("#caption").inner_text().startswith("✗ BD is not an inner")
            page.keyboard.press("ArrowRight")  # nothing after the last
            assert state()[0] == f"step {n} / {n}"
            page.keyboard.press("Home")
            assert state() == (f"step 1 / {n}", "steps/001.png", 854)
        finally:
            browser.close()
    assert requests, "the page loaded nothing at all?"
    assert all(url.startswith("file://") for url in requests), requests


# --- bad input and atomic writes (no real rendering) ---------------------------------------------


@pytest.fixture
def fake_steps(monkeypatch):
    """render_steps that writes one tiny picture per beat at once (records the scene class)."""
    seen = {}

    def fake(cls, log, folder, *args, **kwargs):
        seen["cls"], seen["log"] = cls, log
        (folder / "steps").mkdir()
        (folder / "steps" / "001.png").write_bytes(b"png")
        return [player_module.Still("steps/001.png", "The polygon", None, "polygon")]

    monkeypatch.setattr(player_module, "render_steps", fake)
    return seen


def test_bad_polygon_is_one_line_before_rendering(tmp_path, monkeypatch):
    monkeypatch.setattr(player_module, "render_steps", lambda *a, **k: pytest.fail("rendered"))
    code, out, err = run("player", "scaling", "--polygon", "[[0, 0], [1, 1]]", "-o",
                         str(tmp_path / "out"))
    assert code == 2 and out == ""
    assert err.startswith("error: [[0, 0], [1, 1]]: ") and err.count("\n") == 1
    code, _, err = run("player", "scaling", "--polygon", "triangle", "-o", str(tmp_path / "out"))
    assert code == 2 and err == "error: triangle: a triangle has no diagonal\n"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("scene", "message"), [
    ("nonesuch", "error: nonesuch: unknown scene 'nonesuch'; known: "),
    ("counterexample", "error: counterexample: Counterexample plays several runs"),
    ("polygon", "error: polygon: PolygonScene does not play an algorithm's log"),
    ("examples/nope.py:f", "error: examples/nope.py:f: examples/nope.py: no such file"),
])
def test_bad_scene_is_one_line(tmp_path, monkeypatch, scene, message):
    monkeypatch.setattr(player_module, "render_steps", lambda *a, **k: pytest.fail("rendered"))
    code, out, err = run("player", scene, "-o", str(tmp_path / "out"))
    assert code == 2 and out == ""
    assert err.startswith(message) and err.count("\n") == 1
    assert list(tmp_path.iterdir()) == []


def test_output_must_be_new_empty_or_an_earlier_player(tmp_path, fake_steps):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("keep me")
    code, _, err = run("player", "scaling", "-o", str(mine))
    assert code == 2 and "is not an earlier player" in err
    assert [p.name for p in mine.iterdir()] == ["notes.txt"]
    a_file = tmp_path / "file"
    a_file.write_text("x")
    code, _, err = run("player", "scaling", "-o", str(a_file))
    assert code == 2 and err == f"error: {a_file}: exists and is not a directory\n"

    out = tmp_path / "deep" / "player"
    assert run("player", "scaling", "-o", str(out))[0] == 0
    (out / "stale.png").write_bytes(b"old")
    code, stdout, _ = run("player", "rotation:RotationCcw", "-o", str(out))  # replaces it
    assert code == 0 and stdout == f"{out / 'index.html'}\n"
    assert fake_steps["cls"].__name__ == "RotationCcw"
    assert fake_steps["log"].meta["polygon"] == "counterexample-twin"  # the scene's default
    assert not (out / "stale.png").exists() and (out / "index.html").is_file()
    assert leftovers(out.parent) == []


def test_a_failing_build_leaves_the_output_as_it_was(tmp_path, monkeypatch, fake_steps):
    out = tmp_path / "player"
    assert run("player", "scaling", "-o", str(out))[0] == 0
    before = sorted(p.relative_to(out) for p in out.rglob("*"))

    def broken(*args, **kwargs):
        raise RuntimeError("the scene broke")

    monkeypatch.setattr(player_module, "render_steps", broken)
    code, out_text, err = run("player", "gravity", "-o", str(out))
    assert code == 1 and out_text == ""
    assert err == "error: gravity: player failed: RuntimeError: the scene broke\n"
    assert sorted(p.relative_to(out) for p in out.rglob("*")) == before
    assert leftovers(tmp_path) == []
    shutil.rmtree(out)
    code, _, _ = run("player", "gravity", "-o", str(out))
    assert code == 1 and list(tmp_path.iterdir()) == []


def test_a_heuristic_of_ones_own_and_a_polygon(tmp_path, fake_steps):
    spec = f"{ROOT / 'examples' / 'my_heuristic.py'}:biggest_angle"
    code, _, err = run("player", spec, "--polygon", "counterexample-twin", "-o",
                       str(tmp_path / "mine"))
    assert code == 0, err
    assert fake_steps["log"].meta["user_heuristic"] == "biggest_angle"
    assert fake_steps["log"].meta["polygon"] == "counterexample-twin"
    page = (tmp_path / "mine" / "index.html").read_text()
    assert "<title>biggest_angle: Claim BD for the candidate D" in page


# --- a saved log (--log, TREX_LOG) ---------------------------------------------------------------


def page_data(folder: Path) -> dict:
    page = (folder / "index.html").read_text()
    return json.loads(re.search(r'<script id="player-data" type="application/json">(.*?)</script>',
                                page, re.S).group(1))


def saved_log(folder: Path, *args) -> Path:
    """``trex log ARGS -o folder/NAME.json``: a log as users save them."""
    path = folder / f"{'-'.join(args)}.json"
    code, _, err = run("log", *args, "-o", str(path))
    assert code == 0, err
    return path


def test_a_saved_log_gives_the_live_runs_steps(scaling_player, tmp_path):
    saved = saved_log(tmp_path, "scaling", "counterexample")
    out = tmp_path / "replayed"
    code, stdout, err = run("player", "scaling", "--log", str(saved), "-o", str(out))
    assert code == 0, err
    assert stdout == f"{out / 'index.html'}\n"
    assert page_data(out)["steps"] == page_data(scaling_player)["steps"]
    live = sorted((scaling_player / "steps").glob("*.png"))
    replayed = sorted((out / "steps").glob("*.png"))
    assert [p.read_bytes() for p in replayed] == [p.read_bytes() for p in live]
    assert "Scaling on counterexample, saved in" in (out / "index.html").read_text()


def test_trex_log_is_read_as_scenes_read_it(tmp_path, monkeypatch, fake_steps):
    saved = saved_log(tmp_path, "gravity", "star")
    live = storyboard(run_logged("gravity", "star"))

    def played():
        return [(b.caption, b.call, b.line) for b in storyboard(fake_steps["log"])]

    monkeypatch.setenv("TREX_LOG", str(saved))
    assert run("player", "gravity", "-o", str(tmp_path / "env"))[0] == 0
    assert fake_steps["log"].meta["polygon"] == "star"  # not the scene's gravity-snag
    assert fake_steps["log"].meta["shown"] == "gravity_at"  # as a live run (trex log omits it)
    assert played() == [(b.caption, b.call, b.line) for b in live]
    # --polygon wins over TREX_LOG, as for `trex render --polygon`
    assert run("player", "gravity", "--polygon", "counterexample", "-o",
               str(tmp_path / "polygon"))[0] == 0
    assert fake_steps["log"].meta["polygon"] == "counterexample"
    monkeypatch.delenv("TREX_LOG")
    monkeypatch.setenv("TREX_POLYGON", "two-ears")
    assert run("player", "gravity", "-o", str(tmp_path / "polygon"))[0] == 0
    assert fake_steps["log"].meta["polygon"] == "two-ears"


@pytest.mark.parametrize(("make", "message"), [
    (lambda d: d / "missing.json", "{log}: cannot read: No such file or directory"),
    (lambda d: d, "{log}: cannot read: Is a directory"),
    (lambda d: write(d / "notes.json", "not json"), "{log}: not a trex log: Expecting value"),
    (lambda d: write(d / "other.json", '{"schema": "x", "events": []}'),
     "{log}: not a trex log: unsupported log schema 'x'"),
    (lambda d: write(d / "bad-event.json",
                     '{"schema": "trex-log/1", "meta": {"algorithm": "gravity"}, "events": [1]}'),
     "{log}: not a trex log: an event must be a JSON object"),
    (lambda d: write(d / "empty.json",
                     '{"schema": "trex-log/1", "meta": {"algorithm": "gravity"}, "events": []}'),
     "{log}: cannot be played: it does not start with the polygon"),
    (lambda d: write(d / "nameless.json", '{"schema": "trex-log/1", "meta": {}, "events": []}'),
     "{log}: not the log of a run: its meta names no algorithm"),
    (lambda d: saved_log(d, "scaling", "counterexample"),
     "{log}: is a log of scaling, but gravity plays gravity"),
], ids=["missing", "directory", "not-json", "not-a-log", "bad-event", "no-events", "no-algorithm",
        "other-algorithm"])
def test_a_bad_saved_log_is_one_line_before_rendering(tmp_path, monkeypatch, make, message):
    monkeypatch.setattr(player_module, "render_steps", lambda *a, **k: pytest.fail("rendered"))
    inputs = tmp_path / "in"
    inputs.mkdir()
    log = make(inputs)

    def refused(label, *args):
        code, out, err = run("player", "gravity", *args, "-o", str(tmp_path / "out"))
        assert code == 2 and out == ""
        assert err.startswith("error: " + message.format(log=label)), err
        assert err.count("\n") == 1
        assert sorted(p.name for p in tmp_path.iterdir()) == ["in"]  # nothing written
        return True

    assert refused(str(log), "--log", str(log))
    monkeypatch.setenv("TREX_LOG", str(log))
    assert refused(f"TREX_LOG={log}")


def test_a_saved_log_of_another_heuristic_or_with_a_polygon_is_refused(tmp_path, fake_steps):
    saved = saved_log(tmp_path, "divide-and-conquer", "lecture", "--heuristic", "scaling")
    code, _, err = run("player", "divide_and_conquer", "--log", str(saved), "-o",
                       str(tmp_path / "out"))
    assert code == 2
    assert err == (f"error: {saved}: is a log of divide-and-conquer with scaling, but "
                   "divide_and_conquer plays divide-and-conquer with gravity\n")
    code, _, err = run("player", "gravity", "--log", str(saved), "--polygon", "star", "-o",
                       str(tmp_path / "out"))
    assert code == 2
    assert err == ("error: --polygon and --log: give one of them (a saved log has its own "
                   "polygon)\n")
    assert not (tmp_path / "out").exists() and "log" not in fake_steps
    ok = saved_log(tmp_path, "divide-and-conquer", "lecture")
    assert run("player", "divide_and_conquer", "--log", str(ok), "-o", str(tmp_path / "out"))[0] == 0
    assert fake_steps["log"].meta["shown"] == "divide_and_conquer"


def write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path
