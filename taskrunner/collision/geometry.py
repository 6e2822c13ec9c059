"""A collision geometry as the compiled kernels read it: one record with named fields.

:data:`GEOMETRY` describes one geometry object of a scene's collision model (a robot link's
or an object's) in its own frame: the joint that carries it and its placement there (as
:func:`taskrunner.collision.frames.compose` reads a placement), a sphere and a box that
contain it, and the core shape whose support function the kernels evaluate exactly
(:class:`ShapeKind`, grown by ``swept``). The path verifier
(:class:`taskrunner.scene.path_verifier.PathVerifier`) builds these records; the state screen
(:mod:`taskrunner.scene.screen`) places and measures boxes from the same records (with the
verifier's kernels) and keeps its spheres in rows of its own derived from them.
"""

from __future__ import annotations

from enum import IntEnum

import numpy as np

__all__ = ["GEOMETRY", "ShapeKind"]


class ShapeKind(IntEnum):
    """The core of a geometry whose support function the kernels evaluate exactly (the
    ``shape`` field of :data:`GEOMETRY`); the geometry is its core grown by ``swept``."""

    NONE = 0
    """No exact support function (meshes, cones, capsules, shapes off their box centre)."""
    BOX = 1
    """Its bounding box (``half``) is the shape."""
    HULL = 2
    """A convex hull: its vertices are ``point_count`` rows of the verifier's points from
    ``first_point`` on."""
    CYLINDER = 3
    """A cylinder about z: radius ``half[0]``, half length ``half[2]``."""
    SPHERE = 4
    """A point (the sphere's radius is in ``swept``)."""


GEOMETRY = np.dtype([
    ("joint", np.int64),           # the joint carrying it (0: fixed in the world)
    ("has_box", np.int64),         # 1 where ``half`` and ``box`` hold a bounding box
    ("shape", np.int64),           # a ShapeKind
    ("first_point", np.int64),     # a hull's first vertex in the verifier's points
    ("point_count", np.int64),     # ... and their count
    ("placement", np.float64, (12,)),  # on its joint: rotation (row-major), translation (m)
    ("centre", np.float64, (3,)),  # bounding sphere: centre (own frame, m)
    ("radius", np.float64),        # ... and radius (m)
    ("half", np.float64, (3,)),    # bounding box: half extents (m)
    ("box", np.float64, (3,)),     # ... and centre (own frame, m)
    ("swept", np.float64),         # the core's growth (m)
])
"""One collision geometry (see the module's text)."""
