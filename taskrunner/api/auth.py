"""Bearer-token checks: every endpoint but ``/health`` (and the OpenAPI docs) needs the
token; reads answer without it only when ``open_reads`` is set; ``auth`` off runs open."""

from __future__ import annotations

import json
import secrets
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

from fastapi import Depends, HTTPException, Request, status
from fastapi.security import HTTPAuthorizationCredentials, HTTPBearer
from starlette.routing import Match

__all__ = ["AuthGate", "require_read", "require_write", "token_matches"]

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]

_bearer = HTTPBearer(auto_error=False, description="the server's token (printed at start)")


def token_matches(given: bytes, token: str) -> bool:
    """Whether the credentials ``given`` (as sent) are the server's token, compared in
    constant time."""
    return secrets.compare_digest(given, token.encode())


def _check(request: Request, credentials: HTTPAuthorizationCredentials | None) -> None:
    token: str | None = request.app.state.token
    if token is None:  # running open (--no-auth)
        return
    given = credentials.credentials if credentials is not None else ""
    if not token_matches(given.encode(), token):
        raise HTTPException(
            status.HTTP_401_UNAUTHORIZED,
            "a valid bearer token is required (Authorization: Bearer <token>)"
            if credentials is None else "invalid bearer token",
            headers={"WWW-Authenticate": "Bearer"})


async def require_write(request: Request,
                  credentials: HTTPAuthorizationCredentials | None = Depends(_bearer)) -> None:
    """Dependency of endpoints that move a robot or change state."""
    _check(request, credentials)


async def require_read(request: Request,
                 credentials: HTTPAuthorizationCredentials | None = Depends(_bearer)) -> None:
    """Dependency of read endpoints: checks the token unless reads are open."""
    if not request.app.state.settings.open_reads:
        _check(request, credentials)


class AuthGate:
    """ASGI middleware: a request that needs the token and lacks it is answered 401 here,
    before its body is read or parsed and before routing or any work.

    ``routes`` are the app's routes (its routers' ``routes``); those whose dependencies
    include :func:`require_write`, or :func:`require_read` unless reads are open, need the
    token. A request no such route matches goes on to the app unchanged (public pages,
    404s). The routes' own dependencies still check the token: this gate only answers
    sooner, and makes a flood of requests without the token cheap to refuse.
    """

    def __init__(self, app: Callable[..., Awaitable[None]], routes: list[Any]) -> None:
        self.app = app
        self._guarded = _guarded_routes(routes)  # (route, is a write)

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] == "http":
            state = scope["app"].state
            token: str | None = getattr(state, "token", None)
            if token is not None and not _carries(scope, token) \
                    and self._needs_token(scope, state.settings.open_reads):
                await _refuse(send, scope)
                return
        await self.app(scope, receive, send)

    def _needs_token(self, scope: Scope, open_reads: bool) -> bool:
        for route, write in self._guarded:
            match, _ = route.matches(scope)
            if match == Match.FULL:
                return write or not open_reads
        return False


def _guarded_routes(routes: list[Any]) -> list[tuple[Any, bool]]:
    out = []
    for route in routes:
        dependant = getattr(route, "dependant", None)
        if dependant is None:
            continue
        calls = {d.call for d in dependant.dependencies}
        if require_write in calls:
            out.append((route, True))
        elif require_read in calls:
            out.append((route, False))
    return out


def _credentials(scope: Scope) -> bytes | None:
    """The bearer credentials of the request, as :class:`HTTPBearer` reads them."""
    for name, value in scope["headers"]:
        if name == b"authorization":
            scheme, _, given = value.partition(b" ")
            return given if scheme.lower() == b"bearer" and given else None
    return None


def _carries(scope: Scope, token: str) -> bool:
    given = _credentials(scope)
    return given is not None and token_matches(given, token)


async def _refuse(send: Send, scope: Scope) -> None:
    sent = _credentials(scope) is not None
    detail = ("invalid bearer token" if sent else
              "a valid bearer token is required (Authorization: Bearer <token>)")
    body = json.dumps({"detail": detail}).encode()
    await send({"type": "http.response.start", "status": 401,
                "headers": [(b"content-type", b"application/json"),
                            (b"content-length", str(len(body)).encode()),
                            (b"www-authenticate", b"Bearer")]})
    await send({"type": "http.response.body", "body": body})
