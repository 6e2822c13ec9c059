"""The compiled collision core: one kinematic description of a robot and one forward
kinematics, shared by the path verifier (:mod:`taskrunner.scene.path_verifier`) and the search's
state screen (:mod:`taskrunner.scene.screen`).

* :mod:`taskrunner.collision.tree`: the kinematic tree as records with named fields
  (:data:`JOINT`) and the one joint-kind table (:class:`JointKind`); no numba.
* :mod:`taskrunner.collision.geometry`: a collision geometry as a record (:data:`GEOMETRY`)
  and the table of exact core shapes (:class:`ShapeKind`); no numba.
* :mod:`taskrunner.collision.frames`: the compiled transform composition and forward
  kinematics (imports numba).
"""

from __future__ import annotations

from taskrunner.collision.geometry import GEOMETRY, ShapeKind
from taskrunner.collision.tree import JOINT, JointKind, KinematicTree

__all__ = ["GEOMETRY", "JOINT", "JointKind", "KinematicTree", "ShapeKind"]
