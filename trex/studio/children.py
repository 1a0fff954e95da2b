"""The studio's jobs as hidden commands, each run in a process of its own by
:mod:`trex.studio.jobs`: ``trex studio-hunt``, ``trex studio-video``, ``trex studio-slides``.

A job tells its progress by rewriting one small JSON file (``--progress``:
``{"done": k, "total": n}``, atomically, so the server never reads half of it) and its
result on stdout; errors are one line on stderr with the command line's exit statuses.
A heuristic of one's own runs here, never in the server, under ``--call-timeout``.
"""

from __future__ import annotations

import json
import os
import sys
import tempfile
from pathlib import Path
from typing import cast

import click

from geometry.io import polygon_to_json_points, write_atomic
from trex.inputs import call_timeout_option, error_line, fail, first_line, load_or_exit
from trex.run_commands import HeuristicOrFile
from usercode.errors import UserHeuristicError
from usercode.heuristic import UserHeuristic
from usercode.loading import is_user_spec


class Progress:
    """Writes ``done`` out of ``total`` to a file, at most every ``every`` steps."""

    def __init__(self, path: Path, total: int, every: int = 1) -> None:
        self.path, self.total, self.every, self.done = path, total, max(every, 1), 0
        self.write()

    def add(self, k: int = 1) -> None:
        before = self.done
        self.done += k
        if self.done // self.every != before // self.every or self.done >= self.total:
            self.write()

    def write(self) -> None:
        write_atomic(self.path, json.dumps({"done": self.done, "total": self.total}))


progress_option = click.option("--progress", "progress_file", required=True, metavar="FILE",
                               help="Where to write the progress.")


@click.command(name="studio-hunt", hidden=True)
@click.argument("heuristic", type=HeuristicOrFile())
@click.option("--budget", type=click.IntRange(min=1), default=5000)
@click.option("--seed", type=int, default=0)
@click.option("--max-vertices", type=click.IntRange(min=4), default=8)
@progress_option
@call_timeout_option
def studio_hunt(heuristic: str | UserHeuristic, budget: int, seed: int, max_vertices: int,
                progress_file: str) -> None:
    """Hunt a counterexample (as ``trex hunt``), telling the progress; one JSON line."""
    from story.hunt import hunt, reason

    progress = Progress(Path(progress_file), budget, every=max(budget // 100, 1))
    try:
        result = hunt(heuristic, budget=budget, seed=seed, max_vertices=max_vertices,
                      progress=progress.add)
    except ValueError as exc:  # one's own tried to end the program
        fail(f"{heuristic}: {error_line(exc)}")
    if result.error is not None:  # one's own raised, answered nonsense or timed out: the
        fail(f"{heuristic}: {first_line(result.error)}")  # job fails (issue 20), in one line
    found = result.found and result.polygon is not None
    click.echo(json.dumps({
        "heuristic": str(heuristic), "found": found,
        "polygon": (polygon_to_json_points(list(result.polygon.points))
                    if found and result.polygon is not None else None),  # (found says so)
        "why": reason(result) if found else None, "tried": result.tried,
    }, ensure_ascii=False))


def played_scene(rule: str) -> type:
    """The Scene class that plays a rule or an algorithm (a built-in's scene in ``scenes/``,
    or that of a heuristic of one's own)."""
    from trex.hunt_command import heuristic_video
    from usercode.heuristic import load_user_heuristic

    try:
        return heuristic_video(load_user_heuristic(rule) if is_user_spec(rule) else rule)
    except ValueError as exc:
        fail(f"{rule}: {error_line(exc)}")


def _total_frames(cls: type, quality: str, beside: Path) -> int:
    """How many frames the scene will write: one dry run of it (nothing drawn or encoded),
    its scratch directory in ``beside`` (the job's folder: the studio writes only there)."""
    from manim import config, tempconfig

    with tempfile.TemporaryDirectory(prefix=".count-", dir=beside) as media, tempconfig({
        "quality": quality, "dry_run": True, "disable_caching": True, "media_dir": media,
        "progress_bar": "none", "verbosity": "ERROR", "preview": False,
    }):
        scene = cls()
        scene.render()
        return max(round(scene.renderer.time * config.frame_rate), 1)


def _counting(scene, progress: Progress):
    """The scene, its writer telling ``progress`` of every frame it is handed."""
    writer = scene.renderer.file_writer
    write_frame = writer.write_frame

    def counted(pixels, *, repeat: int = 1):
        write_frame(pixels, repeat=repeat)
        progress.add(repeat)

    writer.write_frame = counted
    return scene


@click.command(name="studio-video", hidden=True)
@click.argument("rule")
@click.option("--polygon", required=True, metavar="FILE")
@click.option("-o", "--output", required=True, metavar="FILE.mp4")
@progress_option
@call_timeout_option
def studio_video(rule: str, polygon: str, output: str, progress_file: str) -> None:
    """Render RULE's scene on POLYGON at 480p (as ``trex render``), telling frames written
    out of the total."""
    from geometry.triangulate import HOLE_ALGORITHMS
    from story.scene_kinds import algorithm_of
    from trex.render_command import (
        QUALITIES,
        RUN_ERRORS,
        render_into,
        run_once,
        scene_input,
        scene_run,
    )
    from trex.signals import EXIT_SIGNAL, Interrupted, interrupts_raise

    cls = played_scene(rule)
    spec = scene_run(cls, polygon, load_or_exit(polygon,
                                                holes=algorithm_of(cls) in HOLE_ALGORITHMS))
    try:
        if spec is not None:
            run_once(spec)
        played = scene_input(cls, polygon)
        total = _total_frames(played, QUALITIES["l"], Path(output).parent)
    except RUN_ERRORS as exc:
        fail(f"{rule}: {error_line(exc)}")
    progress = Progress(Path(progress_file), total, every=15)
    with interrupts_raise() as signals:
        try:
            render_into(lambda: _counting(played(), progress), Path(output), "mp4",
                        QUALITIES["l"], progress=False, signals=signals)
        except Interrupted as exc:
            click.echo(f"error: {rule}: render interrupted; nothing written", err=True)
            raise click.exceptions.Exit(EXIT_SIGNAL + exc.signum) from None
        except UserHeuristicError as exc:
            fail(f"{rule}: {exc}")
    click.echo(output)


@click.command(name="studio-slides", hidden=True)
@click.argument("rule")
@click.option("--polygon", required=True, metavar="FILE")
@click.option("-o", "--output", required=True, metavar="DIR")
@call_timeout_option
@click.pass_context
def studio_slides(ctx: click.Context, rule: str, polygon: str, output: str) -> None:
    """``trex slides`` of RULE's scene on POLYGON, into DIR."""
    from trex.slides_command import slides

    cls = played_scene(rule)
    if is_user_spec(rule):
        scene = rule
    else:
        scene = f"{Path(cast(str, sys.modules[cls.__module__].__file__)).stem}:{cls.__name__}"  # a file's
    ctx.invoke(slides, scene=scene, polygon=polygon, saved=None, quality="l", panel=None,
               output=output, jobs=None, only=None, lecture_dir=None)


def _own_claims(body: dict, own: dict[str, UserHeuristic]) -> list[dict]:
    """The table's rows of one's own heuristics (``body["rules"]``, default all), each one's
    failure its own row's."""
    from trex.studio import api

    rows = []
    for name in [n for n in body.get("rules", own) if n in own]:
        try:
            rows += api.claims(body, own, names=[name])
        except api.BadRequest:
            raise  # the polygon itself was refused: the same for every rule
        except BaseException as exc:  # SystemExit, KeyboardInterrupt: the user's
            rows.append(api.failed_claim(name, f"{name}: {type(exc).__name__}: {error_line(exc)}"))
    return rows


def _answer(request: dict, own: dict[str, UserHeuristic]) -> dict:
    from trex.studio import api

    routes = {"diagonal": api.diagonal, "triangulate": api.triangulate, "claims": _own_claims}
    try:
        return {"ok": routes[request["route"]](request["body"], own)}
    except api.BadRequest as exc:
        return {"error": str(exc), "status": exc.status}
    except BaseException as exc:  # whatever the user's code raised
        return {"error": f"{type(exc).__name__}: {error_line(exc)}", "status": 422}


@click.command(name="studio-own", hidden=True)
@click.argument("specs", nargs=-1, metavar="FILE.py:FUNCTION...")
@call_timeout_option
def studio_own(specs: tuple[str, ...]) -> None:
    """Answer the studio's live requests about one's own heuristics: a JSON line in, a JSON
    line out (:mod:`trex.studio.own`)."""
    from usercode.heuristic import load_user_heuristic

    answers = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)  # whatever the user's code prints goes to stderr, never into the answers
    sys.stdout = sys.stderr
    try:
        own = {spec: load_user_heuristic(spec) for spec in specs}
    except UserHeuristicError as exc:
        fail(str(exc))
    for line in sys.stdin:
        answers.write(json.dumps(_answer(json.loads(line), own), ensure_ascii=False) + "\n")
        answers.flush()


COMMANDS = (studio_hunt, studio_video, studio_slides, studio_own)
