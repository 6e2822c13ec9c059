"""The models of a whole task: the file as written (``TaskFile``) and as loaded (``TaskSpec``).

The steps are in :mod:`taskrunner.tasks.steps`; a loaded task's steps are walked with
:meth:`TaskSpec.walk` (depth first, document order, included steps too)::

    for step in spec.walk():
        match step:
            case GoStep(group=group, to=str(pose)): ...
            case PickStep(): ...
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field, WithJsonSchema

from taskrunner.materials import Material, material_of
from taskrunner.tasks.expect import Scenario, TaskExpectation
from taskrunner.tasks.nodes import Node, ObjectSpec
from taskrunner.tasks.steps import (
    MOTION_OPTIONS,
    STEP_LIST_SCHEMA,
    AddObjectStep,
    AttachStep,
    HandoffStep,
    IncludeStep,
    MotionOptions,
    MotionStep,
    PickStep,
    RemoveObjectStep,
    ScalarSchema,
    Step,  # noqa: F401 (resolves the forward reference of StepList)
    StepList,
    StepNode,
    _DoComposite,
    _ListComposite,
    walk_steps,
)
from taskrunner.validation import Number

__all__ = ["ParamType", "Parameter", "ParameterDecl", "TaskFile", "TaskSpec", "step_document"]

ParamType = Literal["float", "int", "bool", "str"]
_HANDLING = (PickStep, AttachStep, HandoffStep)
"""Steps that take hold of an object: it must be free to move in a physics simulation."""


class ParameterDecl(Node):
    """The long form of a parameter: ``{default: 0.1, type: float, min: 0, max: 1}``."""

    default: Annotated[Any, ScalarSchema] = None
    """Value when not overridden (none: the parameter must be given)."""
    type: ParamType | None = None
    """float, int, bool or str (default: the type of 'default')."""
    min: Number | None = None
    """Smallest allowed value (numbers only)."""
    max: Number | None = None
    """Largest allowed value (numbers only)."""
    description: str = ""
    """What the parameter means, with its unit."""


class Parameter(Node):
    """A declared parameter and the value it is bound to."""

    name: str
    type: ParamType
    default: Any = None
    min: Number | None = None
    max: Number | None = None
    description: str = ""
    value: Any = None


class TaskFile(Node):
    """A task file. The loader validates ``parameters`` and ``steps`` itself."""

    task: str = Field(min_length=1)
    """Name of the task."""
    description: str = ""
    """What the task does."""
    cell: str | None = None
    """The cell file, relative to this file (required except in included files)."""
    parameters: Annotated[dict[str, Any], WithJsonSchema({
        "type": "object", "propertyNames": {"pattern": "^[A-Za-z_][A-Za-z0-9_]*$"},
        "additionalProperties": {"oneOf": [{"type": ["number", "boolean", "string"]},
                                           {"$ref": "#/$defs/ParameterDecl"}]}})] = {}
    """Parameters with their defaults: 'name: default' or 'name: {default, type, min, max}'."""
    objects: list[ObjectSpec] = []
    """Scene objects added before the first step."""
    scene: str | None = None
    """A MoveIt PlanningScene YAML file, relative to this file: its objects, attached
    objects and allowed collisions join the cell's world before the first step."""
    defaults: MotionOptions | None = None
    """Planner options for every motion step that does not set its own."""
    steps: Annotated[list[Any], WithJsonSchema(STEP_LIST_SCHEMA), Field(min_length=1)]
    """The steps, run as a sequence."""
    expect: TaskExpectation | None = None
    """What must be true when the run ends (checked after the last step)."""
    scenarios: list[Scenario] = []
    """Parameter sets, seeds and backends that 'run-task test' runs the task with."""


class TaskSpec(Node):
    """A loaded task: parameters bound, includes expanded, defaults applied."""

    name: str
    """The task's name (``task:``)."""
    description: str = ""
    path: Path | None = None
    """The task file (absolute)."""
    cell: Path
    """The cell file (absolute)."""
    parameters: dict[str, Parameter] = {}
    """The task's own parameters with their bound values."""
    objects: tuple[ObjectSpec, ...] = ()
    """Objects added before the first step: the task's, then those of included files."""
    scene: Path | None = None
    """The MoveIt PlanningScene file applied to the cell's world first (absolute)."""
    defaults: MotionOptions = MotionOptions()
    steps: StepList
    expect: TaskExpectation | None = None
    """What must be true when the run ends (the root file's ``expect:``)."""
    scenarios: tuple[Scenario, ...] = ()
    """The root file's ``scenarios:``."""

    def walk(self) -> Iterator[StepNode]:
        """Every step, depth first, in document order (included steps too)."""
        return walk_steps(self.steps)

    def object_materials(self) -> dict[str, Material]:
        """Mass, density and friction of every object the task declares or handles: the
        task's ``objects:``, then ``add_object`` steps (the first declaration of a name
        wins), then the objects its steps pick, attach or hand over (an empty
        :class:`Material`: the simulator's defaults). A physics backend makes these free
        bodies; other objects of the scene (a scene file's world objects) stay fixed."""
        found: dict[str, Material] = {}
        declared = [*self.objects, *(s.object for s in self.walk() if isinstance(s, AddObjectStep))]
        for obj in declared:
            if obj.name not in found:
                found[obj.name] = material_of(obj)
        for step in self.walk():
            name = getattr(step, "object", None)
            if isinstance(name, str) and isinstance(step, _HANDLING) and name not in found:
                found[name] = Material()
        return found

    def to_document(self) -> dict[str, Any]:
        """The task as a plain YAML document (values substituted, paths absolute) that
        :func:`~taskrunner.tasks.loader.load_task_text` loads back to an equal spec."""
        doc: dict[str, Any] = {"task": self.name}
        if self.description:
            doc["description"] = self.description
        doc["cell"] = str(self.cell)
        if self.parameters:
            doc["parameters"] = {
                p.name: {k: v for k, v in (("default", p.default), ("type", p.type),
                                           ("min", p.min), ("max", p.max),
                                           ("description", p.description)) if v not in (None, "")}
                for p in self.parameters.values()}
        if self.objects:
            doc["objects"] = [_dump(o) for o in self.objects]
        if self.scene is not None:
            doc["scene"] = str(self.scene)
        defaults = _dump(self.defaults)
        if defaults:
            doc["defaults"] = defaults
        doc["steps"] = [step_document(s) for s in self.steps]
        if self.expect is not None:
            doc["expect"] = _dump(self.expect)
        if self.scenarios:
            doc["scenarios"] = [_dump(s) for s in self.scenarios]
        return doc


def _dump(node: Node) -> Any:
    return node.model_dump(mode="json", by_alias=True, exclude_defaults=True)


def step_document(step: StepNode) -> dict[str, Any]:
    """One step as its YAML form ``{verb: body}``."""
    if isinstance(step, _ListComposite):
        return {step.verb: [step_document(s) for s in step.steps]}
    if isinstance(step, _DoComposite):
        body = _dump(step.model_copy(update={"do": ()}))
        body["do"] = [step_document(s) for s in step.do]
        return {step.verb: body}
    if isinstance(step, IncludeStep):
        body = {"file": str(step.path), "parameters": dict(step.parameters)}
        return {step.verb: body | ({"name": step.name} if step.name else {})}
    if isinstance(step, AddObjectStep):
        return {step.verb: _dump(step.object)}
    if isinstance(step, RemoveObjectStep):
        return {step.verb: {"object": step.object}}
    body = _dump(step)
    if isinstance(step, MotionStep):  # the step's own fields first, planner options last
        body = {k: v for k, v in body.items() if k not in MOTION_OPTIONS} | {
            k: v for k, v in body.items() if k in MOTION_OPTIONS}
    return {step.verb: body}
