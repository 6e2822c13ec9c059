"""Taught poses: named poses recorded on a running cell, used like the robot files' own.

The API teaches a pose (``PUT /cells/{id}/poses/{name}``) by storing the group's joint
values in its database. For a run, a check and the command line to agree on which poses
exist, every cell load consults one set of taught poses: :class:`TaughtPoses`, made
the active one for a block of code (:meth:`TaughtPoses.active`); the cell loader adds the
poses of the cell it loads (:func:`apply_taught`). A pose that no longer fits the cell
(its group is gone, a joint is not the group's, a value is outside the limits) is
skipped with a warning.
"""

from __future__ import annotations

import contextvars
import logging
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from taskrunner.robot.cell import Cell

__all__ = ["TaughtPose", "TaughtPoses", "active_taught", "apply_taught"]

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class TaughtPose:
    """A named pose of a group: joint values (rad or m) by joint name."""

    group: str
    name: str
    joints: Mapping[str, float]


@dataclass(frozen=True)
class TaughtPoses:
    """Taught poses by cell file (resolved path)."""

    by_cell: Mapping[Path, tuple[TaughtPose, ...]] = field(default_factory=dict)

    def of(self, cell_path: Path) -> tuple[TaughtPose, ...]:
        """The poses taught on the cell file ``cell_path``."""
        try:
            return self.by_cell.get(cell_path.resolve(), ())
        except (OSError, RuntimeError):
            return ()

    @contextmanager
    def active(self) -> Iterator[TaughtPoses]:
        """Make these the taught poses of every cell loaded in this thread for the block."""
        token = _ACTIVE.set(self)
        try:
            yield self
        finally:
            _ACTIVE.reset(token)


_ACTIVE: contextvars.ContextVar[TaughtPoses | None] = contextvars.ContextVar(
    "taskrunner_taught_poses", default=None)


def active_taught() -> TaughtPoses | None:
    """The taught poses made active with :meth:`TaughtPoses.active`, or None."""
    return _ACTIVE.get()


def fits(cell: Cell, pose: TaughtPose) -> bool:
    """Whether ``pose`` still fits ``cell``: its group exists, its joints are the group's,
    its values within the limits."""
    model = cell.model
    if pose.group not in model.groups:
        return False
    if not all(j in model.group(pose.group).joint_names for j in pose.joints):
        return False
    return bool(model.within_limits(model.state_with(model.default_state(), dict(pose.joints))))


def apply_taught(cell: Cell, poses: TaughtPoses | None = None) -> list[TaughtPose]:
    """Add the taught poses of ``cell``'s file (``poses``, default: the active ones) to
    its model as named poses; returns those added. A taught pose never replaces one of
    the robot or cell files."""
    poses = poses if poses is not None else active_taught()
    if poses is None or cell.path is None:
        return []
    added = []
    for pose in poses.of(cell.path):
        own = cell.model.named_states.get(pose.group, {})
        if pose.name in own or not fits(cell, pose):
            log.warning("taught pose %r of group %r no longer fits cell %s: skipped",
                        pose.name, pose.group, cell.path)
            continue
        cell.model.named_states.setdefault(pose.group, {})[pose.name] = dict(pose.joints)
        added.append(pose)
    return added
