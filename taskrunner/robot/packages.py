"""Resolving ROS package names to folders without ROS.

URDF and xacro files name files as ``package://pkg/path`` and ``$(find pkg)``. Without a
ROS workspace we resolve ``pkg`` from a :class:`PackageMap`: folders the user names
explicitly, plus every folder under the search roots that holds a ``package.xml`` (the
package's name is that file's ``<name>``, which may differ from the folder's name).
"""

from __future__ import annotations

import importlib.metadata
import os
from collections.abc import Iterable, Mapping
from pathlib import Path
from urllib.parse import unquote, urlparse

from taskrunner.errors import RobotDescriptionError
from taskrunner.robot.xmldoc import read_xml

__all__ = ["PackageMap", "example_robot_data_dir"]

# Folders never worth descending into while looking for package.xml files.
_SKIP_DIRS = {".git", "__pycache__", "node_modules", ".venv", "build", "install", "log"}


def example_robot_data_dir() -> Path | None:
    """Share folder of the ``example-robot-data`` wheel, or None when it is not installed."""
    try:
        dist = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        return None
    folder = Path(str(dist.locate_file("cmeel.prefix/share/example-robot-data")))
    return folder if folder.is_dir() else None


class PackageMap:
    """Package name → folder, for ``package://`` URIs and ``$(find pkg)``.

    Args:
        packages: explicit ``{name: folder}`` entries; these win over discovered ones.
        search_roots: folders searched (recursively) for ``package.xml`` files.
    """

    def __init__(
        self,
        packages: Mapping[str, str | Path] | None = None,
        search_roots: Iterable[str | Path] = (),
    ) -> None:
        self._packages: dict[str, Path] = {}
        erd = example_robot_data_dir()
        if erd is not None:
            # Its URDFs say package://example-robot-data/… while its package.xml says
            # example_robot_descriptions: register both.
            self._packages["example-robot-data"] = erd
            self._packages["example_robot_descriptions"] = erd
        for root in search_roots:
            self.discover(root)
        for name, folder in (packages or {}).items():
            self._packages[name] = Path(folder).resolve()

    def discover(self, root: str | Path) -> None:
        """Register every package (a folder with a package.xml) found under ``root``."""
        root = Path(root)
        if not root.is_dir():
            return
        for dirpath, dirnames, filenames in os.walk(root):
            dirnames[:] = sorted(d for d in dirnames if d not in _SKIP_DIRS)
            if "package.xml" in filenames:
                manifest = Path(dirpath) / "package.xml"
                doc = read_xml(manifest)
                name_el = doc.root.find("name")
                name = (name_el.text or "").strip() if name_el is not None else ""
                if not name:
                    raise doc.error(doc.root, "package.xml has no <name>")
                self._packages.setdefault(name, Path(dirpath).resolve())

    def add(self, name: str, folder: str | Path) -> None:
        """Register (or replace) one package."""
        self._packages[name] = Path(folder).resolve()

    @property
    def names(self) -> list[str]:
        """Known package names, sorted."""
        return sorted(self._packages)

    def find(self, name: str) -> Path:
        """Folder of package ``name``.

        Raises:
            RobotDescriptionError: the package is not in the map.
        """
        try:
            return self._packages[name]
        except KeyError:
            known = ", ".join(self.names) or "none"
            raise RobotDescriptionError(
                f"package {name!r} not found (known packages: {known}); add its folder to "
                "the package map or place a package.xml naming it under a search root"
            ) from None

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
