"""Resuming pick_place, handoff and stack_three on the servo arms over the host firmware
after link faults, each at three points: during a motion, with the object held, during a
place.

One story per task (module-scoped, shared by its tests): the run talks to the firmware
through a relay (:mod:`link_relay`) that loses a reply once the motion of the first
point's step is sent: the motion fails, the firmware's watchdog holds the servos where
they are. The run is resumed over a new link (as a new process would), whose relay loses
a reply at the next point, and so on; the last continuation ends with every expectation
of the task met, the servos at the plan's final joints. A servo arm cannot tell whether
its gripper still holds an object: where one was held, resuming is refused until the
operator says ``--held``. Each point's test reads its stop and its continuation from the
story.

Cost on a loaded 2-core machine (load 12; the stories are all of it, built once each):
about 8 s for pick_place, 10 s for handoff, 8 s for stack_three; the tests read them.
"""

from __future__ import annotations

import json
import urllib.request
from dataclasses import dataclass

import numpy as np
import pytest
from firmware_host import build_host, running_host
from link_relay import HttpRelay

from taskrunner.errors import InputError
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.runtime.records import RunRecord, load_record
from taskrunner.runtime.resume import ResumeOptions, ResumePlan, plan_resume
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.runtime.session import make_backend
from taskrunner.tasks import load_task

# Firmware seconds per wall second: the shortest motion stopped (a place's descent, about
# 1 s) lasts longer in wall time than the fault takes to be seen (the next exchange).
SPEEDUP = 6.0
# cells/servo_arm_pair.hardware.yaml: the board channels of the pair's two arms.
PAIR_BOARD = [0, 1, 2, 3, 4, 5, 8, 9, 10, 11, 12, 13]

# Per task, where its link fails (the step whose motion is cut off) and what is held there.
POINTS: dict[str, tuple[tuple[str, str | None], ...]] = {
    "pick_place": (("pick cube: approach", None),           # during a motion
                   ("place cube: to pre-place", "cube"),    # the cube held
                   ("place cube: descend", "cube")),        # during the place
    "handoff": (("pick bar: approach", None),
                ("handoff bar: left_arm presents", "bar"),
                ("place bar: descend", "bar")),
    "stack_three": (("place cube_b: to pre-place", "cube_b"),
                    ("pick cube_c: approach", None),
                    ("place cube_c: descend", "cube_c")),
}
_NO_PROXY = urllib.request.build_opener(urllib.request.ProxyHandler({}))


def firmware_status(url: str) -> dict:
    request = urllib.request.Request(url, data=json.dumps({"cmd": "STATUS"}).encode(),
                                     headers={"Content-Type": "application/json"})
    with _NO_PROXY.open(request, timeout=2.0) as response:
        return json.loads(json.loads(response.read())["reply"][3:])


@dataclass
class Leg:
    """One run of a story: its record, where the servos were when it began, and what
    resuming it without ``--held`` said (None: it was not refused)."""

    record: RunRecord
    began_at: dict[str, float]
    refused: str | None = None
    expectations_met: bool | None = None


@dataclass
class FirmwareStory:
    task: str
    cell: Cell
    legs: list[Leg]
    final_degrees: np.ndarray  # the plan's final joints, in servo degrees
    reported: dict  # the firmware's STATUS at the end


def run_leg(host_url: str, spec, cell: Cell, runs, plan: ResumePlan | None,
            pending: list[str]) -> tuple[Leg, Runner, object]:
    """One run (or continuation) over a new link whose relay loses a reply once the
    motion of ``pending[0]``'s step is sent; with its runner and the link's calibration."""
    relay = HttpRelay(host_url)
    try:
        backend = make_backend("http", cell, None, url=relay.url, firmware_speedup=SPEEDUP)
        try:
            runner = Runner(spec, cell, backend, InProcessPlanner(),
                            RunOptions(seed=1, runs_dir=runs, backend_name="http"),
                            resume=plan)

            def fault(event) -> None:
                if event.kind == "motion" and pending and event.node == pending[0]:
                    pending.pop(0)
                    relay.arm("drop")

            runner.events.subscribe(fault)
            began = dict(zip(cell.model.joint_names, backend.joint_state().positions))
            record = runner.run()
        finally:
            backend.close()
    finally:
        relay.close()
    return Leg(record, began, expectations_met=runner.expectations_met), runner, \
        backend.calibration


def refusal(host_url: str, spec, cell: Cell, runs, record: RunRecord) -> str | None:
    """What resuming ``record`` over a new link says when nobody vouches for what it held
    (None: it is not refused)."""
    backend = make_backend("http", cell, None, url=host_url, firmware_speedup=SPEEDUP)
    try:
        Runner(spec, cell, backend, InProcessPlanner(),
               RunOptions(runs_dir=runs, backend_name="http"), resume=plan_resume(record, spec))
    except InputError as exc:
        return str(exc)
    finally:
        backend.close()
    return None


@pytest.fixture(scope="module", params=list(POINTS))
def story(request, tmp_path_factory) -> FirmwareStory:
    """A task's run and its continuations, stopped at each of its points."""
    task = request.param
    runs = tmp_path_factory.mktemp(f"runs_{task}")
    spec = load_task(DATA_ROOT / "tasks" / f"{task}.yaml")
    cell = load_cell(spec.cell)
    pending = [node for node, _ in POINTS[task]]
    legs: list[Leg] = []
    channels = PAIR_BOARD if len(cell.model.instances) == 2 else None
    with running_host(build_host(), SPEEDUP, channels=channels) as host:
        plan = None
        while True:
            leg, runner, calibration = run_leg(host.url, spec, cell, runs, plan, pending)
            legs.append(leg)
            if leg.record.status != "failed" or len(legs) > len(POINTS[task]):
                break
            record = load_record(runs / f"{leg.record.run_id}.json")
            spec = load_task(record.task_file, record.parameters)
            held = POINTS[task][len(legs) - 1][1]
            if held is not None:  # the arm cannot tell: refused until the operator says so
                leg.refused = refusal(host.url, spec, cell, runs, record)
            plan = plan_resume(record, spec, ResumeOptions(held=(held,) if held else ()))
        reported = firmware_status(host.url)
    state = dict(zip(cell.model.joint_names, runner.scene.state))
    return FirmwareStory(task, cell, legs, np.array(calibration.to_servo_degrees(state)),
                         reported)


def messages(record: RunRecord) -> list[str]:
    return [e.message for e in record.events if e.kind == "message"]


@pytest.mark.parametrize("point", range(3), ids=["mid-motion", "held", "mid-place"])
def test_a_run_stopped_by_a_link_fault_at_a_point_resumes_over_a_new_link(story, point):
    node, held = POINTS[story.task][point]
    assert len(story.legs) > point + 1, [leg.record.error for leg in story.legs]
    stopped, then = story.legs[point], story.legs[point + 1]
    assert stopped.record.status == "failed"
    assert "servo link failed during the motion" in (stopped.record.error or ""), \
        stopped.record.error
    assert [e.node for e in stopped.record.events if e.kind == "node_started"][-1] == node
    if held is not None:
        assert stopped.refused is not None and f"{held!r} was held by" in stopped.refused \
            and f"the http backend cannot tell whether it still is: pass --held {held}" \
            in stopped.refused, stopped.refused
        assert any(m.startswith(f"{held!r} still held by") and "(the operator says so)" in m
                   for m in messages(then.record)), messages(then.record)
    assert then.record.resumes == stopped.record.run_id
    # The leaf that did not finish runs again first, planned from where the servos
    # stopped, not from where the step began. (How far they got depends on when the
    # link's loss is seen, in wall time: not asserted.)
    assert [e.node for e in then.record.events if e.kind == "node_started"][0] == node
    motion = next(e for e in then.record.events if e.kind == "motion")
    assert motion.node == node
    trajectory = motion.data["trajectory"]
    begun = np.array(trajectory["positions"][0])
    assert np.abs(begun - [then.began_at[n] for n in trajectory["joints"]]).max() < 0.02


def test_the_last_continuation_meets_every_expectation_with_the_servos_at_rest(story):
    last = story.legs[-1]
    assert [leg.record.status for leg in story.legs] == ["failed"] * 3 + ["succeeded"], \
        [leg.record.error for leg in story.legs]
    assert last.expectations_met is True
    assert any(m.startswith("expectations met") for m in messages(last.record))
    assert not story.reported["moving"]
    assert np.abs(np.array(story.reported["pos"]) - story.final_degrees).max() < 1.0
