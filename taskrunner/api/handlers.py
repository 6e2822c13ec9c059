"""Errors to HTTP answers, in one place (:data:`ERROR_CODES`), and the request-body size
limit.

======================  ====  ==========================================================
error                   code  body
======================  ====  ==========================================================
InputError (TaskSpec,   422   ``detail`` (the message), ``location`` (file:line) and, for
YamlError, robot …)           a task, ``problems`` (each with its file:line)
UnknownNameError        422   ``detail`` names the unknown name and the known ones
PlanningError           422   ``detail``: why no motion could be produced
NotFoundError           404   no run or cell of that id
ConflictError           409   an arm in use (names the run holding it), a run that has ended
UnavailableError        503   the server is stopping
ServerBusyError         503   ``detail``: what is running and waiting; ``Retry-After``
other TaskrunnerError   422
ValueError              422   pydantic's ValidationError, raised building our models
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
from taskrunner.errors import (
    ConflictError,
    InputError,
    NotFoundError,
    PlanningError,
    TaskrunnerError,
    UnavailableError,
    UnknownNameError,
)
from taskrunner.validation import without_cascades

__all__ = ["BodyLimit", "ERROR_CODES", "MAX_DETAIL_CHARS", "MAX_PROBLEMS", "add_error_handlers",
           "problems_of"]

ERROR_CODES: dict[type[Exception], int] = {
    InputError: 422,
    UnknownNameError: 422,
    PlanningError: 422,
    NotFoundError: 404,
    ConflictError: 409,
    UnavailableError: 503,
    TaskrunnerError: 422,
    ValueError: 422,
}
"""The HTTP code of each error class; an error takes the code of the nearest class of its
MRO in this table (a :class:`~taskrunner.api.admission.ServerBusyError` is an
``UnavailableError``: 503)."""

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


def code_of(exc: BaseException) -> int:
    """The HTTP code of ``exc`` in :data:`ERROR_CODES` (500 for a class not in it)."""
    for cls in type(exc).__mro__:
        if cls in ERROR_CODES:
            return ERROR_CODES[cls]
    return 500


async def _error_answer(request: Request, exc: Exception) -> JSONResponse:
    code = code_of(exc)
    if isinstance(exc, InputError):
        return _answer(code, str(exc), location=exc.location or None, problems=problems_of(exc))
    if isinstance(exc, PlanningError):
        return _answer(code, f"planning failed: {exc}")
    if isinstance(exc, ServerBusyError):
        return JSONResponse({"detail": str(exc)}, status_code=code,
                            headers={"Retry-After": str(max(1, round(exc.retry_after_s)))})
    return _answer(code, str(exc))


async def _invalid_request(request: Request, exc: Exception) -> JSONResponse:
    """FastAPI's answer to a body its schema refuses, with at most :data:`MAX_PROBLEMS`
    errors, each echoing at most a short piece of its input."""
    assert isinstance(exc, RequestValidationError)
    errors = without_cascades(exc.errors())
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
    """The answer of :data:`ERROR_CODES` for each error class in it (Starlette picks the
    handler of the nearest class of the error's MRO, and :func:`code_of` the code)."""
    for cls in ERROR_CODES:
        app.add_exception_handler(cls, _error_answer)
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
