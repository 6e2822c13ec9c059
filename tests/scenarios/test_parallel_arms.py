"""Two arms at work at once in a ``parallel`` (issue 25): the run's motions, replayed on
their common clock, never bring one arm's links into the other's.

The probe (``fixtures/meet_in_the_middle.yaml``): each servo arm of ``servo_arm_pair``
picks a cube 3 cm from the table's middle and places it back on its own side, both
branches of one ``parallel``, so both grippers reach the middle at the same time.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from taskrunner.backends.mock import MockBackend
from taskrunner.backends.sim import SimBackend, SimOptions
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.scene import Scene
from taskrunner.tasks import load_task
from taskrunner.tree.expect import arm_conflicts

FIXTURES = Path(__file__).parent / "fixtures"
PROBE = FIXTURES / "meet_in_the_middle.yaml"


def run_probe(tmp_path: Path, seed: int = 0, sim_speed: float | None = None) -> Runner:
    spec = load_task(PROBE, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    start = dict(zip(names, cell.start_state()))
    backend = (MockBackend(names, start) if sim_speed is None
               else SimBackend(names, start, SimOptions(speed=sim_speed)))
    runner = Runner(spec, cell, backend, InProcessPlanner(),
                    RunOptions(seed=seed, runs_dir=tmp_path / "runs",
                               backend_name="mock" if sim_speed is None else "sim"))
    runner.run()
    return runner


def schedule_of(runner: Runner) -> list[tuple[float, dict]]:
    """Each recorded motion with its start on the run's common clock (s): the ``start``
    of its ``motion`` event; where a record has none (runs before motions were
    scheduled), the timing a parallel promises: each arm's motions back to back from the
    parallel's start."""
    out: list[tuple[float, dict]] = []
    ends: dict[str, float] = {}
    for event in runner.record.events:
        if event.kind != "motion":
            continue
        trajectory = event.data["trajectory"]
        arm = trajectory["joints"][0].split("_")[0]  # left_… / right_…
        start = event.data.get("sent", event.data.get("start"))  # when it really started
        if start is None:
            start = ends.get(arm, 0.0)
        ends[arm] = float(start) + float(trajectory["duration"])
        out.append((float(start), trajectory))
    return out


def arm_contacts(runner: Runner, step: float = 0.005) -> list[tuple[float, str, str, float]]:
    """Replay the record's trajectories on their common clock every ``step`` s and check
    the left arm's links against the right arm's with the scene's exact checker (coal):
    ``(time, link, link, depth)`` of every colliding sample."""
    model = runner.scene.robot
    scene = Scene(model)  # the robots alone: links against links
    schedule = schedule_of(runner)
    horizon = max(start + t["duration"] for start, t in schedule)
    base = scene.state
    found = []
    for now in np.arange(0.0, horizon + step, step):
        q = base.copy()
        for start, trajectory in sorted(schedule, key=lambda s: s[0]):
            if start > now and q is not None:
                continue  # not started: the arm rests where its previous motion ended
            times = np.asarray(trajectory["times"], dtype=float)
            positions = np.asarray(trajectory["positions"], dtype=float)
            idx = model.indices(tuple(trajectory["joints"]))
            local = min(max(now - start, times[0]), times[-1])
            q[idx] = [np.interp(local, times, positions[:, j]) for j in range(len(idx))]
        model.apply_mimic(q)
        for contact in scene.collisions(q):
            sides = {contact.a.split("_")[0], contact.b.split("_")[0]}
            if sides == {"left", "right"}:
                found.append((float(now), contact.a, contact.b, contact.depth))
    return found


def test_probe_runs_with_waits_and_no_arm_against_arm_contact(tmp_path):
    runner = run_probe(tmp_path)
    assert runner.record.status == "succeeded", runner.record.error
    assert runner.expectations_met  # collision_free: true covers arm against arm in time
    contacts = arm_contacts(runner)
    assert not contacts, (
        f"{len(contacts)} colliding samples, first at {contacts[0][0]:.3f} s "
        f"({contacts[0][1]} - {contacts[0][2]}, {1e3 * max(c[3] for c in contacts):.1f} mm)")
    waits = [e for e in runner.record.events if e.kind == "wait"]
    assert waits, "the branches meet in the middle: one of them must have waited"
    for wait in waits:
        assert wait.location and wait.data["other"] and wait.data["other"] != wait.location
        assert len(wait.data["bodies"]) == 2
    # The right arm's pick waited for the left arm's pick (lines 14 and 17 of the probe).
    assert any(w.location.endswith(":17") and w.data["other"].endswith(":14") for w in waits)


def test_the_record_verifier_finds_the_contact_of_the_unscheduled_timing(tmp_path):
    """The same trajectories each arm back to back from the parallel's start (what a run
    did before its motions were scheduled): ``collision_free`` reports the contact."""
    runner = run_probe(tmp_path)
    ends: dict[str, float] = {}
    events = []
    for event in runner.record.events:
        if event.kind == "motion":
            arm = event.data["trajectory"]["joints"][0].split("_")[0]
            start = ends.get(arm, 0.0)
            ends[arm] = start + event.data["trajectory"]["duration"]
            event = replace(event, data={**event.data, "start": start, "sent": start})
        events.append(event)
    misses = arm_conflicts(runner.scene.robot, events)
    assert len(misses) == 1 and "arms collide in a parallel" in misses[0], misses
    assert "left_" in misses[0] and "right_" in misses[0] and ":17" in misses[0]


def test_probe_on_the_simulator_keeps_the_arms_apart_on_its_clock(tmp_path):
    """Motions take their time there: a motion admitted to start later is held until
    then, and the record's start times (when each motion was really sent) replay without
    contact."""
    runner = run_probe(tmp_path, sim_speed=10.0)
    assert runner.record.status == "succeeded", runner.record.error
    assert runner.expectations_met
    assert not arm_contacts(runner)
    motions = [e for e in runner.record.events if e.kind == "motion"]
    assert all(e.data["sent"] >= e.data["start"] - 1e-6 for e in motions)
