"""Reading SRDF files (MoveIt's semantic robot description).

The SRDF is parsed into plain dataclasses that remember their source line. Checking the
names it uses against the URDF happens when the model is assembled
(:mod:`taskrunner.robot.model`), where both are known.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

from taskrunner.errors import RobotDescriptionError
from taskrunner.robot.notes import LoadWarning
from taskrunner.robot.xmldoc import XmlDocument, parse_xml, read_xml

__all__ = [
    "Srdf",
    "SrdfDisabledCollision",
    "SrdfEndEffector",
    "SrdfGroup",
    "SrdfGroupState",
    "SrdfVirtualJoint",
    "parse_srdf",
    "read_srdf",
    "srdf_from_document",
]


@dataclass
class SrdfGroup:
    """A planning group: chains, joints, links and subgroups, any mix."""

    name: str
    line: int | None
    chains: list[tuple[str, str]] = field(default_factory=list)
    joints: list[str] = field(default_factory=list)
    links: list[str] = field(default_factory=list)
    subgroups: list[str] = field(default_factory=list)
    member_lines: dict[tuple[str, str], int | None] = field(default_factory=dict)

    def member_line(self, kind: str, name: str) -> int | None:
        """Line of member ``name`` (kind "chain" by tip, "joint", "link", "group")."""
        return self.member_lines.get((kind, name), self.line)


@dataclass
class SrdfGroupState:
    """A named pose (``group_state``): joint values for one group."""

    name: str
    group: str
    values: dict[str, float]
    line: int | None
    value_lines: dict[str, int | None] = field(default_factory=dict)


@dataclass
class SrdfEndEffector:
    name: str
    parent_link: str
    group: str
    parent_group: str | None
    line: int | None


@dataclass
class SrdfVirtualJoint:
    name: str
    type: str
    parent_frame: str
    child_link: str
    line: int | None


@dataclass
class SrdfDisabledCollision:
    link1: str
    link2: str
    reason: str
    line: int | None


@dataclass
class Srdf:
    """Everything an SRDF declares, with source lines."""

    path: Path | None
    robot_name: str
    groups: dict[str, SrdfGroup] = field(default_factory=dict)
    group_states: list[SrdfGroupState] = field(default_factory=list)
    end_effectors: list[SrdfEndEffector] = field(default_factory=list)
    virtual_joints: list[SrdfVirtualJoint] = field(default_factory=list)
    passive_joints: list[str] = field(default_factory=list)
    disabled_collisions: list[SrdfDisabledCollision] = field(default_factory=list)
    enabled_collisions: list[SrdfDisabledCollision] = field(default_factory=list)
    passive_lines: dict[str, int | None] = field(default_factory=dict)
    warnings: list[LoadWarning] = field(default_factory=list)
    """What was skipped while reading (more is found when checked against the URDF)."""

    def error(self, line: int | None, message: str) -> RobotDescriptionError:
        return RobotDescriptionError(message, self.path, line)


def read_srdf(path: str | Path) -> Srdf:
    """Read an SRDF file (a plain one; see :func:`taskrunner.robot.description` for
    ``.srdf.xacro``).

    Raises:
        RobotDescriptionError: missing file, invalid XML, or a root that is not <robot>.
    """
    return _build(read_xml(path))


def srdf_from_document(doc: XmlDocument) -> Srdf:
    """The SRDF of a parsed document (an expanded ``.srdf.xacro``)."""
    return _build(doc)


def parse_srdf(text: str, path: str | Path | None = None) -> Srdf:
    """Parse SRDF text; ``path`` labels error messages."""
    return _build(parse_xml(text, path))


def _attr(doc: XmlDocument, element: ET.Element, attribute: str, what: str,
          warnings: list[LoadWarning]) -> str | None:
    """The attribute's value, or None after a warning that ``what`` is skipped."""
    value = element.get(attribute)
    if value is None or value == "":
        warnings.append(LoadWarning(f"<{element.tag}> has no '{attribute}' attribute; "
                                    f"{what} skipped", doc.path, doc.line(element)))
        return None
    return value


def _build(doc: XmlDocument) -> Srdf:
    """What MoveIt's SRDF parser (srdfdom) skips with a log line is skipped here with a
    warning naming the file, line and element (see :mod:`taskrunner.robot.notes`)."""
    root = doc.root
    if root.tag != "robot":
        raise doc.error(root, f"root element must be <robot> (got <{root.tag}>)")
    srdf = Srdf(doc.path, root.get("name", ""))
    warnings = srdf.warnings

    def warn(element: ET.Element, message: str) -> None:
        warnings.append(LoadWarning(message, doc.path, doc.line(element)))

    for element in root:
        tag = element.tag
        line = doc.line(element)
        if not isinstance(tag, str):  # a comment or processing instruction
            continue
        if tag == "group":
            name = _attr(doc, element, "name", "group", warnings)
            if name is None:
                continue
            if name in srdf.groups:
                warn(element, f"duplicate group {name!r}; the first definition (line "
                              f"{srdf.groups[name].line}) is kept")
                continue
            group = SrdfGroup(name, line)
            for part in element:
                what = f"a member of group {name!r}"
                if part.tag == "chain":
                    base = _attr(doc, part, "base_link", what, warnings)
                    tip = _attr(doc, part, "tip_link", what, warnings)
                    if base is not None and tip is not None:
                        group.chains.append((base, tip))
                        group.member_lines[("chain", tip)] = doc.line(part)
                elif part.tag in ("joint", "link", "group"):
                    member = _attr(doc, part, "name", what, warnings)
                    if member is None:
                        continue
                    {"joint": group.joints, "link": group.links,
                     "group": group.subgroups}[part.tag].append(member)
                    group.member_lines[(part.tag, member)] = doc.line(part)
                elif part.tag == "passive_joint":
                    warn(part, f"group {name!r}: <passive_joint> inside a group is not a "
                               "group member; skipped (a passive joint is declared at the "
                               "top level of the SRDF)")
                elif isinstance(part.tag, str):
                    warn(part, f"group {name!r}: unknown element <{part.tag}>; skipped")
            srdf.groups[name] = group
        elif tag == "group_state":
            state = _group_state(doc, element, warnings)
            if state is not None:
                srdf.group_states.append(state)
        elif tag == "end_effector":
            what = "end_effector"
            fields = [_attr(doc, element, a, what, warnings)
                      for a in ("name", "parent_link", "group")]
            if None in fields:
                continue
            eef_name, parent_link, eef_group = (str(f) for f in fields)
            srdf.end_effectors.append(SrdfEndEffector(
                eef_name, parent_link, eef_group, element.get("parent_group") or None, line))
        elif tag == "virtual_joint":
            fields = [_attr(doc, element, a, "virtual_joint", warnings)
                      for a in ("name", "type", "parent_frame", "child_link")]
            if None in fields:
                continue
            vj_name, vj_type, vj_parent, vj_child = (str(f) for f in fields)
            srdf.virtual_joints.append(SrdfVirtualJoint(vj_name, vj_type, vj_parent, vj_child,
                                                        line))
        elif tag == "passive_joint":
            joint_name = _attr(doc, element, "name", "passive_joint", warnings)
            if joint_name is not None:
                srdf.passive_joints.append(joint_name)
                srdf.passive_lines[joint_name] = line
        elif tag in ("disable_collisions", "enable_collisions"):
            links = [_attr(doc, element, a, f"<{tag}>", warnings) for a in ("link1", "link2")]
            if None in links:
                continue
            target = srdf.disabled_collisions if tag == "disable_collisions" else (
                srdf.enabled_collisions
            )
            target.append(SrdfDisabledCollision(str(links[0]), str(links[1]),
                                                element.get("reason", ""), line))
        elif tag in ("disable_default_collisions", "link_sphere_approximation", "joint_property"):
            continue  # optional MoveIt extras with no effect on our checks
        else:
            warn(element, f"unknown SRDF element <{tag}>; skipped")
    return srdf


def _group_state(doc: XmlDocument, element: ET.Element,
                 warnings: list[LoadWarning]) -> SrdfGroupState | None:
    state_name = _attr(doc, element, "name", "group_state", warnings)
    if state_name is None:
        return None
    group_name = _attr(doc, element, "group", f"group_state {state_name!r}", warnings)
    if group_name is None:
        return None
    values: dict[str, float] = {}
    value_lines: dict[str, int | None] = {}
    for joint in element.findall("joint"):
        what = f"a joint of group_state {state_name!r}"
        joint_name = _attr(doc, joint, "name", what, warnings)
        raw = _attr(doc, joint, "value", what, warnings) if joint_name is not None else None
        if joint_name is None or raw is None:
            continue
        try:
            # Multi-DOF joints list several numbers; we keep 1-DOF joints only.
            values[joint_name] = float(raw.split()[0])
        except (ValueError, IndexError):
            warnings.append(LoadWarning(
                f"group_state {state_name!r}: joint {joint_name!r} value must be a number "
                f"(got {raw!r}); value skipped", doc.path, doc.line(joint)))
            continue
        if not math.isfinite(values[joint_name]):
            # A named pose of nan or inf is no pose: refused, not skipped (it would reach
            # the planner as a goal, or crash the check).
            raise RobotDescriptionError(
                f"group_state {state_name!r}: joint {joint_name!r} value must be a finite "
                f"number (got {raw!r})", doc.path, doc.line(joint))
        value_lines[joint_name] = doc.line(joint)
    return SrdfGroupState(state_name, group_name, values, doc.line(element), value_lines)
