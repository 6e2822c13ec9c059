"""The robot model: one kinematic tree with its joints, groups, named poses and geometry.

A :class:`RobotModel` is what a MoveIt ``RobotModel`` is to a ROS user: built from one or
more robot descriptions (a cell places several, each with a name prefix), it owns the
pinocchio model, the collision geometry of the robot links, the planning groups, the
named poses, the end effectors, the joint limits (URDF overridden by joint_limits.yaml)
and the pairs of links that are allowed to touch.

Configurations are *state vectors*: one value per 1-DOF joint (revolute, continuous,
prismatic), in :attr:`RobotModel.joint_names` order, in rad or m. Mimic joints are part
of the vector and follow their source joint (:meth:`RobotModel.apply_mimic`). Pinocchio's
own configuration (continuous joints as cos/sin pairs) is produced by
:meth:`RobotModel.to_pin`.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pinocchio as pin

from taskrunner.errors import UnknownNameError
from taskrunner.kinds import CollisionChoice
from taskrunner.robot.moveit_yaml import CartesianLimits, KinematicsSettings, OmplGroupSettings
from taskrunner.types import JointState

__all__ = ["LIMIT_TOLERANCE", "EndEffector", "Group", "JointInfo", "Mimic", "RobotInstance",
           "RobotModel", "describe_excess"]

LIMIT_TOLERANCE = 1e-9
"""rad or m: a joint this close outside a bound is within it, everywhere limits are checked
(a planned, interpolated or solved state lands on a bound up to floating-point round-off;
MoveIt's ``satisfiesPositionBounds`` likewise takes a margin). Larger excesses in input
files are MoveIt's ``start_state_max_bounds_error`` matter (:mod:`taskrunner.moveit.start_bounds`)."""


def describe_excess(joint: str, value: float, bound: float, unit: str = "rad") -> str:
    """``joint 'j' = -3.141595 is below its lower bound -3.14159265 by 2.6e-06 rad``: the
    value and the bound with enough digits to see the excess, and the excess itself."""
    side = "above its upper" if value > bound else "below its lower"
    return (f"joint {joint!r} = {value:.10g} is {side} bound {bound:.10g} by "
            f"{abs(value - bound):.2g} {unit}")


@dataclass(frozen=True)
class Mimic:
    """``value = multiplier * source + offset``."""

    source: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True)
class JointInfo:
    """One 1-DOF joint of the model.

    Attributes:
        index: position in the state vector.
        lower, upper: position limits (rad or m); ±inf for an unbounded continuous joint.
        max_velocity, max_acceleration: limits (rad/s, rad/s²); inf when not given.
    """

    name: str
    type: str
    index: int
    lower: float
    upper: float
    max_velocity: float
    max_acceleration: float
    parent_link: str
    child_link: str
    robot: str
    mimic: Mimic | None = None
    passive: bool = False

    @property
    def bounded(self) -> bool:
        return bool(np.isfinite(self.lower) and np.isfinite(self.upper))


@dataclass(frozen=True)
class Group:
    """A planning group.

    Attributes:
        joint_names: the group's active joints (no mimic, passive or fixed joints), in
            model order; these are the variables a planner moves.
        joint_indices: their positions in the state vector.
        base_link: where a chain starts (or the parent of the first joint).
        tip_link: the frame IK aims by default (chain tip or end-effector parent link);
            None for groups without one (a gripper's finger joints).
        kinematics: IK settings from kinematics.yaml, if the group has an entry.
        end_effector: name of the end effector attached to this group, if any.
    """

    name: str
    joint_names: tuple[str, ...]
    joint_indices: np.ndarray
    links: tuple[str, ...]
    base_link: str
    tip_link: str | None
    subgroups: tuple[str, ...] = ()
    kinematics: KinematicsSettings | None = None
    end_effector: str | None = None
    robot: str | None = None
    planner: OmplGroupSettings | None = None

    @property
    def default_planner(self) -> str | None:
        """The OMPL planner ``ompl_planning.yaml`` gives this group by default (its
        type, ``geometric::RRTConnect``, else the configuration's name), if any."""
        if self.planner is None:
            return None
        return self.planner.planner_type or self.planner.default_planner_config

    @property
    def position_only_ik(self) -> bool:
        return bool(self.kinematics and self.kinematics.position_only_ik)


@dataclass(frozen=True)
class EndEffector:
    name: str
    parent_link: str
    group: str
    parent_group: str | None


@dataclass(frozen=True)
class RobotInstance:
    """One robot placed in the model.

    Attributes:
        name: the instance name ("left", "right", or the robot's own name).
        prefix: put before every link, joint, group and pose-group name of this robot.
        base: placement of the robot's root link in the world frame.
        source: the file it was loaded from.
        hardware_path: its hardware.yaml (servo calibration), if it has one.
    """

    name: str
    prefix: str
    base: pin.SE3
    source: Path
    hardware_path: Path | None = None
    velocity_scaling: float = 1.0
    acceleration_scaling: float = 1.0
    layout: str = ""
    files: tuple[tuple[str, Path], ...] = ()
    notes: tuple[str, ...] = ()
    collision: str = CollisionChoice.AUTO
    """Link geometry to check: exact meshes, convex hulls, or auto (hulls where tight)."""
    cartesian_limits: CartesianLimits | None = None
    """Its ``pilz_cartesian_limits.yaml``: bounds of straight-line tool motions."""

    def describe_files(self) -> list[str]:
        """Which files the robot was loaded from and why, for ``run-task info``."""
        out = [f"loaded as: {self.layout}"] if self.layout else []
        out += [f"{role}: {path}" for role, path in self.files]
        out += [f"note: {note}" for note in self.notes]
        return out


@dataclass
class RobotModel:
    """See the module docstring. Built by :func:`taskrunner.robot.build_model`."""

    name: str
    model: pin.Model
    collision_model: pin.GeometryModel
    joints: tuple[JointInfo, ...]
    groups: dict[str, Group]
    named_states: dict[str, dict[str, dict[str, float]]]
    end_effectors: dict[str, EndEffector]
    disabled_collisions: dict[frozenset[str], str]
    instances: tuple[RobotInstance, ...]
    urdf_xml: str
    warnings: list[str] = field(default_factory=list)
    pose_aliases: dict[str, dict[str, str]] = field(default_factory=dict)
    initial_values: dict[str, float] = field(default_factory=dict)
    """Joint values of the robots' ``initial_positions.yaml`` (the start state)."""
    """group → {alias: pose}: a gripper's other spelling of ``open``/``closed``."""

    def __post_init__(self) -> None:
        self.joint_names: tuple[str, ...] = tuple(j.name for j in self.joints)
        self._joint_by_name = {j.name: j for j in self.joints}
        self.lower = np.array([j.lower for j in self.joints])
        self.upper = np.array([j.upper for j in self.joints])
        self.max_velocity = np.array([j.max_velocity for j in self.joints])
        self.max_acceleration = np.array([j.max_acceleration for j in self.joints])
        self.data = self.model.createData()
        self.link_names: tuple[str, ...] = tuple(
            f.name for f in self.model.frames if f.type in (pin.BODY,)
        )
        # State vector ↔ pinocchio q.
        simple_q, simple_idx, cont_q, cont_idx = [], [], [], []
        for joint in self.joints:
            pin_joint = self.model.joints[self.model.getJointId(joint.name)]
            if pin_joint.nq == 1:
                simple_q.append(pin_joint.idx_q)
                simple_idx.append(joint.index)
            else:
                cont_q.append(pin_joint.idx_q)
                cont_idx.append(joint.index)
        self._identity_q = (
            not cont_q and self.model.nq == len(self.joints) and simple_q == list(range(len(simple_q)))
        )
        self._simple_q, self._simple_idx = np.array(simple_q, int), np.array(simple_idx, int)
        self._cont_q, self._cont_idx = np.array(cont_q, int), np.array(cont_idx, int)
        self._mimic = [
            (j.index, self._joint_by_name[j.mimic.source].index, j.mimic.multiplier, j.mimic.offset)
            for j in self.joints
            if j.mimic is not None
        ]
        self.active_indices = np.array(
            [j.index for j in self.joints if j.mimic is None and not j.passive], int
        )

    # ----------------------------------------------------------------- lookups
    @property
    def nq(self) -> int:
        """Length of a state vector."""
        return len(self.joints)

    def joint(self, name: str) -> JointInfo:
        try:
            return self._joint_by_name[name]
        except KeyError:
            raise UnknownNameError("joint", name, self.joint_names) from None

    def group(self, name: str) -> Group:
        try:
            return self.groups[name]
        except KeyError:
            raise UnknownNameError("group", name, list(self.groups)) from None

    def frame_id(self, name: str) -> int:
        """Pinocchio frame index of a link or frame."""
        if self.model.existFrame(name, pin.BODY):
            return int(self.model.getFrameId(name, pin.BODY))
        if self.model.existFrame(name):
            return int(self.model.getFrameId(name))
        raise UnknownNameError("link", name, self.link_names)

    def has_link(self, name: str) -> bool:
        return bool(self.model.existFrame(name))

    def indices(self, joint_names: Iterable[str]) -> np.ndarray:
        """State-vector positions of ``joint_names``."""
        return np.array([self.joint(n).index for n in joint_names], dtype=int)

    # ----------------------------------------------------------------- states
    def default_state(self) -> np.ndarray:
        """Zero for every joint, moved inside its limits where zero is outside them."""
        q = np.clip(np.zeros(self.nq), self.lower, self.upper)
        return self.apply_mimic(q)

    def named_state_names(self, group: str) -> list[str]:
        self.group(group)
        return sorted(self.named_states.get(group, {}))

    def links_without_collision_geometry(self) -> list[str]:
        """Links (not the world frame) that have no collision geometry, in model order."""
        with_geometry = {self.model.frames[g.parentFrame].name
                         for g in self.collision_model.geometryObjects}
        return [link for link in self.link_names
                if link not in with_geometry and link != "world"]

    def named_state(self, group: str, name: str) -> JointState:
        """The values of named pose ``name`` of ``group`` (the joints it sets)."""
        states = self.named_states.get(self.group(group).name, {})
        if name not in states:
            raise UnknownNameError(f"named pose of group {group!r}", name, list(states))
        return JointState.from_mapping(states[name])

    def state_with(self, q: np.ndarray, values: Mapping[str, float] | JointState) -> np.ndarray:
        """A copy of ``q`` with the given joints set (mimic joints then follow)."""
        out = np.array(q, dtype=float, copy=True)
        items = values.as_dict().items() if isinstance(values, JointState) else values.items()
        for name, value in items:
            out[self.joint(name).index] = float(value)
        return self.apply_mimic(out)

    def mimic_follows(self, indices: Sequence[int] | np.ndarray) -> bool:
        """True if some mimic joint follows one of the state indices ``indices``,
        directly or through other mimic joints (moving them needs :meth:`apply_mimic`)."""
        if not self._mimic:
            return False
        moved = set(np.asarray(indices, dtype=int).reshape(-1).tolist())
        followed = False
        changed = True
        while changed:
            changed = False
            for index, source, _, _ in self._mimic:
                if source in moved and index not in moved:
                    moved.add(index)
                    followed = changed = True
        return followed

    def apply_mimic(self, q: np.ndarray) -> np.ndarray:
        """Set every mimic joint from its source joint, in place; returns ``q`` (one state
        vector, or one per row)."""
        for index, source, multiplier, offset in self._mimic:
            q[..., index] = multiplier * q[..., source] + offset
        return q

    def within_limits(self, q: np.ndarray, tolerance: float = LIMIT_TOLERANCE) -> bool:
        """Whether every joint of ``q`` is within its limits, up to ``tolerance``."""
        return bool(np.all(q >= self.lower - tolerance) and np.all(q <= self.upper + tolerance))

    def limit_violations(self, q: np.ndarray, tolerance: float = LIMIT_TOLERANCE) -> list[str]:
        """One line per joint of ``q`` outside its limits by more than ``tolerance`` (the
        same test as :meth:`within_limits`), with the value, the bound and the excess
        (:func:`describe_excess`)."""
        out = []
        for j in self.joints:
            v = float(q[j.index])
            if v < j.lower - tolerance or v > j.upper + tolerance:
                bound = j.lower if v < j.lower else j.upper
                out.append(describe_excess(j.name, v, bound, "m" if j.type == "prismatic"
                                           else "rad"))
        return out

    def random_state(self, rng: np.random.Generator, group: str | None = None,
                     base: np.ndarray | None = None) -> np.ndarray:
        """A uniformly random state within limits (continuous joints in [-pi, pi]).

        Only ``group``'s joints are drawn when given; the others keep ``base``
        (default: :meth:`default_state`).
        """
        q = np.array(base if base is not None else self.default_state(), dtype=float)
        idx = self.group(group).joint_indices if group else self.active_indices
        lo = np.where(np.isfinite(self.lower[idx]), self.lower[idx], -np.pi)
        hi = np.where(np.isfinite(self.upper[idx]), self.upper[idx], np.pi)
        q[idx] = rng.uniform(lo, hi)
        return self.apply_mimic(q)

    def to_pin(self, q: np.ndarray) -> np.ndarray:
        """Pinocchio configuration of state vector ``q`` (or one per row of ``q``)."""
        if self._identity_q:
            return np.asarray(q, dtype=float)
        q = np.asarray(q, dtype=float)
        out = np.zeros(q.shape[:-1] + (self.model.nq,))
        out[..., self._simple_q] = q[..., self._simple_idx]
        if len(self._cont_q):
            angles = q[..., self._cont_idx]
            out[..., self._cont_q] = np.cos(angles)
            out[..., self._cont_q + 1] = np.sin(angles)
        return out

    def from_pin(self, q_pin: np.ndarray) -> np.ndarray:
        """State vector of pinocchio configuration ``q_pin``."""
        if self._identity_q:
            return np.array(q_pin, dtype=float)
        out = np.zeros(self.nq)
        out[self._simple_idx] = q_pin[self._simple_q]
        if len(self._cont_q):
            out[self._cont_idx] = np.arctan2(q_pin[self._cont_q + 1], q_pin[self._cont_q])
        return out

    def velocity_columns(self, joint_names: Sequence[str]) -> np.ndarray:
        """Columns of a pinocchio Jacobian (tangent indices) for ``joint_names``."""
        return np.array(
            [self.model.joints[self.model.getJointId(n)].idx_v for n in joint_names], dtype=int
        )

    def instance(self, name: str) -> RobotInstance:
        for inst in self.instances:
            if inst.name == name:
                return inst
        raise UnknownNameError("robot", name, [i.name for i in self.instances])
