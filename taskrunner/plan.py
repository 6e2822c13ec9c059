"""A planned, timed motion of one group, as :meth:`taskrunner.Workcell.plan` returns it."""

from __future__ import annotations

from dataclasses import dataclass

from taskrunner.types import JointPath, JointState, JointTrajectory

__all__ = ["Plan"]


@dataclass(frozen=True)
class Plan:
    """A planned, timed motion of one group.

    Attributes:
        group: the planning group that moves.
        path: the geometric path over the group's joints (rad or m), start first.
        trajectory: the path timed by toppra (s, rad, rad/s, rad/s²), rest to rest.
        start: every joint of the cell where the motion starts.
        end: every joint of the cell where the motion ends (the last point reached).
        fraction: share of a Cartesian path achieved, in [0, 1] (MoveIt's
            ``computeCartesianPath`` fraction, weighted by length); 1.0 for a motion
            planned to a goal.
        message: why a Cartesian path stopped short (empty when complete).
        planning_time: seconds spent computing the path (timing not included).
    """

    group: str
    path: JointPath
    trajectory: JointTrajectory
    start: JointState
    end: JointState
    fraction: float = 1.0
    message: str = ""
    planning_time: float = 0.0

    @property
    def duration(self) -> float:
        """Duration of the timed motion (s)."""
        return self.trajectory.duration

    @property
    def complete(self) -> bool:
        """True unless a Cartesian path stopped short of its last waypoint."""
        return self.fraction >= 1.0
