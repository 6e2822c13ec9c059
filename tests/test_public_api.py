"""The public Python API: its names, and each capability on the shipped servo arm (mock)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import taskrunner
from taskrunner import (
    Expect,
    Go,
    Gripper,
    Object,
    Parallel,
    Pick,
    Place,
    Pose,
    Sequence,
    Task,
    TaskrunnerError,
    Wait,
)
from taskrunner.errors import (
    ArgumentError,
    BackendError,
    InputError,
    TaskSpecError,
    UnknownNameError,
)
from taskrunner.taught import read_taught_poses


def test_the_exported_names_are_pinned():
    assert taskrunner.__all__ == [
        "AddObject", "Attach", "Backend", "BackendKind", "CollisionChoice", "Detach", "ExecutionHandle",
        "ExecutionResult", "Expect", "Fallback", "Go", "Gripper", "Handoff", "JointPath",
        "JointState", "JointTrajectory", "LoadOptions", "Move", "Object", "Parallel", "Pick", "Place", "Plan",
        "Pose", "RemoveObject", "Repeat", "ResumeOptions", "Retry", "RunEvent", "RunRecord",
        "RunResult", "Sequence", "Task", "TaskRun", "TaskrunnerError", "TaughtPose", "Timeout",
        "Wait", "Workcell", "__version__", "load_workcell", "run_task", "start_task",
    ]
    for name in taskrunner.__all__:
        value = getattr(taskrunner, name)
        assert name == "__version__" or value.__doc__, f"{name} has no docstring"
    with pytest.raises(AttributeError, match="no attribute 'nope'"):
        taskrunner.nope  # noqa: B018


def test_the_workcell_reads_moveit_scene_and_request_files():
    for method in ("load_planning_scene", "plan_request"):
        assert getattr(taskrunner.Workcell, method).__doc__, f"Workcell.{method} has no docstring"


def test_import_taskrunner_loads_no_heavy_module():
    code = ("import sys, taskrunner; heavy = [m for m in ('numpy', 'pinocchio', 'pydantic', "
            "'ompl', 'toppra', 'py_trees') if m in sys.modules]; print(heavy)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "[]"


@pytest.fixture(scope="module")
def table():
    with taskrunner.load_workcell("servo_arm_table") as cell:
        yield cell


@pytest.fixture()
def cell(table):
    """The servo arm cell on a fresh mock backend, at the cell's start state."""
    table.connect("mock")
    return table


def test_a_workcell_loads_from_a_shipped_name_a_path_or_a_robot(table):
    assert table.name == "servo_arm_table"
    assert table.groups == ("arm", "gripper")
    assert {"home", "Candle", "PickUp", "ready"} <= set(table.named_poses("arm"))
    by_path = taskrunner.load_workcell(table.path)
    assert by_path.joint_names == table.joint_names
    robot = taskrunner.load_workcell("servo_arm")
    assert robot.name == "servo_arm" and robot.path is not None and robot.path.is_dir()
    with pytest.raises(InputError, match="no such file, cell or robot"):
        taskrunner.load_workcell("no_such_cell")


def test_a_moveit_config_package_loads_and_plans():
    package = Path(__file__).parent / "robot" / "fixtures" / "ws" / "src" / "mini_moveit_config"
    mini = taskrunner.load_workcell(package)
    assert mini.name == "mini" and "arm" in mini.groups
    plan = mini.plan("arm", to="home")
    assert plan.duration > 0 and plan.trajectory.names == mini.model.group("arm").joint_names


def test_plan_to_a_named_pose_is_timed_and_executes_on_the_mock(cell):
    plan = cell.plan("arm", to="PickUp", velocity_scaling=1.0)
    assert plan.group == "arm" and plan.fraction == 1.0 and plan.complete
    assert plan.path.names == plan.trajectory.names == cell.model.group("arm").joint_names
    np.testing.assert_allclose(plan.start.positions, cell.joint_state().positions)
    pickup = cell.model.named_state("arm", "PickUp").as_dict()
    np.testing.assert_allclose([plan.end.as_dict()[n] for n in pickup], list(pickup.values()),
                               atol=1e-9)
    handle = cell.execute(plan)
    assert handle.result is not None and handle.result.status == "succeeded"
    state = cell.joint_state().as_dict()
    assert all(abs(state[n] - v) < 1e-9 for n, v in pickup.items())
    assert cell.backend is not None
    assert cell.backend.joint_state().as_dict() == state


def test_plans_are_seeded_and_a_slower_scaling_takes_longer(cell):
    a = cell.plan("arm", joints={"Revolute 1": 0.6}, seed=3, velocity_scaling=1.0,
                  acceleration_scaling=1.0)
    b = cell.plan("arm", joints={"Revolute 1": 0.6}, seed=3, velocity_scaling=1.0,
                  acceleration_scaling=1.0)
    np.testing.assert_array_equal(a.path.waypoints, b.path.waypoints)
    slow = cell.plan("arm", joints={"Revolute 1": 0.6}, seed=3, velocity_scaling=0.25,
                     acceleration_scaling=0.25)
    assert slow.duration > a.duration
    assert cell.time_path(a, velocity_scaling=0.25, acceleration_scaling=0.25).duration \
        == pytest.approx(slow.duration, rel=1e-6)


def test_plan_to_a_position_on_the_position_only_arm_and_to_a_pose(cell):
    target = (0.15, 0.0, 0.9)
    plan = cell.plan("arm", position=target)
    reached = cell.link_pose(cell.model.group("arm").tip_link, plan.end)
    np.testing.assert_allclose(reached.xyz, target, atol=1e-3)
    as_pose = cell.plan("arm", pose=Pose(target), start=plan.start)  # position-only IK
    np.testing.assert_allclose(
        cell.link_pose(cell.model.group("arm").tip_link, as_pose.end).xyz, target, atol=1e-3)


def test_plan_chains_from_a_start_and_needs_exactly_one_target(cell):
    first = cell.plan("arm", to="ready")
    second = cell.plan("arm", to="home", start=first.end)
    np.testing.assert_allclose(second.start.positions, first.end.positions)
    with pytest.raises(ValueError, match="exactly one of 'to', 'joints', 'pose' or 'position'"):
        cell.plan("arm", to="home", joints={"Revolute 1": 0.0})
    with pytest.raises(UnknownNameError, match="'hme'"):
        cell.plan("arm", to="hme")


def test_a_cartesian_path_reports_the_fraction_achieved(cell):
    cell.execute(cell.plan("arm", to="PickUp"))
    tip = cell.model.group("arm").tip_link
    before = cell.link_pose(tip).xyz
    up = cell.plan_cartesian("arm", by=(0.0, 0.0, 0.03), frame="world")
    assert up.fraction == 1.0 and up.message == ""
    cell.execute(up)
    np.testing.assert_allclose(cell.link_pose(tip).xyz, np.add(before, (0, 0, 0.03)), atol=1e-4)
    # Straight down through the table: cut short at the collision, never raised.
    down = cell.plan_cartesian("arm", [(before[0], before[1], 0.70)])
    assert 0.0 < down.fraction < 1.0 and not down.complete
    assert "collision" in down.message and "table" in down.message
    cell.execute(down)  # the part achieved is timed and executable


def test_execute_refuses_a_trajectory_that_does_not_start_where_the_arm_is(cell):
    plan = cell.plan("arm", to="ready")
    cell.execute(cell.plan("arm", to="PickUp"))
    with pytest.raises(BackendError):
        cell.execute(plan)


def test_run_a_shipped_task_by_name_with_parameters(tmp_path, monkeypatch):
    import taskrunner.workcell as workcell

    loads = []
    real_load = workcell.load_task
    monkeypatch.setattr(workcell, "load_task", lambda *a: loads.append(a) or real_load(*a))
    seen = []
    result = taskrunner.run_task("pick_place", parameters={"place_y": -0.1}, seed=1,
                                 runs_dir=tmp_path, on_event=seen.append)
    assert result.ok and result.status == "succeeded" and result.exit_code == 0
    assert result.error is None and result.duration > 0
    assert [e.seq for e in result.events] == list(range(1, len(result.events) + 1))
    assert seen == list(result.events)
    assert result.events[0].kind == "run_started" and result.events[-1].kind == "run_finished"
    saved = json.loads((tmp_path / f"{result.run_id}.json").read_text())
    assert saved["status"] == "succeeded" and saved["parameters"]["place_y"] == -0.1
    assert len(loads) == 1  # the task file is read once, though it also names the cell


def test_a_task_file_of_another_cell_is_refused(cell):
    with pytest.raises(InputError, match="written for cell"):
        cell.run_task("handoff")


def build_pick_place(place_y: float = -0.12) -> Task:
    return Task("py_pick_place", cell="servo_arm_table", objects=[
        Object("cube", "box", size=(0.025, 0.025, 0.025), at=(0.19, 0.04, 0.7625)),
    ], steps=[
        Gripper("arm", "open"),
        Go("arm", "home"),
        Pick("arm", "cube", approach=0.04),
        Place("arm", "cube", at=(0.14, place_y, 0.7635), approach=0.04),
        Sequence(Go("arm", "home"), Wait(0.0)),
    ])


def test_a_task_built_from_steps_runs_and_its_events_name_the_python_lines(cell):
    task = build_pick_place()
    run = cell.start_task(task)
    events = list(run.events(timeout=60))
    result = run.wait()
    assert result.ok, result.error
    assert events == list(result.events)
    places = {e.location for e in events if e.node and e.node.startswith("place cube")}
    assert len(places) == 1 and places.pop().startswith(f"{__file__}:")
    assert result.record.task_text.startswith("{")  # the task as task-file text
    home = cell.model.named_state("arm", "home").as_dict()
    state = cell.joint_state().as_dict()  # the workcell follows the backend
    assert all(abs(state[n] - v) < 1e-6 for n, v in home.items())


def test_a_python_task_runs_in_its_own_cell_too():
    result = taskrunner.run_task(build_pick_place(place_y=-0.08), seed=2)
    assert result.ok, result.error


def test_a_step_built_wrong_fails_at_its_python_line():
    line = sys._getframe().f_lineno + 2
    with pytest.raises(TaskSpecError) as caught:
        Go("arm")
    assert caught.value.path is not None and str(caught.value.path) == __file__
    assert caught.value.line == line
    assert "'go' needs one of 'to', 'joints' or 'pose'" in str(caught.value)
    with pytest.raises(TaskSpecError, match="'pick.approach' must be >= 0"):
        Pick("arm", "cube", approach=-0.01)
    with pytest.raises(TaskSpecError, match="'parallel' needs at least 2 steps"):
        Parallel(Go("arm", "home"))
    with pytest.raises(TaskSpecError, match="'sequence' step 1 must be a step"):
        Sequence("go home")  # type: ignore[arg-type]


def test_a_name_the_cell_lacks_fails_before_anything_moves_at_the_steps_line(cell):
    bad = Go("armm", "home"); line = sys._getframe().f_lineno  # noqa: E702
    before = cell.joint_state()
    with pytest.raises(TaskSpecError) as caught:
        cell.run_task(Task("bad", [Go("arm", "ready"), bad]))
    assert caught.value.line == line
    assert "group 'armm' is not a group of cell 'servo_arm_table'; did you mean 'arm'?" \
        in str(caught.value)
    np.testing.assert_array_equal(cell.joint_state().positions, before.positions)


def test_a_failed_run_is_a_result_naming_the_step(cell):
    unreachable = Go("arm", pose=(1.5, 0.0, 1.0)); line = sys._getframe().f_lineno  # noqa: E702
    result = cell.run_task(Task("far", [unreachable]))
    assert result.status == "failed" and result.exit_code == 3 and not result.ok
    assert result.error is not None and result.error.startswith(f"{__file__}:{line}:")


def test_a_run_can_be_cancelled_from_another_thread(cell):
    cell.connect("mock", speed=1.0)  # real time: the first motion takes seconds
    run = cell.start_task(Task("slow", [Go("arm", "Candle"), Go("arm", "home")]))
    for event in run.events(timeout=30):
        if event.kind == "planned":
            run.cancel()
    result = run.wait(timeout=30)
    assert result.status == "cancelled" and result.exit_code == 130


def test_errors_share_one_base_class():
    assert issubclass(TaskSpecError, TaskrunnerError)
    assert issubclass(BackendError, TaskrunnerError)


@pytest.mark.parametrize("example", ["pick_place.py", "handoff.py", "teach_and_expect.py"])
def test_the_examples_run_from_another_folder(example, tmp_path):
    script = Path(__file__).resolve().parent.parent / "examples" / example
    done = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    assert ": succeeded in " in done.stdout


def test_go_plans_and_executes_from_where_the_arm_is(cell):
    plan = cell.go("arm", to="ready", seed=1)
    assert isinstance(plan, taskrunner.Plan) and plan.group == "arm"
    ready = cell.model.named_state("arm", "ready").as_dict()
    state = cell.joint_state().as_dict()
    assert all(abs(state[n] - v) < 1e-9 for n, v in ready.items())
    assert cell.backend_kind is taskrunner.BackendKind.MOCK
    with pytest.raises(UnknownNameError, match="'hme'"):
        cell.go("arm", to="hme")
    assert cell.joint_state().as_dict() == state  # a failed plan moves nothing


def test_connect_takes_every_backend_kind_and_names_them_when_wrong(table):
    assert isinstance(table.connect(taskrunner.BackendKind.SIM, speed=50.0), taskrunner.Backend)
    assert table.backend_kind == "sim"
    with pytest.raises(ArgumentError, match="'kind' must be one of mock, sim, mujoco, serial, "
                                            r"http, feetech \(got 'nope'\)"):
        table.connect("nope")
    table.close()
    assert table.backend is None and table.backend_kind is None
    with pytest.warns(DeprecationWarning, match=r"Workcell.close\(\)"):
        table.disconnect()


def test_a_taught_pose_is_stored_where_the_command_line_reads_it(cell, tmp_path):
    cell.go("arm", to="PickUp")
    pose = cell.teach("arm", "over_cube", data_dir=tmp_path)
    pickup = cell.model.named_state("arm", "PickUp").as_dict()
    assert isinstance(pose, taskrunner.TaughtPose) and pose.group == "arm"
    assert pose.joints == pytest.approx(pickup)
    assert "over_cube" in cell.named_poses("arm")  # usable at once
    # What run-task --data-dir reads: the API's table, keyed by the cell's id.
    poses = read_taught_poses(tmp_path / "runs.sqlite", Path(cell.path).parent)
    assert [p.name for p in poses.of(Path(cell.path))] == ["over_cube"]
    fresh = taskrunner.load_workcell("servo_arm_table")
    assert "over_cube" not in fresh.named_poses("arm")  # applied explicitly, not ambiently
    added = fresh.load_taught_poses(data_dir=tmp_path)
    assert [(p.group, p.name) for p in added] == [("arm", "over_cube")]
    assert fresh.plan("arm", to="over_cube").end.as_dict()["Revolute 1"] \
        == pytest.approx(pickup["Revolute 1"])
    bent = cell.teach("arm", "over_cube", {"Revolute 1": 0.3}, data_dir=tmp_path)  # retaught
    assert bent.joints["Revolute 1"] == 0.3
    assert fresh.load_taught_poses(data_dir=tmp_path)[0].joints["Revolute 1"] == 0.3
    assert fresh.model.named_state("arm", "over_cube").as_dict()["Revolute 1"] == 0.3


def test_teaching_refuses_the_robot_files_names_bad_names_and_limits(cell, tmp_path):
    with pytest.raises(ArgumentError, match="'home' of group 'arm' comes from the robot"):
        cell.teach("arm", "home", data_dir=tmp_path)
    with pytest.raises(ArgumentError, match="'name' must be a letter"):
        cell.teach("arm", "9 lives", data_dir=tmp_path)
    with pytest.raises(ArgumentError, match="outside the joint limits"):
        cell.teach("arm", "too_far", {"Revolute 1": 40.0}, data_dir=tmp_path)
    with pytest.raises(UnknownNameError, match="'Revolute 9'"):
        cell.teach("arm", "odd", {"Revolute 9": 0.0}, data_dir=tmp_path)
    assert not (tmp_path / "runs.sqlite").exists()  # nothing stored


def test_expect_steps_and_the_tasks_end_are_checked(cell):
    held = Expect(objects={"cube": {"held_by": "arm"}}, step_duration=30)
    task = Task("expecting", objects=[
        Object("cube", "box", size=(0.025, 0.025, 0.025), at=(0.19, 0.04, 0.7625))],
        steps=[Gripper("arm", "open"), Go("arm", "home"), Pick("arm", "cube", approach=0.04),
               held, Place("arm", "cube", at=(0.14, -0.12, 0.7635), approach=0.04),
               Go("arm", "home")],
        expect=Expect(objects={"cube": {"pose": Pose((0.14, -0.12, 0.7625)),
                                        "released": True}},
                      groups={"arm": {"at": "home"}}, duration={"max": 120}))
    result = cell.run_task(task)
    assert result.ok, result.error
    expectation = task.spec(cell.cell).expect
    assert expectation is not None and expectation.groups["arm"].at == "home"
    assert '"held_by": "arm"' in result.record.task_text  # the step, as task-file text


def test_a_missed_expectation_fails_the_run_at_the_expect_line(cell):
    wrong = Expect(groups={"arm": {"at": "ready"}}); line = sys._getframe().f_lineno  # noqa: E702
    result = cell.run_task(Task("missed", [Go("arm", "home"), wrong]))
    assert result.status == "failed" and result.exit_code == 4
    assert result.error is not None and result.error.startswith(f"{__file__}:{line}:")


def test_an_expect_built_wrong_fails_at_its_python_line():
    line = sys._getframe().f_lineno + 2
    with pytest.raises(TaskSpecError) as caught:
        Expect()
    assert caught.value.line == line and "needs at least one of 'objects'" in str(caught.value)
    with pytest.raises(TaskSpecError, match="takes 'error' only with status: failed"):
        Expect(error="unreachable")
    with pytest.raises(TaskSpecError, match=r"'expect.duration.max' must be > 0 \(got -1.0\)"):
        Expect(duration=-1.0)
    end = Expect(status="failed", error="unreachable")  # a task's end may say only that
    assert end.as_task_expectation().status == "failed"
    with pytest.raises(TaskSpecError, match="'status' and 'error' are for a task's end"):
        Task("t", [Go("arm", "home"), end]).spec(taskrunner.load_workcell("servo_arm").cell)
