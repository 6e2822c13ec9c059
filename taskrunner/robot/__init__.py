"""Robot descriptions (URDF, xacro, SRDF, MoveIt YAML) and cells, loaded without ROS."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from taskrunner.robot.build import Placement, build_model
from taskrunner.robot.description import RobotDescription, load_description
from taskrunner.robot.model import EndEffector, Group, JointInfo, RobotInstance, RobotModel
from taskrunner.robot.notes import LoadWarning
from taskrunner.robot.packages import PackageMap

if TYPE_CHECKING:
    from taskrunner.robot.cell import Cell

__all__ = [
    "Cell",
    "EndEffector",
    "Group",
    "JointInfo",
    "LoadWarning",
    "PackageMap",
    "Placement",
    "RobotDescription",
    "RobotInstance",
    "RobotModel",
    "build_model",
    "load_description",
    "load_robot",
]


def load_robot(path: str | Path, packages: PackageMap | None = None,
               strict: bool | None = None,
               allow_missing_meshes: bool | None = None) -> RobotModel:
    """Load one robot (manifest, MoveIt config folder, URDF or xacro) as a model.

    The robot's root link is placed at the world origin, with no name prefix.

    Args:
        path: the robot (see :func:`load_description`).
        packages: package map (default: the environment's and the robot's neighbours').
        strict: every warning (what MoveIt would skip, a missing mesh, a pose in
            self-collision…) is an error; None: the ``TASKRUNNER_STRICT`` variable.
        allow_missing_meshes: load the robot even when mesh files it names cannot be
            found, or it has no collision geometry (one warning); None: the
            ``TASKRUNNER_ALLOW_MISSING_MESHES`` variable. Otherwise either is a
            :class:`~taskrunner.errors.MissingMeshError`.
    """
    description = load_description(path, packages)
    return build_model([Placement(description)], name=description.name, strict=strict,
                       allow_missing_meshes=allow_missing_meshes)


def __getattr__(name: str) -> object:
    # The cell loader imports this package's modules: Cell is looked up on first use.
    if name == "Cell":
        from taskrunner.robot.cell import Cell

        return Cell
    raise AttributeError(f"module 'taskrunner.robot' has no attribute {name!r}")
