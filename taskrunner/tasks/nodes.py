"""The building blocks of task models: locations, the frozen node base, poses, objects.

Every model of a task file derives from :class:`Node`: frozen, ``extra="forbid"`` (a typo
in the YAML is an error, not a silently ignored key), and knowing where it was written.
A node validated from a mapping of :func:`taskrunner.yamlfile.load_yaml` records the
mapping's file and line in :attr:`Node.loc`; the file comes from the validation context
(``model_validate(data, context={"file": path})``). The location is a private attribute:
it is not a field, takes no part in equality or hashing, never shows in ``model_dump``
or in the JSON schema, and a YAML key ``loc`` is an unknown field like any other.

Units: metres and radians; quaternions are (x, y, z, w); angles ``rpy`` are URDF
roll-pitch-yaw (fixed axes X, then Y, then Z).
"""

from __future__ import annotations

import ast
import functools
import inspect
import textwrap
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, Self

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    PrivateAttr,
    ValidationInfo,
    field_validator,
    model_validator,
)

from taskrunner.objectspec import ObjectFields
from taskrunner.posespec import WORLD, PoseFields, TransformFields
from taskrunner.textfile import path_problem
from taskrunner.validation import Metres, Number
from taskrunner.yamlfile import LineDict

__all__ = ["Location", "Node", "ObjectSpec", "PoseSpec", "TargetPose", "Transform", "Vec2",
           "Vec3", "Vec4", "WORLD"]

Vec2 = Annotated[tuple[Metres, ...], Field(min_length=2, max_length=2)]
Vec3 = Annotated[tuple[Number, ...], Field(min_length=3, max_length=3)]
Vec4 = Annotated[tuple[Number, ...], Field(min_length=4, max_length=4)]


@dataclass(frozen=True)
class Location:
    """Where a node was written: a file and a 1-based line.

    Attributes:
        file: the task file (absolute path).
        line: the node's line: for a step the line of its verb, for a mapping (pose,
            object) the line of its first key.
        field_lines: line of each key of the node's mapping, for :meth:`line_of`.
    """

    file: Path
    line: int | None = None
    field_lines: tuple[tuple[str, int], ...] = field(default=(), compare=False, repr=False)

    def line_of(self, name: str) -> int | None:
        """Line of field ``name`` (its YAML key), or of the node when it was not written."""
        for key, line in self.field_lines:
            if key == name:
                return line
        return self.line

    def __str__(self) -> str:
        return f"{self.file}:{self.line}" if self.line is not None else str(self.file)


def location_of(node: Any, file: str | Path | None, line: int | None = None) -> Location | None:
    """Location of a YAML mapping (``line`` overrides the mapping's own line)."""
    if file is None:
        return None
    lines: tuple[tuple[str, int], ...] = ()
    if isinstance(node, LineDict):
        lines = tuple((str(k), v) for k, v in node.key_lines.items())
        line = line if line is not None else node.line
    return Location(Path(file), line, lines)


def _freeze(value: Any) -> Any:
    if isinstance(value, dict):
        return tuple(sorted(((k, _freeze(v)) for k, v in value.items()), key=repr))
    if isinstance(value, (list, tuple)):
        return tuple(_freeze(v) for v in value)
    return value


@functools.cache
def _attribute_docstrings(cls: type) -> dict[str, str]:
    """``name: type`` lines of ``cls``'s own body followed by a string: name → the string
    (cleaned as a docstring)."""
    try:
        source = textwrap.dedent(inspect.getsource(cls))
    except (OSError, TypeError):
        return {}
    tree = ast.parse(source).body[0]
    if not isinstance(tree, ast.ClassDef):
        return {}
    docs: dict[str, str] = {}
    for before, stmt in zip(tree.body, tree.body[1:]):
        if (isinstance(before, ast.AnnAssign) and isinstance(before.target, ast.Name)
                and isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant)
                and isinstance(stmt.value.value, str)):
            docs[before.target.id] = inspect.cleandoc(stmt.value.value)
    return docs


def describe_fields(schema: dict[str, Any], cls: type[BaseModel]) -> None:
    """The JSON Schema of a node model gets each field's description from the docstring
    under the field (what pydantic's ``use_attribute_docstrings`` gives), when the field
    has none of its own. Done here, when a schema is made, because pydantic's own way
    reads and parses each model's source while the model class is built: 0.15 s of
    ``run-task``'s start for ~40 models that a run never turns into a schema."""
    properties = schema.get("properties", {})
    for name, info in cls.model_fields.items():
        owner = next((c for c in cls.__mro__ if name in c.__dict__.get("__annotations__", {})),
                     None)
        doc = _attribute_docstrings(owner).get(name) if owner is not None else None
        if info.description is not None or doc is None:
            continue
        choices = [c for c in getattr(info.validation_alias, "choices", ()) if isinstance(c, str)]
        keys = [info.validation_alias if isinstance(info.validation_alias, str) else None,
                *choices[:1], info.alias, name]
        key = next((k for k in keys if k is not None and k in properties), None)
        if key is None or "description" in properties[key]:
            continue
        # Before the title, where pydantic puts it (a field named "default" keeps the
        # order of its keys in the printed schema).
        prop = properties[key]
        items = list(prop.items())
        prop.clear()
        for k, v in items:
            if k == "title":
                prop["description"] = doc
            prop[k] = v
        prop.setdefault("description", doc)


class Node(BaseModel):
    """Base of every task model: frozen, no unknown keys, knows its :class:`Location`.

    Equality and hashing compare the fields only (not the location), so a node can be a
    dict key; two steps written identically at different places are equal — key a
    per-occurrence map by ``id(node)``.
    """

    # allow_inf_nan=False: every number of a task file is finite (inf, nan, 1e400 refused).
    # json_schema_extra: field descriptions from attribute docstrings (a subclass that sets
    # its own json_schema_extra calls describe_fields first).
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False,
                              json_schema_extra=describe_fields)

    _loc: Location | None = PrivateAttr(default=None)

    @model_validator(mode="wrap")
    @classmethod
    def _record_location(cls, data: Any, handler: Any, info: ValidationInfo) -> Any:
        node = handler(data)
        if isinstance(data, LineDict) and isinstance(node, Node):
            context = info.context if isinstance(info.context, dict) else {}
            loc = location_of(data, context.get("file"))
            if loc is not None:
                node._loc = loc
        return node

    @property
    def loc(self) -> Location | None:
        """Where the node was written (None for a node built in code)."""
        return self._loc

    def located(self, loc: Location | None) -> Self:
        """A copy of this node at ``loc``."""
        copy = self.model_copy()
        copy._loc = loc
        return copy

    def __eq__(self, other: object) -> bool:
        return type(self) is type(other) and self.__dict__ == other.__dict__  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return hash((type(self), _freeze(tuple(self.__dict__.values()))))


class Transform(Node, TransformFields):
    """A rigid transform: translation and an optional orientation (``rpy`` or ``quat``)
    (the fields and checks of :class:`taskrunner.posespec.TransformFields`)."""


class PoseSpec(Transform, PoseFields):
    """A pose in a frame: 'world', a link of the cell, or an object of the scene."""


class TargetPose(PoseSpec):
    """A pose for a link of a group to reach (``go``/``move``)."""

    link: str | None = None
    """The link to place at the pose (default: the group's tip link)."""
    position_only: bool | None = None
    """Reach the position and ignore the orientation (default: the group's IK setting,
    or true when no orientation is given)."""


class ObjectSpec(Node, ObjectFields):  # the fields and checks: taskrunner.objectspec
    """A scene object (the fields of a cell's objects, plus frames of other objects)."""

    pose: PoseSpec = PoseSpec()
    """Placement of the object's centre (mesh origin)."""

    _file_as_written: str | None = PrivateAttr(default=None)

    @field_validator("file")
    @classmethod
    def _absolute_file(cls, value: str | None, info: ValidationInfo) -> str | None:
        """A relative mesh path joined to the task file's folder. Not resolved: the
        name is checked here and never meets the file system (a symlink loop, a name
        too long is reported where the file is looked for, with this field's line)."""
        if value is None or "://" in value:
            return value
        problem = path_problem(value)
        if problem is not None:
            shown = value if len(value) <= 80 else value[:80] + "…"
            raise ValueError(f"must be a path the file system accepts ({problem}; got "
                             f"{shown!r})")
        context = info.context if isinstance(info.context, dict) else {}
        if context.get("file") is None:
            return value
        return str(Path(context["file"]).parent / value)

    @model_validator(mode="wrap")
    @classmethod
    def _keep_file_as_written(cls, data: Any, handler: Any) -> Any:
        node = handler(data)
        if isinstance(data, dict) and isinstance(data.get("file"), str) \
                and isinstance(node, ObjectSpec):
            node._file_as_written = data["file"]
        return node

    @property
    def file_as_written(self) -> str | None:
        """``file`` as the task file wrote it (for messages: never its resolution)."""
        return self._file_as_written if self._file_as_written is not None else self.file
