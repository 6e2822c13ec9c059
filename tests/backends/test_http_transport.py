"""HttpTransport against a small local HTTP server: keep-alive, errors, retries."""

from __future__ import annotations

import json
import socket
import threading
from collections.abc import Callable, Iterator
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import pytest

from taskrunner.backends.http import HttpTransport
from taskrunner.errors import BackendError

Answer = Callable[[str], tuple[int, bytes]]


class _Board(ThreadingHTTPServer):
    daemon_threads = True

    def __init__(self, answer: Answer) -> None:
        self.answer = answer
        self.commands: list[str] = []
        self.connections = 0
        super().__init__(("127.0.0.1", 0), _Handler)


class _Handler(BaseHTTPRequestHandler):
    protocol_version = "HTTP/1.1"  # keep-alive, as the firmware's web server does
    server: _Board

    def setup(self) -> None:
        super().setup()
        self.server.connections += 1

    def do_POST(self) -> None:  # the name http.server calls
        length = int(self.headers.get("Content-Length", "0"))
        command = json.loads(self.rfile.read(length))["cmd"]
        self.server.commands.append(command)
        status, body = self.server.answer(command)
        self.send_response(status)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, format: str, *args: object) -> None:
        pass


@pytest.fixture
def board() -> Iterator[Callable[[Answer], tuple[_Board, str]]]:
    servers: list[_Board] = []

    def start(answer: Answer) -> tuple[_Board, str]:
        server = _Board(answer)
        threading.Thread(target=server.serve_forever, daemon=True).start()
        servers.append(server)
        return server, f"http://127.0.0.1:{server.server_address[1]}/api/command"

    yield start
    for server in servers:
        server.shutdown()
        server.server_close()


def _ok(command: str) -> tuple[int, bytes]:
    return 200, json.dumps({"reply": f"ok {command}"}).encode()


def test_commands_share_one_kept_alive_connection(board) -> None:
    server, url = board(_ok)
    link = HttpTransport(url, reply_timeout=2.0)
    try:
        replies = [link.exchange(f"PING {i}") for i in range(20)]
    finally:
        link.close()
    assert replies == [f"ok PING {i}" for i in range(20)]
    assert server.connections == 1


def test_an_http_error_status_names_the_status_and_the_command(board) -> None:
    _, url = board(lambda command: (500, b'{"error": "boom"}'))
    link = HttpTransport(url)
    with pytest.raises(BackendError, match=r"answered HTTP 500 to 'MOVE:90,90'"):
        link.exchange("MOVE:90,90")
    link.close()


@pytest.mark.parametrize("body", [b"not json", b'{"answer": "ok"}', b'{"reply": 5}'])
def test_an_answer_without_a_reply_line_is_garbage(board, body: bytes) -> None:
    _, url = board(lambda command: (200, body))
    link = HttpTransport(url)
    with pytest.raises(BackendError, match="garbage answer"):
        link.exchange("STATUS")
    link.close()


def _closed_port_url() -> str:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    return f"http://127.0.0.1:{port}/api/command"


def test_only_idempotent_commands_are_retried_after_a_network_error() -> None:
    link = HttpTransport(_closed_port_url(), reply_timeout=0.5, retries=2)
    with pytest.raises(BackendError, match=r"to 'STATUS' \(3 attempt\(s\)\)"):
        link.exchange("STATUS")
    with pytest.raises(BackendError, match=r"to 'TRAJ:0,90,90' \(1 attempt\(s\)\)"):
        link.exchange("TRAJ:0,90,90")


def test_a_closed_link_refuses_commands(board) -> None:
    server, url = board(_ok)
    link = HttpTransport(url)
    link.close()
    link.close()
    with pytest.raises(BackendError, match="is closed"):
        link.exchange("PING")
    assert server.commands == []


def test_a_url_that_is_not_http_is_refused() -> None:
    with pytest.raises(BackendError, match=r"must be http\(s\)://"):
        HttpTransport("ftp://10.0.0.1/api/command")
