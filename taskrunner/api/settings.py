"""Settings of the API server: one :class:`Settings`, from arguments or ``TASKRUNNER_*``.

Every field is settable from the environment as ``TASKRUNNER_<FIELD>`` (upper case):
``TASKRUNNER_TOKEN``, ``TASKRUNNER_OPEN_READS=1``, ``TASKRUNNER_DATA_DIR``,
``TASKRUNNER_ROBOTS_DIRS`` (folders separated by ``:``), ``TASKRUNNER_CHECK_TIMEOUT_S`` …
Two older names are still read: ``TASKRUNNER_NO_AUTH=1`` (``auth`` off) and
``TASKRUNNER_STATE_DIR`` (``data_dir``).
"""

from __future__ import annotations

import contextvars
import math
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Annotated, Any

from pydantic import ValidationError, field_validator, model_validator
from pydantic_settings import BaseSettings, EnvSettingsSource, NoDecode, SettingsConfigDict

from taskrunner import resources
from taskrunner.errors import ArgumentError
from taskrunner.folders import FolderPolicy
from taskrunner.kinds import CollisionChoice
from taskrunner.robot.options import LoadOptions

__all__ = ["Settings"]

PLANNERS = ("worker", "inprocess")
ISOLATIONS = ("process", "inprocess")
_FLAG_TRUE = ("1", "true", "yes", "on")


class Settings(BaseSettings):
    """How the server runs.

    Attributes:
        token: the bearer token; None with ``auth`` on: the app makes one at start
            (``app.state.token``).
        auth: False runs open (the CLI's ``--no-auth``): no endpoint needs a token.
        open_reads: reads (``GET`` runs, cells, events) answer without the token. Off by
            default: every endpoint but ``/health`` and the OpenAPI docs needs it.
        tasks_dir: task files that ``POST /runs`` and ``/tasks/check`` name by file
            name; tasks and their includes load only from here.
        cells_dir: cell files (a cell's id is its file name without ``.yaml``); cells
            load only from here.
        robots_dirs: the only folders robots (URDF, xacro: code) load from; default:
            the shipped robots. The cells folder is allowed too.
        package_path: folders searched for the ROS packages robots name
            (``package://``), as ``run-task run --package-path``; robots may load from
            them too (folders separated by ``os.pathsep`` in ``TASKRUNNER_PACKAGE_PATH``).
        data_dir: where the server keeps its data (the run database ``runs.sqlite``).
        max_body_bytes: larger request bodies are refused with 413.
        planner: ``worker`` plans in a process per run; ``inprocess`` in the run's
            thread (tests: no process start-up).
        planner_nice: how much lower the planning workers' CPU priority is (0 to 19).
        sim_speed: default time scale of the sim backend.
        mock_speed: default replay speed of the mock backend (None: motions end at once).
        tick_hz: behaviour-tree ticks per second.
        shutdown_timeout_s: how long shutdown waits for cancelled runs to stop (s).
        check_timeout_s: longest a request's task loading or check may take (s); past
            it the request answers 422 and the work is stopped.
        check_memory_mb: most memory a check process may use (MiB).
        check_isolation: ``process`` loads and checks request tasks in a worker
            process that is killed past the time limit; ``inprocess`` in a thread (the
            answer comes on time, the work runs on: tests).
        check_workers: how many checks run at once (more wait, within the time limit).
        plan_timeout_s: longest a ``/plan`` may take, planner start-up included (s).
        max_planners: how many plans and previews run at once (each holds a planning
            process); more wait in a queue.
        work_queue: how many more plans, previews or checks may wait for their turn;
            one more is answered 503 with ``Retry-After``, as is one that waited longer
            than its time limit (``plan_timeout_s``, ``check_timeout_s``).
        planner_idle_s: a planning process idle this long is closed (s).
        max_requests: how many requests the server answers at once, cancels, run
            states, ``/health`` and event streams not counted; one more is answered 503
            with ``Retry-After`` at once, so a flood of clients cannot queue ahead of a
            cancel.
        header_timeout_s: a connection must send its request headers within this (s).
        body_timeout_s: a request's body must be complete within this of its headers
            (s); past it the request is answered 408 and its connection closed.
        stream_max_lag: events that may come while an event stream's client takes one
            write; one more and it is dropped (told the ``Last-Event-ID`` to resume
            from).
        stream_send_timeout_s: an event stream whose client takes no bytes for this
            long is disconnected (s).
        servo_port: the serial port of the ``serial`` backend (default: the one in the
            robot's hardware.yaml).
        servo_url: the ESP32's ``/api/command`` URL for the ``http`` backend (none: the
            API offers no http backend). Requests never name a port or URL.
        firmware_speedup: the time scale of a host build of the firmware the servo
            backends drive (``run-task firmware-sim --speedup``); 1 for real servos.
        foxglove_port: serve the runs live over Foxglove's WebSocket protocol, one feed
            per cell on this port and the next ones (0: free ports; none: no feed; see
            :mod:`taskrunner.export.cellfeeds`).
        collision: the link geometry of every robot the server loads (``run-task serve
            --collision``; none: each robot's own choice).
        strict: every robot load warning is an error (``TASKRUNNER_STRICT=1``).
        allow_missing_meshes: load robots whose mesh files cannot be found without
            that geometry, with a warning (``TASKRUNNER_ALLOW_MISSING_MESHES=1``).
        These three and ``package_path`` reach the loaders and the planning workers as one
        :class:`~taskrunner.robot.options.LoadOptions` (:meth:`load_options`).
    """

    model_config = SettingsConfigDict(env_prefix="TASKRUNNER_", frozen=True, extra="forbid",
                                      case_sensitive=False)

    token: str | None = None
    auth: bool = True
    open_reads: bool = False
    tasks_dir: Path = resources.tasks_dir()
    cells_dir: Path = resources.cells_dir()
    robots_dirs: Annotated[tuple[Path, ...], NoDecode] = (resources.robots_dir(),)
    package_path: Annotated[tuple[Path, ...], NoDecode] = ()
    data_dir: Path = Path("state")
    max_body_bytes: int = 1_000_000
    planner: str = "worker"
    planner_nice: int = 10
    sim_speed: float = 1.0
    mock_speed: float | None = None
    tick_hz: float = 100.0
    shutdown_timeout_s: float = 10.0
    check_timeout_s: float = 20.0
    check_memory_mb: int = 2048
    check_isolation: str = "process"
    check_workers: int = 2
    plan_timeout_s: float = 60.0
    max_planners: int = 2
    work_queue: int = 8
    planner_idle_s: float = 120.0
    max_requests: int = 16
    header_timeout_s: float = 10.0
    body_timeout_s: float = 20.0
    stream_max_lag: int = 1000
    stream_send_timeout_s: float = 10.0
    servo_port: str | None = None
    servo_url: str | None = None
    firmware_speedup: float = 1.0
    foxglove_port: int | None = None
    collision: CollisionChoice | None = None
    strict: bool = False
    allow_missing_meshes: bool = False

    @model_validator(mode="before")
    @classmethod
    def _old_names(cls, data: Any) -> Any:
        if isinstance(data, dict) and "state_dir" in data:
            data = dict(data)
            value = data.pop("state_dir")
            data.setdefault("data_dir", value)
        return data

    @classmethod
    def settings_customise_sources(cls, settings_cls: type[BaseSettings], init_settings: Any,
                                   env_settings: Any, dotenv_settings: Any,
                                   file_secret_settings: Any) -> tuple[Any, ...]:
        environ = _ENVIRON.get()
        if environ is not None:  # from_env(environ): that mapping, not the process's
            env_settings = _MappingSource(settings_cls, environ)
        return init_settings, env_settings, _OldEnvNames(settings_cls, environ)

    # ------------------------------------------------------------------ checks
    @field_validator("token")
    @classmethod
    def _token(cls, value: str | None) -> str | None:
        if value is not None and len(value) < 8:
            raise ValueError(f"'token' must be at least 8 characters (got {len(value)})")
        return value or None

    @field_validator("collision", mode="before")
    @classmethod
    def _collision(cls, value: Any) -> Any:
        if value is None or value == "":
            return None
        if value not in tuple(CollisionChoice):
            raise ValueError(f"'collision' must be one of exact, convex, auto (got {value!r})")
        return value

    @field_validator("auth", "open_reads", "strict", "allow_missing_meshes", mode="before")
    @classmethod
    def _flag(cls, value: Any) -> Any:
        if isinstance(value, str):
            return value.strip().lower() in _FLAG_TRUE
        return value

    @field_validator("tasks_dir", "cells_dir", "data_dir")
    @classmethod
    def _folder(cls, value: Path) -> Path:
        return Path(value).resolve()

    @field_validator("robots_dirs", "package_path", mode="before")
    @classmethod
    def _folders(cls, value: Any, info: Any) -> Any:
        if isinstance(value, str | Path):
            value = [p for p in str(value).split(os.pathsep) if p]
        folders = tuple(Path(p).expanduser().resolve() for p in value)
        missing = [str(f) for f in folders if not f.is_dir()]
        if info.field_name == "package_path" and missing:
            raise ValueError(f"must be folders (not found: {', '.join(missing)})")
        return folders

    @field_validator("max_body_bytes", "check_memory_mb", "check_workers", "max_planners",
                     "work_queue", "stream_max_lag", "max_requests", mode="before")
    @classmethod
    def _int_at_least(cls, value: Any, info: Any) -> Any:
        least = 0 if info.field_name == "work_queue" else 1  # a queue may be empty
        number = _integer(value)
        if number is None or number < least:
            what = "a positive integer" if least == 1 else "an integer >= 0"
            raise ValueError(f"'{info.field_name}' must be {what} (got {value!r})")
        return number

    @field_validator("foxglove_port", mode="before")
    @classmethod
    def _foxglove_port(cls, value: Any) -> Any:
        if value is None or value == "":
            return None
        number = _integer(value)
        if number is None or not 0 <= number <= 65535:
            raise ValueError(f"'foxglove_port' must be a port 0..65535 (got {value!r})")
        return number

    @field_validator("planner_nice", mode="before")
    @classmethod
    def _nice(cls, value: Any) -> Any:
        number = _integer(value)
        if number is None or not 0 <= number <= 19:
            raise ValueError(f"'planner_nice' must be an integer from 0 to 19 (got {value!r})")
        return number

    @field_validator("sim_speed", "tick_hz", "shutdown_timeout_s", "check_timeout_s",
                     "plan_timeout_s", "header_timeout_s", "body_timeout_s",
                     "firmware_speedup",
                     "planner_idle_s", "stream_send_timeout_s", mode="before")
    @classmethod
    def _positive(cls, value: Any, info: Any) -> Any:
        number = _number(value)
        if number is None or not number > 0:
            raise ValueError(f"'{info.field_name}' must be a positive number (got {value!r})")
        return number

    @field_validator("mock_speed", mode="before")
    @classmethod
    def _optional_positive(cls, value: Any) -> Any:
        if value is None or value == "":
            return None
        number = _number(value)
        if number is None or not number > 0:
            raise ValueError(f"'mock_speed' must be a positive number (got {value!r})")
        return number

    @field_validator("planner")
    @classmethod
    def _planner(cls, value: str) -> str:
        if value not in PLANNERS:
            raise ValueError(f"'planner' must be one of {', '.join(PLANNERS)} (got {value!r})")
        return value

    @field_validator("check_isolation")
    @classmethod
    def _isolation(cls, value: str) -> str:
        if value not in ISOLATIONS:
            raise ValueError(f"'check_isolation' must be one of {', '.join(ISOLATIONS)} "
                             f"(got {value!r})")
        return value

    # ------------------------------------------------------------------ derived
    @property
    def state_dir(self) -> Path:
        """The older name of :attr:`data_dir`."""
        return self.data_dir

    @property
    def db_path(self) -> Path:
        """The SQLite file of the run records."""
        return self.data_dir / "runs.sqlite"

    @property
    def allowed_robots(self) -> tuple[Path, ...]:
        """The folders robots may load from: ``robots_dirs``, the cells folder and the
        ``package_path`` folders."""
        return (*self.robots_dirs, self.cells_dir, *self.package_path)

    def load_options(self) -> LoadOptions:
        """How the server loads robots (its cells' and their planning workers')."""
        return LoadOptions(strict=self.strict, allow_missing_meshes=self.allow_missing_meshes,
                           collision=self.collision, package_path=self.package_path)

    def folder_policy(self) -> FolderPolicy:
        """What requests may make the server load: tasks from the tasks folder, cells
        from the cells folder, robots from the robot folders."""
        return FolderPolicy(tasks=(self.tasks_dir,), cells=(self.cells_dir,),
                            robots=self.allowed_robots)

    def replaced(self, **changes: Any) -> Settings:
        """These settings with ``changes`` (validated)."""
        values = {name: getattr(self, name) for name in type(self).model_fields}
        values.update(changes)
        token = _ENVIRON.set({})
        try:
            return type(self)(**values)
        finally:
            _ENVIRON.reset(token)

    @classmethod
    def from_env(cls, environ: Mapping[str, str] | None = None, **overrides: object) -> Settings:
        """Settings from ``TASKRUNNER_*`` variables (``environ``, default ``os.environ``);
        ``overrides`` that are not None win over them.

        Raises:
            ValueError: a bad value; the message names the variable and the expectation.
        """
        given = {k: v for k, v in overrides.items() if v is not None}
        token = _ENVIRON.set(None if environ is None else dict(environ))
        try:
            return cls(**given)  # type: ignore[arg-type]
        except ValidationError as exc:
            raise ArgumentError(_messages(exc)) from None
        finally:
            _ENVIRON.reset(token)


# The environment from_env reads (None: the process's), for settings_customise_sources.
_ENVIRON: contextvars.ContextVar[Mapping[str, str] | None] = contextvars.ContextVar(
    "taskrunner_settings_environ", default=None)


def _messages(exc: ValidationError) -> str:
    """The messages of ``exc``, one per line, each naming its variable."""
    lines = []
    for error in exc.errors():
        field = ".".join(str(p) for p in error["loc"])
        text = str(error["msg"]).removeprefix("Value error, ")
        variable = f"TASKRUNNER_{field.upper()}"
        if text.startswith("'"):
            lines.append(f"{variable}: {text}")
        else:
            lines.append(f"{variable}: '{field}' {text} (got {error.get('input')!r})")
    return "; ".join(lines)


def _integer(value: Any) -> int | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, int):
        return value
    if isinstance(value, str):
        text = value.strip()
        if text.lstrip("-").isdigit():
            return int(text)
    return None


def _number(value: Any) -> float | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float):
        number = float(value)
    elif isinstance(value, str):
        try:
            number = float(value)
        except ValueError:
            return None
    else:
        return None
    return number if math.isfinite(number) else None


class _MappingSource(EnvSettingsSource):
    """``TASKRUNNER_*`` values from a mapping instead of the process environment."""

    def __init__(self, settings_cls: type[BaseSettings], environ: Mapping[str, str]) -> None:
        self._given = {k.lower(): v for k, v in environ.items()}
        super().__init__(settings_cls)

    def _load_env_vars(self) -> Mapping[str, str | None]:
        return self._given


class _OldEnvNames:
    """``TASKRUNNER_NO_AUTH`` and ``TASKRUNNER_STATE_DIR``, the older names of ``auth``
    (inverted) and ``data_dir``."""

    def __init__(self, settings_cls: type[BaseSettings],
                 environ: Mapping[str, str] | None = None) -> None:
        self.environ = os.environ if environ is None else environ

    def __call__(self) -> dict[str, Any]:
        out: dict[str, Any] = {}
        if self.environ.get("TASKRUNNER_NO_AUTH"):
            out["auth"] = self.environ["TASKRUNNER_NO_AUTH"].strip().lower() not in _FLAG_TRUE
        if self.environ.get("TASKRUNNER_STATE_DIR") and not self.environ.get(
                "TASKRUNNER_DATA_DIR"):
            out["data_dir"] = self.environ["TASKRUNNER_STATE_DIR"]
        return out
