"""The mujoco world rebuilt mid-run (an object added between motions) keeps its clock:
physics time is the run's, monotonic over every physics report (the MCAP export orders
the physics' samples by it).

Skipped where mujoco is not installed (``pip install -e '.[mujoco]'``).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks.loader import load_task

pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install -e '.[mujoco]'")

from taskrunner.backends.physics import MujocoBackend, MujocoOptions, physics_cell
from taskrunner.planning.service import InProcessPlanner

CELL_OF = Path(__file__).parents[1] / "fixtures" / "moveit_scenes" / "task" / "pick_from_shelf.yaml"


def test_a_world_rebuilt_between_motions_keeps_its_physics_clock(tmp_path, monkeypatch):
    path = tmp_path / "add.yaml"
    path.write_text(
        f"task: add\ncell: {load_task(CELL_OF).cell}\n"
        "steps:\n"
        "  - go: {group: arm, to: ready}\n"
        "  - move: {group: arm, by: {xyz: [0, 0, -0.05]}}\n"
        "  - add_object: {name: block, shape: box, size: [0.04, 0.04, 0.04],\n"
        "                 pose: {xyz: [0.5, -0.3, 0.77]}}\n"
        "  - move: {group: arm, by: {xyz: [0, 0, 0.05]}}\n", encoding="utf-8")
    spec = load_task(path)
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(tmp_path / "cache")))
    rebuilt_at: list[float] = []  # physics time when the world was rebuilt
    build = backend._build

    def counting_build(new_cell):
        rebuilt_at.append(backend.sim_time)
        build(new_cell)

    monkeypatch.setattr(backend, "_build", counting_build)
    try:
        record = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(backend_name="mujoco")).run()
        final = backend.sim_time
        bodies = {backend.model.body(b).name for b in range(backend.model.nbody)}
    finally:
        backend.close()
    assert record.status == "succeeded", record.error
    assert "block" in bodies
    reports = [e.data for e in record.events if e.kind == "physics"]
    assert len(reports) == 2  # the two moves (the cell starts at ready)
    # The block came in after the first move had run: a rebuild in mid-run.
    assert any(t > 0 for t in rebuilt_at), rebuilt_at
    times = [t for report in reports for t in report["t"]]
    assert all(b > a for a, b in zip(times, times[1:])), times
    starts = [m["start"] for report in reports for m in report["motions"]]
    assert len(starts) == 2 and starts[1] >= reports[0]["t"][-1] - 1e-9, starts
    for report in reports:  # each motion's samples are from its start on
        assert report["t"][0] > report["motions"][0]["start"]
    assert final >= times[-1] - 1e-4
