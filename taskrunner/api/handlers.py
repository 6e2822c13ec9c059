"""Errors to HTTP answers, in one place, and the request-body size limit.

======================  ====  ==========================================================
error                   code  body
======================  ====  ==========================================================
InputError (TaskSpec,   422   ``detail`` (the message), ``location`` (file:line) and, for
YamlError, robot …)           a task, ``problems`` (each with its file:line)
UnknownNameError        422   ``detail`` names the unknown name and the known ones
PlanningError           422   ``detail``: why no motion could be produced
ArmBusyError            409   ``detail`` names the run holding the arm
RunNotFinishedError     409   cancelling a run that has ended
RunNotFoundError        404
CellNotFoundError       404
ServerBusyError         503   ``detail``: what is running and waiting; ``Retry-After``
other TaskrunnerError   422
body too large          413
invalid request body    422   FastAPI's ``detail`` list of errors
======================  ====  ==========================================================

An answer's size is bounded whatever the request: at most :data:`MAX_PROBLEMS` problems
(or request errors), then one saying how many more; a ``detail`` text of at most
:data:`MAX_DETAIL_CHARS` characters (a 1 MB body of 60,000 bad parameters used to get a
17-25 MB answer).
"""

from __future__ import annotations

import json
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

from fastapi import FastAPI, Request
from fastapi.encoders import jsonable_encoder
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse

from taskrunner.api.admission import ServerBusyError
from taskrunner.api.cells import CellNotFoundError, PoseConflictError
from taskrunner.api.runs import ArmBusyError, RunNotFinishedError, RunNotFoundError
from taskrunner.errors import InputError, PlanningError, TaskrunnerError, UnknownNameError

__all__ = ["BodyLimit", "MAX_DETAIL_CHARS", "MAX_PROBLEMS", "add_error_handlers", "problems_of"]

MAX_PROBLEMS = 100
"""Most problems (or request errors) one error answer lists; one more entry says how many
were left out."""
MAX_DETAIL_CHARS = 20_000
"""Longest ``detail`` text of an error answer (characters)."""

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]


def problems_of(exc: InputError) -> list[dict[str, Any]]:
    """The problems of a task error, each as file, line, message and text."""
    from taskrunner.tasks.problem import Problem

    found = getattr(exc, "problems", None) or [Problem(exc.path, exc.line, exc.reason)]
    shown = [problem_out(p) for p in found[:MAX_PROBLEMS]]
    if len(found) > MAX_PROBLEMS:
        more = f"and {len(found) - MAX_PROBLEMS} more problems"
        shown.append({"file": None, "line": None, "message": more, "text": more})
    return shown


def _capped(text: str) -> str:
    """``text`` cut to :data:`MAX_DETAIL_CHARS`, saying how much was left out."""
    if len(text) <= MAX_DETAIL_CHARS:
        return text
    return f"{text[:MAX_DETAIL_CHARS]}… (and {len(text) - MAX_DETAIL_CHARS} more characters)"


def problem_out(problem: Any) -> dict[str, Any]:
    return {"file": str(problem.path) if problem.path is not None else None,
            "line": problem.line, "message": problem.message, "text": str(problem)}


def _answer(code: int, detail: Any, **extra: Any) -> JSONResponse:
    if isinstance(detail, str):
        detail = _capped(detail)
    return JSONResponse(_encodable({"detail": detail, **extra}), status_code=code)


async def _input_error(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, InputError)
    return _answer(422, str(exc), location=exc.location or None, problems=problems_of(exc))


async def _unknown_name(request: Request, exc: Exception) -> JSONResponse:
    return _answer(422, str(exc))


async def _planning_error(request: Request, exc: Exception) -> JSONResponse:
    return _answer(422, f"planning failed: {exc}")


async def _taskrunner_error(request: Request, exc: Exception) -> JSONResponse:
    return _answer(422, str(exc))


async def _arm_busy(request: Request, exc: Exception) -> JSONResponse:
    return _answer(409, str(exc))


async def _not_finished(request: Request, exc: Exception) -> JSONResponse:
    return _answer(409, str(exc))


async def _not_found(request: Request, exc: Exception) -> JSONResponse:
    return _answer(404, str(exc))


async def _server_busy(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, ServerBusyError)
    return JSONResponse({"detail": str(exc)}, status_code=503,
                        headers={"Retry-After": str(max(1, round(exc.retry_after_s)))})


async def _value_error(request: Request, exc: Exception) -> JSONResponse:
    return _answer(422, str(exc))


async def _invalid_request(request: Request, exc: Exception) -> JSONResponse:
    """FastAPI's answer to a body its schema refuses, with at most :data:`MAX_PROBLEMS`
    errors, each echoing at most a short piece of its input."""
    assert isinstance(exc, RequestValidationError)
    errors = list(exc.errors())
    shown: list[Any] = []
    for error in errors[:MAX_PROBLEMS]:
        error = dict(error)
        if error.get("type") in ("float_type", "int_type") and isinstance(error.get("input"), bool):
            what = "a number" if error["type"] == "float_type" else "an integer"
            error["msg"] = f"must be {what}, not a boolean"
        error["input"] = _echo(error.get("input"))
        if "ctx" in error:
            error["ctx"] = _echo(error["ctx"])
        shown.append(error)
    if len(errors) > MAX_PROBLEMS:
        shown.append({"type": "too_many_errors", "loc": [],
                      "msg": f"and {len(errors) - MAX_PROBLEMS} more errors"})
    return JSONResponse(_encodable({"detail": shown}), status_code=422)


def _encodable(value: Any) -> Any:
    """``value`` with every lone surrogate of its text (a JSON request may hold one:
    ``"\\ud800"``) written as its escape, so that the answer encodes as UTF-8."""
    if isinstance(value, str):
        return value.encode("utf-8", "backslashreplace").decode("utf-8")
    if isinstance(value, dict):
        return {_encodable(k): _encodable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_encodable(v) for v in value]
    return value


def _echo(value: Any) -> Any:
    """``value`` as an error answer may echo it: JSON as it is when short, the text of a
    number JSON cannot hold (NaN, Infinity), a note in place of anything long."""
    try:
        encoded = jsonable_encoder(value)
        text = json.dumps(encoded, allow_nan=False)
    except ValueError:  # NaN or Infinity (JSON has neither)
        return repr(value) if isinstance(value, float) else "(left out: not JSON)"
    except TypeError:
        return "(left out: not JSON)"
    return encoded if len(text) <= 1_000 else "(left out: too large to show)"


def add_error_handlers(app: FastAPI) -> None:
    """One handler per domain error class (the most specific class wins)."""
    app.add_exception_handler(InputError, _input_error)
    app.add_exception_handler(UnknownNameError, _unknown_name)
    app.add_exception_handler(PlanningError, _planning_error)
    app.add_exception_handler(TaskrunnerError, _taskrunner_error)
    app.add_exception_handler(ArmBusyError, _arm_busy)
    app.add_exception_handler(RunNotFinishedError, _not_finished)
    app.add_exception_handler(RunNotFoundError, _not_found)
    app.add_exception_handler(CellNotFoundError, _not_found)
    app.add_exception_handler(PoseConflictError, _not_finished)
    app.add_exception_handler(ServerBusyError, _server_busy)
    app.add_exception_handler(ValueError, _value_error)
    app.add_exception_handler(RequestValidationError, _invalid_request)


class BodyLimit:
    """ASGI middleware: refuse request bodies over ``max_bytes`` with 413, whether the
    client declares the length or streams the body (chunked: it is read here, up to the
    limit, before the app sees it; a body over it is refused before any of it is used)."""

    def __init__(self, app: Callable[..., Awaitable[None]], max_bytes: int) -> None:
        self.app = app
        self.max_bytes = max_bytes

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        headers = dict(scope.get("headers") or [])
        declared = headers.get(b"content-length")
        if declared is not None:
            try:
                too_big = int(declared) > self.max_bytes
            except ValueError:
                await self._refuse(send, 400, "invalid Content-Length")
                return
            if too_big:
                await self._refuse(send, 413, self._message())
                return
            await self.app(scope, receive, send)
            return
        if b"transfer-encoding" not in headers:  # no body
            await self.app(scope, receive, send)
            return
        chunks: list[bytes] = []
        size = 0
        while True:
            message = await receive()
            if message["type"] != "http.request":  # the client went away
                return
            chunk = message.get("body", b"")
            size += len(chunk)
            if size > self.max_bytes:
                await self._refuse(send, 413, self._message())
                return
            chunks.append(chunk)
            if not message.get("more_body", False):
                break
        whole: list[Message] = [{"type": "http.request", "body": b"".join(chunks),
                                 "more_body": False}]

        async def replay() -> Message:
            return whole.pop() if whole else await receive()

        await self.app(scope, replay, send)

    def _message(self) -> str:
        return f"request body must be at most {self.max_bytes} bytes"

    @staticmethod
    async def _refuse(send: Send, code: int, detail: str) -> None:
        body = json.dumps({"detail": detail}).encode()
        await send({"type": "http.response.start", "status": code,
                    "headers": [(b"content-type", b"application/json"),
                                (b"content-length", str(len(body)).encode())]})
        await send({"type": "http.response.body", "body": body})
