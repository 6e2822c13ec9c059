"""Reading SRDF files (MoveIt's semantic robot description).

The SRDF is parsed into plain dataclasses that remember their source line. Checking the
names it uses against the URDF happens when the model is assembled
(:mod:`taskrunner.robot.model`), where both are known.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from taskrunner.errors import RobotDescriptionError
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

    def error(self, line: int | None, message: str) -> RobotDescriptionError:
        return RobotDescriptionError(message, self.path, line)


def read_srdf(path: str | Path) -> Srdf:
    """Read an SRDF file.

    Raises:
        RobotDescriptionError: missing file, invalid XML, or a malformed element.
    """
    return _build(read_xml(path))


def parse_srdf(text: str, path: str | Path | None = None) -> Srdf:
    """Parse SRDF text; ``path`` labels error messages."""
    return _build(parse_xml(text, path))


def _required(doc: XmlDocument, element, attribute: str) -> str:  # type: ignore[no-untyped-def]
    value = element.get(attribute)
    if value is None or value == "":
        raise doc.error(element, f"<{element.tag}> needs a '{attribute}' attribute")
    return value


def _build(doc: XmlDocument) -> Srdf:
    root = doc.root
    if root.tag != "robot":
        raise doc.error(root, f"root element must be <robot> (got <{root.tag}>)")
    srdf = Srdf(doc.path, root.get("name", ""))
    for element in root:
        tag = element.tag
        line = doc.line(element)
        if tag == "group":
            name = _required(doc, element, "name")
            if name in srdf.groups:
                raise doc.error(element, f"duplicate group {name!r}")
            group = SrdfGroup(name, line)
            for part in element:
                if part.tag == "chain":
                    group.chains.append(
                        (_required(doc, part, "base_link"), _required(doc, part, "tip_link"))
                    )
                elif part.tag == "joint":
                    group.joints.append(_required(doc, part, "name"))
                elif part.tag == "link":
                    group.links.append(_required(doc, part, "name"))
                elif part.tag == "group":
                    group.subgroups.append(_required(doc, part, "name"))
                else:
                    raise doc.error(part, f"group {name!r}: unknown element <{part.tag}>")
            srdf.groups[name] = group
        elif tag == "group_state":
            values: dict[str, float] = {}
            value_lines: dict[str, int | None] = {}
            state_name = _required(doc, element, "name")
            for joint in element.findall("joint"):
                joint_name = _required(doc, joint, "name")
                raw = _required(doc, joint, "value")
                try:
                    # Multi-DOF joints list several numbers; we keep 1-DOF joints only.
                    values[joint_name] = float(raw.split()[0])
                except (ValueError, IndexError):
                    raise doc.error(
                        joint,
                        f"group_state {state_name!r}: joint {joint_name!r} value must be a "
                        f"number (got {raw!r})",
                    ) from None
                value_lines[joint_name] = doc.line(joint)
            srdf.group_states.append(
                SrdfGroupState(
                    state_name, _required(doc, element, "group"), values, line, value_lines
                )
            )
        elif tag == "end_effector":
            srdf.end_effectors.append(
                SrdfEndEffector(
                    _required(doc, element, "name"),
                    _required(doc, element, "parent_link"),
                    _required(doc, element, "group"),
                    element.get("parent_group") or None,
                    line,
                )
            )
        elif tag == "virtual_joint":
            srdf.virtual_joints.append(
                SrdfVirtualJoint(
                    _required(doc, element, "name"),
                    _required(doc, element, "type"),
                    _required(doc, element, "parent_frame"),
                    _required(doc, element, "child_link"),
                    line,
                )
            )
        elif tag == "passive_joint":
            srdf.passive_joints.append(_required(doc, element, "name"))
        elif tag in ("disable_collisions", "enable_collisions"):
            target = srdf.disabled_collisions if tag == "disable_collisions" else (
                srdf.enabled_collisions
            )
            target.append(
                SrdfDisabledCollision(
                    _required(doc, element, "link1"),
                    _required(doc, element, "link2"),
                    element.get("reason", ""),
                    line,
                )
            )
        elif tag in ("disable_default_collisions", "link_sphere_approximation", "joint_property"):
            continue  # optional MoveIt extras with no effect on our checks
        else:
            raise doc.error(element, f"unknown SRDF element <{tag}>")
    return srdf
