"""The order in which the search checks the states along an edge: its end first, then
the inner states coarse to fine (as OMPL's discrete motion validator orders them), and
the table of those fractions per number of steps that the compiled segment scan reads.
"""

from __future__ import annotations

import functools

import numpy as np

__all__ = ["FRACTIONS", "TABLE_STEPS", "bisection_order", "fill_fractions"]

# The edge checks' fractions per number of steps (row ``steps``: the end's 1.0, then
# ``bisection_order(steps) / steps``), up to TABLE_STEPS steps, each row filled the first
# time an edge of that many steps comes (a row not starting with 1.0 is not filled yet);
# longer edges take their fractions from ``bisection_order`` directly.
TABLE_STEPS = 256
FRACTIONS = np.zeros((TABLE_STEPS + 1, TABLE_STEPS))


def fill_fractions(steps: int) -> None:
    row = FRACTIONS[steps]
    row[1:steps] = bisection_order(steps) / steps
    row[0] = 1.0  # last: marks the row filled for the compiled scan reading it


@functools.lru_cache(maxsize=1024)
def bisection_order(steps: int) -> np.ndarray:
    """The inner points 1 .. steps-1 of a segment cut in ``steps``, coarse to fine: the
    middle, then the middles of the halves, and so on (as OMPL's discrete motion
    validator orders them). A blocked stretch of the segment is met after a number of
    checks that depends on its length, not on where it lies."""
    order: list[int] = []
    spans = [(0, steps)]
    while spans:
        following = []
        for lo, hi in spans:
            if hi - lo < 2:
                continue
            mid = (lo + hi) // 2
            order.append(mid)
            following += [(lo, mid), (mid, hi)]
        spans = following
    out = np.array(order, dtype=int)
    out.flags.writeable = False  # shared between callers
    return out
