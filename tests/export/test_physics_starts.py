"""Where a motion starts on the physics clock (taskrunner.export.physics): the start the
physics report lists, read as is; a record without that list fits the start of a motion
sent while another only settled, and says it did."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.errors import InputError
from taskrunner.export.physics import SentMotion, physics_path
from taskrunner.runtime.events import RunEvent

PERIOD = 0.04


def _scene(b_start: float) -> tuple[list[SentMotion], np.ndarray, np.ndarray]:
    """Joint a moves 0 → 1 rad in 1 s from physics 0 and settles 0.3 s; joint b, sent at
    task time 1.0 (a settling, task time standing still), moves 0 → 0.5 rad in 0.8 s
    from physics ``b_start`` and settles 0.3 s. Samples every 0.04 s of physics."""
    a = SentMotion(1, 0.0, ("a",), np.array([0.0, 1.0]), np.array([[0.0], [1.0]]), 1.0, "A")
    b = SentMotion(2, 1.0, ("b",), np.array([0.0, 0.8]), np.array([[0.0], [0.5]]), 0.8, "B")
    p = np.round(np.arange(1, int(round((b_start + 1.1) / PERIOD)) + 1) * PERIOD, 4)
    q = np.column_stack([np.clip(p, 0.0, 1.0),
                         0.5 * np.clip((p - b_start) / 0.8, 0.0, 1.0)])
    return [a, b], p, q


def _report(seq: int, node: str, p: np.ndarray, q: np.ndarray,
            motions: list[dict[str, object]] | None) -> RunEvent:
    data: dict[str, object] = {"period": PERIOD, "joints": ["a", "b"], "t": p.tolist(),
                               "q": q.tolist(), "objects": {}, "grasps": []}
    if motions is not None:
        data["motions"] = motions
    return RunEvent(seq, 0.0, "physics", node=node, data=data)


def _reports(p: np.ndarray, q: np.ndarray, b_start: float, listed: bool) -> list[RunEvent]:
    """A's report (event 3) when A ends at 1.3 s of physics, B's (event 4) at its end."""
    first, rest = p <= 1.3 + 1e-9, p > 1.3 + 1e-9
    a = {"joints": ["a"], "first": [0.0], "start": 0.0, "duration": 1.0, "settle": 0.3,
         "status": "succeeded"}
    b = {"joints": ["b"], "first": [0.0], "start": b_start, "duration": 0.8, "settle": 0.3,
         "status": "succeeded"}
    return [_report(3, "A", p[first], q[first], [a] if listed else None),
            _report(4, "B", p[rest], q[rest], [b] if listed else None)]


@pytest.mark.parametrize("b_start", [1.08, 1.2])
def test_a_listed_start_is_read_and_places_every_sample_of_it(b_start: float) -> None:
    motions, p, q = _scene(b_start)
    path = physics_path(motions, _reports(p, q, b_start, listed=True))
    assert not isinstance(path, str)
    assert path.starts == (0.0, b_start) and path.how == ("reported", "reported")
    # B's samples from its start on are at task time 1.0 + (p - b_start), bit for bit.
    after = p >= b_start - 1e-9
    kept = path.times >= 1.0 - 1e-9
    assert np.array_equal(path.positions[kept], q[after])
    assert np.allclose(path.times[kept], 1.0 + p[after] - b_start, rtol=0, atol=1e-12)
    # A's settling after task time 1.0 and before B started is left out.
    assert not np.any((path.times > 1.0 + 1e-9) & (path.times < 1.0 + PERIOD - 1e-9))


def test_without_the_list_the_settling_case_is_fitted_and_named() -> None:
    motions, p, q = _scene(1.2)
    path = physics_path(motions, _reports(p, q, 1.2, listed=False))
    assert not isinstance(path, str)
    assert path.how == ("paused", "fitted") and path.estimated == (1,)
    assert path.starts[0] == 0.0  # A: the first, nothing ran before
    assert abs(path.starts[1] - 1.2) <= PERIOD  # an estimate


def test_a_listed_motion_of_other_joints_or_start_is_not_taken() -> None:
    motions, p, q = _scene(1.2)
    reports = _reports(p, q, 1.2, listed=True)
    reports[1].data["motions"] = [{"joints": ["a"], "first": [1.0], "start": 1.2}]  # not B
    path = physics_path(motions, reports)
    assert not isinstance(path, str) and path.how == ("reported", "fitted")


def test_a_listed_motion_without_its_start_is_an_error_naming_the_event() -> None:
    motions, p, q = _scene(1.2)
    reports = _reports(p, q, 1.2, listed=True)
    reports[1].data["motions"] = [{"joints": ["b"], "first": [0.0]}]
    with pytest.raises(InputError, match=r"event 4 \(physics of 'B'\).*start, joints and first"):
        physics_path(motions, reports)
