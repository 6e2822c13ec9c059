"""Bearer-token checks: every endpoint but ``/health`` (and the OpenAPI docs) needs the
token; reads answer without it only when ``open_reads`` is set; ``auth`` off runs open."""

from __future__ import annotations

import secrets

from fastapi import Depends, HTTPException, Request, status
from fastapi.security import HTTPAuthorizationCredentials, HTTPBearer

__all__ = ["require_read", "require_write", "token_matches"]

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
