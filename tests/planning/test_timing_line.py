"""Two-waypoint paths are timed in closed form: exact on the line, within the limits, and
as fast as toppra's timing of the same line (which it replaces)."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.planning import timing
from taskrunner.planning.timing import TimingOptions, parameterize_path, path_deviation
from taskrunner.types import JointPath


def _limits(model, names, options: TimingOptions):
    idx = model.indices(names)
    scale_v = model.instances[0].velocity_scaling
    scale_a = model.instances[0].acceleration_scaling
    return model.max_velocity[idx] * scale_v, model.max_acceleration[idx] * scale_a


@pytest.mark.parametrize("robot", ["servo_arm", "panda"])
@pytest.mark.parametrize("seed", range(6))
def test_a_line_is_timed_exactly_and_as_fast_as_toppra_times_it(robot, seed, request,
                                                                 monkeypatch):
    model = request.getfixturevalue(f"{robot}_model")
    names = model.group("arm").joint_names
    idx = model.indices(names)
    lower, upper = model.lower[idx], model.upper[idx]
    rng = np.random.default_rng(seed)
    # Long moves reach full speed, short ones (the last seeds) only accelerate and stop.
    span = (0.6, 0.02, 0.6, 0.3, 0.005, 0.05)[seed]
    a = rng.uniform(lower + 0.3 * (upper - lower), upper - 0.3 * (upper - lower))
    b = np.clip(a + span * (upper - lower) * rng.uniform(-1, 1, len(names)), lower, upper)
    options = TimingOptions()
    curves: list[int] = []
    real = timing._time_curve
    monkeypatch.setattr(timing, "_time_curve", lambda *args: curves.append(1) or real(*args))
    line = parameterize_path(model, JointPath(names, np.vstack([a, b])), options)
    assert not curves  # no spline, no toppra
    # The same line with a midpoint goes through toppra (a spline over the densified line).
    reference = parameterize_path(model, JointPath(names, np.vstack([a, (a + b) / 2, b])),
                                  options)
    assert curves
    assert np.array_equal(line.positions[0], a) and np.array_equal(line.positions[-1], b)
    assert np.all(line.velocities[[0, -1]] == 0.0)
    assert path_deviation(JointPath(names, np.vstack([a, b])), line) < 1e-12
    vmax, amax = _limits(model, names, options)
    # Within the scaled limits over toppra's margin (1 + limit_tolerance / 2), reaching them.
    aim = 1.0 + options.limit_tolerance / 2
    assert np.all(np.abs(line.velocities) <= vmax / aim * (1 + 1e-12))
    assert np.all(np.abs(line.accelerations) <= amax / aim * (1 + 1e-12))
    assert np.max(np.abs(line.accelerations) * aim / amax) == pytest.approx(1.0)
    # Time-optimal: never slower than toppra's discretized optimum, and close to it.
    assert line.duration <= reference.duration * (1 + 1e-9)
    assert line.duration >= 0.98 * reference.duration
    # Samples at the rate, the last one at the end.
    steps = np.diff(line.times)
    assert np.allclose(steps[:-1], 1 / options.sample_rate_hz)
    assert 0.0 < steps[-1] <= 1 / options.sample_rate_hz + 1e-12
    # Positions and velocities agree: the mean velocity over a period is the mean of its
    # ends, exactly where the acceleration is constant, within a_max dt / 4 where it changes.
    mean = np.diff(line.positions, axis=0) / steps[:, None]
    ends = 0.5 * (line.velocities[:-1] + line.velocities[1:])
    assert np.allclose(mean, ends, rtol=0, atol=np.max(amax) * np.max(steps) / 4 + 1e-12)
    assert np.all(np.abs(mean - ends) < 1e-9, axis=1).mean() > 0.9


def test_a_line_over_a_limit_is_refused_by_the_sample_check(servo_arm_model, monkeypatch):
    names = servo_arm_model.group("arm").joint_names
    real = timing._time_line

    def too_fast(*args, **kwargs):
        times, q, qd, qdd = real(*args, **kwargs)
        qdd[len(times) // 2, 1] = 50.0
        return times, q, qd, qdd

    monkeypatch.setattr(timing, "_time_line", too_fast)
    path = JointPath(names, [[0.5, -0.5, -1.0, -1.0, -1.0], [1.5, -1.0, -0.5, -1.5, -0.5]])
    with pytest.raises(timing.PlanningError, match="exceeds its acceleration limit"):
        parameterize_path(servo_arm_model, path)
