"""run-task sweep: parameter axes, success per value, failure clusters, CSV / PNG / HTML;
the same results on Ray as in the process pool."""

from __future__ import annotations

import argparse
import csv
import struct
import textwrap
import zlib
from pathlib import Path

import pytest

from taskrunner import resources
from taskrunner.errors import InputError
from taskrunner.runtime.sweep import (
    SweepReport,
    _step_and_reason,
    cluster_failures,
    parse_axis,
    sweep_cases,
    sweep_command,
    write_png,
)
from taskrunner.runtime.testing import Case, CaseResult, run_cases

CELL = resources.robots_dir() / "cells" / "servo_arm_table.yaml"
TYPES = {"place_y": "float", "n": "int", "pose": "str", "flag": "bool"}


@pytest.mark.parametrize(("spec", "values"), [
    ("place_y=-0.15:0.15:3", [-0.15, 0.0, 0.15]),
    ("place_y=-0.15:0.15:31", None),
    ("place_y=0.1:0.1:1", [0.1]),
    ("place_y=0.1,0.2", [0.1, 0.2]),
    ("n=1:5:3", [1, 3, 5]),
    ("pose=home,Candle", ["home", "Candle"]),
    ("flag=true,no", [True, False]),
])
def test_axes_are_parsed_to_the_parameters_type(spec: str, values: list | None):
    name, parsed = parse_axis(spec, TYPES)
    assert name == spec.split("=")[0]
    if values is None:
        assert len(parsed) == 31 and parsed[0] == -0.15 and parsed[-1] == 0.15
        assert parsed[15] == 0.0
    else:
        assert parsed == values


@pytest.mark.parametrize(("spec", "message"), [
    ("place_y", "must be NAME=START:STOP:COUNT"),
    ("nope=1,2", "the task has no parameter 'nope'"),
    ("place_y=0:1", "range must be START:STOP:COUNT"),
    ("place_y=0:1:0", "COUNT must be >= 1 (got 0)"),
    ("n=1:2:3", "has values between integers"),
    ("pose=a:b:3", "range must be START:STOP:COUNT of a number parameter"),
    ("place_y=a,b", "values must be floats (got 'a')"),
])
def test_bad_axes_are_refused_with_the_reason(spec: str, message: str):
    with pytest.raises(InputError, match=message.replace("(", r"\(").replace(")", r"\)")):
        parse_axis(spec, TYPES)


def _result(params: dict, passed: bool, failure: str | None = None, seed: int = 0) -> CaseResult:
    case = Case(Path("/t.yaml"), "t", "x", params, seed)
    return CaseResult(case, "passed" if passed else "failed", "succeeded" if passed else
                      "failed", 1.0, failure)


def test_failures_cluster_by_step_and_message_with_numbers_normalised():
    results = [
        _result({"y": 0.1}, False, "/t.yaml:18: 'cube' ended 7.1 mm from its target"),
        _result({"y": 0.2}, False, "/t.yaml:18: 'cube' ended 12.6 mm from its target"),
        _result({"y": 0.3}, False, "/t.yaml:12: no IK solution for 'Revolute 1' at 0.3"),
        _result({"y": 0.4}, True),
    ]
    assert cluster_failures(results) == [
        ("/t.yaml:18", "'cube' ended # mm from its target", 2),
        ("/t.yaml:12", "no IK solution for 'Revolute 1' at #", 1),
    ]
    report = SweepReport("t", (("y", (0.1, 0.2, 0.3, 0.4)),), tuple(results), 1.0)
    assert report.rates("y") == [(0.1, 0, 1), (0.2, 0, 1), (0.3, 0, 1), (0.4, 1, 1)]


def _read_png(path: Path) -> tuple[int, int, bytes]:
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, size = 8, b"", (0, 0)
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        assert crc == zlib.crc32(kind + body) & 0xFFFFFFFF
        if kind == b"IHDR":
            size = struct.unpack(">II", body[:8])
            assert body[8:10] == b"\x08\x02"  # 8-bit RGB
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    return size[0], size[1], zlib.decompress(idat)


def test_the_png_is_a_valid_image_coloured_by_success(tmp_path: Path):
    results = [_result({"y": 0.1}, True), _result({"y": 0.2}, False, "/t.yaml:3: x")]
    report = SweepReport("t", (("y", (0.1, 0.2)),), tuple(results), 1.0)
    write_png(report, tmp_path / "s.png", 200, 100)
    width, height, raw = _read_png(tmp_path / "s.png")
    assert (width, height) == (200, 100) and len(raw) == height * (1 + 3 * width)
    row = raw[(height - 41 - 5) * (1 + 3 * width):][:1 + 3 * width]  # just above the x axis
    pixels = {bytes(row[1 + 3 * x:4 + 3 * x]) for x in range(width)}
    assert bytes((220, 60, 60)) not in pixels  # a failed value draws no bar...
    green = bytes((40, 200, 60))
    assert green in pixels  # ...a passed one a full green bar


def test_a_sweep_reports_success_per_value_and_writes_its_files(tmp_path: Path, capsys):
    task = tmp_path / "wave.yaml"
    task.write_text(textwrap.dedent(f"""\
    task: wave
    cell: {CELL}
    parameters:
      pose: {{default: home, type: str}}
    steps:
      - go: {{group: arm, to: "${{pose}}"}}
    expect:
      groups: {{arm: {{at: home}}}}
    """), encoding="utf-8")
    args = argparse.Namespace(task=str(task), param=["pose=home,Candle"], seeds=2,
                              backend="mock", speed=None, jobs=2, out=str(tmp_path / "out"),
                              ray=None)
    assert sweep_command(args) == 1  # Candle never ends at home
    out = capsys.readouterr().out
    assert "        home       2/2       100 %" in out
    assert "      Candle       0/2         0 %" in out
    assert f"2 x  {task}:8: expectation not met: group 'arm' expected at 'home'" in out
    with (tmp_path / "out" / "results.csv").open(encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert [(r["pose"], r["seed"], r["verdict"]) for r in rows] == [
        ("home", "0", "passed"), ("home", "1", "passed"),
        ("Candle", "0", "failed"), ("Candle", "1", "failed")]
    assert rows[2]["step"] == f"{task}:8"
    page = (tmp_path / "out" / "sweep.html").read_text(encoding="utf-8")
    assert "<svg" in page and "By pose" in page and "2 of 4 runs passed" in page
    assert _read_png(tmp_path / "out" / "success.png")[:2] == (640, 360)


def _without_wall_clock_expectation(task: Path, into: Path) -> Path:
    """A copy of ``task`` without its ``duration`` expectation: task time counts waits for
    plans at wall time, so on a busy machine (4 spinning processes) a case may meet it in
    one runner and not in the other; every other expectation depends on the seed alone."""
    text = task.read_text(encoding="utf-8")
    lines = [line for line in text.splitlines(keepends=True)
             if not line.strip().startswith("duration:")]
    assert len(lines) == len(text.splitlines()) - 1, "the task has no duration expectation"
    copy = into / task.name
    copy.write_text("".join(lines).replace("cell: ../robots/cells/servo_arm_table.yaml",
                                           f"cell: {CELL}"), encoding="utf-8")
    return copy


def test_a_sweep_on_ray_gives_the_process_pools_results(tmp_path: Path, monkeypatch):
    ray = pytest.importorskip("ray", reason="ray is not installed (pip install "
                                            "-e '.[ray]')")
    path = _without_wall_clock_expectation(Path(resources.resolve_task("pick_place")), tmp_path)
    # Out to the arm's reach: the far drop spots fail their place.
    axis = parse_axis("place_x=0.10:0.25:25", {"place_x": "float"})
    cases = sweep_cases(path, "pick_place", [axis], 2, ["mock"], None)
    assert len(cases) == 50
    pool = run_cases(cases, jobs=2)
    # Ray runs its workers at nice 15 unless told otherwise: beside 4 spinning processes
    # they had 1.5 % of a core each (the 50 cases took over 10 min). The pool's workers
    # run at nice 0; so do Ray's here.
    monkeypatch.setenv("RAY_worker_niceness", "0")
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        on_ray = run_cases(cases, ray="local")
    finally:
        ray.shutdown()
    # the same verdicts and reasons (a message's timings, 34 ms or 95 ms, may differ)
    assert [(r.case.scenario, r.verdict, _step_and_reason(r.failure)) for r in on_ray] == \
        [(r.case.scenario, r.verdict, _step_and_reason(r.failure)) for r in pool]
    assert {r.verdict for r in pool} == {"passed", "failed"}  # the sweep can tell them apart
