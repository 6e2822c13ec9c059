"""run-task collects no garbage from its start to the run, and gives the caller's garbage
collection back as it found it, however the command ends."""

from __future__ import annotations

import gc

import pytest

from taskrunner.cli import EXIT_INVALID, EXIT_OK, main


@pytest.fixture
def restore_gc():
    enabled = gc.isenabled()
    yield
    if enabled:
        gc.enable()
    else:
        gc.disable()


def _run(tmp_path, *extra: str) -> int:
    return main(["run", "go_home", "--in-process", "--plain", "--backend", "mock",
                 "--runs-dir", str(tmp_path / "runs"), *extra])


def test_collection_is_on_again_once_the_run_started(tmp_path, monkeypatch, restore_gc):
    from taskrunner.runtime import session

    seen = []
    real = session.run_task_file

    def run_task_file(*args, **kwargs):
        # The run starts with collection on, the start's objects left out of it.
        seen.append((gc.isenabled(), gc.get_freeze_count()))
        return real(*args, **kwargs)

    monkeypatch.setattr(session, "run_task_file", run_task_file)
    gc.enable()
    frozen = gc.get_freeze_count()
    assert _run(tmp_path) == EXIT_OK
    assert len(seen) == 1 and seen[0][0] and seen[0][1] > frozen
    assert gc.isenabled()
    if frozen == 0:  # given back to the collector when the command ends
        assert gc.get_freeze_count() == 0
    else:            # a caller's own freeze is left alone
        assert gc.get_freeze_count() >= frozen


def test_a_caller_without_collection_keeps_it_off_and_nothing_frozen(tmp_path, restore_gc):
    gc.disable()
    frozen = gc.get_freeze_count()
    assert _run(tmp_path) == EXIT_OK
    assert not gc.isenabled()
    assert gc.get_freeze_count() <= frozen  # nothing frozen (frozen objects may be freed)


def test_a_refused_task_gives_collection_back(tmp_path, restore_gc):
    bad = tmp_path / "bad.yaml"
    bad.write_text("cell: nowhere.yaml\nsteps: []\n", encoding="utf-8")
    gc.enable()
    assert main(["run", str(bad), "--in-process", "--plain", "--backend", "mock",
                 "--runs-dir", str(tmp_path / "runs")]) == EXIT_INVALID
    assert gc.isenabled()
