"""Start-up benchmark: ``run-task TASK`` from process start to its first motion.

Spawns ``python -m taskrunner.cli TASK --plain --backend mock --seed S`` N times (seeds
S, S+1, …; default behaviour otherwise: the check before the run, the planning worker)
and measures, on this side's wall clock from just before the spawn:

* ``first_motion``: when the first trajectory with a duration went to the backend. The
  run prints a ``planned`` line for each motion just before it sends the trajectory;
  its arrival time on the pipe plus the record's time from that ``planned`` event to
  the ``motion`` event (microseconds) gives it;
* ``checked``: arrival of the ``checked N steps`` line (the end of the check);
* ``main_cpu``: the ``run-task`` process's own CPU time (user + system, from
  ``/proc``) when its first motion was planned: the part of the start that machine
  load does not inflate (its planning worker's CPU time is not in it);
* ``wall``: process exit (includes the motion itself: the mock backend jumps to the end
  of each trajectory, so little);
* the exit code: 0, or 3/4 for a run that failed after it moved (still a start-up
  figure; counted in ``failed_runs``); any other ends the benchmark.

``--cold`` adds one run first with an empty ``XDG_CACHE_HOME`` and ``NUMBA_CACHE_DIR``
(no cached robot models, no compiled kernels: the run plans with coal alone while they
compile in the background, :mod:`taskrunner.planning.warmup`; a run that waited for them
instead recorded the wait as ``warm_up_s``) and Python's bytecode cache redirected to an
empty folder (``PYTHONPYCACHEPREFIX``: every module compiled again), reported apart with
whether it planned with coal, its warm-up if any and whether the task's expectations were
met; ``--cold-runs N`` makes it N such runs (seeds S, S+1, …), each on fresh caches, and
their median. After each, the compilation it left in the background is waited for up to
``--compile-wait`` s (how long after the run's exit it finished is reported), then ended,
so that it does not run beside the next measurement. ``--cold-keeps-bytecode``: the cold
runs keep the warm runs' bytecode (compiled once beforehand), as after ``pip install``,
which compiles it: only taskrunner's own caches are fresh. The warm runs follow, after
``run-task warm-up`` and one unmeasured run that fill the caches.

Warm runs keep their bytecode in a folder of their own (``PYTHONPYCACHEPREFIX`` in the
benchmark's temporary folder, ``PYTHONDONTWRITEBYTECODE`` unset): an environment that
sets ``PYTHONDONTWRITEBYTECODE`` would otherwise have every warm run compile taskrunner's
~90 modules from source again (0.2-0.3 s, which an installed package never pays).
``--no-bytecode-cache`` keeps the environment's setting instead.

``--busy N`` keeps N other processes busy (a Python loop each, at the same priority) for
the whole measurement: a known share of the CPUs taken, on top of whatever else the
machine runs (the load average is reported either way).

Usage::

    python benchmarks/startup.py [--task pick_place] [--runs 10] [--seed 0] [--cold | --cold-runs N]
                                 [--cold-keeps-bytecode] [--compile-wait S] [--json]
                                 [--pythonpath DIR] [--no-bytecode-cache] [--busy N]

``--pythonpath DIR`` runs the taskrunner found in DIR instead (``git archive`` of an
older commit, for a before/after in the same run). Prints a table, and with ``--json``
one JSON object as the last line.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["run", "run_once"]

_PLANNED = re.compile(r"^\s*[0-9.]+s\s+planned in ")
_CHECKED = re.compile(r": checked \d+ steps? in ")
_COAL = "planning with coal alone meanwhile"  # taskrunner.runtime.session.COAL_NOTE


def run_once(task: str, seed: int, runs_dir: Path, env: dict[str, str] | None = None,
             timeout: float = 120.0) -> dict[str, Any]:
    """One ``run-task`` process; times in s from just before the spawn."""
    command = [sys.executable, "-m", "taskrunner.cli", task, "--plain", "--backend", "mock",
               "--seed", str(seed), "--runs-dir", str(runs_dir)]
    lines: list[tuple[float, str]] = []
    started = time.perf_counter()
    # Not from this folder: ``python -m`` puts the working folder first on sys.path, which
    # would shadow the taskrunner ``--pythonpath`` names.
    runs_dir.mkdir(parents=True, exist_ok=True)
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, env=env, bufsize=1, cwd=runs_dir)
    assert process.stdout is not None and process.stderr is not None
    cpu_at: list[float] = []  # the run-task process's own CPU time at each planned line
    for line in process.stdout:
        lines.append((time.perf_counter() - started, line.rstrip("\n")))
        if _PLANNED.match(line):
            cpu_at.append(_cpu_seconds(process.pid))
    stderr = process.stderr.read()
    code = process.wait(timeout)
    wall = time.perf_counter() - started
    shown = "\n".join(text for _, text in lines[-15:])
    if code not in (0, 3, 4):  # 3, 4: the run failed after it started moving (reported)
        raise RuntimeError(f"run-task {task} --seed {seed} ended {code}:\n{shown}\n{stderr[-2000:]}")
    checked = next((t for t, text in lines if _CHECKED.search(text)), None)
    planned_lines = [t for t, text in lines if _PLANNED.match(text)]
    record_path = next((Path(text.split("record:", 1)[1].strip()) for _, text in lines
                        if text.strip().startswith("record:")), None)
    if record_path is None:
        raise RuntimeError(f"run-task {task}: no record line in its output")
    events = json.loads(record_path.read_text(encoding="utf-8"))["events"]
    planned = [e for e in events if e["kind"] == "planned"]
    if len(planned) != len(planned_lines):
        raise RuntimeError(f"{len(planned)} planned events but {len(planned_lines)} lines")
    first_motion = None
    for k, event in enumerate(events):
        if event["kind"] != "motion":
            continue
        before = max(j for j in range(k) if events[j]["kind"] == "planned")
        line_time = planned_lines[planned.index(events[before])]
        first_motion = line_time + event["time"] - events[before]["time"]
        main_cpu = cpu_at[planned.index(events[before])]
        break
    if first_motion is None:
        raise RuntimeError(f"run-task {task} ended {code} with no motion in its record:\n{shown}")
    record = json.loads(record_path.read_text(encoding="utf-8"))
    return {"first_motion": first_motion, "checked": checked, "wall": wall, "exit_code": code,
            "main_cpu": main_cpu, "warm_up": record.get("warm_up_s"),
            "expectations_met": _expectations_met(record),
            "planned_with_coal": any(_COAL in text for _, text in lines)}


def _background_compile(numba_cache: Path, wait: float) -> dict[str, Any]:
    """After a cold run: the kernels' compilation it left running in the background
    (:mod:`taskrunner.planning.warmup`), waited for up to ``wait`` s, then ended (by its
    pid, and the screen's helper it started, by theirs), so that the next measurement
    runs beside nothing of this one's. Returns whether one was running, how long after
    the run it ended, and whether it finished or was stopped."""
    lock = numba_cache / "compiling.lock"
    try:
        pid = int(lock.read_text(encoding="ascii").strip())
    except (OSError, ValueError):
        return {"running": False}
    started = time.perf_counter()
    while _alive(pid) and time.perf_counter() - started < wait:
        time.sleep(0.1)
    waited = time.perf_counter() - started
    if not _alive(pid):
        return {"running": True, "finished": True, "after_exit_s": waited}
    for child in [pid, *_children(pid)]:
        try:
            os.kill(child, signal.SIGKILL)
        except OSError:
            pass
    return {"running": True, "finished": False, "after_exit_s": waited}


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def _children(pid: int) -> list[int]:
    """The direct children of ``pid`` (Linux)."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            fields = (entry / "stat").read_text(encoding="ascii").rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            found.append(int(entry.name))
    return found


def _expectations_met(record: dict[str, Any]) -> bool | None:
    """Whether the run met its task's ``expect:`` (None: the task has none)."""
    verdicts = [e["data"]["expectations"]["met"] for e in record["events"]
                if isinstance(e.get("data"), dict) and "expectations" in e["data"]]
    return bool(verdicts[-1]) if verdicts else None


def _cpu_seconds(pid: int) -> float:
    """User + system CPU time of a process so far (s; Linux), NaN when unknown."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii") as stat:
            fields = stat.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return float("nan")


def _stats(values: list[float]) -> dict[str, float]:
    array = np.asarray(values)
    return {"median": float(np.median(array)), "mean": float(array.mean()),
            "min": float(array.min()), "max": float(array.max())}


_BUSY_LOOP = "import time\nwhile True:\n    for i in range(100000):\n        pass\n"


def run(task: str = "pick_place", runs: int = 10, seed: int = 0, cold: int = 0,
        pythonpath: str | None = None, bytecode_cache: bool = True,
        busy: int = 0, keep_bytecode: bool = False,
        compile_wait: float = 60.0) -> dict[str, Any]:
    """Measure ``runs`` warm starts (after ``cold`` cold ones, each on fresh caches), with
    ``busy`` other processes spinning meanwhile; see the module doc."""
    spinning = [subprocess.Popen([sys.executable, "-c", _BUSY_LOOP], stdin=subprocess.DEVNULL)
                for _ in range(busy)]
    try:
        result = _measure(task, runs, seed, cold, pythonpath, bytecode_cache, keep_bytecode,
                          compile_wait)
    finally:
        for process in spinning:
            process.kill()
            process.wait()
    result["busy"] = busy
    return result


def _measure(task: str, runs: int, seed: int, cold: int, pythonpath: str | None,
             bytecode_cache: bool, keep_bytecode: bool = False,
             compile_wait: float = 60.0) -> dict[str, Any]:
    env = dict(os.environ)
    env.pop("PYTHONPROFILEIMPORTTIME", None)
    if pythonpath:
        env["PYTHONPATH"] = os.pathsep.join(filter(None, [pythonpath, env.get("PYTHONPATH")]))
    result: dict[str, Any] = {"task": task, "runs": runs, "seed": seed,
                              "bytecode_cache": bytecode_cache,
                              "load_before": os.getloadavg()[0]}
    with tempfile.TemporaryDirectory(prefix="startup-bench-") as tmp:
        root = Path(tmp)
        runs_dir = root / "runs"
        if bytecode_cache:
            env.pop("PYTHONDONTWRITEBYTECODE", None)
            env["PYTHONPYCACHEPREFIX"] = str(root / "pycache")
        colds = []
        for k in range(cold):
            fresh = root / f"cold-{k}"
            cold_env = dict(env, XDG_CACHE_HOME=str(fresh / "cache"),
                            NUMBA_CACHE_DIR=str(fresh / "cache" / "taskrunner" / "numba"),
                            PYTHONPYCACHEPREFIX=str(fresh / "pycache"))
            if keep_bytecode:
                if k == 0:  # the bytecode compiled once, by a run on caches of its own
                    own = root / "bytecode-run"
                    run_once(task, seed, runs_dir, dict(
                        cold_env, PYTHONPYCACHEPREFIX=str(root / "pycache"),
                        XDG_CACHE_HOME=str(own), NUMBA_CACHE_DIR=str(own / "numba")))
                    _background_compile(own / "numba", 0.0)
                cold_env["PYTHONPYCACHEPREFIX"] = str(root / "pycache")
            sample = run_once(task, seed + k, runs_dir, cold_env)
            sample["background_compile"] = _background_compile(
                fresh / "cache" / "taskrunner" / "numba", compile_wait)
            colds.append(sample)
        if colds:
            result["cold"] = colds[0]
            result["colds"] = colds
            result["cold_first_motion"] = _stats([c["first_motion"] for c in colds])
        if runs:
            # The kernels compiled in the foreground first (else the unmeasured run would
            # leave them compiling in the background, and the warm runs plan with coal).
            subprocess.run([sys.executable, "-m", "taskrunner.cli", "warm-up"], env=env,
                           cwd=runs_dir, check=True, capture_output=True)
            run_once(task, seed, runs_dir, env)  # fills the caches; not measured
        samples = [run_once(task, seed + k, runs_dir, env) for k in range(runs)]
    for key in ("first_motion", "checked", "wall", "main_cpu"):
        values = [s[key] for s in samples if s[key] is not None]
        if values:
            result[key] = _stats(values)
    result["samples"] = samples
    result["failed_runs"] = sum(1 for s in samples if s["exit_code"] != 0)
    result["load_after"] = os.getloadavg()[0]
    return result


def rows(result: dict[str, Any]) -> list[tuple[str, str]]:
    """``(what, figure)`` rows of a :func:`run` result."""
    out = []
    for key, what in (("first_motion", "start to first motion"), ("checked", "start to check done"),
                      ("wall", "start to exit (wall)"),
                      ("main_cpu", "run-task's own CPU time to first motion")):
        if key in result:
            s = result[key]
            out.append((f"run-task {result['task']}, {what}, {result['runs']} warm runs",
                        f"{s['median']:.3f} s median, {s['mean']:.3f} s mean, "
                        f"{s['min']:.3f}-{s['max']:.3f} s"))
    what = "models, kernels" if result.get("cold_keeps_bytecode") else "models, kernels, bytecode"
    if "cold_first_motion" in result:
        s = result["cold_first_motion"]
        out.append((f"run-task {result['task']}, cold caches ({what}), start to first motion, "
                    f"{len(result['colds'])} runs",
                    f"{s['median']:.3f} s median, {s['min']:.3f}-{s['max']:.3f} s"))
    for k, c in enumerate(result.get("colds", [])):
        warm_up = "none" if c.get("warm_up") is None else f"{c['warm_up']:.1f} s"
        met = {True: "met", False: "NOT met", None: "none"}[c.get("expectations_met")]
        coal = ", planned with coal" if c.get("planned_with_coal") else ""
        out.append((f"run-task {result['task']}, cold caches ({what}) #{k + 1}",
                    f"first motion {c['first_motion']:.3f} s (kernels' warm-up {warm_up}{coal}), "
                    f"wall {c['wall']:.3f} s, exit {c['exit_code']}, expectations {met}"
                    f"{_compile_note(c.get('background_compile', {}))}"))
    if result.get("failed_runs"):
        out.append(("runs that failed after their first motion (exit 3 or 4)",
                    str(result["failed_runs"])))
    out.append(("warm runs' bytecode", "cached (own folder)" if result.get("bytecode_cache")
                else "as the environment says (PYTHONDONTWRITEBYTECODE: compiled every run)"))
    if result.get("busy"):
        out.append(("other processes kept busy meanwhile", str(result["busy"])))
    out.append(("load average (1 min) before / after",
                f"{result['load_before']:.2f} / {result['load_after']:.2f}"))
    return out


def _compile_note(background: dict[str, Any]) -> str:
    if not background.get("running"):
        return ""
    if background["finished"]:
        return f"; kernels compiled {background['after_exit_s']:.1f} s after its exit"
    return f"; kernels still compiling {background['after_exit_s']:.0f} s after its exit (stopped)"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--task", default="pick_place", help="task file or example name")
    parser.add_argument("--runs", type=int, default=10, help="warm runs (10)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the first run (0)")
    parser.add_argument("--cold", action="store_true", help="one cold-cache run first")
    parser.add_argument("--cold-runs", type=int, default=None, metavar="N",
                        help="N cold-cache runs first, each on fresh caches (implies --cold)")
    parser.add_argument("--cold-keeps-bytecode", action="store_true",
                        help="cold runs keep compiled bytecode (as after pip install)")
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    parser.add_argument("--pythonpath", default=None,
                        help="run the taskrunner in this folder (a checkout of another commit)")
    parser.add_argument("--no-bytecode-cache", action="store_true",
                        help="warm runs keep the environment's PYTHONDONTWRITEBYTECODE and "
                             "PYTHONPYCACHEPREFIX (see the module doc)")
    parser.add_argument("--compile-wait", type=float, default=60.0, metavar="S",
                        help="after each cold run, wait up to S s for the compilation it "
                             "left in the background, then stop it (60)")
    parser.add_argument("--busy", type=int, default=0, metavar="N",
                        help="keep N other processes busy meanwhile (0)")
    args = parser.parse_args(argv)
    if args.busy < 0:
        parser.error("--busy must be 0 or more")
    cold = args.cold_runs if args.cold_runs is not None else int(args.cold)
    if cold < 0:
        parser.error("--cold-runs must be 0 or more")
    result = run(args.task, args.runs, args.seed, cold, args.pythonpath,
                 not args.no_bytecode_cache, args.busy, args.cold_keeps_bytecode,
                 args.compile_wait)
    result["cold_keeps_bytecode"] = args.cold_keeps_bytecode
    table = rows(result)
    width = max(len(what) for what, _ in table)
    for what, figure in table:
        print(f"{what:<{width}}  {figure}")
    if args.json:
        result["python"] = platform.python_version()
        result["machine"] = platform.machine()
        result["cpus"] = os.cpu_count()
        print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
