"""Time parameterization: limits on every sample, endpoints, scaling, path following, errors."""

from __future__ import annotations

import dataclasses
import math
import subprocess
import sys

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import PlanningError, UnknownNameError
from taskrunner.planning import timing
from taskrunner.planning.timing import TimingOptions, parameterize_path, path_deviation
from taskrunner.resources import DATA_ROOT
from taskrunner.robot import Placement, RobotModel, build_model, load_description
from taskrunner.types import JointPath, JointTrajectory

SERVO_ARM = ("Revolute 1", "Revolute 2", "Revolute 3", "Revolute 4", "Revolute 5")


def _random_path(model: RobotModel, group: str, waypoints: int, seed: int,
                 step: float = 0.5) -> JointPath:
    """A walk of ``waypoints`` points inside the limits, ``step`` rad per segment at most."""
    rng = np.random.default_rng(seed)
    names = model.group(group).joint_names
    idx = model.indices(names)
    lower, upper = model.lower[idx], model.upper[idx]
    points = [rng.uniform(lower + 0.3 * (upper - lower), upper - 0.3 * (upper - lower))]
    for _ in range(waypoints - 1):
        direction = rng.normal(size=len(names))
        points.append(np.clip(points[-1] + step * direction / np.max(np.abs(direction)),
                              lower, upper))
    return JointPath(names, np.array(points))


def _limits(model: RobotModel, names: tuple[str, ...], v_scale: float, a_scale: float):
    idx = model.indices(names)
    return model.max_velocity[idx] * v_scale, model.max_acceleration[idx] * a_scale


def _assert_within(trajectory: JointTrajectory, vmax: np.ndarray, amax: np.ndarray,
                   tolerance: float = 0.01) -> None:
    assert np.all(np.abs(trajectory.velocities) <= vmax * (1 + tolerance))
    assert np.all(np.abs(trajectory.accelerations) <= amax * (1 + tolerance))


# ------------------------------------------------------------------ limits
@pytest.mark.parametrize(("waypoints", "seed"), [(4, 1), (7, 2), (10, 3)])
def test_panda_samples_respect_the_scaled_limits_and_reach_them(panda_model, waypoints, seed):
    path = _random_path(panda_model, "arm", waypoints, seed)
    trajectory = parameterize_path(panda_model, path)
    vmax, amax = _limits(panda_model, path.names, 0.5, 0.5)  # joint_limits.yaml defaults
    _assert_within(trajectory, vmax, amax)
    # Time-optimal: some joint runs at (nearly) a limit somewhere.
    assert max(np.max(np.abs(trajectory.velocities) / vmax),
               np.max(np.abs(trajectory.accelerations) / amax)) > 0.95


def test_servo_arm_moves_at_its_default_scaling_of_0_2(servo_arm_model):
    path = JointPath(SERVO_ARM, [[0.5, -0.5, -1.0, -1.0, -1.0], [1.5, -1.0, -0.5, -1.5, -0.5],
                                 [1.0, -1.5, -1.0, -1.0, -1.5]])
    trajectory = parameterize_path(servo_arm_model, path)
    vmax, amax = _limits(servo_arm_model, path.names, 0.2, 0.2)
    assert vmax == pytest.approx([0.6, 0.6, 0.6, 0.8, 0.8])  # 3.0 and 4.0 rad/s x 0.2
    _assert_within(trajectory, vmax, amax)
    assert np.max(np.abs(trajectory.velocities) / vmax) > 0.9


def test_halving_velocity_scaling_makes_the_motion_longer(panda_model):
    path = _random_path(panda_model, "arm", 5, seed=4)
    fast = parameterize_path(panda_model, path, TimingOptions(0.2, acceleration_scaling=1.0))
    slow = parameterize_path(panda_model, path, TimingOptions(0.1, acceleration_scaling=1.0))
    assert slow.duration > 1.6 * fast.duration
    vmax, amax = _limits(panda_model, path.names, 0.1, 1.0)
    _assert_within(slow, vmax, amax)
    assert np.max(np.abs(slow.velocities) / vmax) > 0.95


def test_scaling_velocity_by_k_and_acceleration_by_k_squared_stretches_time_by_1_over_k(
        panda_model):
    path = _random_path(panda_model, "arm", 5, seed=5)
    full = parameterize_path(panda_model, path, TimingOptions(1.0, 1.0))
    half = parameterize_path(panda_model, path, TimingOptions(0.5, 0.25))
    assert half.duration == pytest.approx(2 * full.duration, rel=0.01)


def test_a_path_over_two_robots_uses_the_smallest_default_scaling():
    model = build_model([
        Placement(load_description(DATA_ROOT / "robots" / "panda"), "left", "left_", pin.SE3.Identity()),
        Placement(load_description(DATA_ROOT / "robots" / "servo_arm"), "right", "right_",
                  pin.SE3(np.eye(3), np.array([1.0, 0.0, 0.0]))),
    ])
    names = ("left_panda_joint1", "right_Revolute 1")
    trajectory = parameterize_path(model, JointPath(names, [[0.0, 0.5], [1.0, 0.5]]))
    vmax, amax = _limits(model, names, 0.2, 0.2)  # servo arm 0.2 < Panda 0.5
    _assert_within(trajectory, vmax, amax)
    assert np.max(np.abs(trajectory.velocities[:, 0])) > 0.9 * vmax[0]


def test_a_joint_without_acceleration_limit_gets_twice_its_velocity_limit(ur5_model):
    path = _random_path(ur5_model, "manipulator", 4, seed=6)
    vmax, _ = _limits(ur5_model, path.names, 1.0, 1.0)
    assert not np.any(np.isfinite(ur5_model.max_acceleration))
    trajectory = parameterize_path(ur5_model, path)
    _assert_within(trajectory, vmax, 2.0 * vmax)
    constant = parameterize_path(ur5_model, path, TimingOptions(default_acceleration=1.0))
    _assert_within(constant, vmax, np.ones(len(vmax)))
    assert constant.duration > trajectory.duration


def test_a_joint_without_velocity_limit_is_refused_by_name(servo_arm_model):
    joints = tuple(dataclasses.replace(j, max_velocity=math.inf) if j.name == "Revolute 3" else j
                   for j in servo_arm_model.joints)
    model = dataclasses.replace(servo_arm_model, joints=joints)
    path = JointPath(SERVO_ARM, [[0.5, -0.5, -1.0, -1.0, -1.0], [1.0, -1.0, -0.5, -1.5, -0.5]])
    with pytest.raises(PlanningError, match="joint 'Revolute 3' has no velocity limit"):
        parameterize_path(model, path)


# ------------------------------------------------------------------ samples and geometry
def test_endpoints_are_exact_and_at_rest(panda_model):
    path = _random_path(panda_model, "arm", 6, seed=7)
    trajectory = parameterize_path(panda_model, path)
    assert trajectory.times[0] == 0.0
    assert np.array_equal(trajectory.positions[0], path.waypoints[0])
    assert np.array_equal(trajectory.positions[-1], path.waypoints[-1])
    assert np.all(trajectory.velocities[[0, -1]] == 0.0)
    assert np.all(np.isfinite(trajectory.accelerations))


def test_samples_are_at_the_sample_rate_with_the_last_one_at_the_end(panda_model):
    path = _random_path(panda_model, "arm", 4, seed=8)
    trajectory = parameterize_path(panda_model, path, TimingOptions(sample_rate_hz=250.0))
    steps = np.diff(trajectory.times)
    assert np.allclose(steps[:-1], 1 / 250.0)
    assert 0.0 < steps[-1] <= 1 / 250.0 + 1e-12
    assert trajectory.times[-1] == trajectory.duration > 0.5


def test_the_trajectory_stays_on_the_waypoint_polyline(panda_model):
    for seed in range(3):
        path = _random_path(panda_model, "arm", 8, seed=seed)
        assert path_deviation(path, parameterize_path(panda_model, path)) < 0.01


def test_a_two_waypoint_path_is_a_straight_line(panda_model):
    path = JointPath(panda_model.group("arm").joint_names,
                     [[0.0, 0.0, 0.0, -1.5, 0.0, 1.5, 0.0], [1.0, 0.5, -0.5, -2.0, 0.3, 2.0, 0.5]])
    trajectory = parameterize_path(panda_model, path)
    assert path_deviation(path, trajectory) < 1e-12
    vmax, amax = _limits(panda_model, path.names, 0.5, 0.5)
    _assert_within(trajectory, vmax, amax)


def test_a_corner_at_a_position_limit_stays_within_the_limit(servo_arm_model, monkeypatch):
    # Revolute 2 sits at 0 (its upper limit) through the corner: a cubic spline would
    # overshoot it by ~0.004 rad, so the monotone PCHIP curve is used instead.
    kit = timing._toppra_kit()
    made, pchip = [], kit.Pchip
    monkeypatch.setattr(kit, "Pchip", lambda *args: made.append(args) or pchip(*args))
    path = JointPath(SERVO_ARM, [[0.5, 0.0, -1.0, -1.0, -1.0], [1.5, 0.0, -1.0, -1.0, -1.0],
                                 [1.5, -1.0, -1.0, -1.0, -1.0]])
    trajectory = parameterize_path(servo_arm_model, path)
    upper = servo_arm_model.upper[servo_arm_model.indices(SERVO_ARM)]
    assert made
    assert np.all(trajectory.positions <= upper)
    assert path_deviation(path, trajectory) < 0.01


# ------------------------------------------------------------------ degenerate inputs
def test_a_single_waypoint_gives_one_sample_at_rest(panda_model):
    names = panda_model.group("arm").joint_names
    q = panda_model.named_state("arm_and_hand", "default").as_dict()
    path = JointPath(names, [[q[n] for n in names]])
    trajectory = parameterize_path(panda_model, path)
    assert trajectory.times.tolist() == [0.0] and trajectory.duration == 0.0
    assert np.array_equal(trajectory.positions, path.waypoints)
    assert not np.any(trajectory.velocities) and not np.any(trajectory.accelerations)


def test_equal_waypoints_give_one_sample_and_repeats_are_ignored(panda_model):
    path = _random_path(panda_model, "arm", 3, seed=9)
    same = JointPath(path.names, np.repeat(path.waypoints[:1], 4, axis=0))
    assert len(parameterize_path(panda_model, same).times) == 1
    repeated = JointPath(path.names, np.repeat(path.waypoints, 2, axis=0))
    once = parameterize_path(panda_model, path)
    twice = parameterize_path(panda_model, repeated)
    assert np.array_equal(once.times, twice.times)
    assert np.array_equal(once.positions, twice.positions)


def test_a_tiny_motion_is_timed(panda_model):
    names = panda_model.group("arm").joint_names
    start = np.array([0.0, 0.0, 0.0, -1.5, 0.0, 1.5, 0.0])
    trajectory = parameterize_path(panda_model, JointPath(names, [start, start + 1e-6]))
    assert 0.0 < trajectory.duration < 0.01
    assert np.array_equal(trajectory.positions[-1], start + 1e-6)


# ------------------------------------------------------------------ errors
def test_an_unknown_joint_raises_unknown_name_error(panda_model):
    with pytest.raises(UnknownNameError, match="panda_joint9"):
        parameterize_path(panda_model, JointPath(("panda_joint1", "panda_joint9"), [[0, 0], [1, 1]]))


def test_a_waypoint_outside_the_limits_is_refused(panda_model):
    path = JointPath(("panda_joint1", "panda_joint4"), [[0.0, -1.0], [0.5, 0.2]])
    with pytest.raises(PlanningError, match="waypoint 1 puts joint 'panda_joint4' at 0.2000"):
        parameterize_path(panda_model, path)


def test_a_path_without_waypoints_or_with_a_repeated_joint_is_a_value_error(panda_model):
    with pytest.raises(ValueError, match="'path' must have joints and finite waypoints"):
        parameterize_path(panda_model, JointPath(("panda_joint1",), np.zeros((0, 1))))
    with pytest.raises(ValueError, match="'path' must name each joint once"):
        parameterize_path(panda_model, JointPath(("panda_joint1", "panda_joint1"), [[0, 0]]))


def test_a_path_straying_more_than_max_deviation_is_refused(panda_model):
    path = _random_path(panda_model, "arm", 5, seed=10)
    with pytest.raises(PlanningError, match="strays"):
        parameterize_path(panda_model, path, TimingOptions(max_deviation_rad=1e-5))


def test_toppra_failure_is_a_planning_error(panda_model, monkeypatch):
    algorithm = timing._toppra_kit().toppra.algorithm.TOPPRA
    monkeypatch.setattr(algorithm, "compute_parameterization",
                        lambda self, *args, **kwargs: (None, None, None))
    with pytest.raises(PlanningError, match="toppra could not time the path"):
        parameterize_path(panda_model, _random_path(panda_model, "arm", 3, seed=11))


def test_a_sample_over_a_limit_is_refused_with_joint_and_time(panda_model, monkeypatch):
    real = timing._time_curve

    def too_fast(*args, **kwargs):
        times, q, qd, qdd = real(*args, **kwargs)
        qd[len(times) // 2, 2] = 5.0
        return times, q, qd, qdd

    monkeypatch.setattr(timing, "_time_curve", too_fast)
    path = _random_path(panda_model, "arm", 3, seed=12)
    with pytest.raises(PlanningError, match=r"joint 'panda_joint3' exceeds its velocity .* at t ="):
        parameterize_path(panda_model, path)


@pytest.mark.parametrize(
    ("field", "value", "message"),
    [
        ("velocity_scaling", 1.5, "'velocity_scaling' must be in (0, 1] (got 1.5)"),
        ("velocity_scaling", 0.0, "'velocity_scaling' must be in (0, 1] (got 0.0)"),
        ("acceleration_scaling", -0.5, "'acceleration_scaling' must be in (0, 1] (got -0.5)"),
        ("acceleration_scaling", True, "'acceleration_scaling' must be in (0, 1] (got True)"),
        ("sample_rate_hz", 0, "'sample_rate_hz' must be a positive number (got 0)"),
        ("sample_rate_hz", math.inf, "'sample_rate_hz' must be a positive number (got inf)"),
        ("densify_step_rad", -0.1, "'densify_step_rad' must be a positive number (got -0.1)"),
        ("default_acceleration", 0.0, "'default_acceleration' must be a positive number"),
        ("limit_tolerance", -0.01, "'limit_tolerance' must be a number >= 0 (got -0.01)"),
        ("max_deviation_rad", "big", "'max_deviation_rad' must be a positive number (got 'big')"),
    ],
)
def test_bad_options_raise_value_errors(field, value, message):
    with pytest.raises(ValueError) as error:
        TimingOptions(**{field: value})
    assert str(error.value).startswith(message)


# ------------------------------------------------------------------ API
def test_path_deviation_measures_the_distance_to_the_nearest_segment():
    path = JointPath(("a", "b"), [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])
    positions = np.array([[0.0, 0.0], [0.5, 0.1], [1.2, 0.5], [1.0, 1.0]])
    trajectory = JointTrajectory(("a", "b"), [0.0, 1.0, 2.0, 3.0], positions,
                                 np.zeros((4, 2)), np.zeros((4, 2)))
    assert path_deviation(path, trajectory) == pytest.approx(0.2)
    with pytest.raises(ValueError, match="'trajectory' must have the path's joints"):
        path_deviation(JointPath(("b", "a"), path.waypoints), trajectory)


def test_importing_the_module_does_not_import_toppra():
    code = "import sys, taskrunner.planning.timing; assert 'toppra' not in sys.modules"
    subprocess.run([sys.executable, "-c", code], check=True)


def test_a_short_straight_path_of_many_waypoints_is_timed(panda_model):
    """Regression: merging straight intervals once left such a path a single toppra stage,
    which cannot go rest to rest ("toppra stopped inside the path")."""
    start = np.array([0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785])
    delta = np.array([0.05, 0.06, 0.02, 0.08, 0.01, 0.03, 0.0])
    names = panda_model.group("arm").joint_names
    for count in (10, 21, 41):
        path = JointPath(names, start + np.linspace(0.0, 1.0, count)[:, None] * delta)
        trajectory = parameterize_path(panda_model, path)
        assert trajectory.positions[-1] == pytest.approx(path.waypoints[-1])
        assert 0.1 < trajectory.duration < 1.0


def test_trajectory_json_is_exact_and_refuses_non_finite_values():
    import json

    from taskrunner.types import JointTrajectory

    times = np.array([0.0, 0.1, 0.2])
    rows = np.array([[0.1, -1e-7], [1 / 3, 2.5], [0.7, 1e300]])
    traj = JointTrajectory(("a", "b"), times, rows, rows * 2, np.zeros_like(rows))
    decoded = json.loads(timing.trajectory_json(traj))
    assert list(decoded) == ["times", "positions", "velocities"]
    assert decoded["times"] == times.tolist() and decoded["positions"] == rows.tolist()
    bad = JointTrajectory(("a", "b"), times, rows, rows * np.nan, np.zeros_like(rows))
    with pytest.raises(PlanningError, match="non-finite velocities"):
        timing.trajectory_json(bad)


# ------------------------------------------------------------------ short motions
# Regression: this 0.07 rad Panda move once gave a toppra grid ending one float step past
# the path's end ("Invalid manually supplied gridpoints", a raw ValueError).
_GRID_PAST_THE_END = (
    [0.6605690515989162, -0.8771198328386813, -1.719534844242001, -0.7946537706799608,
     -0.5078457760317465, 2.534682025332808, -0.25804133327866374],
    [0.7022318647988337, -0.9449850878947278, -1.772486651735211, -0.8354888484307719,
     -0.48869198887938464, 2.5410778867174195, -0.24757713298894984])


def test_a_short_move_whose_grid_could_end_past_the_path_is_timed(panda_model):
    names = panda_model.group("arm").joint_names
    trajectory = parameterize_path(panda_model, JointPath(names, np.array(_GRID_PAST_THE_END)))
    assert np.allclose(trajectory.positions[-1], _GRID_PAST_THE_END[1], atol=0, rtol=0)


def test_a_toppra_value_error_is_a_planning_error_naming_toppra(panda_model, monkeypatch):
    kit = timing._toppra_kit()

    class Refusing:
        def __init__(self, *args, **kwargs):
            raise ValueError("Invalid manually supplied gridpoints.")

    monkeypatch.setattr(kit.toppra.algorithm, "TOPPRA", Refusing)
    path = _random_path(panda_model, "arm", 3, seed=5)
    with pytest.raises(PlanningError, match="toppra could not time the path .*ValueError: "
                                            "Invalid manually supplied gridpoints"):
        parameterize_path(panda_model, path)


@pytest.mark.parametrize("robot", ["servo_arm", "panda"])
def test_random_short_motions_are_always_timed(robot, request):
    """Property: any straight move of 0.001-0.2 rad well inside the limits is timed, ends
    exactly on its goal and respects the scaled limits (seeded, 400 cases per robot)."""
    from hypothesis import HealthCheck, given, settings
    from hypothesis import strategies as st

    model = request.getfixturevalue(f"{robot}_model")
    names = model.group("arm").joint_names
    idx = model.indices(names)
    lower, upper = model.lower[idx], model.upper[idx]
    vmax, amax = _limits(model, names, model.instances[0].velocity_scaling,
                         model.instances[0].acceleration_scaling)
    unit = st.floats(0.0, 1.0, allow_nan=False)

    @settings(max_examples=400, derandomize=True, deadline=None, database=None,
              suppress_health_check=list(HealthCheck))
    @given(start=st.lists(unit, min_size=len(names), max_size=len(names)),
           direction=st.lists(st.floats(-1.0, 1.0), min_size=len(names), max_size=len(names)),
           length=st.floats(0.001, 0.2))
    def short_move_is_timed(start, direction, length):
        d = np.array(direction)
        if np.max(np.abs(d)) < 1e-3:
            d[0] = 1.0
        a = lower + (0.2 + 0.6 * np.array(start)) * (upper - lower)
        b = a + length * d / np.max(np.abs(d))
        trajectory = parameterize_path(model, JointPath(names, np.vstack([a, b])))
        assert np.array_equal(trajectory.positions[-1], b)
        _assert_within(trajectory, vmax, amax)

    short_move_is_timed()
