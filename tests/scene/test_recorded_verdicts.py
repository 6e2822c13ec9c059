"""The verifier and the screen say today what they said when the verdicts were recorded
(``verdict_cases.py``: MoveIt problem sets of every class and a servo arm cell)."""

from __future__ import annotations

import json

import pytest
from verdict_cases import FIXTURE, build_scene, observe

_CASES = json.loads(FIXTURE.read_text())["cases"]


def test_the_recorded_cases_cover_free_and_colliding_paths_and_states() -> None:
    paths = [p for case in _CASES for p in case["expected"]["paths"]]
    states = [s for case in _CASES for s in case["expected"]["states"]]
    assert len(_CASES) >= 15
    assert sum(p["valid"] for p in paths) > 10 and sum(not p["valid"] for p in paths) > 10
    assert sum(s["row"] == 0 for s in states) > 10 and sum(s["row"] == -1 for s in states) > 10
    assert sum(bool(s["asked"]) for s in states) > 10  # coal was asked about some pairs


@pytest.mark.parametrize("case", _CASES, ids=[case["name"] for case in _CASES])
def test_verdicts_measurements_and_pairs_asked_are_those_recorded(case: dict) -> None:
    seen = observe(build_scene(case), case)
    expected = case["expected"]
    # Where a contact lies comes from coal's distances, whose last digits depend on coal's
    # warm start (what it was asked before, in this process): equal to 1e-9 of a segment.
    for path, recorded in zip(seen["paths"], expected["paths"], strict=True):
        if recorded["fraction"] is not None:
            assert path.pop("fraction") == pytest.approx(recorded["fraction"], rel=0, abs=1e-9)
            recorded = {k: v for k, v in recorded.items() if k != "fraction"}
        assert path == recorded
    assert seen["states"] == expected["states"]
    assert seen["rows"] == expected["rows"]
