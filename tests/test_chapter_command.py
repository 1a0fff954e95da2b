"""``trex chapter``: the hidden command a lecture's chapter renders in (trex.chapter_command),
started by the pool (trex.chapter_pool) with named options."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from trex.chapter_command import chapter, chapter_command_line
from trex.cli import main


def run(*args):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_it_is_hidden_from_the_help():
    code, stdout, _ = run("--help")
    listed = [line.split()[0] for line in stdout.split("Commands:")[1].splitlines() if line]
    assert code == 0 and "lecture" in listed and "chapter" not in listed


def test_the_pools_command_line_reads_back_as_what_it_was_given():
    """Every value, even a polygon file whose name starts with a dash, is the option's."""
    command = chapter_command_line(Path("scenes/gravity.py"), "Gravity", Path("out/01-g.mp4"),
                                   "m", "-odd.json", "source")
    assert command[2:4] == ["trex", "chapter"]
    assert chapter.make_context("chapter", command[4:]).params == {
        "scene_file": "scenes/gravity.py", "class_name": "Gravity", "output": "out/01-g.mp4",
        "quality": "m", "polygon": "-odd.json", "panel": "source"}


def test_options_left_out_are_the_scenes_own():
    command = chapter_command_line(Path("s.py"), None, Path("o.mp4"), "l", None, None)
    assert chapter.make_context("chapter", command[4:]).params == {
        "scene_file": "s.py", "class_name": None, "output": "o.mp4", "quality": "l",
        "polygon": None, "panel": None}


def test_a_missing_option_is_one_line_and_exit_2(tmp_path):
    code, stdout, stderr = run("chapter", "--scene-file", "scenes/gravity.py")
    assert code == 2 and stdout == ""
    assert stderr.startswith("error: Missing option '--output'") and stderr.count("\n") == 1


def test_a_scene_that_does_not_load_is_one_line_and_exit_1(tmp_path):
    broken = tmp_path / "broken.py"
    broken.write_text("raise RuntimeError('the chapter broke')\n")
    output = tmp_path / "01-broken.mp4"
    code, stdout, stderr = run("chapter", "--scene-file", str(broken), "--output", str(output))
    assert code == 1 and stdout == ""
    assert stderr == ("error: render failed: ValueError: cannot load broken.py: RuntimeError: "
                      "the chapter broke\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["broken.py"]
