"""Requests without the token are refused before their body is read or parsed."""

from __future__ import annotations

from pathlib import Path

from apitest import AUTH, make_settings
from fastapi.testclient import TestClient

from taskrunner.api import create_app


def _client(tmp_path: Path, **settings: object) -> TestClient:
    return TestClient(create_app(make_settings(tmp_path / "state", **settings)))


def test_a_write_without_the_token_is_401_whatever_its_body(tmp_path: Path):
    with _client(tmp_path, max_body_bytes=1000) as client:
        for body in (b"{not json", b'{"task": 5, "extra": []}', b"x" * 5000):
            answer = client.post("/runs", content=body,
                                 headers={"Content-Type": "application/json"})
            # Not 400/413/422 first: nothing of the body was looked at.
            assert answer.status_code == 401, (body[:20], answer.text)
            assert answer.headers["www-authenticate"] == "Bearer"
            assert "bearer token is required" in answer.json()["detail"]
        wrong = client.post("/runs/abc/cancel", headers={"Authorization": "Bearer nope-nope"})
        assert wrong.status_code == 401 and wrong.json()["detail"] == "invalid bearer token"
        # With the token the body is read and judged as before.
        judged = client.post("/runs", content=b"{not json",
                             headers={**AUTH, "Content-Type": "application/json"})
        assert judged.status_code == 422


def test_open_reads_let_reads_through_the_gate_and_not_writes(tmp_path: Path):
    with _client(tmp_path, open_reads=True) as client:
        check = client.post("/tasks/check", json={"task": "pick_place"})
        assert check.status_code == 200 and check.json()["ok"] is True
        assert client.get("/cells").status_code == 200
        assert client.post("/runs", json={"task": "pick_place"}).status_code == 401
        assert client.put("/cells/servo_arm_table/poses/x",
                          json={"group": "arm"}).status_code == 401


def test_public_pages_and_unknown_paths_pass_the_gate(tmp_path: Path):
    with _client(tmp_path) as client:
        assert client.get("/health").status_code == 200
        assert client.get("/openapi.json").status_code == 200
        assert client.get("/no/such/path").status_code == 404
        assert client.get("/cells").status_code == 401
