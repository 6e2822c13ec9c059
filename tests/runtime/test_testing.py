"""run-task test: task files and scenarios run in parallel, a table, JUnit XML, exit code."""

from __future__ import annotations

import sys
import textwrap
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from taskrunner import resources
from taskrunner.cli import main
from taskrunner.runtime.testing import Case, find_cases, format_table, run_cases

CELL = resources.robots_dir() / "cells" / "servo_arm_table.yaml"


def test_run_task_test_runs_the_shipped_examples_and_writes_junit(tmp_path: Path, capsys):
    junit = tmp_path / "junit.xml"
    code = main(["test", "--junit", str(junit)])
    out = capsys.readouterr().out
    assert code == 0, out
    suite = ET.parse(junit).getroot()
    examples = sorted(resources.example_tasks())
    cases = suite.findall("testcase")
    names = [c.get("name") for c in cases]
    # every shipped example ran, pick_place once per scenario
    assert {n.split("[")[0] for n in names} == set(examples)
    assert "pick_place[drop left]" in names and "pick_place[sim]" in names
    assert suite.get("tests") == str(len(cases))
    assert suite.get("failures") == "0" and suite.get("errors") == "0"
    assert all(c.find("failure") is None and c.find("error") is None for c in cases)
    assert f"{len(cases)} of {len(cases)} passed" in out


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


def test_a_missed_expectation_fails_with_its_line_in_the_table_and_junit(tmp_path: Path,
                                                                         capsys):
    write(tmp_path, "home.yaml", f"""\
    task: home
    cell: {CELL}
    parameters:
      pose: {{default: home, type: str}}
    steps:
      - go: {{group: arm, to: "${{pose}}"}}
    expect:
      groups: {{arm: {{at: home}}}}
    scenarios:
      - {{name: home}}
      - {{name: candle, parameters: {{pose: Candle}}, seed: 3}}
    """)
    write(tmp_path, "piece.yaml", "task: piece\nsteps:\n  - go: {group: arm, to: home}\n")
    write(tmp_path, "broken.yaml", f"task: broken\ncell: {CELL}\nsteps:\n  - wiat: {{}}\n")
    junit = tmp_path / "out.xml"
    code = main(["test", str(tmp_path), "--jobs", "2", "--junit", str(junit)])
    out = capsys.readouterr().out
    assert code == 1
    lines = {line.split()[0] + " " + line.split()[1]: line for line in out.splitlines()
             if line.startswith(("home ", "broken "))}
    assert "passed" in lines["home home"]
    assert "failed" in lines["home candle"]
    assert f"{tmp_path / 'home.yaml'}:8: expectation not met: " in lines["home candle"]
    assert "error" in lines["broken default"] and "'wiat' is not a step verb" in out
    assert "piece" not in out  # an included piece (no cell) is not a task to run
    suite = ET.parse(junit).getroot()
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("3", "1", "1")
    failed = next(c for c in suite.iter("testcase") if c.get("name") == "home[candle]")
    failure = failed.find("failure")
    assert failure is not None and ":8: expectation not met" in (failure.get("message") or "")
    props = {p.get("name"): p.get("value") for p in failed.iter("property")}
    assert props["seed"] == "3" and props["param.pose"] == "Candle"


DYING = '''
import os
import time
from pathlib import Path
from taskrunner.runtime.testing import CaseResult

def work(case):
    here = Path(case.path)
    if case.scenario == "once":
        # dies on its first run, which is in the shared pool: the other case waits for it
        if not here.with_suffix(".died").exists():
            here.with_suffix(".died").write_text("x")
            os._exit(9)
        return CaseResult(case, "passed", "succeeded", 0.0)
    first = here.with_name("a.died")
    deadline = time.monotonic() + 30
    while not first.exists() and time.monotonic() < deadline:
        time.sleep(0.01)
    os._exit(9)
'''


def test_a_worker_that_dies_is_retried_once_and_reported(tmp_path: Path,
                                                         monkeypatch: pytest.MonkeyPatch):
    (tmp_path / "dying_work.py").write_text(DYING, encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path))  # spawned workers get sys.path too
    import dying_work

    cases = [Case(tmp_path / "a.yaml", "a", "once"), Case(tmp_path / "b.yaml", "b", "always")]
    results = run_cases(cases, jobs=2, work=dying_work.work)
    sys.modules.pop("dying_work", None)
    once, always = results
    assert once.verdict == "passed" and once.attempts == 2
    assert always.verdict == "error" and always.attempts == 2
    assert "died 2 times" in (always.failure or "")
    assert "passed (retried)" in format_table(results)


def test_find_cases_refuses_a_missing_path(tmp_path: Path):
    with pytest.raises(FileNotFoundError, match="no such task file or folder"):
        find_cases([tmp_path / "nope"])


def test_every_case_loads_its_robots_as_the_command_says(tmp_path: Path, capsys):
    from taskrunner.runtime.testing import run_case, test_command

    task = resources.tasks_dir() / "go_home.yaml"
    # Read in the worker: a case whose options say nothing valid is reported, not run
    # with the defaults.
    bad = run_case(Case(task, "go_home", load_options={"collision": "mesh"}))
    assert bad.verdict == "error" and "'collision' must be one of" in (bad.failure or "")
    assert run_case(Case(task, "go_home", load_options={"collision": "convex"})).passed
    assert test_command([str(task)], 1, None, None,
                        load_options={"collision": "mesh"}) == 1  # every case gets them
    assert "'collision' must be one of" in capsys.readouterr().out
    assert main(["test", str(task), "--jobs", "1", "--collision", "convex"]) == 0
