"""One of our errors escaping a leaf ends the run with the exit code of its kind, as
``run-task`` maps errors it catches: planning 3, execution 4, invalid input 2."""

from __future__ import annotations

import textwrap

import pytest

from taskrunner.backends.mock import MockBackend
from taskrunner.errors import (
    BackendError,
    IkFailedError,
    InputError,
    SceneError,
    TrajectoryRejectedError,
    UnknownNameError,
)
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import EXIT_CODES, Runner, RunOptions, error_kind
from taskrunner.tasks import load_task


@pytest.mark.parametrize(("error", "kind", "code"), [
    (IkFailedError("no IK"), "planning", 3),
    (BackendError("controller gone"), "execution", 4),
    (TrajectoryRejectedError("joint 'j1' too fast"), "execution", 4),
    (InputError("bad value"), "invalid", 2),
    (UnknownNameError("object", "cube", ["box"]), "invalid", 2),
    (SceneError("object 'cube' exists"), "invalid", 2),
])
def test_an_error_escaping_a_leaf_ends_the_run_with_its_kinds_exit_code(tmp_path, error, kind,
                                                                       code):
    assert error_kind(error) == kind and EXIT_CODES[kind] == code
    path = tmp_path / "task.yaml"
    cell_file = DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"
    path.write_text(f"task: t\ncell: {cell_file}\n" + textwrap.dedent("""\
        steps:
          - go: {group: arm, to: Candle}
        """))
    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state(), strict=True)))
    runner = Runner(spec, cell, backend, InProcessPlanner(), RunOptions())

    def tick_once() -> None:
        raise error

    runner.tree.tick_once = tick_once  # type: ignore[method-assign]
    record = runner.run()
    assert record.status == "failed"
    assert record.exit_code == code
    assert runner.failure_kind == kind
    assert str(error) in (record.error or "")
