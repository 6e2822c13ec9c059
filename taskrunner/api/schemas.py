"""Request and response bodies of the API (pydantic, unknown fields refused)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from taskrunner.kinds import BackendKind, RunStatus
from taskrunner.posespec import PoseFields, Position
from taskrunner.runtime.events import RunEvent
from taskrunner.validation import Integer, Number

__all__ = [
    "CellDetail", "CellState", "CellSummary", "CheckRequest", "CheckResponse", "ErrorBody",
    "EventOut", "GroupOut", "Health", "ObjectOut", "PlanBody", "PlanResponse", "ProblemOut",
    "RobotOut", "RunAccepted", "RunCreate", "RunDetail", "RunSummary", "TeachBody", "TeachResponse",
]

MAX_YAML_CHARS = 200_000
MAX_PARAMETERS = 1_000
"""Most parameter overrides one request may give (a task declares a handful)."""
MAX_JOINTS = 256
"""Most joint values one request may give."""


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


class _Request(_Strict):
    # Numbers of a request are finite (JSON's NaN and Infinity refused); Number and
    # Integer also refuse booleans and text where a number belongs.
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)


class _TaskSource(_Request):
    task: str | None = Field(default=None, max_length=255,
                             description="a task file name in the tasks folder")
    yaml: str | None = Field(default=None, max_length=MAX_YAML_CHARS,
                             description="the task as inline YAML; relative paths start "
                                         "from the tasks folder")
    parameters: dict[str, Any] = Field(default_factory=dict, max_length=MAX_PARAMETERS,
                                       description="overrides of the task's parameters "
                                                   f"(at most {MAX_PARAMETERS})")
    seed: Integer = Field(default=0, ge=0, le=2**31 - 1)

    @model_validator(mode="after")
    def _one_source(self) -> _TaskSource:
        if (self.task is None) == (self.yaml is None):
            raise ValueError("give exactly one of 'task' (a file name) and 'yaml' (inline)")
        return self


Backend = BackendKind


class RunCreate(_TaskSource):
    backend: Backend = Field(default=BackendKind.SIM, description="sim, mock, mujoco (physics; the "
                             "mujoco extra), or the cell's servos over serial or http (the "
                             "port and URL the server is set up with)")
    speed: Number | None = Field(default=None, gt=0, le=1000,
                                description="time scale of the sim backend (2: twice real "
                                            "time); default: the server's")
    cell: str | None = Field(default=None, max_length=255,
                             description="run on this cell (an id of GET /cells) instead of "
                                         "the task's own")
    check: bool = Field(default=True,
                        description="check the task first (as POST /tasks/check does) and "
                                    "start nothing if the check finds a problem (422 with "
                                    "every problem at its file:line); false skips it")


class RunAccepted(_Strict):
    run_id: str
    status: RunStatus
    url: str


EventOut = RunEvent
"""An event as the API sends it: the run record's own model, not a copy of it (the same
fields, defaults and JSON)."""


class RunSummary(_Strict):
    run_id: str
    status: RunStatus
    task: str
    cell: str
    backend: str
    started: str
    finished: str | None = None
    exit_code: int | None = None
    error: str | None = None


class CurrentNode(_Strict):
    node: str
    location: str | None = None


class RunDetail(RunSummary):
    task_file: str
    parameters: dict[str, Any]
    current: CurrentNode | None = None
    tree: str | None = Field(default=None, description="the behaviour tree with each node's "
                                                       "status (runs of this server only)")
    events_more: bool = Field(default=False, description="more events are recorded after the "
                                                         "last one shown: ask again with "
                                                         "?since=<its seq>")
    events: list[EventOut]


class ProblemOut(_Strict):
    file: str | None
    line: int | None
    message: str
    text: str = Field(description="file:line: message, as run-task check prints it")


class CheckRequest(_TaskSource):
    pass


class LeastClearanceOut(_Strict):
    distance: float | None = Field(description="m, the least distance measured between "
                                   "two branches' links (null: no two arms move at once)")
    lower: float | None = Field(description="m, proven: the arms never come closer")
    links: list[str] | None
    time: float | None = Field(description="s on the parallel's schedule")
    steps: list[str | None] = Field(description="each link's step (file:line) moving then; "
                                    "null: that arm rests")


class OverlapOut(_Strict):
    steps: list[str | None]
    start: float | None
    end: float | None
    seconds: float | None


class ScheduleWaitOut(_Strict):
    step: str | None
    since: float | None
    until: float | None
    reason: str


class PlannedMotionOut(_Strict):
    step: str | None = Field(description="the motion's step (file:line)")
    joints: list[str] = Field(description="the joints it moves")
    start: float | None = Field(description="s on the parallel's schedule")
    end: float | None = Field(description="s on the parallel's schedule")


class ScheduleOut(_Strict):
    """What a ``parallel``'s schedule proves (``taskrunner.tree.schedule_proof``)."""

    least_clearance: LeastClearanceOut
    overlaps: list[OverlapOut]
    waits: list[ScheduleWaitOut]
    motions: int
    makespan: float | None
    timeline: list[PlannedMotionOut] = Field(
        default=[], description="every motion where the check's schedule put it, in order "
                                "of its start: each arm's timeline before anything runs")


class CheckResponse(_Strict):
    ok: bool
    cell: str
    steps: int
    problems: list[ProblemOut]
    schedules: list[ScheduleOut] = []


class ErrorBody(_Strict):
    detail: Any
    location: str | None = None
    problems: list[ProblemOut] | None = None


class RobotOut(_Strict):
    name: str
    prefix: str
    xyz: list[float]


class GroupOut(_Strict):
    name: str
    joints: list[str]
    tip_link: str | None
    poses: list[str]


class ObjectOut(_Strict):
    name: str
    shape: str
    frame: str
    xyz: list[float]


class CellSummary(_Strict):
    id: str
    name: str
    description: str


class CellDetail(CellSummary):
    robots: list[RobotOut]
    groups: list[GroupOut]
    objects: list[ObjectOut]


class AttachedOut(_Strict):
    name: str
    link: str


class CellState(_Strict):
    id: str
    backend: str
    joints: dict[str, float]
    attached: list[AttachedOut]
    running: list[str] = Field(description="ids of the runs in flight on this cell")


class PoseTarget(_Request, PoseFields):
    """A link's pose: ``xyz`` (m) and ``rpy`` (rad) or ``quat`` (x, y, z, w; neither: the
    identity) in ``frame``: the pose model of task and cell files."""

    xyz: Position
    """Translation (m)."""
    link: str | None = None
    position_only: bool | None = None


class PlanBody(_Request):
    """Plan one motion of a group from the cell's current state; nothing moves."""

    cell: str
    group: str
    to: str | None = Field(default=None, description="a named pose of the group (go)")
    joints: dict[str, Number] | None = Field(default=None, max_length=MAX_JOINTS,
                                             description="joint values (go)")
    pose: PoseTarget | None = Field(default=None, description="a link pose (move)")
    backend: Backend = BackendKind.SIM
    planning_time: Number = Field(default=5.0, gt=0, le=30,
                                 description="seconds allowed to search, a cap and not a "
                                             "target: planning stops at the first path")
    seed: Integer = Field(default=0, ge=0, le=2**31 - 1)
    velocity_scaling: Number | None = Field(default=None, gt=0, le=1)
    sample_rate_hz: Number = Field(default=100.0, ge=1, le=1000,
                                  description="samples per second of the trajectory")

    @model_validator(mode="after")
    def _one_goal(self) -> PlanBody:
        if sum(x is not None for x in (self.to, self.joints, self.pose)) != 1:
            raise ValueError("give exactly one goal: 'to', 'joints' or 'pose'")
        if self.joints is not None and not self.joints:
            raise ValueError("'joints' must name at least one joint")
        return self


class PlanResponse(_Strict):
    group: str
    joint_names: list[str]
    times: list[float]
    positions: list[list[float]]
    velocities: list[list[float]]
    duration: float
    planning_time: float
    waypoints: int


class TeachBody(_Request):
    group: str
    backend: Backend = BackendKind.SIM


class TeachResponse(_Strict):
    cell: str
    group: str
    name: str
    joints: dict[str, float]


class Health(_Strict):
    status: Literal["ok"]
    runs_in_flight: int
    auth: bool


class TeachRequest(_Request):
    group: str = Field(description="the group whose joints the pose sets")
    backend: Backend = Field(default=BackendKind.SIM, description="whose joint state to store")


class TaughtPose(_Strict):
    cell: str
    group: str
    name: str
    joints: dict[str, float] = Field(description="rad or m")
    taught: str = Field(description="when (ISO 8601, UTC)")
