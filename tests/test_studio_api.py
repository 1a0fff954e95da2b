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
    ("/api/check", b'{"polygon": [[0, 0], [1' + b"0" * 400 + b', 0], [0, 1]]}', 400),
    ("/api/check", b'[[0, 0], [1, 0], [0, 1]]', 400),
    ("/api/check", b'{"polygon": [[0, 0], [1, 0], [0, 1]], "holes": 5}', 400),
    ("/api/load", b'{"sample": "random-star:1000000"}', 413),
    ("/api/triangulate", b'{"polygon": [[0, 0], [4, 0], [4, 4]], "algorithm": ["x"]}', 400),
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


def test_labels_and_frame_index_the_requests_own_points_when_cleaning_drops_some(client):
    # a repeated point (index 1) and a closing point (index 5): cleaning drops both
    ring = [[1, 4.5], [1, 4.5], [9, 2], [3, 6.5], [4.6, 4.1], [1.6, 8], [1, 4.5]]
    ok = client.post("/api/check", json={"polygon": ring}).json()
    assert ok["labels"] == ["B", None, "C", "D", "E", "A", None]
    assert ok["triangle"] == [5, 0, 2] and ok["candidates"] == [3, 4]
    assert ok["reflex"] == [4]
    claim = client.post("/api/diagonal", json={"polygon": ring, "heuristic": "scaling"}).json()
    assert claim["diagonal"] == [0, 3] and claim["inner"] is False  # BD, input points 0 and 3


def test_an_invalid_polygon_names_its_offending_edges(client):
    bow = client.post("/api/check", json={"polygon": [[0, 0], [4, 4], [4, 0], [0, 4]]}).json()
    assert bow["edges"] == [[0, 1], [2, 3]]
    spike = [[0, 0], [4, 0], [4, 4], [4, 2]]  # a zero-width spike: edges 1–2 and 2–3 fold back
    fold = client.post("/api/check", json={"polygon": spike}).json()
    assert fold["valid"] is False and [1, 2] in fold["edges"] and [2, 3] in fold["edges"]
    holes = {"polygon": SQUARE, "holes": [[[1, 1], [2, 1], [1, 2]], [[1, 1], [2, 1], [1, 2]]]}
    twice = client.post("/api/check", json=holes).json()
    assert twice["valid"] is False and len(twice["edges"]) == 6


def test_claims_of_every_rule_and_the_triangulation_in_input_order(client):
    rows = client.post("/api/claims", json={"polygon": COUNTER}).json()
    verdict = {r["name"]: r["inner"] for r in rows}
    assert verdict["scaling"] is False and verdict["gravity"] is True
    scaling = next(r for r in rows if r["name"] == "scaling")
    assert scaling["why"].startswith("B–D crosses edge E–A") and scaling["crossed"] == [3, 4]
    ring = [*SQUARE, SQUARE[0]]
    t = client.post("/api/triangulate", json={"polygon": ring, "algorithm": "ear-clipping"}).json()
    assert t["vertices"] == ring and all(4 not in tri for tri in t["triangles"])


def test_load_a_sample_or_a_files_text(client):
    keyhole = client.post("/api/load", json={"sample": "keyhole"}).json()
    assert len(keyhole["holes"]) == 2
    wkt = client.post("/api/load", json={"file": {"name": "t.wkt",
                                                  "text": "POLYGON ((0 0, 3 0, 0 3, 0 0))"}})
    assert wkt.json() == {"polygon": [[0, 0], [3, 0], [0, 3], [0, 0]], "holes": []}
    for body in ({"sample": "/etc/passwd"}, {"file": {"name": "x.txt", "text": ""}}):
        r = client.post("/api/load", json=body)
        assert r.status_code == 400 and "\n" not in r.json()["error"]


def test_on_every_interface_any_ip_address_but_no_name_is_served():
    app = create_app(hosts={"0.0.0.0:8765"}, any_address_port=8765)
    client = TestClient(app, base_url="http://192.168.1.20:8765")
    assert client.post("/api/check", json={"polygon": SQUARE}).status_code == 200
    for host in ("evil.example:8765", "192.168.1.20:9999", "[::1]:8765x"):
        r = client.post("/api/check", json={"polygon": SQUARE}, headers={"host": host})
        assert r.status_code == 403, host
    ipv6 = client.post("/api/check", json={"polygon": SQUARE}, headers={"host": "[fe80::1]:8765"})
    assert ipv6.status_code == 200
