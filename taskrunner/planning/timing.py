"""Time parameterization: a geometric :class:`JointPath` becomes a sampled :class:`JointTrajectory`.

The path is the polyline through its waypoints (what a planner checked). It is densified
(``densify_step_rad`` per joint at most), fitted with a cubic spline over the chord length
``s`` (rad, Euclidean in joint space) and timed rest-to-rest by TOPP-RA (toppra; Pham &
Pham, T-RO 2018) within the model's velocity and acceleration limits times the scalings.

toppra imposes the limits at its gridpoints only: inside a stage (constant path
acceleration) a joint acceleration ``q' u + q'' x(s)`` overshoots near corners (20-200 %,
measured). Extra constraints impose the limits at points inside every stage, and every
sample is verified. The spline rings near corners (strays up to ~0.2 x the densify step) and
can cross a position limit a joint sits at through a corner: then a monotone PCHIP curve, which
stays within each joint's range between consecutive waypoints, replaces it (slower at
corners: 10-30 % longer, measured). A path of two waypoints (a straight line in joint
space) needs none of this: its time-optimal timing (a trapezoid of path speed) is exact in
closed form, ten times cheaper than toppra and within 1 % of toppra's discretized optimum.
Units: rad (m), rad/s, rad/s², s.
"""

from __future__ import annotations

import functools
import logging
import math
import threading
from collections.abc import Callable
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any

import numpy as np

from taskrunner.errors import ArgumentError, PlanningError
from taskrunner.robot.model import JointInfo, RobotModel
from taskrunner.types import JointPath, JointTrajectory

__all__ = ["TimingOptions", "load_toppra", "parameterize_path", "path_deviation", "trajectory_json"]

_CHECKS_PER_STAGE = 6  # limit checks per toppra stage (residual overshoot between them ~0.5 %)
_CURVE_ERROR = 3e-3  # rad: spline intervals are split until 0.5 |q''| ds² is below this
_MAX_SPLIT = 3  # stages per spline interval at most
_MAX_STAGE = 0.2  # rad of chord length: longest stage on straight stretches
_REFINEMENTS = 2  # times stages holding a sample over the limits are split and solved again
_GEOMETRY_CHECKS = 8  # points per spline interval where deviation and position are checked
_MIN_STAGES = 8  # short paths: each spline interval gets its share of these
_SAME = 1e-9  # rad: closer waypoints are one waypoint; slack of the position-limit check
_ACCELERATION_PER_VELOCITY = 2.0  # 1/s: default a_max = 2 v_max (full speed in 0.5 s)


def _check(name: str, value: Any, ok: Callable[[float], bool], expectation: str,
           optional: bool = False) -> None:
    if optional and value is None:
        return
    number = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
    if not (number and ok(value)):
        raise ArgumentError(f"'{name}' must be {expectation} (got {value!r})")


@dataclass(frozen=True)
class TimingOptions:
    """How :func:`parameterize_path` times a path.

    Attributes:
        velocity_scaling: factor in (0, 1] on every velocity limit. None: the
            ``default_velocity_scaling_factor`` of the joint_limits.yaml of the robot
            owning the path's joints (the smallest one when the path spans several robots).
        acceleration_scaling: the same for accelerations.
        sample_rate_hz: output samples per second (Hz).
        densify_step_rad: largest change of any joint between densified points (rad).
        default_acceleration: acceleration limit (rad/s², before scaling) of a joint that
            has none. None: twice the joint's velocity limit per second.
        limit_tolerance: relative slack of the check of every sample,
            ``|qd| <= v_max * scaling * (1 + limit_tolerance)``, likewise ``|qdd|``.
            toppra aims at the limits divided by ``1 + limit_tolerance / 2``.
        max_deviation_rad: largest accepted distance (rad, Euclidean in joint space) from
            a sample to the waypoint polyline. None: ``densify_step_rad``.
    """

    velocity_scaling: float | None = None
    acceleration_scaling: float | None = None
    sample_rate_hz: float = 100.0
    densify_step_rad: float = 0.05
    default_acceleration: float | None = None
    limit_tolerance: float = 0.01
    max_deviation_rad: float | None = None

    def __post_init__(self) -> None:
        for name in ("velocity_scaling", "acceleration_scaling"):
            _check(name, getattr(self, name), lambda v: 0 < v <= 1, "in (0, 1]", optional=True)
        for name in ("sample_rate_hz", "densify_step_rad", "default_acceleration",
                     "max_deviation_rad"):
            optional = name in ("default_acceleration", "max_deviation_rad")
            _check(name, getattr(self, name), lambda v: v > 0, "a positive number", optional)
        _check("limit_tolerance", self.limit_tolerance, lambda v: v >= 0, "a number >= 0")


def parameterize_path(model: RobotModel, path: JointPath,
                      options: TimingOptions | None = None) -> JointTrajectory:
    """Time ``path`` rest-to-rest within the model's scaled velocity and acceleration limits.

    Args:
        model: gives the limits of the path's joints (columns are matched by name).
        path: waypoints within the position limits; consecutive duplicates are ignored.
        options: see :class:`TimingOptions`.

    Returns:
        Samples every ``1 / sample_rate_hz`` s from t = 0 plus one exactly at the end (a
        regular sample within 0.1 % of a period before it is dropped); the first and last
        sit exactly on the end waypoints with zero velocity. A path without motion gives
        one sample at t = 0. :func:`path_deviation` measures the distance to the polyline
        (checked here against ``max_deviation_rad``).

    Raises:
        UnknownNameError: a joint of the path is not in the model.
        ValueError: no joint or waypoint, a repeated joint, a non-finite value.
        PlanningError: a joint without velocity limit (add one to joint_limits.yaml), a
            waypoint outside the position limits, toppra failing, samples straying from
            the path or breaking a limit (the message names the joint and the time).
    """
    options = options or TimingOptions()
    names = path.names
    joints = [model.joint(name) for name in names]
    if len(set(names)) != len(names):
        raise ArgumentError(f"'path' must name each joint once (got {list(names)})")
    if not names or len(path) == 0 or not np.all(np.isfinite(path.waypoints)):
        raise ArgumentError("'path' must have joints and finite waypoints "
                         f"(got shape {path.waypoints.shape})")
    vmax, amax = _scaled_limits(model, joints, options)
    lower, upper = np.array([j.lower for j in joints]), np.array([j.upper for j in joints])
    given = np.asarray(path.waypoints)
    _raise_worst(np.maximum(lower - given, given - upper) - _SAME, lambda k, j: (
        f"waypoint {k} puts joint {names[j]!r} at {given[k, j]:.4f}, outside its limits "
        f"[{lower[j]:.4f}, {upper[j]:.4f}]"))
    steps = np.max(np.abs(np.diff(given, axis=0)), axis=1)
    waypoints = given[np.concatenate([[True], steps > _SAME])]
    if len(waypoints) == 1:
        zeros = np.zeros((1, len(names)))
        return JointTrajectory(names, np.zeros(1), waypoints, zeros, zeros)
    if len(waypoints) == 2:
        # A straight line: its time-optimal timing is known in closed form (exact at every
        # instant, no spline, no grid); see _time_line.
        times, q, qd, qdd = _time_line(waypoints, vmax, amax, options)
        q[0], q[-1], qd[0], qd[-1] = waypoints[0], waypoints[-1], 0.0, 0.0
        _check_limits(names, times, qd, vmax, "velocity", "rad/s", options.limit_tolerance)
        _check_limits(names, times, qdd, amax, "acceleration", "rad/s²", options.limit_tolerance)
        return JointTrajectory(names, times, q, qd, qdd)
    max_deviation = options.max_deviation_rad or options.densify_step_rad
    dense, segment = _densify(waypoints, options.densify_step_rad)
    ss = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(dense, axis=0), axis=1))])
    fractions = np.arange(_GEOMETRY_CHECKS) / _GEOMETRY_CHECKS
    check_s = np.append((ss[:-1, None] + np.diff(ss)[:, None] * fractions).ravel(), ss[-1])
    check_segment = np.append(np.repeat(segment, _GEOMETRY_CHECKS), segment[-1])
    kit = _toppra_kit()
    for make_curve in (kit.toppra.SplineInterpolator, kit.Pchip):
        curve = make_curve(ss, dense)
        points = curve(check_s)  # the samples lie on the curve: check it first
        deviation = _deviation_near(waypoints, points, check_segment)
        if deviation > max_deviation or np.any((points < lower - _SAME) | (points > upper + _SAME)):
            continue
        times, q, qd, qdd = _time_curve(kit, curve, ss, vmax, amax, options)
        if np.all((q >= lower - _SAME) & (q <= upper + _SAME)):
            break
    else:
        raise PlanningError(f"the timed path strays {deviation:.4f} rad from the waypoints "
                            f"(max_deviation_rad {max_deviation:.4f}) or leaves a position limit")
    q[0], q[-1], qd[0], qd[-1] = waypoints[0], waypoints[-1], 0.0, 0.0
    _check_limits(names, times, qd, vmax, "velocity", "rad/s", options.limit_tolerance)
    _check_limits(names, times, qdd, amax, "acceleration", "rad/s²", options.limit_tolerance)
    return JointTrajectory(names, times, q, qd, qdd)


def path_deviation(path: JointPath, trajectory: JointTrajectory) -> float:
    """Largest distance (rad, Euclidean in joint space) from a sample of ``trajectory`` to
    the nearest segment of the polyline through ``path``'s waypoints (same joints, same order).
    """
    if tuple(trajectory.names) != tuple(path.names):
        raise ArgumentError(f"'trajectory' must have the path's joints {list(path.names)} "
                         f"(got {list(trajectory.names)})")
    waypoints, q = np.asarray(path.waypoints), np.asarray(trajectory.positions)
    if len(q) == 0 or len(waypoints) == 0:
        return 0.0
    if len(waypoints) == 1:
        return float(np.max(np.linalg.norm(q - waypoints[0], axis=1)))
    start, seg = waypoints[:-1], np.diff(waypoints, axis=0)
    length2 = np.maximum(np.einsum("ij,ij->i", seg, seg), 1e-300)
    worst = 0.0
    for block in np.array_split(q, 1 + len(q) * len(seg) // 20_000):  # bounded temporaries
        offset = block[:, None] - start
        t = np.clip(np.einsum("mij,ij->mi", offset, seg) / length2, 0.0, 1.0)
        distance = np.linalg.norm(offset - t[..., None] * seg, axis=2)
        worst = max(worst, float(np.max(np.min(distance, axis=1))))
    return worst


def _scaled_limits(model: RobotModel, joints: list[JointInfo], options: TimingOptions
                   ) -> tuple[np.ndarray, np.ndarray]:
    robots = [model.instance(name) for name in dict.fromkeys(j.robot for j in joints)]
    v_scale = options.velocity_scaling or min(r.velocity_scaling for r in robots)
    a_scale = options.acceleration_scaling or min(r.acceleration_scaling for r in robots)
    vmax, amax = [], []
    for joint in joints:
        if not (math.isfinite(joint.max_velocity) and joint.max_velocity > 0):
            raise PlanningError(f"joint {joint.name!r} has no velocity limit (got "
                                f"{joint.max_velocity}): give it a max_velocity in joint_limits.yaml")
        accel = joint.max_acceleration
        if not (math.isfinite(accel) and accel > 0):
            accel = options.default_acceleration or _ACCELERATION_PER_VELOCITY * joint.max_velocity
        vmax.append(joint.max_velocity * v_scale)
        amax.append(accel * a_scale)
    return np.array(vmax), np.array(amax)


def _densify(waypoints: np.ndarray, step: float) -> tuple[np.ndarray, np.ndarray]:
    """Points at most ``step`` apart per joint, and the waypoint segment of each interval."""
    deltas = np.diff(waypoints, axis=0)
    counts = np.maximum(1, np.ceil(np.max(np.abs(deltas), axis=1) / step - 1e-9)).astype(int)
    segment = np.repeat(np.arange(len(deltas)), counts)
    ends = np.cumsum(counts)
    fraction = (np.arange(ends[-1]) - (ends - counts)[segment] + 1) / counts[segment]
    points = waypoints[segment] + fraction[:, None] * deltas[segment]
    points[ends - 1] = waypoints[1:]  # segments end exactly on the waypoints
    return np.vstack([waypoints[:1], points]), segment


def _sample_times(end: float, rate: float) -> np.ndarray:
    """Every ``1 / rate`` s from 0, and ``end`` (a regular sample within 0.1 % of a period
    before it is dropped)."""
    times = np.arange(math.ceil(end * rate)) / rate
    return np.append(times[end - times > 1e-3 / rate], end)


def _time_line(waypoints: np.ndarray, vmax: np.ndarray, amax: np.ndarray,
               options: TimingOptions) -> tuple[np.ndarray, ...]:
    """The time-optimal rest-to-rest timing of the straight line between two waypoints.

    Along ``q(s) = q0 + s u`` (``u`` the unit direction, ``s`` the chord length) every
    joint's velocity is ``u_j s'`` and acceleration ``u_j s''``: the box limits become
    ``|s'| <= V = min_j v_j / |u_j|`` and ``|s''| <= A = min_j a_j / |u_j|``, and the
    fastest motion accelerates at A, cruises at V (if it reaches it) and decelerates at
    A: a trapezoid (or triangle) of ``s'``. The limits aimed at are toppra's (the scaled
    limits over ``1 + limit_tolerance / 2``), so both timings agree.
    """
    delta = waypoints[1] - waypoints[0]
    length = float(np.linalg.norm(delta))
    unit = np.abs(delta) / length
    moving = unit > 0.0
    margin = 1.0 + options.limit_tolerance / 2
    # A joint with a tiny share of the line (a step of 1e-310 rad beside 1 rad: a joint
    # "at 0" on one end and at a subnormal on the other) bounds s' and s'' by more than
    # the largest float, that is not at all: its quotient overflows to inf and min() passes
    # over it. The joint moving most (unit >= 1 / sqrt(n)) bounds both finitely.
    with np.errstate(over="ignore"):
        speed = float(np.min(vmax[moving] / margin / unit[moving]))
        accel = float(np.min(amax[moving] / margin / unit[moving]))
    if speed * speed / accel <= length:  # reaches full speed
        ramp, cruise, peak = speed / accel, (length - speed * speed / accel) / speed, speed
    else:
        peak = math.sqrt(length * accel)
        ramp, cruise = peak / accel, 0.0
    end = 2 * ramp + cruise
    times = _sample_times(end, options.sample_rate_hz)
    rising, falling = times < ramp, times > ramp + cruise
    left = end - times
    s = np.where(rising, 0.5 * accel * times**2,
                 np.where(falling, length - 0.5 * accel * left**2,
                          0.5 * accel * ramp**2 + peak * (times - ramp)))
    s_dot = np.where(rising, accel * times, np.where(falling, accel * left, peak))
    s_ddot = np.where(rising, accel, np.where(falling, -accel, 0.0))
    fraction = np.clip(s / length, 0.0, 1.0)[:, None]
    direction = delta / length
    return (times, waypoints[0] + fraction * delta, s_dot[:, None] * direction,
            s_ddot[:, None] * direction)


def _time_curve(kit: SimpleNamespace, curve: Any, ss: np.ndarray, vmax: np.ndarray,
                amax: np.ndarray, options: TimingOptions) -> tuple[np.ndarray, ...]:
    grid = _gridpoints(curve, ss)
    margin = 1.0 + options.limit_tolerance / 2  # room for the overshoot between check points
    v_lim, a_lim = vmax / margin, amax / margin
    constraints = kit.constraints(tuple(v_lim), tuple(a_lim))
    for _ in range(_REFINEMENTS + 1):
        try:
            algorithm = kit.toppra.algorithm.TOPPRA(constraints, curve, gridpoints=grid,
                                                    solver_wrapper="seidel")
            _, sd, _ = algorithm.compute_parameterization(0.0, 0.0)
        except (ValueError, ArithmeticError, IndexError) as exc:  # toppra's own complaints
            raise PlanningError(f"toppra could not time the path of {ss[-1]:.4g} rad over "
                                f"{len(grid) - 1} stages: {type(exc).__name__}: {exc}") from exc
        if sd is None or not np.all(np.isfinite(sd)):
            code = algorithm.problem_data.return_code
            raise PlanningError(f"toppra could not time the path ({code})")
        times, stage, q, qd, qdd = _sample(curve, grid, sd, options.sample_rate_hz)
        ratio = np.maximum(np.abs(qd) / vmax, np.abs(qdd) / amax).max(axis=1)
        bad = np.unique(stage[ratio > 1.0 + options.limit_tolerance])
        if len(bad) == 0:
            break
        # Rare (sharp bends of a PCHIP curve): split the offending stages and solve again.
        extra = grid[bad, None] + np.diff(grid)[bad, None] * np.array([0.25, 0.5, 0.75])
        grid = np.sort(np.concatenate([grid, extra.ravel()]))
    return times, q, qd, qdd


def _gridpoints(curve: Any, ss: np.ndarray) -> np.ndarray:
    """toppra stages: spline intervals split where the curve bends, merged where straight."""
    h = np.diff(ss)
    start = np.linalg.norm(curve(ss[:-1], 2), axis=1)
    end = np.linalg.norm(curve(ss[1:] - 1e-9 * h, 2), axis=1)  # left limit: PCHIP's q'' jumps
    splits = np.ceil(h * np.sqrt(0.5 * np.maximum(start, end) / _CURVE_ERROR))
    at_least = np.maximum(np.ceil(h / _MAX_STAGE), np.ceil(_MIN_STAGES * h / ss[-1]))
    splits = np.maximum(np.clip(splits, 1, _MAX_SPLIT), at_least).astype(int)
    points, last = [0.0], 0.0
    for k, n in enumerate(splits):
        if n > 1:
            # ss[k] + h[k] can differ from ss[k + 1] by one float step: end on ss[k + 1]
            # itself (toppra wants the last gridpoint to be exactly the path's end).
            points.extend(ss[k] + h[k] * np.arange(1, n) / n)
            points.append(ss[k + 1])
        elif k + 1 == len(h) or splits[k + 1] > 1 or ss[k + 1] + h[k + 1] - last > _MAX_STAGE:
            points.append(ss[k + 1])
        else:
            continue
        last = ss[k + 1]
    if len(points) < _MIN_STAGES + 1:
        # Merging straight intervals can leave a short path with a single stage, which
        # cannot go rest to rest: keep at least _MIN_STAGES stages.
        points = sorted(set(points) | set(np.linspace(0.0, ss[-1], _MIN_STAGES + 1)))
    grid = np.array(points)
    # The union above can hold two points a float step apart: keep stages of real length.
    keep = np.concatenate([[True], np.diff(grid) > _SAME * max(1.0, ss[-1])])
    keep[-1] = True
    grid = grid[keep]
    if len(grid) > 2 and grid[-1] - grid[-2] <= _SAME * max(1.0, ss[-1]):
        grid = np.delete(grid, -2)
    grid[0], grid[-1] = ss[0], ss[-1]
    return grid


def _sample(curve: Any, grid: np.ndarray, sd: np.ndarray, rate: float) -> tuple[np.ndarray, ...]:
    """Samples of toppra's solution, with a constant path acceleration in each stage."""
    ds = np.diff(grid)
    x = sd**2
    u = (x[1:] - x[:-1]) / (2 * ds)
    stage_time = 2 * ds / (sd[:-1] + sd[1:])
    if not np.all(np.isfinite(stage_time)):
        raise PlanningError("toppra stopped inside the path (zero velocity at a gridpoint)")
    t_grid = np.concatenate([[0.0], np.cumsum(stage_time)])
    times = _sample_times(float(t_grid[-1]), rate)
    i = np.clip(np.searchsorted(t_grid, times, side="right") - 1, 0, len(ds) - 1)
    tau = times - t_grid[i]
    s = np.clip(grid[i] + sd[i] * tau + 0.5 * u[i] * tau**2, grid[0], grid[-1])
    s_dot = (sd[i] + u[i] * tau)[:, None]
    d1 = curve(s, 1)
    return times, i, curve(s), d1 * s_dot, curve(s, 2) * s_dot**2 + d1 * u[i][:, None]


def _deviation_near(waypoints: np.ndarray, q: np.ndarray, segment: np.ndarray) -> float:
    """:func:`path_deviation` for points known to lie along waypoint segment ``segment``:
    the distance to it and its neighbours only (linear in the number of points)."""
    best = np.full(len(q), np.inf)
    for k in (np.maximum(segment - 1, 0), segment, np.minimum(segment + 1, len(waypoints) - 2)):
        start, seg = waypoints[k], waypoints[k + 1] - waypoints[k]
        t = np.einsum("ij,ij->i", q - start, seg) / np.maximum(np.einsum("ij,ij->i", seg, seg), 1e-300)
        offset = q - start - np.clip(t, 0.0, 1.0)[:, None] * seg
        best = np.minimum(best, np.einsum("ij,ij->i", offset, offset))
    return math.sqrt(float(np.max(best)))


def _raise_worst(excess: np.ndarray, message: Callable[[int, int], str]) -> None:
    """Raise PlanningError(message(row, joint)) for the largest positive ``excess``."""
    k, j = np.unravel_index(int(np.argmax(excess)), excess.shape)
    if excess[k, j] > 0:
        raise PlanningError(message(int(k), int(j)))


def _check_limits(names: tuple[str, ...], times: np.ndarray, values: np.ndarray,
                  limits: np.ndarray, what: str, unit: str, tolerance: float) -> None:
    _raise_worst(np.abs(values) / limits - (1.0 + tolerance), lambda k, j: (
        f"joint {names[j]!r} exceeds its {what} limit at t = {times[k]:.3f} s: "
        f"{abs(values[k, j]):.4g} {unit} > {limits[j]:.4g} {unit} (scaled limit)"))


class _InteriorPoints:
    """The coefficients of every interior limit check (see ``StageInteriorLimits`` in
    :func:`_toppra_kit`), computed for all checked fractions of every stage at once per
    path and grid and handed out per fraction (toppra asks each interior constraint in
    turn, with the same path and grid objects). Per thread: the constraints are shared by
    every caller."""

    def __init__(self, fractions: list[float], vmax: np.ndarray) -> None:
        self._fractions = list(fractions)
        self._v2 = np.asarray(vmax) ** 2
        self._local = threading.local()

    def params(self, path: Any, gridpoints: np.ndarray, fraction: float
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(a, b, c)`` of the check at ``fraction`` of each stage: there
        ``x = x_i + 2 tau u_i``, so the joint accelerations ``(q' + 2 tau q'') u_i + q'' x_i``
        and the velocity bound ``x_i + 2 tau u_i <= min_j v_j² / q'_j²`` are linear in the
        stage's (u, x)."""
        memo = getattr(self._local, "memo", None)
        if memo is None or memo[0] is not path or memo[1] is not gridpoints:
            step = np.append(np.diff(gridpoints), 0.0)[:, None]
            tau = np.concatenate([step * f for f in self._fractions])
            s = np.minimum(np.tile(gridpoints, len(self._fractions)) + tau[:, 0], gridpoints[-1])
            d1, d2 = path(s, 1), path(s, 2)
            x_max = np.min(self._v2 / np.maximum(d1**2, 1e-12), axis=1, keepdims=True)
            a = np.concatenate([d1 + 2 * tau * d2, 2 * tau], axis=1)
            b = np.concatenate([d2, np.ones_like(tau)], axis=1)
            c = np.concatenate([np.zeros_like(d1), -x_max], axis=1)
            n = len(gridpoints)
            memo = (path, gridpoints, {f: (a[k * n:(k + 1) * n], b[k * n:(k + 1) * n],
                                           c[k * n:(k + 1) * n])
                                       for k, f in enumerate(self._fractions)})
            self._local.memo = memo
        return memo[2][fraction]


def load_toppra() -> None:
    """Import toppra and build what the timing needs of it now, not at the first path
    timed: 0.3-0.5 s of CPU on a 2-core machine, most of it ``matplotlib.pyplot``, which
    toppra imports at module level for its debugging plots. A caller that will time
    paths does it ahead, in a thread, while it loads the rest."""
    _toppra_kit()


@functools.cache
def _toppra_kit() -> SimpleNamespace:
    """Import toppra on first use (see :func:`load_toppra`) and build what needs it."""
    logging.getLogger("toppra").setLevel(logging.WARNING)  # it logs every call at INFO
    import toppra
    import toppra.algorithm
    import toppra.constraint as tc
    from scipy.interpolate import PchipInterpolator
    from toppra.constraint.linear_constraint import LinearConstraint
    from toppra.interpolator import AbstractGeometricPath

    class Pchip(AbstractGeometricPath):  # type: ignore[misc]
        """Monotone piecewise cubic (C1): no overshoot between waypoints."""

        def __init__(self, ss: np.ndarray, points: np.ndarray) -> None:
            curve = PchipInterpolator(ss, points, axis=0)
            self._curves = (curve, curve.derivative(), curve.derivative(2))
            self._interval, self._dof = np.array([ss[0], ss[-1]]), points.shape[1]

        def __call__(self, s: Any, order: int = 0) -> np.ndarray:
            return np.asarray(self._curves[order](s))

        dof = property(lambda self: self._dof)
        path_interval = property(lambda self: self._interval)

    class StageInteriorLimits(LinearConstraint):  # type: ignore[misc]
        """Velocity and acceleration limits at ``s_i + fraction (s_i+1 - s_i)`` in each stage.

        There ``x = x_i + 2 tau u_i``: the joint accelerations ``(q' + 2 tau q'') u_i + q'' x_i``
        and the velocity bound ``x_i + 2 tau u_i <= min_j v_j² / q'_j²`` are linear in the
        stage's (u, x). One small constraint per fraction: toppra multiplies each one's
        coefficients by its F with numpy, and OpenBLAS threads large products, which on a
        loaded 2-core machine costs 10-50 ms (measured).
        """

        def __init__(self, vmax: np.ndarray, amax: np.ndarray, fraction: float,
                     shared: _InteriorPoints) -> None:
            super().__init__()
            n = len(vmax)
            self.dof, self.identical, self._fraction = n, True, fraction
            self._shared = shared
            eye, zero = np.eye(n), np.zeros((n, 1))  # rows: +accel, -accel, velocity
            self._f = np.block([[eye, zero], [-eye, zero], [zero.T, np.ones((1, 1))]])
            self._g = np.concatenate([amax, amax, [0.0]])

        def compute_constraint_params(self, path: Any, gridpoints: np.ndarray,
                                      *args: Any, **kwargs: Any) -> tuple[Any, ...]:
            a, b, c = self._shared.params(path, gridpoints, self._fraction)
            return a, b, c, self._f, self._g, None, None

    @functools.lru_cache(maxsize=32)
    def constraints(vmax: tuple[float, ...], amax: tuple[float, ...]) -> list[Any]:
        # Cached: toppra's constructors format the limits into strings (~0.5 ms a call).
        v, a = np.array(vmax), np.array(amax)
        collocation = tc.DiscretizationType.Collocation  # at s_i; the stage's inside is ours
        # The last check is just before s_i+1, where a C1 curve's q'' has its left limit.
        fractions = [*(np.arange(1, _CHECKS_PER_STAGE) / _CHECKS_PER_STAGE), 1.0 - 1e-9]
        shared = _InteriorPoints(fractions, v)
        return [tc.JointVelocityConstraint(np.stack([-v, v], axis=1)),
                tc.JointAccelerationConstraint(np.stack([-a, a], axis=1), collocation),
                *(StageInteriorLimits(v, a, f, shared) for f in fractions)]

    return SimpleNamespace(toppra=toppra, Pchip=Pchip, constraints=constraints)


def trajectory_json(trajectory: JointTrajectory) -> bytes:
    """``trajectory`` as one JSON object: ``{"times": [...], "positions": [[...], ...],
    "velocities": [[...], ...]}``, one row per sample.

    Raises:
        PlanningError: a value is not finite (JSON has no NaN; a timed trajectory
            never should).
    """
    from pydantic_core import to_json

    arrays = {"times": trajectory.times, "positions": trajectory.positions,
              "velocities": trajectory.velocities}
    for name, values in arrays.items():
        if not np.isfinite(values).all():
            raise PlanningError(f"the timed trajectory has non-finite {name}")
    return to_json({name: np.asarray(values, dtype=float).tolist()
                    for name, values in arrays.items()})
