"""Building the host build of the ESP32 firmware (simulated servos behind a pty and HTTP).

The firmware sources ship inside the package (``taskrunner/data/firmware``), which may be
read-only once installed, so the build goes to a cache folder named after a hash of the
sources: an edited source tree builds afresh, an unchanged one is built once.
"""

from __future__ import annotations

import fcntl
import hashlib
import os
import shutil
import subprocess
from pathlib import Path

from taskrunner import resources
from taskrunner.errors import InputError

__all__ = ["HOST_BINARY_NAME", "build_host_firmware", "firmware_source_hash"]

HOST_BINARY_NAME = "taskrunner-servo-host"
_SOURCE_SUFFIXES = (".cpp", ".h", ".ino")


def firmware_source_hash(source: Path | None = None) -> str:
    """A short hash of the firmware's sources and Makefile (what the host build reads)."""
    source = source or resources.firmware_dir()
    digest = hashlib.sha256()
    files = [source / "Makefile", *sorted(
        p for p in source.rglob("*")
        if p.suffix in _SOURCE_SUFFIXES and "build" not in p.relative_to(source).parts)]
    for path in files:
        digest.update(str(path.relative_to(source)).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def build_host_firmware(build_dir: Path | None = None, jobs: int | None = None,
                        timeout_s: float = 600.0) -> Path:
    """Build the host firmware if needed and return the path of its binary.

    Args:
        build_dir: where objects and the binary go (default: the user cache folder,
            ``~/.cache/taskrunner/firmware-<hash>``).
        jobs: parallel compile jobs (default: the number of cores, at most 8).
        timeout_s: how long the build may take (s).

    Raises:
        InputError: make or g++ missing, or the build failed (its last lines quoted).
    """
    missing = [tool for tool in ("make", "g++") if shutil.which(tool) is None]
    if missing:
        raise InputError(f"the host firmware needs {' and '.join(missing)} on PATH "
                         "(Debian: apt-get install make g++)")
    source = resources.firmware_dir()
    build_dir = (build_dir or resources.user_cache_dir() / f"firmware-{firmware_source_hash()}")
    build_dir = build_dir.resolve()
    build_dir.mkdir(parents=True, exist_ok=True)
    jobs = jobs or max(1, min(os.cpu_count() or 1, 8))
    # One build at a time per folder: two processes starting at once on a new machine
    # (two `run-task firmware-sim`, parallel test workers) would write the same objects
    # and link the binary while the other runs it. The second waits, then finds it built.
    with open(build_dir / ".build.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            built = subprocess.run(
                ["make", "-s", "--no-print-directory", "-j", str(jobs), "-C", str(source),
                 f"BUILD={build_dir}", "host"],
                capture_output=True, text=True, timeout=timeout_s, check=False)
        except subprocess.TimeoutExpired:
            raise InputError(f"building the host firmware took over {timeout_s:.0f} s") \
                from None
    if built.returncode != 0:
        raise InputError(f"building the host firmware failed:\n{built.stderr[-2000:]}")
    binary = build_dir / HOST_BINARY_NAME
    if not binary.is_file():
        raise InputError(f"the host firmware build made no {binary}")
    return binary
