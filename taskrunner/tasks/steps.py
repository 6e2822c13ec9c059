"""The step models: one frozen class per step verb.

A task file's ``steps`` is a list of one-key mappings ``verb: body``. Each verb has a
class here (``GoStep`` for ``go``, ``SequenceStep`` for ``sequence`` …), all derived
from :class:`StepNode`, with ``verb`` as a class attribute. The loader
(:mod:`taskrunner.tasks.loader`) builds them; a compiler walks them::

    for step in spec.walk():
        match step:
            case GoStep(group=group, to=str(pose)): ...
            case PickStep(): ...

Leaves that move (:class:`MotionStep`) carry the planner options; the loader fills the
ones a step leaves unset from the task's ``defaults`` (an included file's defaults
first), so ``step.velocity_scaling`` is the effective value (None: the planner's own).
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Annotated, Any, ClassVar, Literal

from pydantic import (
    AliasChoices,
    BaseModel,
    ConfigDict,
    Discriminator,
    Field,
    Tag,
    ValidationInfo,
    WithJsonSchema,
    field_validator,
    model_validator,
)

from taskrunner.errors import ArgumentError
from taskrunner.tasks.expect import Expectation, OutcomeTolerance
from taskrunner.tasks.nodes import (
    Node,
    ObjectSpec,
    PoseSpec,
    TargetPose,
    Transform,
    Vec2,
    describe_fields,
)
from taskrunner.validation import MAX_METRES, Integer, Number

__all__ = [
    "MOMENTS", "AddObjectStep", "AttachStep", "CompositeStep", "DetachStep", "ExpectStep", "FallbackStep",
    "GoStep", "GraspPose",
    "GripperStep", "HandoffStep", "IncludeBody", "IncludeStep", "MOTION_OPTIONS",
    "MOTION_VERBS", "MotionOptions", "MotionStep", "MoveStep", "Offset", "OutcomeTolerance",
    "ParallelStep",
    "PickStep", "PlaceStep", "RemoveObjectStep", "RepeatStep", "RetryStep", "STEP_TYPES",
    "SequenceStep", "Step", "StepList", "StepNode", "TimeoutStep", "WaitFor", "WaitStep",
    "walk_steps",
]

STEP_LIST_SCHEMA = {"type": "array", "items": {"$ref": "#/$defs/Step"}, "minItems": 1}
StepList = Annotated[tuple["Step", ...], WithJsonSchema(STEP_LIST_SCHEMA)]
Scaling = Annotated[Number, Field(gt=0, le=1)]
Distance = Annotated[Number, Field(ge=0, le=MAX_METRES)]
MAX_TIMES = 1_000_000
"""Most runs of a ``repeat`` and attempts of a ``retry``: a bound, so that a typo (or
``2**63``) is refused rather than run until the machine stops."""
MAX_SECONDS = 86_400.0
"""Longest ``wait`` or ``timeout`` (s): a day."""
MAX_PLANNING_TIME = 600.0
"""Longest ``planning_time`` of one motion (s)."""


def _exactly_one(node: Node, *names: str) -> None:
    """Raise unless exactly one of the fields (YAML keys ``names``) is set."""
    attrs = {"from": "from_arm", "to": "to"}
    given = [n for n in names if getattr(node, attrs.get(n, n)) is not None]
    listed = ", ".join(repr(n) for n in names[:-1]) + f" or {names[-1]!r}"
    if not given:
        raise ArgumentError(f"needs one of {listed}")
    if len(given) > 1:
        raise ArgumentError(f"takes only one of {listed} (got {' and '.join(repr(g) for g in given)})")


def _named_or_mapping(value: Any) -> str:
    """Tag of a 'name or pose' field: a mapping (or a built pose) is a pose."""
    return "<pose>" if isinstance(value, (dict, Node)) else "<name>"


MOMENTS: dict[str, tuple[str, ...]] = {
    "place": ("set_down", "released"),
    "pick": ("grasped",),
}
"""The moments within a step, by verb, that a ``wait_for`` can name (``until``) besides
``finished`` (every step has it): a ``place``'s object ``set_down`` at its target (still
held) and ``released`` (the gripper opened, before the retreat); a ``pick``'s object
``grasped`` (the gripper closed on it, before the lift)."""


class WaitFor(Node):
    """What a step of a ``parallel``'s branch waits for before it starts."""

    step: str = Field(min_length=1)
    """The ``name`` of a step of another branch of the same ``parallel``: this step
    starts when that one has reached ``until``."""
    until: Literal["finished", "set_down", "released", "grasped"] = "finished"
    """The moment of that step: ``finished`` (all of it), or one within it
    (:data:`MOMENTS`: which verbs have which)."""


# ------------------------------------------------------------------------- base classes
class StepNode(Node):
    """Base of every step. ``verb`` is the YAML key; ``body`` the shape of its value."""

    verb: ClassVar[str] = ""
    body: ClassVar[Literal["mapping", "list", "object"]] = "mapping"

    @property
    def children(self) -> tuple[StepNode, ...]:
        """The steps directly under this one (none for a leaf)."""
        return ()

    @property
    def label(self) -> str:
        """A short text for displays: the step's ``name``, or its verb and main argument."""
        name = getattr(self, "name", None)
        if name:
            return str(name)
        for attr in ("object", "group", "arm", "to", "task"):
            value = getattr(self, attr, None)
            if isinstance(value, str):
                return f"{self.verb} {value}"
            if isinstance(value, ObjectSpec):
                return f"{self.verb} {value.name}"
        return self.verb


class MotionOptions(Node):
    """Planner options of a motion step (the task's ``defaults`` has the same fields)."""

    planner: str | None = None
    """Planner name (default: the planning layer's default)."""
    velocity_scaling: Scaling | None = None
    """Fraction of the joints' maximum velocities, in (0, 1]."""
    acceleration_scaling: Scaling | None = None
    """Fraction of the joints' maximum accelerations, in (0, 1]."""
    planning_time: Number | None = Field(default=None, gt=0, le=MAX_PLANNING_TIME)
    """Time allowed to plan (s)."""


MOTION_OPTIONS = tuple(MotionOptions.model_fields)


class MotionStep(StepNode, MotionOptions):
    """A leaf that moves the robot."""

    name: str | None = None
    """Label for displays."""
    wait_for: WaitFor | None = None
    """In a ``parallel``'s branch: start when a step of another branch has finished (or
    reached a moment within it: ``until``)."""


# ------------------------------------------------------------------------------- leaves
class GoStep(MotionStep):
    """Move a group to a named pose, joint values, or a pose of its tip (planned)."""

    verb: ClassVar[str] = "go"
    group: str
    """The group to move."""
    to: str | None = None
    """A named pose of the group."""
    joints: dict[str, Number] | None = Field(default=None, min_length=1)
    """Joint values {joint: rad or m}; the group's other joints keep their values."""
    pose: TargetPose | None = None
    """A pose for the group's tip (or 'link')."""

    @model_validator(mode="after")
    def _one_target(self) -> GoStep:
        _exactly_one(self, "to", "joints", "pose")
        return self


class Offset(Transform):
    """A relative motion of a link: translation and rotation in the tool or world frame."""

    frame: Literal["tool", "world"] = "tool"
    """Axes of the offset: the moved link's ('tool') or the world's."""


class MoveStep(MotionStep):
    """Move a link to a pose, or by an offset; by default in a straight line for 'by'."""

    verb: ClassVar[str] = "move"
    group: str
    """The group to move."""
    pose: TargetPose | None = None
    """Absolute target pose."""
    by: Offset | None = None
    """Relative motion from where the link is."""
    link: str | None = None
    """The link to move (default: the group's tip)."""
    cartesian: bool = Field(default=None, validate_default=True,  # type: ignore[call-overload]
                            json_schema_extra=lambda s: s.pop("default", None))
    """Straight line in Cartesian space (default: true with 'by', false with 'pose')."""

    @field_validator("cartesian", mode="before")
    @classmethod
    def _cartesian_default(cls, value: Any, info: ValidationInfo) -> Any:
        return info.data.get("by") is not None if value is None else value

    @model_validator(mode="after")
    def _one_target(self) -> MoveStep:
        _exactly_one(self, "pose", "by")
        if self.link is not None and self.pose is not None and self.pose.link is not None:
            raise ValueError("takes only one of 'link' or 'pose.link'")
        return self

    @property
    def target_link(self) -> str | None:
        """The link to move as written ('link' or 'pose.link'); None: the group's tip."""
        return self.link if self.link is not None else (self.pose.link if self.pose else None)


class GripperStep(MotionStep):
    """Open, close or set a gripper: of an arm (its end effector's group) or a group."""

    verb: ClassVar[str] = "gripper"
    arm: str | None = None
    """An arm whose end effector has a gripper group."""
    group: str | None = None
    """A gripper group."""
    action: Literal["open", "close"] | None = None
    """Open or close fully."""
    to: str | None = None
    """A named pose of the gripper group."""
    width: Distance | None = None
    """Opening between the fingers (m), for grippers with prismatic fingers."""

    @model_validator(mode="after")
    def _one_each(self) -> GripperStep:
        _exactly_one(self, "arm", "group")
        _exactly_one(self, "action", "to", "width")
        return self


class GraspPose(Transform):
    """An explicit grasp: the pose of a link of the arm's hand in the object's frame."""

    link: str | None = None
    """The link (or frame) whose pose this is, e.g. the flange; it must move with the arm's
    tool frame (no joint between them). Default: the arm's tool frame (z out of the hand,
    y the axis the fingers close along)."""


Grasp = Annotated[
    Annotated[Literal["top", "side"], Tag("<name>")] | Annotated[GraspPose, Tag("<pose>")],
    Discriminator(_named_or_mapping),
]
PlaceAt = Annotated[
    Annotated[str, Tag("<name>")] | Annotated[PoseSpec, Tag("<pose>")],
    Discriminator(_named_or_mapping),
]


OrientationCheck = Literal["free", "yaw", "full"]


class PickStep(MotionStep):
    """Approach, grasp, attach and lift an object."""

    verb: ClassVar[str] = "pick"
    arm: str
    """The arm that picks."""
    object: str
    """The object to pick."""
    grasp: Grasp = "top"
    """'top', 'side', or the grasp pose of the tool in the object's frame (the arm's tool
    frame: z out of the hand, y the axis the fingers close along; with 'link', the pose of
    that link instead)."""
    approach: Distance = 0.05
    """Distance of the straight approach to the grasp (m)."""
    retreat: Distance = 0.05
    """Distance of the straight retreat after grasping (m)."""


class PlaceStep(MotionStep):
    """Carry a held object to a pose, or onto a surface object, and release it."""

    verb: ClassVar[str] = "place"
    arm: str
    """The arm holding the object."""
    object: str
    """The object to place."""
    at: PoseSpec | None = None
    """Pose of the object where it is released."""
    on: str | None = None
    """A surface object to put it on top of."""
    offset: Vec2 | None = None
    """With 'on': x, y from the surface's centre (m, surface frame)."""
    grasp: Grasp | None = None
    """How the hand is over the object when it lets go: 'top' (the tool pointing down),
    'side' (pointing sideways), or the tool's pose in the placed object's frame. The
    object is held as it was picked, so this chooses among the ways the object can be
    turned onto its target (its symmetries). Default: any."""
    approach: Distance = 0.05
    """Distance of the straight approach to the release pose (m)."""
    retreat: Distance = 0.05
    """Distance of the straight retreat after releasing (m)."""
    orientation: OrientationCheck | None = None
    """What of the object's orientation is checked when it is put down: 'free' (position
    only), 'yaw' (its turn about the world z axis; its tilt is not checked) or 'full'
    (the whole orientation, up to the object's symmetries). Default: what the arm
    controls: 'full' for an arm that plans full poses; for a position-only arm
    (position_only_ik) 'yaw' with a wrist roll, else 'free'."""
    tolerance: OutcomeTolerance = OutcomeTolerance()
    """How far the object may end from its target (default 5 mm, 5 degrees)."""

    @model_validator(mode="after")
    def _one_target(self) -> PlaceStep:
        _exactly_one(self, "at", "on")
        if self.offset is not None and self.on is None:
            raise ValueError("takes 'offset' only with 'on'")
        return self


class HandoffStep(MotionStep):
    """Pass a held object from one arm to another."""

    verb: ClassVar[str] = "handoff"
    object: str
    """The object handed over."""
    from_arm: str = Field(alias="from")
    """The arm holding the object."""
    to_arm: str = Field(alias="to")
    """The arm taking it."""
    at: PlaceAt
    """A named pose of the giving arm, or the pose of the object at the hand-over."""
    grasp: Grasp | None = None
    """How the taking arm grasps the object where it is presented: 'top', 'side', or the
    pose of its tool in the object's frame, as for 'pick'. Default: across the end of
    the object that the giving arm leaves free."""
    approach: Distance = 0.05
    """Distance of the taking arm's straight approach (m)."""
    retreat: Distance = 0.05
    """Distance both arms retreat after the exchange (m)."""
    orientation: OrientationCheck | None = None
    """What of the object's orientation is checked when it changes hands: 'free' (position
    only), 'yaw' (its turn about the world z axis; its tilt is not checked) or 'full'
    (the whole orientation, up to the object's symmetries). Default: what the giving arm
    controls: 'full' for an arm that plans full poses; for a position-only arm
    (position_only_ik) 'yaw' with a wrist roll, else 'free'."""
    tolerance: OutcomeTolerance = OutcomeTolerance()
    """How far the object may end from its target (default 5 mm, 5 degrees)."""


class AttachStep(StepNode):
    """Attach a scene object to an arm's tool (or a link), without moving."""

    verb: ClassVar[str] = "attach"
    name: str | None = None
    """Label for displays."""
    wait_for: WaitFor | None = None
    """In a ``parallel``'s branch: start when a step of another branch has finished (or
    reached a moment within it: ``until``)."""
    object: str
    """The object to attach."""
    arm: str | None = None
    """Attach to this arm's tool (the link its grasped objects hang from); its fingers and
    palm may touch the object."""
    link: str | None = None
    """Attach to this link (a suction cup, a magnet); it may touch the object."""
    touch_links: tuple[str, ...] = ()
    """Other links allowed to touch the object while it is attached (MoveIt's
    ``touch_links``), besides the holding link (and an arm's hand)."""

    @model_validator(mode="after")
    def _one_holder(self) -> AttachStep:
        _exactly_one(self, "arm", "link")
        return self


class DetachStep(StepNode):
    """Detach an attached object, leaving it where it is in the world."""

    verb: ClassVar[str] = "detach"
    name: str | None = None
    """Label for displays."""
    wait_for: WaitFor | None = None
    """In a ``parallel``'s branch: start when a step of another branch has finished (or
    reached a moment within it: ``until``)."""
    object: str
    """The object to detach."""


class AddObjectStep(StepNode):
    """Add an object to the scene. YAML: ``add_object: {name: …, shape: …, …}``."""

    verb: ClassVar[str] = "add_object"
    body: ClassVar[Literal["mapping", "list", "object"]] = "object"
    object: ObjectSpec


def _name_or_object_schema(schema: dict[str, Any], cls: type[BaseModel]) -> None:
    describe_fields(schema, cls)
    schema["properties"]["name"] = dict(schema["properties"]["object"])
    schema.pop("required", None)
    schema["oneOf"] = [{"required": ["name"]}, {"required": ["object"]}]


class RemoveObjectStep(StepNode):
    """Remove an object from the scene. YAML: ``remove_object: {name: cube}`` (or object:)."""

    verb: ClassVar[str] = "remove_object"
    model_config = ConfigDict(json_schema_extra=_name_or_object_schema)
    object: str = Field(validation_alias=AliasChoices("object", "name"))
    """The object to remove ('name' is accepted too)."""

    @model_validator(mode="before")
    @classmethod
    def _object_or_name(cls, data: Any) -> Any:
        if isinstance(data, dict) and "object" in data and "name" in data:
            raise ValueError("takes only one of 'object' or 'name'")
        return data


class WaitStep(StepNode):
    """Do nothing for a while."""

    verb: ClassVar[str] = "wait"
    name: str | None = None
    """Label for displays."""
    wait_for: WaitFor | None = None
    """In a ``parallel``'s branch: start when a step of another branch has finished (or
    reached a moment within it: ``until``)."""
    seconds: Number = Field(ge=0, le=MAX_SECONDS)
    """Duration (s), at most a day."""


class ExpectStep(StepNode, Expectation):
    """Check the scene, the time and the motions so far (see :mod:`taskrunner.tasks.expect`);
    FAILURE at this step's line when an expectation does not hold."""

    verb: ClassVar[str] = "expect"
    name: str | None = None
    """Label for displays."""


# --------------------------------------------------------------------------- composites
class _ListComposite(StepNode):
    """A composite whose YAML body is the list of its steps."""

    body: ClassVar[Literal["mapping", "list", "object"]] = "list"
    min_steps: ClassVar[int] = 1
    steps: StepList

    @property
    def children(self) -> tuple[StepNode, ...]:
        return self.steps


class SequenceStep(_ListComposite):
    """Run the steps in order; fail at the first failure."""

    verb: ClassVar[str] = "sequence"


class FallbackStep(_ListComposite):
    """Try the steps in order until one succeeds."""

    verb: ClassVar[str] = "fallback"


class ParallelStep(_ListComposite):
    """Run the steps at once (motions of different arms, planned together)."""

    verb: ClassVar[str] = "parallel"
    min_steps: ClassVar[int] = 2


class _DoComposite(StepNode):
    """A composite whose YAML body is a mapping with its steps under ``do``."""

    name: str | None = None
    """Label for displays."""
    wait_for: WaitFor | None = None
    """In a ``parallel``'s branch: start when a step of another branch has finished (or
    reached a moment within it: ``until``)."""
    do: StepList
    """The steps, run as a sequence."""

    @property
    def children(self) -> tuple[StepNode, ...]:
        return self.do


class RetryStep(_DoComposite):
    """Run ``do`` until it succeeds, at most ``times`` attempts in all."""

    verb: ClassVar[str] = "retry"
    times: Integer = Field(ge=1, le=MAX_TIMES)
    """Attempts in all (1: no retry), at most 1,000,000."""


class TimeoutStep(_DoComposite):
    """Run ``do``; fail if it takes longer than ``seconds``."""

    verb: ClassVar[str] = "timeout"
    seconds: Number = Field(gt=0, le=MAX_SECONDS)
    """Time limit (s), at most a day."""


class RepeatStep(_DoComposite):
    """Run ``do`` ``times`` times; fail at the first failure."""

    verb: ClassVar[str] = "repeat"
    times: Integer = Field(ge=1, le=MAX_TIMES)
    """Number of runs, at most 1,000,000."""


ScalarSchema = WithJsonSchema({"type": ["number", "boolean", "string"]})


class IncludeBody(Node):
    """What an ``include:`` step says (the loader turns it into an :class:`IncludeStep`)."""

    file: str = Field(min_length=1)
    """Another task file, relative to this one."""
    parameters: dict[str, Annotated[Any, ScalarSchema]] = {}
    """Values for the included task's parameters."""
    name: str | None = None
    """Label for displays."""
    wait_for: WaitFor | None = None
    """In a ``parallel``'s branch: start when a step of another branch has finished (or
    reached a moment within it: ``until``)."""


class IncludeStep(StepNode):
    """Another task file's steps, run as a sequence, with its parameters bound."""

    verb: ClassVar[str] = "include"
    path: Path
    """The included file (absolute)."""
    task: str
    """The included task's name."""
    parameters: dict[str, Any] = {}
    """Every parameter of the included task with its bound value."""
    steps: StepList
    name: str | None = None
    wait_for: WaitFor | None = None
    """In a ``parallel``'s branch: start when a step of another branch has finished (or
    reached a moment within it: ``until``)."""

    @property
    def children(self) -> tuple[StepNode, ...]:
        return self.steps


Step = (
    GoStep | MoveStep | GripperStep | PickStep | PlaceStep | HandoffStep | AttachStep
    | DetachStep | AddObjectStep | RemoveObjectStep | WaitStep | ExpectStep | SequenceStep
    | FallbackStep
    | ParallelStep | RetryStep | TimeoutStep | RepeatStep | IncludeStep
)
STEP_TYPES: dict[str, type[StepNode]] = {
    cls.verb: cls for cls in Step.__args__  # type: ignore[attr-defined]
}
MOTION_VERBS = frozenset(v for v, cls in STEP_TYPES.items() if issubclass(cls, MotionStep))

for _cls in (SequenceStep, FallbackStep, ParallelStep, RetryStep, TimeoutStep, RepeatStep,
             IncludeStep):
    _cls.model_rebuild()


def walk_steps(steps: tuple[StepNode, ...]) -> Iterator[StepNode]:
    """Every step under ``steps``, depth first, in document order."""
    for step in steps:
        yield step
        yield from walk_steps(step.children)



CompositeStep = _ListComposite | _DoComposite | IncludeStep
