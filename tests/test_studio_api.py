"""The studio's JSON API through Starlette's test client: every route, bad input, the 403s."""

from __future__ import annotations

import pytest
from starlette.testclient import TestClient

from trex.studio.app import create_app

HOST = "127.0.0.1:8765"
SQUARE = [[0, 0], [4, 0], [4, 4], [0, 4]]
COUNTER = [[1, 4.5], [9, 2], [3, 6.5], [4.6, 4.1], [1.6, 8]]


@pytest.fixture
def client() -> TestClient:
    return TestClient(create_app(hosts={HOST}), base_url=f"http://{HOST}")


def test_check_valid_and_invalid(client):
    ok = client.post("/api/check", json={"polygon": COUNTER}).json()
    assert ok["valid"] is True and ok["why"] is None
    assert ok["labels"][ok["labels"].index("B")] == "B" and sorted(ok["labels"]) == list("ABCDE")
    bow = client.post("/api/check", json={"polygon": [[0, 0], [4, 4], [4, 0], [0, 4]]}).json()
    assert bow["valid"] is False and bow["why"]


def test_diagonal_and_triangulate(client):
    d = client.post("/api/diagonal", json={"polygon": SQUARE, "heuristic": "gravity"}).json()
    assert d["inner"] is True and len(d["diagonal"]) == 2
    t = client.post("/api/triangulate", json={"polygon": SQUARE, "algorithm": "ear-clipping"})
    assert t.status_code == 200 and len(t.json()["triangles"]) == 2 and t.json()["valid"]


@pytest.mark.parametrize("route, body, status", [
    ("/api/check", b"{nope", 400),
    ("/api/check", b'{"polygon": [[0, NaN], [1, 0], [0, 1]]}', 400),
    ("/api/diagonal", b'{"polygon": [[0, 0], [4, 0], [4, 4]], "heuristic": "nope"}', 400),
    ("/api/diagonal", b'{"polygon": [[0, 0], [4, 4], [4, 0], [0, 4]], "heuristic": "gravity"}', 422),
    ("/api/triangulate", b'{"polygon": [[0, 0], [1, 1], [2, 2]]}', 422),
])
def test_bad_input_is_one_line(client, route, body, status):
    r = client.post(route, content=body)
    assert r.status_code == status and "\n" not in r.json()["error"]


def test_too_many_vertices(client):
    big = [[i, (i * i) % 7] for i in range(5001)]
    r = client.post("/api/check", json={"polygon": big})
    assert r.status_code == 413 and "5000" in r.json()["error"]


def test_foreign_host_and_origin_are_403(client):
    r = client.post("/api/check", json={"polygon": SQUARE}, headers={"host": "evil.example"})
    assert r.status_code == 403
    r = client.post("/api/check", json={"polygon": SQUARE}, headers={"origin": "http://evil.example"})
    assert r.status_code == 403
    r = client.post("/api/check", json={"polygon": SQUARE}, headers={"origin": f"http://{HOST}"})
    assert r.status_code == 200
