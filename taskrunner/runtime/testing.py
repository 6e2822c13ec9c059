"""Scenario regression: run task files with their expectations, many at once.

``run-task test [PATHS…]`` finds task files (:func:`find_cases`: a folder is searched for
``*.yaml`` files that are tasks with a ``cell``; a task's ``scenarios:`` each make one
case, else its defaults make one), runs every case in its own process
(:func:`run_cases`: a process pool of ``jobs`` workers, or a Ray cluster), and reports a
table (:func:`format_table`) and JUnit XML (:func:`junit_xml`). A case passes when its
run meets the task's ``expect:`` (a task without one must succeed): the verdict is the
run's own ``expectations`` check (:mod:`taskrunner.tree.expect`).

Every case is independent and seeded; a worker process that dies is retried once, and
the retry is reported (``attempts``). ``run-task sweep`` (:mod:`taskrunner.runtime.sweep`)
runs its cases through the same :func:`run_cases`.
"""

from __future__ import annotations

import os
import time
import xml.etree.ElementTree as ET
from collections.abc import Callable, Iterable, Mapping, Sequence
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from taskrunner.errors import TaskrunnerError

__all__ = ["Case", "CaseResult", "find_cases", "format_table", "junit_xml", "run_case",
           "run_cases"]


@dataclass(frozen=True)
class Case:
    """One run to make: a task file with parameters, a seed and a backend.

    Attributes:
        path: the task file (absolute).
        task: its name (for reports).
        scenario: the scenario's name (``default`` without ``scenarios:``).
        parameters: values of the task's parameters (typed: float, int, bool, str).
        seed: seeds every planner call.
        backend: ``mock``, ``sim`` or ``mujoco``.
        speed: replay speed of sim or mujoco (None: the backend's default).
        load_options: how the cell's robots are loaded
            (:meth:`~taskrunner.robot.options.LoadOptions.as_data`; None: the defaults).
    """

    path: Path
    task: str
    scenario: str = "default"
    parameters: Mapping[str, Any] = field(default_factory=dict)
    seed: int = 0
    backend: str = "mock"
    speed: float | None = None
    error: str | None = None  # the case could not be made (the file does not load)
    load_options: Mapping[str, Any] | None = None


@dataclass(frozen=True)
class CaseResult:
    """How a case ended.

    Attributes:
        case: the case.
        verdict: ``passed`` (expectations met), ``failed`` (not met) or ``error`` (the
            task did not load, or the worker died twice).
        status: the run's status (``succeeded``, ``failed``, ``cancelled``), or None.
        seconds: wall time of the run (s).
        failure: the first failure, starting with its file:line; None when passed.
        failures: every expectation failure.
        attempts: 2 when the first worker died and the case was run again.
    """

    case: Case
    verdict: str
    status: str | None
    seconds: float
    failure: str | None = None
    failures: tuple[str, ...] = ()
    attempts: int = 1

    @property
    def passed(self) -> bool:
        return self.verdict == "passed"


def _is_task_file(path: Path) -> bool:
    """A YAML mapping with ``task``, ``cell`` and ``steps`` (an included piece has no cell)."""
    from taskrunner.errors import YamlError
    from taskrunner.yamlfile import load_yaml

    try:
        node = load_yaml(path)
    except YamlError:
        return path.suffix == ".yaml" and "task" in path.read_text(errors="replace")[:4096]
    return isinstance(node, dict) and {"task", "cell", "steps"} <= set(node)


def find_cases(paths: Iterable[str | Path]) -> list[Case]:
    """The cases of the task files at ``paths`` (files, or folders searched recursively
    for ``*.yaml`` task files), in path order; a task's ``scenarios:`` make one case each.

    A file that does not load becomes a case with its ``error`` set (reported, not run).

    Raises:
        FileNotFoundError: a path does not exist.
    """
    from taskrunner.tasks.loader import load_task

    files: list[Path] = []
    for raw in paths:
        path = Path(raw).resolve()
        if path.is_dir():
            files += [p for p in sorted(path.rglob("*.yaml")) if _is_task_file(p)]
        elif path.is_file():
            files.append(path)
        else:
            from taskrunner.resources import resolve_task

            try:
                files.append(resolve_task(str(raw)))  # a shipped example's name
            except (TaskrunnerError, FileNotFoundError, ValueError):
                raise FileNotFoundError(f"no such task file or folder: {raw}") from None
    cases: list[Case] = []
    for path in dict.fromkeys(files):
        try:
            spec = load_task(path)
        except TaskrunnerError as exc:
            cases.append(Case(path, path.stem, error=str(exc)))
            continue
        if not spec.scenarios:
            cases.append(Case(path, spec.name))
        for s in spec.scenarios:
            cases.append(Case(path, spec.name, s.name, dict(s.parameters), s.seed, s.backend,
                              s.speed))
    return cases


def run_case(case: Case) -> CaseResult:
    """Run one case in this process (what each worker does); never raises for a task's
    own failure."""
    import taskrunner
    from taskrunner.robot.options import LoadOptions

    if case.error is not None:
        return CaseResult(case, "error", None, 0.0, case.error)
    started = time.monotonic()
    try:
        options = (LoadOptions.from_data(case.load_options) if case.load_options is not None
                   else None)
        result = taskrunner.run_task(case.path, parameters=dict(case.parameters),
                                     backend=case.backend,  # type: ignore[arg-type]
                                     speed=case.speed, seed=case.seed, options=options)
    except (TaskrunnerError, ValueError) as exc:
        return CaseResult(case, "error", None, time.monotonic() - started, str(exc))
    seconds = time.monotonic() - started
    checks = [e.data["expectations"] for e in result.events if "expectations" in e.data]
    if not checks:  # the run ended before its end check (an internal error)
        return CaseResult(case, "error", result.status, seconds,
                          result.error or "the run ended without checking its expectations")
    failures = tuple(checks[-1]["failures"])
    if checks[-1]["met"]:
        return CaseResult(case, "passed", result.status, seconds)
    status = checks[-1].get("status", {})
    if status.get("expected") == "succeeded" and status.get("observed") == "failed":
        first = result.error  # the failed step's own error, at its file:line
    else:
        first = failures[0] if failures else result.error
    return CaseResult(case, "failed", result.status, seconds, first, failures)


def _died(case: Case, attempts: int, reason: str) -> CaseResult:
    return CaseResult(case, "error", None, 0.0, f"the worker running it died {attempts} "
                      f"times ({reason})", attempts=attempts)


def run_cases(cases: Sequence[Case], jobs: int | None = None, ray: str | None = None,
              on_result: Callable[[CaseResult], object] | None = None,
              work: Callable[[Case], CaseResult] = run_case) -> list[CaseResult]:
    """Run every case, each in a worker process; results in the order of ``cases``.

    Args:
        jobs: worker processes (default: every core); 1 runs the cases here, one by one.
        ray: run on Ray instead: ``"auto"``, ``"local"`` (start one here) or a cluster
            address (``ray://host:10001``); needs the ``ray`` extra.
        on_result: called with each result as it comes in.
        work: what a worker runs for a case (a module-level function: it is pickled).

    A worker that dies (killed, out of memory, a crash in native code) breaks the pool:
    the cases it failed run again once, each alone in a fresh worker (``attempts`` 2);
    a second death is an ``error`` result.
    """
    if ray is not None:
        from taskrunner.runtime.rayrun import run_on_ray

        return run_on_ray(cases, ray, on_result, work)
    jobs = jobs or os.cpu_count() or 1
    results: dict[int, CaseResult] = {}

    def done(index: int, result: CaseResult) -> None:
        results[index] = result
        if on_result is not None:
            on_result(result)

    if jobs == 1:
        for i, case in enumerate(cases):
            done(i, work(case))
        return [results[i] for i in range(len(cases))]
    import multiprocessing
    from concurrent.futures import ThreadPoolExecutor

    context = multiprocessing.get_context("spawn")  # no threads or locks inherited
    died: list[int] = []
    with ProcessPoolExecutor(max_workers=min(jobs, len(cases)), mp_context=context) as pool:
        futures = {pool.submit(work, case): i for i, case in enumerate(cases)}
        remaining = set(futures)
        while remaining:
            finished, remaining = wait(remaining, return_when=FIRST_COMPLETED)
            for future in finished:
                try:
                    done(futures[future], future.result())
                except BrokenProcessPool:
                    died.append(futures[future])
    # A dead worker breaks the whole pool, failing every case it still held: each runs
    # again alone, in a worker of its own, so that one case's death cannot fail another.

    def again(i: int) -> None:
        with ProcessPoolExecutor(max_workers=1, mp_context=context) as alone:
            try:
                done(i, replace(alone.submit(work, cases[i]).result(), attempts=2))
            except BrokenProcessPool as exc:
                done(i, _died(cases[i], 2, str(exc) or "the pool broke"))

    with ThreadPoolExecutor(max_workers=jobs) as threads:
        list(threads.map(again, sorted(died)))
    return [results[i] for i in range(len(cases))]


def _cell(text: str | None, width: int) -> str:
    text = (text or "").replace("\n", " ")
    return text if len(text) <= width else text[:width - 1] + "…"


def format_table(results: Sequence[CaseResult], failure_width: int = 160) -> str:
    """A text table: task, scenario, verdict, duration, first failure (file:line …)."""
    rows = [("task", "scenario", "status", "duration", "first failure")]
    for r in results:
        verdict = r.verdict + (" (retried)" if r.attempts > 1 else "")
        rows.append((r.case.task, r.case.scenario, verdict, f"{r.seconds:.1f} s",
                     _cell(r.failure, failure_width)))
    widths = [max(len(row[k]) for row in rows) for k in range(4)]
    lines = ["  ".join(row[k].ljust(widths[k]) for k in range(4)) + "  " + row[4]
             for row in rows]
    lines.insert(1, "  ".join("-" * w for w in widths) + "  " + "-" * 13)
    passed = sum(r.passed for r in results)
    lines.append(f"{passed} of {len(results)} passed" + (
        "" if passed == len(results) else f", {len(results) - passed} did not"))
    return "\n".join(line.rstrip() for line in lines)


def junit_xml(results: Sequence[CaseResult], seconds: float, name: str = "taskrunner") -> str:
    """The results as JUnit XML: one ``testcase`` per case (``classname`` the task file,
    ``name`` the task and scenario), ``failure`` or ``error`` with the first failure."""
    suite = ET.Element("testsuite", name=name, tests=str(len(results)),
                       failures=str(sum(r.verdict == "failed" for r in results)),
                       errors=str(sum(r.verdict == "error" for r in results)),
                       skipped="0", time=f"{seconds:.3f}")
    for r in results:
        case = ET.SubElement(suite, "testcase", classname=str(r.case.path),
                             name=f"{r.case.task}[{r.case.scenario}]", time=f"{r.seconds:.3f}")
        properties = ET.SubElement(case, "properties")
        for key, value in (("seed", r.case.seed), ("backend", r.case.backend),
                           ("attempts", r.attempts),
                           *((f"param.{k}", v) for k, v in r.case.parameters.items())):
            ET.SubElement(properties, "property", name=key, value=str(value))
        if r.verdict != "passed":
            tag = "failure" if r.verdict == "failed" else "error"
            element = ET.SubElement(case, tag, message=r.failure or r.verdict,
                                    type=r.status or r.verdict)
            element.text = "\n".join(r.failures) if r.failures else (r.failure or "")
    ET.indent(suite)
    return '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(suite, encoding="unicode")


def shipped_tasks_dir() -> Path:
    """The shipped example tasks (``run-task test`` with no path runs them)."""
    from taskrunner import resources

    return Path(resources.tasks_dir())


def test_command(paths: Sequence[str], jobs: int | None, junit: str | None,
                 ray: str | None, out: Any = None,
                 load_options: Mapping[str, Any] | None = None) -> int:
    """``run-task test``: run, print the table, write JUnit; 0 only when all pass.
    ``load_options``: how every case loads its cell's robots (its ``--package-path`` …,
    as :meth:`~taskrunner.robot.options.LoadOptions.as_data`)."""
    import sys

    out = out or sys.stdout
    started = time.monotonic()
    try:
        cases = [replace(c, load_options=load_options)
                 for c in find_cases(paths or [shipped_tasks_dir()])]
    except FileNotFoundError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if not cases:
        print("no task files found in " + ", ".join(map(str, paths)), file=out)
        return 2
    where = f"Ray ({ray})" if ray else f"{jobs or os.cpu_count() or 1} worker(s)"
    print(f"running {len(cases)} case(s) of {len({c.path for c in cases})} task file(s) "
          f"on {where}", file=out, flush=True)
    results = run_cases(cases, jobs, ray)
    seconds = time.monotonic() - started
    print(format_table(results), file=out)
    print(f"in {seconds:.1f} s", file=out)
    if junit:
        Path(junit).write_text(junit_xml(results, seconds), encoding="utf-8")
        print(f"JUnit XML: {junit}", file=out)
    return 0 if all(r.passed for r in results) else 1
