"""``trex studio`` as a process: it says where it listens, answers, and stops cleanly."""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def start_studio(tmp_path: Path, *args: str) -> tuple[subprocess.Popen, str]:
    """The studio on a free port, its temporary directories under ``tmp_path``; its URL."""
    env = {**os.environ, "TMPDIR": str(tmp_path), "PYTHONPATH": str(ROOT)}
    process = subprocess.Popen(
        [sys.executable, "-m", "trex", "studio", "--no-browser", "--port", "0", *args],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, cwd=ROOT)
    line = process.stdout.readline()
    assert line.startswith("studio: http://127.0.0.1:"), (line, process.stderr.read())
    return process, line.split(" ", 1)[1].strip()


def post(url: str, body: dict) -> dict:
    request = urllib.request.Request(url, data=json.dumps(body).encode(),
                                     headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(request, timeout=10) as answer:
        return json.loads(answer.read())


@pytest.mark.parametrize("signum, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_serves_then_stops_on_a_signal_and_removes_its_work_dir(tmp_path, signum, status):
    process, url = start_studio(tmp_path)
    try:
        answer = post(url + "api/check", {"polygon": [[0, 0], [4, 0], [4, 4], [0, 4]]})
        assert answer["valid"] is True and answer["labels"] == ["B", "C", "D", "A"]
        assert len(list(tmp_path.glob("trex-studio-*"))) == 1  # its work dir, meanwhile
        with urllib.request.urlopen(url, timeout=10) as page:
            assert b"<title>trex studio</title>" in page.read()
    finally:
        process.send_signal(signum)
        out, err = process.communicate(timeout=20)
    assert process.returncode == status, err
    assert err == "" and out == ""
    assert list(tmp_path.iterdir()) == []


def test_keep_keeps_the_work_dir(tmp_path):
    kept = tmp_path / "kept"
    process, _url = start_studio(tmp_path, "--keep", str(kept))
    process.send_signal(signal.SIGINT)
    process.communicate(timeout=20)
    assert kept.is_dir() and process.returncode == 130


def run_refused(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "trex", "studio", "--no-browser", *args],
                          capture_output=True, text=True, cwd=ROOT, timeout=60,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})


def test_a_port_in_use_is_one_line():
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen(1)
        port = taken.getsockname()[1]
        result = run_refused("--port", str(port))
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr == f"error: port {port} on 127.0.0.1 is in use (try --port)\n"


@pytest.mark.parametrize("args, message", [
    (["--heuristic", "scaling"], "error: --heuristic scaling: expected FILE.py:FUNCTION"),
    (["--heuristic", "no/such.py:f"], "error: --heuristic no/such.py:f: "),
    (["--polygon", "no-such-sample"], "error: no-such-sample: "),
])
def test_bad_arguments_are_one_line_before_serving(args, message):
    result = run_refused("--port", "0", *args)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.startswith(message) and result.stderr.count("\n") == 1


def get(url: str) -> dict:
    with urllib.request.urlopen(url, timeout=10) as answer:
        return json.loads(answer.read())


def test_stopping_ends_a_running_render_and_leaves_nothing(tmp_path):
    process, url = start_studio(tmp_path)
    try:
        polygon = [[1, 4.5], [9, 2], [3, 6.5], [4.6, 4.1], [1.6, 8]]
        job = post(url + "api/render", {"polygon": polygon, "scene": "scaling"})["job"]
        deadline = time.monotonic() + 120
        while get(f"{url}api/jobs/{job}")["state"] != "running":
            assert time.monotonic() < deadline
            time.sleep(0.2)
        child = next(tmp_path.glob("trex-studio-*/jobs/*"))
        assert (child / "polygon.json").is_file()
    finally:
        process.send_signal(signal.SIGTERM)
        process.communicate(timeout=30)
    assert process.returncode == 143
    assert list(tmp_path.iterdir()) == []
    left = subprocess.run(["pgrep", "-f", f"studio-video.*{tmp_path}"], capture_output=True)
    assert left.stdout == b""  # the render's process ended with the studio


@pytest.mark.parametrize("flags", [[], ["--no-browser"]])
def test_opens_the_page_in_the_browser_unless_told_not_to(tmp_path, flags):
    opened = tmp_path / "opened.txt"
    browser = tmp_path / "browser"  # $BROWSER, which webbrowser runs with the URL
    browser.write_text(f"#!/bin/sh\necho \"$1\" > {opened}\n")
    browser.chmod(0o755)
    env = {**os.environ, "PYTHONPATH": str(ROOT), "BROWSER": str(browser),
           "TMPDIR": str(tmp_path)}
    process = subprocess.Popen([sys.executable, "-m", "trex", "studio", "--port", "0", *flags],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=env, cwd=ROOT)
    try:
        url = process.stdout.readline().split(" ", 1)[1].strip()
        if flags:
            post(url + "api/check", {"polygon": [[0, 0], [4, 0], [0, 4]]})
            time.sleep(1)
            assert not opened.exists()
            return
        deadline = time.monotonic() + 30
        while not opened.exists() or not opened.read_text():
            assert time.monotonic() < deadline, "the browser was not opened"
            time.sleep(0.1)
        assert opened.read_text().strip() == url
    finally:
        process.send_signal(signal.SIGINT)
        process.communicate(timeout=30)


def test_the_polygon_and_ones_own_heuristic_given_on_the_command_line(tmp_path):
    mine = f"{ROOT / 'examples' / 'my_heuristic.py'}:biggest_angle"
    process, url = start_studio(tmp_path, "--polygon", "counterexample", "--heuristic", mine)
    try:
        setup = get(url + "api/setup")
        assert setup["initial"] == {"polygon": [[0.4, 2.5], [7, 1], [4, 3.5], [4.4, 2.2], [0.8, 7]],
                                    "holes": []}
        assert get(url + "api/rules")[-1]["name"] == mine
        rows = post(url + "api/claims", setup["initial"])
        assert rows[-1]["name"] == mine and rows[-1]["labels"] == ["B", "E"]
        assert rows[-1]["inner"] is True
    finally:
        process.send_signal(signal.SIGINT)
        process.communicate(timeout=30)
