"""The studio's jobs through the test client: hunts and renders in processes of their own,
their bad requests, cancelling, and one's own heuristic failing its job, not the server."""

from __future__ import annotations

import textwrap
import time

import pytest
from starlette.testclient import TestClient

from trex.studio.app import create_app
from usercode.heuristic import load_user_heuristic

HOST = "127.0.0.1:8765"
COUNTER = [[1, 4.5], [9, 2], [3, 6.5], [4.6, 4.1], [1.6, 8]]
SQUARE = [[0, 0], [4, 0], [4, 4], [0, 4]]


def own_heuristics(tmp_path) -> dict:
    source = tmp_path / "mine.py"
    source.write_text(textwrap.dedent("""
        def forever(polygon):
            while True:
                pass

        def broken(polygon):
            raise RuntimeError("oops")
    """))
    return {f"{source}:{name}": load_user_heuristic(f"{source}:{name}")
            for name in ("forever", "broken")}


@pytest.fixture
def client(tmp_path):
    app = create_app(hosts={HOST}, own=own_heuristics(tmp_path), work=tmp_path / "work",
                     call_timeout=1)
    with TestClient(app, base_url=f"http://{HOST}") as client:
        yield client


def wait(client, job: str, seconds: float = 240) -> dict:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        status = client.get(f"/api/jobs/{job}").json()
        if status["state"] not in ("queued", "running"):
            return status
        time.sleep(0.3)
    raise AssertionError(f"job {job} still {status}")


def test_a_hunt_finds_rotations_counterexample(client):
    job = client.post("/api/hunt", json={"heuristic": "rotation", "budget": 300}).json()["job"]
    status = wait(client, job)
    assert status["state"] == "done" and status["progress"] == 1 and status["error"] is None
    assert status["result"]["found"] is True and len(status["result"]["polygon"]) >= 4
    assert status["result"]["why"].startswith("crosses edge")


@pytest.mark.parametrize("name, message", [
    ("forever", "did not finish within 1 s"),
    ("broken", "oops"),
])
def test_ones_own_heuristic_fails_its_job_not_the_server(client, tmp_path, name, message):
    spec = f"{tmp_path / 'mine.py'}:{name}"
    job = client.post("/api/hunt", json={"heuristic": spec, "budget": 50}).json()["job"]
    status = wait(client, job, 120)
    assert status["state"] == "failed" and message in status["error"]
    assert "\n" not in status["error"]
    assert client.post("/api/check", json={"polygon": SQUARE}).json()["valid"] is True


@pytest.mark.parametrize("route, body, status", [
    ("/api/hunt", {"heuristic": "nope"}, 400),
    ("/api/hunt", {"heuristic": "rotation", "budget": 0}, 400),
    ("/api/hunt", {"heuristic": "print('hi')"}, 400),
    ("/api/render", {"polygon": SQUARE, "scene": "nope"}, 400),
    ("/api/render", {"polygon": SQUARE, "scene": "scaling", "kind": "gif"}, 400),
    ("/api/render", {"polygon": [[0, 0], [4, 4], [4, 0], [0, 4]], "scene": "scaling"}, 422),
    ("/api/render", {"polygon": SQUARE, "holes": [[[1, 1], [2, 1], [1, 2]]],
                     "scene": "scaling"}, 422),
])
def test_bad_job_requests_are_refused_before_any_process(client, route, body, status):
    answer = client.post(route, json=body)
    assert answer.status_code == status and "\n" not in answer.json()["error"]


def test_no_such_job_is_404(client):
    assert client.get("/api/jobs/nope").status_code == 404
    assert client.delete("/api/jobs/nope").status_code == 404


def test_renders_queue_one_at_a_time_and_cancel_leaves_nothing(client, tmp_path):
    body = {"polygon": COUNTER, "scene": "scaling"}
    first = client.post("/api/render", json=body).json()["job"]
    second = client.post("/api/render", json=body).json()["job"]
    assert client.get(f"/api/jobs/{second}").json()["state"] == "queued"
    deadline = time.monotonic() + 120
    while client.get(f"/api/jobs/{first}").json()["state"] != "running":
        assert time.monotonic() < deadline
        time.sleep(0.1)
    assert client.get(f"/api/jobs/{second}").json()["state"] == "queued"
    assert client.post("/api/check", json={"polygon": COUNTER}).json()["valid"] is True
    assert client.delete(f"/api/jobs/{second}").json()["state"] == "cancelled"
    assert client.delete(f"/api/jobs/{first}").json()["state"] == "cancelled"
    assert sorted((tmp_path / "work" / "jobs").iterdir()) == []


def test_ones_own_heuristic_answers_live_from_a_worker_and_cannot_stop_the_server(tmp_path):
    source = tmp_path / "live.py"
    source.write_text(textwrap.dedent("""
        import os

        def chatty(polygon):
            print("hello from the user's code")
            return "B", "D"

        def forever(polygon):
            while True:
                pass

        def leaves(polygon):
            raise SystemExit(3)

        def dies(polygon):
            os._exit(7)
    """))
    own = {f"{source}:{n}": load_user_heuristic(f"{source}:{n}")
           for n in ("chatty", "forever", "leaves", "dies")}
    with TestClient(create_app(hosts={HOST}, own=own, work=tmp_path / "w", call_timeout=1),
                    base_url=f"http://{HOST}") as client:
        rows = {r["name"].rsplit(":", 1)[-1]: r
                for r in client.post("/api/claims", json={"polygon": COUNTER}).json()}
        assert rows["chatty"]["labels"] == ["B", "D"] and rows["chatty"]["inner"] is False
        assert "did not finish within 1 s" in rows["forever"]["error"]
        assert "sys.exit" in rows["leaves"]["error"]
        assert "ended" in rows["dies"]["error"] and rows["scaling"]["inner"] is False
        diagonal = client.post("/api/diagonal", json={"polygon": COUNTER,
                                                      "heuristic": f"{source}:chatty"})
        assert diagonal.status_code == 200 and diagonal.json()["diagonal"] == [0, 2]
        dead = client.post("/api/diagonal", json={"polygon": COUNTER, "heuristic": f"{source}:dies"})
        assert dead.status_code == 422 and "\n" not in dead.json()["error"]
        assert client.post("/api/check", json={"polygon": SQUARE}).json()["valid"] is True
