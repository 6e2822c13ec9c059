"""Robot descriptions (URDF, xacro, SRDF, MoveIt YAML) and cells, loaded without ROS.

The names below are imported on first use (PEP 562): ``taskrunner.robot.options`` (what
the command line builds before it starts its planning worker) does not import the
loaders, pinocchio or coal.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from taskrunner.robot.build import Placement, build_model
    from taskrunner.robot.cell import Cell
    from taskrunner.robot.description import RobotDescription, load_description
    from taskrunner.robot.model import EndEffector, Group, JointInfo, RobotInstance, RobotModel
    from taskrunner.robot.notes import LoadWarning
    from taskrunner.robot.options import LoadOptions
    from taskrunner.robot.packages import PackageMap

__all__ = [
    "Cell",
    "EndEffector",
    "Group",
    "JointInfo",
    "LoadOptions",
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
               allow_missing_meshes: bool | None = None, *,
               options: LoadOptions | None = None) -> RobotModel:
    """Load one robot (manifest, MoveIt config folder, URDF or xacro) as a model.

    The robot's root link is placed at the world origin, with no name prefix.

    Args:
        path: the robot (see :func:`load_description`).
        packages: package map (default: the ``options``' package path, the ROS
            environment's and the robot's neighbours').
        strict: every warning (what MoveIt would skip, a missing mesh, a pose in
            self-collision…) is an error; None: ``options.strict``.
        allow_missing_meshes: load the robot even when mesh files it names cannot be
            found, or it has no collision geometry (one warning); None:
            ``options.allow_missing_meshes``. Otherwise either is a
            :class:`~taskrunner.errors.MissingMeshError`.
        options: how robots are loaded (default: ``LoadOptions()``: not strict, no
            missing meshes, each robot's own collision choice). The environment is not
            read.
    """
    from taskrunner.robot.build import Placement, build_model
    from taskrunner.robot.description import load_description
    from taskrunner.robot.options import LoadOptions

    options = options or LoadOptions()
    description = load_description(path, packages, options=options)
    return build_model([Placement(description)], name=description.name,
                       strict=options.strict if strict is None else strict,
                       allow_missing_meshes=(options.allow_missing_meshes
                                             if allow_missing_meshes is None
                                             else allow_missing_meshes),
                       collision=options.collision)


# Where each name lives (imported on first access).
_HOMES = {
    "Placement": "build", "build_model": "build", "Cell": "cell",
    "RobotDescription": "description", "load_description": "description",
    "EndEffector": "model", "Group": "model", "JointInfo": "model", "RobotInstance": "model",
    "RobotModel": "model", "LoadWarning": "notes", "LoadOptions": "options",
    "PackageMap": "packages",
}


def __getattr__(name: str) -> Any:
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module 'taskrunner.robot' has no attribute {name!r}")
    import importlib

    value = getattr(importlib.import_module(f"taskrunner.robot.{home}"), name)
    globals()[name] = value  # later lookups skip this function
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
