"""Names in MoveIt files (a robot's own joint, link and group names) → names of a cell.

A MoveIt file speaks of one robot with the names of its URDF and SRDF (``panda_joint1``,
``panda_link0``, ``panda_arm``). A cell puts a prefix before every name of each robot
(``left_panda_joint1``). A name of the file is found as follows:

- with a robot chosen (``robot=`` the instance name, ``--robot`` on the command line):
  that robot's prefix + the name, else the name as written (``world``, a cell object);
- without one: the name as written when the model has it, else the one robot whose
  prefix + the name exists; when several robots have it the name is ambiguous (an error
  that asks to choose a robot).
"""

from __future__ import annotations

from collections.abc import Callable

import pinocchio as pin

from taskrunner.errors import InputError, UnknownNameError
from taskrunner.robot.model import RobotModel

__all__ = ["AmbiguousName", "NameMap"]


class AmbiguousName(InputError):
    """A file's name matches the same name of several robots of the cell (its readers
    catch it and say which file and line)."""


class NameMap:
    """See the module docstring.

    Args:
        model: the cell's (or robot's) model.
        robot: the robot instance the file describes, or None.

    Raises:
        UnknownNameError: ``robot`` is not an instance of the model.
    """

    def __init__(self, model: RobotModel, robot: str | None = None) -> None:
        self.model = model
        instances = {inst.name: inst for inst in model.instances}
        if robot is not None and robot not in instances:
            raise UnknownNameError("robot", robot, list(instances))
        self.robot = robot
        self.prefixes = ([instances[robot].prefix] if robot is not None
                         else sorted({inst.prefix for inst in model.instances if inst.prefix}))
        self._joints = frozenset(model.joint_names)
        # Joints of the URDF that pinocchio merged into frames (pinocchio's own root,
        # ``universe``, is not a joint of any description).
        self._fixed = frozenset(f.name for f in model.model.frames
                                if f.type == pin.FIXED_JOINT and f.name != "universe")

    def joint(self, name: str) -> str | None:
        """A joint of the state vector (revolute, continuous, prismatic, mimic)."""
        return self._find(name, lambda n: n in self._joints)

    def fixed_joint(self, name: str) -> str | None:
        """A joint of the description that is fixed in the model (it has no value)."""
        return self._find(name, lambda n: n in self._fixed)

    def link(self, name: str) -> str | None:
        """A link or other frame of the model (``world`` included)."""
        return self._find(name, lambda n: bool(self.model.model.existFrame(n)))

    def group(self, name: str) -> str | None:
        return self._find(name, lambda n: n in self.model.groups)

    def _find(self, name: str, exists: Callable[[str], bool]) -> str | None:
        if self.robot is not None:
            prefixed = self.prefixes[0] + name
            if exists(prefixed):
                return prefixed
            return name if exists(name) else None
        if exists(name):
            return name
        found = [p + name for p in self.prefixes if exists(p + name)]
        if len(found) > 1:
            raise AmbiguousName(f"{name!r} is {' and '.join(repr(f) for f in found)} in this "
                                "cell: choose the robot the file is for (robot=, --robot)")
        return found[0] if found else None
