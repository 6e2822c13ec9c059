"""Straight joint-space motions of servo_arm_pair's two arms, for tests of the motion
schedule's rule on its own (``MotionSchedule.admit``) without planning."""

from __future__ import annotations

import numpy as np

from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene, scene_from_cell
from taskrunner.types import JointTrajectory

P = [1.5708, -0.7, -0.9, -0.6, -1.5708]  # reaching to the middle: the two arms overlap there
CANDLE = [1.5708, -1.5708, -1.5708, -1.5708, -1.5708]
LEFT, RIGHT = ((1, 0),), ((1, 1),)  # the two branches of one parallel's first instance


def pair_scene() -> Scene:
    """servo_arm_pair's scene (its table), both arms at their start."""
    return scene_from_cell(load_cell(DATA_ROOT / "robots/cells/servo_arm_pair.yaml"))


def line(side: str, a: list[float], b: list[float], duration: float = 2.0) -> JointTrajectory:
    """The ``side`` arm's five joints from ``a`` to ``b`` in a straight line, 21 samples."""
    times = np.linspace(0.0, duration, 21)
    rows = np.array([np.add(a, s * np.subtract(b, a)) for s in np.linspace(0.0, 1.0, 21)])
    return JointTrajectory(tuple(f"{side}_Revolute {i}" for i in range(1, 6)), times, rows,
                           np.zeros_like(rows), np.zeros_like(rows))
