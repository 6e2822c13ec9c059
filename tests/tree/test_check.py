"""``run-task check``: every problem of a task at its file:line, nothing moved.

The fixtures in ``fixtures/`` mark each problem they should produce with a comment
``# expect: <message>`` on its line, ``*`` standing for any text (percentages,
residuals). A fixture line without such a comment must produce no problem.
"""

from __future__ import annotations

import re
import time
from pathlib import Path

import pytest

from taskrunner.cli import EXIT_INVALID, EXIT_OK, main
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import task_scene
from taskrunner.tasks import Problem, load_task
from taskrunner.tree.check import CheckReport, _start_scene, check_task

FIXTURES = Path(__file__).resolve().parent / "fixtures"
TASKS = DATA_ROOT / "tasks"
_EXPECT = re.compile(r"#\s*expect:\s*")


def expected(path: Path) -> list[tuple[int, str]]:
    """``(line, pattern)`` of every ``# expect:`` comment of a fixture, in line order."""
    found = []
    for number, text in enumerate(path.read_text().splitlines(), 1):
        for pattern in _EXPECT.split(text)[1:]:
            found.append((number, pattern.strip().replace("{file}", str(path))))
    return found


def matches(message: str, pattern: str) -> bool:
    regex = ".*".join(re.escape(part) for part in pattern.split("*"))
    return re.fullmatch(regex, message) is not None


def assert_reports(report: CheckReport, path: Path) -> None:
    """The report holds exactly the fixture's expected problems, in line order."""
    got = [(p.line, p.message) for p in report.problems]
    want = expected(path)
    assert [line for line, _ in got] == [line for line, _ in want], "\n".join(
        str(p) for p in report.problems)
    for (line, message), (_, pattern) in zip(got, want):
        assert matches(message, pattern), f"line {line}: {message!r} !~ {pattern!r}"
    assert all(p.path == path for p in report.problems)


@pytest.mark.parametrize("name", [
    "out_of_reach.yaml",        # go to a pose 2 m away
    "candle_blocked.yaml",      # a named pose made to collide by an object
    "lid_over_cube.yaml",       # a pick whose straight approach is blocked
    "edge_pick.yaml",           # the run's pre-grasp solution fails where others would not
    "edge_pick_retry.yaml",     # ... and a retry does not help
    "place_occupied.yaml",      # a place onto a spot another object takes
    "place_not_held.yaml",      # a place of an object the arm does not hold
    "handoff_not_held.yaml",    # a hand-over of an object the giver does not hold
    "straight_into_table.yaml",  # a straight 'move by' that runs into the table
    "fallback.yaml",            # a fallback reports only when every branch fails
    "compile_errors.yaml",      # what compiling finds: width, spanning group, planner
])
def test_each_problem_is_reported_at_its_line(name: str):
    path = FIXTURES / name
    assert_reports(check_task(path), path)


def test_loader_problems_are_all_reported_and_stop_the_check():
    path = FIXTURES / "loader_errors.yaml"
    report = check_task(path)
    assert_reports(report, path)  # the unreachable go of line 9 is never dry-run
    assert report.cell == "" and report.steps == 0


def test_several_problems_of_one_file_are_all_reported_in_line_order():
    path = FIXTURES / "several.yaml"
    report = check_task(path)
    assert_reports(report, path)
    # The step with an unknown pose is skipped; the steps after it are still checked.
    assert report.cell == "servo_arm_table" and report.steps == 7


def test_a_problem_prints_as_file_line_message():
    path = FIXTURES / "candle_blocked.yaml"
    (problem,) = check_task(path).problems
    assert str(problem).startswith(f"{path}:8: go arm to 'Candle': target in collision (")


def test_a_name_problem_is_not_reported_again_by_the_dry_run(repo_root: Path):
    path = repo_root / "tests" / "tasks" / "fixtures" / "bad_names_table.yaml"
    report = check_task(path)
    assert_reports(report, path)


@pytest.mark.parametrize("path", sorted(TASKS.glob("*.yaml")), ids=lambda p: p.name)
def test_every_shipped_task_checks_clean(path: Path):
    report = check_task(path)
    assert report.problems == [], "\n".join(str(p) for p in report.problems)
    assert report.ok and report.steps > 0


def test_a_handoff_between_two_pandas_checks_clean():
    report = check_task(FIXTURES / "handoff_panda.yaml")
    assert report.problems == [] and report.steps == 4


def test_parameters_are_bound_before_checking():
    report = check_task(TASKS / "pick_place.yaml", {"pick_x": "0.10", "pick_y": "0.0"})
    assert [(p.line, p.message.split(" (IK)")[0]) for p in report.problems] == [
        (14, "pick cube: pre-grasp out of reach")]
    bad = check_task(TASKS / "pick_place.yaml", {"pick_x": "0.5"})
    assert [p.message for p in bad.problems] == ["'pick_x' must be <= 0.25 (got 0.5)"]


def test_the_same_seed_gives_the_same_report():
    path = FIXTURES / "edge_pick.yaml"
    assert check_task(path, seed=3) == check_task(path, seed=3)


def test_the_check_starts_from_the_scene_the_run_starts_from():
    spec = load_task(TASKS / "pick_place.yaml")
    cell = load_cell(spec.cell)
    scene, problems, missing = _start_scene(spec, cell, set())
    ours, theirs = scene.snapshot(), task_scene(spec, cell).snapshot()
    assert (ours.objects, ours.allowed) == (theirs.objects, theirs.allowed)
    assert list(ours.state.positions) == list(theirs.state.positions)
    assert problems == [] and missing == set()


def test_checking_pick_place_takes_well_under_a_second():
    check_task(TASKS / "pick_place.yaml")  # warm-up: imports, toppra, IK seed tables
    started = time.perf_counter()
    assert check_task(TASKS / "pick_place.yaml").ok
    assert time.perf_counter() - started < 1.0


def test_a_missing_file_is_a_problem_not_an_exception(tmp_path: Path):
    report = check_task(tmp_path / "nope.yaml")
    assert report.problems == [Problem(tmp_path / "nope.yaml", None, "file not found")]


# --------------------------------------------------------------------------- run-task
def test_run_task_check_exits_0_on_a_clean_task(capsys):
    path = TASKS / "pick_place.yaml"
    assert main(["check", str(path)]) == EXIT_OK
    out = capsys.readouterr().out
    assert "ok (4 steps checked against cell 'servo_arm_table')" in out


def test_run_task_check_exits_2_and_lists_every_problem(capsys):
    path = FIXTURES / "several.yaml"
    assert main(["check", str(path)]) == EXIT_INVALID
    err = capsys.readouterr().err.splitlines()
    assert [line.split(": ")[0] for line in err[:-1]] == [
        f"{path}:{line}" for line, _ in expected(path)]
    assert err[-1] == f"{path}: {len(expected(path))} problem(s)"


def test_run_task_check_passes_parameters(capsys):
    code = main(["check", str(TASKS / "pick_place.yaml"), "--param", "pick_x=0.5"])
    assert code == EXIT_INVALID
    assert "'pick_x' must be <= 0.25 (got 0.5)" in capsys.readouterr().err


# --------------------------------------------------------------------------- agreement
@pytest.mark.slow
@pytest.mark.parametrize("name", ["lid_over_cube.yaml", "edge_pick.yaml",
                                  "straight_into_table.yaml", "handoff_panda.yaml"])
def test_a_run_fails_where_the_check_says_and_only_there(name: str):
    from taskrunner.backends.mock import MockBackend
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.runtime.runner import Runner, RunOptions

    path = FIXTURES / name
    problems = check_task(path).problems
    spec = load_task(path)
    cell = load_cell(spec.cell)
    backend = MockBackend(cell.model.joint_names,
                          dict(zip(cell.model.joint_names, cell.start_state())))
    record = Runner(spec, cell, backend, InProcessPlanner(), RunOptions()).run()
    if not problems:
        assert record.status == "succeeded", record.error
    else:
        assert record.status == "failed"
        assert record.error is not None
        assert record.error.startswith(f"{path}:{problems[0].line}: ")
