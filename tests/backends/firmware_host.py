"""Building and starting the host build of the ESP32 firmware for backend tests."""

from __future__ import annotations

import os
import select
import shutil
import signal
import subprocess
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import pytest

from taskrunner.backends.host_firmware import build_host_firmware
from taskrunner.processes import ending_with_parent


def build_host() -> Path:
    """The host firmware, built as ``run-task firmware-sim`` builds it (one cached build
    shared by the tests and the CLI); skips the test when make or g++ is missing."""
    missing = [tool for tool in ("make", "g++") if shutil.which(tool) is None]
    if missing:
        pytest.skip(f"the firmware host build needs {' and '.join(missing)}, not on PATH")
    return build_host_firmware(timeout_s=300)


def read_address_lines(proc: subprocess.Popen[bytes], timeout: float = 5.0) -> tuple[str, str]:
    """The pty path and the URL a firmware host prints on its first two lines."""
    assert proc.stdout is not None
    data, deadline = b"", time.monotonic() + timeout
    while data.count(b"\n") < 2:
        ready, _, _ = select.select([proc.stdout], [], [], max(0.0, deadline - time.monotonic()))
        assert ready, f"the firmware host printed {data!r} in {timeout} s"
        chunk = os.read(proc.stdout.fileno(), 4096)
        assert chunk, f"the firmware host exited early after printing {data!r}"
        data += chunk
    pty, url = data.decode().splitlines()[:2]
    return pty, url


def stop_process(proc: subprocess.Popen[bytes], sig: int = signal.SIGTERM) -> None:
    """End ``proc`` (resuming it first if a test stopped it), killing it if it lingers."""
    if proc.poll() is None:
        os.kill(proc.pid, signal.SIGCONT)
        proc.send_signal(sig)
    try:
        proc.wait(10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait(5)


@dataclass
class FirmwareHost:
    proc: subprocess.Popen[bytes]
    pty: str
    url: str
    log: Path | None


@contextmanager
def running_host(binary: Path, speedup: float, log: Path | None = None,
                 channels: list[int] | None = None) -> Iterator[FirmwareHost]:
    """A firmware host at ``speedup`` (ticks logged to ``log`` if given; servos on
    ``channels``, default one arm's six), stopped after."""
    command = [str(binary), "--speedup", str(speedup)]
    if channels is not None:
        command += ["--channels", ",".join(map(str, channels))]
    if log is not None:
        command += ["--log", str(log)]
    # Ended with the test process even when it is killed (a busy CI's timeout).
    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                            preexec_fn=ending_with_parent())
    try:
        pty, url = read_address_lines(proc)
        yield FirmwareHost(proc, pty, url, log)
    finally:
        stop_process(proc)
