"""Assembling robot descriptions into one :class:`~taskrunner.robot.model.RobotModel`.

Each description is copied with its name prefix, hung under a common ``world`` link at
its base pose, and the result is loaded by pinocchio as one tree. The SRDF, the MoveIt
YAML and the cell's own additions are then checked against that tree: every group,
named pose, end effector, limit override and IK setting must name things that exist,
and every named pose must lie within the joint limits.
"""

from __future__ import annotations

import logging
import xml.etree.ElementTree as ET
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import cast

import numpy as np
import pinocchio as pin

from taskrunner.errors import RobotDescriptionError, YamlError
from taskrunner.robot.description import RobotDescription
from taskrunner.robot.model import EndEffector, Group, JointInfo, Mimic, RobotInstance, RobotModel
from taskrunner.robot.srdf import Srdf, SrdfEndEffector
from taskrunner.robot.urdf import MOVABLE_TYPES, prefixed_copy

__all__ = ["Placement", "build_model"]

log = logging.getLogger(__name__)

WORLD = "world"
# A named pose may sit this far outside a limit (MoveIt configs round to 4-6 digits).
POSE_LIMIT_TOLERANCE = 1e-6


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
) -> RobotModel:
    """Build one model from one or more placed robot descriptions.

    Args:
        placements: the robots, each with its prefix and base pose.
        name: the model's name (default: the single robot's name, or the joined names).
        extra_groups: groups made of (prefixed) subgroups, e.g. ``{"both_arms":
            ["left_arm", "right_arm"]}``; a named pose that every subgroup has becomes
            a named pose of the new group too.

    Raises:
        RobotDescriptionError, YamlError: names clash or a file names something that
            does not exist, a chain is broken, a named pose is outside the limits.
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
    xml, tree = _merge_urdf(placements, model_name)
    model, collision_model = _load_pinocchio(xml, placements)
    joints = _joint_infos(model, tree, placements)
    by_name = {j.name: j for j in joints}
    instances = tuple(
        RobotInstance(
            p.name, p.prefix, pin.SE3(p.base), p.description.source, p.description.hardware_path,
            *_scaling(p.description),
        )
        for p in placements
    )
    groups: dict[str, Group] = {}
    states: dict[str, dict[str, dict[str, float]]] = {}
    end_effectors: dict[str, EndEffector] = {}
    disabled: dict[frozenset[str], str] = {}
    warnings = [w for p in placements for w in p.description.warnings]
    for p in placements:
        srdf = p.description.srdf
        if srdf is not None:
            _add_srdf(srdf, p, tree, by_name, groups, states, end_effectors, disabled, warnings)
        _add_kinematics(p, groups)
        _add_extra_states(p, groups, by_name, states)
    for group_name, subgroups in (extra_groups or {}).items():
        _add_composite_group(group_name, list(subgroups), groups, states, by_name)
    _add_adjacent_pairs(model, collision_model, tree, disabled)
    for message in warnings:
        log.warning("%s", message)
    return RobotModel(
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
        warnings=warnings,
    )


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


def _merge_urdf(placements: Sequence[Placement], model_name: str) -> tuple[str, _Tree]:
    merged = ET.Element("robot", name=model_name)
    ET.SubElement(merged, "link", name=WORLD)
    tree = _Tree(links=[WORLD])
    tree.owner[("link", WORLD)] = ""
    for p in placements:
        urdf = p.description.urdf
        root = prefixed_copy(urdf, p.prefix)
        root_link = p.prefix + urdf.root_link
        srdf = p.description.srdf
        mount_name = p.prefix + (srdf.virtual_joints[0].name if srdf and srdf.virtual_joints
                                 else "world_joint")
        # A URDF whose root link is itself called "world" (no prefix) shares our world link:
        # its top joints take the base pose instead of a mount joint.
        shares_world = root_link == WORLD
        if srdf is not None:
            for vj in srdf.virtual_joints:
                if vj.child_link != urdf.root_link:
                    raise srdf.error(
                        vj.line,
                        f"virtual_joint {vj.name!r}: child_link {vj.child_link!r} is not the "
                        f"URDF's root link {urdf.root_link!r}",
                    )
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
def _joint_infos(model: pin.Model, tree: _Tree, placements: Sequence[Placement]) -> list[JointInfo]:
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
                    raise srdf.error(None, f"passive_joint {joint_name!r} is not a movable joint")
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
    warnings: list[str],
) -> None:
    pre = p.prefix
    own_links = {link for link in tree.links if tree.owner.get(("link", link)) == p.name}
    own_joints = {j for j in tree.joint_elements if tree.owner.get(("joint", j)) == p.name}
    eef_of_group: dict[str, SrdfEndEffector] = {}
    for eef in srdf.end_effectors:
        if pre + eef.parent_link not in own_links:
            raise srdf.error(eef.line, f"end_effector {eef.name!r}: parent_link "
                             f"{eef.parent_link!r} is not a link of the URDF")
        for g in (eef.group, eef.parent_group):
            if g is not None and g not in srdf.groups:
                raise srdf.error(eef.line, f"end_effector {eef.name!r}: group {g!r} is not "
                                 "defined in the SRDF")
        end_effectors[pre + eef.name] = EndEffector(
            pre + eef.name, pre + eef.parent_link, pre + eef.group,
            pre + eef.parent_group if eef.parent_group else None,
        )
        owner = eef.parent_group or eef.group
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
            for link in (chain_base, chain_tip):
                if pre + link not in own_links:
                    raise srdf.error(group.line, f"group {group_name!r}: chain link {link!r} "
                                     "is not a link of the URDF")
            chain = _chain(tree, pre + chain_base, pre + chain_tip)
            if chain is None:
                raise srdf.error(group.line, f"group {group_name!r}: chain tip {chain_tip!r} "
                                 f"is not below base {chain_base!r} in the URDF tree")
            joint_list += [j for j, _ in chain]
            link_list += [link for _, link in chain]
            base = base or pre + chain_base
            tip = pre + chain_tip
        for joint_name in group.joints:
            if pre + joint_name not in own_joints:
                raise srdf.error(group.line, f"group {group_name!r}: joint {joint_name!r} is "
                                 "not a joint of the URDF")
            joint_list.append(pre + joint_name)
            link_list.append(_joint_link(tree.joint_elements[pre + joint_name], "child"))
        for link in group.links:
            if pre + link not in own_links:
                raise srdf.error(group.line, f"group {group_name!r}: link {link!r} is not a "
                                 "link of the URDF")
            link_list.append(pre + link)
            if pre + link in tree.parent_of_link:
                joint_list.append(tree.parent_of_link[pre + link][0])
        for sub in group.subgroups:
            if sub not in srdf.groups:
                raise srdf.error(group.line, f"group {group_name!r}: subgroup {sub!r} is not "
                                 "defined in the SRDF")
            if sub in stack:
                raise srdf.error(group.line, f"group {group_name!r}: subgroups form a cycle "
                                 f"({' -> '.join((*stack, sub))})")
            sub_joints, sub_links, sub_base, sub_tip = resolve(sub, (*stack, sub))
            joint_list += sub_joints
            link_list += sub_links
            base = base or sub_base
            tip = tip or sub_tip
        if base is None:
            first = next((j for j in joint_list if j in tree.joint_elements), None)
            base = (_joint_link(tree.joint_elements[first], "parent")
                    if first else pre + p.description.urdf.root_link)
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
            subgroups=tuple(pre + s for s in group.subgroups),
            end_effector=pre + group_eef.name if group_eef is not None else None,
            robot=p.name,
        )

    for state in srdf.group_states:
        if state.group not in srdf.groups:
            raise srdf.error(state.line, f"group_state {state.name!r}: group {state.group!r} "
                             "is not defined")
        model_group = groups[pre + state.group]
        group_joints = set(resolve(state.group, (state.group,))[0])
        values: dict[str, float] = {}
        for joint_name, value in state.values.items():
            line = state.value_lines.get(joint_name, state.line)
            full = pre + joint_name
            if full not in group_joints:
                raise srdf.error(line, f"group_state {state.name!r}: joint {joint_name!r} is "
                                 f"not in group {state.group!r}")
            if full not in joints:
                continue  # a fixed joint listed in a pose: nothing to set
            _check_in_limits(joints[full], value, lambda msg: srdf.error(line, msg),
                             f"group_state {state.name!r}")
            values[full] = value
        if state.name in states.get(model_group.name, {}):
            raise srdf.error(state.line, f"group_state {state.name!r} of group "
                             f"{state.group!r} is defined twice")
        states.setdefault(model_group.name, {})[state.name] = values

    for pair in srdf.disabled_collisions:
        a, b = pre + pair.link1, pre + pair.link2
        missing = [x for x in (pair.link1, pair.link2) if pre + x not in own_links]
        if missing:
            warnings.append(f"{srdf.path}:{pair.line}: disable_collisions names unknown "
                            f"link(s) {missing}; entry ignored")
            continue
        disabled[frozenset((a, b))] = pair.reason or "SRDF"
    for pair in srdf.enabled_collisions:
        disabled.pop(frozenset((pre + pair.link1, pre + pair.link2)), None)


def _check_in_limits(joint: JointInfo, value: float, error, what: str) -> None:  # type: ignore[no-untyped-def]
    if value < joint.lower - POSE_LIMIT_TOLERANCE or value > joint.upper + POSE_LIMIT_TOLERANCE:
        raise error(f"{what}: joint {joint.name!r} = {value} is outside its limits "
                    f"[{joint.lower}, {joint.upper}]")


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


def _add_kinematics(p: Placement, groups: dict[str, Group]) -> None:
    import dataclasses

    for group_name, settings in p.description.kinematics.items():
        full = p.prefix + group_name
        if full not in groups or groups[full].robot != p.name:
            own = sorted(g[len(p.prefix):] for g, v in groups.items() if v.robot == p.name)
            raise YamlError(
                f"group {group_name!r} is not defined in the SRDF (groups: {', '.join(own)})",
                p.description.kinematics_path,
                settings.line,
            )
        groups[full] = dataclasses.replace(groups[full], kinematics=settings)


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
