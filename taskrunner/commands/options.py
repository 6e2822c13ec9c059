"""The robot-loading options of every command that loads robots: the flags, and the
:class:`~taskrunner.robot.options.LoadOptions` they and the documented variables give."""

from __future__ import annotations

import argparse
from pathlib import Path

from taskrunner.errors import InputError
from taskrunner.kinds import CollisionChoice
from taskrunner.robot.options import LoadOptions

__all__ = ["add_robot_options", "load_options"]


def add_robot_options(parser: argparse.ArgumentParser, default: str = "") -> None:
    """``--package-path``, ``--strict``, ``--allow-missing-meshes`` and ``--collision``,
    for every command that loads robots; ``default``: said after each flag's help."""
    parser.add_argument("--package-path", action="append", default=[], metavar="DIR",
                        help="also look for ROS packages under DIR (repeatable; before "
                             "TASKRUNNER_PACKAGE_PATH, ROS_PACKAGE_PATH, AMENT_PREFIX_PATH)"
                             + default)
    parser.add_argument("--strict", action="store_true",
                        help="robot file warnings (what MoveIt would skip) are errors" + default)
    parser.add_argument("--allow-missing-meshes", action="store_true",
                        help="load robots whose mesh files cannot be found (or that have "
                             "no collision geometry) without that geometry, with a warning"
                             + default)
    parser.add_argument("--collision", choices=tuple(CollisionChoice), default=None,
                        help="link geometry of every robot: exact meshes, convex hulls, or "
                             "auto (hulls where tight; default: each robot's own choice)"
                             + default)


def load_options(args: argparse.Namespace) -> LoadOptions:
    """How this command loads robots: ``--package-path``, ``--strict``,
    ``--allow-missing-meshes`` and ``--collision`` over what the documented variables say
    (``TASKRUNNER_PACKAGE_PATH`` … :meth:`LoadOptions.from_env`, read here only). The
    command hands the result to the loaders and to the worker processes it starts; the
    environment is not changed."""
    from_env = LoadOptions.from_env()
    folders = [Path(p).expanduser().resolve() for p in getattr(args, "package_path", None) or []]
    missing = [str(f) for f in folders if not f.is_dir()]
    if missing:
        raise InputError(f"'--package-path' must be a folder (got {', '.join(missing)})")
    return LoadOptions(
        strict=bool(getattr(args, "strict", False)) or from_env.strict,
        package_path=(*folders, *from_env.package_path),
        allow_missing_meshes=(bool(getattr(args, "allow_missing_meshes", False))
                              or from_env.allow_missing_meshes),
        collision=getattr(args, "collision", None) or from_env.collision,
    )
