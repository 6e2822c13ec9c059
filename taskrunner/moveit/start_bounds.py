"""A start state just outside its joint bounds, moved onto them: MoveIt's ``FixStartStateBounds``.

MoveIt's planning pipeline runs request adapters before the planner; its
``FixStartStateBounds`` adapter moves each joint of the start state that lies outside its
bounds by less than the pipeline parameter ``start_state_max_bounds_error`` (0.05 rad or m
when unset) onto the bound, and plans from there. A start further out is left as it is, and
the planner refuses it. Recorded states often sit a hair outside a bound (a value rounded to
4 decimals, an encoder reading), so without the adapter such files could not be planned.

Here, :func:`fix_start_bounds` does the same for every bounded joint of the state (MoveIt
looks only at the request's group; our planner checks every joint of the start, so every
joint is moved or refused): an excess up to :data:`BOUNDS_TOLERANCE` is rounding and moved
silently, one up to the allowance is moved with a warning naming the joint, its value, the
bound and the excess, and one beyond the allowance is an
:class:`~taskrunner.errors.InvalidStateError` saying the same.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from taskrunner.errors import InputError, InvalidStateError
from taskrunner.robot.model import RobotModel, describe_excess

__all__ = ["BOUNDS_TOLERANCE", "START_STATE_MAX_BOUNDS_ERROR", "BoundsFix", "check_allowance",
           "describe_excess", "fix_start_bounds"]

START_STATE_MAX_BOUNDS_ERROR = 0.05
"""rad or m: MoveIt's default ``start_state_max_bounds_error``."""
BOUNDS_TOLERANCE = 1e-5
"""rad or m: an excess this small is rounding in the file (values written to 4 or 5
decimals), accepted without a word."""


@dataclass(frozen=True)
class BoundsFix:
    """One joint of a start state moved onto its bound.

    Attributes:
        joint: the joint's name (model name).
        value: its value as given (rad or m).
        bound: the bound it was moved to.
        excess: ``|value - bound|``.
    """

    joint: str
    value: float
    bound: float
    excess: float

    unit: str = "rad"

    def __str__(self) -> str:
        return f"{describe_excess(self.joint, self.value, self.bound, self.unit)}: moved to the bound"


def check_allowance(value: float, where: str = "start_state_max_bounds_error") -> float:
    """``value`` if it is an allowance (a finite number >= 0), else an InputError."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or value < 0:
        raise InputError(f"{where!r} must be a finite number >= 0 (rad or m) (got {value!r})")
    return float(value)


def fix_start_bounds(model: RobotModel, q: np.ndarray,
                     max_bounds_error: float = START_STATE_MAX_BOUNDS_ERROR,
                     ) -> tuple[np.ndarray, list[BoundsFix]]:
    """``q`` with every joint outside its bounds by at most ``max_bounds_error`` moved onto
    the bound (mimic joints then follow their source).

    Args:
        model: the model ``q`` is a state of.
        q: the start state (rad or m, :attr:`RobotModel.joint_names` order).
        max_bounds_error: the allowance (rad or m), as MoveIt's parameter.

    Returns:
        the state, and the joints moved by more than :data:`BOUNDS_TOLERANCE` (to warn of).

    Raises:
        InvalidStateError: a joint outside its bounds by more than the allowance (every such
            joint named, with value, bound and excess).
    """
    out = np.array(q, dtype=float, copy=True)
    fixes: list[BoundsFix] = []
    refused: list[str] = []
    for joint in model.joints:
        if joint.mimic is not None:
            continue
        value = float(out[joint.index])
        if value < joint.lower:
            bound = joint.lower
        elif value > joint.upper:
            bound = joint.upper
        else:
            continue
        excess = abs(value - bound)
        unit = "m" if joint.type == "prismatic" else "rad"
        if excess > max(max_bounds_error, BOUNDS_TOLERANCE):
            refused.append(describe_excess(joint.name, value, bound, unit))
            continue
        out[joint.index] = bound
        if excess > BOUNDS_TOLERANCE:
            fixes.append(BoundsFix(joint.name, value, bound, excess, unit))
    if refused:
        raise InvalidStateError(
            f"start state outside the joint bounds by more than start_state_max_bounds_error "
            f"({max_bounds_error:g} rad or m): {'; '.join(refused)}")
    return model.apply_mimic(out), fixes
