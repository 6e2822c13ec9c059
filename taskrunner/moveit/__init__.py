"""MoveIt planning-scene and motion-plan-request files, without ROS.

Read a ``moveit_msgs/PlanningScene`` dumped as YAML (ROS 1 or ROS 2, as MotionBenchMaker
writes its problems) and apply it to a :class:`~taskrunner.scene.Scene`; read a
``moveit_msgs/MotionPlanRequest`` and turn it into a :class:`~taskrunner.planning.PlanRequest`
for :class:`~taskrunner.planning.MotionPlanner`::

    from taskrunner.moveit import load_planning_scene, load_motion_plan_request, plan_request_file

    cell = load_cell_or_robot(...)
    scene = scene_from_cell(cell)
    load_planning_scene("scene.yaml", cell.model).apply(scene)
    request = load_motion_plan_request("request.yaml", cell.model)
    report = plan_request_file(scene, request, seed=0)
"""

from __future__ import annotations

from taskrunner.moveit.messages import ObjectEdit
from taskrunner.moveit.names import NameMap
from taskrunner.moveit.report import PlanReport, plan_files, plan_request_file
from taskrunner.moveit.request_file import MotionPlanRequestFile, load_motion_plan_request, planner_name
from taskrunner.moveit.scene_file import PlanningSceneFile, apply_scene_file, load_planning_scene

__all__ = [
    "MotionPlanRequestFile",
    "NameMap",
    "ObjectEdit",
    "PlanReport",
    "PlanningSceneFile",
    "apply_scene_file",
    "load_motion_plan_request",
    "load_planning_scene",
    "plan_files",
    "plan_request_file",
    "planner_name",
]
