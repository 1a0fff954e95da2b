"""``course.json``: one record per task of the last run, and what a rerun may reuse.

A record is ``{"id", "kind", "item", "files", "status", "video_seconds", "wall_seconds",
"worker", "fingerprint", "error"}``, status ``done``, ``failed`` or ``reused``. A task is
reused when the manifest's record of it has its fingerprint, was done (or reused) and
every file it lists is there. The manifest is written atomically after each task, so an
interrupted course still knows what it finished.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from geometry.io import write_atomic
from trex.course.tasks import Task

MANIFEST = "course.json"
STATUSES = ("done", "failed", "reused")


def record(task: Task, status: str, *, files: tuple[str, ...] = (), video_seconds: float = 0.0,
           wall_seconds: float = 0.0, worker: str | None = None,
           error: str | None = None) -> dict[str, Any]:
    """The manifest's record of ``task``."""
    assert status in STATUSES, status
    return {"id": task.id, "kind": task.kind, "item": task.item, "files": list(files),
            "status": status, "video_seconds": video_seconds, "wall_seconds": wall_seconds,
            "worker": worker, "fingerprint": task.fingerprint, "error": error}


def read_manifest(out_dir: Path) -> dict[str, dict[str, Any]]:
    """The records of the last run by task id; none when there is no manifest or it cannot
    be read as one (then every task renders again)."""
    try:
        data = json.loads((out_dir / MANIFEST).read_text(encoding="utf-8"))
        records = data["tasks"]
        return {r["id"]: r for r in records if isinstance(r, dict) and isinstance(r.get("id"),
                                                                                   str)}
    except (OSError, ValueError, KeyError, TypeError):
        return {}


def reusable(task: Task, previous: dict[str, dict[str, Any]], out_dir: Path) -> dict | None:
    """The earlier record of ``task`` if its outputs are there, made by the same
    fingerprint; else None."""
    old = previous.get(task.id)
    if old is None or old.get("fingerprint") != task.fingerprint:
        return None
    files = old.get("files")
    if old.get("status") not in ("done", "reused") or not isinstance(files, list) or not files:
        return None
    if not all(isinstance(f, str) and (out_dir / f).is_file() for f in files):
        return None
    return old


def write_manifest(out_dir: Path, title: str, records: list[dict[str, Any]]) -> None:
    text = json.dumps({"title": title, "tasks": records}, indent=2, ensure_ascii=False)
    write_atomic(out_dir / MANIFEST, text + "\n")
