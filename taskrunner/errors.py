"""The exceptions taskrunner raises.

Every error the library raises on purpose derives from :class:`TaskrunnerError`, so a
caller can catch ours without catching a library's ``KeyError`` or ``RuntimeError``::

    TaskrunnerError
    ├── InputError                  bad input from a file or a caller; names the file:line
    │   ├── ArgumentError           a Python caller's argument out of range or of the wrong
    │   │                           shape (also a ValueError, as pydantic validators need)
    │   ├── RobotDescriptionError   URDF / xacro / SRDF / MoveIt YAML / robot manifest / cell
    │   │   └── MissingMeshError    a mesh file (robot collision or scene object) that does not exist
    │   ├── YamlError               a YAML file that does not parse, or repeats a key
    │   ├── TaskSpecError           a task file that is invalid (unknown verb, field, name …)
    │   ├── AmbiguousName           a MoveIt file's name that several robots of the cell have
    │   │                           (moveit/names.py; its readers report it with file:line)
    │   └── PathNotAllowedError     a file outside the folders a server allows (folders.py)
    ├── UnknownNameError            a group, joint, link, frame, pose or object that is not there
    ├── SceneError                  an invalid scene edit (duplicate object, bad shape)
    ├── PlanningError               no motion could be produced
    │   ├── IkFailedError           the target pose is unreachable (within limits and tolerance)
    │   ├── InvalidStateError       a start or goal outside the joint limits, or not of the group
    │   ├── StartInCollisionError   the start state collides (names the pair)
    │   ├── GoalInCollisionError    every goal state collides (names the pair)
    │   ├── PlanningTimeoutError    no path found within the planning time
    │   ├── PlanningCancelledError  the caller cancelled the request
    │   ├── NoDirectPathError       a direct-only request whose straight lines are all blocked
    │   ├── ScheduleConflictError   a parallel branch's motion meets another arm; waiting cannot help
    │   └── WorkerDiedError         the planning worker process ended (planning/worker.py)
    ├── BackendError                an execution backend failed or refused a command
    │   ├── TrajectoryRejectedError a trajectory refused before anything moved (names the joint)
    │   ├── BackendBusyError        joints already moving under another trajectory
    │   ├── ExecutionCancelledError the motion was stopped on request
    │   └── BusFaultError           a servo bus fault: status flags, stall, or link (feetech/)
    └── ServiceError                the REST API refuses a request (HTTP code: api/handlers.py)
        ├── NotFoundError           no such run or cell (404; also a LookupError)
        │   ├── RunNotFoundError    (api/runs.py)
        │   └── CellNotFoundError   (api/cells.py)
        ├── ConflictError           the request conflicts with what runs now (409)
        │   ├── ArmBusyError        a run in flight moves the same joints (api/runs.py)
        │   ├── RunNotFinishedError (api/runs.py)
        │   └── PoseConflictError   (api/cells.py)
        ├── UnavailableError        the server is stopping (503)
        │   └── ServerBusyError     its queue for a kind of work is full (api/admission.py)
        └── WorkLimitError          a request's work passed a time or memory limit (api/requestwork.py)

Messages follow the form ``'<field>' must be <expectation> (got <value>)`` where it fits,
and every error raised from a file starts with ``path:line:``.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from pathlib import Path

__all__ = [
    "ArgumentError",
    "BackendBusyError",
    "BackendError",
    "BusFaultError",
    "ConflictError",
    "ExecutionCancelledError",
    "GoalInCollisionError",
    "IkFailedError",
    "InvalidStateError",
    "NoDirectPathError",
    "NotFoundError",
    "PlanningCancelledError",
    "PlanningTimeoutError",
    "StartInCollisionError",
    "TaskSpecError",
    "TrajectoryRejectedError",
    "InputError",
    "MissingMeshError",
    "PlanningError",
    "RobotDescriptionError",
    "ScheduleConflictError",
    "SceneError",
    "ServiceError",
    "TaskrunnerError",
    "UnavailableError",
    "UnknownNameError",
    "YamlError",
    "did_you_mean",
]


def did_you_mean(name: str, known: Iterable[str], what: str = "") -> str:
    """``"; did you mean 'x'?"``, or ``"; <what>: 'a', 'b'"`` when nothing is close (and
    ``what`` is given): the one suggestion of every "unknown name" message (task files,
    the CLI, the Python API)."""
    known = sorted(set(known), key=str)
    close = difflib.get_close_matches(str(name), known, n=1, cutoff=0.6)
    if close:
        return f"; did you mean {close[0]!r}?"
    if not known or not what:
        return ""
    shown = ", ".join(repr(k) for k in known[:12])
    return f"; {what}: {shown}{', …' if len(known) > 12 else ''}"


class TaskrunnerError(Exception):
    """Base class of every error taskrunner raises on purpose."""


class InputError(TaskrunnerError):
    """Bad input. Carries where it came from so that messages point back into the file.

    Args:
        message: what is wrong, without the location.
        path: the file the input came from, if any.
        line: 1-based line in that file, if known.
    """

    def __init__(self, message: str, path: str | Path | None = None, line: int | None = None):
        self.reason = message
        self.path = Path(path) if path is not None else None
        self.line = line
        super().__init__(self._format())

    def __reduce__(self):  # type: ignore[no-untyped-def]
        # Errors travel back from the planning worker process: keep every field.
        return (type(self), (self.reason, self.path, self.line))

    @property
    def location(self) -> str:
        """``path:line`` (or ``path``, or an empty string when neither is known)."""
        if self.path is None:
            return ""
        return f"{self.path}:{self.line}" if self.line is not None else str(self.path)

    def _format(self) -> str:
        loc = self.location
        return f"{loc}: {self.reason}" if loc else self.reason


class ArgumentError(InputError, ValueError):
    """A Python caller's argument (an option, a state, a name) that is out of its range or
    of the wrong shape. Also a :class:`ValueError`: pydantic validators that call our
    checks turn it into a validation error naming the field, and callers that caught
    ``ValueError`` before it existed still catch it."""


class RobotDescriptionError(InputError):
    """A robot description (URDF, xacro, SRDF, MoveIt YAML, manifest or cell) is invalid."""


class MissingMeshError(RobotDescriptionError):
    """A mesh file that does not exist: a URDF collision mesh or a scene object's mesh."""


class YamlError(InputError):
    """A YAML file does not parse, repeats a key, or has the wrong shape."""


class TaskSpecError(InputError):
    """A task file is invalid: an unknown verb or field, a wrong type, an unknown arm,
    pose or object, a target out of reach."""


class UnknownNameError(TaskrunnerError):
    """A name (group, joint, link, frame, named pose, object) that the model does not have.

    Args:
        kind: what was looked up ("group", "joint", ...).
        name: the name asked for.
        known: the names that exist, listed in the message to help fix typos.
    """

    def __init__(self, kind: str, name: str, known: list[str] | tuple[str, ...] = ()):
        self.kind = kind
        self.name = name
        self.known = tuple(known)
        shown = ", ".join(repr(k) for k in sorted(self.known)[:20])
        more = "" if len(self.known) <= 20 else f", … ({len(self.known)} in all)"
        close = did_you_mean(name, self.known)
        if close and self.known:
            hint = f"{close} (known: {shown}{more})"
        else:
            hint = f"; known: {shown}{more}" if self.known else ""
        super().__init__(f"unknown {kind} {name!r}{hint}")

    def __reduce__(self):  # type: ignore[no-untyped-def]
        return (type(self), (self.kind, self.name, self.known))


class SceneError(TaskrunnerError):
    """An invalid change to the planning scene."""


class PlanningError(TaskrunnerError):
    """No motion could be produced for a request."""


class IkFailedError(PlanningError):
    """No joint configuration reaches the target within the limits and the tolerance.

    Attributes:
        best_error: the smallest residual reached (metres for position, mixed SE3 norm
            for a full pose), to tell "far out of reach" from "just missed".
    """

    def __init__(self, message: str, best_error: float | None = None):
        self.best_error = best_error
        super().__init__(message)

    def __reduce__(self):  # type: ignore[no-untyped-def]
        return (type(self), (self.args[0], self.best_error))


class InvalidStateError(PlanningError):
    """A start or goal that cannot be planned for: outside the joint limits, or not of the group."""


class _CollisionReported(PlanningError):
    """A state in collision; ``pairs`` names the colliding bodies (deepest first)."""

    def __init__(self, message: str, pairs: list[tuple[str, str]] | None = None):
        self.pairs = list(pairs or [])
        super().__init__(message)

    def __reduce__(self):  # type: ignore[no-untyped-def]
        return (type(self), (self.args[0], self.pairs))


class StartInCollisionError(_CollisionReported):
    """The start state is in collision."""


class GoalInCollisionError(_CollisionReported):
    """Every goal state is in collision."""


class PlanningTimeoutError(PlanningError):
    """The planner found no path within its time (and attempts)."""


class PlanningCancelledError(PlanningError):
    """The request was cancelled before a path was found."""


class NoDirectPathError(PlanningError):
    """A request that allows straight joint-space lines only
    (``PlannerOptions.direct_only``) found the line to every goal state blocked: no
    search was run."""


class ScheduleConflictError(PlanningError):
    """A motion of one branch of a ``parallel`` meets another branch's arm in time and
    waiting cannot resolve it (the other arm stays in its way, or both wait for each
    other): the message names both steps' file:lines (:mod:`taskrunner.tree.schedule`)."""


class BackendError(TaskrunnerError):
    """An execution backend failed, lost its device, or refused a command."""


class TrajectoryRejectedError(BackendError):
    """A trajectory refused before anything moved (unknown joint, angle out of range)."""


class BackendBusyError(BackendError):
    """A trajectory names joints that are already moving under another one."""


class ExecutionCancelledError(BackendError):
    """The motion was stopped on request, where it was."""


class BusFaultError(BackendError):
    """A servo bus failed: a servo's status flags (overload, overheat …), a stall, or the
    link (no reply, bad checksum, wrong ID, adapter unplugged). ``kind`` names the fault
    (``taskrunner.backends.feetech.FaultKind``), ``servo_id`` the servo (None: the bus)."""

    def __init__(self, message: str, kind: str = "link", servo_id: int | None = None):
        self.kind = kind
        self.servo_id = servo_id
        super().__init__(message)

    def __reduce__(self):  # type: ignore[no-untyped-def]
        return (type(self), (self.args[0], self.kind, self.servo_id))


class ServiceError(TaskrunnerError):
    """The REST API refuses a request; :mod:`taskrunner.api.handlers` maps each subclass
    to its HTTP code in one table."""


class NotFoundError(ServiceError, LookupError):
    """No run, cell or other resource of that id (HTTP 404)."""


class ConflictError(ServiceError, RuntimeError):
    """The request conflicts with the server's state: an arm in use, a run that has ended
    (HTTP 409)."""


class UnavailableError(ServiceError):
    """The server cannot take the request now: it is stopping, or full (HTTP 503)."""
