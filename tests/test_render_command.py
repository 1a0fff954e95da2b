"""trex render: real low-quality renders checked with PyAV, bad input before any rendering,
and no truncated or temporary file left by an interrupted or failed render."""

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import av
import pytest
from click.testing import CliRunner
from PIL import Image

from trex import render_command
from trex.cli import main

LOW = (854, 480)  # -ql


def run(*args):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def leftovers(directory: Path, keep=()) -> list[str]:
    return sorted(p.name for p in directory.iterdir() if p.name not in keep)


@pytest.fixture(scope="module")
def scaling_mp4(tmp_path_factory):
    out = tmp_path_factory.mktemp("mp4") / "scaling.mp4"
    code, stdout, stderr = run("render", "scaling", "-q", "l", "-o", str(out))
    assert code == 0, stderr
    assert stderr == ""  # stderr is no terminal here: no progress bars (issue 24 item 12)
    return out, stdout


def test_mp4_is_a_real_video_with_subtitles(scaling_mp4):
    out, stdout = scaling_mp4
    assert stdout.strip() == str(out)
    with av.open(str(out)) as container:
        stream = container.streams.video[0]
        assert (stream.width, stream.height) == LOW
        frames = sum(1 for _ in container.decode(video=0))
    assert frames > 0
    srt = out.with_suffix(".srt").read_text(encoding="utf-8")
    assert "00:00:00,000 -->" in srt
    assert leftovers(out.parent, keep={"scaling.mp4", "scaling.srt"}) == []


def test_png_is_the_last_frame(tmp_path):
    out = tmp_path / "still.png"
    code, stdout, stderr = run("render", "scaling", "-ql", "--format", "png", "-o", str(out))
    assert code == 0, stderr
    assert stdout.strip() == str(out)
    with Image.open(out) as image:
        assert image.size == LOW
        assert len(image.getcolors(1 << 16) or range(2)) > 1  # not a blank frame
    assert leftovers(tmp_path, keep={"still.png"}) == []


def test_format_follows_the_output_extension(tmp_path, monkeypatch):
    seen = {}

    def fake_render(make_scene, output, fmt, quality, **kw):
        seen.update(fmt=fmt, quality=quality, scene=make_scene.__name__)
        output.write_bytes(b"x")
        return output

    monkeypatch.setattr(render_command, "render_into", fake_render)
    code, _, stderr = run("render", "rotation:RotationCcw", "-q", "m", "-o",
                          str(tmp_path / "a.gif"))
    assert code == 0, stderr
    assert seen == {"fmt": "gif", "quality": "medium_quality", "scene": "RotationCcw"}


def test_bad_polygon_fails_before_manim_is_imported(tmp_path):
    bad = tmp_path / "bowtie.json"
    bad.write_text("[[0,0],[2,2],[2,0],[0,2]]")
    out = tmp_path / "x.mp4"
    script = textwrap.dedent(f"""
        import sys
        from trex.cli import main
        try:
            main(["render", "scaling", "--polygon", {str(bad)!r}, "-o", {str(out)!r}])
        except SystemExit as exc:
            assert "manim" not in sys.modules, "manim was imported"
            sys.exit(exc.code)
    """)
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            timeout=60)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {bad}: "), result.stderr
    assert leftovers(tmp_path, keep={"bowtie.json"}) == []


def test_polygon_the_algorithm_rejects_is_one_line(tmp_path, monkeypatch):
    monkeypatch.setattr(render_command, "render_into", lambda *a, **k: pytest.fail("rendered"))
    code, _, stderr = run("render", "scaling", "--polygon", "triangle", "-o",
                          str(tmp_path / "x.mp4"))
    assert code == 2
    assert stderr == "error: triangle: a triangle has no diagonal\n"
    assert leftovers(tmp_path) == []


@pytest.mark.parametrize(("polygon", "why"), [("triangle", "a triangle has no diagonal"),
                                           ("nonesuch-xyz", "no such file or sample")])
def test_a_bad_polygon_from_the_environment_is_one_line_too(polygon, why, tmp_path,
                                                            monkeypatch):
    monkeypatch.setattr(render_command, "render_into", lambda *a, **k: pytest.fail("rendered"))
    monkeypatch.setenv("TREX_POLYGON", polygon)
    code, _, stderr = run("render", "scaling", "-o", str(tmp_path / "x.mp4"))
    assert code == 2
    assert stderr.startswith(f"error: {polygon}: {why}") and len(stderr.splitlines()) == 1
    assert leftovers(tmp_path) == []


@pytest.mark.parametrize("scene", ["nonesuch", "no/such/file.py"])
def test_unknown_scene(scene, tmp_path):
    code, _, stderr = run("render", scene, "-o", str(tmp_path / "x.mp4"))
    assert code == 2
    assert len(stderr.splitlines()) == 1 and stderr.startswith(f"error: {scene}: ")
    if "/" not in scene:
        assert "known: " in stderr and "scaling" in stderr
    assert leftovers(tmp_path) == []


def test_unknown_class_lists_the_classes(tmp_path):
    code, _, stderr = run("render", "rotation:Nope", "-o", str(tmp_path / "x.mp4"))
    assert code == 2
    assert stderr == "error: rotation:Nope: rotation.py has no scene class 'Nope'; it has: Rotation, RotationCcw\n"


def test_output_that_is_a_directory(tmp_path):
    code, _, stderr = run("render", "scaling", "-o", str(tmp_path))
    assert code == 2
    assert stderr == f"error: {tmp_path}: is a directory; give a file path\n"


def test_failed_render_leaves_nothing(tmp_path):
    scene = tmp_path / "broken.py"
    scene.write_text(textwrap.dedent("""
        from manim import Circle, Create, Scene

        class Broken(Scene):
            def construct(self):
                self.play(Create(Circle()), run_time=0.2)
                raise RuntimeError("the scene broke")
    """))
    out_dir = tmp_path / "out"
    code, _, stderr = run("render", str(scene), "-o", str(out_dir / "broken.mp4"))
    assert code == 1
    assert stderr.splitlines()[-1] == (
        f"error: {scene}: render failed: RuntimeError: the scene broke")
    assert leftovers(out_dir) == []


def _partial_files(directory: Path) -> list[Path]:
    return list(directory.glob(".*.render/media/videos/*/partial_movie_files/*/*.mp4"))


def test_interrupted_render_leaves_nothing(tmp_path):
    """SIGINT and SIGTERM, each sent to a real `trex render` once it has written frames."""
    trex = Path(sys.executable).with_name("trex")
    jobs = {}
    for sig in (signal.SIGINT, signal.SIGTERM):
        out_dir = tmp_path / sig.name
        out_dir.mkdir()
        out = out_dir / "scaling.mp4"
        # Output to files, not pipes: an undrained pipe full of progress bars would block the
        # child in a write, and the test would measure the pipe, not the interrupt handling.
        log = tmp_path / f"{sig.name}.stderr"
        with open(log, "w") as err:
            proc = subprocess.Popen([str(trex), "render", "scaling", "-ql", "-o", str(out)],
                                    stdout=subprocess.DEVNULL, stderr=err, text=True)
        jobs[sig] = (proc, out_dir)
    try:
        for sig, (proc, out_dir) in jobs.items():
            deadline = time.monotonic() + 90
            while not _partial_files(out_dir) and proc.poll() is None:
                assert time.monotonic() < deadline, "render never started"
                time.sleep(0.1)
            assert proc.poll() is None, "render finished before it could be interrupted"
            proc.send_signal(sig)
        for sig, (proc, out_dir) in jobs.items():
            proc.wait(timeout=60)
            stderr = (tmp_path / f"{sig.name}.stderr").read_text()
            assert proc.returncode == 128 + sig, stderr
            assert stderr.rstrip().endswith("error: scaling: render interrupted; nothing written")
            assert leftovers(out_dir) == []
    finally:
        for proc, _ in jobs.values():
            if proc.poll() is None:
                proc.kill()
                proc.wait()


def _encoder_threads() -> list:
    return [t for t in threading.enumerate()
            if t.name.startswith("partial-movie-encoder") and t.is_alive()]


def _scaling_scene():
    scene_file = Path(__file__).resolve().parents[1] / "scenes" / "scaling.py"
    return render_command.scene_input(render_command.load_scene_class(scene_file, None),
                                      "counterexample")


def _render_interrupted(tmp_path, own_signals: bool) -> BaseException:
    """What render_into of the scaling scene raised, which must be a KeyboardInterrupt; with
    ``own_signals`` inside :func:`interrupts_raise`, else without (render_into then installs
    its own)."""
    out = tmp_path / "scaling.mp4"
    with pytest.raises(KeyboardInterrupt) as raised:  # a bare one would stop pytest itself
        if own_signals:
            with render_command.interrupts_raise() as signals:
                render_command.render_into(_scaling_scene(), out, "mp4", "low_quality",
                                           progress=False, signals=signals)
        else:
            render_command.render_into(_scaling_scene(), out, "mp4", "low_quality",
                                       progress=False)
    return raised.value


@pytest.mark.parametrize("own_signals", [True, False], ids=["signals", "no-signals"])
def test_an_interrupt_as_an_encoder_starts_orphans_no_thread(tmp_path, monkeypatch,
                                                              own_signals):
    """SIGINT arriving just after manim started a segment's encoder thread, before its writer
    kept the job: the render is interrupted and no encoder thread is left waiting for frames
    (one would keep the process from ever exiting). Also when the caller hands render_into
    no ``signals``: blocking signals in the main thread (as it did then) does not defer them,
    since the kernel hands them to an encoder thread."""
    from manim.scene import scene_file_writer

    started = scene_file_writer._PartialMovieEncodeJob.__init__
    sent = []

    def start_then_interrupt(job, *args, **kwargs):
        started(job, *args, **kwargs)
        if not sent:
            sent.append(job)
            os.kill(os.getpid(), signal.SIGINT)

    monkeypatch.setattr(scene_file_writer._PartialMovieEncodeJob, "__init__",
                        start_then_interrupt)
    before = set(_encoder_threads())
    try:
        raised = _render_interrupted(tmp_path, own_signals)
    finally:
        orphans = [t for t in _encoder_threads() if t not in before]
        for job in sent:  # unblock an orphan, so a failure here does not hang the suite
            job.abort()
    assert sent, "no encoder was started"
    assert orphans == []
    assert isinstance(raised, render_command.Interrupted)
    assert leftovers(tmp_path) == []


def test_an_interrupt_inside_a_full_seal_still_exits(tmp_path, monkeypatch):
    """The hang of issue 24 item 13, forced: manim's ``seal()`` marks the job sealed, then
    blocks putting the closing message on a full queue (the encoder is behind); SIGINT
    arrives inside that put. manim's abort then sealed again, sending nothing, and joined
    the encoder thread for ever. Now the render is interrupted at once, and no thread is
    left. (A watchdog unblocks the thread after 30 s, so that the old hang fails the test
    instead of hanging the suite.)"""
    from manim import config
    from manim.scene import scene_file_writer

    write_frame = scene_file_writer.VideoSegmentEncoder.write_frame

    def write_slowly(encoder, *args, **kwargs):  # an encoder behind, as on loaded cores
        time.sleep(0.2)
        return write_frame(encoder, *args, **kwargs)

    seal = scene_file_writer._PartialMovieEncodeJob.seal
    sealed = []

    def seal_interrupted(job):
        if not sealed and job.queue.full():  # the put below will block: signal inside it
            sealed.append(job)
            threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT)).start()
        seal(job)

    monkeypatch.setattr(config, "encoder_queue_size", 1)
    monkeypatch.setattr(scene_file_writer.VideoSegmentEncoder, "write_frame", write_slowly)
    monkeypatch.setattr(scene_file_writer._PartialMovieEncodeJob, "seal", seal_interrupted)
    hung = threading.Event()

    def watchdog():
        if not done.wait(30):
            hung.set()
            for job in sealed:
                job.queue.put((-1, None))

    done = threading.Event()
    threading.Thread(target=watchdog, daemon=True).start()
    before = set(_encoder_threads())
    try:
        raised = _render_interrupted(tmp_path, own_signals=True)
    finally:
        done.set()
    assert sealed, "no seal found its queue full"
    assert not hung.is_set(), "the interrupted render hung in manim's abort"
    assert isinstance(raised, render_command.Interrupted)
    assert [t for t in _encoder_threads() if t not in before] == []
    assert leftovers(tmp_path) == []


def test_a_signal_deferred_is_raised_at_the_end_even_if_the_block_fails():
    signals = render_command.Signals()
    with pytest.raises(render_command.Interrupted), signals.deferred():
        signals.signum = signal.SIGTERM  # as the handler notes it inside the block
        raise OSError("the block failed too")
    done = render_command.Signals()
    with done.deferred():
        done.signum, done.done = signal.SIGINT, True  # after the output is in place: no matter


def test_trex_render_runs_as_many_encoders_as_manim_cfg(tmp_path, monkeypatch):
    """No longer one encoder at a time (the old workaround for the hang): manim.cfg's
    number, read from the project's file wherever trex runs from; none set, manim's own."""
    import configparser

    parser = configparser.ConfigParser()
    parser.read(render_command.MANIM_CFG, encoding="utf-8")
    wanted = parser.getint("CLI", "max_inflight_encoders")
    assert wanted > 1
    monkeypatch.chdir(tmp_path)  # not the repository: its manim.cfg is still the one read
    settings = render_command._settings(tmp_path / "media", "mp4", "low_quality", False)
    assert settings["max_inflight_encoders"] == wanted
    bare = tmp_path / "manim.cfg"
    bare.write_text("[CLI]\nmedia_dir = media\n")
    assert render_command.inflight_encoders(bare) is None
    monkeypatch.setattr(render_command, "MANIM_CFG", bare)
    assert "max_inflight_encoders" not in render_command._settings(
        tmp_path / "media", "mp4", "low_quality", False)
