"""Resuming pick_place on the servo arm over the host firmware after a link fault.

The run talks to the firmware through a relay (:mod:`link_relay`) that starts dropping
every request once the motion carrying the cube to its place is sent: the motion fails,
the firmware's watchdog holds the servos where they are. The run is resumed over a new
link (as a new process would): a servo arm cannot tell whether its gripper still holds
the cube, so resuming is refused until the operator says so; then the motion is planned
again from where the servos stopped and the task ends with every expectation met, the
servos at the plan's final joints.
"""

from __future__ import annotations

import json
import urllib.request

import numpy as np
import pytest
from firmware_host import build_host, running_host
from link_relay import HttpRelay

from taskrunner.errors import InputError
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.records import load_record
from taskrunner.runtime.resume import ResumeOptions, plan_resume
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.runtime.session import make_backend, servo_calibration
from taskrunner.tasks import load_task

# Firmware seconds per wall second: the carrying motion (about 2 s) lasts 0.3 s of wall
# time, longer than the fault takes to be seen (the next exchange, within 125 ms).
SPEEDUP = 6.0
FAULT_AT = "place cube: to pre-place"  # mid-motion, the cube held
_NO_PROXY = urllib.request.build_opener(urllib.request.ProxyHandler({}))


def firmware_status(url: str) -> dict:
    request = urllib.request.Request(url, data=json.dumps({"cmd": "STATUS"}).encode(),
                                     headers={"Content-Type": "application/json"})
    with _NO_PROXY.open(request, timeout=2.0) as response:
        return json.loads(json.loads(response.read())["reply"][3:])


def test_a_run_cut_off_by_a_link_fault_resumes_over_a_new_link_and_meets_its_expectations(
        tmp_path):
    spec = load_task(DATA_ROOT / "tasks" / "pick_place.yaml")
    cell = load_cell(spec.cell)
    runs = tmp_path / "runs"
    with running_host(build_host(), SPEEDUP) as host:
        relay = HttpRelay(host.url)
        try:
            backend = make_backend("http", cell, None, url=relay.url, firmware_speedup=SPEEDUP)
            try:
                runner = Runner(spec, cell, backend, InProcessPlanner(),
                                RunOptions(seed=1, runs_dir=runs, backend_name="http"))

                def fault(event) -> None:
                    if event.kind == "motion" and event.node == FAULT_AT:
                        relay.arm("drop")

                runner.events.subscribe(fault)
                first = runner.run()
            finally:
                backend.close()
        finally:
            relay.close()
        assert first.status == "failed"
        assert "servo link failed during the motion" in (first.error or ""), first.error
        assert [e.node for e in first.events if e.kind == "node_started"][-1] == FAULT_AT

        record = load_record(runs / f"{first.run_id}.json")
        spec = load_task(record.task_file, record.parameters)
        backend = make_backend("http", cell, None, url=host.url, firmware_speedup=SPEEDUP)
        try:
            with pytest.raises(InputError, match=r"'cube' was held by 'arm' .* the http "
                                                 r"backend cannot tell .* --held cube"):
                Runner(spec, cell, backend, InProcessPlanner(),
                       RunOptions(runs_dir=runs, backend_name="http"),
                       resume=plan_resume(record, spec))
            plan = plan_resume(record, spec, ResumeOptions(held=("cube",)))
            resumed = Runner(spec, cell, backend, InProcessPlanner(),
                             RunOptions(seed=1, runs_dir=runs, backend_name="http"),
                             resume=plan)
            stopped_at = backend.joint_state().positions.copy()
            record = resumed.run()
        finally:
            backend.close()
        final = servo_calibration(cell).to_servo_degrees(
            dict(zip(cell.model.joint_names, resumed.scene.state)))
        reported = firmware_status(host.url)
    assert record.status == "succeeded", record.error
    assert resumed.expectations_met is True
    assert record.resumes == first.run_id
    assert [e.node for e in record.events if e.kind == "node_started"][0] == FAULT_AT
    # Planned again from where the servos stopped (part of the way), not from where the
    # step began.
    assert any(e.kind == "message" and e.message.startswith("joints not where the last "
                                                            "finished step left them")
               for e in record.events)
    motion = next(e for e in record.events if e.kind == "motion")
    begun = np.array(motion.data["trajectory"]["positions"][0])
    names = list(motion.data["trajectory"]["joints"])
    stopped = dict(zip(cell.model.joint_names, stopped_at))
    assert np.abs(begun - [stopped[n] for n in names]).max() < 0.02
    assert not reported["moving"]
    assert np.abs(np.array(reported["pos"]) - final).max() < 1.0
