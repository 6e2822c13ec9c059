"""A xacro expansion is bounded by the CPU time it uses, not by the wall-clock time a busy
machine takes to give it that CPU: a child held off the processor (here: stopped with
SIGSTOP for longer than the limit) still expands the robot."""

from __future__ import annotations

import multiprocessing
import os
import signal
import threading
import time
from pathlib import Path

import pytest

from taskrunner.errors import RobotDescriptionError
from taskrunner.robot.packages import PackageMap
from taskrunner.robot.xacrofile import XacroOptions, expand_xacro


def _xacro(tmp_path: Path) -> Path:
    path = tmp_path / "arm.urdf.xacro"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                    '<xacro:property name="l" value="${3 * 4}"/>\n'
                    '<link name="base"/><link name="tip_${l}"/>\n</robot>\n')
    return path


def _hold_the_child_off_the_cpu(seconds: float, held: list[int]) -> threading.Thread:
    """Stop the next child process this one starts for ``seconds``, then let it go on."""
    before = {p.pid for p in multiprocessing.active_children()}

    def hold() -> None:
        deadline = time.monotonic() + 30.0
        while time.monotonic() < deadline:
            new = [p.pid for p in multiprocessing.active_children() if p.pid not in before]
            if new:
                os.kill(new[0], signal.SIGSTOP)
                held.append(new[0])
                time.sleep(seconds)
                try:
                    os.kill(new[0], signal.SIGCONT)
                except ProcessLookupError:
                    pass  # stopped by the expansion's own limit meanwhile
                return
            time.sleep(0.001)

    thread = threading.Thread(target=hold, daemon=True)
    thread.start()
    return thread


def test_an_expansion_held_off_the_cpu_past_its_limit_still_expands(tmp_path, monkeypatch):
    monkeypatch.setenv("TASKRUNNER_XACRO_CACHE", "0")
    path = _xacro(tmp_path)
    held: list[int] = []
    holder = _hold_the_child_off_the_cpu(1.0, held)
    start = time.monotonic()
    text = expand_xacro(path, PackageMap(), options=XacroOptions(time_limit_s=0.5))
    holder.join(5)
    assert held, "the child was never seen (so never held)"
    assert time.monotonic() - start >= 1.0  # it waited past its CPU limit in wall time
    assert 'name="tip_12"' in text


def test_an_expansion_waiting_past_the_wall_clock_limit_is_stopped(tmp_path, monkeypatch):
    monkeypatch.setenv("TASKRUNNER_XACRO_CACHE", "0")
    path = _xacro(tmp_path)
    held: list[int] = []
    holder = _hold_the_child_off_the_cpu(1.0, held)
    with pytest.raises(RobotDescriptionError) as info:
        expand_xacro(path, PackageMap(), options=XacroOptions(wall_limit_s=0.3))
    holder.join(5)
    assert held
    assert str(info.value) == (f"{path}: xacro expansion did not end in 0.3 s (waiting on "
                               "something it reads?)")
