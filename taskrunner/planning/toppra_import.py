"""Import toppra without importing matplotlib.

toppra 0.6 imports ``matplotlib.pyplot`` at module level (``toppra.parametrizer`` and
``toppra.algorithm.algorithm``) for its debugging plots only; that import is about 70 %
of toppra's import time (0.3-0.45 s of 0.4-0.8 s on a 2-core machine), paid on the way
to a run's first motion, in the check and in the planning worker. :func:`import_toppra`
imports toppra with a placeholder ``matplotlib.pyplot`` whose first attribute access
imports the real one, so toppra's plots still work (``plt.plot`` in its ``compute_*``
debug helpers), and removes the placeholder from ``sys.modules`` before returning:
every later ``import matplotlib`` anywhere gets the real package.

When matplotlib is already imported, toppra is simply imported. The placeholder is in
``sys.modules`` only while toppra imports (under a lock, once per process); a thread
importing matplotlib in that window would see it, and nothing in taskrunner does so.
"""

from __future__ import annotations

import importlib
import sys
import threading
import types
from typing import Any

__all__ = ["import_toppra"]

_LOCK = threading.Lock()
_MODULES = ("toppra", "toppra.algorithm", "toppra.constraint",
            "toppra.constraint.linear_constraint", "toppra.interpolator")


class _DeferredPyplot(types.ModuleType):
    """Stands for ``matplotlib.pyplot`` in toppra's modules; imports it when used."""

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        return getattr(importlib.import_module("matplotlib.pyplot"), name)


def import_toppra() -> types.ModuleType:
    """The ``toppra`` module, with the submodules taskrunner uses imported."""
    with _LOCK:
        if "toppra.interpolator" in sys.modules and "toppra.algorithm" in sys.modules:
            return sys.modules["toppra"]
        if "matplotlib" in sys.modules or "matplotlib.pyplot" in sys.modules:
            for name in _MODULES:
                importlib.import_module(name)
            return sys.modules["toppra"]
        package = types.ModuleType("matplotlib")
        package.__path__ = []  # a package, so that "matplotlib.pyplot" resolves under it
        pyplot = _DeferredPyplot("matplotlib.pyplot")
        package.pyplot = pyplot  # type: ignore[attr-defined]
        sys.modules["matplotlib"] = package
        sys.modules["matplotlib.pyplot"] = pyplot
        try:
            for name in _MODULES:
                importlib.import_module(name)
        finally:
            if sys.modules.get("matplotlib.pyplot") is pyplot:
                del sys.modules["matplotlib.pyplot"]
            if sys.modules.get("matplotlib") is package:
                del sys.modules["matplotlib"]
        return sys.modules["toppra"]
