"""Smoke test of benchmarks/ik_bench.py (the figures themselves are not asserted here)."""

from __future__ import annotations

import importlib.util
import json
import math
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[2]


def _load_bench():
    spec = importlib.util.spec_from_file_location("ik_bench", REPO_ROOT / "benchmarks" / "ik_bench.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_bench_reports_every_robot_and_formats_rows() -> None:
    bench = _load_bench()
    result = bench.run(quick=True, seed=1, targets=5)
    for key in ("panda_ik", "ur5_ik", "arm5_ik_position"):
        assert 0.0 <= result[f"{key}_success"] <= 1.0
        assert result[f"{key}_ms_mean"] > 0 and math.isfinite(result[f"{key}_ms_p95"])
        assert result[f"{key}_targets"] == 5
    json.dumps(result)
    rows = bench.rows(result)
    assert result["calibration_us"] > 0
    assert len(rows) == 4
    assert rows[0][0].startswith("machine speed")
    assert rows[1][0].startswith("IK Panda arm, full pose, 5 random reachable targets")
    assert "% success" in rows[3][1] and "ms mean" in rows[3][1] and "ms p99" in rows[3][1]
    for key in ("panda_ik", "ur5_ik"):
        assert result[f"{key}_ms_p99"] <= result[f"{key}_ms_max"]
        assert 0.0 <= result[f"{key}_first_attempt"] <= result[f"{key}_success"]
        assert result[f"{key}_failures"] == round(5 * (1 - result[f"{key}_success"]))
