"""load_task: a valid task becomes frozen, typed, located models."""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest
import yaml
from pydantic import ValidationError

import taskrunner.tasks as tasks
from taskrunner.errors import TaskSpecError
from taskrunner.resources import DATA_ROOT
from taskrunner.tasks import (
    AddObjectStep,
    AttachStep,
    DetachStep,
    FallbackStep,
    GoStep,
    GripperStep,
    HandoffStep,
    IncludeStep,
    Location,
    MoveStep,
    ParallelStep,
    PickStep,
    PlaceStep,
    PoseSpec,
    RemoveObjectStep,
    RepeatStep,
    RetryStep,
    SequenceStep,
    TargetPose,
    TimeoutStep,
    Transform,
    WaitStep,
    load_task,
    load_task_text,
)


def test_public_names_are_pinned():
    assert set(tasks.__all__) == {
        "AddObjectStep", "AttachStep", "DetachStep", "Expectation", "FallbackStep", "GoStep",
        "GripperStep", "HandoffStep", "IncludeStep", "Location", "MOTION_VERBS", "MotionOptions",
        "MotionStep", "MoveStep", "Node", "ObjectSpec", "Offset", "ParallelStep", "Parameter",
        "PickStep", "PlaceStep", "PoseSpec", "Problem", "RemoveObjectStep", "RepeatStep",
        "RetryStep", "STEP_TYPES", "SequenceStep", "Step", "StepNode", "TargetPose",
        "TaskExpectation", "TaskSpec", "TimeoutStep", "Transform", "WaitStep", "arm_groups", "check_names",
        "gripper_group_of", "load_and_check", "load_task", "load_task_text", "problems_error",
        "raise_for_problems", "walk_steps",
    }
    assert all(hasattr(tasks, name) for name in tasks.__all__)


def test_example_task_loads_with_its_values_typed(fixtures: Path, repo_root: Path):
    spec = load_task(fixtures / "pick_place.yaml")
    assert spec.name == "pick_place"
    assert spec.description == "Move a cube from one spot to another."
    assert spec.path == fixtures / "pick_place.yaml"
    assert spec.cell == DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"
    [cube] = spec.objects
    assert cube.name == "cube" and cube.shape == "box" and cube.size == (0.025, 0.025, 0.025)
    assert cube.pose.xyz == (0.2, 0.05, 0.7625)
    assert isinstance(cube.pose.xyz[0], float)
    verbs = [step.verb for step in spec.steps]
    assert verbs == ["gripper", "go", "pick", "place", "go"]
    gripper, go, pick, place, _ = spec.steps
    assert isinstance(gripper, GripperStep) and gripper.arm == "arm" and gripper.action == "open"
    assert isinstance(go, GoStep) and go.group == "arm" and go.to == "home"
    assert isinstance(pick, PickStep) and pick.grasp == "top"
    assert (pick.approach, pick.retreat) == (0.04, 0.05)
    assert isinstance(place, PlaceStep) and place.at == PoseSpec(xyz=(0.15, -0.08, 0.7625))
    assert place.name == "put the cube down"


def test_every_step_knows_its_file_and_the_line_of_its_verb(fixtures: Path):
    path = fixtures / "pick_place.yaml"
    spec = load_task(path)
    assert [step.loc for step in spec.steps] == [
        Location(path, 14), Location(path, 15), Location(path, 16), Location(path, 17),
        Location(path, 25)]
    place = spec.steps[3]
    assert place.loc is not None
    assert place.loc.line_of("velocity_scaling") == 23
    assert place.loc.line_of("not_written") == 17
    assert place.at is not None and place.at.loc == Location(path, 20)
    assert spec.objects[0].loc == Location(path, 11)
    assert str(place.loc) == f"{path}:17"
    assert spec.loc == Location(path, 2)


def test_defaults_fill_the_options_a_step_leaves_unset(fixtures: Path):
    spec = load_task(fixtures / "pick_place.yaml")
    assert spec.defaults.velocity_scaling == 0.5
    assert [s.velocity_scaling for s in spec.steps] == [0.5, 0.5, 0.5, 0.25, 0.5]
    assert all(s.acceleration_scaling is None for s in spec.steps)


def test_every_verb_loads_into_its_model(fixtures: Path):
    spec = load_task(fixtures / "dual_arm.yaml")
    kinds = [type(step) for step in spec.walk()]
    assert kinds == [
        ParallelStep, GoStep, GoStep, GripperStep, GripperStep, IncludeStep, GripperStep,
        PickStep, HandoffStep, RetryStep, PlaceStep, TimeoutStep, MoveStep, MoveStep,
        RepeatStep, WaitStep, FallbackStep, GoStep, GoStep, AddObjectStep, AttachStep,
        DetachStep, RemoveObjectStep, SequenceStep, PickStep, AttachStep]
    steps = list(spec.walk())
    assert steps[2].joints == {"right_Revolute 1": 0.5}
    assert steps[4].width == 0.02 and steps[4].arm == "right_arm"
    handoff = steps[8]
    assert (handoff.from_arm, handoff.to_arm, handoff.at) == ("left_arm", "right_arm", "HandOff")
    assert steps[9].times == 3
    place = steps[10]
    assert (place.on, place.offset, place.at) == ("table", (0.1, 0.0), None)
    assert steps[11].seconds == 20.0
    by, pose = steps[12], steps[13]
    assert by.by is not None and by.by.frame == "world" and by.cartesian is True
    assert pose.cartesian is False and pose.target_link == "left_gripper_base_1"
    assert steps[14].times == 2 and isinstance(steps[14].times, int)
    target = steps[17].pose
    assert isinstance(target, TargetPose)
    assert target.frame == "left_base_link" and target.position_only is True
    assert steps[18].planner == "PRM" and steps[17].planner == "RRTConnect"
    assert steps[19].object.name == "ball" and steps[19].object.pose.frame == "cube"
    assert steps[20].arm == "left_arm" and steps[22].object == "ball"
    assert isinstance(steps[24].grasp, Transform) and steps[24].grasp.rpy == (3.14159, 0.0, 0.0)
    assert steps[25].link == "left_gripper_base_1" and steps[25].label == "hold it"


def test_children_and_labels_describe_the_tree(fixtures: Path):
    spec = load_task(fixtures / "dual_arm.yaml")
    parallel, include = spec.steps[0], spec.steps[3]
    assert [c.label for c in parallel.children] == ["go left_arm", "go right_arm"]
    assert include.label == "include pick_part"
    assert spec.steps[1].children == ()


def test_nodes_are_frozen_and_compare_by_content():
    go = GoStep(group="arm", to="home")
    with pytest.raises(ValidationError):
        go.group = "other"  # type: ignore[misc]
    located = go.located(Location(Path("/x.yaml"), 3))
    assert located == go and hash(located) == hash(go)
    assert located.loc == Location(Path("/x.yaml"), 3) and go.loc is None
    joints = GoStep(group="arm", joints={"a": 1.0})
    assert {joints: 1}[GoStep(group="arm", joints={"a": 1.0})] == 1


def test_a_loaded_task_round_trips_through_its_document(fixtures: Path, tmp_path: Path):
    for name in ("pick_place.yaml", "dual_arm.yaml", "include_twice.yaml"):
        spec = load_task(fixtures / name)
        text = yaml.safe_dump(spec.to_document(), sort_keys=False)
        copy = load_task_text(text, tmp_path / name)
        assert copy.steps == spec.steps
        assert (copy.objects, copy.parameters, copy.defaults, copy.cell) == (
            spec.objects, spec.parameters, spec.defaults, spec.cell)
        assert all(step.loc is not None for step in copy.walk())


def test_text_is_loaded_with_paths_relative_to_the_file_it_stands_for(fixtures: Path):
    text = textwrap.dedent("""\
        task: inline
        cell: ../../../taskrunner/data/robots/cells/servo_arm_table.yaml
        steps:
          - include: {file: open_part.yaml}
        """)
    spec = load_task_text(text, fixtures / "inline.yaml")
    [include] = spec.steps
    assert isinstance(include, IncludeStep) and include.path == fixtures / "open_part.yaml"
    assert include.loc == Location(fixtures / "inline.yaml", 4)
    assert include.steps[0].loc == Location(fixtures / "open_part.yaml", 3)


def test_pose_models_give_transforms():
    rpy = PoseSpec(xyz=(0.1, 0.2, 0.3), rpy=(0.0, 0.0, np.pi / 2))
    quat = PoseSpec(xyz=(0.1, 0.2, 0.3), quat=(0.0, 0.0, np.sqrt(0.5), np.sqrt(0.5)))
    assert rpy.has_orientation and quat.has_orientation
    assert np.allclose(rpy.se3().homogeneous, quat.se3().homogeneous)
    assert np.allclose(rpy.to_pose().quat, (0.0, 0.0, np.sqrt(0.5), np.sqrt(0.5)))
    bare = Transform(xyz=(1.0, 0.0, 0.0))
    assert not bare.has_orientation
    assert np.allclose(bare.se3().rotation, np.eye(3))
    assert isinstance(bare.se3(), pin.SE3)
    # A quaternion a little off unit length is normalised.
    near = PoseSpec(quat=(0.0, 0.0, 0.7071, 0.7071))
    assert np.isclose(np.linalg.norm(near.quat), 1.0)


def test_mesh_files_are_resolved_from_the_task_file(tmp_path: Path, robots_dir: Path):
    cell = robots_dir / "cells" / "servo_arm_table.yaml"
    text = textwrap.dedent("""\
        task: meshes
        cell: /nowhere/cell.yaml
        objects:
          - {name: part, shape: mesh, file: meshes/part.stl, scale: [0.001, 0.001, 0.001]}
          - {name: other, shape: mesh, file: "package://parts/meshes/other.stl"}
        steps:
          - wait: {seconds: 0}
        """)
    with pytest.raises(TaskSpecError, match=r"task.yaml:2: cell file not found: "):
        load_task_text(text, tmp_path / "task.yaml")
    text = text.replace("/nowhere/cell.yaml", str(cell))
    spec = load_task_text(text, tmp_path / "task.yaml")
    assert spec.objects[0].file == str(tmp_path / "meshes" / "part.stl")
    assert spec.objects[1].file == "package://parts/meshes/other.stl"
