"""Taught poses: named poses recorded on a running cell, used like the robot files' own.

The API teaches a pose (``PUT /cells/{id}/poses/{name}``) by storing the group's joint
values in its database. For a run, a check and the command line to agree on which poses
exist, the caller reads one set of taught poses (:class:`TaughtPoses`, e.g.
:func:`read_taught_poses`) and passes it down to every cell load
(``load_cell(..., taught=)``, ``check_task(..., taught=)``, ``run_task_file(...,
taught=)``): the cell loader adds the poses of the cell it loads (:func:`apply_taught`).
Nothing is looked up from the thread or the process: two cells loaded side by side
with different poses each get their own. A pose that no longer fits the cell (its group
is gone, a joint is not the group's, a value is outside the limits) is skipped with a
warning.
"""

from __future__ import annotations

import json
import logging
import os
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from taskrunner.robot.cell import Cell

__all__ = ["TAUGHT_POSES_TABLE", "TaughtPose", "TaughtPoses", "apply_taught",
           "cell_key", "cells_dir_from_env", "check_pose_name", "data_dir_from_env",
           "read_taught_poses", "save_taught_pose", "taught_poses_from_rows"]

TAUGHT_POSES_TABLE = """
CREATE TABLE IF NOT EXISTS taught_poses (
    cell     TEXT NOT NULL,
    grp      TEXT NOT NULL,
    name     TEXT NOT NULL,
    joints   TEXT NOT NULL,
    taught   TEXT NOT NULL,
    PRIMARY KEY (cell, grp, name)
);
"""
"""The table of taught poses in the data folder's ``runs.sqlite`` (the API's store, and
:func:`save_taught_pose` from Python); ``cell`` is an id of the cells folder or a path."""

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


def taught_poses_from_rows(rows: Iterable[tuple[str, str, str, str]],
                           cells_dir: Path) -> TaughtPoses:
    """Taught poses from ``(cell, group, name, joints JSON)`` rows of the API's database
    (a cell is an id, a file of ``cells_dir``, or a path)."""
    by_cell: dict[Path, list[TaughtPose]] = {}
    for cell, group, name, joints in rows:
        path = (cells_dir / f"{cell}.yaml") if "/" not in cell else Path(cell)
        by_cell.setdefault(path.resolve(), []).append(TaughtPose(group, name, json.loads(joints)))
    return TaughtPoses({path: tuple(poses) for path, poses in by_cell.items()})


def read_taught_poses(db_path: Path, cells_dir: Path) -> TaughtPoses:
    """The poses the API taught, read from its database ``db_path`` (the data folder's
    ``runs.sqlite``), for the command line to load cells as the server does: pass them
    to the loads (``check_task(..., taught=)``). No database: none."""
    if not Path(db_path).is_file():
        return TaughtPoses()
    import sqlite3  # here: 10-15 ms of run-task's start when there is no database

    db = sqlite3.connect(f"file:{Path(db_path).resolve()}?mode=ro", uri=True)
    try:
        rows = db.execute("SELECT cell, grp, name, joints FROM taught_poses "
                          "ORDER BY taught").fetchall()
    except sqlite3.Error:  # a database without the table: nothing taught
        rows = []
    finally:
        db.close()
    return taught_poses_from_rows(rows, cells_dir)


def data_dir_from_env(data_dir: str | os.PathLike[str] | None = None) -> Path:
    """The API's data folder, as the command line finds it: ``data_dir``, else
    ``TASKRUNNER_DATA_DIR`` (or ``TASKRUNNER_STATE_DIR``), else ``./state``."""
    return Path(data_dir or os.environ.get("TASKRUNNER_DATA_DIR")
                or os.environ.get("TASKRUNNER_STATE_DIR") or "state")


def cells_dir_from_env() -> Path:
    """The cells folder that cell ids name: ``TASKRUNNER_CELLS_DIR``, else the shipped one."""
    from taskrunner import resources

    return Path(os.environ.get("TASKRUNNER_CELLS_DIR") or resources.cells_dir())


_POSE_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_\-]{0,63}$")


def check_pose_name(name: str) -> None:
    """Refuse a name the REST API's teach refuses.

    Raises:
        ArgumentError: not a letter or ``_``, then up to 63 letters, digits, ``_``, ``-``.
    """
    if not isinstance(name, str) or not _POSE_NAME.match(name):
        from taskrunner.errors import ArgumentError

        raise ArgumentError(f"'name' must be a letter or _ then letters, digits, _ or - "
                            f"(got {name!r})")


def cell_key(cell_path: Path, cells_dir: Path) -> str:
    """How the database names a cell: its id when its file is in ``cells_dir`` (as the
    API names it), else its resolved path (read back the same by
    :func:`taught_poses_from_rows`)."""
    path = Path(cell_path).resolve()
    if path.suffix == ".yaml" and path.parent == Path(cells_dir).resolve():
        return path.stem
    return str(path)


def save_taught_pose(db_path: Path, cell: str, pose: TaughtPose) -> str:
    """Store (or replace) ``pose`` of ``cell`` (see :func:`cell_key`) in the database
    ``db_path`` (made if missing), as the API's teach does; returns when it was taught
    (ISO 8601, UTC)."""
    import sqlite3
    from datetime import UTC, datetime

    Path(db_path).parent.mkdir(parents=True, exist_ok=True)
    now = datetime.now(UTC).isoformat()
    db = sqlite3.connect(Path(db_path), isolation_level=None)
    try:
        db.executescript(TAUGHT_POSES_TABLE)
        db.execute("INSERT OR REPLACE INTO taught_poses VALUES (?, ?, ?, ?, ?)",
                   (cell, pose.group, pose.name, json.dumps(dict(pose.joints)), now))
    finally:
        db.close()
    return now


def fits(cell: Cell, pose: TaughtPose) -> bool:
    """Whether ``pose`` still fits ``cell``: its group exists, its joints are the group's,
    its values within the limits."""
    model = cell.model
    if pose.group not in model.groups:
        return False
    if not all(j in model.group(pose.group).joint_names for j in pose.joints):
        return False
    return bool(model.within_limits(model.state_with(model.default_state(), dict(pose.joints))))


def apply_taught(cell: Cell, poses: TaughtPoses | None) -> list[TaughtPose]:
    """Add the taught poses of ``cell``'s file (``poses``; None: none) to its model as
    named poses; returns those added. A taught pose never replaces one of the robot or
    cell files."""
    if poses is None or cell.path is None:
        return []
    added = []
    for pose in poses.of(cell.path):
        own = cell.model.named_states.get(pose.group, {})
        if pose.name in own or not fits(cell, pose):
            message = (f"taught pose {pose.name!r} of group {pose.group!r} no longer fits "
                       f"cell {cell.path}: skipped")
            log.warning("%s", message)
            cell.model.warnings.append(message)  # run-task info lists every load warning
            continue
        cell.model.named_states.setdefault(pose.group, {})[pose.name] = dict(pose.joints)
        added.append(pose)
    return added
