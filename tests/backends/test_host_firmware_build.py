"""The host firmware's build: one at a time per build folder (parallel starts on a new
machine must not write the same objects or link the binary while another runs it)."""

from __future__ import annotations

import fcntl
import threading

from firmware_host import build_host

from taskrunner import resources
from taskrunner.backends.host_firmware import build_host_firmware, firmware_source_hash


def test_a_second_build_waits_for_the_first_then_finds_it_built():
    binary = build_host()  # built (or cached) once
    folder = resources.user_cache_dir() / f"firmware-{firmware_source_hash()}"
    assert binary.parent == folder.resolve()
    results: list[object] = []
    with open(folder / ".build.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # a build in progress elsewhere
        second = threading.Thread(target=lambda: results.append(build_host_firmware()))
        second.start()
        second.join(0.5)
        assert second.is_alive() and not results  # waiting for the lock, not building
        fcntl.flock(lock, fcntl.LOCK_UN)
    second.join(120)
    assert results == [binary]
