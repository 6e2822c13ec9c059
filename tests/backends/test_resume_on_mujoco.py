"""Resuming pick_place_panda, handoff and stack on the mujoco backend after faults, end
to end, each at three points: during a motion, with the object held, during a place.

One story per task (module-scoped, shared by its tests): the run is stopped by a fault
(the backend stops every motion half-way through the motion of a point's step), resumed
in the same process (``TaskRun.resume``), where the simulated world went on and says
whether the object is still held, stopped again at the next point, and so on; the last
continuation ends with every expectation of the task met (objects at their places within
their tolerances, released, on what they should be on). Each point's test reads its stop
and its continuation from the story.

A new process (``run-task resume``) starts a new simulated world, which is no evidence:
it is made the run's (its objects where the last checkpoint has them: a stacked cube on
the stack), and resuming is refused until the operator says ``--held cube``; then the new
world puts the cube back between the fingers where the scene holds it, closes them on it,
and the task ends as the first would have (pick_place_panda, and handoff and stack
stopped mid-place). Fingers that do not close on it are refused, saying what to do.

Cost on a loaded 2-core machine (the stories are most of it, built once each): about 5 s
for pick_place_panda, 4 s for handoff, 4 s for stack; the new-process tests 5 s.
Skipped where mujoco is not installed (``pip install -e '.[mujoco]'``).
"""

from __future__ import annotations

import re
import threading
import time
from pathlib import Path

import numpy as np
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

# Per task, where it is stopped (the step whose motion is cut half-way) and what is held
# there, by which arm.
POINTS: dict[str, tuple[tuple[str, tuple[str, str] | None], ...]] = {
    "pick_place_panda": (("pick cube: approach", None),                 # during a motion
                         ("place cube: to pre-place", ("cube", "arm")),  # the cube held
                         ("place cube: descend", ("cube", "arm"))),      # during the place
    "handoff": (("pick bar: approach", None),
                ("handoff bar: left_arm presents", ("bar", "left_arm")),
                ("place bar: descend", ("bar", "right_arm"))),
    "stack": (("place cube_b: to pre-place", ("cube_b", "arm")),
              ("pick cube_c: approach", None),
              ("place cube_c: descend", ("cube_c", "arm"))),
}


STORY_SPEED = 4.0  # the stories' physics, times real time (a half motion: >= 60 ms)


class Fault:
    """Stops every motion of ``backend`` half-way through the motion of the next point's
    step (by the physics' clock, which runs only while something moves): the run fails in
    the middle of that step, the arm part of the way."""

    def __init__(self, backend: MujocoBackend, nodes: list[str]) -> None:
        self.backend = backend
        self.pending = list(nodes)

    def __call__(self, event) -> None:
        if event.kind == "motion" and self.pending and event.node == self.pending[0]:
            self.pending.pop(0)
            halfway = self.backend.sim_time + 0.5 * event.data["trajectory"]["times"][-1]
            threading.Thread(target=self._stop_at, args=(halfway,), daemon=True).start()

    def _stop_at(self, sim_time: float) -> None:
        deadline = time.monotonic() + 60.0  # a motion that ends early leaves the stop undone
        while self.backend.sim_time < sim_time and time.monotonic() < deadline:
            time.sleep(0.001)
        self.backend.stop()


@pytest.fixture(scope="module", params=list(POINTS))
def story(request, tmp_path_factory) -> tuple[str, list[RunResult], Path]:
    """A task's run and its continuations on one simulated world; the runs' folder."""
    task = request.param
    runs = tmp_path_factory.mktemp(f"runs_{task}")
    spec = load_task(resolve_task(task), {})
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    # Paced at STORY_SPEED times real time: unpaced, the physics runs a short motion's
    # second half in a few ms, and on a loaded machine the fault's thread woke after it.
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(runs / "cache"), speed=STORY_SPEED))
    fault = Fault(backend, [node for node, _ in POINTS[task]])
    try:
        run = start_run(spec, cell, backend, seed=1, backend_name="mujoco", runs_dir=runs,
                        on_event=fault)
        results = [run.wait(120)]
        while not results[-1].ok and len(results) <= len(POINTS[task]):
            run = run.resume(on_event=fault)
            results.append(run.wait(120))
    finally:
        backend.close()
    return task, results, runs


def messages(result: RunResult) -> list[str]:
    return [e.message for e in result.events if e.kind == "message"]


@pytest.mark.parametrize("point", range(3), ids=["mid-motion", "held", "mid-place"])
def test_a_run_stopped_at_a_point_on_mujoco_resumes_where_it_stopped(story, point):
    task, results, _ = story
    node, held = POINTS[task][point]
    assert len(results) > point + 1, [r.error for r in results]
    stopped, then = results[point], results[point + 1]
    assert stopped.status == "failed"
    assert "execution failed" in (stopped.error or ""), stopped.error
    assert [e.node for e in stopped.events if e.kind == "node_started"][-1] == node
    assert then.record.resumes == stopped.run_id
    # The leaf that did not finish runs again first, nothing before it, planned from
    # where the arm stopped (half-way).
    assert [e.node for e in then.events if e.kind == "node_started"][0] == node
    cut = [e for e in stopped.events if e.kind == "motion"][-1].data["trajectory"]
    again = next(e for e in then.events if e.kind == "motion").data["trajectory"]
    assert again["joints"] == cut["joints"]
    stop = next(e for e in stopped.events if e.kind == "run_finished").data["scene"]["joints"]
    restart = np.array(again["positions"][0])
    assert np.abs(restart - [stop[n] for n in again["joints"]]).max() < 0.005
    assert np.abs(restart - cut["positions"][0]).max() > 0.01, "stopped before it moved"
    if held is not None:  # stopped with it in the gripper: the physics says it still is
        obj, arm = held
        assert any(f"{obj!r} still held by {arm!r} (the simulated world has it" in m
                   for m in messages(then)), messages(then)


def test_the_last_continuation_on_mujoco_meets_every_expectation(story):
    task, results, _ = story
    assert [r.status for r in results] == ["failed", "failed", "failed", "succeeded"], \
        [r.error for r in results]
    verdict = next(m for m in messages(results[-1]) if m.startswith("expectations met"))
    # The task's duration (handoff's: its motion time) is the story's: the four runs'
    # summed.
    said = ("motion_time: .* s over the 4 runs of the story" if task == "handoff" else
            "duration: .* s of task time over the 4 runs of the story")
    assert re.search(said, verdict), verdict


NEW_PROCESS = pytest.mark.parametrize("story", ["pick_place_panda"], indirect=True)


@NEW_PROCESS
def test_a_new_process_on_mujoco_needs_the_operator_to_say_where_the_cube_is(story, capsys):
    _, results, runs = story
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


@pytest.mark.parametrize("story", ["handoff", "stack"], indirect=True)
def test_a_new_process_on_mujoco_makes_the_world_the_runs_and_grips_the_held_object(
        story, capsys):
    task, results, runs = story
    node, (obj, _) = POINTS[task][2]  # stopped setting it down, the objects placed before
    stopped = runs / f"{results[2].run_id}.json"
    assert main(["resume", str(stopped), "--plain", "--in-process", "--runs-dir", str(runs),
                 "--held", obj]) == 0
    out = capsys.readouterr().out
    assert "objects put where the scene has them" in out  # cube_b on cube_a, not at its start
    assert f"{obj!r} put back in the grip of" in out and "(the operator says it is held)" in out
    assert f"▶ {node}" in out and "expectations met" in out, out


@NEW_PROCESS
def test_a_new_world_whose_fingers_do_not_close_on_the_cube_refuses_to_resume_it_held(story):
    _, results, runs = story
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
