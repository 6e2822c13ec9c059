"""The taskrunner REST API: runs, live events, cancel, checking, cells, planning.

    from api import Settings, create_app
    app = create_app(Settings(token="..."))      # serve with uvicorn, or run-task serve
"""

from __future__ import annotations

from api.app import create_app, new_token
from api.settings import Settings

__all__ = ["Settings", "create_app", "new_token"]
