"""Fault injection between a servo backend and the host firmware.

:class:`PtyRelay` sits between the backend (on the relay's own pseudo-terminal) and the
firmware's pty; :class:`HttpRelay` between the backend and the firmware's HTTP URL. Both
pass lines through unchanged until told to inject a fault, and log every command and
reply with a monotonic timestamp, so that a test can measure when the fault began, when
the backend reacted (its STOP) and what it sent in between.

Faults (``arm(kind, ...)``):
    stall:    the firmware hangs: nothing more passes either way.
    drop:     the next reply is lost.
    delay:    every reply from now on arrives ``seconds`` late.
    corrupt:  one digit of the next reply (before its checksum) is changed.
    garbage:  the next reply is replaced by bytes that are no reply at all.
    corrupt_command: one digit of the next command is changed on its way to the firmware.
"""

from __future__ import annotations

import heapq
import http.server
import json
import os
import select
import threading
import time
import tty
import urllib.request
from dataclasses import dataclass, field

__all__ = ["HttpRelay", "LoggedLine", "PtyRelay"]

_KINDS = ("stall", "drop", "delay", "corrupt", "garbage", "corrupt_command")
GARBAGE = b"\x00\xff\xfe#!garbage 12,,\x07"


@dataclass(frozen=True)
class LoggedLine:
    """A line the relay saw: ``t`` (time.monotonic), ``way`` ("cmd" or "reply")."""

    t: float
    way: str
    line: str


def corrupt_digit(line: str) -> str:
    """``line`` with its first digit before the checksum changed (5 <-> 6 and so on)."""
    end = line.rfind("*") if "*" in line else len(line)
    for i, c in enumerate(line[:end]):
        if c.isdigit():
            return line[:i] + str((int(c) + 5) % 10) + line[i + 1:]
    return line


@dataclass
class _Faults:
    """The armed fault and the log, shared by both relays (thread-safe)."""

    kind: str | None = None
    seconds: float = 0.0
    fault_at: float | None = None  # when the fault first changed what passed
    log: list[LoggedLine] = field(default_factory=list)
    lock: threading.Lock = field(default_factory=threading.Lock)

    def arm(self, kind: str, seconds: float = 0.0) -> None:
        if kind not in _KINDS:
            raise ValueError(f"'kind' must be one of {_KINDS} (got {kind!r})")
        with self.lock:
            self.kind, self.seconds = kind, seconds
            if kind in ("stall", "delay"):
                self.fault_at = time.monotonic()

    def record(self, way: str, line: str) -> None:
        with self.lock:
            self.log.append(LoggedLine(time.monotonic(), way, line))

    def on_reply(self, line: str) -> tuple[str | None, float]:
        """What to forward for a reply (None: nothing) and how late (s)."""
        with self.lock:
            kind = self.kind
            if kind is None:
                return line, 0.0
            if kind == "stall":
                return None, 0.0
            if kind == "delay":
                return line, self.seconds
            if kind == "corrupt_command" or (kind == "corrupt" and corrupt_digit(line) == line):
                return line, 0.0  # armed for a command, or for a reply with a digit
            self.kind = None  # one-shot faults
            self.fault_at = time.monotonic()
            if kind == "drop":
                return None, 0.0
            if kind == "corrupt":
                return corrupt_digit(line), 0.0
            return GARBAGE.decode("latin-1"), 0.0

    def on_command(self, line: str) -> str | None:
        """What to forward for a command (None: nothing)."""
        with self.lock:
            if self.kind == "stall":
                return None
            if self.kind == "corrupt_command" and corrupt_digit(line) != line:
                self.kind = None
                self.fault_at = time.monotonic()
                return corrupt_digit(line)
            return line

    def commands_after_fault(self) -> list[LoggedLine]:
        """Commands the backend sent once the fault had begun, in order."""
        with self.lock:
            assert self.fault_at is not None, "no fault happened"
            return [e for e in self.log if e.way == "cmd" and e.t >= self.fault_at]


class PtyRelay:
    """A pty for the backend, relayed line by line to the firmware's pty ``upstream``.

    Attributes:
        path: the pty the backend opens as its serial port.
    """

    def __init__(self, upstream: str) -> None:
        self.faults = _Faults()
        self._master, self._slave = os.openpty()
        tty.setraw(self._slave)  # keep our end open: no EIO when the backend closes
        self.path = os.ttyname(self._slave)
        self._up = os.open(upstream, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        tty.setraw(self._up)
        self._wake_r, self._wake_w = os.pipe()
        self._stopped = False
        self._thread = threading.Thread(target=self._run, name="PtyRelay", daemon=True)
        self._thread.start()

    def arm(self, kind: str, seconds: float = 0.0) -> None:
        """Inject ``kind`` (see the module) from now on."""
        self.faults.arm(kind, seconds)

    def _run(self) -> None:
        from_host, from_fw = b"", b""
        pending: list[tuple[float, int, bytes]] = []  # (due, order, bytes) for the backend
        order = 0
        while not self._stopped:
            timeout = max(0.0, pending[0][0] - time.monotonic()) if pending else 0.05
            ready, _, _ = select.select([self._master, self._up, self._wake_r], [], [], timeout)
            while pending and pending[0][0] <= time.monotonic():
                os.write(self._master, heapq.heappop(pending)[2])
            if self._master in ready:
                try:
                    from_host += os.read(self._master, 4096)
                except OSError:
                    from_host = b""
                while b"\n" in from_host:
                    raw, from_host = from_host.split(b"\n", 1)
                    line = raw.decode("latin-1")
                    self.faults.record("cmd", line)
                    forward = self.faults.on_command(line)
                    if forward is not None:
                        os.write(self._up, forward.encode("latin-1") + b"\n")
            if self._up in ready:
                try:
                    from_fw += os.read(self._up, 4096)
                except BlockingIOError:
                    pass
                while b"\n" in from_fw:
                    raw, from_fw = from_fw.split(b"\n", 1)
                    line = raw.decode("latin-1")
                    self.faults.record("reply", line)
                    if line.startswith("#"):
                        os.write(self._master, raw + b"\n")
                        continue
                    out, late = self.faults.on_reply(line)
                    if out is not None:
                        order += 1
                        heapq.heappush(pending, (time.monotonic() + late, order,
                                                 out.encode("latin-1") + b"\n"))

    def close(self) -> None:
        """Stop relaying and close every descriptor (idempotent)."""
        if self._stopped:
            return
        self._stopped = True
        os.write(self._wake_w, b"x")
        self._thread.join(2.0)
        for fd in (self._master, self._slave, self._up, self._wake_r, self._wake_w):
            try:
                os.close(fd)
            except OSError:
                pass


class HttpRelay:
    """An HTTP server on 127.0.0.1 forwarding ``POST /api/command`` to ``upstream``.

    Attributes:
        url: the command URL the backend posts to.
    """

    def __init__(self, upstream: str) -> None:
        self.faults = _Faults()
        self._release = threading.Event()
        faults, release = self.faults, self._release
        opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))

        class Handler(http.server.BaseHTTPRequestHandler):
            protocol_version = "HTTP/1.1"  # keep-alive, as httpx expects
            disable_nagle_algorithm = True  # headers and body leave at once, no 40 ms ACK wait

            def log_message(self, *args: object) -> None:
                pass

            def do_POST(self) -> None:
                body = self.rfile.read(int(self.headers.get("Content-Length", 0)))
                try:
                    cmd = json.loads(body)["cmd"]
                except (ValueError, KeyError, TypeError):
                    cmd = body.decode("latin-1")
                faults.record("cmd", cmd)
                forward = faults.on_command(cmd)
                if forward is None:
                    release.wait(30.0)
                    self.close_connection = True
                    return
                body = json.dumps({"cmd": forward}).encode()
                request = urllib.request.Request(upstream, data=body,
                                                 headers={"Content-Type": "application/json"})
                with opener.open(request, timeout=5.0) as response:
                    answer = json.loads(response.read())
                reply = answer.get("reply", "")
                faults.record("reply", reply)
                out, late = faults.on_reply(reply)
                if out is None:  # a stall or a lost answer: hold the request
                    release.wait(30.0)
                    self.close_connection = True
                    return
                if late:
                    time.sleep(late)
                data = (GARBAGE if out == GARBAGE.decode("latin-1")
                        else json.dumps({"reply": out}).encode())
                try:
                    self.send_response(200)
                    self.send_header("Content-Type", "application/json")
                    self.send_header("Content-Length", str(len(data)))
                    self.end_headers()
                    self.wfile.write(data)
                except OSError:  # the backend gave up on this request
                    self.close_connection = True

        self._server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self._server.daemon_threads = True
        self.url = f"http://127.0.0.1:{self._server.server_address[1]}/api/command"
        self._thread = threading.Thread(target=self._server.serve_forever, name="HttpRelay",
                                        daemon=True)
        self._thread.start()

    def arm(self, kind: str, seconds: float = 0.0) -> None:
        """Inject ``kind`` (see the module) from now on."""
        self.faults.arm(kind, seconds)

    def close(self) -> None:
        """Release held requests and stop the server."""
        self._release.set()
        self._server.shutdown()
        self._server.server_close()
        self._thread.join(2.0)
