"""Smoke test of benchmarks/api_latency.py: it starts a server, loads it and reports
(the figures are not asserted here; they belong to benchmarks/RESULTS.md)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_the_latency_benchmark_measures_polls_plans_and_streams():
    done = subprocess.run(
        [sys.executable, str(REPO_ROOT / "benchmarks" / "api_latency.py"), "--clients", "5",
         "--seconds", "1", "--repeats", "1", "--planners", "1", "--streams", "2", "--json"],
        capture_output=True, text=True, timeout=180, cwd=REPO_ROOT)
    assert done.returncode == 0, done.stderr[-2000:]
    lines = done.stdout.strip().splitlines()
    assert lines[0].startswith("GET /runs/{id}: 5 python clients (closed loop)")
    assert any(line.startswith("target p99 <= 20 ms: ") for line in lines)
    result = json.loads(lines[-1])
    (window,) = result["windows"]
    assert window["requests"] > 0 and window["p50_ms"] <= window["p99_ms"] <= window["max_ms"]
    assert window["run_status"] == "running" and window["run_events"] >= 1
    assert window["plans_answered"] >= 1 and set(window["plan_codes"]) <= {"200", "422"}
    assert window["streamed_events"] >= 2  # each stream had at least run_started
    assert result["met"] == (result["p99_ms_median"] <= 20.0)
