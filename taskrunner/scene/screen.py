"""The search's state check, screened: coal only where cheap bounds cannot clear a pair.

A motion planner checks thousands of states per plan, one edge (a row of states) at a
time, and wants the first state in collision. :class:`StateScreen` answers exactly as the
scene's :class:`~taskrunner.scene.collision.CollisionChecker` does, but first runs compiled
forward kinematics and, per checked pair, the bounding volumes the path verifier measures
far pairs with (:mod:`taskrunner.scene.path_verifier`: a sphere around each geometry, the box of
its local bounds): a pair whose volumes are more than 1 µm apart cannot be in contact, so
coal's narrow phase runs only on the pairs left, at the states where some are left. On
the benchmark scenes most states clear every pair (85 % of the box class's, two thirds of
the under-table pick's); those cost about a microsecond instead of coal's five.

The tests are the cheapest first: the two spheres; then each sphere against the other
geometry's box (the box's own frame); then the two boxes' separation along their six face
normals. Each is a lower bound on the distance of the two geometries (they lie inside
their sphere and their box), so clearing a pair never hides a contact. Geometries that
do not move (world objects, the robot's fixed links) have their spheres placed once per
scan and their boxes the first time a pair needs one; the others' spheres at every state,
their boxes when a pair needs them. The pairs' reaches (the sum of the two radii) are
squared once per screen. Last, a pair with a triangle mesh whose volumes overlap (two UR5
links a joint apart, in nearly every folded state) is cleared where the mesh's convex
pieces (:mod:`taskrunner.scene.mesh_pieces`: hulls that together hold its surface) are all
apart from the other geometry (its pieces, or itself), by the path verifier's support
bound (:func:`taskrunner.scene.distance_bounds._pieces_bound`).

The screen is built from a :class:`~taskrunner.scene.path_verifier.PathVerifier` (the same
geometry records: bounding spheres, boxes, the joint tree) and runs on robots whose joints
the verifier's compiled kinematics cover (revolute, continuous, prismatic); for the others
:meth:`StateScreen.first_in_collision` is the checker's own.
"""

from __future__ import annotations

import hashlib
import math
import subprocess
import sys
from collections.abc import Callable, Sequence
from pathlib import Path

import coal
import numpy as np

# numba itself only through frames (first): it sets numba's environment before numba's
# import reads it (its error message highlighting, which cost ~0.1 s of CPU at the kernels'
# first compilation, set up again for each typing attempt; a terminal reset at exit).
from taskrunner.collision import frames as collision_frames
from taskrunner.collision.frames import ORIGIN, ZERO, jit_plain, joint_frames
from taskrunner.errors import ArgumentError
from taskrunner.resources import kernel_cache_dir
from taskrunner.scene import advancement, distance_bounds, geometry_records, path_verifier
from taskrunner.scene.coalpath import exact_line_scanner
from taskrunner.scene.collision import CollisionChecker
from taskrunner.scene.distance_bounds import (
    _FR_CENTRE,
    _FR_COLUMNS,
    _FR_PLACED,
    _box_gap,
    _geometry_frame,
    _pieces_bound,
    _sphere_to_box,
)
from taskrunner.scene.path_verifier import PathVerifier

__all__ = ["CLEAR", "StateScreen", "warm_kernels"]

CLEAR = 1e-6
"""m: a pair whose bounding volumes are farther apart than this is free at that state."""
PROVEN = 1e-5
"""m: a pair whose inner volumes overlap by more than this collides at that state (coal
agrees without being asked: well beyond its 1 µm tolerance)."""

# The screen's own rows per geometry (``geo``), derived from the verifier's GEOMETRY
# records (taskrunner.collision.geometry) in the joint's frame, for what the screen places
# at every state: the bounding sphere's centre in its joint's frame and its radius, then a
# sphere inside the geometry: its centre in the joint's frame and radius (0: none). Plain
# float rows, not records: read for every pair at every state (with records for these the
# scan measured 8-10 % slower per state). The boxes are the verifier's, placed by its
# kernels (taskrunner.scene.distance_bounds) when a pair needs them.
_G_CENTRE, _G_RADIUS, _G_INNER, _G_INNER_RADIUS = 0, 3, 4, 7
_G_COLUMNS = 8
# Per-geometry int rows (``gi``): the joint, whether it has a box, whether the box is the
# geometry itself (a box shape).
_I_JOINT, _I_BOX, _I_EXACT = 0, 1, 2
# Work rows: the verifier's frames (taskrunner.scene.distance_bounds: the joints' frame
# rows, then a row per geometry, of which the screen writes the bounding sphere's centre at
# every state and the rest, with the box, when a pair needs it), then two rows whose centre
# columns hold the pair's inner spheres' centres.


# The scan kernel's arguments after the states (StateScreen._tail): joints, geometries,
# points, pieces (None without any), gi, geo, pairs, reach2, moving, work, found.
_Tail = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray | None, np.ndarray, np.ndarray,
              np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]

_INNER: dict[int, tuple[object, tuple[float, float, float, float, float]]] = {}


def _inner_sphere(geometry: coal.CollisionGeometry) -> tuple[float, float, float, float, float]:
    """A sphere inside the geometry (centre in its frame, radius; radius 0: none known)
    and 1.0 if the geometry is a box (its local bounding box is itself), else 0.0. Kept
    per coal geometry (the robot's links are the same objects in every scene revision)."""
    kept = _INNER.get(id(geometry))
    if kept is not None and kept[0] is geometry:
        return kept[1]
    exact = 0.0
    centre = np.zeros(3)
    radius = 0.0
    if isinstance(geometry, coal.Box):
        exact = 1.0
        radius = float(np.min(geometry.halfSide))
    elif isinstance(geometry, coal.Sphere):
        radius = float(geometry.radius)
    elif isinstance(geometry, coal.Capsule):
        radius = float(geometry.radius)
    elif isinstance(geometry, coal.Cylinder):
        radius = float(min(geometry.radius, geometry.halfLength))
    elif isinstance(geometry, coal.Convex) and geometry.num_polygons > 0:
        points = np.asarray(geometry.points(), dtype=float)
        faces = np.array([[geometry.polygons(i)[k] for k in range(3)]
                          for i in range(geometry.num_polygons)], dtype=np.int64)
        centre = points.mean(axis=0)  # inside the hull of the points
        p0, p1, p2 = points[faces[:, 0]], points[faces[:, 1]], points[faces[:, 2]]
        normals = np.cross(p1 - p0, p2 - p0)
        lengths = np.linalg.norm(normals, axis=1)
        keep = lengths > 1e-12 * max(1.0, float(np.max(lengths, initial=0.0)))
        if keep.any() and _closed(faces):
            normals = normals[keep] / lengths[keep, None]
            p0 = p0[keep]
            # Outward normals (away from the centre); every point on or inside every face's
            # plane: a closed convex hull, which holds the ball of radius the centre's
            # smallest distance to a face plane.
            offset = np.einsum("fi,fi->f", normals, centre - p0)
            normals[offset > 0.0] *= -1.0
            depth = np.abs(offset)
            support = normals @ points.T - np.einsum("fi,fi->f", normals, p0)[:, None]
            if float(support.max()) <= 1e-9 * max(1.0, float(np.abs(points).max())):
                radius = float(depth.min())
    radius = radius * (1.0 - 1e-9) if np.isfinite(radius) and radius > 0.0 else 0.0
    found = (float(centre[0]), float(centre[1]), float(centre[2]), radius, exact)
    if len(_INNER) > 4096:
        _INNER.clear()
    _INNER[id(geometry)] = (geometry, found)
    return found


def _closed(faces: np.ndarray) -> bool:
    """True when every edge of the triangles ``faces`` is shared by exactly two of them."""
    edges = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return bool(len(counts)) and bool(np.all(counts == 2))


class StateScreen:
    """The first state in collision among rows of states, as the checker says, sooner.

    Args:
        verifier: the scene revision's path verifier (its geometry records and pairs are
            those of ``verifier``'s checker).
    """

    def __init__(self, verifier: PathVerifier) -> None:
        self.robot = verifier.robot
        self.checker: CollisionChecker = verifier._checker
        self.supported = bool(verifier._tree.supported)
        kin = verifier._kinematics
        self._joints = kin.joints
        # The records of the scene's geometry objects, then of their meshes' convex pieces.
        geometries = verifier._geometries
        n = verifier._objects
        objects = verifier._geometry.geometryObjects
        inner = np.array([_inner_sphere(objects[g].geometry) for g in range(n)]).reshape(n, 5)
        self._gi = np.zeros((n, 3), dtype=np.int64)
        self._gi[:, _I_JOINT] = geometries["joint"][:n]
        self._gi[:, _I_BOX] = geometries["has_box"][:n]
        self._gi[:, _I_EXACT] = inner[:, 4]
        # Each geometry's sphere centres in its joint's frame (the records give them in
        # the geometry's own frame, and its placement on the joint).
        placement = geometries["placement"][:n]
        rot = placement[:, :9].reshape(n, 3, 3)
        trans = placement[:, 9:]
        geo = np.zeros((n, _G_COLUMNS))
        geo[:, _G_CENTRE:_G_CENTRE + 3] = (np.einsum("gij,gj->gi", rot, geometries["centre"][:n])
                                           + trans)
        geo[:, _G_RADIUS] = geometries["radius"][:n]
        geo[:, _G_INNER:_G_INNER + 3] = np.einsum("gij,gj->gi", rot, inner[:, :3]) + trans
        geo[:, _G_INNER_RADIUS] = inner[:, 3]
        self._geo = geo
        self._geometries = geometries
        self._points = verifier._points
        self._pieces = verifier._pieces
        self._pairs = np.ascontiguousarray(
            np.column_stack([verifier._first, verifier._second]), dtype=np.int64).reshape(-1, 2)
        reach = geo[self._pairs[:, 0], _G_RADIUS] + geo[self._pairs[:, 1], _G_RADIUS] + CLEAR
        self._reach2 = np.ascontiguousarray(reach * reach)
        self._moving = np.ascontiguousarray(np.flatnonzero(self._gi[:, 0] != 0), dtype=np.int64)

    def _new_buffers(self) -> tuple[np.ndarray, np.ndarray]:
        nj, ng = len(self._joints), len(self._geometries)
        work = np.zeros((nj + ng + 2, _FR_COLUMNS))
        return work, np.zeros(len(self._pairs), dtype=np.int64)

    def _tail(self, work: np.ndarray, found: np.ndarray) -> _Tail:
        """The kernels' arguments after the states: this screen's arrays (``pieces``: None
        without any) and the work ones."""
        return (self._joints, self._geometries, self._points, self._pieces, self._gi, self._geo,
                self._pairs, self._reach2, self._moving, work, found)

    def scanner(self) -> Callable[[np.ndarray], int]:
        """:meth:`first_in_collision` with work arrays of its own, for one thread: what a
        search calls thousands of times (no lock, the arrays and methods bound once)."""
        checker, robot = self.checker, self.robot
        to_pin = robot.to_pin
        if not self.supported:
            first = checker.first_in_collision
            return lambda states: first(to_pin(states))
        work, found = self._new_buffers()
        tail = self._tail(work, found)
        collide = checker.pairs_collide

        no_values = np.zeros(0)
        no_table = np.zeros((1, 0))

        def scan(states: np.ndarray) -> int:
            row, _ = _line_until_collision(states, no_table, no_values, no_values, 0, 0,
                                           len(states), 1.0, tail, found, collide, to_pin)
            return -1 if row < 0 else int(row)

        return scan

    def line_scanner(self) -> Callable[[np.ndarray, np.ndarray, np.ndarray, np.ndarray, int, int],
                                         int]:
        """A scan of states on a segment, for one thread: ``scan(rows, fractions, a, b,
        first, begin)`` writes row ``s >= begin`` of ``rows`` (full states: the columns
        ``first`` to ``first + len(a)`` are the segment's, the others are kept) as
        ``a + fractions[s] (b - a)`` (``b`` at fraction 1) and returns the first row in
        collision, or -1, as :meth:`scanner` would on the rows written; the interpolation
        runs in the compiled loop, row by row, as far as the first collision."""
        checker, robot = self.checker, self.robot
        to_pin = robot.to_pin
        if not self.supported:
            return exact_line_scanner(checker.first_in_collision, to_pin)
        work, found = self._new_buffers()
        tail = self._tail(work, found)
        collide = checker.pairs_collide

        def scan(rows: np.ndarray, fractions: np.ndarray, a: np.ndarray, b: np.ndarray,
                 first: int, begin: int) -> int:
            row, _ = _line_until_collision(rows, fractions.reshape(1, -1), a, b, first, begin,
                                           len(fractions), 1.0, tail, found, collide, to_pin)
            return -1 if row < 0 else int(row)

        return scan

    def segment_scanner(self, base: np.ndarray, first: int, table: np.ndarray,
                        resolution: float, fill: Callable[[int], None] | None = None
                        ) -> Callable[[np.ndarray, np.ndarray, int], tuple[int, int]] | None:
        """A search's edge check, for one thread (None where the screen runs coal alone):
        ``scan(a, b, begin)`` checks the segment from ``a`` to ``b`` (the values of columns
        ``first`` to ``first + len(a)`` of ``base``, a full state; the other columns are
        ``base``'s) cut in ``steps = max(1, ceil(max |b - a| / resolution))`` steps: its
        states at the fractions ``table[steps, begin:steps]`` (row ``steps`` of ``table``:
        the end's 1.0 first, then the inner states in the order to check them), and returns
        the first of them in collision (its position in that row) or -1, and ``steps``.
        A row not filled yet (not starting with 1.0) is filled by ``fill(steps)`` (which
        writes ``table``: it is read, not copied) before the scan; -2: ``table`` has no
        row for that many steps, or, without ``fill``, not yet (check the segment
        otherwise). The step count, the interpolation and the screening run in one
        compiled call."""
        if not self.supported:
            return None
        if (table.dtype != np.float64 or not table.flags.c_contiguous or table.ndim != 2
                or table.shape[0] < 2 or table.shape[1] < table.shape[0] - 1):
            raise ArgumentError("'table' must be a C-contiguous float array with a row of "
                             f"fractions per step count (got {table.dtype}, {table.shape})")
        rows = np.empty((table.shape[0] - 1, self.robot.nq))
        rows[:] = np.asarray(base, dtype=float)
        work, found = self._new_buffers()
        tail = self._tail(work, found)
        collide, to_pin = self.checker.pairs_collide, self.robot.to_pin

        def scan(a: np.ndarray, b: np.ndarray, begin: int) -> tuple[int, int]:
            row, steps = _line_until_collision(rows, table, a, b, first, begin, 0, resolution,
                                               tail, found, collide, to_pin)
            if row == -2 and fill is not None and steps < table.shape[0]:
                fill(steps)
                row, steps = _line_until_collision(rows, table, a, b, first, begin, 0,
                                                   resolution, tail, found, collide, to_pin)
            return row, steps

        return scan

    def first_in_collision(self, states: np.ndarray) -> int:
        """The index of the first row of ``states`` (full state vectors, ``(n, nq)``) in
        collision, or -1."""
        states = np.ascontiguousarray(states, dtype=float)
        nq = self.robot.nq
        if states.ndim != 2 or states.shape[1] != nq:
            raise ArgumentError(f"states must be an (n, {nq}) array of full state vectors "
                             f"(got shape {states.shape})")
        return self.scanner()(states)


def _line_until_collision(rows: np.ndarray, table: np.ndarray, a: np.ndarray, b: np.ndarray,
                          first: int, begin: int, steps: int, resolution: float,
                          tail: _Tail, found: np.ndarray,
                          collide: Callable[[np.ndarray, Sequence[int] | np.ndarray], bool],
                          to_pin: Callable[[np.ndarray], np.ndarray]) -> tuple[int, int]:
    """Run :func:`_first_uncleared_on_line` from row ``begin`` on, asking coal about the
    pairs it leaves at each row it stops at, until a row is in collision: that row (-1:
    none; -2: no fractions for the segment's steps) and the steps."""
    while True:
        row, count, counted = _first_uncleared_on_line(rows, table, a, b, first, begin, steps,
                                                       resolution, *tail)
        if row < 0 or count < 0 or collide(to_pin(rows[row]), found[:count]):
            return row, counted
        begin = row + 1


def warm_kernels(verifier: PathVerifier, q: np.ndarray) -> None:
    """Load the compiled kernels of ``verifier`` and of its screen (compiling them the
    first time on a machine: about 2.7 and 0.6 s of CPU, then cached on disk) by checking a
    short motion from state ``q`` (within the limits).

    The first time (no mark of a finished warm-up for these kernels' sources), the
    screen's kernels compile in a second process while this one compiles the verifier's:
    on two cores the first run waits for the longer of the two, not their sum."""
    robot = verifier.robot
    states = np.ascontiguousarray(np.stack([q, np.clip(q + 1e-3, robot.lower, robot.upper)]),
                                  dtype=float)
    mark = _warm_mark()
    helper = None
    if not mark.exists():
        try:
            helper = subprocess.Popen(
                [sys.executable, "-c", "from taskrunner.scene.screen import _compile_alone; "
                 "_compile_alone()"], stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL)
        except OSError:
            helper = None  # compiled here instead, after the verifier's
    verifier.verify(states)
    if helper is not None:
        try:
            helper.wait(timeout=_COMPILE_WAIT)
        except subprocess.TimeoutExpired:
            helper.kill()
    _scan_both(StateScreen(verifier), states)
    try:
        mark.parent.mkdir(parents=True, exist_ok=True)
        mark.touch()
    except OSError:
        pass  # a read-only cache: the next run warms up the same way


_COMPILE_WAIT = 900.0  # s: the screen's compilation in the second process, at most


def _scan_both(screen: StateScreen, states: np.ndarray) -> None:
    """Both scans once on ``states`` (two rows): their kernels compiled or loaded."""
    screen.first_in_collision(states)
    rows = states.copy()
    values = np.ascontiguousarray(states[0])
    screen.line_scanner()(rows, np.array([1.0, 0.5]), values, values.copy(), 0, 0)
    scan = screen.segment_scanner(states[0], 0, np.array([[0.0], [1.0]]), 1.0)
    if scan is not None:
        scan(values, values.copy(), 0)


def _warm_mark() -> Path:
    """The file that marks the kernels of these sources as compiled on this machine."""
    digest = hashlib.sha256()
    # numba caches per source file and content
    for module in (__file__, path_verifier.__file__, advancement.__file__,
                   distance_bounds.__file__, geometry_records.__file__, collision_frames.__file__):
        digest.update(str(Path(module).resolve()).encode())
        digest.update(Path(module).read_bytes())
    import numba  # loaded by then (through frames, above)

    digest.update(f"{numba.__version__} {sys.version}".encode())
    return kernel_cache_dir() / f"warm-{digest.hexdigest()[:16]}"


def _compile_alone() -> None:
    """Compile (and cache) the screen's kernels on the servo arm alone: what
    :func:`warm_kernels` runs in its second process."""
    from taskrunner.resources import DATA_ROOT
    from taskrunner.robot import load_robot
    from taskrunner.scene.scene import Scene

    scene = Scene(load_robot(DATA_ROOT / "robots" / "servo_arm"))
    q = scene.state
    states = np.ascontiguousarray(np.stack([q, q]), dtype=float)
    _scan_both(scene.state_screen(), states)


@jit_plain
def _first_uncleared_on_line(rows: np.ndarray, table: np.ndarray, a: np.ndarray, b: np.ndarray,
                             first: int, begin: int, steps: int, resolution: float,
                             joints: np.ndarray, geometries: np.ndarray, points: np.ndarray,
                             pieces: np.ndarray | None, gi: np.ndarray,
                             geo: np.ndarray, pairs: np.ndarray, reach2: np.ndarray,
                             moving: np.ndarray, work: np.ndarray, found: np.ndarray
                             ) -> tuple[int, int, int]:
    """From row ``begin`` of ``rows`` on, the first state at which some pairs are not
    cleared: returns its row, how many pairs (their indices in ``found``; -1: a pair
    surely collides) and ``steps``; ``(-1, 0, steps)`` when every state clears every pair.
    A state that is not finite clears nothing. The one scan kernel of both scans.

    On a segment from ``a`` to ``b`` (the values of columns ``first`` to
    ``first + len(a)``; the other columns are ``rows``'): row ``s``
    (``begin <= s < steps``) is written ``a + f (b - a)`` there, ``f`` the fraction
    ``table[0, s]`` (``b`` itself at 1), before it is screened, so that a row returned
    holds its state. ``steps`` 0: the segment's own count,
    ``max(1, ceil(max |b - a| / resolution))``, and the fractions ``table[steps]``
    (``(-2, 0, steps)`` without such a row, or where it does not start with 1.0). Rows
    as they are (:meth:`StateScreen.scanner`): ``a`` and ``b`` empty, ``steps`` the
    rows' count (``table`` is not read).

    At each state the bounding spheres are placed here; the boxes (when a pair needs one)
    are placed, and a sphere measured against a box and two boxes against each other, by
    the path verifier's kernels (:mod:`taskrunner.scene.distance_bounds`). One function
    with no helpers of its own: each level of called kernels has LLVM optimize the code
    beneath it once more at the first compilation."""
    n = a.shape[0]
    if steps > 0:
        fractions = table[0]
    else:
        longest = 0.0
        for i in range(n):
            gap = abs(b[i] - a[i])
            if gap > longest:
                longest = gap
        steps = math.ceil(longest / resolution)
        if steps < 1:  # max(1, steps), without compiling numba's max()
            steps = 1
        if steps >= table.shape[0] or steps > rows.shape[0] or table[steps, 0] != 1.0:
            return -2, 0, steps
        fractions = table[steps]
    nj = joints.shape[0]
    ng = gi.shape[0]  # the geometry objects; their meshes' pieces' records follow theirs
    inner_a = nj + geometries.shape[0]  # two rows: the pair's inner sphere centres
    inner_b = inner_a + 1
    for g in range(geometries.shape[0]):  # no geometry placed yet
        work[nj + g, _FR_PLACED] = -1.0
    for g in range(ng):  # the fixed ones' sphere centres placed
        if gi[g, _I_JOINT] == 0:
            for i in range(3):
                work[nj + g, _FR_CENTRE + i] = geo[g, _G_CENTRE + i]
    for s in range(begin, steps):
        if n > 0:
            f = fractions[s]
            for i in range(n):
                rows[s, first + i] = b[i] if f == 1.0 else a[i] + f * (b[i] - a[i])
        stamp = float(s)
        joint_frames(rows[s], joints, work)
        for m in range(moving.shape[0]):
            g = moving[m]
            jid = gi[g, _I_JOINT]
            for i in range(3):
                work[nj + g, _FR_CENTRE + i] = (work[jid, ORIGIN + i]
                                                + work[jid, 3 * i] * geo[g, _G_CENTRE]
                                                + work[jid, 3 * i + 1] * geo[g, _G_CENTRE + 1]
                                                + work[jid, 3 * i + 2] * geo[g, _G_CENTRE + 2])
        count = ZERO
        for k in range(pairs.shape[0]):
            ga, gb = pairs[k, 0], pairs[k, 1]
            row_a, row_b = nj + ga, nj + gb
            dx = work[row_a, _FR_CENTRE] - work[row_b, _FR_CENTRE]
            dy = work[row_a, _FR_CENTRE + 1] - work[row_b, _FR_CENTRE + 1]
            dz = work[row_a, _FR_CENTRE + 2] - work[row_b, _FR_CENTRE + 2]
            if dx * dx + dy * dy + dz * dz > reach2[k]:
                continue
            cleared = False
            for side in range(2):  # a's sphere against b's box, then b's against a's
                box, other = (gb, ga) if side == 0 else (ga, gb)
                if gi[box, _I_BOX] == 0:
                    continue
                if work[nj + box, _FR_PLACED] < stamp:  # placed once per scan if fixed
                    _geometry_frame(box, geometries, work, nj)
                    work[nj + box, _FR_PLACED] = np.inf if gi[box, _I_JOINT] == 0 else stamp
                if _sphere_to_box(work, nj + other, geo[other, _G_RADIUS], box, geometries,
                                  nj) > CLEAR:
                    cleared = True
                    break
            if cleared or (gi[ga, _I_BOX] != 0 and gi[gb, _I_BOX] != 0
                           and _box_gap(ga, gb, geometries, work, nj) > CLEAR):
                continue
            # Surely overlapping (by more than PROVEN): the inner spheres do, or one's
            # inner sphere overlaps the other's box where that box is the geometry.
            ra = geo[ga, _G_INNER_RADIUS]
            rb = geo[gb, _G_INNER_RADIUS]
            if ra > 0.0 or rb > 0.0:
                for side in range(2):
                    g = ga if side == 0 else gb
                    jid = gi[g, _I_JOINT]
                    x, y, z = geo[g, _G_INNER], geo[g, _G_INNER + 1], geo[g, _G_INNER + 2]
                    for i in range(3):
                        work[inner_a + side, _FR_CENTRE + i] = (
                            work[jid, ORIGIN + i] + work[jid, 3 * i] * x
                            + work[jid, 3 * i + 1] * y + work[jid, 3 * i + 2] * z)
                proven = False
                if ra > 0.0 and rb > 0.0:
                    reach = ra + rb - PROVEN
                    gap = 0.0
                    for i in range(3):
                        offset = work[inner_a, _FR_CENTRE + i] - work[inner_b, _FR_CENTRE + i]
                        gap += offset * offset
                    proven = reach > 0.0 and gap < reach * reach
                for side in range(2):  # a's inner sphere in b's box, then b's in a's
                    inner, box = (ra, gb) if side == 0 else (rb, ga)
                    if (not proven and inner > 0.0 and gi[box, _I_EXACT] != 0
                            and gi[box, _I_BOX] != 0
                            and _sphere_to_box(work, inner_a + side, inner, box, geometries,
                                               nj) < -PROVEN):
                        proven = True
                if proven:
                    return s, -1, steps
            # A mesh's convex pieces apart from the other's (or the other itself). Without
            # pieces (None), numba compiles the scan without this code (a type of its own).
            if pieces is not None:
                if ((pieces[ga, 1] != 0 or pieces[gb, 1] != 0)
                        and _pieces_bound(ga, gb, geometries, work, points, nj, pieces, stamp,
                                          CLEAR, 2.0 * CLEAR, np.inf) > CLEAR):
                    continue
            found[count] = k
            count += 1
        if count != 0:
            return s, count, steps
    return -1, 0, steps
