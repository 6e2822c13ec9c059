"""The joints an IK search moves: a group's joints that move the aimed frame.

:class:`SolvedJoints` maps them between the state vector, pinocchio's configuration and
the Jacobian's columns, with their limits and the mimic joints they drive, all
precomputed once so that an IK iteration does no lookups.
"""

from __future__ import annotations

import numpy as np

from taskrunner.errors import InputError
from taskrunner.robot.model import Group, JointInfo, RobotModel

__all__ = ["SolvedJoints"]


class SolvedJoints:
    """The variables of an IK search and their index maps.

    Args:
        model: the robot model.
        group: the group whose joints may move.
        frame_id: pinocchio frame index of the aimed frame.

    Attributes:
        names: the group's joints that move the frame (directly, or through a mimic
            joint that follows them), in the group's order.
        indices: their positions in the state vector.
        columns: their columns in pinocchio's Jacobian (a slice when contiguous).
        lower, upper: their limits (±inf for continuous joints).
        continuous: mask of the unbounded (continuous) ones.
        sample_lower, sample_span: the box random configurations are drawn from
            (continuous joints in [-pi, pi]).
        mimic: ``(follower index, source index, multiplier, offset)`` in the state vector
            for every mimic joint driven by a solved joint.
        mimic_columns: ``(solved joint position, pinocchio column, multiplier)`` for those
            followers that move the frame: their Jacobian column adds to their source's.
        moved_indices, moved_lower, moved_upper: every state entry a search changes
            (solved joints and their followers) and their limits.
        direct: the solved joints are a contiguous slice of a state vector that is also
            pinocchio's q, with no followers: a view of that slice is all a step updates.
        state_slice: that slice (meaningful when ``direct``).
        only_movers: no joint outside these (and their followers) moves the frame, so
            the frame's pose is a function of the solved joints alone.
        default_seed: the model's default state with the solved joints at mid-range
            (continuous ones at 0).

    Raises:
        InputError: no joint of the group moves the frame.
    """

    def __init__(self, model: RobotModel, group: Group, frame_id: int):
        pm = model.model
        self.model = model
        supports = {int(j) for j in pm.supports[pm.frames[frame_id].parentJoint]}

        def moves_frame(name: str) -> bool:
            return int(pm.getJointId(name)) in supports

        followers: dict[str, list[JointInfo]] = {}
        for info in model.joints:
            if info.mimic is not None:
                followers.setdefault(info.mimic.source, []).append(info)
        self.names = tuple(
            name for name in group.joint_names
            if moves_frame(name) or any(moves_frame(f.name) for f in followers.get(name, ()))
        )
        if not self.names:
            raise InputError(
                f"'frame' must be moved by a joint of group {group.name!r} "
                f"(got {pm.frames[frame_id].name!r})"
            )
        count = len(self.names)
        self.indices = model.indices(self.names)
        self.lower = model.lower[self.indices].copy()
        self.upper = model.upper[self.indices].copy()
        bounded = np.isfinite(self.lower) & np.isfinite(self.upper)
        self.continuous = ~bounded
        self.has_continuous = bool(self.continuous.any())
        self.sample_lower = np.where(bounded, self.lower, -np.pi)
        self.sample_span = np.where(bounded, self.upper, np.pi) - self.sample_lower

        self.mimic: list[tuple[int, int, float, float]] = []
        self.mimic_columns: list[tuple[int, int, float]] = []
        for k, name in enumerate(self.names):
            for info in followers.get(name, ()):
                assert info.mimic is not None
                self.mimic.append(
                    (info.index, int(self.indices[k]), info.mimic.multiplier, info.mimic.offset)
                )
                if moves_frame(info.name):
                    column = int(model.velocity_columns([info.name])[0])
                    self.mimic_columns.append((k, column, info.mimic.multiplier))
        self.moved_indices = np.array(
            sorted({*map(int, self.indices), *(m[0] for m in self.mimic)}), dtype=int
        )
        self.moved_lower = model.lower[self.moved_indices]
        self.moved_upper = model.upper[self.moved_indices]
        driven = {int(pm.getJointId(model.joint_names[i])) for i in self.moved_indices}
        self.only_movers = (supports - {0}) <= driven

        self.identity_q = pm.nq == model.nq and all(
            pm.joints[pm.getJointId(j.name)].nq == 1
            and pm.joints[pm.getJointId(j.name)].idx_q == j.index
            for j in model.joints
        )
        first = int(self.indices[0])
        contiguous = np.array_equal(self.indices, np.arange(first, first + count))
        self.direct = self.identity_q and contiguous and not self.mimic
        self.state_slice = slice(first, first + count)
        columns = model.velocity_columns(self.names)
        c0 = int(columns[0])
        contiguous_columns = np.array_equal(columns, np.arange(c0, c0 + count))
        self.columns: slice | np.ndarray = slice(c0, c0 + count) if contiguous_columns else columns

        seed = model.default_state()
        seed[self.indices] = self.sample_lower + 0.5 * self.sample_span
        self.default_seed = self.apply_mimic(seed)

    def __len__(self) -> int:
        return len(self.names)

    def apply_mimic(self, q: np.ndarray) -> np.ndarray:
        """Set the followers of the solved joints in state vector ``q`` (in place)."""
        for follower, source, multiplier, offset in self.mimic:
            q[follower] = multiplier * q[source] + offset
        return q

    def values(self, q: np.ndarray) -> np.ndarray:
        """The solved joints' values in ``q``: a view when ``direct``, else a copy."""
        return q[self.state_slice] if self.direct else q[self.indices]

    def sync(self, q: np.ndarray, values: np.ndarray) -> np.ndarray:
        """Write ``values`` into state vector ``q`` (followers too); pinocchio's q of it."""
        q[self.indices] = values
        self.apply_mimic(q)
        return q if self.identity_q else self.model.to_pin(q)

    def within_limits(self, q: np.ndarray) -> bool:
        """Whether every state entry a search changes is within its limits (no margin)."""
        moved = q[self.moved_indices]
        outside = np.less(moved, self.moved_lower)
        outside |= np.greater(moved, self.moved_upper)
        return not np.logical_or.reduce(outside)  # no Python-level .any() wrapper

    def wrap_near(self, values: np.ndarray, reference: np.ndarray) -> np.ndarray:
        """``values`` with each continuous joint turned by whole turns to within pi of
        ``reference`` (same pose, nearest angle)."""
        if not self.has_continuous:
            return values
        delta = np.remainder(values - reference + np.pi, 2.0 * np.pi) - np.pi
        return np.where(self.continuous, reference + delta, values)

    def distance(self, a: np.ndarray, b: np.ndarray) -> float:
        """Euclidean distance of two value vectors (continuous joints modulo 2 pi)."""
        delta = a - b
        if self.has_continuous:
            wrapped = np.remainder(delta + np.pi, 2.0 * np.pi) - np.pi
            delta = np.where(self.continuous, wrapped, delta)
        return float(np.sqrt(np.dot(delta, delta)))
