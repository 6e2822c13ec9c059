"""Reading URDF and xacro files into a checked, self-contained URDF tree.

What comes out of :func:`read_urdf` is an XML tree that pinocchio can load with no ROS
around: xacro expanded, ``package://`` and relative mesh paths made absolute, the tags
pinocchio has no use for (``<ros2_control>``, ``<gazebo>``, ``<transmission>``) removed,
and the structure checked (unique names, every parent and child link present, one root,
mimic joints naming a real joint). Meshes that cannot be found are recorded
(:attr:`UrdfDescription.missing_meshes`) and dropped from the tree: a visual is dropped, a
collision falls back to the link's visual geometry, else the link has no collision
geometry; building the model refuses such a robot unless told to load it without them
(:mod:`taskrunner.robot.missing_meshes`).
"""

from __future__ import annotations

import copy
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field, replace
from pathlib import Path

from taskrunner.errors import RobotDescriptionError
from taskrunner.robot.missing_meshes import MissingMesh
from taskrunner.robot.notes import LoadWarning
from taskrunner.robot.packages import PackageMap, package_of
from taskrunner.robot.xacrofile import XacroOptions, expand_xacro
from taskrunner.robot.xmldoc import XmlDocument, parse_xml
from taskrunner.textfile import read_text_file
from taskrunner.validation import MAX_METRES, MAX_RADIANS, check_number

__all__ = ["UrdfDescription", "expand_xacro", "read_urdf"]

IGNORED_TAGS = ("ros2_control", "gazebo", "transmission")
MOVABLE_TYPES = ("revolute", "continuous", "prismatic")
SUPPORTED_TYPES = (*MOVABLE_TYPES, "fixed")

# Attributes that must hold numbers (attribute → how many), checked here so that a typo
# is reported at its file:line instead of as pinocchio's "not a valid URDF model".
_NUMERIC_ATTRIBUTES = {
    "origin": {"xyz": 3, "rpy": 3},
    "axis": {"xyz": 3},
    "limit": {"lower": 1, "upper": 1, "effort": 1, "velocity": 1},
    "mimic": {"multiplier": 1, "offset": 1},
    "box": {"size": 3},
    "cylinder": {"radius": 1, "length": 1},
    "sphere": {"radius": 1},
    "mesh": {"scale": 3},
    "mass": {"value": 1},
    "inertia": dict.fromkeys(("ixx", "ixy", "ixz", "iyy", "iyz", "izz"), 1),
}

# What each numeric attribute must be besides finite: (low, high, unit, low excluded).
_M, _RAD = MAX_METRES, MAX_RADIANS
_RANGES: dict[tuple[str, str], tuple[float, float, str, bool]] = {
    ("origin", "xyz"): (-_M, _M, "m", False),
    ("origin", "rpy"): (-_RAD, _RAD, "rad", False),
    ("box", "size"): (0.0, _M, "m", True),
    ("cylinder", "radius"): (0.0, _M, "m", True),
    ("cylinder", "length"): (0.0, _M, "m", True),
    ("sphere", "radius"): (0.0, _M, "m", True),
    ("mesh", "scale"): (-1e6, 1e6, "", False),  # a negative scale mirrors the mesh
    ("mass", "value"): (0.0, 1e6, "kg", False),
    # Exporters write rounding noise such as -5e-20 for a zero moment of inertia.
    ("inertia", "ixx"): (-1e-12, 1e6, "kg·m²", False),
    ("inertia", "iyy"): (-1e-12, 1e6, "kg·m²", False),
    ("inertia", "izz"): (-1e-12, 1e6, "kg·m²", False),
    ("limit", "effort"): (0.0, math.inf, "", False),
    ("limit", "velocity"): (0.0, math.inf, "", False),
}
_ANY = (-1e9, 1e9, "", False)


@dataclass
class UrdfDescription:
    """A checked URDF: its XML document plus the facts the rest of the loader needs.

    Attributes:
        doc: the URDF document (mesh paths absolute, ignored tags removed).
        source: the file it was read from (the xacro file for xacro input).
        name: the ``<robot name>``.
        root_link: the one link that is nobody's child.
        links: link names in file order.
        joints: joint name → (type, parent link, child link).
        warnings: what was wrong but left the model usable.
        missing_meshes: meshes that cannot be found (dropped from ``doc``; whether the
            robot may load without them is decided when it is built, see
            :mod:`taskrunner.robot.missing_meshes`).
    """

    doc: XmlDocument
    source: Path
    name: str
    root_link: str
    links: list[str]
    joints: dict[str, tuple[str, str, str]]
    warnings: list[LoadWarning]
    missing_meshes: list[MissingMesh] = field(default_factory=list)

    @property
    def root(self) -> ET.Element:
        return self.doc.root

    def to_string(self) -> str:
        """The URDF as XML text."""
        return ET.tostring(self.doc.root, encoding="unicode")


def read_urdf(
    path: str | Path,
    packages: PackageMap | None = None,
    xacro_args: dict[str, str] | None = None,
    xacro_options: XacroOptions | None = None,
) -> UrdfDescription:
    """Read a URDF (``.urdf``) or xacro (``.xacro``, ``.urdf.xacro``) file and check it.

    xacro is expanded in a child process bounded in time and memory
    (:func:`~taskrunner.robot.xacrofile.expand_xacro`, ``xacro_options``).

    Raises:
        RobotDescriptionError: unreadable, not well-formed, or structurally invalid.
    """
    path = Path(path)
    packages = packages or PackageMap()
    if path.name.endswith(".xacro") or _has_substitutions(path):
        text = expand_xacro(path, packages, xacro_args, xacro_options)
        doc = parse_xml(text, path)
        # Lines of the expanded text mean nothing to the user: report elements by name.
        doc._lines.clear()
    else:
        doc = parse_xml(read_text_file(path, RobotDescriptionError), path)
    return check_urdf(doc, path, packages)


# What xacro substitutes: $(find pkg), $(arg name), $(env VAR), ${expression}.
_SUBSTITUTION = re.compile(r"\$\((?:find|arg|env|optenv|eval|dirname|cwd)\b|\$\{")


def _has_substitutions(path: Path) -> bool:
    """Whether a plain ``.urdf`` holds xacro substitutions (moveit_resources' Panda has
    ``file://$(find moveit_resources_panda_description)/meshes/...``). MoveIt reads such a
    file through xacro (ROS 1 ``command="xacro FILE"``, ROS 2 MoveItConfigsBuilder's
    ``load_xacro`` whatever the extension), so it is expanded here too."""
    return _SUBSTITUTION.search(read_text_file(path, RobotDescriptionError)) is not None


def check_urdf(doc: XmlDocument, source: Path, packages: PackageMap) -> UrdfDescription:
    """Check a parsed URDF document in place (see :func:`read_urdf`)."""
    root = doc.root
    if root.tag != "robot":
        raise doc.error(root, f"root element must be <robot> (got <{root.tag}>)")
    warnings: list[LoadWarning] = []
    missing_meshes: list[MissingMesh] = []
    for tag in IGNORED_TAGS:
        for element in root.findall(tag):
            root.remove(element)

    _check_numbers(doc)
    links: list[str] = []
    for link in root.findall("link"):
        name = link.get("name")
        if not name:
            raise doc.error(link, "<link> without a name")
        if name in links:
            raise doc.error(link, f"duplicate link {name!r}")
        links.append(name)
        _resolve_meshes(doc, link, source, packages, missing_meshes)
    if not links:
        raise doc.error(root, "URDF has no <link>")

    joints: dict[str, tuple[str, str, str]] = {}
    children: dict[str, str] = {}
    for joint in root.findall("joint"):
        name = joint.get("name")
        if not name:
            raise doc.error(joint, "<joint> without a name")
        if name in joints:
            raise doc.error(joint, f"duplicate joint {name!r}")
        jtype = joint.get("type", "")
        if jtype not in SUPPORTED_TYPES:
            raise doc.error(
                joint,
                f"joint {name!r}: 'type' must be one of {', '.join(SUPPORTED_TYPES)} "
                f"(got {jtype!r})",
            )
        parent_el, child_el = joint.find("parent"), joint.find("child")
        parent = parent_el.get("link") if parent_el is not None else None
        child = child_el.get("link") if child_el is not None else None
        for role, link_name in (("parent", parent), ("child", child)):
            if not link_name:
                raise doc.error(joint, f"joint {name!r} has no <{role} link=…>")
            if link_name not in links:
                raise doc.error(joint, f"joint {name!r}: {role} link {link_name!r} is not defined")
        assert parent is not None and child is not None
        if child in children:
            raise doc.error(
                joint, f"link {child!r} is the child of two joints ({children[child]!r}, {name!r})"
            )
        children[child] = name
        limit = joint.find("limit")
        if limit is not None:
            # URDF's parser (urdfdom, which MoveIt and pinocchio read with) refuses a <limit>
            # without either: named here, not as pinocchio's "not a valid URDF model".
            absent = [a for a in ("effort", "velocity") if limit.get(a) is None]
            if absent:
                raise doc.error(limit, f"joint {name!r}: <limit> needs "
                                       f"{' and '.join(a + '=' for a in absent)} (URDF requires "
                                       "effort and velocity; MoveIt refuses the file too)")
        if jtype in ("revolute", "prismatic"):
            if limit is None:
                raise doc.error(joint, f"joint {name!r} ({jtype}) needs a <limit lower= upper= "
                                       "effort= velocity=> (URDF requires one; MoveIt refuses "
                                       "the file too)")
            unset = [a for a in ("lower", "upper") if limit.get(a) is None]
            for attribute in unset:
                limit.set(attribute, "0")  # URDF's default, as MoveIt reads the file
            lower, upper = float(limit.get("lower", 0)), float(limit.get("upper", 0))
            if lower > upper:
                raise doc.error(
                    joint, f"joint {name!r}: lower limit {lower} is above upper limit {upper}"
                           + (f" (URDF's default for the missing {' and '.join(unset)}=)"
                              if unset else ""))
            if unset:
                warnings.append(LoadWarning(
                    f"joint {name!r} ({jtype}): its <limit> has no "
                    f"{' or '.join(a + '=' for a in unset)}; URDF's default is 0, so its range "
                    f"is [{lower:g}, {upper:g}]" + (" (it cannot move)" if lower == upper else "")
                    + ", as MoveIt reads it, unless joint_limits.yaml gives its min_position "
                      "and max_position", source, doc.line(limit)))
        joints[name] = (jtype, parent, child)

    for joint in root.findall("joint"):
        mimic = joint.find("mimic")
        if mimic is None:
            continue
        target = mimic.get("joint")
        if target not in joints:
            # MoveIt logs this and loads the joint as an independent one: so do we.
            warnings.append(LoadWarning(
                f"joint {joint.get('name')!r} mimics {target!r}, which is not a joint; it moves "
                "on its own", source, doc.line(mimic)))
            joint.remove(mimic)
            continue
        if joints[target][0] not in MOVABLE_TYPES:
            raise doc.error(joint, f"joint {joint.get('name')!r} mimics fixed joint {target!r}")

    roots = [link for link in links if link not in children]
    if len(roots) != 1:
        raise doc.error(
            root, f"URDF must form one tree with one root link (roots found: {roots})"
        )
    _check_acyclic(doc, joints, roots[0], links)
    # The warnings are logged by build_model (once, with the SRDF's), not here.
    return UrdfDescription(
        doc, source, root.get("name", source.stem), roots[0], links, joints, warnings,
        missing_meshes,
    )


def _check_numbers(doc: XmlDocument) -> None:
    """Every numeric attribute (see _NUMERIC_ATTRIBUTES) of a link or joint is a number."""
    for owner in doc.root:
        if owner.tag not in ("link", "joint"):
            continue
        for element in owner.iter():
            for attribute, count in _NUMERIC_ATTRIBUTES.get(element.tag, {}).items():
                value = element.get(attribute)
                if value is None:
                    continue
                try:
                    numbers = [float(v) for v in value.split()]
                except ValueError:
                    numbers = []
                if len(numbers) != count:
                    expected = "a number" if count == 1 else f"{count} numbers"
                    raise doc.error(
                        element,
                        f"{owner.tag} {owner.get('name')!r}: <{element.tag}> '{attribute}' "
                        f"must be {expected} (got {value!r})",
                    )
                low, high, unit, low_open = _RANGES.get((element.tag, attribute), _ANY)
                for number in numbers:
                    problem = check_number(number, low, high, unit, low_open)
                    if problem is None and (element.tag, attribute) == ("mesh", "scale") \
                            and number == 0:
                        problem = "must be non-zero"
                    if problem is not None:
                        shown = f" (got {value!r})" if count > 1 else ""
                        if element.tag == "limit" and attribute in ("lower", "upper") \
                                and abs(number) >= high:
                            # Gazebo's SDF-to-URDF export writes +-1e16 for "no limit".
                            shown += ("; a joint that turns without limit is "
                                      "type=\"continuous\"")
                        raise doc.error(
                            element,
                            f"{owner.tag} {owner.get('name')!r}: <{element.tag}> "
                            f"'{attribute}' {problem}{shown}")


def _check_acyclic(
    doc: XmlDocument, joints: dict[str, tuple[str, str, str]], root: str, links: list[str]
) -> None:
    below: dict[str, list[str]] = {}
    for _, parent, child in joints.values():
        below.setdefault(parent, []).append(child)
    seen, stack = {root}, [root]
    while stack:
        for child in below.get(stack.pop(), []):
            if child not in seen:
                seen.add(child)
                stack.append(child)
    unreachable = [link for link in links if link not in seen]
    if unreachable:
        raise doc.error(doc.root, f"links not connected to the root {root!r}: {unreachable}")


def _resolve_meshes(
    doc: XmlDocument,
    link: ET.Element,
    source: Path,
    packages: PackageMap,
    missing_meshes: list[MissingMesh],
) -> None:
    """Make mesh paths absolute, recording each mesh that cannot be found (see
    :mod:`taskrunner.robot.missing_meshes`, which decides whether the robot may load
    without it). A visual whose mesh is missing is dropped; a collision whose mesh is
    missing too, and a link left without collision geometry takes its visual geometry
    instead, else has none."""
    link_name = link.get("name", "")

    def find(element: ET.Element, kind: str) -> MissingMesh | None:
        """The element's mesh if it cannot be found, else None (its path made absolute)."""
        mesh = element.find("geometry/mesh")
        if mesh is None:
            return None
        uri = mesh.get("filename", "")
        line = doc.line(element)
        package = package_of(uri)
        if package is not None and not packages.has(package):
            return MissingMesh(link_name, kind, uri, line, package=package,
                               searched=tuple(packages.searched_folders()))
        try:
            resolved = packages.resolve(uri, source.parent)
        except RobotDescriptionError as exc:
            raise doc.error(element, f"link {link_name!r}: {kind} mesh {uri!r}: "
                                     f"{exc.reason}") from None
        if not resolved.is_file():
            relative = "://" not in uri and not Path(uri).is_absolute()
            base = packages.find(package, near=source.parent) if package is not None else (
                source.parent if relative else None)
            return MissingMesh(link_name, kind, uri, line, looked_at=resolved, base=base)
        mesh.set("filename", str(resolved))
        return None

    for element in list(link.findall("visual")):
        found = find(element, "visual")
        if found is not None:
            missing_meshes.append(replace(found, fallback="visual dropped"))
            link.remove(element)
    collisions = link.findall("collision")
    dropped: list[MissingMesh] = []
    for element in collisions:
        found = find(element, "collision")
        if found is not None:
            dropped.append(found)
            link.remove(element)
    if not dropped:
        return
    visuals = link.findall("visual")
    fallback = len(dropped) == len(collisions) and visuals
    if fallback:
        what = "visual geometry used for collisions"
    elif len(dropped) < len(collisions):
        what = "collision element dropped"
    else:
        what = "no collision geometry"
    missing_meshes += [replace(found, fallback=what) for found in dropped]
    if fallback:
        for visual in visuals:
            collision = ET.SubElement(link, "collision")
            for child in visual:
                if child.tag != "material":
                    collision.append(copy.deepcopy(child))


def prefixed_copy(urdf: UrdfDescription, prefix: str) -> ET.Element:
    """A copy of the URDF tree with ``prefix`` put before every link, joint and material
    name (and every reference to one), so two copies of one robot can share a model."""
    root = copy.deepcopy(urdf.root)
    if not prefix:
        return root
    for element in root.iter():
        if element.tag in ("link", "joint") and element.get("name"):
            element.set("name", prefix + element.get("name", ""))
        elif element.tag in ("parent", "child") and element.get("link"):
            element.set("link", prefix + element.get("link", ""))
        elif element.tag == "mimic" and element.get("joint"):
            element.set("joint", prefix + element.get("joint", ""))
        elif element.tag == "material" and element.get("name"):
            element.set("name", prefix + element.get("name", ""))
    return root
