"""expect: in task files: checked in the run, reported at file:line, known to the checker."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

import taskrunner
from taskrunner import resources
from taskrunner.errors import TaskSpecError
from taskrunner.scene import Scene
from taskrunner.shapes import Box
from taskrunner.tasks import load_and_check, load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.context import ExecutedMotion
from taskrunner.tree.expect import motion_collisions
from taskrunner.types import Pose

CELL = resources.robots_dir() / "cells" / "servo_arm_table.yaml"

PICK_PLACE = """\
task: expect_demo
cell: {cell}
parameters:
  place_y: {{default: -0.12, type: float}}
objects:
  - {{name: cube, shape: box, size: [0.025, 0.025, 0.025], pose: {{xyz: [0.19, 0.04, 0.7625]}}}}
steps:
  - go: {{group: arm, to: home}}
  - pick: {{arm: arm, object: cube, grasp: top, approach: 0.04, retreat: 0.05}}
  - expect:
      objects: {{cube: {{held_by: {held}}}}}
      step_duration: {{max: {step_max}}}
  - place: {{arm: arm, object: cube, at: {{xyz: [0.14, "${{place_y}}", 0.7635]}}, orientation: yaw, approach: 0.04, retreat: 0.05}}
  - go: {{group: arm, to: home}}
expect:
  objects:
    cube: {{pose: {{xyz: [0.14, {end_y}, 0.7635]}}, orientation: yaw, released: true, on: table}}
  groups:
    arm: {{at: {end_pose}}}
  duration: {{max: 30}}
  collision_free: true
"""


def write(tmp_path: Path, text: str, name: str = "task.yaml") -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


def demo(tmp_path: Path, held: str = "arm", step_max: float = 20, end_y: float = -0.12,
         end_pose: str = "home") -> Path:
    return write(tmp_path, PICK_PLACE.format(cell=CELL, held=held, step_max=step_max,
                                             end_y=end_y, end_pose=end_pose))


def expectations(result: taskrunner.RunResult) -> dict:
    found = [e.data["expectations"] for e in result.events if "expectations" in e.data]
    assert len(found) == 1
    return found[0]


def test_met_expectations_let_the_run_succeed(tmp_path: Path):
    result = taskrunner.run_task(demo(tmp_path))
    assert result.status == "succeeded", result.error
    assert expectations(result)["met"] is True and expectations(result)["failures"] == []
    assert any(e.message == "expectations met" and e.location and e.location.endswith(":10")
               for e in result.events)


def test_missed_end_expectations_fail_the_run_with_expected_and_observed(tmp_path: Path):
    path = demo(tmp_path, end_y=-0.11, end_pose="Candle")
    result = taskrunner.run_task(path)
    assert result.status == "failed" and result.exit_code == 4
    error = result.error or ""
    assert error.startswith(f"{path}:16: expectation not met: ")
    assert "'cube' ended 10.0 mm from its target position" in error or "mm from" in error
    assert "expected xyz (0.1400, -0.1100, 0.7635)" in error
    assert "observed xyz (0.1400, -0.1200" in error
    assert "group 'arm' expected at 'Candle'" in error and "observed 0.8000" in error
    assert expectations(result)["met"] is False


def test_a_missed_step_expectation_fails_at_its_line(tmp_path: Path):
    path = demo(tmp_path, held="base_link", step_max=1)
    result = taskrunner.run_task(path, parameters=None)
    assert result.status == "failed" and result.exit_code == 4
    error = result.error or ""
    assert error.startswith(f"{path}:10: expectation not met: ")
    assert "'cube' expected held by 'base_link'" in error and "observed attached to 'tool0'" in error
    assert "the step's duration expected at most 1 s; observed" in error
    # The place never ran: the cube is still held.
    assert not any(e.node and e.node.startswith("place") for e in result.events)


def test_an_expected_failure_is_met_when_the_error_matches(tmp_path: Path):
    text = f"""\
    task: unreachable
    cell: {CELL}
    steps:
      - go: {{group: arm, pose: {{xyz: [2.0, 0.0, 0.8]}}}}
    expect:
      status: failed
      error: "{{error}}"
      groups: {{arm: {{joints: {{"Revolute 1": 0.8}}, tolerance: 0.05}}}}
    """
    met = taskrunner.run_task(write(tmp_path, text.replace("{error}", "task.yaml:4")))
    assert met.status == "failed"
    assert expectations(met)["met"] is True and expectations(met)["failures"] == []
    missed = taskrunner.run_task(write(tmp_path, text.replace("{error}", "no such text")))
    assert expectations(missed)["met"] is False
    assert "expected the run's error to contain 'no such text'" in expectations(missed)[
        "failures"][0]


def test_a_run_expected_to_fail_that_succeeds_fails(tmp_path: Path):
    path = write(tmp_path, f"""\
    task: home
    cell: {CELL}
    steps:
      - go: {{group: arm, to: home}}
    expect: {{status: failed}}
    """)
    result = taskrunner.run_task(path)
    assert result.status == "failed" and result.exit_code == 4
    assert result.error == (f"{path}:5: expectation not met: expected the run to have "
                            "failed; it succeeded")


def test_collision_free_finds_a_motion_through_an_obstacle(tmp_path: Path):
    path = write(tmp_path, f"""\
    task: wave
    cell: {CELL}
    steps:
      - go: {{group: arm, to: Candle}}
      - go: {{group: arm, to: home}}
    """)
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.robot.cell import load_cell
    from taskrunner.runtime.runner import Runner
    from taskrunner.runtime.session import make_backend

    spec = load_task(path)
    cell = load_cell(spec.cell)
    runner = Runner(spec, cell, make_backend("mock", cell, None), InProcessPlanner())
    assert runner.run().status == "succeeded"
    ctx = runner.ctx
    assert motion_collisions(ctx) == []
    # The same motion, had a block stood where the arm passes.
    first = ctx.executed[0]
    scene = Scene.from_snapshot(cell.model, first.scene)
    scene.set_state(dict(zip(first.trajectory.names, first.trajectory.positions[-1])))
    tip = scene.link_pose("gripper_base_1").xyz
    scene.set_state(first.scene.state)
    scene.add_object("block", Box((0.06, 0.06, 0.06)), Pose(tuple(tip)))
    ctx.executed[0] = ExecutedMotion(first.node, first.location, first.trajectory,
                                     scene.snapshot())
    found = motion_collisions(ctx)
    assert len(found) == 1
    assert found[0].startswith(f"motion 'go arm' ({path}:4) collides: ")
    assert " and block at " in found[0] and "s of its trajectory" in found[0]


def test_check_reports_expectations_that_can_never_hold(tmp_path: Path):
    path = write(tmp_path, f"""\
    task: bad
    cell: {CELL}
    objects:
      - {{name: cube, shape: box, size: [0.025, 0.025, 0.025], pose: {{xyz: [0.19, 0.04, 0.7625]}}}}
    steps:
      - expect: {{step_duration: {{max: 1}}}}
      - go: {{group: arm, to: home}}
      - expect:
          objects: {{cub: {{released: true}}}}
      - remove_object: {{name: cube}}
    expect:
      objects:
        cube: {{held_by: arms}}
        table: {{pose: {{xyz: [0, 0, 0], frame: bogus}}, on: tabel}}
      groups:
        arm: {{at: hom}}
        gripper: {{joints: {{"Revolute 1": 0.1}}}}
        amr: {{at: home}}
    """)
    _, _, problems = load_and_check(path)
    found = sorted((p.line, p.message) for p in problems)
    assert found == sorted([
        (6, "'step_duration' needs a step before this 'expect' in the same list"),
        (9, "object 'cub' is not in the scene; did you mean 'cube'?"),
        (12, "object 'cube' is not in the scene (removed at "
             f"{path}:10)"),
        (13, "'held_by': 'arms' is not an arm or a link of cell 'servo_arm_table'; did you "
             "mean 'arm'?"),
        (14, "frame 'bogus' is not 'world', a link of cell 'servo_arm_table' or an object"),
        (14, "object 'tabel' is not in the scene; did you mean 'table'?"),
        (16, "'hom' is not a named pose of group 'arm'; did you mean 'home'?"),
        (17, found_joint(found)),
        (15, "group 'amr' is not a group of cell 'servo_arm_table'; did you mean 'arm'?"),
    ])
    report = check_task(path)
    assert not report.ok


def found_joint(found: list[tuple[int, str]]) -> str:
    message = next(m for line, m in found if line == 17)
    assert message.startswith("joint 'Revolute 1' is not a joint of group 'gripper'")
    return message


@pytest.mark.parametrize(("body", "message"), [
    ("{}", "needs at least one of 'objects', 'groups', 'duration'"),
    ("{objects: {cube: {held_by: arm, released: true}}}", "takes only one of 'held_by' or"),
    ("{objects: {cube: {orientation: yaw, released: true}}}", "takes 'orientation' only with"),
    ("{groups: {arm: {at: home, joints: {a: 1}}}}", "needs exactly one of 'at' or 'joints'"),
    ("{duration: {min: 5, max: 1}}", "'min' must be <= 'max' (got 5.0 > 1.0)"),
    ("{collision_free: false}", "collision_free"),
])
def test_malformed_expectations_are_refused_at_their_line(tmp_path: Path, body: str,
                                                          message: str):
    path = write(tmp_path, f"""\
    task: bad
    cell: {CELL}
    steps:
      - go: {{group: arm, to: home}}
      - expect: {body}
    """)
    with pytest.raises(TaskSpecError) as info:
        load_task(path)
    assert f"{path.name}:5" in str(info.value) or f"{path}:5" in str(info.value)
    assert message in str(info.value)


def test_motion_time_counts_only_the_time_a_motion_ran(tmp_path: Path):
    text = demo(tmp_path).read_text().replace("  duration: {max: 30}\n",
                                              "  motion_time: {max: 0.5}\n")
    path = write(tmp_path, text, "short.yaml")
    result = taskrunner.run_task(path, backend="mock")
    assert result.status == "failed" and result.exit_code == 4
    finished = next(e for e in result.events if e.kind == "run_finished")
    moving, total = finished.data["motion_time"], finished.data["task_time"]
    planned = sum(e.data["trajectory"]["times"][-1] for e in result.events
                  if e.kind == "motion")
    assert moving == pytest.approx(planned, abs=1e-3)  # one arm: its motions, end to end
    assert 0 < moving < total  # the planning is task time, not motion time
    assert (f"the run's motion time expected at most 0.5 s; observed {moving:.3f} s (task "
            "time while a motion ran)") in (result.error or "")
    met = write(tmp_path, text.replace("{max: 0.5}", f"{{min: {moving - 0.1:.3f}}}"), "ok.yaml")
    assert taskrunner.run_task(met, backend="mock").status == "succeeded"
