"""``/health``: is the server up (never needs a token)."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Depends, Request

from taskrunner.api.dependencies import get_manager
from taskrunner.api.runs import RunManager
from taskrunner.api.schemas import Health

__all__ = ["router"]

router = APIRouter(tags=["health"])


@router.get("/health", response_model=Health)
async def health(request: Request,
                 manager: Annotated[RunManager, Depends(get_manager)]) -> Health:
    return Health(status="ok", runs_in_flight=manager.in_flight(),
                  auth=request.app.state.token is not None)
