"""MockBackend: jumps to a trajectory's end, or replays it in scaled time on its clock."""

from __future__ import annotations

import time

import numpy as np
import pytest

from taskrunner.backends import MockBackend, MockOptions, sample_positions
from taskrunner.errors import BackendError, ExecutionCancelledError
from taskrunner.types import JointTrajectory

JOINTS = ("j1", "j2", "j3")


def test_mock_jumps_to_the_end_and_is_done_at_once(ramp):
    backend = MockBackend(JOINTS, {"j3": 0.7})
    trajectory = ramp(["j1", "j2"], [0.0, 0.0], [1.0, -0.5], duration=3.0)
    handle = backend.execute(trajectory)
    assert handle.done() and handle.status == "succeeded"
    assert handle.progress == pytest.approx(3.0)
    np.testing.assert_array_equal(backend.joint_state().positions, [1.0, -0.5, 0.7])
    result = handle.wait(timeout=0.0)
    assert result is handle.result
    assert result.status == "succeeded" and result.final.as_dict() == {"j1": 1.0, "j2": -0.5}
    assert result.duration < 0.1


def test_mock_with_speed_replays_and_reports_intermediate_states(ramp, clock):
    backend = MockBackend(JOINTS, {"j2": 1.0}, MockOptions(speed=10.0), clock=clock)
    trajectory = ramp(["j1", "j2"], [0.0, 1.0], [2.0, -1.0], duration=2.0)
    handle = backend.execute(trajectory)
    assert not handle.done() and handle.status == "running" and handle.result is None
    seen = []
    for _ in range(4):
        clock.advance(0.05)  # 0.5 s of trajectory at 10x
        seen.append(backend.joint_state().positions[:2])
    np.testing.assert_allclose(seen[:3], [sample_positions(trajectory, t) for t in (0.5, 1.0, 1.5)],
                               atol=1e-9)
    assert handle.done() and handle.status == "succeeded"
    np.testing.assert_allclose(seen[3], [2.0, -1.0])
    assert handle.wait().duration == pytest.approx(0.2)


def test_mock_replay_is_the_same_every_time(ramp, clock):
    def replay():
        backend = MockBackend(JOINTS, options=MockOptions(speed=3.0), clock=clock)
        handle = backend.execute(ramp(["j1"], [0.0], [1.0], duration=1.5))
        states = []
        while not handle.done():
            clock.advance(0.01)
            states.append((handle.progress, backend.joint_state().positions[0]))
        return states

    assert replay() == replay()


def test_mock_with_speed_wait_blocks_for_the_scaled_duration(ramp):
    backend = MockBackend(JOINTS, options=MockOptions(speed=20.0))
    handle = backend.execute(ramp(["j1"], [0.0], [1.0], duration=1.0))
    start = time.monotonic()
    result = handle.wait(timeout=2.0)
    assert 0.045 <= time.monotonic() - start < 0.5
    assert result.status == "succeeded" and result.final.as_dict() == {"j1": 1.0}


def test_mock_wait_times_out_while_the_replay_runs(ramp, clock):
    backend = MockBackend(JOINTS, options=MockOptions(speed=1.0), clock=clock)
    handle = backend.execute(ramp(["j1"], [0.0], [1.0], duration=1.0))
    clock.advance(0.25)
    with pytest.raises(TimeoutError, match="0.250 s of 1.000 s"):
        handle.wait(timeout=0.01)
    assert handle.status == "running"
    clock.advance(1.0)
    assert handle.wait(timeout=0.01).status == "succeeded"


def test_fail_after_makes_wait_raise_backend_error_where_the_joints_stopped(ramp):
    backend = MockBackend(JOINTS, options=MockOptions(fail_after=0.4))
    trajectory = ramp(["j1"], [0.0], [1.0], duration=1.0)
    handle = backend.execute(trajectory)
    assert handle.done() and handle.status == "failed"
    with pytest.raises(BackendError, match="after 0.400 s") as info:
        handle.wait()
    assert not isinstance(info.value, ExecutionCancelledError)
    assert handle.result.status == "failed" and handle.progress == pytest.approx(0.4)
    assert backend.joint_state().positions[0] == pytest.approx(0.4)
    # the joint is free again, and a trajectory shorter than fail_after succeeds
    assert backend.execute(ramp(["j1"], [0.4], [0.5], duration=0.3)).status == "succeeded"


def test_fail_after_with_speed_runs_first_then_fails(ramp, clock):
    backend = MockBackend(JOINTS, options=MockOptions(speed=2.0, fail_after=1.0), clock=clock)
    handle = backend.execute(ramp(["j1"], [0.0], [2.0], duration=2.0))
    clock.advance(0.25)
    assert handle.status == "running" and handle.progress == pytest.approx(0.5)
    clock.advance(0.5)
    assert handle.status == "failed" and handle.progress == pytest.approx(1.0)
    assert isinstance(handle.error, BackendError)
    assert backend.joint_state().positions[0] == pytest.approx(1.0)


def test_cancel_holds_the_replay_where_it_is(ramp, clock):
    backend = MockBackend(JOINTS, options=MockOptions(speed=1.0), clock=clock)
    handle = backend.execute(ramp(["j1"], [0.0], [1.0], duration=1.0))
    clock.advance(0.3)
    handle.cancel()
    clock.advance(1.0)
    assert handle.status == "cancelled" and handle.progress == pytest.approx(0.3)
    assert backend.joint_state().positions[0] == pytest.approx(0.3)
    with pytest.raises(ExecutionCancelledError, match="cancelled at 0.300 s"):
        handle.wait()
    handle.cancel()  # no-op once finished
    assert handle.status == "cancelled"


def test_stop_cancels_every_replay(ramp, clock):
    backend = MockBackend(JOINTS, options=MockOptions(speed=1.0), clock=clock)
    first = backend.execute(ramp(["j1"], [0.0], [1.0], duration=1.0))
    second = backend.execute(ramp(["j2", "j3"], [0.0, 0.0], [1.0, 2.0], duration=2.0))
    clock.advance(0.5)
    backend.stop()
    assert first.status == second.status == "cancelled"
    np.testing.assert_allclose(backend.joint_state().positions, [0.5, 0.25, 0.5])
    for handle in (first, second):
        with pytest.raises(ExecutionCancelledError, match="stop"):
            handle.wait(timeout=0.0)


def test_trajectory_time_counts_from_the_first_sample(clock):
    trajectory = JointTrajectory(("j1",), [5.0, 6.0], [[0.0], [1.0]], [[1.0], [1.0]],
                                 [[0.0], [0.0]])
    backend = MockBackend(JOINTS, options=MockOptions(speed=1.0), clock=clock)
    handle = backend.execute(trajectory)
    clock.advance(0.5)
    assert handle.progress == pytest.approx(0.5)
    assert backend.joint_state().positions[0] == pytest.approx(0.5)
    clock.advance(0.5)
    assert handle.status == "succeeded"
