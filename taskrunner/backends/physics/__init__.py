"""The physics backend (MuJoCo): objects are really grasped, carried and released.

Importing this package needs ``mujoco`` (``pip install -e '.[mujoco]'`` from a checkout); the rest
of taskrunner does not. :func:`make_mujoco_backend` builds the backend for a cell.
"""

from __future__ import annotations

from taskrunner.backends.physics.backend import MujocoBackend
from taskrunner.backends.physics.mjcf import (
    ObjectPhysics,
    PhysicsCell,
    PhysicsObject,
    cell_mjcf,
    physics_cell,
)
from taskrunner.backends.physics.options import MujocoOptions, PhysicsSample

__all__ = ["MujocoBackend", "MujocoOptions", "ObjectPhysics", "PhysicsCell", "PhysicsObject",
           "PhysicsSample", "cell_mjcf", "physics_cell"]
