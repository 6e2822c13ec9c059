"""How robots and cells are loaded: one immutable :class:`LoadOptions`, passed explicitly.

The command line (``--strict``, ``--package-path``, ``--allow-missing-meshes``,
``--collision``), the API server's settings and a Python caller each build one and hand
it to the loaders (:func:`~taskrunner.robot.load_robot`,
:func:`~taskrunner.robot.cell.load_cell`, :func:`~taskrunner.load_workcell`) and to the
planning worker processes they start (as an argument of the process, not through the
environment). No loader reads the environment for them: two cells loaded in one process
with different options each get their own.

The documented variables (``TASKRUNNER_STRICT``, ``TASKRUNNER_PACKAGE_PATH``,
``TASKRUNNER_ALLOW_MISSING_MESHES``, ``TASKRUNNER_COLLISION``) are read only where a
program starts, by :meth:`LoadOptions.from_env` (the command line calls it; a Python
caller may).
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path

from taskrunner.errors import ArgumentError
from taskrunner.kinds import CollisionChoice

__all__ = ["ALLOW_MISSING_MESHES_ENV", "COLLISION_ENV", "PACKAGE_PATH_ENV", "STRICT_ENV",
           "LoadOptions"]

STRICT_ENV = "TASKRUNNER_STRICT"
PACKAGE_PATH_ENV = "TASKRUNNER_PACKAGE_PATH"
ALLOW_MISSING_MESHES_ENV = "TASKRUNNER_ALLOW_MISSING_MESHES"
COLLISION_ENV = "TASKRUNNER_COLLISION"

_TRUE = ("1", "true", "yes", "on")
_FALSE = ("", "0", "false", "no", "off")


@dataclass(frozen=True)
class LoadOptions:
    """How robots are loaded.

    Attributes:
        strict: every load warning (what MoveIt would skip, a named pose in
            self-collision…) is a :class:`~taskrunner.errors.RobotDescriptionError`.
        package_path: folders searched (recursively) for ROS packages before the robot's
            surroundings, ``ROS_PACKAGE_PATH`` and ``AMENT_PREFIX_PATH`` (see
            :mod:`taskrunner.robot.packages`).
        allow_missing_meshes: load robots whose mesh files cannot be found, or that have
            no collision geometry, without that geometry (one warning per robot; see
            :mod:`taskrunner.robot.missing_meshes`). Otherwise that is a
            :class:`~taskrunner.errors.MissingMeshError`.
        collision: the link geometry of every robot (None: each robot's own choice, its
            cell's or robot.yaml's ``collision:``, else auto).
    """

    strict: bool = False
    package_path: tuple[Path, ...] = field(default=())
    allow_missing_meshes: bool = False
    collision: CollisionChoice | None = None

    def __post_init__(self) -> None:
        for name in ("strict", "allow_missing_meshes"):
            value = getattr(self, name)
            if not isinstance(value, bool):
                raise ArgumentError(f"'{name}' must be a bool (got {value!r})")
        if isinstance(self.package_path, str | Path) or not isinstance(
                self.package_path, Iterable):
            raise ArgumentError(
                f"'package_path' must be a sequence of folders (got {self.package_path!r})")
        object.__setattr__(self, "package_path",
                           tuple(Path(p).expanduser().resolve() for p in self.package_path))
        if self.collision is not None:
            if self.collision not in tuple(CollisionChoice):
                raise ArgumentError(f"'collision' must be one of exact, convex, auto "
                                    f"(got {self.collision!r})")
            object.__setattr__(self, "collision", CollisionChoice(self.collision))

    def replaced(self, **changes: object) -> LoadOptions:
        """These options with ``changes`` (checked)."""
        return replace(self, **changes)  # type: ignore[arg-type]

    def as_data(self) -> dict[str, object]:
        """These options as JSON data (what a run's record keeps; :meth:`from_data`)."""
        return {"strict": self.strict, "package_path": [str(p) for p in self.package_path],
                "allow_missing_meshes": self.allow_missing_meshes,
                "collision": None if self.collision is None else str(self.collision)}

    @classmethod
    def from_data(cls, data: Mapping[str, object]) -> LoadOptions:
        """Options from :meth:`as_data`'s form (a run's record).

        Raises:
            ArgumentError: a field that is not one, or a value of the wrong kind.
        """
        unknown = sorted(set(data) - {"strict", "package_path", "allow_missing_meshes",
                                      "collision"})
        if unknown:
            raise ArgumentError(f"load options: unknown field {unknown[0]!r}")
        path = data.get("package_path", ())
        if isinstance(path, str) or not isinstance(path, list | tuple):
            raise ArgumentError(f"'package_path' must be a list of folders (got {path!r})")
        strict, allow = data.get("strict", False), data.get("allow_missing_meshes", False)
        if not isinstance(strict, bool) or not isinstance(allow, bool):
            raise ArgumentError(f"'strict' and 'allow_missing_meshes' must be bools (got "
                                f"{strict!r}, {allow!r})")
        collision = data.get("collision")
        if collision is not None and collision not in tuple(CollisionChoice):
            raise ArgumentError(f"'collision' must be one of exact, convex, auto "
                                f"(got {collision!r})")
        return cls(strict=strict, package_path=tuple(Path(str(p)) for p in path),
                   allow_missing_meshes=allow,
                   collision=None if collision is None else CollisionChoice(str(collision)))

    @classmethod
    def from_env(cls, environ: Mapping[str, str] | None = None) -> LoadOptions:
        """The options the documented variables give (``environ``, default ``os.environ``):
        ``TASKRUNNER_STRICT=1``, ``TASKRUNNER_PACKAGE_PATH`` (folders separated by
        ``os.pathsep``), ``TASKRUNNER_ALLOW_MISSING_MESHES=1``, ``TASKRUNNER_COLLISION``.
        For a program's entry only (the command line); loaders never call it.

        Raises:
            ArgumentError: a value is not a flag or not a collision choice, naming the
                variable.
        """
        env = os.environ if environ is None else environ
        collision = env.get(COLLISION_ENV, "").strip() or None
        if collision is not None and collision not in tuple(CollisionChoice):
            raise ArgumentError(f"'{COLLISION_ENV}' must be one of exact, convex, auto "
                                f"(got {collision!r})")
        return cls(
            strict=_flag(env, STRICT_ENV),
            package_path=tuple(Path(p) for p in env.get(PACKAGE_PATH_ENV, "").split(os.pathsep)
                               if p.strip()),
            allow_missing_meshes=_flag(env, ALLOW_MISSING_MESHES_ENV),
            collision=CollisionChoice(collision) if collision is not None else None,
        )


def _flag(env: Mapping[str, str], name: str) -> bool:
    value = env.get(name, "").strip().lower()
    if value in _TRUE:
        return True
    if value in _FALSE:
        return False
    raise ArgumentError(f"'{name}' must be 1 or 0 (got {env[name]!r})")
