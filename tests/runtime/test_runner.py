"""The runner: success, failures with file:line and exit codes, cancel mid-motion on sim."""

from __future__ import annotations

import textwrap
import threading
import time

import numpy as np
import pytest

from taskrunner.backends.mock import MockBackend, MockOptions
from taskrunner.backends.sim import SimBackend, SimOptions
from taskrunner.cli import main
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import EXIT_CODES, Runner, RunOptions
from taskrunner.tasks import load_task


def write_task(tmp_path, repo_root, body: str):
    path = tmp_path / "task.yaml"
    cell = DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"
    path.write_text(f"task: t\ncell: {cell}\n" + textwrap.dedent(body))
    return path


def make_runner(path, backend_factory, **options):
    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = backend_factory(names, dict(zip(names, cell.start_state())))
    return Runner(spec, cell, backend, InProcessPlanner(), RunOptions(**options)), backend


def test_an_unreachable_pose_fails_the_run_with_the_steps_line(tmp_path, repo_root):
    path = write_task(tmp_path, repo_root, """\
        steps:
          - go: {group: arm, to: Candle}
          - go: {group: arm, pose: {xyz: [1.5, 0, 1.0]}}
        """)
    runner, _ = make_runner(path, MockBackend)
    record = runner.run()
    assert record.status == "failed"
    assert record.exit_code == EXIT_CODES["planning"] == 3
    assert record.error.startswith(f"{path}:5: no IK solution for group 'arm'")


def test_an_execution_failure_is_exit_code_4(tmp_path, repo_root):
    path = write_task(tmp_path, repo_root, "steps:\n  - go: {group: arm, to: Candle}\n")
    runner, _ = make_runner(
        path, lambda n, s: MockBackend(n, s, MockOptions(speed=1000.0, fail_after=0.5)))
    record = runner.run()
    assert record.exit_code == EXIT_CODES["execution"] == 4
    assert "execution failed" in record.error and f"{path}:4" in record.error


def test_fallback_recovers_and_the_run_succeeds(tmp_path, repo_root):
    path = write_task(tmp_path, repo_root, """\
        steps:
          - fallback:
              - go: {group: arm, pose: {xyz: [1.5, 0, 1.0]}}
              - go: {group: arm, to: Candle}
        """)
    runner, _ = make_runner(path, MockBackend)
    record = runner.run()
    assert record.status == "succeeded"
    failures = [e for e in record.events if e.kind == "node_finished" and e.status == "FAILURE"]
    assert len(failures) == 1 and failures[0].location == f"{path}:5"


def test_cancel_stops_the_sim_where_it_is_and_records_cancelled(tmp_path, repo_root):
    path = write_task(tmp_path, repo_root, "steps:\n  - go: {group: arm, to: Candle, "
                      "velocity_scaling: 0.01, acceleration_scaling: 0.01}\n")
    runner, backend = make_runner(
        path, lambda n, s: SimBackend(n, s, SimOptions(speed=10.0)), runs_dir=tmp_path / "runs")
    start = backend.joint_state().positions.copy()
    result = []
    thread = threading.Thread(target=lambda: result.append(runner.run()))
    thread.start()
    deadline = time.monotonic() + 20
    while not runner.ctx.executed and time.monotonic() < deadline:
        time.sleep(0.01)
    time.sleep(0.3)  # let it move for a while (~30 s of motion at 1 % scaling, 10x: ~3 s)
    runner.cancel()
    thread.join(10)
    backend_state = backend.joint_state().positions.copy()
    time.sleep(0.2)
    try:
        assert result[0].status == "cancelled" and result[0].exit_code == 130
        # Stopped part-way: moved from the start, not at Candle, and not moving any more.
        candle = runner.scene.robot.named_state("arm", "Candle").positions
        assert not np.allclose(backend_state[:5], start[:5], atol=1e-3)
        assert not np.allclose(backend_state[:5], candle, atol=1e-3)
        assert np.array_equal(backend.joint_state().positions, backend_state)
        # The scene followed the backend.
        assert runner.scene.state == pytest.approx(backend_state)
    finally:
        backend.close()


def test_servo_arm_pick_place_is_under_40_s_of_motion_and_a_gripper_move_under_2_s():
    """At the servo arm's default limits (servo datasheet speeds, joint_limits.yaml): once
    218 s of motion, 28 s for each gripper open or close."""
    runner, backend = make_runner(DATA_ROOT / "tasks" / "pick_place.yaml", MockBackend)
    try:
        record = runner.run()
    finally:
        backend.close()
    assert record.status == "succeeded", record.error
    planned = [e for e in record.events if e.kind == "planned"]
    assert 5.0 < sum(e.data["duration"] for e in planned) <= 40.0
    gripper = [e.data["duration"] for e in planned if e.node.endswith((": open", ": close"))
               and e.data["duration"] > 0]  # the first open: the gripper is open already
    assert len(gripper) == 2 and all(d <= 2.0 for d in gripper), gripper


def test_cli_runs_a_task_and_reports(tmp_path, repo_root, capsys):
    path = write_task(tmp_path, repo_root, "steps:\n  - go: {group: arm, to: Candle}\n")
    code = main(["run", str(path), "--in-process", "--runs-dir", str(tmp_path / "runs")])
    out = capsys.readouterr().out
    assert code == 0
    assert "t: succeeded (exit 0)" in out
    assert list((tmp_path / "runs").glob("*.json"))


def test_cli_exit_code_2_for_an_invalid_task(tmp_path, repo_root, capsys):
    path = write_task(tmp_path, repo_root, "steps:\n  - go: {group: arm, too: Candle}\n")
    assert main([str(path), "--in-process", "--runs-dir", str(tmp_path / "runs")]) == 2
    assert f"{path}:4: 'too' is not a field of 'go'" in capsys.readouterr().err


@pytest.mark.parametrize("planner_times", [False, True])
def test_planned_motions_are_timed_where_the_run_options_say(tmp_path, repo_root,
                                                               planner_times):
    path = write_task(tmp_path, repo_root, """\
        steps:
          - go: {group: arm, to: Candle}
          - go: {group: arm, to: home}
        """)
    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    service = InProcessPlanner()
    sent, returned = [], []
    submit = service.submit

    def recording_submit(scene, request):
        sent.append(request)
        ticket = submit(scene, request)
        result = ticket.result

        def recorded_result(timeout=None):
            returned.append(result(timeout))
            return returned[-1]

        ticket.result = recorded_result
        return ticket

    service.submit = recording_submit
    runner = Runner(spec, cell, backend, service, RunOptions(planner_times=planner_times))
    assert runner.run().status == "succeeded"
    assert len(sent) == 2
    assert all((r.timing is not None) == planner_times for r in sent)
    assert all((r.trajectory is not None) == planner_times for r in returned)
    executed = [m.trajectory for m in runner.ctx.executed]
    if planner_times:  # what ran is what the planner timed
        assert [t for t in executed if len(t.times) > 1] == \
            [r.trajectory for r in returned if len(r.trajectory.times) > 1]


def test_a_failed_timing_fails_the_run_cleanly_and_the_cell_stays_usable(tmp_path, repo_root,
                                                                        monkeypatch):
    """toppra raising (as it did with a grid ending past the path) is a planning failure
    with file:line, not a ValueError out of the run; the next run, with the same planning
    worker and backend, plans and moves."""
    from taskrunner.planning import timing
    from taskrunner.planning.worker import PlanningWorker

    path = write_task(tmp_path, repo_root, "steps:\n  - go: {group: arm, to: Candle}\n")
    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    kit = timing._toppra_kit()
    real = kit.toppra.algorithm.TOPPRA
    calls = []

    def refusing_once(*args, **kwargs):
        calls.append(1)
        if len(calls) == 1:
            raise ValueError("Invalid manually supplied gridpoints.")
        return real(*args, **kwargs)

    monkeypatch.setattr(kit.toppra.algorithm, "TOPPRA", refusing_once)
    # The path to Candle is a straight line, which is timed in closed form: a midpoint on
    # it makes toppra time it.
    from taskrunner.tree import behaviours
    from taskrunner.types import JointPath

    real_parameterize = behaviours.parameterize_path

    def through_the_middle(model, path, options):  # type: ignore[no-untyped-def]
        w = np.asarray(path.waypoints)
        if len(w) == 2:
            path = JointPath(path.names, np.vstack([w[0], 0.5 * (w[0] + w[1]), w[1]]))
        return real_parameterize(model, path, options)

    monkeypatch.setattr(behaviours, "parameterize_path", through_the_middle)
    with PlanningWorker(spec.cell) as worker:
        failed = Runner(spec, cell, backend, worker, RunOptions(runs_dir=tmp_path / "runs")).run()
        assert (failed.status, failed.exit_code) == ("failed", EXIT_CODES["planning"])
        assert failed.error.startswith(f"{path}:4: toppra could not time the path")
        again = Runner(load_task(path), cell, backend, worker).run()
    assert again.status == "succeeded", again.error
    candle = cell.model.named_state("arm", "Candle").as_dict()
    state = backend.joint_state().as_dict()
    assert all(abs(state[name] - value) < 1e-6 for name, value in candle.items())
