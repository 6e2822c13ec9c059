"""The task language: YAML task files loaded into frozen, located models.

    spec = load_task("tasks/pick_place.yaml", {"cube_x": "0.22"})
    spec, cell, problems = load_and_check("tasks/pick_place.yaml")

See ``ARCHITECTURE.md`` ("Task language") and :mod:`taskrunner.tasks.spec` for the verbs;
the JSON Schema of task files is :func:`taskrunner.tasks.schema.task_json_schema`.
"""

from __future__ import annotations

from taskrunner.tasks.expect import Expectation, TaskExpectation
from taskrunner.tasks.loader import load_task, load_task_text
from taskrunner.tasks.names import arm_groups, check_names, gripper_group_of, load_and_check
from taskrunner.tasks.nodes import Location, Node, ObjectSpec, PoseSpec, TargetPose, Transform
from taskrunner.tasks.problem import Problem, problems_error, raise_for_problems
from taskrunner.tasks.spec import Parameter, TaskSpec
from taskrunner.tasks.steps import (
    MOTION_VERBS,
    STEP_TYPES,
    AddObjectStep,
    AttachStep,
    DetachStep,
    FallbackStep,
    GoStep,
    GripperStep,
    HandoffStep,
    IncludeStep,
    MotionOptions,
    MotionStep,
    MoveStep,
    Offset,
    ParallelStep,
    PickStep,
    PlaceStep,
    RemoveObjectStep,
    RepeatStep,
    RetryStep,
    SequenceStep,
    Step,
    StepNode,
    TimeoutStep,
    WaitStep,
    walk_steps,
)

__all__ = [
    "AddObjectStep", "AttachStep", "DetachStep", "Expectation", "FallbackStep", "GoStep",
    "GripperStep", "HandoffStep", "IncludeStep", "Location", "MOTION_VERBS", "MotionOptions",
    "MotionStep", "MoveStep", "Node", "ObjectSpec", "Offset", "ParallelStep", "Parameter", "PickStep",
    "PlaceStep", "PoseSpec", "Problem", "RemoveObjectStep", "RepeatStep", "RetryStep",
    "STEP_TYPES", "SequenceStep", "Step", "StepNode", "TargetPose", "TaskExpectation",
    "TaskSpec", "TimeoutStep",
    "Transform", "WaitStep", "arm_groups", "check_names", "gripper_group_of", "load_and_check",
    "load_task", "load_task_text", "problems_error", "raise_for_problems",
    "walk_steps",
]
