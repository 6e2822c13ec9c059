"""run-task starts its run from the task and cell its check loaded: same events, same
outcome as loading them again; a relative path is loaded again (messages name it as given),
its cell is the check's."""

from __future__ import annotations

import io
import os

import pytest

from taskrunner.resources import resolve_task
from taskrunner.runtime import session
from taskrunner.runtime.records import load_record
from taskrunner.runtime.session import run_task_file

# Wall-clock figures, different in every run; the run's task time too (on the mock
# backend its clock runs on while a motion is planned), and its motion time (within the
# clock's sampling of a motion's end).
_TIMING = {"planning_time", "seconds", "task_time", "motion_time"}


def _run(path, runs_dir, seed: int) -> tuple[int, list[tuple]]:
    out = io.StringIO()
    code = run_task_file(path, backend="mock", seed=seed, runs_dir=runs_dir, worker=False,
                         out=out, check=True)
    (record_file,) = runs_dir.glob("*.json")
    record = load_record(record_file)
    events = [(e.kind, e.node, e.location, e.status, e.message,
               {k: v for k, v in e.data.items() if k not in _TIMING}) for e in record.events]
    return code, events


@pytest.mark.parametrize("task,seed", [("pick_place", 0), ("stack", 4), ("fallback_place", 1)])
def test_the_run_from_the_checks_task_and_cell_is_the_run_from_a_fresh_load(
        tmp_path, monkeypatch, task, seed):
    path = resolve_task(task)
    assert path.is_absolute()
    loads: list[str] = []
    real_task, real_cell = session.load_task, session.load_cell
    monkeypatch.setattr(session, "load_task", lambda *a: loads.append("task") or real_task(*a))
    monkeypatch.setattr(session, "load_cell",
                        lambda *a, **k: loads.append("cell") or real_cell(*a, **k))
    handed = _run(path, tmp_path / "handed", seed)
    assert loads == []  # the check's task and cell were used
    monkeypatch.setattr(session, "_from_check", lambda report, path: None)
    monkeypatch.setattr(session, "_checked_cell", lambda report, spec: None)
    fresh = _run(path, tmp_path / "fresh", seed)
    assert loads == ["task", "cell"]
    assert handed[0] == fresh[0]
    assert len(handed[1]) == len(fresh[1]) > 5
    for a, b in zip(handed[1], fresh[1], strict=True):
        assert a == b


def test_a_relative_task_path_is_loaded_again(tmp_path, monkeypatch):
    path = resolve_task("go_home")
    monkeypatch.chdir(path.parent)
    loads: list[object] = []
    real_task, real_cell = session.load_task, session.load_cell
    monkeypatch.setattr(session, "load_task", lambda p, *a: loads.append(p) or real_task(p, *a))
    monkeypatch.setattr(session, "load_cell",
                        lambda *a, **k: loads.append("cell") or real_cell(*a, **k))
    code, _ = _run(type(path)(path.name), tmp_path / "runs", 0)
    assert code == 0
    assert [str(p) for p in loads] == [path.name]  # its cell: the one the check loaded
    assert not os.path.isabs(path.name)
