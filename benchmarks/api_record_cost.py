"""What recording an event costs the API server, at the start of a long run and at its end.

    python benchmarks/api_record_cost.py [--events 5000] [--window 100] [--json]

A run of ``--events`` events (a step's shape: node_started, planned, motion,
node_finished, with the figures a real run carries) is emitted through an
:class:`~taskrunner.runtime.events.EventLog` whose journal appends to a
:class:`~taskrunner.api.store.RunStore` in a temporary folder, as ``RunManager`` does.
For the first and the last ``--window`` events it reports the time ``emit`` took (what
the run's thread waits), median and p99, for:

* ``append (NORMAL)``: what the server does: one ``INSERT`` a commit, WAL with
  ``synchronous=NORMAL`` (no fsync; survives a killed process), the WAL fsync'd at each
  ``planned`` event of a motion;
* ``append, fsync each``: every commit fsync'd (``synchronous=FULL``), for comparison;
* ``whole record at node_finished``: the previous design, the record with all its events
  rewritten into the runs row at every ``node_finished``.

It also times ``GET /runs/{id}`` bodies of the recorded run from the database: the
default page (the first 1000 events) and a page of 100 at the end (``?since=``).

Times are wall-clock on whatever machine runs it; the test
``tests/api/test_record_append.py`` pins the count (one statement an event, the same at
event 100 and 5,000). Prints a table and, with ``--json``, one JSON line at the end.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from taskrunner.api.detail import StoredDetails
from taskrunner.api.store import RunStore, StoreJournal
from taskrunner.runtime.events import EventLog, RunEvent
from taskrunner.runtime.records import RunRecord

STEP = ("node_started", "planned", "motion", "node_finished")


def emit_step_event(log: EventLog, k: int) -> None:
    kind = STEP[k % len(STEP)]
    node = f"go arm {k // len(STEP)}"
    if kind == "planned":
        log.emit(kind, node=node, location="loop.yaml:7", duration=1.2, planning_time=0.03,
                 waypoints=40)
    elif kind == "motion":
        log.emit(kind, node=node, location="loop.yaml:7",
                 trajectory={"joint_names": [f"j{i}" for i in range(6)],
                             "t": [0.1 * i for i in range(10)],
                             "q": [[0.01 * i] * 6 for i in range(10)]})
    elif kind == "node_finished":
        log.emit(kind, node=node, location="loop.yaml:7", status="SUCCESS")
    else:
        log.emit(kind, node=node, location="loop.yaml:7")


def run_once(folder: Path, name: str, events: int,
             wire: Callable[[RunStore, RunRecord, EventLog], None]) -> tuple[list[float],
                                                                                  RunStore]:
    store = RunStore(folder / f"{name}.sqlite")
    record = RunRecord(run_id=name, task="loop", task_file="loop.yaml", cell="servo_arm_table",
                       backend="sim", parameters={})
    log = EventLog()
    log.subscribe(record.events.append)
    wire(store, record, log)
    store.save(record)
    times = []
    for k in range(events):
        started = time.perf_counter()
        emit_step_event(log, k)
        times.append(time.perf_counter() - started)
    record.status = "succeeded"
    store.save(record, events=())
    return times, store


def journal_normal(store: RunStore, record: RunRecord, log: EventLog) -> None:
    log.set_journal(StoreJournal(store, record.run_id))


def journal_fsync_each(store: RunStore, record: RunRecord, log: EventLog) -> None:
    def append(event: RunEvent) -> None:
        store.append_event(record.run_id, event, durable=True)

    log.set_journal(append)


def whole_record(store: RunStore, record: RunRecord, log: EventLog) -> None:
    def save(event: RunEvent) -> None:  # the design before: all events, again and again
        if event.kind in ("run_started", "node_finished"):
            with store._lock:
                store._db.execute(
                    "UPDATE runs SET record = ? WHERE run_id = ?",
                    (json.dumps(record.as_dict()), record.run_id))

    log.subscribe(save)


def stats(times: list[float]) -> dict[str, float]:
    ordered = sorted(times)
    return {"median_us": round(statistics.median(ordered) * 1e6, 1),
            "p99_us": round(ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))] * 1e6, 1),
            "mean_us": round(statistics.fmean(ordered) * 1e6, 1)}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--events", type=int, default=5000)
    parser.add_argument("--window", type=int, default=100)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    if args.window * 2 > args.events:
        parser.error("--window must be at most half of --events")
    results: dict[str, object] = {"events": args.events, "window": args.window}
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for name, wire in (("append (NORMAL)", journal_normal),
                           ("append, fsync each", journal_fsync_each),
                           ("whole record at node_finished", whole_record)):
            times, store = run_once(folder, name.split()[0] + str(len(rows)), args.events, wire)
            first, last = stats(times[:args.window]), stats(times[-args.window:])
            results[name] = {"first": first, "last": last,
                             "total_s": round(sum(times), 3)}
            rows.append((name, first, last, sum(times)))
            if wire is journal_normal:
                run_id = store.summaries()[0]["run_id"]
                details = StoredDetails(store)
                pages = {}
                for label, since, limit in (("default page (1000)", 0, 1000),
                                            ("last 100 (?since=)", args.events - 100, 100)):
                    spent = []
                    for _ in range(20):
                        details._cache.clear()
                        started = time.perf_counter()
                        body = details.body(str(run_id), since, limit)
                        spent.append(time.perf_counter() - started)
                    pages[label] = {"ms": round(statistics.median(spent) * 1e3, 2),
                                    "bytes": len(body or b"")}
                results["pages"] = pages
            store.close()
    print(f"{args.events} events; emit() time for the first and the last {args.window}")
    print(f"{'recording':32} {'first med':>10} {'first p99':>10} {'last med':>10} "
          f"{'last p99':>10} {'total':>8}")
    for name, first, last, total in rows:
        print(f"{name:32} {first['median_us']:>8.1f}us {first['p99_us']:>8.1f}us "
              f"{last['median_us']:>8.1f}us {last['p99_us']:>8.1f}us {total:>7.2f}s")
    for label, page in results["pages"].items():  # type: ignore[union-attr]
        print(f"GET /runs/{{id}} {label:22} {page['ms']:>7.2f} ms {page['bytes']:>9} bytes")
    if args.json:
        print(json.dumps(results))
    return 0


if __name__ == "__main__":
    sys.exit(main())
