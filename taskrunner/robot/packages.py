"""Resolving ROS package names to folders without ROS.

URDF and xacro files name files as ``package://pkg/path`` and ``$(find pkg)``. Without a
ROS workspace we resolve ``pkg`` from a :class:`PackageMap`, which looks in this order
(the first place that has the package wins; when two places have one name, using it
gives a warning naming both folders):

1. explicit ``{name: folder}`` entries given in code;
2. ``--package-path DIR`` on the command line and ``TASKRUNNER_PACKAGE_PATH``
   (``:``-separated folders, searched recursively);
3. the folders searched for the robot at hand (its folder and the one above);
4. ``ROS_PACKAGE_PATH`` (searched recursively, as rospack does);
5. ``AMENT_PREFIX_PATH`` (each prefix's ``share/<pkg>``, as ament does);
6. the ``example-robot-data`` wheel, when installed.

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

__all__ = ["PACKAGE_PATH_ENV", "PackageMap", "default_package_map", "example_robot_data_dir"]

PACKAGE_PATH_ENV = "TASKRUNNER_PACKAGE_PATH"

# Folders never worth descending into while looking for package.xml files.
_SKIP_DIRS = {".git", "__pycache__", "node_modules", ".venv", "build", "install", "log"}
_IGNORE_MARKERS = ("COLCON_IGNORE", "CATKIN_IGNORE", "AMENT_IGNORE")

# Search tiers, first wins (see the module docstring).
_EXPLICIT, _USER, _ROBOT, _ROS, _AMENT, _BUNDLED = range(6)


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


def default_package_map(path: str | Path) -> PackageMap:
    """The package map for a robot at ``path`` (file or folder): the environment's
    packages plus every package in the robot's folder and the folder above it."""
    packages = PackageMap()
    packages.discover_around(path)
    return packages


class PackageMap:
    """Package name → folder, for ``package://`` URIs and ``$(find pkg)``.

    Args:
        packages: explicit ``{name: folder}`` entries; these win over found ones.
        search_roots: folders searched (recursively) for ``package.xml`` files.
        environment: also search ``TASKRUNNER_PACKAGE_PATH``, ``ROS_PACKAGE_PATH`` and
            ``AMENT_PREFIX_PATH`` (see the module docstring).

    Attributes:
        warnings: a package found in two folders, once for each such package used.
    """

    def __init__(
        self,
        packages: Mapping[str, str | Path] | None = None,
        search_roots: Iterable[str | Path] = (),
        environment: bool = True,
    ) -> None:
        # name → [(tier, order, folder)], the first of each tier's search order first.
        self._entries: dict[str, list[tuple[int, int, Path]]] = {}
        self._order = 0
        self._warned: set[str] = set()
        self._skipped: list[str] = []
        self.warnings: list[LoadWarning] = []
        erd = example_robot_data_dir()
        if erd is not None:
            # Its URDFs say package://example-robot-data/… while its package.xml says
            # example_robot_descriptions: register both.
            self._register("example-robot-data", erd, _BUNDLED)
            self._register("example_robot_descriptions", erd, _BUNDLED)
        if environment:
            for user_root in _env_folders(PACKAGE_PATH_ENV):
                self._discover(user_root, _USER)
            for ros_root in _env_folders("ROS_PACKAGE_PATH"):
                self._discover(ros_root, _ROS)
            for prefix in _env_folders("AMENT_PREFIX_PATH"):
                share = prefix / "share"
                if share.is_dir():
                    for folder in sorted(share.iterdir()):
                        self._add_if_package(folder, _AMENT)
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

    def _discover(self, root: str | Path, tier: int) -> None:
        root = Path(root)
        if not root.is_dir():
            return
        for dirpath, dirnames, filenames in os.walk(root):
            if any(marker in filenames for marker in _IGNORE_MARKERS):
                dirnames[:] = []
                continue
            dirnames[:] = sorted(d for d in dirnames if d not in _SKIP_DIRS)
            if "package.xml" in filenames and self._add_if_package(Path(dirpath), tier):
                dirnames[:] = []  # packages do not nest

    def discover(self, root: str | Path) -> None:
        """Register every package (a folder with a package.xml) found under ``root``,
        after those found before (search tier 3 of the module docstring)."""
        self._discover(root, _ROBOT)

    def discover_around(self, path: str | Path) -> None:
        """Register the packages of a robot at ``path``: the folder above its folder,
        then its folder (a file's folder is its parent)."""
        path = Path(path).resolve()
        folder = path if path.is_dir() else path.parent
        self.discover(folder.parent)
        self.discover(folder)

    def add(self, name: str, folder: str | Path) -> None:
        """Register (or replace) one package, ahead of every found one."""
        folder = Path(folder).resolve()
        self._entries[name] = [e for e in self._entries.get(name, []) if e[0] != _EXPLICIT]
        self._register(name, folder, _EXPLICIT)

    @property
    def names(self) -> list[str]:
        """Known package names, sorted."""
        return sorted(self._entries)

    def find(self, name: str) -> Path:
        """Folder of package ``name``.

        Raises:
            RobotDescriptionError: the package is not in the map.
        """
        entries = self._entries.get(name)
        if not entries:
            known = ", ".join(self.names) or "none"
            skipped = (f"; skipped broken manifests: {'; '.join(self._skipped)}"
                       if self._skipped else "")
            raise RobotDescriptionError(
                f"package {name!r} not found (known packages: {known}); add its folder "
                f"with --package-path or {PACKAGE_PATH_ENV}, or place a package.xml naming "
                f"it under a search root{skipped}"
            )
        tier, _, folder = entries[0]
        others = list(dict.fromkeys(str(f) for _, _, f in entries[1:] if f != folder))
        if others and tier != _EXPLICIT and name not in self._warned:
            self._warned.add(name)
            self.warnings.append(LoadWarning(
                f"package {name!r} is in two places: {folder} (used, first in the search "
                f"order) and {', '.join(others)}"))
        return folder

    def resolve(self, uri: str, base_dir: str | Path) -> Path:
        """Turn a URDF file reference into a path.

        ``package://pkg/rel``, ``file:///abs``, absolute paths and paths relative to
        ``base_dir`` (the folder of the referencing file) are understood.

        Raises:
            RobotDescriptionError: an unknown package or URI scheme.
        """
        if uri.startswith("package://"):
            rest = uri[len("package://") :]
            pkg, _, rel = rest.partition("/")
            return self.find(pkg) / unquote(rel)
        if uri.startswith("file://"):
            return Path(unquote(urlparse(uri).path))
        if "://" in uri:
            raise RobotDescriptionError(f"unsupported URI scheme in {uri!r}")
        path = Path(uri)
        return path if path.is_absolute() else Path(base_dir) / path

    def __repr__(self) -> str:
        return f"PackageMap({self.names})"
