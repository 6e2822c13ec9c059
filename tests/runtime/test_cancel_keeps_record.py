"""A cancel keeps what happened: the tree text (the REST tree), the terminal's last frame
and the record show each node as it was when the run stopped; a cancel that comes once
every step has ended is reported as too late, and the run keeps its one outcome."""

from __future__ import annotations

import io
import os
import signal
import textwrap
import threading

import pytest

from taskrunner.backends.mock import MockBackend, MockOptions
from taskrunner.cli import main
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import cells_dir
from taskrunner.robot.cell import load_cell
from taskrunner.runtime import runner as runner_module
from taskrunner.runtime.display import LiveTree, view_tree
from taskrunner.runtime.runner import CANCELLED, Runner, RunOptions
from taskrunner.tasks import load_task

# Line 5 is the slow go: at 5 % of the servo speeds, replayed in real time, it is seconds
# long, so the run is in it when the cancel is seen at the next tick.
TASK = textwrap.dedent(f"""\
    task: t
    cell: {cells_dir() / "servo_arm_table.yaml"}
    steps:
      - wait: {{seconds: 0.01}}
      - go: {{group: arm, to: Candle, velocity_scaling: 0.05, acceleration_scaling: 0.05}}
      - go: {{group: arm, to: home}}
    """)


def make_runner(path):
    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())), MockOptions(speed=1.0))
    return Runner(spec, cell, backend, InProcessPlanner(), RunOptions()), backend


def cancelled_mid_way(tmp_path):
    """A run cancelled as its second step (the slow go, line 5) starts."""
    path = tmp_path / "t.yaml"
    path.write_text(TASK)
    runner, backend = make_runner(path)

    def on_event(event):
        if event.kind == "node_started" and (event.location or "").endswith(":5"):
            runner.cancel("cancelled (test)")

    runner.events.subscribe(on_event)
    try:
        record = runner.run()
    finally:
        backend.close()
    return runner, record


def leaf_lines(text: str) -> list[str]:
    return [line.strip() for line in text.splitlines() if line.strip().startswith("-->")]


def test_the_tree_after_a_cancel_shows_what_ran_not_a_reset_tree(tmp_path):
    runner, record = cancelled_mid_way(tmp_path)
    assert record.status == "cancelled" and record.exit_code == 130
    wait, go, home = leaf_lines(runner.snapshot())
    assert wait.endswith("[✓]") or "[✓] --" in wait
    assert go.endswith("[-] -- cancelled (test)")
    assert home.endswith("[-]")
    # The tree itself was stopped (every node reset), the text is what it was.
    assert all(n.status.value == "INVALID" for n in runner.tree.iterate())
    assert runner.stopped is not None


def test_the_record_holds_each_leafs_end(tmp_path):
    runner, record = cancelled_mid_way(tmp_path)
    ends = [(e.location.rsplit(":", 1)[1], e.status) for e in record.events
            if e.kind == "node_finished"]
    assert ends == [("4", "SUCCESS"), ("5", "INVALID")]


def test_the_last_frame_counts_the_finished_steps_and_marks_the_cancelled_one(tmp_path):
    runner, _ = cancelled_mid_way(tmp_path)
    view = view_tree(runner.tree, stopped=runner.stopped)
    assert [leaf.status for leaf in view.children] == ["SUCCESS", CANCELLED, "INVALID"]
    out = io.StringIO()
    live = LiveTree(out)
    live.update(runner)
    live.close()
    frame = out.getvalue()
    assert "1 of 3 steps" in frame
    assert "✔ wait" in frame and "■ go arm" in frame


def test_a_cancel_during_the_expectations_check_is_too_late_and_the_run_succeeds(
        tmp_path, monkeypatch):
    path = tmp_path / "t.yaml"
    path.write_text(TASK.replace("velocity_scaling: 0.05, acceleration_scaling: 0.05",
                                 "velocity_scaling: 1.0"))
    runner, backend = make_runner(path)
    answers = []
    real_check = runner_module.check_task_end

    def check_then_cancel(*args):
        answers.append(runner.cancel("cancelled (test)"))
        return real_check(*args)

    monkeypatch.setattr(runner_module, "check_task_end", check_then_cancel)
    try:
        record = runner.run()
    finally:
        backend.close()
    assert answers == [False]  # the cancel was told it came too late
    assert (record.status, record.exit_code, record.error) == ("succeeded", 0, None)
    late = [e for e in record.events if e.kind == "message" and e.data.get("late_cancel")]
    assert [e.message for e in late] == [
        "cancelled (test) too late: every step had ended; the run succeeded"]
    assert record.events[-1].kind == "run_finished" and record.events[-1].status == "succeeded"
    assert "cancelled" not in runner.snapshot()  # the tree is as it ended: all done


@pytest.mark.skipif(threading.current_thread() is not threading.main_thread(),
                    reason="Ctrl-C handlers are installed from the main thread only")
def test_ctrl_c_during_the_expectations_check_prints_one_outcome(tmp_path, monkeypatch, capsys):
    path = tmp_path / "t.yaml"
    path.write_text(TASK.replace("velocity_scaling: 0.05, acceleration_scaling: 0.05",
                                 "velocity_scaling: 1.0"))
    real_check = runner_module.check_task_end
    seen = threading.Event()
    real_cancel = Runner.cancel

    def cancel_and_note(self, *args, **kwargs):
        answer = real_cancel(self, *args, **kwargs)
        seen.set()
        return answer

    def check_after_ctrl_c(*args):
        os.kill(os.getpid(), signal.SIGINT)  # a Ctrl-C, handled on the main thread
        assert seen.wait(10), "the Ctrl-C handler never ran"
        return real_check(*args)

    monkeypatch.setattr(Runner, "cancel", cancel_and_note)
    monkeypatch.setattr(runner_module, "check_task_end", check_after_ctrl_c)
    code = main(["run", str(path), "--in-process", "--plain", "--no-check"])
    out = capsys.readouterr().out
    assert code == 0
    assert "cancelled (Ctrl-C) too late: every step has ended" in out
    assert "stopping the motion" not in out
    assert "t: succeeded (exit 0)" in out
    assert "cancelled (Ctrl-C) too late: every step had ended; the run succeeded" in out
