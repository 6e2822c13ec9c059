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

``scipy.optimize`` is deferred the same way: toppra imports ``scipy.interpolate``, whose
``_bsplines`` module imports ``minimize_scalar`` from it at module level (for
``make_smoothing_spline`` only), and importing ``scipy.optimize`` (linprog, shgo, sparse
linear algebra …) is 0.07-0.14 s of the 0.1-0.2 s toppra costs ``run-task`` before its
first motion. While toppra imports, ``scipy.optimize`` is a placeholder whose
``minimize_scalar`` imports the real module when called; any other name asked of it
imports the real module at once. Nothing in toppra or taskrunner uses scipy.optimize.
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


def _real_optimize() -> types.ModuleType:
    """The real ``scipy.optimize`` (the placeholder taken out of the way first)."""
    if isinstance(sys.modules.get("scipy.optimize"), _DeferredOptimize):
        del sys.modules["scipy.optimize"]
    return importlib.import_module("scipy.optimize")


class _DeferredOptimize(types.ModuleType):
    """Stands for ``scipy.optimize`` while toppra imports (see the module docstring)."""

    _DEFERRED = frozenset({"minimize_scalar"})

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        if name not in self._DEFERRED:
            return getattr(_real_optimize(), name)

        def deferred(*args: Any, **kwargs: Any) -> Any:
            return getattr(_real_optimize(), name)(*args, **kwargs)

        deferred.__name__ = deferred.__qualname__ = name
        deferred.__module__ = "scipy.optimize"
        return deferred


def import_toppra() -> types.ModuleType:
    """The ``toppra`` module, with the submodules taskrunner uses imported."""
    with _LOCK:
        if "toppra.interpolator" in sys.modules and "toppra.algorithm" in sys.modules:
            return sys.modules["toppra"]
        placeholders: dict[str, types.ModuleType] = {}
        if "matplotlib" not in sys.modules and "matplotlib.pyplot" not in sys.modules:
            package = types.ModuleType("matplotlib")
            package.__path__ = []  # a package, so that "matplotlib.pyplot" resolves under it
            pyplot = _DeferredPyplot("matplotlib.pyplot")
            package.pyplot = pyplot  # type: ignore[attr-defined]
            placeholders.update({"matplotlib": package, "matplotlib.pyplot": pyplot})
        if "scipy.optimize" not in sys.modules and "scipy.interpolate" not in sys.modules:
            placeholders["scipy.optimize"] = _DeferredOptimize("scipy.optimize")
        sys.modules.update(placeholders)
        try:
            for name in _MODULES:
                importlib.import_module(name)
        finally:
            for name, placeholder in placeholders.items():
                if sys.modules.get(name) is placeholder:
                    del sys.modules[name]
        return sys.modules["toppra"]
