"""The lecture's directory: what DIR receives, its check before any work, and the rendered
chapters joined into it (``trex lecture``).

:mod:`trex.assemble` does the joining: one mp4 (packets remuxed, not encoded again), one
.srt, ``chapters.json`` and ``chapters.md``, and the chapters' ``teacher-notes.md``; the chapter mp4s are kept in ``chapters/``.
Everything is written into a stage beside DIR, then moved into place
(:func:`trex.output_dir.move_into_place`, only :data:`OUTPUTS`: other files in DIR stay).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from trex.chapters import Chapter, teacher_notes_markdown
from trex.inputs import make_parent

__all__ = ["CHAPTER_DIR", "DEFAULT_DIR", "LIST_JSON", "LIST_MD", "NOTES", "OUTPUTS", "SUBTITLES",
           "VIDEO", "check_output_dir", "join_lecture"]

DEFAULT_DIR = Path("media") / "lecture"
VIDEO, SUBTITLES, LIST_JSON, LIST_MD, CHAPTER_DIR, NOTES = (
    "lecture.mp4", "lecture.srt", "chapters.json", "chapters.md", "chapters", "teacher-notes.md")
OUTPUTS = (CHAPTER_DIR, VIDEO, SUBTITLES, LIST_JSON, LIST_MD, NOTES)  # what DIR receives


def check_output_dir(out_dir: Path) -> None:
    """DIR must be a directory (or not exist yet) whose entries we write are of the right
    kind; its parent is created. Raises ValueError with a one-line reason."""
    if out_dir.exists() and not out_dir.is_dir():
        raise ValueError("exists and is not a directory")
    for name in OUTPUTS:
        target = out_dir / name
        if target.exists() and target.is_dir() != (name == CHAPTER_DIR):
            kind = "not a directory" if name == CHAPTER_DIR else "a directory"
            raise ValueError(f"{name} in it is {kind}")
    make_parent(out_dir)
    if out_dir.is_dir() and not os.access(out_dir, os.W_OK):
        raise ValueError("cannot write there")


def join_lecture(chapters: Sequence[Chapter], videos: Sequence, stage: Path) -> str | None:
    """Write the lecture's files into ``stage`` (which holds ``chapters/``, the chapters'
    ``videos``); returns why the video had to be encoded again (None: remuxed)."""
    from trex import assemble as joiner

    reason = joiner.join_videos(videos, stage / VIDEO)
    starts = joiner.starts_of(videos)
    texts = []
    for video in videos:
        srt_file = video.path.with_suffix(".srt")
        texts.append(srt_file.read_text(encoding="utf-8") if srt_file.is_file() else None)
    durations = [v.duration for v in videos]
    (stage / SUBTITLES).write_text(joiner.join_subtitles(texts, starts, durations),
                                   encoding="utf-8")
    files = [f"{CHAPTER_DIR}/{v.path.name}" for v in videos]
    entries = joiner.chapter_entries(chapters, videos, files)
    (stage / LIST_JSON).write_text(joiner.chapters_json(entries), encoding="utf-8")
    (stage / LIST_MD).write_text(joiner.chapters_markdown(entries, VIDEO), encoding="utf-8")
    (stage / NOTES).write_text(teacher_notes_markdown(chapters), encoding="utf-8")
    return reason
