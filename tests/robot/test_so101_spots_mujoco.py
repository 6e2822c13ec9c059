"""``pick_place_so101`` away from its default spots, on the physics backend, as a newcomer
runs it (``run-task FILE --param ... --backend mujoco``: the check, then the run).

The cube sits about a millimetre and a degree off in the physics grip, so the place's
wanted tool pose is a little off what the 5-joint arm reaches exactly; the goal choice
takes the nearest orientation the arm allows (it took a random posture 14-21° off: the
cube dropped 7.5 mm away, or turned 14°, or the opening jaw touched the table). And
where the run's situation is not the check's to the micrometre, the run checks its
planner's goal state by the check's rule (tree/lookahead.py).

Skipped where mujoco is not installed (``pip install -e '.[mujoco]'``).
"""

from __future__ import annotations

import io

import numpy as np
import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.runtime.session import run_task_file
from taskrunner.tree.check import check_task

pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install -e '.[mujoco]'")

TASK = DATA_ROOT / "tasks" / "pick_place_so101.yaml"
# The three spots that failed before, then seeded spots of the task's ranges (cube and
# drop spot at least 5 cm apart), drawn once.
REPORTED = [{"place_x": 0.18, "place_y": -0.08}, {"place_x": 0.25, "place_y": 0.0},
            {"place_x": 0.22, "place_y": 0.10}]


def _seeded(count: int, seed: int = 7) -> list[dict[str, float]]:
    rng = np.random.default_rng(seed)
    spots: list[dict[str, float]] = []
    while len(spots) < count:
        pick = rng.uniform((0.12, -0.12), (0.26, 0.12))
        place = rng.uniform((0.12, -0.12), (0.26, 0.12))
        if np.hypot(*(pick - place)) >= 0.05:
            spots.append({"pick_x": round(float(pick[0]), 3), "pick_y": round(float(pick[1]), 3),
                          "place_x": round(float(place[0]), 3),
                          "place_y": round(float(place[1]), 3)})
    return spots


SPOTS = REPORTED + _seeded(2)


@pytest.mark.parametrize("spot", SPOTS, ids=[",".join(f"{v}" for v in s.values()) for s in SPOTS])
def test_a_checked_spot_of_pick_place_so101_passes_on_mujoco(spot, tmp_path):
    parameters = {k: str(v) for k, v in spot.items()}
    report = check_task(TASK, parameters, seed=0)
    assert report.ok, [p.message for p in report.problems]
    out = io.StringIO()
    code = run_task_file(TASK, backend="mujoco", parameters=parameters, seed=0,
                         runs_dir=tmp_path / "runs", worker=False, out=out, check=False,
                         loaded=report)
    # Exit 0: the task's own expectations met (the cube released on the table within
    # 5 mm and 5° of the drop spot, the arm at rest, no unplanned contact).
    assert code == 0, out.getvalue()[-3000:]
