"""Resolving ROS package names to folders without ROS.

URDF and xacro files name files as ``package://pkg/path`` and ``$(find pkg)``. Without a
ROS workspace we resolve ``pkg`` from a :class:`PackageMap`, which looks in this order
(the first place that has the package wins; when two places have one name, using it
gives a warning naming both folders):

1. explicit ``{name: folder}`` entries given in code;
2. the load options' package path (``LoadOptions(package_path=…)``; on the command line
   ``--package-path DIR`` and ``TASKRUNNER_PACKAGE_PATH``, ``:``-separated), folders
   searched recursively;
3. the folders searched for the robot at hand (its folder, and the one above it at most
   four folders deep);
4. ``ROS_PACKAGE_PATH`` (searched recursively, as rospack does);
5. ``AMENT_PREFIX_PATH`` (each prefix's ``share/<pkg>``, as ament does);
6. the ``example-robot-data`` wheel, when installed;
7. only for a package none of these has: the workspace around the robot, so that a
   description package that is a sibling of the config package's repository is found
   with no flag (``ws/src/sawyer_moveit/sawyer_moveit_config`` finds
   ``ws/src/sawyer_robot/sawyer_description``). Up to two folders above the robot's
   surroundings are searched, at most four folders deep, stopping at a workspace's
   ``src`` folder or at a folder holding ``src``, ``.catkin_workspace`` or
   ``.catkin_tools``, and never searching the home folder or the file system's root.

A package that is not found is an error naming every folder searched.

A package is a folder holding a ``package.xml``; its name is that file's ``<name>``,
which may differ from the folder's name. Packages do not nest: the search does not
descend into a package, nor into a folder holding ``COLCON_IGNORE`` or ``CATKIN_IGNORE``.
"""

from __future__ import annotations

import importlib.metadata
import os
from collections.abc import Iterable, Mapping
from pathlib import Path
from urllib.parse import unquote, urlparse

from taskrunner.errors import RobotDescriptionError
from taskrunner.robot.notes import LoadWarning
from taskrunner.robot.xmldoc import read_xml

__all__ = ["PackageMap", "default_package_map", "example_robot_data_dir", "package_of"]

# Folders never worth descending into while looking for package.xml files.
_SKIP_DIRS = {".git", "__pycache__", "node_modules", ".venv", "build", "install", "log"}
_IGNORE_MARKERS = ("COLCON_IGNORE", "CATKIN_IGNORE", "AMENT_IGNORE")

# Search tiers, first wins (see the module docstring).
_EXPLICIT, _USER, _ROBOT, _ROS, _AMENT, _BUNDLED, _WORKSPACE = range(7)
# The workspace search (tier 7): how many folders above the robot's surroundings, and how
# deep below each.
_WORKSPACE_LEVELS = 2
_WORKSPACE_DEPTH = 4
_WORKSPACE_MARKERS = ("src", ".catkin_workspace", ".catkin_tools")


def example_robot_data_dir() -> Path | None:
    """Share folder of the ``example-robot-data`` wheel, or None when it is not installed."""
    try:
        dist = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        return None
    folder = Path(str(dist.locate_file("cmeel.prefix/share/example-robot-data")))
    return folder if folder.is_dir() else None


def _env_folders(name: str) -> list[Path]:
    return [Path(p) for p in os.environ.get(name, "").split(os.pathsep) if p.strip()]


def default_package_map(path: str | Path, package_path: Iterable[str | Path] = ()
                        ) -> PackageMap:
    """The package map for a robot at ``path`` (file or folder): the packages under
    ``package_path`` and the ROS environment's, plus every package in the robot's folder
    and the folder above it."""
    packages = PackageMap(package_path=package_path)
    packages.discover_around(path)
    return packages


class PackageMap:
    """Package name → folder, for ``package://`` URIs and ``$(find pkg)``.

    Args:
        packages: explicit ``{name: folder}`` entries; these win over found ones.
        search_roots: folders searched (recursively) for ``package.xml`` files.
        environment: also search ``ROS_PACKAGE_PATH`` and ``AMENT_PREFIX_PATH`` (ROS's
            own variables, as rospack and ament read them; see the module docstring).
        package_path: folders searched (recursively) before the robot's surroundings and
            the ROS environment (:attr:`~taskrunner.robot.options.LoadOptions.package_path`).

    Attributes:
        warnings: a package found in two folders, once for each such package used.
    """

    def __init__(
        self,
        packages: Mapping[str, str | Path] | None = None,
        search_roots: Iterable[str | Path] = (),
        environment: bool = True,
        package_path: Iterable[str | Path] = (),
    ) -> None:
        # name → [(tier, order, folder)], the first of each tier's search order first.
        self._entries: dict[str, list[tuple[int, int, Path]]] = {}
        self._order = 0
        self._warned: set[str] = set()
        self._skipped: list[str] = []
        # What was searched, for "not found" messages: (tier, order, description).
        self._searched: list[tuple[int, int, str]] = []
        # Workspaces around robots, searched only when a package is not found elsewhere.
        self._pending: list[Path] = []
        self.warnings: list[LoadWarning] = []
        erd = example_robot_data_dir()
        if erd is not None:
            # Its URDFs say package://example-robot-data/… while its package.xml says
            # example_robot_descriptions: register both.
            self._register("example-robot-data", erd, _BUNDLED)
            self._register("example_robot_descriptions", erd, _BUNDLED)
        for user_root in package_path:
            self._discover(Path(user_root), _USER)
        if environment:
            for ros_root in _env_folders("ROS_PACKAGE_PATH"):
                self._discover(ros_root, _ROS)
            for prefix in _env_folders("AMENT_PREFIX_PATH"):
                share = prefix / "share"
                self._note_searched(_AMENT, f"{share} (AMENT_PREFIX_PATH)")
                if share.is_dir():
                    for folder in sorted(share.iterdir()):
                        self._add_if_package(folder, _AMENT)
            unset = [v for v in ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH") if not os.environ.get(v)]
            if unset:
                self._note_searched(_ROS, f"{' and '.join(unset)} not set")
        for root in search_roots:
            self.discover(root)
        for name, explicit in (packages or {}).items():
            self._register(name, Path(explicit).resolve(), _EXPLICIT)

    def _register(self, name: str, folder: Path, tier: int) -> None:
        entries = self._entries.setdefault(name, [])
        if any(f == folder and t <= tier for t, _, f in entries):
            return
        entries.append((tier, self._order, folder))
        entries.sort()
        self._order += 1

    def _add_if_package(self, folder: Path, tier: int) -> bool:
        manifest = folder / "package.xml"
        if not manifest.is_file():
            return False
        try:
            doc = read_xml(manifest)
            name_el = doc.root.find("name")
            name = (name_el.text or "").strip() if name_el is not None else ""
            if not name:
                raise doc.error(doc.root, "package.xml has no <name>")
        except RobotDescriptionError as exc:
            # As rospack and ament do: a broken manifest somewhere under a search root
            # (a sibling project, a half-written package) is skipped, not fatal; a robot
            # that needs that package gets "not found" naming the skipped manifests.
            self._skipped.append(f"{exc.location}: {exc.reason}")
            self.warnings.append(LoadWarning(f"{exc.reason}; package skipped", exc.path,
                                             exc.line))
            return True  # a package folder all the same: packages do not nest
        self._register(name, folder.resolve(), tier)
        return True

    def _note_searched(self, tier: int, what: str) -> None:
        if all(w != what for _, _, w in self._searched):
            self._searched.append((tier, self._order, what))
            self._order += 1

    def _discover(self, root: str | Path, tier: int, max_depth: int | None = None) -> None:
        root = Path(root)
        label = {_USER: " (--package-path / TASKRUNNER_PACKAGE_PATH)",
                 _ROS: " (ROS_PACKAGE_PATH)",
                 _WORKSPACE: f" (the workspace around the robot, {max_depth} folders deep)",
                 }.get(tier, "")
        if tier == _ROBOT and max_depth is not None:
            label = f" ({max_depth} folders deep)"
        self._note_searched(tier, f"{root.resolve() if root.is_dir() else root}{label}"
                                  f"{'' if root.is_dir() else ' (no such folder)'}")
        if not root.is_dir():
            return
        for dirpath, dirnames, filenames in os.walk(root):
            if any(marker in filenames for marker in _IGNORE_MARKERS):
                dirnames[:] = []
                continue
            depth = len(Path(dirpath).relative_to(root).parts)
            if max_depth is not None and depth >= max_depth:
                dirnames[:] = []
            dirnames[:] = sorted(d for d in dirnames if d not in _SKIP_DIRS)
            if "package.xml" in filenames and self._add_if_package(Path(dirpath), tier):
                dirnames[:] = []  # packages do not nest

    def discover(self, root: str | Path, max_depth: int | None = None) -> None:
        """Register every package (a folder with a package.xml) found under ``root``
        (at most ``max_depth`` folders deep), after those found before (search tier 3 of
        the module docstring)."""
        self._discover(root, _ROBOT, max_depth)

    def discover_around(self, path: str | Path) -> None:
        """Register the packages of a robot at ``path``: the folder above its folder (at
        most four folders deep: a robot file in ``/tmp`` or a home folder's subfolder must
        not pick up a same-named package from anywhere under it), then its folder (a
        file's folder is its parent)."""
        path = Path(path).resolve()
        folder = path if path.is_dir() else path.parent
        self.discover(folder.parent, _WORKSPACE_DEPTH)
        self.discover(folder)
        for workspace in _workspace_folders(folder.parent):
            if workspace not in self._pending:
                self._pending.append(workspace)

    def _search_workspaces(self) -> None:
        """Search the pending workspace folders (tier 7), once."""
        pending, self._pending = self._pending, []
        for folder in pending:
            self._discover(folder, _WORKSPACE, _WORKSPACE_DEPTH)

    def has(self, name: str) -> bool:
        """Whether package ``name`` can be found (searching the workspaces around the
        robots when no other place has it)."""
        if not self._entries.get(name) and self._pending:
            self._search_workspaces()
        return bool(self._entries.get(name))

    def searched_folders(self) -> list[str]:
        """Every place searched for packages so far, in search order, for messages."""
        return [what for _, _, what in sorted(self._searched)]

    def add(self, name: str, folder: str | Path) -> None:
        """Register (or replace) one package, ahead of every found one."""
        folder = Path(folder).resolve()
        self._entries[name] = [e for e in self._entries.get(name, []) if e[0] != _EXPLICIT]
        self._register(name, folder, _EXPLICIT)

    @property
    def names(self) -> list[str]:
        """Known package names, sorted."""
        return sorted(self._entries)

    def find(self, name: str, near: str | Path | None = None) -> Path:
        """Folder of package ``name``.

        When several folders of the first search tier that has the package hold one of
        that name, the one holding ``near`` (the folder of the file that names the
        package: a robot's URDF naming its own package) wins, silently; else the nearest
        to ``near`` (the longest common folder), with a warning naming them all. Without
        ``near``, the first found wins, with that warning.

        Raises:
            RobotDescriptionError: the package is not in the map.
        """
        if not self.has(name):
            known = ", ".join(self.names) or "none"
            skipped = (f"; skipped broken manifests: {'; '.join(self._skipped)}"
                       if self._skipped else "")
            searched = "; ".join(self.searched_folders()) or "no folder"
            raise RobotDescriptionError(
                f"package {name!r} not found (searched: {searched}; known packages: "
                f"{known}); add its folder with --package-path or TASKRUNNER_PACKAGE_PATH, or "
                f"place a package.xml naming it under a search root{skipped}"
            )
        entries = self._entries[name]
        tier, _, folder = entries[0]
        if near is not None and tier != _EXPLICIT:
            here = Path(near).resolve()
            tied = [f for t, _, f in entries if t == tier]
            holding = [f for f in tied if here == f or f in here.parents]
            if holding:  # the file is inside that package: no ambiguity
                return max(holding, key=lambda f: len(f.parts))
            folder = max(tied, key=lambda f: _shared_parts(f, here))
        others = list(dict.fromkeys(str(f) for _, _, f in entries if f != folder))
        if others and tier != _EXPLICIT and name not in self._warned:
            self._warned.add(name)
            self.warnings.append(LoadWarning(
                f"package {name!r} is in two places: {folder} (used, "
                f"{'nearest to ' + str(near) if near is not None else 'first in the search order'}"
                f") and {', '.join(others)}"))
        return folder

    def resolve(self, uri: str, base_dir: str | Path) -> Path:
        """Turn a URDF file reference into a path.

        ``package://pkg/rel``, ``file:///abs``, absolute paths and paths relative to
        ``base_dir`` (the folder of the referencing file) are understood.

        Raises:
            RobotDescriptionError: an unknown package or URI scheme.
        """
        package = package_of(uri)
        if package is not None:
            rel = uri[len("package://"):].lstrip("/").partition("/")[2]
            return self.find(package, near=base_dir) / unquote(rel)
        if uri.startswith("file://"):
            return Path(unquote(urlparse(uri).path))
        if "://" in uri:
            raise RobotDescriptionError(f"unsupported URI scheme in {uri!r}")
        path = Path(uri)
        return path if path.is_absolute() else Path(base_dir) / path

    def __repr__(self) -> str:
        return f"PackageMap({self.names})"


def _shared_parts(a: Path, b: Path) -> int:
    """How many leading folders ``a`` and ``b`` share."""
    count = 0
    for x, y in zip(a.parts, b.parts):
        if x != y:
            break
        count += 1
    return count


def package_of(uri: str) -> str | None:
    """The package a ``package://`` URI names, else None. ``package:///pkg/rel`` (three
    slashes, as example-robot-data writes them and pinocchio reads them) names ``pkg``."""
    if not uri.startswith("package://"):
        return None
    return uri[len("package://"):].lstrip("/").partition("/")[0]


def _workspace_folders(above: Path) -> list[Path]:
    """The folders above ``above`` (the folder above a robot's, already searched) to
    search for a package found nowhere else (see the module docstring, tier 7)."""
    found: list[Path] = []
    stops = {Path.home().resolve(), Path(above.anchor)}
    current = above
    for _ in range(_WORKSPACE_LEVELS):
        if current.name == "src" or any((current / m).exists() for m in _WORKSPACE_MARKERS):
            break  # the workspace itself: already searched
        current = current.parent
        if current in stops:
            break
        found.append(current)
    return found
