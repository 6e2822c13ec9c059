"""``run-task sweep TASK``: how robust a task is over its parameters, seeds and backends.

The cases are the Cartesian product of parameter values (``--param place_y=-0.15:0.15:31``:
31 values from -0.15 to 0.15 inclusive; ``--param pose=home,Candle``: a list), seeds
``0..N-1`` and backends; each runs like a ``run-task test`` case
(:func:`taskrunner.runtime.testing.run_cases`: a process pool, or Ray) and passes when
its run meets the task's ``expect:``. The report:

- the success rate per value of each swept parameter (and per seed and backend);
- failure reasons clustered by step (file:line) and message, numbers normalised
  (``12.3 mm`` and ``7.1 mm`` are one reason);
- ``results.csv`` (one row per run; ``results.parquet`` too when pyarrow is installed);
- ``success.png``: success over the parameter space, a raster drawn here with the
  standard library (``zlib`` + ``struct``; bars for one parameter, a grid for two or
  more — the first two parameters, the others pooled), no text in it;
- ``sweep.html``: the same plot as labelled SVG, with the tables.
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import html
import itertools
import math
import os
import re
import struct
import sys
import time
import zlib
from collections import Counter, defaultdict
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from taskrunner.errors import InputError
from taskrunner.runtime.testing import Case, CaseResult, run_cases

__all__ = ["SweepReport", "cluster_failures", "parse_axis", "sweep_cases", "sweep_command",
           "write_png", "write_report"]


def _typed(text: str, kind: str, name: str) -> Any:
    text = text.strip()
    try:
        if kind == "float":
            return float(text)
        if kind == "int":
            return int(text)
        if kind == "bool":
            lowered = text.lower()
            if lowered in ("true", "yes", "on", "1"):
                return True
            if lowered in ("false", "no", "off", "0"):
                return False
            raise InputError(f"'--param {name}' values must be {kind}s (got {text!r})")
    except ValueError:
        raise InputError(f"'--param {name}' values must be {kind}s (got {text!r})") from None
    return text


def parse_axis(spec: str, types: Mapping[str, str]) -> tuple[str, list[Any]]:
    """``NAME=START:STOP:COUNT`` (COUNT values, both ends included) or ``NAME=A,B,C``,
    typed as the task declares parameter NAME (``types``: name -> float|int|bool|str).

    Raises:
        InputError: bad syntax, an undeclared parameter, a value of the wrong type.
    """
    name, sep, values = spec.partition("=")
    name = name.strip()
    if not sep or not name or not values.strip():
        raise InputError(f"'--param' must be NAME=START:STOP:COUNT or NAME=A,B,... "
                         f"(got {spec!r})")
    if name not in types:
        raise InputError(f"'--param {name}': the task has no parameter {name!r} "
                         f"(parameters: {', '.join(types) or 'none'})")
    kind = types[name]
    if ":" in values:
        parts = values.split(":")
        if len(parts) != 3 or kind not in ("float", "int"):
            raise InputError(f"'--param {name}' range must be START:STOP:COUNT of a number "
                             f"parameter (got {values!r}, a {kind})")
        start, stop = (_typed(p, "float", name) for p in parts[:2])
        count = _typed(parts[2], "int", name)
        if count < 1:
            raise InputError(f"'--param {name}' COUNT must be >= 1 (got {count})")
        points = [start] if count == 1 else [
            start + (stop - start) * k / (count - 1) for k in range(count)]
        if kind == "int":
            if any(abs(p - round(p)) > 1e-9 for p in points):
                raise InputError(f"'--param {name}' is an int: {values!r} has values between "
                                 "integers")
            return name, [int(round(p)) for p in points]
        return name, [round(p, 12) for p in points]
    return name, [_typed(v, kind, name) for v in values.split(",")]


def sweep_cases(path: Path, task: str, axes: Sequence[tuple[str, list[Any]]], seeds: int,
                backends: Sequence[str], speed: float | None) -> list[Case]:
    """The product of the axes' values, seeds ``0..seeds-1`` and backends, as cases."""
    cases = []
    names = [n for n, _ in axes]
    for values in itertools.product(*(v for _, v in axes)):
        for backend in backends:
            for seed in range(seeds):
                params = dict(zip(names, values))
                label = " ".join([*(f"{k}={v}" for k, v in params.items()), f"seed={seed}",
                                  backend])
                cases.append(Case(path, task, label, params, seed, backend, speed))
    return cases


_NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?(?!\w)")  # not in names
_LOCATION = re.compile(r"^(?P<where>\S+?:\d+): ")


def _step_and_reason(failure: str | None) -> tuple[str, str]:
    """``(file:line of the first failing step, the message with numbers as #)``."""
    text = failure or "(no message)"
    match = _LOCATION.match(text)
    where = match.group("where") if match else "-"
    rest = text[match.end():] if match else text
    # an end-of-run expectation quotes the step's error: cluster on that step instead
    inner = _LOCATION.search(rest.split("; it failed (", 1)[-1]) if "; it failed (" in rest \
        else None
    if inner:
        where = inner.group("where")
    # quoted names ('Revolute 1', 'cube_2') keep their digits
    parts = re.split(r"('[^']*')", rest)
    return where, "".join(p if p.startswith("'") else _NUMBER.sub("#", p) for p in parts)


def cluster_failures(results: Sequence[CaseResult]) -> list[tuple[str, str, int]]:
    """Failure reasons, most frequent first: ``(step file:line, message with numbers
    normalised, count)``."""
    counts = Counter(_step_and_reason(r.failure) for r in results if not r.passed)
    return [(where, reason, n) for (where, reason), n in counts.most_common()]


@dataclass(frozen=True)
class SweepReport:
    """What a sweep found (the results in case order, the axes swept)."""

    task: str
    axes: tuple[tuple[str, tuple[Any, ...]], ...]
    results: tuple[CaseResult, ...]
    seconds: float

    def rates(self, key: str) -> list[tuple[Any, int, int]]:
        """``(value, passed, runs)`` for each value of parameter (or ``seed``,
        ``backend``) ``key``, in sweep order."""
        tally: dict[Any, list[int]] = defaultdict(lambda: [0, 0])
        for r in self.results:
            value = {"seed": r.case.seed, "backend": r.case.backend}.get(
                key, r.case.parameters.get(key))
            tally[value][0] += r.passed
            tally[value][1] += 1
        return [(v, p, n) for v, (p, n) in tally.items()]

    def grid(self) -> tuple[list[Any], list[Any], dict[tuple[Any, Any], float]]:
        """Success rate over the first two axes (one axis: a single row)."""
        xs = list(self.axes[0][1]) if self.axes else [None]
        ys = list(self.axes[1][1]) if len(self.axes) > 1 else [None]
        tally: dict[tuple[Any, Any], list[int]] = defaultdict(lambda: [0, 0])
        for r in self.results:
            x = r.case.parameters.get(self.axes[0][0]) if self.axes else None
            y = r.case.parameters.get(self.axes[1][0]) if len(self.axes) > 1 else None
            tally[(x, y)][0] += r.passed
            tally[(x, y)][1] += 1
        return xs, ys, {k: p / n for k, (p, n) in tally.items()}


# ------------------------------------------------------------------------------ PNG
def _png(width: int, height: int, rgb: bytearray) -> bytes:
    """An 8-bit RGB PNG (filter 0 on every row)."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    rows = b"".join(b"\x00" + bytes(rgb[y * width * 3:(y + 1) * width * 3])
                    for y in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2,
                                                              0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def _colour(rate: float | None) -> tuple[int, int, int]:
    """Red (0) through yellow to green (1); grey: no run."""
    if rate is None or math.isnan(rate):
        return (200, 200, 200)
    if rate < 0.5:
        return (220, int(60 + 340 * rate), 60)
    return (int(220 - 360 * (rate - 0.5)), 200, 60)


def write_png(report: SweepReport, path: Path, width: int = 640, height: int = 360) -> None:
    """``success.png``: bars of the success rate per value (one axis) or a grid of cells
    coloured by success rate (two axes and more: the first two, the others pooled)."""
    rgb = bytearray(b"\xff" * (width * height * 3))

    def rect(x0: int, y0: int, x1: int, y1: int, c: tuple[int, int, int]) -> None:
        for y in range(max(0, y0), min(height, y1)):
            row = y * width * 3
            rgb[row + 3 * max(0, x0):row + 3 * min(width, x1)] = bytes(c) * max(
                0, min(width, x1) - max(0, x0))

    left, right, top, bottom = 40, 20, 20, 40
    plot_w, plot_h = width - left - right, height - top - bottom
    xs, ys, rates = report.grid()
    if len(ys) == 1:  # bars, height = success rate, with 0 %, 50 %, 100 % grid lines
        for frac in (0.0, 0.5, 1.0):
            y = top + int(plot_h * (1 - frac))
            rect(left, y, left + plot_w, y + 1, (210, 210, 210))
        slot = plot_w / max(1, len(xs))
        for i, x in enumerate(xs):
            rate = rates.get((x, ys[0]))
            h = int(plot_h * (rate or 0.0))
            x0 = left + int(i * slot + slot * 0.1)
            x1 = left + int((i + 1) * slot - slot * 0.1)
            rect(x0, top + plot_h - max(h, 1), max(x1, x0 + 1), top + plot_h, _colour(rate))
    else:
        cw, ch = plot_w / len(xs), plot_h / len(ys)
        for i, x in enumerate(xs):
            for j, y in enumerate(ys):
                rect(left + int(i * cw), top + plot_h - int((j + 1) * ch),
                     left + int((i + 1) * cw) - 1, top + plot_h - int(j * ch) - 1,
                     _colour(rates.get((x, y))))
    rect(left - 2, top, left, top + plot_h + 2, (0, 0, 0))           # y axis
    rect(left - 2, top + plot_h, left + plot_w, top + plot_h + 2, (0, 0, 0))  # x axis
    path.write_bytes(_png(width, height, rgb))


# ------------------------------------------------------------------------- SVG, HTML
def _svg(report: SweepReport, width: int = 640, height: int = 360) -> str:
    left, right, top, bottom = 60, 20, 20, 50
    plot_w, plot_h = width - left - right, height - top - bottom
    xs, ys, rates = report.grid()
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="11">']
    step = max(1, len(xs) // 8)
    if len(ys) == 1:
        slot = plot_w / max(1, len(xs))
        for frac in (0.0, 0.5, 1.0):
            y = top + plot_h * (1 - frac)
            out.append(f'<line x1="{left}" x2="{left + plot_w}" y1="{y:.1f}" y2="{y:.1f}" '
                       f'stroke="#ddd"/><text x="{left - 6}" y="{y + 4:.1f}" '
                       f'text-anchor="end">{int(frac * 100)} %</text>')
        for i, x in enumerate(xs):
            rate = rates.get((x, ys[0]))
            h = plot_h * (rate or 0.0)
            r, g, b = _colour(rate)
            out.append(f'<rect x="{left + i * slot + slot * 0.1:.1f}" y="{top + plot_h - h:.1f}"'
                       f' width="{slot * 0.8:.1f}" height="{max(h, 1):.1f}" '
                       f'fill="rgb({r},{g},{b})"><title>{html.escape(str(x))}: '
                       f'{100 * (rate or 0):.0f} %</title></rect>')
            if i % step == 0:
                out.append(f'<text x="{left + (i + 0.5) * slot:.1f}" y="{top + plot_h + 16}" '
                           f'text-anchor="middle">{html.escape(_short(x))}</text>')
    else:
        cw, ch = plot_w / len(xs), plot_h / len(ys)
        for i, x in enumerate(xs):
            for j, y in enumerate(ys):
                rate = rates.get((x, y))
                r, g, b = _colour(rate)
                out.append(f'<rect x="{left + i * cw:.1f}" y="{top + plot_h - (j + 1) * ch:.1f}"'
                           f' width="{cw:.1f}" height="{ch:.1f}" fill="rgb({r},{g},{b})" '
                           f'stroke="#fff"><title>{html.escape(_short(x))}, '
                           f'{html.escape(_short(y))}: {100 * (rate or 0):.0f} %</title></rect>')
            if i % step == 0:
                out.append(f'<text x="{left + (i + 0.5) * cw:.1f}" y="{top + plot_h + 16}" '
                           f'text-anchor="middle">{html.escape(_short(x))}</text>')
        ystep = max(1, len(ys) // 8)
        for j, y in enumerate(ys):
            if j % ystep == 0:
                out.append(f'<text x="{left - 6}" y="{top + plot_h - (j + 0.5) * ch + 4:.1f}" '
                           f'text-anchor="end">{html.escape(_short(y))}</text>')
        out.append(f'<text x="14" y="{top + plot_h / 2:.1f}" transform="rotate(-90 14 '
                   f'{top + plot_h / 2:.1f})" text-anchor="middle">'
                   f'{html.escape(report.axes[1][0])}</text>')
    xname = report.axes[0][0] if report.axes else "(no parameter)"
    out.append(f'<text x="{left + plot_w / 2:.1f}" y="{height - 8}" text-anchor="middle">'
               f'{html.escape(xname)}</text></svg>')
    return "\n".join(out)


def _short(value: Any) -> str:
    return f"{value:.4g}" if isinstance(value, float) else str(value)


def _table(head: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    cells = "".join(f"<th>{html.escape(h)}</th>" for h in head)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in row) + "</tr>"
                   for row in rows)
    return f"<table><tr>{cells}</tr>{body}</table>"


def _html(report: SweepReport) -> str:
    passed = sum(r.passed for r in report.results)
    parts = [f"<!doctype html><html><head><meta charset='utf-8'><title>sweep "
             f"{html.escape(report.task)}</title><style>body{{font-family:sans-serif;"
             "margin:2em}td,th{padding:2px 8px;text-align:left}table{border-collapse:collapse;"
             "margin-bottom:1.5em}tr:nth-child(even){background:#f4f4f4}</style></head><body>",
             f"<h1>Sweep of {html.escape(report.task)}</h1>",
             f"<p>{passed} of {len(report.results)} runs passed in {report.seconds:.1f} s. "
             "Success means the run met the task's <code>expect:</code>.</p>",
             _svg(report), '<p><img src="success.png" alt="success over the parameter '
             'space (raster)"></p>']
    for name in [n for n, _ in report.axes] + ["seed", "backend"]:
        rows = [(_short(v), p, n, f"{100 * p / n:.0f} %") for v, p, n in report.rates(name)]
        parts += [f"<h2>By {html.escape(name)}</h2>",
                  _table([name, "passed", "runs", "success"], rows)]
    clusters = cluster_failures(report.results)
    if clusters:
        parts += ["<h2>Failure reasons</h2>",
                  _table(["count", "step", "reason (numbers as #)"],
                         [(n, w, r) for w, r, n in clusters])]
    return "\n".join(parts) + "</body></html>\n"


# ---------------------------------------------------------------------------- files
def write_report(report: SweepReport, out: Path) -> list[Path]:
    """``results.csv`` (and ``results.parquet`` with pyarrow), ``success.png``,
    ``sweep.html`` in ``out``; returns the paths written."""
    out.mkdir(parents=True, exist_ok=True)
    names = [n for n, _ in report.axes]
    head = [*names, "seed", "backend", "verdict", "status", "seconds", "attempts", "step",
            "reason", "failure"]
    rows = []
    for r in report.results:
        step, reason = _step_and_reason(r.failure) if not r.passed else ("", "")
        rows.append([*(r.case.parameters.get(n) for n in names), r.case.seed, r.case.backend,
                     r.verdict, r.status or "", round(r.seconds, 3), r.attempts, step, reason,
                     r.failure or ""])
    written = [out / "results.csv"]
    with written[0].open("w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f)
        writer.writerow(head)
        writer.writerows(rows)
    try:
        import pyarrow as pa  # type: ignore[import-not-found]
        import pyarrow.parquet as pq  # type: ignore[import-not-found]
    except ImportError:
        pass
    else:
        table = pa.table({h: [row[k] for row in rows] for k, h in enumerate(head)})
        pq.write_table(table, out / "results.parquet")
        written.append(out / "results.parquet")
    write_png(report, out / "success.png")
    (out / "sweep.html").write_text(_html(report), encoding="utf-8")
    return [*written, out / "success.png", out / "sweep.html"]


def format_report(report: SweepReport) -> str:
    """The text report: success per value of each axis, then the failure clusters."""
    lines = []
    for name in [n for n, _ in report.axes] + ["seed", "backend"]:
        rates = report.rates(name)
        if name in ("seed", "backend") and len(rates) == 1:
            continue
        lines.append(f"{name:>12}  passed/runs  success")
        for value, p, n in rates:
            bar = "#" * round(20 * p / n)
            lines.append(f"{_short(value):>12}  {p:>6}/{n:<4}  {100 * p / n:5.0f} %  {bar}")
        lines.append("")
    clusters = cluster_failures(report.results)
    if clusters:
        lines.append("failure reasons (numbers as #), most frequent first:")
        for where, reason, n in clusters:
            lines.append(f"  {n:>4} x  {where}: {reason[:160]}")
    passed = sum(r.passed for r in report.results)
    lines.append(f"{passed} of {len(report.results)} runs passed in {report.seconds:.1f} s")
    return "\n".join(lines)


def sweep_command(args: argparse.Namespace, out_stream: Any = None) -> int:
    """``run-task sweep``: 0 when every run passed, 1 otherwise, 2 for bad arguments."""
    from taskrunner.resources import resolve_task
    from taskrunner.tasks.loader import load_task

    stream = out_stream or sys.stdout
    path = resolve_task(args.task)
    spec = load_task(path)
    types = {name: p.type for name, p in spec.parameters.items()}
    axes = [parse_axis(s, types) for s in args.param]
    if len({n for n, _ in axes}) != len(axes):
        raise InputError("'--param': each parameter may be swept once")
    backends = [b.strip() for b in str(args.backend).split(",") if b.strip()]
    bad = [b for b in backends if b not in ("mock", "sim", "mujoco")]
    if bad or not backends:
        raise InputError(f"'--backend' must be mock, sim or mujoco, comma-separated "
                         f"(got {args.backend!r})")
    if args.seeds < 1:
        raise InputError(f"'--seeds' must be >= 1 (got {args.seeds})")
    cases = sweep_cases(path, spec.name, axes, args.seeds, backends, args.speed)
    options = getattr(args, "load_options", None)
    if options is not None:  # how every run loads its robots (--package-path …)
        cases = [dataclasses.replace(c, load_options=options.as_data()) for c in cases]
    where = f"Ray ({args.ray})" if args.ray else f"{args.jobs or os.cpu_count()} worker(s)"
    print(f"sweeping {spec.name}: {len(cases)} runs on {where}", file=stream, flush=True)
    started = time.monotonic()
    results = run_cases(cases, args.jobs, args.ray)
    report = SweepReport(spec.name, tuple((n, tuple(v)) for n, v in axes), tuple(results),
                         time.monotonic() - started)
    print(format_report(report), file=stream)
    stamp = datetime.now(UTC).strftime("%Y%m%dT%H%M%S")
    out = Path(args.out) if args.out else Path("sweeps") / f"{spec.name}-{stamp}"
    for written in write_report(report, out):
        print(f"wrote {written}", file=stream)
    return 0 if all(r.passed for r in results) else 1
