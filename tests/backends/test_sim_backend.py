"""SimBackend: a controller thread plays trajectories in scaled real time.

Runs at 20x so that a 2 s trajectory takes 0.1 s.
"""

from __future__ import annotations

import time

import numpy as np
import pytest

from taskrunner.backends import SimBackend, SimOptions, sample_positions
from taskrunner.errors import BackendError, ExecutionCancelledError
from taskrunner.types import JointTrajectory

JOINTS = ("j1", "j2", "j3")
FAST = SimOptions(speed=20.0, rate_hz=200.0)


def _sine(duration: float = 2.0, rate_hz: float = 100.0) -> JointTrajectory:
    """j1 = sin(t), j2 = 1 - cos(t), sampled every 1 / rate_hz s."""
    t = np.linspace(0.0, duration, round(duration * rate_hz) + 1)
    q = np.c_[np.sin(t), 1.0 - np.cos(t)]
    qd = np.c_[np.cos(t), np.sin(t)]
    qdd = np.c_[-np.sin(t), np.cos(t)]
    return JointTrajectory(("j1", "j2"), t, q, qd, qdd)


def _wait_for(predicate, timeout: float = 2.0) -> None:
    deadline = time.monotonic() + timeout
    while not predicate():
        assert time.monotonic() < deadline, "condition not met in time"
        time.sleep(0.002)


def test_sim_plays_the_trajectory_and_ends_on_its_last_sample():
    trajectory = _sine()
    with SimBackend(JOINTS, {"j3": 0.5}, FAST) as backend:
        handle = backend.execute(trajectory)
        assert handle.status == "running"
        result = handle.wait(timeout=2.0)
        assert result.status == "succeeded" and handle.progress == pytest.approx(2.0)
        np.testing.assert_array_equal(result.final.positions, trajectory.positions[-1])
        state = backend.joint_state()
        np.testing.assert_array_equal(state.positions, [*trajectory.positions[-1], 0.5])
        assert 0.09 <= result.duration < 1.0  # 2 s at 20x


def test_sim_history_follows_the_trajectory_at_the_controller_rate():
    trajectory = _sine()
    with SimBackend(JOINTS, options=FAST) as backend:
        handle = backend.execute(trajectory)
        handle.wait(timeout=2.0)
        history = backend.history()
    times = np.array([t for t, _ in history])
    positions = np.array([s.positions for _, s in history])
    assert len(history) >= 3 and all(s.names == JOINTS for _, s in history)
    # The controller ticks on a 200 Hz grid of its clock, a late tick catching up or
    # resyncing; how late the host wakes its thread is the host's (a median of 8 ms with
    # 4 spinning processes beside the test), so what is checked is that it never ticks
    # faster than its rate: n ticks span at least n - 1 periods.
    assert times[-1] - times[0] >= (len(times) - 1) / 200 - 1e-9
    elapsed = np.clip((times - handle.start_time) * 20.0, 0.0, 2.0)
    # exactly the linear interpolation of the samples at the tick's time ...
    expected = np.array([sample_positions(trajectory, t) for t in elapsed])
    np.testing.assert_allclose(positions[:, :2], expected, atol=1e-12)
    # ... which is within the interpolation error (dt² / 8 · max|q''|) of the curve
    np.testing.assert_allclose(positions[:, :2], np.c_[np.sin(elapsed), 1 - np.cos(elapsed)],
                               atol=0.01**2 / 8 + 1e-12)
    assert np.all(positions[:, 2] == 0.0)
    np.testing.assert_array_equal(positions[-1, :2], trajectory.positions[-1])


def test_sim_cancel_mid_motion_stops_where_it_is(ramp):
    trajectory = ramp(["j1", "j2"], [0.0, 0.0], [1.0, -2.0], duration=4.0)
    with SimBackend(JOINTS, options=FAST) as backend:
        handle = backend.execute(trajectory)
        _wait_for(lambda: handle.progress > 0.5)
        handle.cancel()
        assert handle.status == "cancelled" and handle.done()
        held = backend.joint_state().positions
        ticks = len(backend.history())
        time.sleep(0.03)
        np.testing.assert_array_equal(backend.joint_state().positions, held)
        assert len(backend.history()) == ticks  # the controller went idle
        assert 0.5 < handle.progress < trajectory.duration
        # on the trajectory, between its start and end, where the progress says
        np.testing.assert_allclose(held[:2], sample_positions(trajectory, handle.progress))
        assert 0.0 < held[0] < 1.0 and -2.0 < held[1] < 0.0
        with pytest.raises(ExecutionCancelledError, match="cancelled at"):
            handle.wait(timeout=1.0)
        np.testing.assert_array_equal(handle.result.final.positions, held[:2])
        # the joints are free: a trajectory from where they stopped is accepted
        back = ramp(["j1", "j2"], held[:2], [0.0, 0.0], duration=0.5)
        assert backend.execute(back).wait(timeout=2.0).status == "succeeded"


def test_sim_stop_cancels_every_motion(ramp):
    with SimBackend(JOINTS, options=FAST) as backend:
        first = backend.execute(ramp(["j1"], [0.0], [1.0], duration=4.0))
        second = backend.execute(ramp(["j2", "j3"], [0.0, 0.0], [1.0, 1.0], duration=4.0))
        _wait_for(lambda: first.progress > 0.2)
        backend.stop()
        assert first.status == second.status == "cancelled"
        for handle in (first, second):
            with pytest.raises(ExecutionCancelledError, match="stop"):
                handle.wait(timeout=1.0)
        held = backend.joint_state().positions
        time.sleep(0.02)
        np.testing.assert_array_equal(backend.joint_state().positions, held)


def test_sim_wait_times_out_and_the_motion_goes_on(ramp):
    with SimBackend(JOINTS, options=FAST) as backend:
        handle = backend.execute(ramp(["j1"], [0.0], [1.0], duration=2.0))
        with pytest.raises(TimeoutError, match="still running after 0.01 s"):
            handle.wait(timeout=0.01)
        assert handle.status == "running"
        assert handle.wait(timeout=2.0).status == "succeeded"


def test_sim_close_cancels_motions_and_stops_the_thread(ramp):
    backend = SimBackend(JOINTS, options=FAST)
    assert backend.running
    handle = backend.execute(ramp(["j1"], [0.0], [1.0], duration=4.0))
    backend.close()
    assert not backend.running and backend.closed
    assert handle.status == "cancelled"
    with pytest.raises(BackendError, match="closed"):
        backend.execute(ramp(["j1"], [0.0], [1.0]))
    backend.close()  # idempotent


def test_sim_keeps_no_history_when_asked_and_bounds_it_otherwise(ramp):
    trajectory = ramp(["j1"], [0.0], [1.0], duration=1.0)
    with SimBackend(JOINTS, options=SimOptions(speed=20.0, keep_history=False)) as backend:
        backend.execute(trajectory).wait(timeout=2.0)
        assert backend.history() == []
    with SimBackend(JOINTS, options=SimOptions(speed=20.0, rate_hz=400.0,
                                               history_limit=5)) as backend:
        backend.execute(trajectory).wait(timeout=2.0)
        history = backend.history()
        assert len(history) == 5 and history[-1][1].positions[0] == 1.0
        backend.clear_history()
        assert backend.history() == []


def test_sim_controller_failure_fails_the_motions_and_closes_the_backend(ramp, monkeypatch):
    with SimBackend(JOINTS, options=FAST) as backend:
        def broken_tick(now):
            raise RuntimeError("encoder lost")

        monkeypatch.setattr(backend, "_tick", broken_tick)
        handle = backend.execute(ramp(["j1"], [0.0], [1.0], duration=1.0))
        with pytest.raises(BackendError, match="encoder lost"):
            handle.wait(timeout=2.0)
        assert handle.status == "failed"
        _wait_for(lambda: not backend.running)
        with pytest.raises(BackendError, match="controller thread died"):
            backend.execute(ramp(["j1"], [0.0], [1.0]))
