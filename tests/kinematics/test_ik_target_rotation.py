"""An IK target whose rotation part is not a rotation (scaled, sheared, a reflection, all
zeros) is refused as an input error naming what is wrong: its SE3 log error means nothing,
and the search either "solved" it silently (position only) or failed with a residual of
inf or nan."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import InputError
from taskrunner.kinematics import IkOptions, IkSolver
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell


@pytest.fixture(scope="module")
def solver_and_start():
    cell = load_cell(DATA_ROOT / "robots" / "cells" / "so101_table.yaml")
    return IkSolver(cell.model, "arm"), cell.start_state()


def _matrix(rotation: np.ndarray) -> np.ndarray:
    out = np.eye(4)
    out[:3, :3] = rotation
    out[:3, 3] = (0.2, 0.0, 0.9)
    return out


@pytest.mark.parametrize("rotation", [
    np.diag([2.0, 2.0, 2.0]),
    np.diag([-1.0, 1.0, 1.0]),
    np.zeros((3, 3)),
    np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]),
], ids=["scaled", "reflection", "zeros", "sheared"])
@pytest.mark.parametrize("position_only", [False, True])
def test_a_target_whose_rotation_is_not_a_rotation_is_refused(solver_and_start, rotation,
                                                              position_only):
    solver, start = solver_and_start
    options = IkOptions(position_only=position_only, attempts=2)
    for call in (solver.solve, solver.solve_near, solver.solve_all):
        with pytest.raises(InputError, match="'target' must be a pose whose rotation is a "
                                             "proper rotation matrix"):
            call(_matrix(rotation), seed_q=start, options=options)


def test_a_rotation_off_orthonormal_by_float_rounding_is_accepted(solver_and_start):
    solver, start = solver_and_start
    rotation = pin.rpy.rpyToMatrix(0.1, 1.5708, -0.4) @ pin.rpy.rpyToMatrix(0.2, 0.0, 0.3)
    rotation = rotation + 1e-9  # far above float rounding, far below a wrong matrix
    solution = solver.solve(_matrix(rotation), seed_q=start,
                            options=IkOptions(position_only=True, attempts=20))
    assert solution.position_error <= 1e-5
