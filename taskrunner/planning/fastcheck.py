"""A compiled, conservative collision checker for the planner's search.

Every moving collision geometry of a scene's checker (robot links, attached objects) is
covered by spheres (:mod:`taskrunner.planning.spheres`); world boxes and cylinders stay
exact primitives, other fixed geometry (meshes, a robot base) is covered by spheres too.
Forward kinematics over the pinocchio joint tree, the sphere placement and the sphere
tests are compiled with numba (``cache=True``: compiled once per machine, kept in
``user_cache_dir()/numba`` unless ``NUMBA_CACHE_DIR`` says otherwise).

Guarantees, for the pairs the scene's checker checks (allowances applied):

* :meth:`GroupChecker.state_free` True ⇒ no checked pair of the exact geometry overlaps
  at that state (the spheres contain the geometry). False says nothing: the caller asks
  coal then.
* :meth:`GroupChecker.edge` returning ≥ 1 ⇒ no checked pair overlaps anywhere on the
  straight joint-space segment, not only at samples. Over a stretch of the segment of
  length ``h`` (as a fraction), a pair's bodies move relative to each other by at most
  ``rate · h / 2`` from where they are at the stretch's middle, ``rate`` being the pair's
  displacement bound for the whole segment (per-joint lever arms,
  :func:`taskrunner.scene.sweep.lever_arms`, times each joint's motion). So if the
  pair's spheres at the middle, grown by that much, do not touch, the exact geometry
  cannot touch anywhere on the stretch. The walk bisects in time: the whole segment
  first, then both halves of every stretch where some pair's grown spheres touch, for
  those pairs only, depth first from the start. A stretch where they touch with less
  than ``eps`` of growth stops the walk; the segment is clear up to that stretch's
  start, and the caller checks the rest exactly.

Pairs whose relative pose the group cannot change (both fixed, or moved by the same
group joints) are left out: they are as they are at the start state, which the planner
checked exactly.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass

import coal
import numpy as np
import pinocchio as pin

from taskrunner.resources import user_cache_dir

if not os.environ.get("NUMBA_CACHE_DIR"):
    # Before numba's import: an installed package's own folder may be read-only.
    os.environ["NUMBA_CACHE_DIR"] = str(user_cache_dir() / "numba")

import numba

from taskrunner.planning.spheres import SphereSet, cover
from taskrunner.robot import RobotModel
from taskrunner.scene.collision import CollisionChecker
from taskrunner.scene.sweep import lever_arms

__all__ = ["GroupChecker", "SphereModel", "UnsupportedModelError"]

if not numba.config.CACHE_DIR:  # type: ignore[attr-defined]  # numba was imported first
    numba.config.CACHE_DIR = os.environ["NUMBA_CACHE_DIR"]  # type: ignore[attr-defined]

_REVOLUTE, _PRISMATIC = 0, 1
_SPHERES, _BOX, _CYLINDER = 0, 1, 2
_EARLY = 0.05  # a pair due within this fraction of the segment is checked with the others

# Integer header (layout of the packed arrays, see _Packer).
_H_NJ, _H_NG, _H_NS, _H_NP, _H_NM, _H_NQ, _H_NIDX = range(7)
(_I_PARENT, _I_JTYPE, _I_JSTATE, _I_GJOINT, _I_GKIND, _I_GSTART, _I_GEND, _I_PA, _I_PB,
 _I_MT, _I_MS, _I_IDX, _I_GCSTART, _I_GCEND, _I_CFIRST, _I_CLAST) = range(7, 23)
(_F_AXIS, _F_PR, _F_PP, _F_SC, _F_SR, _F_BC, _F_BR, _F_GR, _F_GP, _F_GD, _F_LEV, _F_MM,
 _F_MO, _F_GLO, _F_GHI, _F_GLEV) = range(23, 39)
_HEADER = 39
_CLUSTER = 4  # spheres per cluster: a geometry's spheres are tested cluster by cluster


class UnsupportedModelError(Exception):
    """The robot model has a joint type the compiled kinematics does not handle."""


@dataclass(frozen=True)
class _Geometry:
    joint: int              # pinocchio joint (0: fixed in the world)
    kind: int               # _SPHERES, _BOX or _CYLINDER
    rotation: np.ndarray    # (3, 3) placement in the joint's frame
    translation: np.ndarray
    dims: np.ndarray        # box half sides, or (radius, half length, 0)
    spheres: SphereSet | None


class SphereModel:
    """Sphere model of one collision checker (one scene revision): every geometry and
    pair of ``checker``, with the compiled kinematics of ``robot``.

    Raises:
        UnsupportedModelError: a joint that is not revolute, continuous or prismatic.
    """

    def __init__(self, robot: RobotModel, checker: CollisionChecker,
                 max_spheres: int = 16, max_radius: float = 0.03) -> None:
        t0 = time.perf_counter()
        self.robot = robot
        self.checker = checker
        model = robot.model
        geometry_model = checker.geometry_model
        self._joints = _joint_table(robot)
        self.geometries: list[_Geometry] = []
        for g in geometry_model.geometryObjects:
            shape = g.geometry
            placement = g.placement
            rotation = np.array(placement.rotation, dtype=float)
            translation = np.array(placement.translation, dtype=float)
            swept = float(getattr(shape, "getSweptSphereRadius", lambda: 0.0)())
            joint = int(g.parentJoint)
            if joint == 0 and swept == 0.0 and isinstance(shape, coal.Box):
                dims = np.asarray(shape.halfSide, dtype=float).copy()
                self.geometries.append(_Geometry(0, _BOX, rotation, translation, dims, None))
            elif joint == 0 and swept == 0.0 and isinstance(shape, coal.Cylinder):
                dims = np.array([float(shape.radius), float(shape.halfLength), 0.0])
                self.geometries.append(_Geometry(0, _CYLINDER, rotation, translation, dims, None))
            else:
                spheres = cover(shape, max_spheres, max_radius)
                self.geometries.append(_Geometry(joint, _SPHERES, rotation, translation,
                                                 np.zeros(3), spheres))
        self.pairs = [(int(p.first), int(p.second)) for p in geometry_model.collisionPairs]
        self.levers = lever_arms(robot, geometry_model)       # (n_geometries, nq)
        self.mimic = [(j.index, robot.joint(j.mimic.source).index, j.mimic.multiplier,
                       j.mimic.offset) for j in robot.joints if j.mimic is not None]
        self.build_seconds = time.perf_counter() - t0
        del model

    @property
    def sphere_count(self) -> int:
        return sum(len(g.spheres) for g in self.geometries if g.spheres is not None)

    def group(self, joint_indices: np.ndarray) -> GroupChecker:
        """The checker for planning the state-vector joints ``joint_indices``."""
        return GroupChecker(self, np.asarray(joint_indices, dtype=np.int64))


class GroupChecker:
    """Compiled checks of full state vectors for one group (see the module docstring)."""

    def __init__(self, model: SphereModel, joint_indices: np.ndarray) -> None:
        self.model = model
        robot = model.robot
        nq = robot.nq
        moved = np.zeros(nq, dtype=bool)
        moved[joint_indices] = True
        for target, source, _, _ in model.mimic:  # mimic joints follow their source
            if moved[source]:
                moved[target] = True
        moving = model.levers[:, moved] > 0                   # (n_geometries, group-ish)
        pairs = []
        for a, b in model.pairs:
            if np.array_equal(moving[a], moving[b]):
                continue  # both fixed, or moved rigidly together: as at the start state
            if model.geometries[a].kind != _SPHERES:
                a, b = b, a
            pairs.append((a, b))
        self.pairs = pairs
        levers = model.levers
        moves = levers > 0
        pair_levers = np.array([levers[a] * ~moves[b] + levers[b] * ~moves[a] for a, b in pairs],
                               dtype=float).reshape(len(pairs), nq)
        self._ints, self._floats = _pack(model, pairs, pair_levers, joint_indices)
        nj = robot.model.njoints
        entries = int(self._ints[_H_NS])  # spheres and cluster balls
        self._work = np.zeros(nj * 12 + entries * 3 + len(model.geometries) * 3 + 2 * nq)
        self._pending = np.zeros(len(pairs) * 65 + 1, dtype=np.int64)
        self._rates = np.zeros(len(pairs))
        self.joint_indices = joint_indices

    @property
    def pair_count(self) -> int:
        return len(self.pairs)

    def warm_up(self, base: np.ndarray) -> None:
        """Load (or, the first time on a machine, compile) every kernel, so that no
        search pays for it."""
        base = np.array(base, dtype=float)  # writable, like the planner's (numba types
        values = base[self.joint_indices]   # read-only arrays apart: another compilation)
        self.state_free(base, values)
        self.edge(base, values, values, 1e-3, 1)
        self.touching(base, values, values, 0.0, 1)

    def state_free(self, base: np.ndarray, values: np.ndarray) -> bool:
        """True when the spheres of no checked pair touch at ``base`` with the group's
        joints set to ``values`` (mimic joints follow)."""
        return bool(_state_free(self._ints, self._floats, self._work, base, values))

    def edge(self, base: np.ndarray, a: np.ndarray, b: np.ndarray, eps: float,
             max_checks: int = 200) -> tuple[float, int]:
        """Check the segment from group values ``a`` to ``b`` (other joints at ``base``).

        Returns:
            ``(s, checks)``: ``s`` ≥ 1 when the whole segment is free; otherwise the
            fraction of the segment proven free from its start (the walk stopped there:
            spheres touching with less than ``eps`` m of growth, or ``max_checks``
            states evaluated); ``checks`` states were evaluated.
        """
        s, checks = _edge(self._ints, self._floats, self._work, self._pending, self._rates,
                          base, a, b, eps, max_checks)
        return float(s), int(checks)

    def touching(self, base: np.ndarray, a: np.ndarray, b: np.ndarray, s: float,
                 steps: int) -> np.ndarray:
        """The fractions ``s + (1 - s) i / steps`` (i = 0 … steps) of the segment from
        ``a`` to ``b`` at which spheres touch (the states that need an exact check)."""
        out = np.empty(steps + 1)
        found = _scan(self._ints, self._floats, self._work, base, a, b, float(s), int(steps), out)
        return out[:found]

    def link_frames(self, state: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Compiled forward kinematics of a full state vector: the rotations ``(njoints,
        3, 3)`` and translations ``(njoints, 3)`` of every pinocchio joint frame."""
        nj = self.model.robot.model.njoints
        rotations = np.zeros((nj, 3, 3))
        translations = np.zeros((nj, 3))
        _fk_public(self._ints, self._floats, np.asarray(state, dtype=float), rotations,
                   translations)
        return rotations, translations


# ---------------------------------------------------------------------- building
def _joint_table(robot: RobotModel) -> dict[str, np.ndarray]:
    """Per pinocchio joint: parent, type, state index, axis, placement (joint 0: none)."""
    model = robot.model
    nj = model.njoints
    parent = np.zeros(nj, dtype=np.int64)
    jtype = np.full(nj, -1, dtype=np.int64)
    jstate = np.zeros(nj, dtype=np.int64)
    axis = np.zeros((nj, 3))
    place_r = np.tile(np.eye(3), (nj, 1, 1))
    place_p = np.zeros((nj, 3))
    by_name = {j.name: j for j in robot.joints}
    data = model.createData()
    for jid in range(1, nj):
        name = model.names[jid]
        joint = model.joints[jid]
        info = by_name.get(name)
        if info is None or joint.nv != 1:
            raise UnsupportedModelError(
                f"joint {name!r} ({joint.shortname()}) is not a 1-DOF joint of the state vector")
        parent[jid] = model.parents[jid]
        jstate[jid] = info.index
        placement = model.jointPlacements[jid]
        place_r[jid] = placement.rotation
        place_p[jid] = placement.translation
        # The joint's own motion, read off pinocchio at a test value.
        q = pin.neutral(model)
        angle = 0.7
        if joint.nq == 2:
            q[joint.idx_q:joint.idx_q + 2] = (np.cos(angle), np.sin(angle))
        else:
            q[joint.idx_q] = angle
        pin.forwardKinematics(model, data, q)
        motion = placement.inverse() * data.liMi[jid]
        if np.linalg.norm(motion.translation) < 1e-12:
            rotvec = pin.log3(motion.rotation)
            if abs(np.linalg.norm(rotvec) - angle) > 1e-9:
                raise UnsupportedModelError(f"joint {name!r} ({joint.shortname()}) is not a "
                                            "revolute joint about a fixed axis")
            jtype[jid] = _REVOLUTE
            axis[jid] = rotvec / angle
        else:
            if not np.allclose(motion.rotation, np.eye(3), atol=1e-12) or \
                    abs(np.linalg.norm(motion.translation) - angle) > 1e-9:
                raise UnsupportedModelError(f"joint {name!r} ({joint.shortname()}) is not a "
                                            "prismatic joint along a fixed axis")
            jtype[jid] = _PRISMATIC
            axis[jid] = motion.translation / angle
    return {"parent": parent, "jtype": jtype, "jstate": jstate, "axis": axis,
            "place_r": place_r, "place_p": place_p}


def _pack(model: SphereModel, pairs: list[tuple[int, int]], pair_levers: np.ndarray,
          joint_indices: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    joints = model._joints
    geometries = model.geometries
    n_geometries = len(geometries)
    # Entries: every geometry's spheres (grouped by cluster), then every cluster's ball.
    sphere_start, sphere_end, cluster_start, cluster_end = [], [], [], []
    centres, radii, bound_centres, bound_radii = [], [], [], []
    cluster_balls: list[tuple[np.ndarray, float, int, int]] = []
    count = 0
    for g in geometries:
        sphere_start.append(count)
        first_cluster = len(cluster_balls)
        if g.spheres is not None:
            # Spheres in the joint's frame; the bounding sphere of the spheres too.
            local = g.spheres.centres @ g.rotation.T + g.translation
            for members in _clusters(local):
                ball_centre = 0.5 * (local[members].min(axis=0) + local[members].max(axis=0))
                ball_radius = float(np.max(np.linalg.norm(local[members] - ball_centre, axis=1)
                                           + g.spheres.radii[members]))
                cluster_balls.append((ball_centre, ball_radius, count, count + len(members)))
                centres.append(local[members])
                radii.append(g.spheres.radii[members])
                count += len(members)
            middle = 0.5 * (local.min(axis=0) + local.max(axis=0))
            bound_centres.append(middle)
            bound_radii.append(float(np.max(np.linalg.norm(local - middle, axis=1)
                                            + g.spheres.radii)))
        else:
            bound_centres.append(g.translation)
            bound_radii.append(float(np.linalg.norm(g.dims)))
        sphere_end.append(count)
        cluster_start.append(first_cluster)
        cluster_end.append(len(cluster_balls))
    n_spheres = count
    cluster_first = np.zeros(n_spheres + len(cluster_balls), dtype=np.int64)
    cluster_last = np.zeros(n_spheres + len(cluster_balls), dtype=np.int64)
    for k, (ball_centre, ball_radius, first, last) in enumerate(cluster_balls):
        centres.append(ball_centre[None, :])
        radii.append(np.array([ball_radius]))
        cluster_first[n_spheres + k] = first
        cluster_last[n_spheres + k] = last
        count += 1
    ints_sections = [
        joints["parent"], joints["jtype"], joints["jstate"],
        np.array([g.joint for g in geometries], dtype=np.int64),
        np.array([g.kind for g in geometries], dtype=np.int64),
        np.array(sphere_start, dtype=np.int64), np.array(sphere_end, dtype=np.int64),
        np.array([a for a, _ in pairs], dtype=np.int64),
        np.array([b for _, b in pairs], dtype=np.int64),
        np.array([m[0] for m in model.mimic], dtype=np.int64),
        np.array([m[1] for m in model.mimic], dtype=np.int64),
        np.asarray(joint_indices, dtype=np.int64),
        np.array(cluster_start, dtype=np.int64) + n_spheres,
        np.array(cluster_end, dtype=np.int64) + n_spheres,
        cluster_first, cluster_last,
    ]
    float_sections = [
        joints["axis"].ravel(), joints["place_r"].ravel(), joints["place_p"].ravel(),
        (np.vstack(centres) if centres else np.zeros((0, 3))).ravel(),
        np.concatenate(radii) if radii else np.zeros(0),
        np.array(bound_centres, dtype=float).reshape(-1, 3).ravel(),
        np.array(bound_radii, dtype=float),
        np.array([g.rotation for g in geometries], dtype=float).reshape(-1).copy(),
        np.array([g.translation for g in geometries], dtype=float).reshape(-1).copy(),
        np.array([g.dims for g in geometries], dtype=float).reshape(-1).copy(),
        pair_levers.ravel(),
        np.array([m[2] for m in model.mimic], dtype=float),
        np.array([m[3] for m in model.mimic], dtype=float),
        np.array([_box_of(g)[0] for g in geometries], dtype=float).reshape(-1).copy(),
        np.array([_box_of(g)[1] for g in geometries], dtype=float).reshape(-1).copy(),
        np.asarray(model.levers, dtype=float).reshape(-1).copy(),
    ]
    header = np.zeros(_HEADER, dtype=np.int64)
    header[_H_NJ] = len(joints["parent"])
    header[_H_NG] = n_geometries
    header[_H_NS] = count
    header[_H_NP] = len(pairs)
    header[_H_NM] = len(model.mimic)
    header[_H_NQ] = model.robot.nq
    header[_H_NIDX] = len(joint_indices)
    offset = _HEADER
    for k, section in enumerate(ints_sections):
        header[_I_PARENT + k] = offset
        offset += len(section)
    offset = 0
    for k, section in enumerate(float_sections):
        header[_F_AXIS + k] = offset
        offset += len(section)
    ints = np.concatenate([header] + ints_sections).astype(np.int64)
    floats = np.concatenate(float_sections).astype(np.float64)
    return ints, floats


def _clusters(points: np.ndarray) -> list[np.ndarray]:
    """Indices of ``points`` in groups of at most ``_CLUSTER`` neighbours (split across the
    longest principal axis, recursively)."""
    groups = [np.arange(len(points))]
    out = []
    while groups:
        members = groups.pop()
        if len(members) <= _CLUSTER:
            out.append(members)
            continue
        centred = points[members] - points[members].mean(axis=0)
        axis = np.linalg.svd(centred, full_matrices=False)[2][0]
        order = members[np.argsort(centred @ axis, kind="stable")]
        half = len(order) // 2
        groups += [order[:half], order[half:]]
    return out


def _box_of(g: _Geometry) -> tuple[np.ndarray, np.ndarray]:
    """The world axis-aligned box around a fixed primitive (unused for sphere sets)."""
    if g.kind == _BOX:
        half = np.abs(g.rotation) @ g.dims
    elif g.kind == _CYLINDER:
        axis = g.rotation[:, 2]
        half = np.abs(axis) * g.dims[1] + g.dims[0] * np.sqrt(np.clip(1.0 - axis**2, 0.0, 1.0))
    else:
        return np.zeros(3), np.zeros(3)
    return g.translation - half, g.translation + half


# ---------------------------------------------------------------------- kernels
_jit = numba.njit(cache=True, nogil=True, error_model="numpy")


@_jit
def _fill(ints, floats, state, base, values):  # type: ignore[no-untyped-def]
    """state = base with the group's values set, mimic joints following."""
    nq = ints[_H_NQ]
    for k in range(nq):
        state[k] = base[k]
    idx = ints[ints[_I_IDX]:ints[_I_IDX] + ints[_H_NIDX]]
    for k in range(len(idx)):
        state[idx[k]] = values[k]
    nm = ints[_H_NM]
    targets = ints[ints[_I_MT]:ints[_I_MT] + nm]
    sources = ints[ints[_I_MS]:ints[_I_MS] + nm]
    mult = floats[ints[_F_MM]:ints[_F_MM] + nm]
    off = floats[ints[_F_MO]:ints[_F_MO] + nm]
    for k in range(nm):
        state[targets[k]] = mult[k] * state[sources[k]] + off[k]


@_jit
def _fk(ints, floats, state, rot, pos):  # type: ignore[no-untyped-def]
    """World frames of every pinocchio joint: rot (nj, 3, 3), pos (nj, 3)."""
    nj = ints[_H_NJ]
    parent = ints[ints[_I_PARENT]:ints[_I_PARENT] + nj]
    jtype = ints[ints[_I_JTYPE]:ints[_I_JTYPE] + nj]
    jstate = ints[ints[_I_JSTATE]:ints[_I_JSTATE] + nj]
    axis = floats[ints[_F_AXIS]:ints[_F_AXIS] + 3 * nj].reshape((nj, 3))
    place_r = floats[ints[_F_PR]:ints[_F_PR] + 9 * nj].reshape((nj, 3, 3))
    place_p = floats[ints[_F_PP]:ints[_F_PP] + 3 * nj].reshape((nj, 3))
    for r in range(3):
        for c in range(3):
            rot[0, r, c] = 1.0 if r == c else 0.0
        pos[0, r] = 0.0
    local = np.empty((3, 3))
    joint_r = np.empty((3, 3))
    offset = np.empty(3)
    for j in range(1, nj):
        value = state[jstate[j]]
        if jtype[j] == _REVOLUTE:
            x, y, z = axis[j, 0], axis[j, 1], axis[j, 2]
            c, s = np.cos(value), np.sin(value)
            t = 1.0 - c
            joint_r[0, 0] = t * x * x + c
            joint_r[0, 1] = t * x * y - s * z
            joint_r[0, 2] = t * x * z + s * y
            joint_r[1, 0] = t * x * y + s * z
            joint_r[1, 1] = t * y * y + c
            joint_r[1, 2] = t * y * z - s * x
            joint_r[2, 0] = t * x * z - s * y
            joint_r[2, 1] = t * y * z + s * x
            joint_r[2, 2] = t * z * z + c
            for r in range(3):
                for cc in range(3):
                    local[r, cc] = (place_r[j, r, 0] * joint_r[0, cc] + place_r[j, r, 1]
                                    * joint_r[1, cc] + place_r[j, r, 2] * joint_r[2, cc])
                offset[r] = place_p[j, r]
        else:
            for r in range(3):
                for cc in range(3):
                    local[r, cc] = place_r[j, r, cc]
                offset[r] = place_p[j, r] + value * (place_r[j, r, 0] * axis[j, 0]
                                                     + place_r[j, r, 1] * axis[j, 1]
                                                     + place_r[j, r, 2] * axis[j, 2])
        p = parent[j]
        for r in range(3):
            for cc in range(3):
                rot[j, r, cc] = (rot[p, r, 0] * local[0, cc] + rot[p, r, 1] * local[1, cc]
                                 + rot[p, r, 2] * local[2, cc])
            pos[j, r] = (pos[p, r] + rot[p, r, 0] * offset[0] + rot[p, r, 1] * offset[1]
                         + rot[p, r, 2] * offset[2])


@_jit
def _place(ints, floats, rot, pos, centres, bounds):  # type: ignore[no-untyped-def]
    """World centres of every sphere and of every geometry's bounding sphere."""
    ng = ints[_H_NG]
    ns = ints[_H_NS]
    gjoint = ints[ints[_I_GJOINT]:ints[_I_GJOINT] + ng]
    gstart = ints[ints[_I_GSTART]:ints[_I_GSTART] + ng]
    gend = ints[ints[_I_GEND]:ints[_I_GEND] + ng]
    local = floats[ints[_F_SC]:ints[_F_SC] + 3 * ns].reshape((ns, 3))
    blocal = floats[ints[_F_BC]:ints[_F_BC] + 3 * ng].reshape((ng, 3))
    gcstart = ints[ints[_I_GCSTART]:ints[_I_GCSTART] + ng]
    gcend = ints[ints[_I_GCEND]:ints[_I_GCEND] + ng]
    for g in range(ng):
        j = gjoint[g]
        for i in range(gcstart[g], gcend[g]):
            for r in range(3):
                centres[i, r] = (pos[j, r] + rot[j, r, 0] * local[i, 0] + rot[j, r, 1]
                                 * local[i, 1] + rot[j, r, 2] * local[i, 2])
        for i in range(gstart[g], gend[g]):
            for r in range(3):
                centres[i, r] = (pos[j, r] + rot[j, r, 0] * local[i, 0] + rot[j, r, 1]
                                 * local[i, 1] + rot[j, r, 2] * local[i, 2])
        for r in range(3):
            bounds[g, r] = (pos[j, r] + rot[j, r, 0] * blocal[g, 0] + rot[j, r, 1]
                            * blocal[g, 1] + rot[j, r, 2] * blocal[g, 2])


@_jit
def _point_primitive(grot, gpos, dims, g, kind, x, y, z):  # type: ignore[no-untyped-def]
    """Signed distance from a world point to fixed primitive ``g`` (negative inside)."""
    dx, dy, dz = x - gpos[g, 0], y - gpos[g, 1], z - gpos[g, 2]
    # The primitive's frame: R^T (p - t).
    lx = grot[g, 0, 0] * dx + grot[g, 1, 0] * dy + grot[g, 2, 0] * dz
    ly = grot[g, 0, 1] * dx + grot[g, 1, 1] * dy + grot[g, 2, 1] * dz
    lz = grot[g, 0, 2] * dx + grot[g, 1, 2] * dy + grot[g, 2, 2] * dz
    if kind == _BOX:
        qx = abs(lx) - dims[g, 0]
        qy = abs(ly) - dims[g, 1]
        qz = abs(lz) - dims[g, 2]
        ox, oy, oz = max(qx, 0.0), max(qy, 0.0), max(qz, 0.0)
        outside = np.sqrt(ox * ox + oy * oy + oz * oz)
        return outside + min(max(qx, max(qy, qz)), 0.0)
    radial = np.sqrt(lx * lx + ly * ly) - dims[g, 0]
    axial = abs(lz) - dims[g, 1]
    orad, oax = max(radial, 0.0), max(axial, 0.0)
    return np.sqrt(orad * orad + oax * oax) + min(max(radial, axial), 0.0)


@_jit
def _geometry_views(ints, floats):  # type: ignore[no-untyped-def]
    """The per-geometry and per-sphere arrays of the packed model."""
    ng = ints[_H_NG]
    ns = ints[_H_NS]
    gkind = ints[ints[_I_GKIND]:ints[_I_GKIND] + ng]
    gstart = ints[ints[_I_GSTART]:ints[_I_GSTART] + ng]
    gend = ints[ints[_I_GEND]:ints[_I_GEND] + ng]
    radii = floats[ints[_F_SR]:ints[_F_SR] + ns]
    bradius = floats[ints[_F_BR]:ints[_F_BR] + ng]
    grot = floats[ints[_F_GR]:ints[_F_GR] + 9 * ng].reshape((ng, 3, 3))
    gpos = floats[ints[_F_GP]:ints[_F_GP] + 3 * ng].reshape((ng, 3))
    dims = floats[ints[_F_GD]:ints[_F_GD] + 3 * ng].reshape((ng, 3))
    lo = floats[ints[_F_GLO]:ints[_F_GLO] + 3 * ng].reshape((ng, 3))
    hi = floats[ints[_F_GHI]:ints[_F_GHI] + 3 * ng].reshape((ng, 3))
    gcstart = ints[ints[_I_GCSTART]:ints[_I_GCSTART] + ng]
    gcend = ints[ints[_I_GCEND]:ints[_I_GCEND] + ng]
    cfirst = ints[ints[_I_CFIRST]:ints[_I_CFIRST] + ns]
    clast = ints[ints[_I_CLAST]:ints[_I_CLAST] + ns]
    return (gkind, gstart, gend, radii, bradius, grot, gpos, dims, lo, hi, gcstart, gcend,
            cfirst, clast)


@_jit
def _off_box(lo, hi, g, x, y, z, r):  # type: ignore[no-untyped-def]
    """Whether the ball (x, y, z; r) misses primitive ``g``'s world box."""
    return (x + r < lo[g, 0] or x - r > hi[g, 0] or y + r < lo[g, 1] or y - r > hi[g, 1]
            or z + r < lo[g, 2] or z - r > hi[g, 2])


@_jit
def _touching(views, centres, bounds, pa, pb, pending, first, last, rates, half, out,
              stop_at_first):  # type: ignore[no-untyped-def]
    """The pairs ``pending[first:last]`` whose spheres, grown by ``rates[p] * half`` m,
    touch: written to ``pending[out:]``; returns the index after the last one written.
    Bounding spheres of the geometries first, then of clusters, then the spheres. (One
    call for all pairs: a call per pair would cost more than its tests.)"""
    (gkind, gstart, gend, radii, bradius, grot, gpos, dims, lo, hi, gcstart, gcend,
     cfirst, clast) = views
    for n in range(first, last):
        p = pending[n]
        a = pa[p]
        b = pb[p]
        grow = rates[p] * half
        kind = gkind[b]
        touch = False
        if kind != _SPHERES:
            if _off_box(lo, hi, b, bounds[a, 0], bounds[a, 1], bounds[a, 2], bradius[a] + grow):
                continue
            if _point_primitive(grot, gpos, dims, b, kind, bounds[a, 0], bounds[a, 1],
                                bounds[a, 2]) > bradius[a] + grow:
                continue
            for c in range(gcstart[a], gcend[a]):
                if _off_box(lo, hi, b, centres[c, 0], centres[c, 1], centres[c, 2],
                            radii[c] + grow):
                    continue
                if _point_primitive(grot, gpos, dims, b, kind, centres[c, 0], centres[c, 1],
                                    centres[c, 2]) > radii[c] + grow:
                    continue
                for i in range(cfirst[c], clast[c]):
                    if _off_box(lo, hi, b, centres[i, 0], centres[i, 1], centres[i, 2],
                                radii[i] + grow):
                        continue
                    if _point_primitive(grot, gpos, dims, b, kind, centres[i, 0],
                                        centres[i, 1], centres[i, 2]) <= radii[i] + grow:
                        touch = True
                        break
                if touch:
                    break
        else:
            dx = bounds[a, 0] - bounds[b, 0]
            dy = bounds[a, 1] - bounds[b, 1]
            dz = bounds[a, 2] - bounds[b, 2]
            reach = bradius[a] + bradius[b] + grow
            if dx * dx + dy * dy + dz * dz > reach * reach:
                continue
            for c in range(gcstart[a], gcend[a]):
                dx = centres[c, 0] - bounds[b, 0]
                dy = centres[c, 1] - bounds[b, 1]
                dz = centres[c, 2] - bounds[b, 2]
                reach = radii[c] + bradius[b] + grow
                if dx * dx + dy * dy + dz * dz > reach * reach:
                    continue
                for e in range(gcstart[b], gcend[b]):
                    dx = centres[c, 0] - centres[e, 0]
                    dy = centres[c, 1] - centres[e, 1]
                    dz = centres[c, 2] - centres[e, 2]
                    reach = radii[c] + radii[e] + grow
                    if dx * dx + dy * dy + dz * dz > reach * reach:
                        continue
                    for i in range(cfirst[c], clast[c]):
                        for k in range(cfirst[e], clast[e]):
                            dx = centres[i, 0] - centres[k, 0]
                            dy = centres[i, 1] - centres[k, 1]
                            dz = centres[i, 2] - centres[k, 2]
                            reach = radii[i] + radii[k] + grow
                            if dx * dx + dy * dy + dz * dz <= reach * reach:
                                touch = True
                                break
                        if touch:
                            break
                    if touch:
                        break
                if touch:
                    break
        if touch:
            pending[out] = p
            out += 1
            if stop_at_first:
                return out
    return out


@_jit
def _views(ints, work):  # type: ignore[no-untyped-def]
    nj = ints[_H_NJ]
    ns = ints[_H_NS]
    ng = ints[_H_NG]
    nq = ints[_H_NQ]
    o = 0
    rot = work[o:o + 9 * nj].reshape((nj, 3, 3))
    o += 9 * nj
    pos = work[o:o + 3 * nj].reshape((nj, 3))
    o += 3 * nj
    centres = work[o:o + 3 * ns].reshape((ns, 3))
    o += 3 * ns
    bounds = work[o:o + 3 * ng].reshape((ng, 3))
    o += 3 * ng
    state = work[o:o + nq]
    o += nq
    delta = work[o:o + nq]
    return rot, pos, centres, bounds, state, delta


@_jit
def _state_free(ints, floats, work, base, values):  # type: ignore[no-untyped-def]
    rot, pos, centres, bounds, state, _ = _views(ints, work)
    _fill(ints, floats, state, base, values)
    _fk(ints, floats, state, rot, pos)
    _place(ints, floats, rot, pos, centres, bounds)
    npairs = ints[_H_NP]
    pa = ints[ints[_I_PA]:ints[_I_PA] + npairs]
    pb = ints[ints[_I_PB]:ints[_I_PB] + npairs]
    views = _geometry_views(ints, floats)
    pending = np.arange(npairs + 1)
    rates = np.zeros(npairs)
    return _touching(views, centres, bounds, pa, pb, pending, 0, npairs, rates, 0.0, npairs,
                     True) == npairs


@_jit
def _edge(ints, floats, work, pending, rates, base, a, b, eps, max_checks):  # type: ignore[no-untyped-def]
    """Bisection in time: an interval is clear for a pair when the pair's spheres at the
    interval's middle, grown by the pair's displacement bound over half the interval,
    do not touch; the pairs that do are checked again on both halves."""
    rot, pos, centres, bounds, state, delta = _views(ints, work)
    nq = ints[_H_NQ]
    npairs = ints[_H_NP]
    pa = ints[ints[_I_PA]:ints[_I_PA] + npairs]
    pb = ints[ints[_I_PB]:ints[_I_PB] + npairs]
    levers = floats[ints[_F_LEV]:ints[_F_LEV] + npairs * nq].reshape((npairs, nq))
    # Joint motion over the segment (mimic joints included: their map is affine).
    _fill(ints, floats, state, base, b)
    for k in range(nq):
        delta[k] = state[k]
    _fill(ints, floats, state, base, a)
    for k in range(nq):
        delta[k] = abs(delta[k] - state[k])
    # Lever arms at the segment's start (the distance from each axis to each geometry's
    # bounding sphere) grown by what the joints below can move it over the segment: much
    # tighter than the lever arms at full reach when the arm is folded.
    _fk(ints, floats, state, rot, pos)
    _place(ints, floats, rot, pos, centres, bounds)
    contribution = _segment_levers(ints, floats, rot, pos, bounds, delta)
    ng = ints[_H_NG]
    glevers = floats[ints[_F_GLEV]:ints[_F_GLEV] + ng * nq].reshape((ng, nq))
    for p in range(npairs):
        rate = 0.0
        full = 0.0
        ga = pa[p]
        gb = pb[p]
        for k in range(nq):
            full += levers[p, k] * delta[k]
            if glevers[gb, k] == 0.0:
                rate += contribution[ga, k]
            if glevers[ga, k] == 0.0:
                rate += contribution[gb, k]
        rates[p] = min(rate, full)
        pending[p] = p
    n_values = len(a)
    values = np.empty(n_values)
    views = _geometry_views(ints, floats)
    # Stack of intervals: start, end, and their pending pairs pending[first:last].
    depth_limit = 64
    starts = np.empty(depth_limit)
    ends = np.empty(depth_limit)
    firsts = np.empty(depth_limit, dtype=np.int64)
    lasts = np.empty(depth_limit, dtype=np.int64)
    starts[0], ends[0], firsts[0], lasts[0] = 0.0, 1.0, 0, npairs
    top = 1
    checks = 0
    while top > 0:
        top -= 1
        s0, s1, first, last = starts[top], ends[top], firsts[top], lasts[top]
        if checks >= max_checks:
            return s0, checks
        half = 0.5 * (s1 - s0)
        middle = s0 + half
        for k in range(n_values):
            values[k] = a[k] + middle * (b[k] - a[k])
        _fill(ints, floats, state, base, values)
        _fk(ints, floats, state, rot, pos)
        _place(ints, floats, rot, pos, centres, bounds)
        checks += 1
        # The pairs still touching go above everything pending (a stack in the buffer).
        out = _touching(views, centres, bounds, pa, pb, pending, first, last, rates, half,
                        last, False)
        if out == last:
            continue  # the whole interval is clear
        grow_max = 0.0
        for i in range(last, out):
            grow_max = max(grow_max, rates[pending[i]] * half)
        if grow_max <= eps or top + 2 > depth_limit:
            return s0, checks  # spheres (nearly) touch here
        starts[top], ends[top], firsts[top], lasts[top] = middle, s1, last, out
        starts[top + 1], ends[top + 1] = s0, middle
        firsts[top + 1], lasts[top + 1] = last, out
        top += 2
    return 2.0, checks


@_jit
def _scan(ints, floats, work, base, a, b, s, steps, out):  # type: ignore[no-untyped-def]
    """States ``s + (1 - s) i / steps`` (i = 0 … steps) of the segment whose spheres touch:
    their fractions go to ``out``; returns how many."""
    rot, pos, centres, bounds, state, _ = _views(ints, work)
    npairs = ints[_H_NP]
    pa = ints[ints[_I_PA]:ints[_I_PA] + npairs]
    pb = ints[ints[_I_PB]:ints[_I_PB] + npairs]
    n_values = len(a)
    values = np.empty(n_values)
    views = _geometry_views(ints, floats)
    pending = np.arange(npairs + 1)
    rates = np.zeros(npairs)
    found = 0
    for i in range(steps + 1):
        t = s + (1.0 - s) * i / steps
        for k in range(n_values):
            values[k] = a[k] + t * (b[k] - a[k])
        _fill(ints, floats, state, base, values)
        _fk(ints, floats, state, rot, pos)
        _place(ints, floats, rot, pos, centres, bounds)
        if _touching(views, centres, bounds, pa, pb, pending, 0, npairs, rates, 0.0, npairs,
                     True) > npairs:
            out[found] = t
            found += 1
    return found


@_jit
def _segment_levers(ints, floats, rot, pos, bounds, delta):  # type: ignore[no-untyped-def]
    """Per geometry and state column: how far that joint's motion ``delta`` can move the
    geometry over the segment, from the frames at its start (``rot``, ``pos``, bounding
    sphere centres ``bounds``): (distance from the axis to the bounding sphere's centre +
    its radius + what the joints between the axis and the geometry can move it) × the
    joint's motion; a prismatic joint moves it by its motion."""
    nj = ints[_H_NJ]
    ng = ints[_H_NG]
    nq = ints[_H_NQ]
    parent = ints[ints[_I_PARENT]:ints[_I_PARENT] + nj]
    jtype = ints[ints[_I_JTYPE]:ints[_I_JTYPE] + nj]
    jstate = ints[ints[_I_JSTATE]:ints[_I_JSTATE] + nj]
    gjoint = ints[ints[_I_GJOINT]:ints[_I_GJOINT] + ng]
    axis = floats[ints[_F_AXIS]:ints[_F_AXIS] + 3 * nj].reshape((nj, 3))
    bradius = floats[ints[_F_BR]:ints[_F_BR] + ng]
    glevers = floats[ints[_F_GLEV]:ints[_F_GLEV] + ng * nq].reshape((ng, nq))
    out = np.zeros((ng, nq))
    for g in range(ng):
        below = 0.0  # what the joints already walked (below the current one) move it
        j = gjoint[g]
        while j > 0:
            k = jstate[j]
            if jtype[j] == _PRISMATIC:
                out[g, k] = delta[k]
            else:
                # The axis in the world: through pos[j], along rot[j] @ axis[j].
                ux = rot[j, 0, 0] * axis[j, 0] + rot[j, 0, 1] * axis[j, 1] + rot[j, 0, 2] * axis[j, 2]
                uy = rot[j, 1, 0] * axis[j, 0] + rot[j, 1, 1] * axis[j, 1] + rot[j, 1, 2] * axis[j, 2]
                uz = rot[j, 2, 0] * axis[j, 0] + rot[j, 2, 1] * axis[j, 1] + rot[j, 2, 2] * axis[j, 2]
                dx = bounds[g, 0] - pos[j, 0]
                dy = bounds[g, 1] - pos[j, 1]
                dz = bounds[g, 2] - pos[j, 2]
                along = dx * ux + dy * uy + dz * uz
                off = dx * dx + dy * dy + dz * dz - along * along
                distance = np.sqrt(max(off, 0.0))
                # Both bounds hold: the one at full reach and the one from here.
                out[g, k] = min(distance + bradius[g] + below, glevers[g, k]) * delta[k]
            below += glevers[g, k] * delta[k]
            j = parent[j]
    return out


@_jit
def _fk_public(ints, floats, state, rot, pos):  # type: ignore[no-untyped-def]
    _fk(ints, floats, state, rot, pos)
