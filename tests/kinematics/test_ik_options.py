"""IkOptions checks and the package's public names."""

from __future__ import annotations

import pytest

from taskrunner import kinematics
from taskrunner.kinematics import IkOptions


def test_the_public_names_are_pinned() -> None:
    assert sorted(kinematics.__all__) == [
        "IkOptions", "IkSolution", "IkSolver", "IkTarget", "frame_jacobian", "frame_pose",
        "frame_poses", "is_reachable", "solve_ik",
    ]


def test_defaults_take_timeout_and_attempts_from_the_group() -> None:
    options = IkOptions()
    assert options.tolerance == 1e-5 and options.rotation_tol == 1e-5
    assert options.timeout is None and options.attempts is None
    assert options.position_only is None and options.num_solutions == 1
    assert IkOptions(tolerance=1e-4, rotation_tolerance=1e-3).rotation_tol == 1e-3


@pytest.mark.parametrize(
    ("field", "value", "message"),
    [
        ("tolerance", 0.0, "'tolerance' must be a positive number (got 0.0)"),
        ("tolerance", float("nan"), "'tolerance' must be a positive number"),
        ("rotation_tolerance", -1.0, "'rotation_tolerance' must be a positive number"),
        ("max_iterations", 0, "'max_iterations' must be a positive integer (got 0)"),
        ("max_iterations", 2.5, "'max_iterations' must be a positive integer"),
        ("timeout", -0.1, "'timeout' must be a positive number"),
        ("attempts", True, "'attempts' must be a positive integer (got True)"),
        ("num_solutions", 0, "'num_solutions' must be a positive integer"),
        ("seed", 1.5, "'seed' must be an integer (got 1.5)"),
        ("position_only", "yes", "'position_only' must be True, False or None"),
        ("min_distance", -1.0, "'min_distance' must be a number >= 0 (got -1.0)"),
    ],
)
def test_bad_options_are_rejected_with_the_field_named(field: str, value, message: str) -> None:
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        IkOptions(**{field: value})


def test_options_are_frozen() -> None:
    with pytest.raises(AttributeError):
        IkOptions().tolerance = 1.0  # type: ignore[misc]
