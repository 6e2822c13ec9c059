"""Resuming pick_place_panda on the mujoco backend after a fault, end to end.

One run is stopped three times by a fault (the backend stops every motion as soon as a
step's motion is sent): reaching for the cube, carrying it, setting it down. Each time it
is resumed in the same process (``TaskRun.resume``), where the simulated world went on
and says whether the cube is still held; the last continuation ends with every
expectation of the task met (the cube at its place within 1 cm, released, on the table).
A new process (``run-task resume``) starts a new simulated world, which is no evidence:
it is refused until the operator says ``--held cube``; then the new world puts the cube
back between the fingers where the scene holds it, closes them on it, and the task ends as
the first would have. Fingers that do not close on it are refused, saying what to do.

Skipped where mujoco is not installed (``pip install -e '.[mujoco]'``).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from taskrunner.errors import InputError
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import resolve_task
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.records import load_record
from taskrunner.runtime.resume import ResumeOptions, plan_resume
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks.loader import load_task

pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install -e '.[mujoco]'")

from taskrunner.backends.physics import MujocoBackend, MujocoOptions, physics_cell
from taskrunner.cli import main
from taskrunner.taskrun import RunResult, start_run

FAULTS = (
    "pick cube: approach",       # during a motion, reaching for the cube
    "place cube: to pre-place",  # the cube held
    "place cube: descend",       # during the place
)


class Fault:
    """Stops every motion of ``backend`` once the motion of the next step of ``FAULTS``
    is sent (before the step can see it end): the run fails in the middle of that step."""

    def __init__(self, backend: MujocoBackend) -> None:
        self.backend = backend
        self.pending = list(FAULTS)

    def __call__(self, event) -> None:
        if event.kind == "motion" and self.pending and event.node == self.pending[0]:
            self.pending.pop(0)
            self.backend.stop()


@pytest.fixture(scope="module")
def story(tmp_path_factory) -> tuple[list[RunResult], Path]:
    """The run and its three continuations on one simulated world; and the runs' folder."""
    runs = tmp_path_factory.mktemp("runs")
    spec = load_task(resolve_task("pick_place_panda"), {})
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(runs / "cache")))
    fault = Fault(backend)
    try:
        run = start_run(spec, cell, backend, seed=1, backend_name="mujoco", runs_dir=runs,
                        on_event=fault)
        results = [run.wait(120)]
        while not results[-1].ok and len(results) <= len(FAULTS):
            run = run.resume(on_event=fault)
            results.append(run.wait(120))
    finally:
        backend.close()
    return results, runs


def messages(result: RunResult) -> list[str]:
    return [e.message for e in result.events if e.kind == "message"]


def test_a_run_stopped_three_times_on_mujoco_resumes_each_time_and_meets_its_expectations(
        story):
    results, _ = story
    assert [r.status for r in results] == ["failed", "failed", "failed", "succeeded"], \
        [r.error for r in results]
    for stopped, node in zip(results, FAULTS):
        assert "execution failed" in (stopped.error or ""), stopped.error
        assert [e.node for e in stopped.events if e.kind == "node_started"][-1] == node
    for first, then, node in zip(results, results[1:], FAULTS):
        assert then.record.resumes == first.run_id
        # The leaf that did not finish runs again first, nothing before it.
        assert [e.node for e in then.events if e.kind == "node_started"][0] == node
    # Stopped with the cube in the gripper: the physics says it is still there.
    for then in results[2:]:
        assert any("'cube' still held by 'arm' (the simulated world has it" in m
                   for m in messages(then)), messages(then)
    verdict = next(m for m in messages(results[-1]) if m.startswith("expectations met"))
    # The task's duration (max 60 s) is the story's: the four runs' task time summed.
    assert "of task time over the 4 runs of the story" in verdict


def test_a_new_process_on_mujoco_needs_the_operator_to_say_where_the_cube_is(story, capsys):
    results, runs = story
    held = runs / f"{results[1].run_id}.json"  # stopped carrying the cube
    assert load_record(held).status == "failed"
    args = ["resume", str(held), "--plain", "--in-process", "--runs-dir", str(runs)]
    assert main(args) == 2
    said = capsys.readouterr()
    assert "the mujoco backend cannot tell whether it still is: pass --held cube" \
        in said.out + said.err
    # Said held: the new world puts it back between the fingers, which close on it.
    assert main([*args, "--held", "cube"]) == 0
    out = capsys.readouterr().out
    assert "'cube' put back in the grip of 'panda_hand_tcp' and held" in out, out
    assert "expectations met" in out
    # Where it lies (back at its pick spot), and picked again: the task ends as planned.
    assert main([*args, "--object", "cube=0.5,0.15,0.77", "--from", "pick cube"]) == 0
    out = capsys.readouterr().out
    assert "'cube' no longer held by 'arm' (the operator says so)" in out
    assert "expectations met" in out


def test_a_new_world_whose_fingers_do_not_close_on_the_cube_refuses_to_resume_it_held(story):
    results, runs = story
    record = load_record(runs / f"{results[1].run_id}.json")  # stopped carrying the cube
    spec = load_task(record.task_file, record.parameters)
    plan = plan_resume(record, spec, ResumeOptions(held=("cube",)))
    cell = load_cell(spec.cell)
    # 'closed' 6 cm apart: the fingers stay off the 4 cm cube, which falls out of the hand.
    cell.model.named_states["hand"]["closed"] = {"panda_finger_joint1": 0.03}
    start = dict(zip(cell.model.joint_names, plan.start_state(cell)))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(runs / "cache")))
    try:
        with pytest.raises(InputError, match=r"'cube' said to be held, but the mujoco backend "
                                             r"could not grip it again \(.*(slipped|not touched)"
                                             r".*\); say where it lies with --object"):
            Runner(spec, cell, backend, InProcessPlanner(),
                   RunOptions(runs_dir=runs, backend_name="mujoco"), resume=plan)
    finally:
        backend.close()
