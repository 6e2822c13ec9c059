"""Inside a ``parallel``, the run finds every goal choice ``run-task check`` made.

The check plays a parallel's branches one after another, the run ticks them at once: the
seeds of a branch's motions are its own stream, and their choice keys hold only their
arm's part of the situation (:mod:`taskrunner.tree.choice`), so the order of play does not
matter.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.runtime.session import run_task_file
from taskrunner.tree import choice
from taskrunner.tree.check import check_task
from taskrunner.tree.context import TaskContext

FIXTURES = Path(__file__).parent / "fixtures"


@pytest.mark.parametrize("path", [DATA_ROOT / "tasks" / "tray_pair.yaml",
                                  DATA_ROOT / "tasks" / "assembly_panda.yaml",
                                  FIXTURES / "handoff_overlap.yaml"],
                         ids=["tray_pair", "assembly_panda", "handoff_overlap"])
def test_every_motion_of_the_run_finds_its_check_choice(path: Path, tmp_path: Path) -> None:
    choice.forget()
    report = check_task(path, seed=0)
    assert report.ok, [p.message for p in report.problems]
    assert choice.lookups() == choice.Lookups()  # the check remembers, it does not look up
    out = io.StringIO()
    code = run_task_file(path, backend="mock", seed=0, runs_dir=tmp_path, worker=False,
                         out=out, check=False, loaded=report)
    assert code == 0, out.getvalue()[-2000:]
    found = choice.lookups()
    assert found.missed == 0 and found.found >= 3, found


def test_a_branch_s_seeds_do_not_depend_on_what_other_branches_drew(cell_free_ctx) -> None:
    ctx = cell_free_ctx
    with ctx.drawing((1,), "pick: to pre-grasp"):
        alone = [ctx.next_seed(), ctx.next_seed()]
    other = ctx.__class__(ctx.cell, ctx.scene, seed=ctx.seed)
    with other.drawing((0,), "pick: to pre-grasp"):
        other.next_seed()
    with other.drawing((1,), "pick: to pre-grasp"):
        after = [other.next_seed(), other.next_seed()]
    assert alone == after and alone[0] != alone[1]
    # Outside a parallel the run's seeds are as they always were: one counter.
    assert other.next_seed() == ctx.seed * 1000 + 1


def test_a_copy_of_the_context_draws_apart_from_it(cell_free_ctx) -> None:
    from dataclasses import replace

    ctx = cell_free_ctx
    copy = replace(ctx)
    with copy.drawing((0,), "leaf"):
        drawn = copy.next_seed()
    with ctx.drawing((0,), "leaf"):
        assert ctx.next_seed() == drawn  # the copy's draw left the original's stream as it was


@pytest.fixture
def cell_free_ctx() -> TaskContext:
    from taskrunner.robot.cell import load_cell
    from taskrunner.scene import Scene

    cell = load_cell(DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml")
    return TaskContext(cell, Scene(cell.model), seed=3)


def test_an_arm_s_part_is_its_joints_and_links_and_nothing_of_the_other_arm() -> None:
    from taskrunner.robot.cell import load_cell

    model = load_cell(DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml").model
    left = choice.arm_part(model, "left_arm")
    names = [model.joint_names[i] for i in left.indices]
    assert names == [n for n in model.joint_names if n.startswith("left_")]
    assert "left_gripper_base_1" in left.links
    assert not any(link.startswith("right_") for link in left.links)
