"""Reading ROS messages dumped as YAML, field by field, with file:line in every message.

A :class:`MessageReader` walks a tree from :func:`taskrunner.yamlfile.load_yaml`. Each
message is read against the fields its ROS definition has: a field the definition does
not have, or one we do not support with a value that matters, becomes a
:class:`~taskrunner.robot.notes.LoadWarning` naming the field path and line (strict
mode raises it instead); a field with a wrong type or value raises an
:class:`~taskrunner.errors.InputError` of the form ``path:line: '<field>' must be …
(got …)``. Fields are named by their path in the message (``world.collision_objects[2].
primitives[0].dimensions``).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

from taskrunner.errors import InputError
from taskrunner.robot.notes import LoadWarning, resolve_strict
from taskrunner.types import Pose
from taskrunner.yamlfile import LineDict, LineList, line_of

__all__ = ["HEADER", "MessageReader", "Msg", "as_bool"]

HEADER = ("seq", "stamp", "frame_id")
MAX_COORDINATE = 1e4  # m: points and offsets beyond this are mistakes


def _shown(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:60] + "…"


class Msg:
    """One message mapping of the file and where it is (its field path)."""

    def __init__(self, reader: MessageReader, node: LineDict, where: str) -> None:
        self.reader = reader
        self.node = node
        self.where = where

    @property
    def line(self) -> int | None:
        return self.node.line

    def field(self, key: str) -> str:
        return f"{self.where}.{key}" if self.where else key

    def line_of(self, key: str) -> int | None:
        return self.node.line_of(key)

    def has(self, key: str) -> bool:
        return key in self.node

    def raw(self, key: str, default: Any = None) -> Any:
        return self.node.get(key, default)

    def error(self, key: str | None, message: str) -> InputError:
        """``'<field>' <message>`` at the key's line."""
        name = self.field(key) if key is not None else self.where or "<message>"
        line = self.line_of(key) if key is not None else self.line
        return self.reader.error(f"{name!r} {message}", line)

    def warn(self, key: str | None, message: str) -> None:
        name = self.field(key) if key is not None else self.where or "<message>"
        line = self.line_of(key) if key is not None else self.line
        self.reader.warn(f"{name!r} {message}", line)

    # ------------------------------------------------------------------ typed fields
    def msg(self, key: str, known: Iterable[str], required: bool = False) -> Msg | None:
        """The sub-message ``key`` (None when absent and not required)."""
        if key not in self.node or self.node[key] is None:
            if required:
                raise self.error(None, f"must have the field {key!r}")
            return None
        return self.reader.msg(self.node[key], self.field(key), known, self.line_of(key))

    def msgs(self, key: str, known: Iterable[str]) -> list[Msg]:
        """The list of messages ``key`` (empty when absent)."""
        items = self.seq(key)
        known = tuple(known)
        out = []
        for index, item in enumerate(items):
            line = line_of(items, index) or self.line_of(key)
            out.append(self.reader.msg(item, f"{self.field(key)}[{index}]", known, line))
        return out

    def seq(self, key: str) -> LineList:
        value = self.node.get(key)
        if value is None:
            return LineList()
        if not isinstance(value, LineList):
            raise self.error(key, f"must be a list (got {_shown(value)})")
        return value

    def number(self, key: str, default: float | None = 0.0) -> float:
        value = self.node.get(key, default)
        if value is None and default is None:
            raise self.error(None, f"must have the field {key!r}")
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise self.error(key, f"must be a finite number (got {_shown(value)})")
        return float(value)

    def integer(self, key: str, default: int = 0) -> int:
        value = self.node.get(key, default)
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.error(key, f"must be an integer (got {_shown(value)})")
        return value

    def string(self, key: str, default: str = "") -> str:
        value = self.node.get(key, default)
        if value is None:
            return default
        if not isinstance(value, str):
            raise self.error(key, f"must be a string (got {_shown(value)})")
        return value

    def boolean(self, key: str, default: bool = False) -> bool:
        value = as_bool(self.node.get(key, default))
        if value is None:
            raise self.error(key, f"must be true or false (got {_shown(self.node.get(key))})")
        return value

    def numbers(self, key: str) -> list[float]:
        items = self.seq(key)
        out = []
        for index, value in enumerate(items):
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                line = line_of(items, index) or self.line_of(key)
                raise self.reader.error(f"'{self.field(key)}[{index}]' must be a finite number "
                                        f"(got {_shown(value)})", line)
            out.append(float(value))
        return out

    def strings(self, key: str) -> list[str]:
        items = self.seq(key)
        for index, value in enumerate(items):
            if not isinstance(value, str):
                line = line_of(items, index) or self.line_of(key)
                raise self.reader.error(f"'{self.field(key)}[{index}]' must be a string "
                                        f"(got {_shown(value)})", line)
        return [str(v) for v in items]

    def _tuple(self, key: str, size: int) -> tuple[float, ...] | None:
        """A ``[x, y, z(, w)]`` list (robowflex / MotionBenchMaker writes points and
        quaternions so), or None when the field is a mapping or absent."""
        value = self.node.get(key)
        if not isinstance(value, LineList):
            return None
        numbers = self.numbers(key)
        if len(numbers) != size:
            raise self.error(key, f"must be {size} numbers {'[x, y, z, w]' if size == 4 else '[x, y, z]'} "
                                  f"or a mapping (got {len(numbers)} values)")
        return tuple(numbers)

    def vector3(self, key: str) -> tuple[float, float, float]:
        """A geometry_msgs Vector3 / Point: ``{x, y, z}`` (missing components are 0) or
        ``[x, y, z]``."""
        listed = self._tuple(key, 3)
        if listed is not None:
            if max(abs(v) for v in listed) > MAX_COORDINATE:
                raise self.error(key, f"must be within {MAX_COORDINATE:g} m of the origin "
                                      f"(got {list(listed)})")
            return (listed[0], listed[1], listed[2])
        sub = self.msg(key, ("x", "y", "z"))
        return (0.0, 0.0, 0.0) if sub is None else sub.point()

    def quaternion(self, key: str) -> tuple[float, float, float, float]:
        """A geometry_msgs Quaternion ``{x, y, z, w}`` or ``[x, y, z, w]``: unit length
        within 1e-3, else an error. An absent quaternion is the identity."""
        listed = self._tuple(key, 4)
        if listed is not None:
            quat = (listed[0], listed[1], listed[2], listed[3])
        else:
            sub = self.msg(key, ("x", "y", "z", "w"))
            if sub is None:
                return (0.0, 0.0, 0.0, 1.0)
            quat = (sub.number("x"), sub.number("y"), sub.number("z"), sub.number("w"))
        norm = math.sqrt(sum(v * v for v in quat))
        if abs(norm - 1.0) > 1e-3:
            raise self.error(key, f"must be a unit quaternion x, y, z, w (got {quat}, norm {norm:.4g})")
        return quat

    def pose(self, key: str, frame: str) -> Pose | None:
        """A geometry_msgs Pose (position, orientation) in ``frame`` (None when absent)."""
        sub = self.msg(key, ("position", "orientation"))
        if sub is None:
            return None
        return sub.as_pose(frame)

    def point(self) -> tuple[float, float, float]:
        """This message as a Point / Vector3 (x, y, z), each within ±:data:`MAX_COORDINATE`."""
        values = (self.number("x"), self.number("y"), self.number("z"))
        if max(abs(v) for v in values) > MAX_COORDINATE:
            raise self.error(None, f"must be within {MAX_COORDINATE:g} m of the origin (got {values})")
        return values

    def as_pose(self, frame: str) -> Pose:
        return Pose(self.vector3("position"), self.quaternion("orientation"), frame)

    def frame_id(self) -> str:
        """``header.frame_id`` with a leading ``/`` (ROS 1 style) removed; "" if absent."""
        header = self.msg("header", HEADER)
        if header is None:
            return ""
        return header.string("frame_id").lstrip("/")


def as_bool(value: Any) -> bool | None:
    """A bool field's value: true / false, 0 / 1 (some ROS 1 dumps), ``"true"`` /
    ``"false"`` (robowflex writes strings); None for anything else."""
    if isinstance(value, bool):
        return value
    if isinstance(value, int) and value in (0, 1):
        return bool(value)
    if isinstance(value, str) and value.lower() in ("true", "false"):
        return value.lower() == "true"
    return None


class MessageReader:
    """Reads the messages of one file; collects warnings; strict mode raises them.

    Args:
        path: the file (for messages).
        strict: warnings are errors (None: no; the environment is not read).
        package_path: folders searched for the ROS packages of ``package://`` resources
            (``LoadOptions.package_path``), before the ROS environment's.
    """

    def __init__(self, path: str | Path | None, strict: bool | None = None,
                 package_path: Sequence[Path] = ()) -> None:
        self.path = Path(path) if path is not None else None
        self.strict = resolve_strict(strict)
        self.package_path = tuple(package_path)
        self.warnings: list[LoadWarning] = []

    def error(self, message: str, line: int | None) -> InputError:
        return InputError(message, self.path, line)

    def warn(self, message: str, line: int | None) -> None:
        if self.strict:
            raise InputError(message + " (an error with --strict)", self.path, line)
        self.warnings.append(LoadWarning(message, self.path, line))

    def msg(self, node: Any, where: str, known: Iterable[str], line: int | None = None) -> Msg:
        """``node`` as a message with the fields ``known``; other fields are warned about."""
        if not isinstance(node, LineDict):
            name = where or "<file>"
            raise self.error(f"{name!r} must be a mapping of message fields (got {_shown(node)})",
                             line if line is not None else line_of(node))
        known = tuple(known)
        message = Msg(self, node, where)
        for key in node:
            if key not in known:
                message.warn(str(key), "is not a field of this message; ignored")
        return message
