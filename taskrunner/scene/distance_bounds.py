"""Compiled lower bounds on the distance between two collision geometries, for the path
verifier (:mod:`taskrunner.scene.path_verifier`): bounding spheres and boxes
(:func:`_lower_bound`), and the separation of exact core shapes (boxes, cylinders,
spheres, convex hulls) along their boxes' face normals and a few directions of Gilbert's
iteration (:func:`_support_bound`), the least of those over a mesh's convex pieces
(:func:`_pieces_bound`); with the forward kinematics that places the geometries
(:func:`_forward`).

Each geometry is a record of :data:`taskrunner.collision.geometry.GEOMETRY`; the frames
are the rows of :func:`taskrunner.collision.frames.joint_frames`, then one row per
geometry (columns ``_FR_*`` below).
"""

from __future__ import annotations

import math

import numpy as np

from taskrunner.collision.frames import ORIGIN, compose, inline, jit, joint_frames
from taskrunner.collision.geometry import ShapeKind

# The geometries' records (taskrunner.collision.geometry.GEOMETRY): their core shapes.
_SHAPE_NONE, _SHAPE_BOX, _SHAPE_HULL = int(ShapeKind.NONE), int(ShapeKind.BOX), int(ShapeKind.HULL)
_SHAPE_CYLINDER, _SHAPE_SPHERE = int(ShapeKind.CYLINDER), int(ShapeKind.SPHERE)
# frames (n_joints + n_geometries, 19): a joint's frame row (world rotation, origin and
# axis: :mod:`taskrunner.collision.frames`); a geometry's world rotation and origin, then
# its bounding sphere centre and bounding box centre.
_FR_CENTRE, _FR_BOX = 12, 15
# The walk places a geometry only when a pair of it is measured: column _FR_PLACED of its
# row holds the count of compiled states when it was placed (inf: a world object's, fixed).
_FR_PLACED = 18
_FR_COLUMNS = 19
_SUPPORT_STEPS = 4  # at most this many directions refined by Gilbert's iteration
_SUPPORT_TOLERANCE = 0.05  # ... until the bound is within this fraction of the distance


# ---------------------------------------------------------------------- kernels
# The entry points (called from Python) are compiled functions of their own, and so are
# the helpers (``inline``, ``jit``): each compiled once and called, not inlined into every
# caller (inlined, the first compilation took 38 % longer for no measurable speed).
@jit
def _forward(q: np.ndarray, joints: np.ndarray, geometries: np.ndarray, frames: np.ndarray) -> None:
    """World frames of the joints and the geometries at state ``q`` (into ``frames``,
    columns ``_FR_*``: geometry ``g`` is row ``n_joints + g``)."""
    joint_frames(q, joints, frames)
    nj = joints.shape[0]
    for g in range(geometries.shape[0]):
        _geometry_frame(g, geometries, frames, nj)


@inline
def _geometry_frame(g: int, geometries: np.ndarray, frames: np.ndarray, nj: int) -> None:
    """Geometry ``g``'s world frame, bounding sphere and box centres (row ``nj + g`` of
    ``frames``) from its joint's frame."""
    jid = geometries[g].joint
    row = nj + g
    compose(frames, row, jid, geometries[g].placement)
    for a in range(3):
        centre = frames[row, ORIGIN + a]
        box = frames[row, ORIGIN + a]
        for b in range(3):
            centre += frames[row, 3 * a + b] * geometries[g].centre[b]
            box += frames[row, 3 * a + b] * geometries[g].box[b]
        frames[row, _FR_CENTRE + a] = centre
        frames[row, _FR_BOX + a] = box


@jit
def _farthest_point_centre(points: np.ndarray, centre: np.ndarray, iterations: int) -> float:
    """Badoiu-Clarkson: move ``centre`` (in place) towards the farthest point, with
    shrinking steps; returns the distance from the final centre to the farthest point."""
    for i in range(iterations + 1):
        best, farthest = -1.0, 0
        for p in range(points.shape[0]):
            d = 0.0
            for a in range(3):
                offset = points[p, a] - centre[a]
                d += offset * offset
            if d > best:
                best, farthest = d, p
        if i == iterations:
            return math.sqrt(best)
        for a in range(3):
            centre[a] += (points[farthest, a] - centre[a]) / (i + 2)
    return 0.0


@inline
def _sphere_to_box(frames: np.ndarray, row: int, radius: float, box: int, geometries: np.ndarray,
                   nj: int) -> float:
    """Distance from the bounding sphere of frames row ``row`` (radius ``radius``) to
    geometry ``box``'s bounding box (negative: may overlap)."""
    other = nj + box
    outside = 0.0
    for b in range(3):
        local = -geometries[box].box[b]
        for a in range(3):
            local += frames[other, 3 * a + b] * (frames[row, _FR_CENTRE + a]
                                                 - frames[other, ORIGIN + a])
        excess = abs(local) - geometries[box].half[b]
        if excess > 0.0:
            outside += excess * excess
    return math.sqrt(outside) - radius


@inline
def _box_gap(a: int, b: int, geometries: np.ndarray, frames: np.ndarray, nj: int) -> float:
    """The largest gap between the projections of geometries ``a``'s and ``b``'s bounding
    boxes on their six face normals: a lower bound on their distance where positive.

    Along a unit normal ``n``, the gap is ``|(c_a - c_b) . n|`` less each box's half
    extent projected on ``n``; with ``C = R_a^T R_b`` the projections of one box's axes on
    the other's normals are the entries of ``C`` (its own: 0 or 1)."""
    ra, rb = nj + a, nj + b
    best = -np.inf
    for axis in range(3):
        along_a = 0.0               # the centres' offset along a's and b's normals
        along_b = 0.0
        for m in range(3):
            t = frames[ra, _FR_BOX + m] - frames[rb, _FR_BOX + m]
            along_a += t * frames[ra, 3 * m + axis]
            along_b += t * frames[rb, 3 * m + axis]
        gap_a = abs(along_a) - geometries[a].half[axis]
        gap_b = abs(along_b) - geometries[b].half[axis]
        for j in range(3):
            c_aj = 0.0              # C[axis, j] and C[j, axis]
            c_ja = 0.0
            for m in range(3):
                c_aj += frames[ra, 3 * m + axis] * frames[rb, 3 * m + j]
                c_ja += frames[ra, 3 * m + j] * frames[rb, 3 * m + axis]
            gap_a -= geometries[b].half[j] * abs(c_aj)
            gap_b -= geometries[a].half[j] * abs(c_ja)
        if gap_a > best:
            best = gap_a
        if gap_b > best:
            best = gap_b
    return best


@inline
def _lower_bound(a: int, b: int, geometries: np.ndarray, frames: np.ndarray, nj: int) -> float:
    """A lower bound on the distance of geometries ``a`` and ``b`` where positive: the
    best of their bounding spheres' distance, each sphere's distance to the other's
    bounding box and the boxes' separation along their face normals (the walk measures
    the spheres' distance alone first, written out there)."""
    ra, rb = nj + a, nj + b
    gap = 0.0
    for i in range(3):
        offset = frames[ra, _FR_CENTRE + i] - frames[rb, _FR_CENTRE + i]
        gap += offset * offset
    best = math.sqrt(gap) - geometries[a].radius - geometries[b].radius
    if geometries[b].has_box != 0:
        value = _sphere_to_box(frames, ra, geometries[a].radius, b, geometries, nj)
        if value > best:
            best = value
    if geometries[a].has_box != 0:
        value = _sphere_to_box(frames, rb, geometries[b].radius, a, geometries, nj)
        if value > best:
            best = value
    if geometries[a].has_box != 0 and geometries[b].has_box != 0:
        value = _box_gap(a, b, geometries, frames, nj)
        if value > best:
            best = value
    return best


@inline
def _support(g: int, dx: float, dy: float, dz: float, geometries: np.ndarray, frames: np.ndarray,
             points: np.ndarray, nj: int) -> tuple[float, float, float]:
    """The point of geometry ``g``'s core (see ``_SHAPE_*``; without the radius it is
    grown by) furthest along the world direction ``(dx, dy, dz)``."""
    row = nj + g
    # Its rotation read once (each array read is code numba compiles: the first
    # compilation pays per read written, not per read run).
    r0, r1, r2 = frames[row, 0], frames[row, 1], frames[row, 2]
    r3, r4, r5 = frames[row, 3], frames[row, 4], frames[row, 5]
    r6, r7, r8 = frames[row, 6], frames[row, 7], frames[row, 8]
    # The direction in the geometry's frame (its rotation's columns are its axes).
    lx = r0 * dx + r3 * dy + r6 * dz
    ly = r1 * dx + r4 * dy + r7 * dz
    lz = r2 * dx + r5 * dy + r8 * dz
    shape = geometries[g].shape
    px = py = pz = 0.0
    if shape != _SHAPE_HULL:
        half = geometries[g].half
        if shape == _SHAPE_BOX:
            px, py, pz = half[0], half[1], half[2]
            if not lx >= 0.0:
                px = -px
            if not ly >= 0.0:
                py = -py
            if not lz >= 0.0:
                pz = -pz
        elif shape == _SHAPE_CYLINDER:
            radial = math.sqrt(lx * lx + ly * ly)
            if radial > 0.0:
                px = half[0] * lx / radial
                py = half[0] * ly / radial
            pz = half[2]
            if not lz >= 0.0:
                pz = -pz
        ox, oy, oz = frames[row, _FR_BOX], frames[row, _FR_BOX + 1], frames[row, _FR_BOX + 2]
    else:
        first = geometries[g].first_point
        best = -np.inf
        for v in range(first, first + geometries[g].point_count):
            value = points[v, 0] * lx + points[v, 1] * ly + points[v, 2] * lz
            if value > best:
                best = value
                px, py, pz = points[v, 0], points[v, 1], points[v, 2]
        ox, oy, oz = frames[row, ORIGIN], frames[row, ORIGIN + 1], frames[row, ORIGIN + 2]
    return (ox + r0 * px + r1 * py + r2 * pz,
            oy + r3 * px + r4 * py + r5 * pz,
            oz + r6 * px + r7 * py + r8 * pz)


@inline
def _support_bound(a: int, b: int, geometries: np.ndarray, frames: np.ndarray, points: np.ndarray,
                   nj: int, enough: float) -> float:
    """A lower bound on the distance of geometries ``a`` and ``b`` where positive, from
    their support functions (boxes and convex hulls; -inf for other shapes).

    For any unit direction ``n``, ``min over a of n.a - max over b of n.b`` is at most
    their distance (they are separated by at least that along ``n``); the points are the
    shapes' own (a box's corners, a hull's vertices), so the bound is exact for the
    direction. The directions tried: the face normals of the boxes among them, a cylinder's
    axis and the direction from its axis towards the other's centre, the centres' offset,
    then the best of those refined by Gilbert's iteration on the difference ``A - B`` (its point
    closest to the origin, approached over segments), until the bound is within
    ``_SUPPORT_TOLERANCE`` of the distance estimate or after ``_SUPPORT_STEPS``, or once the
    bound is at least ``enough`` (inf: never). Each swept sphere radius is subtracted."""
    if geometries[a].shape == _SHAPE_NONE or geometries[b].shape == _SHAPE_NONE:
        return -np.inf
    ra, rb = nj + a, nj + b
    swept = geometries[a].swept + geometries[b].swept
    best = -np.inf
    vx = vy = vz = 0.0
    # The offset of the bounding spheres' centres, from A to B.
    nx = frames[rb, _FR_CENTRE] - frames[ra, _FR_CENTRE]
    ny = frames[rb, _FR_CENTRE + 1] - frames[ra, _FR_CENTRE + 1]
    nz = frames[rb, _FR_CENTRE + 2] - frames[ra, _FR_CENTRE + 2]
    # Face normals of the boxes, a cylinder's axis and the direction away from it towards
    # the other's centre (all pointing from A to B), and the offset itself.
    for side in range(3):
        for axis in range(4):
            if side < 2:
                if axis == 3:
                    continue
                owner = ra if side == 0 else rb
                shape = geometries[owner - nj].shape
                if shape == _SHAPE_CYLINDER and axis < 2:
                    ux, uy, uz = frames[owner, 2], frames[owner, 5], frames[owner, 8]
                    if axis == 1:     # the offset less its part along the axis
                        along = ux * nx + uy * ny + uz * nz
                        ux, uy, uz = nx - along * ux, ny - along * uy, nz - along * uz
                        length = math.sqrt(ux * ux + uy * uy + uz * uz)
                        if not length > 0.0:
                            continue
                        ux, uy, uz = ux / length, uy / length, uz / length
                elif shape == _SHAPE_BOX:
                    ux, uy, uz = frames[owner, axis], frames[owner, 3 + axis], frames[owner, 6 + axis]
                else:
                    continue
                if ux * nx + uy * ny + uz * nz < 0.0:
                    ux, uy, uz = -ux, -uy, -uz
            else:
                if axis > 0:
                    break
                length = math.sqrt(nx * nx + ny * ny + nz * nz)
                if not length > 0.0:
                    continue
                ux, uy, uz = nx / length, ny / length, nz / length
            # Separation along u: min over B of u.b - max over A of u.a.
            ax, ay, az = _support(a, ux, uy, uz, geometries, frames, points, nj)
            bx, by, bz = _support(b, -ux, -uy, -uz, geometries, frames, points, nj)
            gap = (bx - ax) * ux + (by - ay) * uy + (bz - az) * uz
            if gap > best:
                best = gap
                vx, vy, vz = bx - ax, by - ay, bz - az      # a point of B - A
    # Gilbert: v, a point of B - A (its norm: at least the distance), moves towards the
    # origin's nearest; the directions v/|v|.
    for _ in range(_SUPPORT_STEPS):
        length = math.sqrt(vx * vx + vy * vy + vz * vz)
        if (not length > 0.0 or length - best <= _SUPPORT_TOLERANCE * length
                or best - swept >= enough):
            break
        ux, uy, uz = vx / length, vy / length, vz / length
        ax, ay, az = _support(a, ux, uy, uz, geometries, frames, points, nj)
        bx, by, bz = _support(b, -ux, -uy, -uz, geometries, frames, points, nj)
        wx, wy, wz = bx - ax, by - ay, bz - az
        gap = wx * ux + wy * uy + wz * uz
        if gap > best:
            best = gap
        if length - gap <= _SUPPORT_TOLERANCE * length:
            break
        # The point of the segment [v, w] nearest the origin.
        dx, dy, dz = wx - vx, wy - vy, wz - vz
        dd = dx * dx + dy * dy + dz * dz
        if not dd > 0.0:
            break
        t = -(vx * dx + vy * dy + vz * dz) / dd
        if t <= 0.0:
            break
        if t > 1.0:
            t = 1.0
        vx, vy, vz = vx + t * dx, vy + t * dy, vz + t * dz
    return best - swept


@inline
def _pieces_bound(a: int, b: int, geometries: np.ndarray, frames: np.ndarray, points: np.ndarray,
                  nj: int, pieces: np.ndarray, stamp: float, floor: float, enough: float,
                  whole: float) -> float:
    """:func:`_support_bound` of geometries ``a`` and ``b``, or where either is a mesh cut
    into convex pieces (:mod:`taskrunner.scene.mesh_pieces`; ``pieces[g]``: the first of
    geometry ``g``'s pieces' records and their count, 0 for none), unless that bound is at
    least ``whole`` (inf: not tried), the least over pairs of its pieces (or the other
    geometry itself) of the better of that bound and their bounding spheres' distance: each
    piece holds its part of the mesh, so this too is a lower bound on the distance where
    positive. A pair of pieces whose spheres are no nearer than the least so far is
    skipped; once the least is below ``floor`` the search stops and returns -inf (no bound:
    the caller asks coal); a pair's bound is refined only while it is below the least so
    far and ``enough`` (the least found is then at least ``enough`` where it is not the
    bound itself: the screen only asks whether the pieces are apart). The pieces' frames
    rows not placed at ``stamp`` (their ``_FR_PLACED`` column below it) are placed here
    first (a fixed one's: for good)."""
    count_a, count_b = pieces[a, 1], pieces[b, 1]
    if count_a == 0 and count_b == 0:
        return _support_bound(a, b, geometries, frames, points, nj, np.inf)
    if whole < np.inf:  # the meshes' own hulls first: where they are that far apart, it serves
        hulls = _support_bound(a, b, geometries, frames, points, nj, whole)
        if hulls >= whole:
            return hulls
    first_a, first_b = a, b
    if count_a == 0:
        count_a = 1
    else:
        first_a = pieces[a, 0]
    if count_b == 0:
        count_b = 1
    else:
        first_b = pieces[b, 0]
    for side in range(2):
        first, count = (first_a, count_a) if side == 0 else (first_b, count_b)
        for g in range(first, first + count):
            if frames[nj + g, _FR_PLACED] < stamp:
                _geometry_frame(g, geometries, frames, nj)
                frames[nj + g, _FR_PLACED] = np.inf if geometries[g].joint == 0 else stamp
    # The pair of pieces whose spheres are nearest first (its bound prunes the others),
    # then the rest; each pair's bound: the better of its spheres' and boxes' separation,
    # and where that is below the least so far, its support bound.
    near_i, near_j, nearest = first_a, first_b, np.inf
    for i in range(first_a, first_a + count_a):
        for j in range(first_b, first_b + count_b):
            gap = 0.0
            for c in range(3):
                offset = frames[nj + i, _FR_CENTRE + c] - frames[nj + j, _FR_CENTRE + c]
                gap += offset * offset
            if gap < nearest:
                near_i, near_j, nearest = i, j, gap
    least = np.inf
    for t in range(-1, count_a * count_b):
        if t < 0:
            i, j = near_i, near_j
        else:
            i, j = first_a + t // count_b, first_b + t % count_b
            if i == near_i and j == near_j:
                continue
        spheres = 0.0
        for c in range(3):
            offset = frames[nj + i, _FR_CENTRE + c] - frames[nj + j, _FR_CENTRE + c]
            spheres += offset * offset
        spheres = math.sqrt(spheres) - geometries[i].radius - geometries[j].radius
        if spheres < least and geometries[i].has_box != 0 and geometries[j].has_box != 0:
            boxes = _box_gap(i, j, geometries, frames, nj)
            if boxes > spheres:
                spheres = boxes
        if spheres >= least:
            continue
        # Refined only while it could lower the least (or stay below ``enough``).
        bound = _support_bound(i, j, geometries, frames, points, nj,
                               least if least < enough else enough)
        if bound < spheres:
            bound = spheres
        if bound < least:
            least = bound
            if least < floor:
                return -np.inf
    return least
