"""Constants and helpers shared by the planning tests."""

from __future__ import annotations

import numpy as np

from taskrunner.scene import Scene

READY = {
    "panda_joint1": 0.0, "panda_joint2": -0.785, "panda_joint3": 0.0, "panda_joint4": -2.356,
    "panda_joint5": 0.0, "panda_joint6": 1.571, "panda_joint7": 0.785,
}

# A table under the Panda and a shelf with a middle board in front of it (full sizes, m).
SHELF = (
    ("table", (1.2, 1.2, 0.04), (0.3, 0.0, -0.02)),
    ("shelf_left", (0.3, 0.02, 0.6), (0.75, -0.3, 0.3)),
    ("shelf_right", (0.3, 0.02, 0.6), (0.75, 0.3, 0.3)),
    ("shelf_board", (0.3, 0.6, 0.02), (0.75, 0.0, 0.3)),
    ("shelf_top", (0.3, 0.62, 0.02), (0.75, 0.0, 0.61)),
)


def dense_states(scene: Scene, result, resolution: float = 0.005) -> np.ndarray:
    """Full state vectors along a plan result's path, every ``resolution`` rad."""
    from taskrunner.planning.planner import interpolate_path

    idx = scene.robot.indices(result.path.names)
    states = []
    for values in interpolate_path(result.path.waypoints, resolution):
        q = result.start.copy()
        q[idx] = values
        states.append(scene.robot.apply_mimic(q))
    return np.array(states)
