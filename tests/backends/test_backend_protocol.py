"""What every backend does the same way: checks before anything moves, joint bookkeeping,
the handle protocol."""

from __future__ import annotations

import math

import numpy as np
import pytest

from taskrunner import backends
from taskrunner.backends import (
    Backend,
    ExecutionHandle,
    MockBackend,
    MockOptions,
    SimBackend,
    SimOptions,
    sample_positions,
)
from taskrunner.errors import (
    BackendBusyError,
    BackendError,
    TrajectoryRejectedError,
    UnknownNameError,
)
from taskrunner.types import JointState, JointTrajectory

JOINTS = ("j1", "j2", "j3", "j4")


def _mock(initial=None, **options):
    return MockBackend(JOINTS, initial, MockOptions(**options))


def _sim(initial=None, **options):
    return SimBackend(JOINTS, initial, SimOptions(speed=20.0, **options))


@pytest.fixture(params=["mock", "sim"])
def make_backend(request):
    """``make_backend(initial=None, **options)`` for each backend; closed after the test."""
    made = []

    def make(initial=None, **options):
        backend = (_mock if request.param == "mock" else _sim)(initial, **options)
        made.append(backend)
        return backend

    make.kind = request.param
    yield make
    for backend in made:
        backend.close()


def test_public_names_are_pinned():
    assert sorted(backends.__all__) == sorted([
        "Backend", "BaseBackend", "ExecutionHandle", "ExecutionResult", "ExecutionStatus",
        "MockBackend", "MockOptions", "SimBackend", "SimOptions", "TrajectoryExecution",
        "check_trajectory", "sample_positions",
        "HttpBackend", "SerialBackend", "ServoBackend", "ServoCalibration", "ServoOptions",
        "load_calibration",
    ])


def test_backends_and_handles_satisfy_the_protocols(make_backend, ramp):
    backend = make_backend()
    assert isinstance(backend, Backend)
    handle = backend.execute(ramp(["j1"], [0.0], [0.1], duration=0.1))
    assert isinstance(handle, ExecutionHandle)
    assert handle.wait(timeout=2.0).status == "succeeded"


def test_joint_state_starts_at_the_initial_positions_or_zero(make_backend):
    backend = make_backend({"j2": 0.5, "j4": -1.0})
    state = backend.joint_state()
    assert state.names == JOINTS
    np.testing.assert_array_equal(state.positions, [0.0, 0.5, 0.0, -1.0])
    other = make_backend(JointState(("j1",), [0.25]))
    np.testing.assert_array_equal(other.joint_state().positions, [0.25, 0.0, 0.0, 0.0])


def test_initial_position_of_an_unknown_joint_is_refused():
    with pytest.raises(UnknownNameError, match="'elbow'"):
        MockBackend(JOINTS, {"elbow": 1.0})
    with pytest.raises(ValueError, match="joint_names"):
        MockBackend(["a", "a"])
    with pytest.raises(ValueError, match="joint_names"):
        MockBackend([])


def test_trajectory_from_a_stale_start_is_refused_naming_joint_and_positions(make_backend, ramp):
    backend = make_backend({"j2": 0.3})
    with pytest.raises(TrajectoryRejectedError) as info:
        backend.execute(ramp(["j1", "j2"], [0.0, 0.0], [1.0, 1.0]))
    message = str(info.value)
    assert "'j2'" in message and "0.3000" in message and "0.0000" in message
    assert "stale" in message
    np.testing.assert_array_equal(backend.joint_state().positions, [0.0, 0.3, 0.0, 0.0])


def test_start_within_the_tolerance_is_accepted(make_backend, ramp):
    backend = make_backend({"j1": 0.0005})
    assert backend.execute(ramp(["j1"], [0.0], [0.1], 0.1)).wait(2.0).status == "succeeded"
    loose = make_backend({"j1": 0.5}, start_tolerance=math.inf)
    assert loose.execute(ramp(["j1"], [0.0], [0.1], 0.1)).wait(2.0).status == "succeeded"


def test_unknown_joint_is_refused_by_name(make_backend, ramp):
    backend = make_backend()
    with pytest.raises(TrajectoryRejectedError, match="'elbow'.*'j1'"):
        backend.execute(ramp(["j1", "elbow"], [0.0, 0.0], [1.0, 1.0]))


def test_non_finite_value_is_refused_naming_joint_and_time(make_backend, ramp):
    backend = make_backend()
    good = ramp(["j1", "j2"], [0.0, 0.0], [1.0, 1.0])
    for attr in ("positions", "velocities", "accelerations"):
        values = np.array(getattr(good, attr))
        values[30, 1] = np.nan
        bad = JointTrajectory(**{**vars(good), attr: values})
        with pytest.raises(TrajectoryRejectedError, match=r"'j2' at t = 0\.300 s"):
            backend.execute(bad)


def test_empty_or_repeated_trajectory_is_refused(make_backend):
    backend = make_backend()
    empty = JointTrajectory(("j1",), np.zeros(0), np.zeros((0, 1)), np.zeros((0, 1)),
                            np.zeros((0, 1)))
    with pytest.raises(TrajectoryRejectedError, match="samples"):
        backend.execute(empty)
    twice = JointTrajectory(("j1", "j1"), [0.0], [[0.0, 0.0]], [[0.0, 0.0]], [[0.0, 0.0]])
    with pytest.raises(TrajectoryRejectedError, match="'j1' more than once"):
        backend.execute(twice)


def test_busy_joint_is_refused_but_disjoint_joints_run_in_parallel(make_backend, ramp, clock):
    # The mock replays at real speed on a fake clock; the sim runs 20x on the real one.
    backend = (MockBackend(JOINTS, options=MockOptions(speed=1.0), clock=clock)
               if make_backend.kind == "mock" else make_backend())
    left = backend.execute(ramp(["j1", "j2"], [0.0, 0.0], [1.0, 1.0], duration=4.0))
    with pytest.raises(BackendBusyError, match="'j2' is already moving"):
        backend.execute(ramp(["j2", "j3"], [0.0, 0.0], [1.0, 1.0]))
    right = backend.execute(ramp(["j3", "j4"], [0.0, 0.0], [-1.0, -1.0], duration=1.0))
    assert left.status == "running" and right.status == "running"
    clock.advance(1.0)
    assert right.wait(timeout=2.0).status == "succeeded"
    assert left.status == "running"
    clock.advance(3.0)
    assert left.wait(timeout=2.0).status == "succeeded"
    np.testing.assert_allclose(backend.joint_state().positions, [1.0, 1.0, -1.0, -1.0])
    backend.close()


def test_joints_are_free_again_after_a_trajectory_ends(make_backend, ramp):
    backend = make_backend()
    backend.execute(ramp(["j1"], [0.0], [0.2], 0.1)).wait(2.0)
    handle = backend.execute(ramp(["j1"], [0.2], [0.0], 0.1))
    assert handle.wait(2.0).final.as_dict() == {"j1": 0.0}


def test_closed_backend_refuses_trajectories(make_backend, ramp):
    backend = make_backend()
    with backend:
        pass
    assert backend.closed
    with pytest.raises(BackendError, match="closed"):
        backend.execute(ramp(["j1"], [0.0], [1.0]))
    backend.close()  # idempotent


def test_single_sample_trajectory_succeeds_without_motion(make_backend):
    backend = make_backend({"j1": 0.5})
    hold = JointTrajectory(("j1",), [0.0], [[0.5]], [[0.0]], [[0.0]])
    result = backend.execute(hold).wait(timeout=2.0)
    assert result.status == "succeeded" and result.final.as_dict() == {"j1": 0.5}


@pytest.mark.parametrize("options, field", [
    (lambda: MockOptions(speed=0.0), "speed"),
    (lambda: MockOptions(fail_after=-1.0), "fail_after"),
    (lambda: MockOptions(start_tolerance=math.nan), "start_tolerance"),
    (lambda: SimOptions(speed=-1.0), "speed"),
    (lambda: SimOptions(rate_hz=0.0), "rate_hz"),
    (lambda: SimOptions(history_limit=0), "history_limit"),
])
def test_invalid_options_are_refused_by_field(options, field):
    with pytest.raises(ValueError, match=f"'{field}' must be"):
        options()


def test_sample_positions_interpolates_linearly_and_holds_the_ends(ramp):
    trajectory = ramp(["a", "b"], [0.0, 1.0], [1.0, 3.0], duration=1.0, rate_hz=4.0)
    np.testing.assert_allclose(sample_positions(trajectory, 0.3), [0.3, 1.6])
    np.testing.assert_allclose(sample_positions(trajectory, -1.0), [0.0, 1.0])
    np.testing.assert_allclose(sample_positions(trajectory, 5.0), [1.0, 3.0])
