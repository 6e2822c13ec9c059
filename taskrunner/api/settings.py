"""Settings of the API server, built once from arguments or the environment.

Environment variables (all optional):

- ``TASKRUNNER_TOKEN``: the bearer token; with none, :func:`api.app.create_app` makes one.
- ``TASKRUNNER_NO_AUTH=1``: run open (no token at all).
- ``TASKRUNNER_READ_REQUIRES_AUTH=1``: GET endpoints need the token too.
- ``TASKRUNNER_TASKS_DIR``, ``TASKRUNNER_CELLS_DIR``, ``TASKRUNNER_STATE_DIR``: folders.
- ``TASKRUNNER_MAX_BODY_BYTES``: largest accepted request body (bytes).
- ``TASKRUNNER_PLANNER``: ``worker`` (a planning process per run, default) or ``inprocess``.
- ``TASKRUNNER_PLANNER_NICE``: how much lower the planning workers' CPU priority is (10).
- ``TASKRUNNER_SIM_SPEED``: time scale of the simulated backend (2: twice real time).
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from taskrunner import resources

__all__ = ["Settings"]

PLANNERS = ("worker", "inprocess")


@dataclass(frozen=True)
class Settings:
    """How the server runs.

    Attributes:
        token: the bearer token required by endpoints that move a robot or change state;
            None with ``auth`` on: the app makes one at start (``app.state.token``).
        auth: False runs open (the CLI's ``--no-auth``): no endpoint needs a token.
        read_requires_auth: GET endpoints need the token too.
        tasks_dir: task files that ``POST /runs`` and ``/tasks/check`` name by file name.
        cells_dir: cell files; a cell's id is its file name without ``.yaml``.
        state_dir: where the run database lives (``runs.sqlite``).
        max_body_bytes: larger request bodies are refused with 413.
        planner: ``worker`` plans in a process per run (the event loop and the other runs
            keep going while OMPL searches); ``inprocess`` plans in the run's thread
            (tests: no process start-up).
        planner_nice: how much lower the planning workers' CPU priority is than the
            server's (Unix ``nice``, 0 to 19): planning gets the cycles the server and
            the runs' execution leave, and cannot slow their answers.
        sim_speed: default time scale of the sim backend.
        mock_speed: default replay speed of the mock backend (None: motions end at once).
        tick_hz: behaviour-tree ticks per second.
        shutdown_timeout_s: how long shutdown waits for cancelled runs to stop (s).
    """

    token: str | None = None
    auth: bool = True
    read_requires_auth: bool = False
    tasks_dir: Path = field(default_factory=resources.tasks_dir)
    cells_dir: Path = field(default_factory=resources.cells_dir)
    state_dir: Path = Path("state")
    max_body_bytes: int = 1_000_000
    planner: str = "worker"
    planner_nice: int = 10
    sim_speed: float = 1.0
    mock_speed: float | None = None
    tick_hz: float = 100.0
    shutdown_timeout_s: float = 10.0

    def __post_init__(self) -> None:
        for name in ("tasks_dir", "cells_dir", "state_dir"):
            object.__setattr__(self, name, Path(getattr(self, name)).resolve())
        if self.token is not None and len(self.token) < 8:
            raise ValueError(f"'token' must be at least 8 characters (got {len(self.token)})")
        if isinstance(self.max_body_bytes, bool) or not isinstance(self.max_body_bytes, int) \
                or self.max_body_bytes < 1:
            raise ValueError(f"'max_body_bytes' must be a positive integer "
                             f"(got {self.max_body_bytes!r})")
        if self.planner not in PLANNERS:
            raise ValueError(f"'planner' must be one of {', '.join(PLANNERS)} "
                             f"(got {self.planner!r})")
        if isinstance(self.planner_nice, bool) or not isinstance(self.planner_nice, int) \
                or not 0 <= self.planner_nice <= 19:
            raise ValueError(f"'planner_nice' must be an integer from 0 to 19 "
                             f"(got {self.planner_nice!r})")
        for name in ("sim_speed", "tick_hz", "shutdown_timeout_s"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise ValueError(f"'{name}' must be a positive number (got {value!r})")
        if self.mock_speed is not None and not self.mock_speed > 0:
            raise ValueError(f"'mock_speed' must be a positive number (got {self.mock_speed!r})")

    @property
    def db_path(self) -> Path:
        """The SQLite file of the run records."""
        return self.state_dir / "runs.sqlite"

    @classmethod
    def from_env(cls, environ: Mapping[str, str] | None = None, **overrides: object) -> Settings:
        """Settings from ``TASKRUNNER_*`` variables; ``overrides`` win over them."""
        env = os.environ if environ is None else environ
        values: dict[str, object] = {}
        if env.get("TASKRUNNER_TOKEN"):
            values["token"] = env["TASKRUNNER_TOKEN"]
        if "TASKRUNNER_NO_AUTH" in env:
            values["auth"] = not _flag(env["TASKRUNNER_NO_AUTH"])
        if "TASKRUNNER_READ_REQUIRES_AUTH" in env:
            values["read_requires_auth"] = _flag(env["TASKRUNNER_READ_REQUIRES_AUTH"])
        for key, name in (("TASKS_DIR", "tasks_dir"), ("CELLS_DIR", "cells_dir"),
                          ("STATE_DIR", "state_dir"), ("PLANNER", "planner")):
            if env.get(f"TASKRUNNER_{key}"):
                values[name] = env[f"TASKRUNNER_{key}"]
        for key, name, kind in (("MAX_BODY_BYTES", "max_body_bytes", int),
                                ("PLANNER_NICE", "planner_nice", int),
                                ("SIM_SPEED", "sim_speed", float)):
            text = env.get(f"TASKRUNNER_{key}")
            if text:
                try:
                    values[name] = kind(text)
                except ValueError:
                    raise ValueError(f"TASKRUNNER_{key} must be "
                                     f"{'an integer' if kind is int else 'a number'} "
                                     f"(got {text!r})") from None
        values.update({k: v for k, v in overrides.items() if v is not None})
        return cls(**values)  # type: ignore[arg-type]


def _flag(value: str) -> bool:
    return value.strip().lower() in ("1", "true", "yes", "on")
