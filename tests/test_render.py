"""Pixels and video: two last-frame comparisons, one real low-quality render read back with PyAV.

The last-frame tests use manim's ``frames_comparison``; their control frames live in
``tests/control_data/render/`` and are rewritten with ``pytest tests/test_render.py --set_test``
(after a deliberate visual change). ``tests/conftest.py`` lets them run on Debian's cairo 1.16.

The render test runs ``manim -ql scenes/gravity.py Gravity`` into a temporary media directory
and checks the video (854×480, 15 fps, duration and frame count from the scene's own plays)
and the ``.srt`` beside it (one well-formed cue per caption change, in order, at the time of
the play that changed it).
"""

from __future__ import annotations

import configparser
import importlib.util
import itertools
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import av
import pytest
from manim import Wait
from manim.utils.testing.frames_comparison import frames_comparison

from story.reading import readable
from trex.render_command import X264_OPTIONS
from trex.scene_graph import build

__module_test__ = "render"

ROOT = Path(__file__).resolve().parents[1]
#: What a scene reads from the environment under plain manim (left out of the render's).
SCENE_ENV = ("TREX_LOG", "TREX_POLYGON")

#: The scene rendered for real.
RENDERED = ("gravity", "Gravity")
FPS, WIDTH, HEIGHT = 15, 854, 480


def scene_class(file: str, name: str):
    """A Scene class of ``scenes/<file>.py`` (imported by path: scenes/ is not a package)."""
    module_name = f"trex_scenes_{file}"
    module = sys.modules.get(module_name)
    if module is None:
        spec = importlib.util.spec_from_file_location(module_name, ROOT / "scenes" / f"{file}.py")
        module = importlib.util.module_from_spec(spec)
        sys.modules[module_name] = module
        spec.loader.exec_module(module)
    return getattr(module, name)


# --- last frames ---------------------------------------------------------------------------------

# handed their default runs: whatever TREX_POLYGON and TREX_LOG say
PolygonScene = scene_class("polygon", "PolygonScene").handed()
Scaling = scene_class("scaling", "Scaling").handed()


@frames_comparison(last_frame=True, base_scene=PolygonScene)
def test_polygon_last_frame(scene):
    PolygonScene.construct(scene)
    scene.wait()


@frames_comparison(last_frame=True, base_scene=Scaling)
def test_scaling_last_frame(scene):
    Scaling.construct(scene)
    scene.wait()


# --- one real render -----------------------------------------------------------------------------

_CUE = re.compile(
    r"(\d+)\n(\d\d):(\d\d):(\d\d),(\d{3}) --> (\d\d):(\d\d):(\d\d),(\d{3})\n(.+?)(?:\n\n|\n?$)",
    re.S,
)


def parse_srt(text: str) -> list[tuple[int, float, float, str]]:
    """(number, start, end, text) per cue; the whole file must be cues and nothing else."""
    cues, position = [], 0
    text = text.replace("\r\n", "\n").strip("\n") + "\n"
    for match in _CUE.finditer(text):
        assert match.start() == position, f"not a cue at {text[position:position + 60]!r}"
        g = match.groups()
        start = int(g[1]) * 3600 + int(g[2]) * 60 + int(g[3]) + int(g[4]) / 1000
        end = int(g[5]) * 3600 + int(g[6]) * 60 + int(g[7]) + int(g[8]) / 1000
        cues.append((int(g[0]), start, end, g[9].strip()))
        position = match.end()
    assert position == len(text), f"trailing text {text[position:position + 60]!r}"
    return cues


def frames_of(play) -> int:
    """Frames manim renders for a play at FPS: a still wait ``int(run_time × fps)``, any
    other play a frame at each step of ``np.arange(0, run_time, 1 / fps)``."""
    frames = round(play.run_time * FPS, 6)
    if all(isinstance(a, Wait) for a in play.animations):
        return int(frames)
    return math.ceil(frames)


def render_scene(media: Path, scene: tuple[str, str] = RENDERED) -> Path:
    """``manim -ql`` of the rendered scene (or another), as a user runs it from the repository
    root (so ``manim.cfg`` applies), into ``media``: the video's path."""
    file, name = scene
    env = {k: v for k, v in os.environ.items() if k not in SCENE_ENV}
    # Caching off: a first render in a fresh directory has nothing to reuse, and hashing
    # every play's mobjects would only slow it down.
    command = [sys.executable, "-m", "manim", "-ql", "--disable_caching", "--media_dir",
               str(media), f"scenes/{file}.py", name]
    done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    video = media / "videos" / file / f"{HEIGHT}p{FPS}" / f"{name}.mp4"
    assert video.is_file(), sorted(str(p) for p in media.rglob("*"))
    return video


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    video = render_scene(tmp_path_factory.mktemp("media"))
    _, plays = build(scene_class(*RENDERED).handed())  # exact run times, not the graph's
    return video, plays


def test_same_input_gives_the_same_video(tmp_path):
    """Two renders in two processes are the same file, byte for byte. manim.cfg has x264 run
    one thread and no macroblock tree; with the tree, Scaling gave a different file in each
    of three processes (the same frames, coded differently)."""
    first, again = (render_scene(tmp_path / name, ("scaling", "Scaling"))
                    for name in ("one", "two"))
    assert first.read_bytes() == again.read_bytes()


def test_trex_render_encodes_as_manim_cfg_does():
    parser = configparser.ConfigParser()
    parser.read(ROOT / "manim.cfg")
    assert dict(parser["video_encoder.options"]) == X264_OPTIONS


def test_render_video_stream(rendered):
    video, plays = rendered
    expected_frames = sum(frames_of(p) for p in plays)
    with av.open(str(video)) as container:
        stream = container.streams.video[0]
        assert (stream.codec_context.width, stream.codec_context.height) == (WIDTH, HEIGHT)
        assert stream.guessed_rate == FPS
        assert float(stream.average_rate) == pytest.approx(FPS, rel=1e-3)
        frames = sum(1 for _ in container.decode(stream))
        duration = float(stream.duration * stream.time_base)
    assert abs(frames - expected_frames) <= 1, (frames, expected_frames)
    assert duration == pytest.approx(frames / FPS, abs=1.5 / FPS)


def test_render_subtitles(rendered):
    video, plays = rendered
    srt = video.with_suffix(".srt")
    assert srt.is_file()
    cues = parse_srt(srt.read_text(encoding="utf-8"))
    # One cue per caption change, at the time of the play that changed it.
    expected, t = [], 0.0
    for play in plays:
        if play.subcaption:
            expected.append((t, play.subcaption))
        t += frames_of(play) / FPS
    assert [c[3] for c in cues] == [text for _, text in expected]
    assert [c[0] for c in cues] == list(range(1, len(cues) + 1))
    for (_, start, end, text), (at, _) in zip(cues, expected, strict=True):
        assert text and 0 <= start < end <= t + 1 / FPS, (start, end, text)
        assert start == pytest.approx(at, abs=1.5 / FPS), text
    starts = [c[1] for c in cues]
    assert starts == sorted(starts)
    # a subtitle stays on screen until the next one replaces it, and so does its cue
    for (_, _, end, text), (_, start, _, _) in itertools.pairwise(cues):
        assert end == pytest.approx(start, abs=1.5 / FPS), text
    # and each stays long enough to read, in the video's own .srt (issue 12)
    assert [text for _, start, end, text in cues if not readable(text, end - start)] == []
