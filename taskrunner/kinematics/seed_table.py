"""Restart seeds for IK: stored configurations whose frame pose is nearest a target.

A damped least-squares attempt from a random configuration converges about half the
time on a 6-7 joint arm; from the stored configuration whose frame is nearest the
target it converges more often, notably for targets that need joints near their limits.
:class:`SeedTable` samples configurations once (seeded, deterministic), keeps the
frame's world pose at each, and answers nearest-pose queries with a k-d tree.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin

if TYPE_CHECKING:
    from scipy.spatial import cKDTree

__all__ = ["SeedTable"]

# Weight of the orientation in the pose distance: d² = ‖Δp‖² + 2·w²·(1 - |⟨u, u_t⟩|)
# (u unit quaternions), i.e. 1 rad of rotation counts about as much as 0.5 m here.
_ORIENTATION_WEIGHT = 0.7


class SeedTable:
    """Configurations of the solved joints and the pose of one frame at each.

    Args:
        samples: ``(n, k)`` array of joint values (rad or m), one configuration a row.
        frame_pose_of: maps one row to the frame's world pose.
    """

    def __init__(self, samples: np.ndarray, frame_pose_of: Callable[[np.ndarray], pin.SE3]):
        from scipy.spatial import cKDTree  # here: scipy.spatial takes 50-70 ms to import

        self.samples = np.asarray(samples, dtype=float)
        n = len(self.samples)
        positions = np.empty((n, 3))
        quaternions = np.empty((n, 4))
        for row, values in enumerate(self.samples):
            pose = frame_pose_of(values)
            positions[row] = pose.translation
            quaternions[row] = pin.Quaternion(pose.rotation).coeffs()
        self._positions = positions
        # q and -q are the same rotation: store both so the tree's Euclidean distance is
        # the distance to the nearer of the two.
        weighted = _ORIENTATION_WEIGHT * quaternions
        self._pose_tree = cKDTree(
            np.vstack([np.hstack([positions, weighted]), np.hstack([positions, -weighted])])
        )
        self._position_tree: cKDTree | None = None

    def __len__(self) -> int:
        return len(self.samples)

    def nearest_to_pose(self, target: pin.SE3, count: int) -> np.ndarray:
        """Rows of the ``count`` stored configurations nearest ``target``, nearest first."""
        quaternion = pin.Quaternion(target.rotation).coeffs()
        point = np.concatenate([target.translation, _ORIENTATION_WEIGHT * quaternion])
        _, rows = self._pose_tree.query(point, k=2 * count)
        n = len(self.samples)
        # A row can come twice (once per quaternion sign): keep the first of each (a
        # loop over 2·count ints is several times faster than np.unique here).
        kept: list[int] = []
        for row in np.atleast_1d(rows).tolist():
            row %= n
            if row not in kept:
                kept.append(row)
                if len(kept) == count:
                    break
        return np.asarray(kept, dtype=np.intp)

    def nearest_to_position(self, target: np.ndarray, count: int) -> np.ndarray:
        """Rows of the ``count`` stored configurations whose frame origin is nearest."""
        if self._position_tree is None:
            from scipy.spatial import cKDTree

            self._position_tree = cKDTree(self._positions)
        _, rows = self._position_tree.query(target, k=count)
        return np.atleast_1d(rows)
