"""Kinds and codes are defined once (taskrunner.kinds) and keep the values that records,
the REST API and scripts reading ``run-task``'s exit status already hold."""

from __future__ import annotations

import json

from taskrunner import cli
from taskrunner.api import schemas
from taskrunner.api.cells import BACKENDS as API_BACKENDS
from taskrunner.errors import BackendError, PlanningError, TaskSpecError
from taskrunner.kinds import BackendKind, EventKind, ExitCode, FailureKind, RunStatus, StopReason
from taskrunner.runtime.events import KINDS
from taskrunner.runtime.records import STATUSES
from taskrunner.runtime.runner import EXIT_CODES, error_kind
from taskrunner.runtime.session import BACKENDS


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
