"""Assembling robot descriptions into one :class:`~taskrunner.robot.model.RobotModel`.

Each description is copied with its name prefix, hung under a common ``world`` link at
its base pose, and the result is loaded by pinocchio as one tree. The SRDF, the MoveIt
YAML and the cell's own additions are then checked against that tree: every group,
named pose, end effector, limit override and IK setting must name things that exist,
and every named pose must lie within the joint limits.
"""

from __future__ import annotations

import dataclasses
import logging
import xml.etree.ElementTree as ET
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import cast

import numpy as np
import pinocchio as pin

from taskrunner.errors import RobotDescriptionError, YamlError
from taskrunner.kinds import CollisionChoice
from taskrunner.robot.description import RobotDescription
from taskrunner.robot.missing_meshes import check_robot_geometry, resolve_allow_missing_meshes
from taskrunner.robot.model import (
    EndEffector,
    Group,
    JointInfo,
    Mimic,
    RobotInstance,
    RobotModel,
    describe_excess,
)
from taskrunner.robot.notes import LoadWarning, raise_if_strict
from taskrunner.robot.selfcollision import self_collision_warnings
from taskrunner.robot.srdf import Srdf, SrdfEndEffector, SrdfGroupState
from taskrunner.robot.urdf import MOVABLE_TYPES, prefixed_copy

__all__ = ["Placement", "build_model"]

log = logging.getLogger(__name__)

WORLD = "world"
# A named pose may sit this far outside a limit (MoveIt configs round to 4-6 digits).
POSE_LIMIT_TOLERANCE = 1e-6
# A mimic joint's value in a named pose may differ this much from its relation's.
MIMIC_TOLERANCE = 1e-4
# The gripper actions' pose names and the other spelling MoveIt configs use for each.
GRIPPER_POSE_SPELLINGS = (("open", "opened"), ("closed", "close"))


@dataclass(frozen=True)
class Placement:
    """A robot description to place in a model.

    Attributes:
        description: the robot's files.
        name: instance name (defaults to the description's name).
        prefix: put before all of its link, joint and group names.
        base: pose of its root link in the world frame.
        extra_states: more named poses, ``{group: {pose: {joint: value}}}`` with the
            robot's own (unprefixed) names; from a cell file.
        extra_states_source: where those came from, for error messages.
    """

    description: RobotDescription
    name: str = ""
    prefix: str = ""
    base: pin.SE3 = field(default_factory=pin.SE3.Identity)
    extra_states: Mapping[str, Mapping[str, Mapping[str, float]]] = field(default_factory=dict)
    extra_states_lines: Mapping[tuple[str, str], tuple[str, int | None]] = field(
        default_factory=dict
    )


@dataclass
class _Tree:
    """The merged URDF's structure, by (prefixed) name."""

    joint_elements: dict[str, ET.Element] = field(default_factory=dict)
    parent_of_link: dict[str, tuple[str, str]] = field(default_factory=dict)  # child → (joint, parent)
    links: list[str] = field(default_factory=list)
    # (tag, name) → instance name; URDF allows a link and a joint to share a name.
    owner: dict[tuple[str, str], str] = field(default_factory=dict)


def build_model(
    placements: Sequence[Placement],
    name: str | None = None,
    extra_groups: Mapping[str, Sequence[str]] | None = None,
    strict: bool | None = None,
    check_self_collision: bool = True,
    allow_missing_meshes: bool | None = None,
    collision: CollisionChoice | None = None,
) -> RobotModel:
    """Build one model from one or more placed robot descriptions.

    Args:
        placements: the robots, each with its prefix and base pose.
        name: the model's name (default: the single robot's name, or the joined names).
        extra_groups: groups made of (prefixed) subgroups, e.g. ``{"both_arms":
            ["left_arm", "right_arm"]}``; a named pose that every subgroup has becomes
            a named pose of the new group too.
        strict: turn every warning (content MoveIt would skip, a missing mesh, a named
            pose in self-collision…) into an error (None: no).
        check_self_collision: warn when the default state or a named pose is in
            self-collision (see :mod:`taskrunner.robot.selfcollision`).
        allow_missing_meshes: load a robot whose mesh files cannot be found, or that has
            no collision geometry at all, without that geometry (one warning per robot;
            see :mod:`taskrunner.robot.missing_meshes`; None: no).
        collision: every robot's link geometry (None: each description's own, else auto).

    Raises:
        MissingMeshError: a robot's mesh files cannot be found, or it has no collision
            geometry, and ``allow_missing_meshes`` is not set.
        RobotDescriptionError, YamlError: names clash, a URDF is broken, a named pose is
            outside the limits; in strict mode, any warning.
    """
    if not placements:
        raise RobotDescriptionError("a model needs at least one robot")
    placements = [
        p if p.name else Placement(p.description, p.description.name, p.prefix, p.base,
                                   p.extra_states, p.extra_states_lines)
        for p in placements
    ]
    names = [p.name for p in placements]
    if len(set(names)) != len(names):
        raise RobotDescriptionError(f"robot instance names must be unique (got {names})")
    model_name = name or "+".join(names)
    warnings: list[LoadWarning] = [w for p in placements for w in p.description.warnings]
    # Explicitly allowed, so logged but never raised by strict mode.
    allowed_losses = _check_geometry(placements, allow_missing_meshes)
    xml, tree = _merge_urdf(placements, model_name, warnings)
    model, collision_model = _load_pinocchio(xml, placements)
    joints = _joint_infos(model, tree, placements, warnings)
    by_name = {j.name: j for j in joints}
    instances = tuple(
        RobotInstance(
            p.name, p.prefix, pin.SE3(p.base), p.description.source, p.description.hardware_path,
            *_scaling(p.description), p.description.layout,
            tuple(p.description.files.items()), tuple(p.description.notes),
            _collision_choice(p.description, collision), p.description.cartesian_limits,
        )
        for p in placements
    )
    groups: dict[str, Group] = {}
    states: dict[str, dict[str, dict[str, float]]] = {}
    end_effectors: dict[str, EndEffector] = {}
    disabled: dict[frozenset[str], str] = {}
    initial: dict[str, float] = {}
    for p in placements:
        srdf = p.description.srdf
        if srdf is not None:
            _add_srdf(srdf, p, tree, by_name, groups, states, end_effectors, disabled, warnings)
        _add_kinematics(p, groups, warnings)
        _add_ompl(p, groups, warnings)
        _add_initial_positions(p, by_name, initial, warnings)
        _add_extra_states(p, groups, by_name, states)
    aliases = _add_gripper_aliases(end_effectors, states)
    for group_name, subgroups in (extra_groups or {}).items():
        _add_composite_group(group_name, list(subgroups), groups, states, by_name)
    _add_adjacent_pairs(model, collision_model, tree, disabled)
    robot = RobotModel(
        name=model_name,
        model=model,
        collision_model=collision_model,
        joints=tuple(joints),
        groups=groups,
        named_states=states,
        end_effectors=end_effectors,
        disabled_collisions=disabled,
        instances=instances,
        urdf_xml=xml,
        pose_aliases=aliases,
        initial_values=initial,
    )
    if check_self_collision:
        warnings += self_collision_warnings(robot)
    unique = list(dict.fromkeys(warnings))
    raise_if_strict(unique, strict)
    unique = allowed_losses + unique
    robot.warnings = [str(w) for w in unique]
    for warning in unique:
        log.warning("%s", warning)
    return robot


def _check_geometry(placements: Sequence[Placement],
                    allow_missing_meshes: bool | None) -> list[LoadWarning]:
    """Every robot's mesh files found and some collision geometry, or the opt-out (see
    :mod:`taskrunner.robot.missing_meshes`): one warning per robot description."""
    allow = resolve_allow_missing_meshes(allow_missing_meshes)
    found: list[LoadWarning] = []
    for description in {id(p.description.urdf): p.description for p in placements}.values():
        urdf = description.urdf
        collisions = sum(1 for link in urdf.root.findall("link")
                         for _ in link.findall("collision"))
        warning = check_robot_geometry(description.name, urdf.source, urdf.missing_meshes,
                                       collisions, allow)
        if warning is not None:
            found.append(warning)
    return found


def _collision_choice(description: RobotDescription, override: CollisionChoice | None) -> str:
    """``override`` (``LoadOptions.collision``), else the robot's own choice, else auto."""
    if override is not None and override not in tuple(CollisionChoice):
        raise RobotDescriptionError(
            f"'collision' must be one of exact, convex, auto (got {override!r})")
    return override or description.collision or CollisionChoice.AUTO


def _scaling(description: RobotDescription) -> tuple[float, float]:
    limits = description.joint_limits
    if limits is None:
        return 1.0, 1.0
    return limits.default_velocity_scaling_factor, limits.default_acceleration_scaling_factor


# --------------------------------------------------------------------------- URDF merge
def _origin(transform: pin.SE3) -> ET.Element:
    rpy = pin.rpy.matrixToRpy(transform.rotation)
    return ET.Element(
        "origin",
        xyz=" ".join(f"{v:.12g}" for v in transform.translation),
        rpy=" ".join(f"{v:.12g}" for v in rpy),
    )


def _joint_link(joint: ET.Element, role: str) -> str:
    """The link named by a joint element's ``<parent>`` or ``<child>`` (``role``); both are
    there by construction (the URDF's structure was checked when it was loaded)."""
    return cast(str, cast(ET.Element, joint.find(role)).get("link"))


def _premultiply_origin(joint: ET.Element, base: pin.SE3) -> None:
    origin = joint.find("origin")
    xyz = [float(v) for v in (origin.get("xyz", "0 0 0") if origin is not None else "0 0 0").split()]
    rpy = [float(v) for v in (origin.get("rpy", "0 0 0") if origin is not None else "0 0 0").split()]
    local = pin.SE3(pin.rpy.rpyToMatrix(*rpy), np.array(xyz))
    if origin is not None:
        joint.remove(origin)
    joint.insert(0, _origin(base * local))


def _merge_urdf(placements: Sequence[Placement], model_name: str,
                warnings: list[LoadWarning]) -> tuple[str, _Tree]:
    merged = ET.Element("robot", name=model_name)
    ET.SubElement(merged, "link", name=WORLD)
    tree = _Tree(links=[WORLD])
    tree.owner[("link", WORLD)] = ""
    for p in placements:
        urdf = p.description.urdf
        root = prefixed_copy(urdf, p.prefix)
        root_link = p.prefix + urdf.root_link
        srdf = p.description.srdf
        mounts = [vj.name for vj in (srdf.virtual_joints if srdf else [])
                  if vj.child_link == urdf.root_link]
        mount_name = p.prefix + (mounts[0] if mounts else "world_joint")
        # A URDF whose root link is itself called "world" (no prefix) shares our world link:
        # its top joints take the base pose instead of a mount joint.
        shares_world = root_link == WORLD
        if srdf is not None:
            for vj in srdf.virtual_joints:
                if vj.child_link != urdf.root_link:
                    warnings.append(LoadWarning(
                        f"virtual_joint {vj.name!r}: child_link {vj.child_link!r} is not the "
                        f"URDF's root link {urdf.root_link!r}; skipped", srdf.path, vj.line))
        for element in root:
            if element.tag not in ("link", "joint", "material"):
                continue
            element_name = element.get("name", "")
            if shares_world and element.tag == "link" and element_name == WORLD:
                continue
            if shares_world and element.tag == "joint":
                parent_el = element.find("parent")
                if parent_el is not None and parent_el.get("link") == WORLD:
                    _premultiply_origin(element, p.base)
            if element.tag in ("link", "joint"):
                key = (element.tag, element_name)
                if key in tree.owner or (element.tag == "link" and element_name == WORLD):
                    other = tree.owner.get(key, "the world frame")
                    raise RobotDescriptionError(
                        f"{element.tag} {element_name!r} of robot {p.name!r} clashes with "
                        f"{other or 'the world frame'}; give the robots different prefixes",
                        p.description.source,
                    )
                tree.owner[key] = p.name
            if element.tag == "link":
                tree.links.append(element_name)
            elif element.tag == "joint":
                tree.joint_elements[element_name] = element
                parent = _joint_link(element, "parent")
                child = _joint_link(element, "child")
                tree.parent_of_link[child] = (element_name, parent)
            merged.append(element)
        if shares_world:
            continue
        if ("joint", mount_name) in tree.owner:
            raise RobotDescriptionError(
                f"joint {mount_name!r} clashes with another robot's; give the robots "
                "different prefixes", p.description.source,
            )
        mount = ET.SubElement(merged, "joint", name=mount_name, type="fixed")
        mount.append(_origin(p.base))
        ET.SubElement(mount, "parent", link=WORLD)
        ET.SubElement(mount, "child", link=root_link)
        tree.owner[("joint", mount_name)] = p.name
        tree.joint_elements[mount_name] = mount
        tree.parent_of_link[root_link] = (mount_name, WORLD)
    return ET.tostring(merged, encoding="unicode"), tree


def _load_pinocchio(
    xml: str, placements: Sequence[Placement]
) -> tuple[pin.Model, pin.GeometryModel]:
    sources = ", ".join(str(p.description.source) for p in placements)
    try:
        model = pin.buildModelFromXML(xml)
    except Exception as exc:  # pinocchio raises ValueError / RuntimeError with its own text
        raise RobotDescriptionError(f"pinocchio could not build the model: {exc}", sources) from None
    try:
        collision_model = pin.buildGeomFromUrdfString(model, xml, pin.COLLISION)
    except Exception as exc:
        raise RobotDescriptionError(
            f"could not load the collision geometry: {exc}", sources
        ) from None
    return model, collision_model


# --------------------------------------------------------------------------- joints
def _joint_infos(model: pin.Model, tree: _Tree, placements: Sequence[Placement],
                 warnings: list[LoadWarning]) -> list[JointInfo]:
    by_instance = {p.name: p for p in placements}
    joints: list[JointInfo] = []
    overrides_used: set[tuple[str, str]] = set()
    for jid in range(1, model.njoints):
        name = model.names[jid]
        element = tree.joint_elements[name]
        jtype = element.get("type", "")
        if jtype not in MOVABLE_TYPES:  # pragma: no cover - pinocchio only makes these
            raise RobotDescriptionError(f"joint {name!r}: unsupported type {jtype!r}")
        instance = tree.owner[("joint", name)]
        placement = by_instance[instance]
        limit = element.find("limit")
        lower, upper = -np.inf, np.inf
        if jtype != "continuous" and limit is not None:
            lower, upper = float(limit.get("lower", 0)), float(limit.get("upper", 0))
        velocity = float(limit.get("velocity", "inf")) if limit is not None else np.inf
        if velocity <= 0:
            velocity = np.inf
        acceleration = np.inf
        config = placement.description.joint_limits
        unprefixed = name[len(placement.prefix):]
        if config is not None and config.joints and unprefixed in config.joints:
            override = config.joints[unprefixed]
            overrides_used.add((instance, unprefixed))
            lower = override.min_position if override.min_position is not None else lower
            upper = override.max_position if override.max_position is not None else upper
            velocity = override.max_velocity if override.max_velocity is not None else velocity
            acceleration = (
                override.max_acceleration if override.max_acceleration is not None else acceleration
            )
        mimic_el = element.find("mimic")
        mimic = None
        if mimic_el is not None:
            mimic = Mimic(
                mimic_el.get("joint", ""),
                float(mimic_el.get("multiplier", 1.0)),
                float(mimic_el.get("offset", 0.0)),
            )
        parent = element.find("parent").get("link", "")  # type: ignore[union-attr]
        child = element.find("child").get("link", "")  # type: ignore[union-attr]
        passive = bool(
            placement.description.srdf
            and unprefixed in placement.description.srdf.passive_joints
        )
        joints.append(
            JointInfo(name, jtype, len(joints), lower, upper, velocity, acceleration,
                      parent, child, instance, mimic, passive)
        )
    for p in placements:
        config = p.description.joint_limits
        srdf = p.description.srdf
        known = {j.name[len(p.prefix):] for j in joints if j.robot == p.name}
        if config is not None and config.joints:
            for joint_name, override in config.joints.items():
                if joint_name not in known:
                    raise YamlError(
                        f"joint {joint_name!r} is not a movable joint of robot {p.name!r} "
                        f"(movable joints: {', '.join(sorted(known))})",
                        config.path,
                        override.line,
                    )
        if srdf is not None:
            for joint_name in srdf.passive_joints:
                if joint_name not in known:
                    warnings.append(LoadWarning(
                        f"passive_joint {joint_name!r} is not a movable joint of the URDF; "
                        "skipped", srdf.path, srdf.passive_lines.get(joint_name)))
    return joints


# --------------------------------------------------------------------------- SRDF
def _chain(tree: _Tree, base: str, tip: str) -> list[tuple[str, str]] | None:
    """(joint, child link) pairs from ``base`` down to ``tip``, or None if tip is not below."""
    path: list[tuple[str, str]] = []
    link = tip
    while link != base:
        if link not in tree.parent_of_link:
            return None
        joint, parent = tree.parent_of_link[link]
        path.append((joint, link))
        link = parent
    return list(reversed(path))


def _add_srdf(
    srdf: Srdf,
    p: Placement,
    tree: _Tree,
    joints: dict[str, JointInfo],
    groups: dict[str, Group],
    states: dict[str, dict[str, dict[str, float]]],
    end_effectors: dict[str, EndEffector],
    disabled: dict[frozenset[str], str],
    warnings: list[LoadWarning],
) -> None:
    """Check the SRDF against the merged tree. What MoveIt skips (with a log line) is
    skipped with a warning; a named pose outside the joint limits is an error."""
    pre = p.prefix
    own_links = {link for link in tree.links if tree.owner.get(("link", link)) == p.name}
    own_joints = {j for j in tree.joint_elements if tree.owner.get(("joint", j)) == p.name}

    def warn(line: int | None, message: str) -> None:
        warnings.append(LoadWarning(message, srdf.path, line))

    eef_of_group: dict[str, SrdfEndEffector] = {}
    for eef in srdf.end_effectors:
        if pre + eef.parent_link not in own_links:
            warn(eef.line, f"end_effector {eef.name!r}: parent_link {eef.parent_link!r} is "
                           "not a link of the URDF; end effector skipped")
            continue
        if eef.group not in srdf.groups:
            warn(eef.line, f"end_effector {eef.name!r}: group {eef.group!r} is not defined "
                           "in the SRDF; end effector skipped")
            continue
        parent_group = eef.parent_group
        if parent_group is not None and parent_group not in srdf.groups:
            warn(eef.line, f"end_effector {eef.name!r}: parent_group {parent_group!r} is not "
                           "defined in the SRDF; the end effector has no parent group")
            parent_group = None
        end_effectors[pre + eef.name] = EndEffector(
            pre + eef.name, pre + eef.parent_link, pre + eef.group,
            pre + parent_group if parent_group else None,
        )
        owner = parent_group or eef.group
        eef_of_group.setdefault(owner, eef)

    resolved: dict[str, tuple[list[str], list[str], str, str | None]] = {}

    def resolve(group_name: str, stack: tuple[str, ...]) -> tuple[list[str], list[str], str, str | None]:
        if group_name in resolved:
            return resolved[group_name]
        group = srdf.groups[group_name]
        joint_list: list[str] = []
        link_list: list[str] = []
        base: str | None = None
        tip: str | None = None
        for chain_base, chain_tip in group.chains:
            line = group.member_line("chain", chain_tip)
            unknown = [link for link in (chain_base, chain_tip) if pre + link not in own_links]
            if unknown:
                warn(line, f"group {group_name!r}: chain link {unknown[0]!r} is not a link "
                           "of the URDF; chain skipped")
                continue
            chain = _chain(tree, pre + chain_base, pre + chain_tip)
            if chain is None:
                warn(line, f"group {group_name!r}: chain tip {chain_tip!r} is not below base "
                           f"{chain_base!r} in the URDF tree; chain skipped")
                continue
            joint_list += [j for j, _ in chain]
            link_list += [link for _, link in chain]
            base = base or pre + chain_base
            tip = pre + chain_tip
        for joint_name in group.joints:
            if pre + joint_name not in own_joints:
                warn(group.member_line("joint", joint_name),
                     f"group {group_name!r}: joint {joint_name!r} is not a joint of the URDF; "
                     "skipped")
                continue
            joint_list.append(pre + joint_name)
            link_list.append(_joint_link(tree.joint_elements[pre + joint_name], "child"))
        for link in group.links:
            if pre + link not in own_links:
                warn(group.member_line("link", link),
                     f"group {group_name!r}: link {link!r} is not a link of the URDF; skipped")
                continue
            link_list.append(pre + link)
            if pre + link in tree.parent_of_link:
                joint_list.append(tree.parent_of_link[pre + link][0])
        for sub in group.subgroups:
            line = group.member_line("group", sub)
            if sub not in srdf.groups:
                warn(line, f"group {group_name!r}: subgroup {sub!r} is not defined in the "
                           "SRDF; skipped")
                continue
            if sub in stack:
                warn(line, f"group {group_name!r}: subgroups form a cycle "
                           f"({' -> '.join((*stack, sub))}); subgroup skipped")
                continue
            sub_joints, sub_links, sub_base, sub_tip = resolve(sub, (*stack, sub))
            joint_list += sub_joints
            link_list += sub_links
            base = base or sub_base
            tip = tip or sub_tip
        if base is None:
            first = next((j for j in joint_list if j in tree.joint_elements), None)
            base = (_joint_link(tree.joint_elements[first], "parent")
                    if first else pre + p.description.urdf.root_link)
        if not joint_list and not link_list:
            warn(group.line, f"group {group_name!r} is empty")
        resolved[group_name] = (joint_list, link_list, base, tip)
        return resolved[group_name]

    for group_name, group in srdf.groups.items():
        joint_list, link_list, base, tip = resolve(group_name, (group_name,))
        group_eef = eef_of_group.get(group_name)
        if tip is None and group_eef is not None:
            tip = pre + group_eef.parent_link
        if tip is None and not group.subgroups:
            movable = [j for j in joint_list if j in joints]
            if movable and _is_serial(tree, movable):
                tip = joints[movable[-1]].child_link
        active = [n for n in _model_order(joints, joint_list)
                  if joints[n].mimic is None and not joints[n].passive]
        full_name = pre + group_name
        if full_name in groups:
            raise srdf.error(group.line, f"group {full_name!r} is defined twice")
        groups[full_name] = Group(
            name=full_name,
            joint_names=tuple(active),
            joint_indices=np.array([joints[n].index for n in active], dtype=int),
            links=tuple(dict.fromkeys(link_list)),
            base_link=base,
            tip_link=tip,
            subgroups=tuple(pre + s for s in group.subgroups if s in srdf.groups),
            end_effector=pre + group_eef.name if group_eef is not None else None,
            robot=p.name,
        )

    for state in srdf.group_states:
        if state.group not in srdf.groups:
            warn(state.line, f"group_state {state.name!r}: group {state.group!r} is not "
                             "defined; named pose skipped")
            continue
        model_group = groups[pre + state.group]
        if state.name in states.get(model_group.name, {}):
            warn(state.line, f"group_state {state.name!r} of group {state.group!r} is "
                             "defined twice; the first definition is kept")
            continue
        group_joints = set(resolve(state.group, (state.group,))[0])
        values = _state_values(srdf, state, pre, group_joints, joints, warn)
        if values is not None:
            states.setdefault(model_group.name, {})[state.name] = values

    for pair in srdf.disabled_collisions:
        a, b = pre + pair.link1, pre + pair.link2
        missing = [x for x in (pair.link1, pair.link2) if pre + x not in own_links]
        if missing:
            warn(pair.line, f"disable_collisions names unknown link(s) {missing}; entry ignored")
            continue
        disabled[frozenset((a, b))] = pair.reason or "SRDF"
    for pair in srdf.enabled_collisions:
        disabled.pop(frozenset((pre + pair.link1, pre + pair.link2)), None)


def _state_values(srdf: Srdf, state: SrdfGroupState, pre: str, group_joints: set[str],
                  joints: dict[str, JointInfo],
                  warn: Callable[[int | None, str], None]) -> dict[str, float] | None:
    """The values a named pose sets: its group's active joints. A mimic joint's
    value is checked against its relation, then left to follow its source (a value of its
    own would put the state off the relation). Fixed joints set nothing. None, with a
    warning, for a pose outside the joint limits (MoveIt loads it, then cannot plan to it)."""
    values: dict[str, float] = {}
    mimics: list[tuple[str, float, int | None]] = []
    for joint_name, value in state.values.items():
        line = state.value_lines.get(joint_name, state.line)
        full = pre + joint_name
        if full not in group_joints:
            warn(line, f"group_state {state.name!r}: joint {joint_name!r} is not in group "
                       f"{state.group!r}; value skipped")
            continue
        if full not in joints:
            continue  # a fixed joint listed in a pose: nothing to set
        try:
            _check_in_limits(joints[full], value, lambda msg, line=line: srdf.error(line, msg),
                             f"group_state {state.name!r}")
        except RobotDescriptionError as exc:
            warn(line, f"{exc.reason}; named pose skipped")
            return None
        if joints[full].mimic is not None:
            mimics.append((full, value, line))
        elif not joints[full].passive:  # nothing moves a passive joint (MoveIt's rule too)
            values[full] = value
    for full, value, line in mimics:
        mimic = joints[full].mimic
        assert mimic is not None
        if mimic.source not in values:
            continue  # its source is not in the pose: the source's own value decides
        expected = mimic.multiplier * values[mimic.source] + mimic.offset
        if abs(expected - value) > MIMIC_TOLERANCE:
            warn(line, f"group_state {state.name!r}: mimic joint {full[len(pre):]!r} = "
                       f"{value:g} does not follow its relation ({mimic.multiplier:g} × "
                       f"{mimic.source[len(pre):]!r} + {mimic.offset:g} = {expected:g}); "
                       "the relation's value is used")
    return values


def _add_gripper_aliases(end_effectors: Mapping[str, EndEffector],
                         states: dict[str, dict[str, dict[str, float]]]
                         ) -> dict[str, dict[str, str]]:
    """Let a gripper open and close whichever way its SRDF spells the poses (MoveIt
    configs say ``open`` or ``opened``, ``closed`` or ``close``): when an end effector's
    group lacks ``open`` (``closed``) but has ``opened`` (``close``), the name the
    ``gripper`` actions use becomes an alias of it."""
    aliases: dict[str, dict[str, str]] = {}
    for eef in end_effectors.values():
        poses = states.get(eef.group)
        if not poses:
            continue
        for canonical, other in GRIPPER_POSE_SPELLINGS:
            if canonical not in poses and other in poses:
                poses[canonical] = dict(poses[other])
                aliases.setdefault(eef.group, {})[canonical] = other
    return aliases


def _check_in_limits(joint: JointInfo, value: float, error, what: str) -> None:  # type: ignore[no-untyped-def]
    if value < joint.lower - POSE_LIMIT_TOLERANCE or value > joint.upper + POSE_LIMIT_TOLERANCE:
        bound = joint.lower if value < joint.lower else joint.upper
        raise error(f"{what}: {_excess(joint, value, bound)} (limits [{joint.lower:.10g}, "
                    f"{joint.upper:.10g}])")


def _excess(joint: JointInfo, value: float, bound: float) -> str:
    return describe_excess(joint.name, value, bound, "m" if joint.type == "prismatic" else "rad")


def _model_order(joints: dict[str, JointInfo], names: list[str]) -> list[str]:
    unique = {n for n in names if n in joints}
    return sorted(unique, key=lambda n: joints[n].index)


def _is_serial(tree: _Tree, joint_names: list[str]) -> bool:
    """True if each joint's child link is an ancestor of the next joint."""
    ordered = joint_names
    for upper, lower in zip(ordered, ordered[1:]):
        child = _joint_link(tree.joint_elements[upper], "child")
        link = _joint_link(tree.joint_elements[lower], "parent")
        while link != child:
            if link not in tree.parent_of_link:
                return False
            link = tree.parent_of_link[link][1]
    return True


def _add_kinematics(p: Placement, groups: dict[str, Group], warnings: list[LoadWarning]) -> None:
    """IK settings per group; an entry for a group the SRDF lacks is unused (as in MoveIt)."""
    for group_name, settings in p.description.kinematics.items():
        full = p.prefix + group_name
        if full not in groups or groups[full].robot != p.name:
            own = sorted(g[len(p.prefix):] for g, v in groups.items() if v.robot == p.name)
            warnings.append(LoadWarning(
                f"group {group_name!r} is not defined in the SRDF (groups: {', '.join(own)}); "
                "its settings are not used", p.description.kinematics_path, settings.line))
            continue
        groups[full] = dataclasses.replace(groups[full], kinematics=settings)


def _add_ompl(p: Placement, groups: dict[str, Group], warnings: list[LoadWarning]) -> None:
    """Each group's default planner; an entry for a group the SRDF lacks is unused."""
    config = p.description.ompl
    if config is None:
        return
    for group_name, settings in config.groups.items():
        full = p.prefix + group_name
        if full not in groups or groups[full].robot != p.name:
            warnings.append(LoadWarning(
                f"group {group_name!r} is not defined in the SRDF; its planner settings are "
                "not used", config.path, settings.line))
            continue
        groups[full] = dataclasses.replace(groups[full], planner=settings)


def _add_initial_positions(p: Placement, joints: dict[str, JointInfo],
                           initial: dict[str, float], warnings: list[LoadWarning]) -> None:
    """The start values of ``initial_positions.yaml``: unknown, mimic or passive joints
    and values outside the limits are skipped with a warning."""
    description = p.description
    for joint_name, value in description.initial_positions.items():
        line = description.initial_positions_lines.get(joint_name)
        full = p.prefix + joint_name
        joint = joints.get(full)
        problem = None
        if joint is None or joint.robot != p.name:
            problem = f"joint {joint_name!r} is not a movable joint of the URDF"
        elif joint.mimic is not None:
            continue  # it follows its source
        elif not (joint.lower - POSE_LIMIT_TOLERANCE <= value
                  <= joint.upper + POSE_LIMIT_TOLERANCE):
            bound = joint.lower if value < joint.lower else joint.upper
            problem = (f"{_excess(joint, value, bound)} (limits [{joint.lower:.10g}, "
                       f"{joint.upper:.10g}])")
        if problem is not None:
            warnings.append(LoadWarning(f"initial_positions: {problem}; skipped",
                                        description.initial_positions_path, line))
            continue
        initial[full] = value


def _add_extra_states(
    p: Placement,
    groups: dict[str, Group],
    joints: dict[str, JointInfo],
    states: dict[str, dict[str, dict[str, float]]],
) -> None:
    for group_name, poses in p.extra_states.items():
        full = p.prefix + group_name
        for pose_name, values in poses.items():
            source, line = p.extra_states_lines.get((group_name, pose_name), (None, None))

            def error(message: str) -> RobotDescriptionError:
                return RobotDescriptionError(message, source, line)

            if full not in groups:
                raise error(f"pose {pose_name!r}: group {group_name!r} is not a group of "
                            f"robot {p.name!r}")
            group = groups[full]
            resolved: dict[str, float] = {}
            for joint_name, value in values.items():
                name = p.prefix + joint_name
                if name not in group.joint_names:
                    raise error(f"pose {pose_name!r}: joint {joint_name!r} is not an active "
                                f"joint of group {group_name!r} ({', '.join(group.joint_names)})")
                _check_in_limits(joints[name], float(value), error, f"pose {pose_name!r}")
                resolved[name] = float(value)
            states.setdefault(full, {})[pose_name] = resolved


def _add_composite_group(
    name: str,
    subgroups: list[str],
    groups: dict[str, Group],
    states: dict[str, dict[str, dict[str, float]]],
    joints: dict[str, JointInfo],
) -> None:
    if name in groups:
        raise RobotDescriptionError(f"group {name!r} already exists")
    missing = [s for s in subgroups if s not in groups]
    if missing:
        raise RobotDescriptionError(f"group {name!r}: unknown subgroups {missing} "
                                    f"(groups: {', '.join(sorted(groups))})")
    parts = [groups[s] for s in subgroups]
    active = _model_order(joints, [j for g in parts for j in g.joint_names])
    groups[name] = Group(
        name=name,
        joint_names=tuple(active),
        joint_indices=np.array([joints[n].index for n in active], dtype=int),
        links=tuple(dict.fromkeys(link for g in parts for link in g.links)),
        base_link=WORLD,
        tip_link=None,
        subgroups=tuple(subgroups),
    )
    common = set.intersection(*(set(states.get(s, {})) for s in subgroups)) if subgroups else set()
    for pose in sorted(common):
        merged: dict[str, float] = {}
        for s in subgroups:
            merged.update(states[s][pose])
        states.setdefault(name, {})[pose] = merged


def _add_adjacent_pairs(
    model: pin.Model,
    collision_model: pin.GeometryModel,
    tree: _Tree,
    disabled: dict[frozenset[str], str],
) -> None:
    """Allow contact between each link with geometry and its nearest ancestor with geometry
    (links joined through geometry-less links count as adjacent, as MoveIt does)."""
    with_geometry = {model.frames[g.parentFrame].name for g in collision_model.geometryObjects}
    for link in with_geometry:
        parent = link
        while parent in tree.parent_of_link:
            parent = tree.parent_of_link[parent][1]
            if parent in with_geometry:
                disabled.setdefault(frozenset((link, parent)), "Adjacent")
                break
