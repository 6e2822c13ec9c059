"""The servo firmware (firmware/): core unit tests, and the host build over a pty and HTTP.

``make -C firmware test`` runs the C++ core's unit tests under ASan/UBSan; the host build
(``build/taskrunner-servo-host``) runs the same core with simulated servos behind a
pseudo-terminal and a 127.0.0.1 HTTP server, which these tests drive with plain
``os.read``/``os.write`` and ``urllib``. Skipped when ``make`` or ``g++`` is missing.
Every wait is bounded; the host runs its 80 ms tick faster than real time (``--speedup``).
Protocol: firmware/PROTOCOL.md.
"""

from __future__ import annotations

import csv
import json
import os
import re
import select
import shutil
import signal
import subprocess
import time
import urllib.error
import urllib.request
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest
import yaml

from taskrunner.backends.host_firmware import firmware_source_hash
from taskrunner.backends.servo_protocol import strip_checksum, with_checksum
from taskrunner.resources import DATA_ROOT, user_cache_dir

REPO_ROOT = Path(__file__).resolve().parents[2]
FIRMWARE = DATA_ROOT / "firmware"
# The same build folder as run-task firmware-sim (outside the package: nothing built lands
# in the source tree, so a wheel built afterwards holds no binaries).
BUILD_DIR = user_cache_dir() / f"firmware-{firmware_source_hash()}"
HOST_BIN = BUILD_DIR / "taskrunner-servo-host"
HARDWARE_YAML = DATA_ROOT / "robots" / "servo_arm" / "config" / "hardware.yaml"

TICK_MS = 80
SPEEDUP = 10.0  # one 80 ms tick every 8 ms of wall time
BUILD_TIMEOUT_S = 300  # a cold build compiles ~25 files (~25 s on 2 cores); then incremental
REPLY_TIMEOUT_S = 2.0
# No proxies: the host firmware listens on loopback only.
_URL_OPENER = urllib.request.build_opener(urllib.request.ProxyHandler({}))


def _require_toolchain() -> None:
    missing = [tool for tool in ("make", "g++") if shutil.which(tool) is None]
    if missing:
        pytest.skip(f"the firmware build needs {' and '.join(missing)}, not found on PATH")


def _make(target: str) -> subprocess.CompletedProcess[str]:
    jobs = str(max(1, min(os.cpu_count() or 1, 8)))
    try:
        return subprocess.run(
            ["make", "--no-print-directory", "-j", jobs, "-C", str(FIRMWARE), f"BUILD={BUILD_DIR}",
             target],
            check=False,  # the caller reports the output
            capture_output=True,
            text=True,
            timeout=BUILD_TIMEOUT_S,
        )
    except subprocess.TimeoutExpired as exc:
        pytest.fail(f"make {target} took more than {BUILD_TIMEOUT_S} s: {exc.stdout!r}")


def _read_stdout_lines(proc: subprocess.Popen[bytes], count: int, timeout: float) -> list[str]:
    """The first ``count`` lines the process prints, or a test failure after ``timeout`` s."""
    assert proc.stdout is not None
    fd = proc.stdout.fileno()
    data = b""
    deadline = time.monotonic() + timeout
    while data.count(b"\n") < count:
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            pytest.fail(f"host firmware printed {data!r} within {timeout} s, expected {count} lines")
        ready, _, _ = select.select([fd], [], [], remaining)
        if ready:
            chunk = os.read(fd, 4096)
            if not chunk:
                stderr = proc.stderr.read().decode() if proc.stderr else ""
                pytest.fail(f"host firmware exited early ({proc.wait(1)}): {stderr}")
            data += chunk
    return data.decode().splitlines()[:count]


@dataclass
class HostFirmware:
    """A running host firmware: its pty (opened raw, non-blocking), URL and tick log."""

    proc: subprocess.Popen[bytes]
    pty_path: str
    url: str
    log_path: Path
    link_path: Path
    fd: int = -1
    _pending: bytes = b""
    info_lines: list[str] = field(default_factory=list)

    def open_pty(self) -> None:
        self.fd = os.open(self.pty_path, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)

    def write(self, data: bytes) -> None:
        view = memoryview(data)
        deadline = time.monotonic() + REPLY_TIMEOUT_S
        while view:
            _, ready, _ = select.select([], [self.fd], [], max(0.0, deadline - time.monotonic()))
            if not ready:
                pytest.fail(f"pty not writable within {REPLY_TIMEOUT_S} s")
            view = view[os.write(self.fd, view) :]

    def read_line(self, timeout: float = REPLY_TIMEOUT_S) -> str:
        """The next line from the firmware (``#`` information lines included)."""
        deadline = time.monotonic() + timeout
        while b"\n" not in self._pending:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                pytest.fail(f"no line from the firmware within {timeout} s (got {self._pending!r})")
            ready, _, _ = select.select([self.fd], [], [], remaining)
            if ready:
                self._pending += os.read(self.fd, 4096)
        line, self._pending = self._pending.split(b"\n", 1)
        return line.decode("ascii")

    def read_reply(self) -> str:
        """The next reply line, skipping ``#`` information lines (kept in ``info_lines``)."""
        while True:
            line = self.read_line()
            if not line.startswith("#"):
                return line
            self.info_lines.append(line)

    def command(self, line: str) -> str:
        self.write(line.encode("ascii") + b"\n")
        return self.read_reply()

    def status(self) -> dict[str, Any]:
        reply = self.command("STATUS")
        assert reply.startswith("ok {"), reply
        return json.loads(reply[3:])

    def wait_status(self, predicate: Callable[[dict[str, Any]], bool], timeout: float = 3.0,
                    ) -> dict[str, Any]:
        """Polls STATUS until ``predicate`` holds; fails with the last status after ``timeout`` s."""
        deadline = time.monotonic() + timeout
        status = self.status()
        while not predicate(status):
            if time.monotonic() > deadline:
                pytest.fail(f"firmware did not reach the expected state in {timeout} s: {status}")
            time.sleep(0.005)
            status = self.status()
        return status

    def post(self, body: bytes, content_type: str | None = "application/json",
             method: str = "POST", url: str | None = None) -> tuple[int, dict[str, Any]]:
        """HTTP request to the firmware; returns (status code, decoded JSON answer)."""
        headers = {"Content-Type": content_type} if content_type else {}
        request = urllib.request.Request(url or self.url, data=body if method == "POST" else None,
                                         headers=headers, method=method)
        try:
            with _URL_OPENER.open(request, timeout=REPLY_TIMEOUT_S) as response:
                return response.status, json.loads(response.read())
        except urllib.error.HTTPError as error:
            with error:
                return error.code, json.loads(error.read())

    def http_command(self, cmd: str) -> str:
        code, answer = self.post(json.dumps({"cmd": cmd}).encode())
        assert code == 200, answer
        return answer["reply"]

    def terminate(self, timeout: float = 5.0) -> int:
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
        try:
            return self.proc.wait(timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait(timeout)
            pytest.fail(f"host firmware ignored SIGTERM for {timeout} s")

    def log_rows(self) -> list[list[float]]:
        with self.log_path.open(newline="") as stream:
            rows = list(csv.reader(stream))
        assert rows[0] == ["t_ms", "a1", "a2", "a3", "a4", "a5", "a6"]
        return [[float(value) for value in row] for row in rows[1:]]


@pytest.fixture(scope="module")
def host_binary() -> Path:
    _require_toolchain()
    result = _make("host")
    assert result.returncode == 0, result.stdout + result.stderr
    assert HOST_BIN.is_file()
    return HOST_BIN


def _start(binary: Path, tmp_path: Path, speedup: float,
           extra: tuple[str, ...] = ()) -> HostFirmware:
    log_path = tmp_path / "ticks.csv"
    link_path = tmp_path / "ttyServo"
    proc = subprocess.Popen(
        [str(binary), "--speedup", str(speedup), "--log", str(log_path), "--link", str(link_path),
         *extra],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    try:
        pty_path, url = _read_stdout_lines(proc, 2, timeout=5.0)
    except BaseException:
        proc.kill()
        proc.wait(5)
        raise
    firmware = HostFirmware(proc, pty_path, url, log_path, link_path)
    firmware.open_pty()
    return firmware


@pytest.fixture
def firmware(host_binary: Path, tmp_path: Path) -> Iterator[HostFirmware]:
    """A fresh host firmware at 10x speed; the pty is open and the boot banner read."""
    fw = _start(host_binary, tmp_path, SPEEDUP)
    try:
        yield fw
    finally:
        fw.terminate()
        os.close(fw.fd)


# --- build and unit tests --------------------------------------------------------------


def test_core_unit_tests_pass_under_sanitizers() -> None:
    _require_toolchain()
    result = _make("test")
    output = result.stdout + result.stderr
    assert result.returncode == 0, output
    last = result.stdout.strip().splitlines()[-1]  # the test runner's summary comes last
    match = re.fullmatch(r"(\d+) passed, 0 failed", last)
    assert match, f"unexpected last line {last!r}:\n{output}"
    assert int(match.group(1)) >= 50


def test_sketch_type_checks_against_the_arduino_stubs() -> None:
    _require_toolchain()
    result = _make("sketch-check")
    assert result.returncode == 0, result.stdout + result.stderr


# --- host firmware over the pty ----------------------------------------------------------


def test_host_prints_pty_path_then_url(firmware: HostFirmware) -> None:
    assert firmware.pty_path.startswith("/dev/")
    assert os.isatty(firmware.fd)
    assert os.path.realpath(firmware.link_path) == os.path.realpath(firmware.pty_path)
    assert re.fullmatch(r"http://127\.0\.0\.1:\d+/api/command", firmware.url)
    assert firmware.read_line() == "# taskrunner-servo 1.1.0 protocol 2 ready"


def test_status_reports_home_angles_unpowered_at_boot(firmware: HostFirmware) -> None:
    status = firmware.status()
    assert status["status"] == "ok"
    assert status["mode"] == "idle"
    assert status["moving"] is False
    assert status["powered"] is False
    assert status["pos"] == [90] * 6
    assert status["speed"] == 5


def test_version_channels_match_hardware_yaml(firmware: HostFirmware) -> None:
    reply = firmware.command("VERSION")
    assert reply.startswith("ok {"), reply
    version = json.loads(reply[3:])
    joints = yaml.safe_load(HARDWARE_YAML.read_text())["joints"]
    channels = [joint["channel"] for joint in joints if "same_servo_as" not in joint]
    assert version["servos"] == len(channels) == 6
    assert version["channels"] == channels
    assert version["tick_ms"] == TICK_MS
    assert version["protocol"] == 2 and version["checksum"] == "crc8"


def test_move_reaches_its_target_after_enough_ticks(firmware: HostFirmware) -> None:
    target = [120, 60, 90, 100, 80, 112.5]
    before = firmware.status()
    assert firmware.command("MOVE:" + ",".join(str(a) for a in target)) == "ok"
    started = firmware.status()
    assert started["target"] == target
    assert started["powered"] is True
    # 30 degrees at 5 degrees per tick: 6 ticks = 480 ms of firmware time.
    done = firmware.wait_status(lambda s: not s["moving"])
    assert done["pos"] == target
    assert done["mode"] == "idle"
    assert done["tick"] - before["tick"] >= 6


def test_bad_commands_get_one_error_reply_each(firmware: HostFirmware) -> None:
    assert firmware.command("FOO").startswith("err 1 unknown command 'FOO'")
    assert firmware.command("MOVE:90,90,200,90,90,90") == (
        "err 2 angle 3 out of range 0..180 (got 200)")
    assert firmware.command("MOVE:1,2") == "err 3 MOVE needs 6 angles (got 2)"
    assert firmware.command("SPEED:fast") == "err 4 speed must be an integer 1..20 (got 'fast')"
    assert firmware.command("PING" + "x" * 200) == "err 6 line too long (max 128 bytes)"
    firmware.write(b"\xff\x00junk\r\n")
    assert firmware.read_reply() == "err 7 invalid byte 0xff at column 1 (printable ASCII only)"
    firmware.write(b"PING\r\n\r\nPING\r")
    assert firmware.read_reply() == "ok pong"
    assert firmware.read_reply() == "ok pong"
    assert firmware.status()["powered"] is False  # nothing moved


def test_stop_halts_mid_move(firmware: HostFirmware) -> None:
    assert firmware.command("SPEED:1") == "ok"
    assert firmware.command("MOVE:180,180,180,180,180,180") == "ok"
    firmware.wait_status(lambda s: s["pos"][0] >= 93)
    assert firmware.command("STOP") == "ok"
    stopped = firmware.status()
    assert stopped["moving"] is False
    assert stopped["target"] == stopped["pos"]
    firmware.wait_status(lambda s: s["tick"] >= stopped["tick"] + 5)
    assert firmware.status()["pos"] == stopped["pos"]


def test_streamed_trajectory_is_followed_tick_by_tick(host_binary: Path, tmp_path: Path) -> None:
    # A host streaming 80 ms points: servo 1 90 -> 130, servo 2 90 -> 60 over 1.6 s.
    # The host build's tick clock follows the wall clock, so a test process kept off the
    # CPU (a busy machine) lets the queue run dry whatever lead it keeps, and the firmware
    # then rightly holds. What is judged here is the firmware's side: the points are
    # written while the firmware is stopped (SIGSTOP), so all of them are queued, in order,
    # before its next tick; then the tick log (firmware time) must follow them tick by
    # tick. The watchdog is off: it would stop the queue if STATUS polls came late, and it
    # has tests of its own.
    fw = _start(host_binary, tmp_path, speedup=4.0, extra=("--watchdog-ms", "0"))
    try:
        points = 20
        duration_ms = points * TICK_MS

        def angles_at(t_ms: float) -> list[float]:
            s = min(1.0, max(0.0, t_ms / duration_ms))
            return [90 + 40 * s, 90 - 30 * s, 90, 90, 90, 90]

        lines = [with_checksum(f"TRAJ:{TICK_MS}:" + ",".join(
            f"{a:.2f}" for a in angles_at(k * TICK_MS))) for k in range(1, points + 1)]
        os.kill(fw.proc.pid, signal.SIGSTOP)
        try:
            fw.write("".join(line + "\n" for line in lines).encode("ascii"))
        finally:
            os.kill(fw.proc.pid, signal.SIGCONT)
        replies = [strip_checksum(fw.read_reply()) for _ in lines]
        # Each point joined the queue behind the others, none played yet.
        assert replies == [f"ok {k} {k * TICK_MS}" for k in range(1, points + 1)], replies
        done = fw.wait_status(lambda s: not s["moving"] and s["queued"] == 0, timeout=10.0)
        assert done["pos"] == [130, 60, 90, 90, 90, 90]
    finally:
        returncode = fw.terminate()
        os.close(fw.fd)
    assert returncode == 0

    rows = fw.log_rows()
    times = [row[0] for row in rows]
    assert times == [TICK_MS * k for k in range(len(rows))]  # one row per tick
    # The timeline's origin is the tick before the first point took effect.
    first_move = next(k for k, row in enumerate(rows) if row[1] != 90)
    origin = rows[first_move - 1][0]
    for row in rows[first_move - 1 :]:
        expected = angles_at(row[0] - origin)
        assert all(abs(a - e) <= 1.0 for a, e in zip(row[1:], expected)), (row, expected)


# --- host firmware over HTTP -----------------------------------------------------------


def test_http_status_move_and_shared_state(firmware: HostFirmware) -> None:
    reply = firmware.http_command("STATUS")
    assert reply.startswith("ok {"), reply
    assert json.loads(reply[3:])["pos"] == [90] * 6
    assert firmware.http_command("MOVE:100,100,100,100,100,100") == "ok"
    done = firmware.wait_status(lambda s: not s["moving"])  # over the pty
    assert done["pos"] == [100] * 6


def test_http_errors(firmware: HostFirmware) -> None:
    assert firmware.http_command("FOO").startswith("err 1 unknown command 'FOO'")
    assert strip_checksum(firmware.http_command(with_checksum("TRAJ:0:1,1,1,1,1,1"))) == (
        "err 2 dt_ms out of range 1..60000 (got 0)")
    # A TRAJ point without its checksum never runs, over HTTP as over serial.
    assert firmware.http_command("TRAJ:80:1,1,1,1,1,1").startswith("err 8 TRAJ needs a checksum")
    assert firmware.command("TRAJ:80:1,1,1,1,1,1").startswith("err 8 TRAJ needs a checksum")
    assert firmware.status()["queued"] == 0

    code, answer = firmware.post(b'{"command": "PING"}')
    assert code == 400
    assert answer["error"].startswith("missing 'cmd'")
    # urllib's default Content-Type is a form: the ESP32 WebServer would not see the JSON.
    code, answer = firmware.post(b'{"cmd": "PING"}', content_type=None)
    assert code == 400
    assert "Content-Type: application/json" in answer["error"]
    code, answer = firmware.post(b"", method="GET")
    assert code == 405
    code, answer = firmware.post(b'{"cmd": "PING"}', url=firmware.url.replace("/api/command", "/x"))
    assert code == 404


# --- shutdown ----------------------------------------------------------------------------


def test_sigterm_exits_cleanly(firmware: HostFirmware) -> None:
    assert firmware.command("PING") == "ok pong"
    started = time.monotonic()
    assert firmware.terminate() == 0
    assert time.monotonic() - started < 2.0
    assert not firmware.link_path.exists()
    text = firmware.log_path.read_text()
    assert text.endswith("\n")
    assert len(firmware.log_rows()) >= 1
