"""A grasp whose closed fingers cannot touch the object is refused: by check, at the
task's file:line with the distance, and by the run's pick the same way."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import resolve_task
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.scene import scene_from_cell
from taskrunner.shapes import Box
from taskrunner.tasks.loader import load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.context import TaskContext
from taskrunner.tree.grasp_contact import finger_gaps, touching_grasps
from taskrunner.tree.grasps import grasp_candidates, tool_grasp
from taskrunner.types import Pose

CELL = Path(resolve_task("pick_place_panda")).parent.parent / "robots" / "cells" / "panda_table.yaml"


def task_file(tmp_path: Path, grasp: str) -> Path:
    path = tmp_path / "grasp.yaml"
    path.write_text(
        f"task: grasp\ncell: {CELL}\n"
        "objects:\n"
        "  - {name: cube, shape: box, size: [0.04, 0.04, 0.04], pose: {xyz: [0.5, 0.15, 0.77]}}\n"
        "steps:\n"
        "  - go: {group: arm, to: ready}\n"
        f"  - pick: {{arm: arm, object: cube, grasp: {grasp}}}\n", encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def panda():
    cell = load_cell(CELL)
    scene = scene_from_cell(cell)
    scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((0.5, 0.15, 0.77)))
    return cell, scene


def test_a_grasp_above_the_cube_fails_check_and_run_at_the_pick_line(tmp_path):
    # The tool pointing down 8 cm above the cube's centre: the pads close on air.
    path = task_file(tmp_path, "{xyz: [0, 0, 0.08], rpy: [3.141592653589793, 0, 0]}")
    report = check_task(path)
    assert len(report.problems) == 1
    problem = report.problems[0]
    assert (problem.path, problem.line) == (path, 7)
    assert "grasp does not reach 'cube'" in problem.message
    assert "the fingers close to 0 mm" in problem.message
    gap = float(problem.message.split("stays ")[1].split(" mm")[0])
    assert 30.0 < gap < 60.0  # pads ~5 cm long reach to ~4 cm above the cube's top
    spec = load_task(path)
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    record = Runner(spec, cell, MockBackend(cell.model.joint_names, start), InProcessPlanner(),
                    RunOptions(backend_name="mock")).run()
    assert record.status == "failed"
    assert f"{path}:7" in record.error and "grasp does not reach 'cube'" in record.error


def test_a_top_grasp_of_the_cube_touches(tmp_path, panda):
    cell, scene = panda
    ctx = TaskContext(cell, scene, None, None)  # type: ignore[arg-type]
    grasps = grasp_candidates(ctx, "cube", "top")
    gaps = finger_gaps(ctx, "arm", "cube", grasps)
    assert gaps is not None and all(g.touches() for g in gaps)
    assert touching_grasps(ctx, "arm", "cube", grasps) == grasps
    assert check_task(task_file(tmp_path, "top")).ok


def test_a_cube_narrower_than_the_closed_fingers_is_not_grasped():
    cell = load_cell(CELL)  # a copy whose hand closes only to 6 cm
    cell.model.named_states["hand"]["closed"] = {"panda_finger_joint1": 0.03}
    scene = scene_from_cell(cell)
    scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((0.5, 0.15, 0.77)))
    ctx = TaskContext(cell, scene, None, None)  # type: ignore[arg-type]
    grasps = grasp_candidates(ctx, "cube", "top")
    with pytest.raises(Exception, match=r"the fingers close to 60 mm and 'panda_\w+finger' "
                                        r"stays 10\.0 mm from 'cube' at closed width"):
        touching_grasps(ctx, "arm", "cube", grasps)


def test_a_grasp_written_for_the_flange_is_honoured_with_its_link(tmp_path, panda):
    cell, scene = panda
    model = cell.model
    ctx = TaskContext(cell, scene, None, None)  # type: ignore[arg-type]
    tool = ctx.arm("arm").grasp_frame
    flange = "panda_link8"
    frames = model.model.frames
    flange_to_tool = frames[model.frame_id(flange)].placement.actInv(
        frames[model.frame_id(tool)].placement)
    assert 0.10 < np.linalg.norm(flange_to_tool.translation) < 0.12  # the hand's length
    wanted = grasp_candidates(ctx, "cube", "top")[0]  # the tool's pose, world
    placed = scene.object_pose("cube").se3
    at_flange = placed.actInv(wanted) * flange_to_tool.inverse()  # flange in cube frame
    xyz = ", ".join(f"{v:.9f}" for v in at_flange.translation)
    rpy = ", ".join(f"{v:.9f}" for v in pin.rpy.matrixToRpy(at_flange.rotation))
    written = f"{{xyz: [{xyz}], rpy: [{rpy}]"
    honoured = check_task(task_file(tmp_path, written + f", link: {flange}}}"))
    assert honoured.ok, honoured.problems
    # Read as the tool frame's pose, the same numbers put the fingers 11 cm too high.
    misread = check_task(task_file(tmp_path, written + "}"))
    assert "grasp does not reach 'cube'" in misread.problems[0].message
    spec = load_task(task_file(tmp_path, written + f", link: {flange}}}"))
    pose = spec.steps[1].grasp
    assert pose.link == flange
    converted = tool_grasp(ctx, "arm", Pose.from_se3(pose.se3()), pose.link).se3
    assert np.allclose((placed * converted).homogeneous, wanted.homogeneous, atol=1e-6)


def test_a_grasp_link_that_a_joint_separates_from_the_tool_is_refused(tmp_path):
    report = check_task(task_file(tmp_path, "{xyz: [0, 0, 0.2], link: panda_link5}"))
    assert len(report.problems) == 1
    assert report.problems[0].line == 7
    assert "'grasp.link': 'panda_link5' does not move with arm 'arm'" in report.problems[0].message


def test_a_box_wider_than_the_open_hand_is_refused_at_open_width(tmp_path):
    """The Panda opens to 8 cm (2 x 0.04 m); a top grasp of a 9 cm box would bring the
    fingers down on it. Check and run refuse it at the pick's line before the arm moves."""
    path = tmp_path / "wide.yaml"
    path.write_text(
        f"task: wide\ncell: {CELL}\n"
        "objects:\n"
        "  - {name: crate, shape: box, size: [0.09, 0.09, 0.04], pose: {xyz: [0.5, 0.15, 0.77]}}\n"
        "steps:\n"
        "  - go: {group: arm, to: ready}\n"
        "  - pick: {arm: arm, object: crate, grasp: top}\n", encoding="utf-8")
    report = check_task(path)
    assert len(report.problems) == 1
    problem = report.problems[0]
    assert (problem.path, problem.line) == (path, 7)
    assert "grasp does not fit 'crate': the fingers open to" in problem.message
    overlap = float(problem.message.split(" by ")[1].split(" mm")[0])
    assert 3.0 < overlap < 10.0  # 9 cm box, pads about 8 cm apart: ~5 mm into each side
    spec = load_task(path)
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state(), strict=True))
    record = Runner(spec, cell, MockBackend(cell.model.joint_names, start), InProcessPlanner(),
                    RunOptions(backend_name="mock")).run()
    assert record.status == "failed"
    assert f"{path}:7" in record.error and "grasp does not fit 'crate'" in record.error


def test_the_receivers_grasp_in_a_handoff_must_touch_too(tmp_path):
    """A hand-over whose receiver grasp (explicit, 8 cm above the bar's centre, pointing
    down) closes on air is refused at the handoff's line by check and run alike."""
    source = Path(resolve_task("handoff_panda"))
    text = source.read_text(encoding="utf-8").replace(
        "cell: ../robots/cells/panda_pair.yaml",
        f"cell: {source.parent.parent / 'robots' / 'cells' / 'panda_pair.yaml'}")
    line = "  - handoff: {object: bar, from: left_arm, to: right_arm, at: handoff, approach: 0.06, retreat: 0.08}"
    assert line in text
    text = text.replace(line, line[:-1] + ", grasp: {xyz: [0, 0, 0.08], rpy: [3.141592653589793, 0, 0]}}")
    path = tmp_path / "handoff_air.yaml"
    path.write_text(text, encoding="utf-8")
    handoff_line = text.splitlines().index(line[:-1] + ", grasp: {xyz: [0, 0, 0.08], rpy: "
                                           "[3.141592653589793, 0, 0]}}") + 1
    report = check_task(path)
    messages = [(p.line, p.message) for p in report.problems]
    assert any(n == handoff_line and "grasp does not reach 'bar'" in m for n, m in messages), \
        messages
    spec = load_task(path)
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state(), strict=True))
    record = Runner(spec, cell, MockBackend(cell.model.joint_names, start), InProcessPlanner(),
                    RunOptions(backend_name="mock")).run()
    assert record.status == "failed"
    assert f"{path}:{handoff_line}" in record.error
    assert "grasp does not reach 'bar'" in record.error
