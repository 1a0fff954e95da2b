"""trex.output_dir.move_into_place: a directory built beside its target, moved into place
whole (trex player, trex slides) or entry by entry (trex lecture)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from trex import output_dir
from trex.output_dir import move_into_place


def tree(root: Path) -> dict[str, str]:
    return {str(p.relative_to(root)): p.read_text() for p in sorted(root.rglob("*"))
            if p.is_file()}


def built(tmp_path: Path, files: dict[str, str]) -> Path:
    folder = tmp_path / ".built"
    for name, text in files.items():
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text(text)
    return folder


def test_a_new_target_is_the_built_directory(tmp_path):
    move_into_place(built(tmp_path, {"a": "1", "d/b": "2"}), tmp_path / "out")
    assert tree(tmp_path / "out") == {"a": "1", "d/b": "2"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_a_whole_move_replaces_the_earlier_directory(tmp_path):
    target = tmp_path / "out"
    (target / "old").mkdir(parents=True)
    (target / "old" / "x").write_text("earlier")
    move_into_place(built(tmp_path, {"a": "1"}), target)
    assert tree(target) == {"a": "1"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]  # no .old left


def test_entries_replace_their_namesakes_and_other_files_stay(tmp_path):
    target = tmp_path / "out"
    (target / "chapters").mkdir(parents=True)
    (target / "chapters" / "01-old.mp4").write_text("old chapter")
    (target / "lecture.mp4").write_text("old lecture")
    (target / "notes.txt").write_text("the user's")
    stage = built(tmp_path, {"chapters/01-new.mp4": "new chapter", "lecture.mp4": "new",
                             "unlisted": "not moved"})
    move_into_place(stage, target, ("chapters", "lecture.mp4"))
    assert tree(target) == {"chapters/01-new.mp4": "new chapter", "lecture.mp4": "new",
                            "notes.txt": "the user's"}
    assert sorted(p.name for p in tmp_path.iterdir()) == [".built", "out"]  # no .old left


def test_a_failed_move_puts_the_earlier_directory_back(tmp_path, monkeypatch):
    target = tmp_path / "out"
    (target / "chapters").mkdir(parents=True)
    (target / "chapters" / "01.mp4").write_text("earlier")
    stage = built(tmp_path, {"chapters/01.mp4": "new"})
    real = os.replace

    def failing(src, dst):
        if Path(src) == stage / "chapters":
            raise OSError("disk full")
        real(src, dst)

    monkeypatch.setattr(output_dir.os, "replace", failing)
    with pytest.raises(OSError, match="disk full"):
        move_into_place(stage, target, ("chapters",))
    assert tree(target) == {"chapters/01.mp4": "earlier"}
    assert sorted(p.name for p in tmp_path.iterdir()) == [".built", "out"]
