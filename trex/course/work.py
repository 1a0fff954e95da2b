"""The body of each task, run on a Dask worker: it renders with the existing commands'
functions and returns what it wrote.

Each body writes beside its outputs and renames into place (``render_into``, the lecture's
join, ``built_beside``), so a task that fails or whose worker is killed leaves no
half-written output, only a temporary entry that :func:`trex.course.run.sweep` removes.
A body raises :class:`TaskFailed` with a one-line reason; it returns a :class:`Done`.
"""

from __future__ import annotations

import contextlib
import io
import os
import shutil
import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, cast

from trex.course.tasks import (
    ChapterSettings,
    JoinSettings,
    SceneSettings,
    SlidesSettings,
    StudentSettings,
    Task,
)
from trex.inputs import error_line

TEMP_SUFFIXES = (".render", ".build", ".join", ".old", ".tmp")  # what sweep may remove


class TaskFailed(Exception):
    """A task that could not be done; the message is its one-line reason."""


@dataclass(frozen=True)
class Done:
    """What a finished task wrote (relative to the output directory) and how long it took."""

    files: tuple[str, ...]
    video_seconds: float
    wall_seconds: float
    worker: str


def run_task(task: Task, out_dir: str, *deps: Done) -> Done:
    """Do ``task`` into ``out_dir`` (``deps``: what its dependencies wrote)."""
    began = time.monotonic()
    root = Path(out_dir)
    try:
        # what the commands' functions print (``reused …``) would land in the client's stdout
        with contextlib.redirect_stdout(io.StringIO()):
            files, seconds = BODIES[task.kind](task, root, deps)
    except TaskFailed:
        raise
    except Exception as exc:  # a render that failed: one line, as trex render says it
        raise TaskFailed(f"{type(exc).__name__}: {error_line(exc)}") from None
    return Done(tuple(files), round(seconds, 3), round(time.monotonic() - began, 3),
                _worker_name())


def _worker_name() -> str:
    try:
        from distributed import get_worker

        return str(get_worker().name)
    except ValueError:  # not on a worker (a test calling the body itself)
        return f"pid {os.getpid()}"


def _duration(path: Path) -> float:
    from trex.assemble import probe

    return float(probe(path).duration)


def _handed(cls: type, polygon: str | None, panel: str | None) -> type:
    """The scene handed its run on ``polygon`` as ``trex render`` and ``trex lecture`` hand
    it (None: what ``manim`` would play, ``TREX_*`` read from the environment, which the
    fingerprints cover: :func:`trex.course.command.code_fingerprint`)."""
    from trex.render_command import scene_input

    return scene_input(cls, polygon, panel)


# --- the bodies -------------------------------------------------------------------------------------


def _chapter(task: Task, root: Path, _deps) -> tuple[list[str], float]:
    """One chapter as ``trex lecture`` renders it (its step marks' settings too, so that
    ``trex slides lecture --lecture DIR/lecture-K`` reuses it)."""
    from trex import chapter_command as cc
    from trex.render_command import QUALITIES, load_scene_class, render_into

    s = cast(ChapterSettings, task.settings)  # each body is its kind's (BODIES)
    chapter = s["chapter"]
    output = root / task.files[0]
    output.parent.mkdir(parents=True, exist_ok=True)
    cls = load_scene_class(Path(chapter["scene_file"]), chapter["scene_class"])
    made_by = cc.render_settings(chapter["scene_file"], chapter["scene_class"], s["quality"],
                                 s["polygon"], s["panel"])
    render_into(_handed(cls, s["polygon"], s["panel"]), output, "mp4", QUALITIES[s["quality"]],
                progress=False, marks_made_by=made_by)
    files = [task.files[0]] + [str(Path(task.files[0]).with_suffix(x)) for x in (".srt",)
                               if output.with_suffix(x).is_file()]
    return files, _duration(output)


def _join(task: Task, root: Path, deps: Sequence[Done]) -> tuple[list[str], float]:
    """The chapters joined by ``trex lecture``'s own join, staged beside and renamed in."""
    from trex import chapters as ch
    from trex import lecture_join as lj
    from trex.assemble import probe

    s = cast(JoinSettings, task.settings)
    folder = root / s["folder"]
    chapters = [ch.Chapter(**c) for c in s["chapters"]]
    videos = [probe(root / done.files[0]) for done in deps]
    stage = Path(tempfile.mkdtemp(prefix=".lecture.", suffix=".join", dir=folder))
    try:
        lj.join_lecture(chapters, videos, stage)
        for name in task.files:
            os.replace(stage / Path(name).name, root / name)
    finally:
        shutil.rmtree(stage, ignore_errors=True)
    return list(task.files), float(sum(v.duration for v in videos))


def _scene(task: Task, root: Path, _deps) -> tuple[list[str], float]:
    """One scene on one polygon, as ``trex render`` renders it."""
    from trex.render_command import QUALITIES, load_scene_class, render_into, resolve_scene

    s = cast(SceneSettings, task.settings)
    if ".py:" in s["scene"]:
        from metaphors.scene import scene_for_heuristic

        cls = scene_for_heuristic(s["scene"])
    else:
        cls = load_scene_class(*resolve_scene(s["scene"]))
    output = root / task.files[0]
    render_into(_handed(cls, s["polygon"], s["panel"]), output, s["format"],
                QUALITIES[s["quality"]], progress=False)
    files = [task.files[0]]
    if s["format"] != "png" and output.with_suffix(".srt").is_file():
        files.append(str(Path(task.files[0]).with_suffix(".srt")))
    return files, 0.0 if s["format"] == "png" else _duration(output)


def _slides(task: Task, root: Path, _deps) -> tuple[list[str], float]:
    """``trex slides``' page, of a scene or of the lecture (reusing the course's chapters)."""
    from trex import chapters as ch
    from trex import slides_command as sc
    from trex.scene_inputs import choose

    s = cast(SlidesSettings, task.settings)
    target = root / Path(task.files[0]).parent
    if s["scene"] == "lecture":
        chapters = [ch.Chapter(**c) for c in s["chapters"]]
        sc._lecture_slides(chapters, target, s["quality"], 1, s["polygon"], s["panel"],
                           root / s["lecture"])
    else:
        chosen = choose(s["scene"], s["polygon"], None, "slides", several_runs=True)
        played, subtitle = sc._played(chosen, s["scene"])
        played = played.with_panel(s["panel"]) if s["panel"] else played
        sc._scene_slides(played, s["quality"], subtitle, target)
    clips = sorted((target / "clips").glob("*.mp4"))
    return [task.files[0]], sum(_duration(c) for c in clips)


def _student(task: Task, root: Path, _deps) -> tuple[list[str], float]:
    """One student's sheets (``trex exercises``' files) and, if asked, a video of the first
    exercise's heuristic on its polygon; built beside and renamed into place whole."""
    from story.exercises import make_exercises
    from trex.exercises_command import write_exercises
    from trex.output_dir import move_into_place

    s = cast(StudentSettings, task.settings)
    target = root / Path(task.files[0]).parent
    target.parent.mkdir(parents=True, exist_ok=True)
    built = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".build", dir=target.parent))
    try:
        items = make_exercises(s["n"], s["seed"])
        written = write_exercises(items, built, s["seed"])
        seconds = _student_video(items, built / "video.mp4", s["quality"]) if s["video"] else 0.0
        built.chmod(0o755)  # mkdtemp makes it private
        move_into_place(built, target)
    finally:
        shutil.rmtree(built, ignore_errors=True)
    base = Path(task.files[0]).parent
    names = [p.name for p in written] + (["video.mp4"] if s["video"] else [])
    return sorted(str(base / n) for n in names), seconds


def _student_video(items: Sequence, output: Path, quality: str) -> float:
    from metaphors.scene import TraceScene
    from trex.render_command import QUALITIES, render_into

    exercise = next((e for e in items if e.heuristic), None)
    if exercise is None:
        raise TaskFailed("no exercise names a heuristic to play")
    played = cast("type[TraceScene]", type("StudentVideo", (TraceScene,), {
        "algorithm": exercise.heuristic, "polygon": exercise.spec, "__module__": __name__}))
    render_into(played.handed(), output, "mp4", QUALITIES[quality], progress=False, srt=False)
    return _duration(output)


BODIES: dict[str, Callable[[Task, Path, Any], tuple[list[str], float]]] = {
    "chapter": _chapter, "join": _join, "scene": _scene, "slides": _slides,
    "student": _student,
}
