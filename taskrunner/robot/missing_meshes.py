"""Mesh files a robot names that cannot be found, and the rule for them.

A robot whose mesh files are missing would plan as if those links were thinner, or not
there at all: every state "valid", every path "collision-free". So a missing mesh is an
error (:class:`~taskrunner.errors.MissingMeshError`) listing every missing mesh of the
robot at once, grouped by cause, with the folders looked in and what to pass. Loading
without them is an explicit opt-out (``allow_missing_meshes=True`` in Python,
``LoadOptions(allow_missing_meshes=True)``, ``--allow-missing-meshes`` on the command
line); it keeps the
fallback (a visual is dropped; a link whose collision meshes are all missing uses its
visual geometry, else has none) and logs one warning per robot summing up what was lost.

A robot with no collision geometry at all is refused the same way, with the same opt-out.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from taskrunner.errors import MissingMeshError
from taskrunner.robot.notes import LoadWarning

__all__ = ["MissingMesh", "check_robot_geometry", "resolve_allow_missing_meshes"]

_WHAT_TO_PASS = (
    "add the folder holding a missing package with --package-path DIR (repeatable; or "
    "TASKRUNNER_PACKAGE_PATH, ROS_PACKAGE_PATH, or PackageMap({name: folder}) in Python), "
    "or put the files where they were looked for; to load the robot without them (a "
    "visual dropped, a link's collision replaced by its visual geometry or dropped), pass "
    "--allow-missing-meshes (allow_missing_meshes=True)")


@dataclass(frozen=True)
class MissingMesh:
    """One ``<visual>`` or ``<collision>`` mesh of a URDF that cannot be found.

    Attributes:
        link: the link it belongs to.
        kind: ``"visual"`` or ``"collision"``.
        uri: the ``filename`` as the URDF writes it.
        line: its line in the URDF (None for expanded xacro).
        package: the package of a ``package://`` URI that is not known, else None.
        searched: the folders searched for that package (for the message).
        looked_at: the path tried, when the package (or the folder) was found but the
            file is not there.
        base: the folder the path was taken from: the package's, or the URDF's own for a
            relative path.
        fallback: what loading without it does (``"visual dropped"``, …).
    """

    link: str
    kind: str
    uri: str
    line: int | None
    package: str | None = None
    searched: tuple[str, ...] = ()
    looked_at: Path | None = None
    base: Path | None = None
    fallback: str = ""

    def describe(self) -> str:
        where = f" (line {self.line})" if self.line is not None else ""
        looked = f"; looked at {self.looked_at}" if self.looked_at is not None else ""
        return f"link {self.link!r}: {self.kind} mesh {self.uri!r}{where}{looked}"


def resolve_allow_missing_meshes(allow: bool | None) -> bool:
    """``allow`` itself; None (not given) does not allow. The environment is not read."""
    return bool(allow)


def _groups(missing: Sequence[MissingMesh]) -> dict[str, list[MissingMesh]]:
    """The missing meshes by cause, each cause a heading naming the folders looked in."""
    groups: dict[str, list[MissingMesh]] = {}
    for mesh in missing:
        if mesh.package is not None:
            searched = "; ".join(mesh.searched) or "no folder"
            heading = f"package {mesh.package!r} not found (searched: {searched})"
        elif mesh.uri.startswith("package://"):
            package = mesh.uri[len("package://"):].lstrip("/").partition("/")[0]
            heading = f"files missing from package {package!r} (its folder: {mesh.base})"
        elif mesh.base is not None:
            heading = f"files missing relative to the URDF's folder {mesh.base}"
        else:
            heading = "files missing"
        groups.setdefault(heading, []).append(mesh)
    return groups


def _error(name: str, source: Path, missing: Sequence[MissingMesh]) -> MissingMeshError:
    lines = [f"{len(missing)} mesh file(s) of robot {name!r} cannot be found, so its "
             "collision checks would miss that geometry:"]
    for heading, meshes in _groups(missing).items():
        lines.append(f"  {heading}:")
        lines += [f"    {mesh.describe()}" for mesh in meshes]
    lines.append(_WHAT_TO_PASS[0].upper() + _WHAT_TO_PASS[1:])
    return MissingMeshError("\n".join(lines), source, missing[0].line)


def _summary(name: str, source: Path, missing: Sequence[MissingMesh]) -> LoadWarning:
    by_fallback: dict[str, list[str]] = {}
    for mesh in missing:
        links = by_fallback.setdefault(mesh.fallback, [])
        if mesh.link not in links:
            links.append(mesh.link)
    lost = "; ".join(f"{fallback}: {', '.join(links)}" for fallback, links in by_fallback.items())
    causes = "; ".join(f"{heading} ({len(meshes)})"
                       for heading, meshes in _groups(missing).items())
    return LoadWarning(
        f"robot {name!r} loaded WITHOUT {len(missing)} mesh file(s) it names "
        f"(--allow-missing-meshes): {lost}. Causes: {causes}", source)


def check_robot_geometry(name: str, source: Path, missing: Sequence[MissingMesh],
                         collision_elements: int, allow: bool) -> LoadWarning | None:
    """Refuse a robot with missing meshes or no collision geometry, unless ``allow``.

    Args:
        name: the robot's name, for the message.
        source: the URDF (or xacro) file.
        missing: every mesh of the URDF that cannot be found.
        collision_elements: ``<collision>`` elements left once missing meshes are dropped
            (and replaced by visuals where a link has one).
        allow: the opt-out (see the module docstring).

    Returns:
        The one warning summing up what was lost, when ``allow`` and something was.

    Raises:
        MissingMeshError: something is missing and ``allow`` is False.
    """
    if missing and not allow:
        raise _error(name, source, missing)
    warning = _summary(name, source, missing) if missing else None
    if collision_elements == 0:
        if not allow:
            raise MissingMeshError(
                f"robot {name!r} has no collision geometry at all (no link has a "
                "<collision>): every state would be collision-free. Give its links "
                "<collision> elements; to load it anyway, pass --allow-missing-meshes "
                "(allow_missing_meshes=True)", source)
        text = (f"robot {name!r} has no collision geometry at all "
                "(--allow-missing-meshes): nothing of it is collision-checked")
        warning = LoadWarning(text if warning is None else f"{warning.message}. {text}",
                              source)
    return warning
