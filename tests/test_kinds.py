"""Kinds and codes are defined once (taskrunner.kinds) and keep the values that records,
the REST API and scripts reading ``run-task``'s exit status already hold."""

from __future__ import annotations

import ast
import json
from pathlib import Path

from py_trees.common import Status

from taskrunner import cli
from taskrunner.api import schemas
from taskrunner.api.cells import BACKENDS as API_BACKENDS
from taskrunner.errors import BackendError, PlanningError, TaskSpecError
from taskrunner.kinds import (
    BackendKind,
    CollisionChoice,
    EventKind,
    ExitCode,
    FailureKind,
    NodeStatus,
    RunStatus,
    StopReason,
    WaitKind,
)
from taskrunner.robot import description
from taskrunner.robot.cell import RobotSpec
from taskrunner.runtime.events import KINDS
from taskrunner.runtime.records import STATUSES
from taskrunner.runtime.runner import CANCELLED, EXIT_CODES, error_kind
from taskrunner.runtime.session import BACKENDS
from taskrunner.scene import linkgeometry

PACKAGE = Path(__file__).resolve().parents[1] / "taskrunner"


def _members(enum: type) -> dict[str, object]:
    return {member.name: member.value for member in enum}


def test_the_values_are_those_records_and_scripts_already_hold():
    """New kinds may come; the ones records and scripts hold keep their values."""
    assert _members(ExitCode).items() >= {
        "OK": 0, "INVALID": 2, "PLANNING": 3, "EXECUTION": 4, "CANCELLED": 130,
        "TERMINATED": 143}.items()
    assert _members(BackendKind).items() >= {
        "MOCK": "mock", "SIM": "sim", "MUJOCO": "mujoco", "SERIAL": "serial",
        "HTTP": "http"}.items()
    assert _members(RunStatus).items() >= {
        "RUNNING": "running", "SUCCEEDED": "succeeded", "FAILED": "failed",
        "CANCELLED": "cancelled", "INTERRUPTED": "interrupted"}.items()
    assert _members(EventKind).items() >= {
        "RUN_STARTED": "run_started", "NODE_STARTED": "node_started",
        "NODE_FINISHED": "node_finished", "PLANNED": "planned", "MOTION": "motion",
        "PHYSICS": "physics", "WAIT": "wait", "MESSAGE": "message",
        "RUN_FINISHED": "run_finished"}.items()
    assert _members(StopReason).items() >= {
        "IK": "ik", "COLLISION": "collision", "JUMP": "jump"}.items()
    assert _members(NodeStatus).items() >= {
        "SUCCESS": "SUCCESS", "FAILURE": "FAILURE", "RUNNING": "RUNNING",
        "INVALID": "INVALID", "CANCELLED": "CANCELLED"}.items()
    assert _members(CollisionChoice).items() >= {
        "EXACT": "exact", "CONVEX": "convex", "AUTO": "auto"}.items()
    assert _members(WaitKind).items() >= {"DELAY": "delay", "UNTIL_END": "until_end"}.items()


def test_every_user_takes_its_kinds_from_the_enums():
    values = tuple(k.value for k in BackendKind)
    assert BACKENDS == API_BACKENDS == values
    assert all(type(v) is str for v in (*BACKENDS, *KINDS, *STATUSES))  # plain text in records
    assert KINDS == tuple(k.value for k in EventKind)
    assert STATUSES == tuple(s.value for s in RunStatus)
    assert schemas.Backend is BackendKind
    assert schemas.RunSummary.model_fields["status"].annotation is RunStatus
    run = next(a for a in cli._parser()._subparsers._group_actions[0].choices["run"]._actions
               if a.dest == "backend")
    assert list(run.choices) == list(values)
    assert EXIT_CODES == {"succeeded": 0, "invalid": 2, "planning": 3, "execution": 4,
                          "cancelled": 130, "terminated": 143}
    assert all(type(v) is int for v in EXIT_CODES.values())
    assert (cli.EXIT_OK, cli.EXIT_INVALID, cli.EXIT_PLANNING, cli.EXIT_EXECUTION,
            cli.EXIT_CANCELLED) == (0, 2, 3, 4, 130)


def test_an_api_answer_keeps_its_bytes():
    accepted = schemas.RunAccepted(run_id="r1", status=RunStatus.RUNNING, url="/runs/r1")
    assert accepted.model_dump_json() == '{"run_id":"r1","status":"running","url":"/runs/r1"}'
    body = schemas.RunCreate.model_validate({"task": "t.yaml", "backend": "mock"})
    assert body.backend == "mock" and json.loads(body.model_dump_json())["backend"] == "mock"
    assert schemas.RunCreate.model_validate({"task": "t.yaml"}).backend == "sim"
    assert json.dumps({"backend": BackendKind.SIM, "code": ExitCode.PLANNING}) \
        == '{"backend": "sim", "code": 3}'


def test_a_failure_kind_names_its_exit_code():
    kinds = [error_kind(e) for e in (PlanningError("x"), BackendError("x"), TaskSpecError("x"))]
    assert kinds == ["planning", "execution", "invalid"] == [k.value for k in (
        FailureKind.PLANNING, FailureKind.EXECUTION, FailureKind.INVALID)]
    assert [EXIT_CODES[k] for k in kinds] == [ExitCode.PLANNING, ExitCode.EXECUTION,
                                              ExitCode.INVALID]


def test_node_status_and_collision_choice_users_take_the_enums():
    # A node's status is py_trees' own value, or CANCELLED (which py_trees has not).
    assert {s.value for s in Status} | {CANCELLED} == {s.value for s in NodeStatus}
    assert CANCELLED == NodeStatus.CANCELLED and type(CANCELLED) is str  # plain in records
    values = tuple(c.value for c in CollisionChoice)
    assert description.COLLISION_CHOICES == linkgeometry.COLLISION_CHOICES == values
    parser = cli._parser()
    run = parser._subparsers._group_actions[0].choices["run"]
    serve = parser._subparsers._group_actions[0].choices["serve"]
    for command in (run, serve):
        collision = next(a for a in command._actions if a.dest == "collision")
        assert tuple(collision.choices) == values
    assert RobotSpec.model_fields["collision"].annotation == CollisionChoice | None
    assert RobotSpec.model_validate({"name": "a", "robot": "r", "collision": "convex"}
                                    ).collision is CollisionChoice.CONVEX


# Words that are a kind's value only where a kind is meant: a string literal equal to
# one of these outside taskrunner/kinds.py is a copy that can drift.
_COPIES = {**{s.value: NodeStatus for s in NodeStatus},
           **{c.value: CollisionChoice for c in CollisionChoice if c is not CollisionChoice.AUTO}}
# "auto" also names Ray's cluster discovery: a copy of the collision choice only where a
# collision is in the same statement.
_STRAGGLERS: set[tuple[str, str]] = set()
"""Copies in modules being rewritten elsewhere at the time of writing, to convert there."""


def _string_literals(path: Path) -> list[tuple[int, str, str]]:
    """(line, value, the line's text) of each string constant of a module's code
    (not docstrings, which are prose, nor the names in ``__all__``)."""
    text = path.read_text(encoding="utf-8")
    tree = ast.parse(text)
    skip: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant):
            skip.add(id(node.value))
        if isinstance(node, ast.Assign | ast.AugAssign | ast.AnnAssign):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            if any(isinstance(t, ast.Name) and t.id == "__all__" for t in targets):
                skip.update(id(n) for n in ast.walk(node))
    lines = text.splitlines()
    return [(node.lineno, node.value, lines[node.lineno - 1]) for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and isinstance(node.value, str)
            and id(node) not in skip]


def test_no_module_keeps_its_own_copy_of_a_node_status_or_a_collision_choice():
    stray = []
    for path in sorted(PACKAGE.rglob("*.py")):
        where = str(path.relative_to(PACKAGE))
        if where == "kinds.py":
            continue
        for line, value, text in _string_literals(path):
            copy = value in _COPIES or (value == "auto" and "collision" in text.lower())
            if copy and (where, value) not in _STRAGGLERS:
                stray.append(f"taskrunner/{where}:{line}: {value!r}")
    assert not stray, "use taskrunner.kinds instead of:\n" + "\n".join(stray)
