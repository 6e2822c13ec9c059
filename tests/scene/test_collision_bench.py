"""The collision benchmark module runs and reports what the lead's table needs."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

import pytest


@pytest.fixture(scope="module")
def bench(repo_root: Path) -> ModuleType:
    spec = importlib.util.spec_from_file_location(
        "collision_bench", repo_root / "benchmarks" / "collision_bench.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def quick_result(bench: ModuleType, example_robot_data: Path) -> dict:
    return bench.run(quick=True, seed=0)


def test_quick_run_reports_median_p95_and_collision_fraction(quick_result: dict) -> None:
    assert 0 < quick_result["panda_collision_us_median"] <= quick_result["panda_collision_us_p95"]
    assert 0.05 < quick_result["panda_collision_fraction"] < 0.6
    assert quick_result["pairs"] > 100
    assert "variants" not in quick_result


def test_rows_give_one_labelled_figure_each(bench: ModuleType, quick_result: dict) -> None:
    table = bench.rows(quick_result)
    assert all(isinstance(what, str) and ("µs" in figure or "%" in figure) for what, figure in table)
    assert table[0][0].startswith("Panda")


@pytest.mark.slow
def test_panda_state_check_meets_the_25_us_median_target(quick_result: dict) -> None:
    assert quick_result["panda_collision_us_median"] <= 25.0


def test_quick_run_compares_the_previous_checker_and_splits_the_check(quick_result: dict) -> None:
    compare = quick_result["compare"]
    assert compare["verdict_disagreements"] == 0
    assert compare["edits"] == sum(compare["edit_kinds"].values()) == 20
    for key in ("rebuild_ms_before", "rebuild_ms_after", "rebuild_ms_after_pairs_cached",
                "state_us_before", "state_us_after"):
        assert compare[key] > 0
    stages = list(quick_result["breakdown"])
    assert stages[0] == "call_overhead" and stages[-1] == "whole_check"
    assert all(us > 0 for us in quick_result["breakdown"].values())
