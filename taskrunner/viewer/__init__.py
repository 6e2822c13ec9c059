"""The browser view of cells, tasks and runs.

``src/`` holds the page's JavaScript (three.js and urdf-loader, bundled with esbuild by
``build.mjs``: ``npm ci && npm run build`` in this folder); ``static/`` the built bundle,
the page and ``THIRD_PARTY_LICENSES.txt`` (the bundled packages' licences), shipped as
package data so that serving it needs no node and no network. CI rebuilds ``static/``
from the lockfile and fails if it differs from the committed files.
:mod:`taskrunner.viewer.describe` turns cells, trees and records into the JSON the page
reads; :mod:`taskrunner.api.routers.viewer` serves both.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["STATIC_DIR"]

STATIC_DIR = Path(__file__).resolve().parent / "static"
