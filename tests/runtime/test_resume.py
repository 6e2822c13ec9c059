"""Resuming a stopped run from its record: pick_place, handoff and stack stopped by an
injected fault at several points (on sim, fast), a run killed with SIGKILL, refusals."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from taskrunner.backends.sim import SimBackend, SimOptions
from taskrunner.cli import main
from taskrunner.commands.resume import parse_object_pose
from taskrunner.errors import InputError
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.checkpoint import checkpoints_of, restore_scene, scene_state
from taskrunner.runtime.records import load_record
from taskrunner.runtime.resume import ResumeOptions, plan_resume
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.taskrun import start_run
from taskrunner.tasks import load_task
from taskrunner.tree.start import task_start

TASKS = DATA_ROOT / "tasks"
SPEED = 50.0  # sim: trajectory seconds per wall second


class FaultySim(SimBackend):
    """The sim, each motion held at its start until the run has emitted its "motion"
    event: a fault injected on that event (:meth:`fault_on`) always finds the motion
    running, however loaded the machine (at SPEED a short motion could otherwise end
    before its event is emitted, and the fault would stop nothing)."""

    def __init__(self, *args, **kwargs) -> None:
        self._holding = False
        super().__init__(*args, **kwargs)

    def execute(self, trajectory):
        self._holding = True
        try:
            return super().execute(trajectory)
        except BaseException:
            self._holding = False
            raise

    def _tick(self, now: float) -> None:
        if not self._holding:
            super()._tick(now)

    def fault_on(self, when):
        """An event callback: stops every motion at the first event for which
        ``when(event)`` is true (and each later one), then lets the held motion go."""
        def callback(event) -> None:
            if when(event):
                self.stop()
            if event.kind == "motion":
                self._holding = False
        return callback


def sim_runner(path: Path, runs_dir: Path, plan=None, start=None, fault=None):
    """A runner of ``path`` on a :class:`FaultySim`; ``fault(event)`` true: the backend
    stops every motion then."""
    spec = load_task(path, plan.record.parameters if plan is not None else None)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    q = start if start is not None else (plan.start_state(cell) if plan is not None
                                         else task_start(spec, cell).q)
    backend = FaultySim(names, dict(zip(names, q)), SimOptions(speed=SPEED))
    runner = Runner(spec, cell, backend, InProcessPlanner(),
                    RunOptions(seed=1, runs_dir=runs_dir, backend_name="sim"), resume=plan)
    runner.events.subscribe(backend.fault_on(fault or (lambda event: False)))
    return runner, backend


def run_with_fault(path: Path, runs_dir: Path, node: str) -> Path:
    """Run ``path`` on sim; once the motion of ``node`` is sent, the backend stops every
    motion (a servo fault, deterministic: before the step can see its motion end): the
    run fails in the middle of that step. The record's path."""
    runner, backend = sim_runner(
        path, runs_dir, fault=lambda event: event.kind == "motion" and event.node == node)
    try:
        record = runner.run()
    finally:
        backend.close()
    assert record.status == "failed", record.error
    assert record.error and "execution failed" in record.error
    return runs_dir / f"{record.run_id}.json"


def resume(record_path: Path, runs_dir: Path, options: ResumeOptions | None = None):
    record = load_record(record_path)
    spec = load_task(record.task_file, record.parameters)
    plan = plan_resume(record, spec, options)
    runner, backend = sim_runner(Path(record.task_file), runs_dir, plan)
    try:
        return record, runner.run(), runner
    finally:
        backend.close()


@pytest.mark.parametrize(("task", "node"), [
    ("pick_place", "pick cube: approach"),        # during a motion, reaching for the cube
    ("pick_place", "place cube: to pre-place"),   # with the object held
    ("handoff", "handoff bar: right_arm approaches"),  # between two arms, held by one
    ("stack", "place cube_c: descend"),           # the second cube, set on the first
])
def test_a_run_stopped_by_a_fault_resumes_where_it_stopped_and_meets_its_expectations(
        tmp_path, task, node):
    stopped = run_with_fault(TASKS / f"{task}.yaml", tmp_path, node)
    first, record, runner = resume(stopped, tmp_path)
    assert record.status == "succeeded", record.error
    assert runner.expectations_met is True
    assert record.resumes == first.run_id
    started = [e.node for e in record.events if e.kind == "node_started"]
    assert started[0] == node  # the leaf that did not finish runs again, nothing before it
    # The new record can be resumed in turn: it has its checkpoints, and the story so far
    # (the stopped run's task time and motion time, for duration and motion_time).
    assert checkpoints_of(record) and record.task_sha256 == first.task_sha256
    story = next(e.data["story"] for e in record.events
                 if e.kind == "message" and "story" in e.data)
    ended = next(e.data for e in first.events if e.kind == "run_finished")
    assert list(story["runs"]) == [first.run_id]
    assert story["task_time"] == pytest.approx(ended["task_time"])
    assert story["motion_time"] == pytest.approx(ended["motion_time"])
    assert 0 < story["motion_time"] < story["task_time"]


LOOPS = """\
task: loops
cell: {cell}
steps:
  - fallback:
      - go: {{group: arm, pose: {{xyz: [1.5, 0, 1.0]}}}}   # out of reach: fails
      - go: {{group: arm, to: home}}
  - repeat:
      times: 3
      do:
        - go: {{group: arm, to: Candle}}
        - go: {{group: arm, to: home}}
"""


def test_a_fallbacks_branch_and_a_repeats_round_are_where_the_run_left_them(tmp_path):
    path = tmp_path / "loops.yaml"
    path.write_text(LOOPS.format(cell=DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"))
    candles = []

    def fault(event):  # in the second round, on the way to Candle
        if event.kind == "motion" and event.location.endswith(":10"):
            candles.append(event)
            return len(candles) == 2
        return False

    runner, backend = sim_runner(path, tmp_path, fault=fault)
    try:
        first = runner.run()
    finally:
        backend.close()
    assert first.status == "failed"
    _, record, resumed = resume(tmp_path / f"{first.run_id}.json", tmp_path)
    assert record.status == "succeeded", record.error
    lines = [e.location.rsplit(":", 1)[1] for e in record.events if e.kind == "node_started"]
    assert lines == ["10", "11", "10", "11"]  # the rest of round 2, then round 3; no fallback
    points = checkpoints_of(record)
    replayed = [p for p in points if p.run_id is not None]  # the first run's, repeated
    assert {p.run_id for p in replayed} == {first.run_id} and points[:len(replayed)] == replayed
    own = points[len(replayed):]
    assert [p["repeat"] for p in own[0].position if "repeat" in p] == [1]
    assert [p["repeat"] for p in own[-1].position if "repeat" in p] == [2]


TIMED = """\
task: timed
cell: {cell}
steps:
  - fallback:
      - timeout:
          seconds: 0.2
          do:
            - go: {{group: arm, to: Candle}}   # longer than 0.2 s of task time: cut short
      - go: {{group: arm, to: home}}
  - go: {{name: last, group: arm, to: Candle}}
expect:
  duration: {{max: 600}}
  collision_free: true
"""


def test_a_timeout_that_fired_in_a_fallback_stays_fired_and_duration_counts_the_story(
        tmp_path):
    path = tmp_path / "timed.yaml"
    path.write_text(TIMED.format(cell=DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"))
    runner, backend = sim_runner(path, tmp_path,
                                 fault=lambda e: e.kind == "motion" and e.node == "last")
    try:
        first = runner.run()
    finally:
        backend.close()
    assert first.status == "failed"
    timed_out = [p for p in checkpoints_of(first) if p.cut]
    assert len(timed_out) == 1 and timed_out[0].status == "FAILURE"
    first_time = next(e.data["task_time"] for e in first.events if e.kind == "run_finished")
    _, record, resumed = resume(tmp_path / f"{first.run_id}.json", tmp_path)
    assert record.status == "succeeded", record.error
    # The fallback stays on its second branch: nothing of the first runs again.
    assert [e.node for e in record.events if e.kind == "node_started"] == ["last"]
    own = next(e.data["task_time"] for e in record.events if e.kind == "run_finished")
    verdict = next(e for e in record.events if e.kind == "message" and "expectations" in e.data)
    assert verdict.data["expectations"]["met"]
    assert f"duration: {first_time + own:.1f} s of task time over the 2 runs of the story " \
           f"({first_time:.1f} s before this one)" in verdict.message
    assert "collision_free: this run's 1 motions" in verdict.message


def test_taskrun_resume_continues_on_the_same_backend_from_where_the_arm_stopped(tmp_path):
    spec = load_task(TASKS / "pick_place.yaml")
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = FaultySim(names, dict(zip(names, task_start(spec, cell).q)),
                        SimOptions(speed=SPEED))
    # during a place, letting go of the cube
    fault = backend.fault_on(lambda e: e.kind == "motion" and e.node == "place cube: open")
    try:
        run = start_run(spec, cell, backend, backend_name="sim", runs_dir=tmp_path,
                        on_event=fault)
        first = run.wait(60)
        assert first.status == "failed"
        stopped_at = backend.joint_state().positions.copy()
        resumed = run.resume(on_event=backend.fault_on(lambda e: False)).wait(60)
    finally:
        backend.close()
    assert resumed.ok, resumed.error
    assert resumed.record.resumes == first.run_id
    assert resumed.events[0].data["scene"]["joints"] == pytest.approx(
        dict(zip(names, stopped_at.round(5))), abs=1e-5)
    assert [e.node for e in resumed.events if e.kind == "node_started"][0] == "place cube: open"


def test_a_run_killed_with_sigkill_mid_motion_resumes_from_its_journal(tmp_path, capsys):
    command = [sys.executable, "-m", "taskrunner.cli", "run", "pick_place", "--backend",
               "sim", "--speed", str(SPEED / 5), "--runs-dir", str(tmp_path), "--plain",
               "--in-process", "--no-check"]
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    journal = None
    deadline = time.monotonic() + 120
    try:
        while time.monotonic() < deadline and process.poll() is None:
            found = list(tmp_path.glob("*.events.jsonl"))
            if found:
                journal = found[0]
                kinds = [json.loads(line) for line in journal.read_text().splitlines()
                         if line.endswith("}")]
                if any(k.get("kind") == "motion" and k.get("node") == "pick cube: retreat"
                       for k in kinds):
                    os.kill(process.pid, signal.SIGKILL)  # mid-motion, the cube held
                    break
            time.sleep(0.02)
    finally:
        process.wait(30)
    assert process.returncode == -signal.SIGKILL, process.stderr.read()  # type: ignore[union-attr]
    assert journal is not None and load_record(journal).status == "interrupted"
    code = main(["resume", str(journal), "--plain", "--in-process", "--speed", str(SPEED)])
    out = capsys.readouterr().out
    assert code == 0, out
    assert "'cube' still held by 'arm'" in out
    finished = {e.node for e in load_record(journal).events
                if e.kind == "checkpoint" and e.status == "SUCCESS"}
    started = [line.split("▶ ", 1)[1].split("  (")[0] for line in out.splitlines()
               if "▶ " in line]
    assert "pick cube: approach" in finished and started[0] not in finished  # none again
    assert "expectations met" in out


@pytest.fixture(scope="module")
def held_record(tmp_path_factory) -> Path:
    """pick_place stopped by a fault while the arm carries the cube."""
    runs = tmp_path_factory.mktemp("runs")
    return run_with_fault(TASKS / "pick_place.yaml", runs, "place cube: to pre-place")


def test_a_resumed_run_stopped_again_resumes_from_its_own_record(held_record, tmp_path):
    record = load_record(held_record)
    plan = plan_resume(record, load_task(record.task_file, record.parameters))
    runner, backend = sim_runner(  # the second stop: setting the cube down
        Path(record.task_file), tmp_path, plan,
        fault=lambda e: e.kind == "motion" and e.node == "place cube: descend")
    try:
        second = runner.run()
    finally:
        backend.close()
    assert second.status == "failed" and second.resumes == record.run_id
    # Its record alone holds every finished leaf: the first run's, then its own.
    finished = [p.node for p in checkpoints_of(second)]
    assert finished[:len(checkpoints_of(record))] == [p.node for p in checkpoints_of(record)]
    assert finished[-1] == "place cube: descend"
    _, third, resumed = resume(tmp_path / f"{second.run_id}.json", tmp_path)
    assert third.status == "succeeded", third.error
    assert resumed.expectations_met is True and third.resumes == second.run_id
    assert [e.node for e in third.events if e.kind == "node_started"][0] == "place cube: descend"


def test_resuming_after_the_task_file_changed_is_refused_saying_what_to_do(tmp_path):
    text = (TASKS / "pick_place.yaml").read_text()
    path = tmp_path / "pick_place.yaml"
    path.write_text(text.replace("../robots/cells/", f"{DATA_ROOT}/robots/cells/"))
    stopped = run_with_fault(path, tmp_path, "pick cube: to pre-grasp")
    path.write_text(path.read_text().replace("retreat: 0.05}", "retreat: 0.06}", 1))
    with pytest.raises(InputError, match="changed since it ran; restore it as it was .* "
                                         "or run the task anew"):
        plan_resume(load_record(stopped), load_task(path))
    assert main(["resume", str(stopped), "--plain", "--in-process"]) == 2


def test_a_held_object_a_servo_backend_cannot_see_is_refused_naming_the_three_options(
        held_record):
    record = load_record(held_record)
    record.backend = "serial"  # a servo arm's gripper says nothing of the cube
    spec = load_task(record.task_file, record.parameters)
    plan = plan_resume(record, spec)
    with pytest.raises(InputError, match=r"'cube' was held by 'arm' .* cannot tell whether "
                                         r"it still is: pass --held cube .*--released cube"
                                         r".*--object cube="):
        sim_runner(Path(record.task_file), held_record.parent, plan)
    # Said by the operator: resumed (the scene keeps it in the gripper).
    confirmed = plan_resume(record, spec, ResumeOptions(held=("cube",)))
    runner, backend = sim_runner(Path(record.task_file), held_record.parent, confirmed)
    backend.close()
    assert runner.scene.object("cube").attached_to is not None
    assert any("still held by 'arm' (the operator says so)" in n for n in runner.resume_notes)


def test_the_operator_says_a_held_object_fell_and_the_place_fails_cleanly(held_record,
                                                                           tmp_path):
    fallen = ResumeOptions(objects={"cube": parse_object_pose("cube=0.2,0.0,0.7625")[1]})
    first, record, runner = resume(held_record, tmp_path, fallen)
    assert runner.scene.object("cube").attached_to is None
    assert record.status == "failed"
    assert "'cube' is not held by arm 'arm'" in (record.error or "")


def test_resuming_a_succeeded_run_or_an_unknown_object_is_refused(held_record, tmp_path):
    record = load_record(held_record)
    spec = load_task(record.task_file, record.parameters)
    with pytest.raises(InputError, match="no object 'cuboid'"):
        resume(held_record, tmp_path, ResumeOptions(released=("cuboid",)))
    record.status = "succeeded"
    with pytest.raises(InputError, match="it succeeded: there is nothing left to do"):
        plan_resume(record, spec)


def test_from_step_rewinds_to_a_step_the_run_reached_and_refuses_a_name_the_task_lacks(
        held_record):
    record = load_record(held_record)
    spec = load_task(record.task_file, record.parameters)
    plan = plan_resume(record, spec, ResumeOptions(from_step="pick cube"))
    assert [p.node for p in plan.replay] == ["go arm"]
    line = next(p.location for p in checkpoints_of(record) if p.node.startswith("pick"))
    by_line = plan_resume(record, spec, ResumeOptions(from_step=Path(line).name))
    assert [p.node for p in by_line.replay] == [p.node for p in plan.replay]
    with pytest.raises(InputError, match="--from 'go left': no step of that name or "
                                         "file:line at the task's top level"):
        plan_resume(record, spec, ResumeOptions(from_step="go left"))


def test_from_a_step_the_rest_is_checked_from_the_real_state_and_refused_on_a_problem(
        held_record, tmp_path):
    record = load_record(held_record)  # stopped carrying the cube
    spec = load_task(record.task_file, record.parameters)
    with pytest.raises(InputError, match=r"--from 'pick cube': the rest of the task does not "
                                         r"check from where the robot and the objects are now:"
                                         r" .*pick_place.yaml:\d+: pick cube: 'cube' is "
                                         r"already held"):
        sim_runner(Path(record.task_file), tmp_path,
                   plan_resume(record, spec, ResumeOptions(from_step="pick cube")))
    # The operator put it back where it was picked: checked, picked again, placed.
    back = ResumeOptions(objects=dict([parse_object_pose("cube=0.19,0.04,0.7625")]),
                         from_step="pick cube")
    _, resumed, runner = resume(held_record, tmp_path, back)
    assert resumed.status == "succeeded", resumed.error
    assert runner.expectations_met is True
    assert any("the rest of the task checked from where the robot and the objects are now"
               in n for n in runner.resume_notes)
    assert [e.node for e in resumed.events if e.kind == "node_started"][0] == "pick cube: open"


STEPS = """\
task: three
cell: {cell}
objects:
  - {{name: cube, shape: box, size: [0.025, 0.025, 0.025], pose: {{xyz: [0.19, 0.04, 0.7625]}}}}
steps:
  - go: {{name: first, group: arm, to: Candle}}
  - go: {{name: second, group: arm, to: home}}
  - go: {{name: third, group: arm, to: Candle}}
  - pick: {{arm: arm, object: cube, grasp: top, approach: 0.04, retreat: 0.05}}
"""


def test_from_a_step_not_reached_skips_to_it_when_the_rest_checks_from_the_real_state(
        tmp_path):
    path = tmp_path / "three.yaml"
    path.write_text(STEPS.format(cell=DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"))
    runner, backend = sim_runner(  # in the first step
        path, tmp_path, fault=lambda e: e.kind == "motion" and e.node == "first")
    try:
        first = runner.run()
    finally:
        backend.close()
    assert first.status == "failed"
    stopped = tmp_path / f"{first.run_id}.json"
    _, record, resumed = resume(stopped, tmp_path, ResumeOptions(from_step="third"))
    assert record.status == "succeeded", record.error
    assert [e.node for e in record.events if e.kind == "node_started"][0] == "third"
    points = checkpoints_of(record)
    assert [p.node for p in points if p.skipped] == ["first", "second"]
    assert any("2 leaves the run never finished skipped (first, second)" in n
               for n in resumed.resume_notes)
    # Skipping over the pick to an imagined place is refused by the check, with its reason.
    path.write_text(path.read_text() + "  - place: {arm: arm, object: cube, at: {xyz: "
                    "[0.14, -0.12, 0.7635]}, orientation: yaw}\n")
    changed = tmp_path / "four.yaml"
    changed.write_text(path.read_text().replace("task: three", "task: four"))
    runner, backend = sim_runner(
        changed, tmp_path, fault=lambda e: e.kind == "motion" and e.node == "first")
    try:
        first = runner.run()
    finally:
        backend.close()
    record = load_record(tmp_path / f"{first.run_id}.json")
    spec = load_task(changed)
    with pytest.raises(InputError, match=r"--from 'place cube': .*does not check .*: .*"
                                         r"arm 'arm' is not holding 'cube'"):
        sim_runner(changed, tmp_path, plan_resume(record, spec,
                                                  ResumeOptions(from_step="place cube")))


def test_a_checkpoint_scene_comes_back_exactly_with_attachments_and_reasons(held_record):
    record = load_record(held_record)
    point = checkpoints_of(record)[-1]
    assert point.held == {"cube": "arm"}
    assert [e["name"] for e in point.position] == ["pick_place", "place cube"]
    runner, backend = sim_runner(Path(record.task_file), held_record.parent)
    backend.close()
    restore_scene(runner.scene, point.scene)
    assert scene_state(runner.scene) == point.scene


def test_an_object_pose_is_three_or_seven_numbers():
    name, pose = parse_object_pose("cube=0.1,0.2,0.3,0,0,1,0")
    assert name == "cube" and pose.xyz == (0.1, 0.2, 0.3) and pose.quat == (0, 0, 1, 0)
    with pytest.raises(InputError, match=r"'--object' must be NAME=X,Y,Z .*\(got 'cube=1,2'\)"):
        parse_object_pose("cube=1,2")


class _SimulatedWorld(SimBackend):
    """A sim that reports objects as a physics backend does (ObjectTracking): where the
    test puts them."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.poses = {}

    def bind_scene(self, scene, materials=None):
        pass

    def object_poses(self):
        return dict(self.poses)

    def physics_report(self):
        return None


@pytest.mark.parametrize("dropped", [False, True])
def test_on_a_physics_backend_that_went_on_the_simulated_world_says_what_is_held(
        held_record, dropped):
    record = load_record(held_record)
    record.backend = "mujoco"
    spec = load_task(record.task_file, record.parameters)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    plan = plan_resume(record, spec, same_world=True)
    backend = _SimulatedWorld(names, dict(zip(names, plan.start_state(cell))),
                              SimOptions(speed=SPEED))
    vouched = plan_resume(record, spec, ResumeOptions(held=("cube",)))
    probe, probe_backend = sim_runner(Path(record.task_file), held_record.parent, vouched)
    probe_backend.close()
    held_at = probe.scene.object_pose("cube")  # where the gripper holds it
    on_table = parse_object_pose("cube=0.19,0.04,0.7625")[1]
    backend.poses = {"cube": on_table if dropped else held_at}
    try:
        runner = Runner(spec, cell, backend, InProcessPlanner(), RunOptions(backend_name="mujoco"),
                        resume=plan)
    finally:
        backend.close()
    cube = runner.scene.object("cube")
    if dropped:
        assert cube.attached_to is None and cube.pose.xyz == pytest.approx(on_table.xyz)
        assert any("no longer held by 'arm': the simulated world has it at (0.19, 0.04"
                   in n for n in runner.resume_notes)
    else:
        assert cube.attached_to is not None
        assert any("still held by 'arm' (the simulated world has it 0 mm" in n
                   for n in runner.resume_notes)
    with pytest.raises(InputError, match="the mujoco backend cannot tell whether it still is"):
        sim_runner(Path(record.task_file), held_record.parent,
                   plan_resume(record, spec))  # a new process: a new simulated world


def test_a_run_records_how_its_robots_were_loaded_and_resume_loads_them_so(tmp_path):
    import argparse

    from taskrunner.commands.resume import _load_options
    from taskrunner.robot.options import LoadOptions

    assert main(["run", "go_home", "--backend", "mock", "--in-process", "--plain",
                 "--no-check", "--runs-dir", str(tmp_path), "--collision", "exact"]) == 0
    record_path = next(tmp_path.glob("*.json"))
    record = load_record(record_path)
    assert record.load_options == LoadOptions(collision="exact").as_data()
    # Resumed without robot flags: as the run loaded them (the geometry it was checked
    # against); with a flag: as the command line says.
    plain = argparse.Namespace(load_options=LoadOptions())
    assert _load_options(plain, record, record_path) == LoadOptions(collision="exact")
    given = argparse.Namespace(load_options=LoadOptions(collision="convex"))
    assert _load_options(given, record, record_path) == LoadOptions(collision="convex")
    record.load_options = {"collision": "mesh"}
    with pytest.raises(InputError, match=f"run {record.run_id}: its load_options: "
                                         "'collision' must be one of"):
        _load_options(plain, record, record_path)
