"""A CLI run ended by a signal: Ctrl-C and SIGTERM stop it cleanly, SIGKILL loses nothing
it announced. Real subprocesses of ``run-task`` on the sim backend, signalled mid-motion."""

from __future__ import annotations

import json
import os
import queue
import re
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from taskrunner.runtime.records import journal_path, load_record

MOTION = re.compile(r"planned in \d+ ms, motion (\d+\.\d+) s")


class RunTask:
    """``run-task pick_place --backend sim`` in its own process group, read line by line."""

    def __init__(self, runs_dir: Path) -> None:
        env = {**os.environ, "PYTHONUNBUFFERED": "1"}
        self.process = subprocess.Popen(
            [sys.executable, "-m", "taskrunner.cli", "pick_place", "--backend", "sim",
             "--plain", "--runs-dir", str(runs_dir)],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
            start_new_session=True)
        self.lines: queue.Queue[str | None] = queue.Queue()
        self.out: list[str] = []
        self.err: list[str] = []
        threading.Thread(target=self._pump, args=(self.process.stdout, self.lines),
                         daemon=True).start()
        threading.Thread(target=lambda: self.err.extend(self.process.stderr or []),
                         daemon=True).start()

    @staticmethod
    def _pump(stream, lines: queue.Queue) -> None:  # type: ignore[no-untyped-def]
        for line in stream:
            lines.put(line)
        lines.put(None)

    def wait_for_motion(self, timeout: float = 120.0) -> None:
        """Wait until a motion longer than 1.5 s is planned and has run for a moment."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            try:
                line = self.lines.get(timeout=max(0.1, deadline - time.monotonic()))
            except queue.Empty:
                break
            if line is None:
                break
            self.out.append(line)
            found = MOTION.search(line)
            if found and float(found.group(1)) > 1.5:
                time.sleep(0.3)
                return
        self.kill()
        pytest.fail("no long motion started:\n" + "".join(self.out) + "".join(self.err))

    def finish(self, timeout: float = 60.0) -> tuple[int, str, str]:
        try:
            code = self.process.wait(timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            pytest.fail("run-task did not end after the signal:\n" + "".join(self.out))
        deadline = time.monotonic() + 10.0
        while time.monotonic() < deadline:
            line = self.lines.get(timeout=10.0)
            if line is None:
                break
            self.out.append(line)
        time.sleep(0.1)  # let the stderr reader drain
        return code, "".join(self.out), "".join(self.err)

    def kill(self) -> None:
        try:
            os.killpg(self.process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        self.process.wait(10)


def only_record(runs_dir: Path) -> Path:
    records = list(runs_dir.glob("*.json"))
    assert len(records) == 1, records
    return records[0]


def test_ctrl_c_mid_motion_stops_cleanly_with_exit_130_and_a_cancelled_record(tmp_path):
    run = RunTask(tmp_path / "runs")
    run.wait_for_motion()
    os.killpg(run.process.pid, signal.SIGINT)  # what a terminal does: the whole group
    code, out, err = run.finish()
    assert "Traceback" not in err, err
    assert code == 130, out + err
    assert "pick_place: cancelled (exit 130)" in out  # the summary
    record = load_record(only_record(tmp_path / "runs"))
    assert record.status == "cancelled" and record.exit_code == 130
    assert record.error == "cancelled (Ctrl-C)"
    assert record.events[-1].kind == "run_finished"
    stopped = [e for e in record.events if e.kind == "node_finished" and e.status == "INVALID"]
    assert stopped, "the motion in progress was stopped"
    assert not journal_path(only_record(tmp_path / "runs")).exists()


def test_sigterm_mid_motion_ends_the_run_as_cancelled_with_exit_143(tmp_path):
    run = RunTask(tmp_path / "runs")
    run.wait_for_motion()
    run.process.send_signal(signal.SIGTERM)
    code, out, err = run.finish()
    assert "Traceback" not in err, err
    assert code == 143, out + err
    record = load_record(only_record(tmp_path / "runs"))
    assert (record.status, record.exit_code, record.error) == (
        "cancelled", 143, "cancelled (SIGTERM)")


def test_a_run_killed_outright_leaves_every_event_it_announced(tmp_path):
    run = RunTask(tmp_path / "runs")
    run.wait_for_motion()
    os.killpg(run.process.pid, signal.SIGKILL)
    run.process.wait(30)
    announced = [line for line in run.out if "▶" in line or "✔" in line or "planned" in line]
    runs = tmp_path / "runs"
    # no record file claims the run goes on: the JSON is written only at a run's end;
    # the journal, with the record's head, is all there is
    assert list(runs.glob("*.json")) == []
    [journal] = runs.glob("*.events.jsonl")
    header = json.loads(journal.read_text().splitlines()[0])
    assert "status" not in header["record"] and header["record"]["task"] == "pick_place"
    path = journal.with_name(journal.name.replace(".events.jsonl", ".json"))
    assert journal_path(path) == journal
    assert load_record(journal).as_dict() == load_record(path).as_dict()
    record = load_record(path)
    shown = [e for e in record.events if e.kind in ("node_started", "planned")
             or (e.kind == "node_finished" and e.status == "SUCCESS")]
    assert len(shown) >= len(announced) >= 6
    assert [e.seq for e in record.events] == list(range(1, len(record.events) + 1))
    assert record.status == "interrupted"
    assert "ended without finishing the run" in (record.error or "")
