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
from geometry.user_heuristics import (
    UserHeuristicError,
    call_timeout,
    load_user_heuristic,
    set_call_timeout,
)

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
    ["hunt", "{spec}", "--budget", "10"],
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
