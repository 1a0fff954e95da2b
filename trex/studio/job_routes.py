"""The studio's job requests: ``POST /api/hunt`` and ``POST /api/render`` start a job of
:mod:`trex.studio.jobs` and answer ``{"job": id}``; its status is ``GET /api/jobs/{id}``.

The request is checked here, before any process starts (4xx, one line); names are the
command line's, and a heuristic of one's own is one named on the studio's command line.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Protocol

from story.registry import heuristics, triangulations
from trex.studio import api
from trex.studio.jobs import Job, Jobs


class Own(Protocol):
    """The studio's own heuristics, by name: a dict of them, or the worker that runs them."""

    def __contains__(self, name: object) -> bool: ...
    def __iter__(self) -> Iterator[str]: ...

MAX_BUDGET = 100_000
MAX_HUNT_VERTICES = 20


def _int(body: dict, key: str, default: int, low: int, high: int) -> int:
    value = body.get(key, default)
    if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
        raise api.BadRequest(f"{key} must be a whole number from {low} to {high}")
    return value


def _timeout(seconds: float | None) -> list[str]:
    return ["--call-timeout", f"{seconds or 0:g}"]


def _last_json_line(_job: Job, stdout: str) -> dict:
    return json.loads(stdout.strip().splitlines()[-1])


def hunt(body: dict, jobs: Jobs, own: Own, timeout: float | None) -> dict:
    """Start ``trex hunt``'s search for the named heuristic."""
    name = body.get("heuristic")
    if not isinstance(name, str) or (name not in heuristics() and name not in own):
        raise api.BadRequest(f"unknown heuristic {name!r} (known: {', '.join([*heuristics(), *own])})")
    budget = _int(body, "budget", 5000, 1, MAX_BUDGET)
    largest = _int(body, "max_vertices", 8, 4, MAX_HUNT_VERTICES)
    seed = _int(body, "seed", 0, -(2**31), 2**31 - 1)
    args = ["studio-hunt", name, "--budget", str(budget), "--max-vertices", str(largest),
            "--seed", str(seed), "--progress", "{folder}/progress.json", *_timeout(timeout)]
    return {"job": jobs.submit("hunt", args, _last_json_line).id}


def render(body: dict, jobs: Jobs, own: Own, timeout: float | None) -> dict:
    """Queue the video (``kind: video``) or the slides (``kind: slides``) of a rule's or an
    algorithm's scene on the request's polygon."""
    scene, kind = body.get("scene"), body.get("kind", "video")
    known = [*heuristics(), *own, *triangulations()]
    if not isinstance(scene, str) or scene not in known:
        raise api.BadRequest(f"unknown scene {scene!r} (known: {', '.join(known)})")
    if kind not in ("video", "slides"):
        raise api.BadRequest(f"kind must be video or slides, not {kind!r}")
    rings = api.rings_of(body)
    api.checked_polygon(rings)
    if len(rings) > 1 and scene not in triangulations():
        raise api.BadRequest(f"{scene} takes polygons without holes", 422)

    def prepare(folder: Path) -> None:
        data = rings if len(rings) > 1 else rings[0]  # as `trex` reads them
        (folder / "polygon.json").write_text(json.dumps(data) + "\n", encoding="utf-8")

    polygon = ["--polygon", "{folder}/polygon.json"]
    if kind == "video":
        args = ["studio-video", scene, *polygon, "-o", "{folder}/video.mp4",
                "--progress", "{folder}/progress.json", *_timeout(timeout)]
        where = "video.mp4"
    else:
        args = ["studio-slides", scene, *polygon, "-o", "{folder}/slides", *_timeout(timeout)]
        where = "slides/index.html"

    def finish(job: Job, _stdout: str) -> dict:
        return {"url": f"/media/{job.id}/{where}"}

    return {"job": jobs.submit(kind, args, finish, prepare).id}
