"""A user's function that never returns is stopped after --call-timeout seconds, with one
line: for trex hunt, diagonal and render alike (SIGALRM in the main thread, so the run a
video records is recorded in the process that renders)."""

import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from geometry.polygon import Polygon
from geometry.samples import make_sample
from usercode.errors import UserHeuristicError
from usercode.heuristic import load_user_heuristic
from usercode.limits import call_timeout, set_call_timeout

ROOT = Path(__file__).resolve().parent.parent

LOOP = '''
def forever(polygon):
    """Never returns, and swallows what it can."""
    while True:
        try:
            pass
        except Exception:
            pass
'''


@pytest.fixture
def looping(tmp_path):
    path = tmp_path / "loop.py"
    path.write_text(textwrap.dedent(LOOP))
    return f"{path}:forever"


def trex(*args):
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run([sys.executable, "-m", "trex.cli", *args], capture_output=True,
                          text=True, cwd=ROOT, env=env, timeout=120)


def test_a_looping_function_is_stopped_in_process(looping):
    before = call_timeout()
    set_call_timeout(0.3)
    try:
        h = load_user_heuristic(looping)
        start = time.monotonic()
        with pytest.raises(UserHeuristicError, match=r"forever did not finish within 0\.3 s"):
            h.run(Polygon.from_points(make_sample("counterexample")))
        assert time.monotonic() - start < 3
    finally:
        set_call_timeout(before)


def test_a_looping_file_is_stopped_while_loading(tmp_path):
    path = tmp_path / "hang.py"
    path.write_text("while True:\n    pass\ndef f(polygon):\n    return 0, 2\n")
    before = call_timeout()
    set_call_timeout(0.3)
    try:
        with pytest.raises(UserHeuristicError, match="loading did not finish"):
            load_user_heuristic(f"{path}:f")
    finally:
        set_call_timeout(before)


@pytest.mark.parametrize("command", [
    ["diagonal", "counterexample", "--heuristic", "{spec}"],
    ["render", "{spec}", "--polygon", "counterexample", "-o", "{out}"],
])
def test_each_command_stops_it_with_one_line(looping, tmp_path, command):
    args = [a.format(spec=looping, out=tmp_path / "x.mp4") for a in command]
    start = time.monotonic()
    result = trex(*args, "--call-timeout", "0.5")
    assert time.monotonic() - start < 60
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert "forever did not finish within 0.5 s" in lines[0]
    assert not (tmp_path / "x.mp4").exists()


def test_hunt_stops_it_and_reports_the_polygon(looping):
    """In a hunt, running out of time on a searched polygon is a finding (issue 24 item 7):
    exit 1 and the polygon, shrunk while it runs out of time (at most
    story.hunt.MAX_SHRINK_TIMEOUTS more times, then it says it stopped)."""
    start = time.monotonic()
    result = trex("hunt", looping, "--budget", "10", "--call-timeout", "0.5")
    assert time.monotonic() - start < 60
    assert result.returncode == 1, result.stderr
    first, *rest = result.stdout.splitlines()
    assert first.startswith(f"{looping} fails on this 4-vertex polygon: forever did not "
                            "finish within 0.5 s")
    assert rest[-1].startswith("(found among 1 polygon, on one of 4 vertices, shrunk in ")
    assert "(stopped: more than 8 of them ran out of time)" in rest[-1]
    assert result.stderr == ""


def _in_process(*args):
    from click.testing import CliRunner

    from trex.cli import main

    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


@pytest.mark.parametrize("command", [
    ["log", "divide-and-conquer", "counterexample", "--heuristic", "{spec}", "-o", "{out}"],
    ["snapshot", "{spec}", "-o", "{out}"],
    ["player", "{spec}", "-o", "{dir}"],
    ["slides", "{spec}", "-o", "{dir}"],
])
def test_every_command_running_ones_own_takes_call_timeout(looping, tmp_path, command):
    """Issue 24 item 10: the message says --call-timeout sets the limit; every command that
    runs a function of one's own takes it (log, snapshot, player and slides had none)."""
    out, folder = tmp_path / "out.json", tmp_path / "dir"
    args = [a.format(spec=looping, out=out, dir=folder) for a in command]
    start = time.monotonic()
    code, stdout, err = _in_process(*args, "--call-timeout", "0.3")
    assert time.monotonic() - start < 60
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "forever did not finish within 0.3 s" in lines[0], err
    assert stdout == "" and not out.exists() and not folder.exists()


def test_a_lectures_chapters_get_its_call_timeout(looping, tmp_path):
    """`trex lecture --call-timeout` reaches the chapter's own process (trex chapter --call-timeout)."""
    scene = tmp_path / "looping_scene.py"
    scene.write_text(textwrap.dedent(f"""
        from metaphors.scene import scene_for_heuristic

        class Looping(scene_for_heuristic({looping!r})):
            pass
    """))
    start = time.monotonic()
    result = trex("lecture", "--chapters", str(scene), "-o", str(tmp_path / "lecture"),
                  "--call-timeout", "0.3")
    assert time.monotonic() - start < 100
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "forever did not finish within 0.3 s" in lines[0], result.stderr
    assert result.returncode == 2  # a function of one's own that failed in the chapter
    assert not (tmp_path / "lecture").exists()


def test_a_commands_limit_ends_with_the_command():
    """Invoked in process (as tests and the studio do), a command's --call-timeout must not
    stay the limit for what runs after it."""
    before = call_timeout()
    code, _, err = _in_process("diagonal", "lecture", "--heuristic", "gravity",
                               "--call-timeout", "0.3")
    assert code == 0, err
    assert call_timeout() == before
