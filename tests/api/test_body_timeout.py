"""A request body must arrive within ``body_timeout_s`` of its headers (raw sockets against
a real server): a trickling client is answered 408 and closed, a normal one is not, and a
crowd of trickling clients does not delay a cancel."""

from __future__ import annotations

import socket
import time
from pathlib import Path

import pytest
from apitest import TOKEN, make_settings, served
from test_control_under_load import _request
from test_runs import GO_CANDLE

from taskrunner.api import Settings, create_app
from taskrunner.api.serving import header_timeout_protocol

LIMIT_S = 0.5  # the body timeout of these servers (s)
BODY = b'{"task": "pick_place"}'


def _head(path: str, length: int | None, token: bool = True) -> bytes:
    lines = [f"POST {path} HTTP/1.1", "Host: test", "Content-Type: application/json"]
    if token:
        lines.append(f"Authorization: Bearer {TOKEN}")
    lines.append(f"Content-Length: {length}" if length is not None
                 else "Transfer-Encoding: chunked")
    return ("\r\n".join(lines) + "\r\n\r\n").encode()


def _trickle(port: int, head: bytes, piece: bytes, every_s: float,
             most: int = 50) -> tuple[bytes, int]:
    """Send ``head``, then ``piece`` every ``every_s`` until the server answers and closes
    (at most ``most`` pieces); returns what the server sent and how many pieces went."""
    with socket.create_connection(("127.0.0.1", port), timeout=10) as sock:
        sock.sendall(head)
        answer = b""
        sent = 0
        while sent < most:
            try:
                sock.sendall(piece)
            except OSError:  # closed under us (a reset): what it said is read below
                break
            sent += 1
            sock.settimeout(every_s)
            try:
                data = sock.recv(65536)
            except TimeoutError:
                continue
            except OSError:
                break
            answer += data
            if not data:
                break
        sock.settimeout(10)
        try:
            while data := sock.recv(65536):
                answer += data
        except OSError:
            pass
        return answer, sent


def _read_answer(sock: socket.socket) -> bytes:
    """One whole answer (with a Content-Length) from ``sock``."""
    answer = b""
    while b"\r\n\r\n" not in answer:
        data = sock.recv(65536)
        assert data, answer
        answer += data
    head, _, body = answer.partition(b"\r\n\r\n")
    length = next(int(line.split(b":")[1]) for line in head.split(b"\r\n")
                  if line.lower().startswith(b"content-length:"))
    while len(body) < length:
        data = sock.recv(65536)
        assert data, answer
        body += data
    return head + b"\r\n\r\n" + body


def _app(tmp_path: Path, **overrides: object) -> object:
    return create_app(make_settings(tmp_path / "state", **overrides))


def test_a_body_trickled_a_byte_at_a_time_is_answered_408_and_closed(tmp_path: Path):
    with served(_app(tmp_path), http=header_timeout_protocol(10.0, LIMIT_S)) as port:
        answer, sent = _trickle(port, _head("/tasks/check", 1000), b" ", every_s=0.2)
    assert answer.startswith(b"HTTP/1.1 408 "), answer
    assert b"connection: close" in answer.lower() and b"request body not received" in answer
    # 1000 bytes at 5 a second would take 200 s: it was cut off near the limit.
    assert sent < 1000 and sent * 0.2 < 20 * LIMIT_S, sent


def test_a_chunked_body_that_never_ends_is_answered_408(tmp_path: Path):
    with served(_app(tmp_path), http=header_timeout_protocol(10.0, LIMIT_S)) as port:
        answer, sent = _trickle(port, _head("/tasks/check", None), b"1\r\n \r\n", every_s=0.2)
    assert answer.startswith(b"HTTP/1.1 408 "), answer
    assert sent * 0.2 < 20 * LIMIT_S, sent


def test_a_refused_request_whose_body_trickles_on_is_closed_without_a_second_answer(
        tmp_path: Path):
    """Without the token the answer is 401 before the body; the connection the client
    goes on trickling into is closed at the limit all the same."""
    with served(_app(tmp_path), http=header_timeout_protocol(10.0, LIMIT_S)) as port:
        answer, sent = _trickle(port, _head("/tasks/check", 1000, token=False), b" ",
                                every_s=0.2)
    assert answer.startswith(b"HTTP/1.1 401 "), answer
    assert b"408" not in answer
    assert sent * 0.2 < 20 * LIMIT_S, sent


def test_a_client_sending_its_body_at_once_is_unaffected_and_kept_alive(tmp_path: Path):
    with served(_app(tmp_path), http=header_timeout_protocol(10.0, LIMIT_S)) as port, \
            socket.create_connection(("127.0.0.1", port), timeout=30) as sock:
        answers = []
        for _ in range(2):
            sock.sendall(_head("/tasks/check", len(BODY)) + BODY)
            answers.append(_read_answer(sock))
            time.sleep(3 * LIMIT_S)  # idle past the body limit: its timer was disarmed
    assert all(a.startswith(b"HTTP/1.1 200 ") for a in answers), answers


def test_fifty_trickling_clients_do_not_delay_a_cancel(tmp_path: Path):
    import threading

    limit_s = 3.0  # long enough to see the cancel answered while all are still held
    # All fifty admitted (max_requests above them), so each is held until its body times
    # out; past max_requests they would be answered 503 at once.
    app = _app(tmp_path, sim_speed=0.5, max_requests=64)
    with served(app, http=header_timeout_protocol(10.0, limit_s)) as port:
        status, _, started, _ = _request(port, "POST", "/runs",
                                         {"yaml": GO_CANDLE, "backend": "sim", "check": False})
        assert status == 202, started
        run_id = started["run_id"]
        deadline = time.monotonic() + 30
        while not any(e["kind"] == "planned"
                      for e in _request(port, "GET", f"/runs/{run_id}")[2]["events"]):
            assert time.monotonic() < deadline
            time.sleep(0.05)
        closed_at: list[float] = []
        answers: list[bytes] = []

        def trickler() -> None:
            answer, _ = _trickle(port, _head("/runs", 1000), b" ", every_s=0.5)
            closed_at.append(time.monotonic())
            answers.append(answer)

        clients = [threading.Thread(target=trickler) for _ in range(50)]
        for client in clients:
            client.start()
        time.sleep(0.3)  # all 50 connected and trickling
        status, _, cancelled, _ = _request(port, "POST", f"/runs/{run_id}/cancel")
        cancel_answered = time.monotonic()
        for client in clients:
            client.join(60)
        deadline = time.monotonic() + 20
        while (state := _request(port, "GET", f"/runs/{run_id}")[2])["status"] == "running":
            assert time.monotonic() < deadline
            time.sleep(0.05)
    assert status == 202, cancelled
    assert len(closed_at) == 50 and cancel_answered < min(closed_at), \
        "the cancel waited for the trickling clients"
    assert all(a.startswith(b"HTTP/1.1 408 ") for a in answers), answers[:3]
    assert state["status"] == "cancelled"


def test_the_body_timeout_is_a_positive_number_of_seconds():
    assert Settings(token=TOKEN).body_timeout_s == 20.0
    with pytest.raises(ValueError, match="'body_timeout_s' must be a positive number"):
        Settings.from_env({"TASKRUNNER_BODY_TIMEOUT_S": "0"})
    with pytest.raises(ValueError, match="'body_timeout_s'"):
        header_timeout_protocol(10.0, float("nan"))
