"""The state columns of a set of joints, as the space-time verifier
(:mod:`taskrunner.collision.spacetime`) asks them of every timeline it builds: made once
per robot model and joint names, so that the same joints give the very same array (which
the lanes' caches of that module key on).
"""

from __future__ import annotations

import weakref
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from taskrunner.robot import RobotModel

__all__ = ["state_columns"]

# Per robot model (by id, with a reference to it, kept while it lives): the state
# columns of joint name tuples.
_COLUMNS: dict[int, tuple[weakref.ref[RobotModel], dict[tuple[str, ...], np.ndarray]]] = {}
_KEPT = 256


def state_columns(model: RobotModel, names: Sequence[str]) -> np.ndarray:
    """``model.indices(names)``, read-only, kept: the same names give the same array."""
    key = tuple(names)
    entry = _COLUMNS.get(id(model))
    if entry is None or entry[0]() is not model:
        entry = _COLUMNS[id(model)] = (weakref.ref(model, _forget(id(model))), {})
    kept = entry[1]
    found = kept.get(key)
    if found is None:
        found = model.indices(key) if key else np.zeros(0, dtype=np.int64)
        found.flags.writeable = False
        if len(kept) >= _KEPT:
            kept.pop(next(iter(kept)))
        kept[key] = found
    return found


def _forget(key: int) -> Callable[[object], None]:
    """Drop the columns of the model of id ``key`` when it goes (if not replaced)."""
    def forget(ref: object) -> None:
        entry = _COLUMNS.get(key)
        if entry is not None and entry[0] is ref:
            del _COLUMNS[key]
    return forget
