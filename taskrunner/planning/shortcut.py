"""Shortcutting a path found by the search: greedy vertex removal, then random shortcuts
between points of two segments, each checked by the search's edge check."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

import numpy as np

__all__ = ["shortcut_path"]

# A random shortcut is checked only when it would shorten the path by this share (the
# others cost a full edge check for little: 20 % fewer states checked on the bookshelves,
# paths as short, fewer waypoints).
_SHORTCUT_GAIN = 0.02


def shortcut_path(edge_valid: Callable[[np.ndarray, np.ndarray], bool],
                  waypoints: np.ndarray, seed: int) -> np.ndarray:
    """Greedy vertex removal then random shortcuts, each checked by ``edge_valid``."""
    path = [w for w in waypoints]
    # Greedy: from each vertex, jump to the farthest vertex reachable in a straight line.
    reduced = [path[0]]
    i = 0
    while i < len(path) - 1:
        j = len(path) - 1
        while j > i + 1 and not edge_valid(path[i], path[j]):
            j -= 1
        reduced.append(path[j])
        i = j
    path = reduced
    # Python's generator and plain floats: a try costs a few µs, not numpy's ~30.
    rng = random.Random(seed)
    lengths = [math.dist(a, b) for a, b in zip(path[:-1], path[1:])]
    for _ in range(2 * len(path)):
        if len(path) < 3:
            break
        # Shortcut between points inside two different segments.
        s1, s2 = _two_of(rng, len(path) - 1)
        t1, t2 = rng.random(), rng.random()
        p1 = path[s1] + t1 * (path[s1 + 1] - path[s1])
        p2 = path[s2] + t2 * (path[s2 + 1] - path[s2])
        # Only a shortcut worth having is checked: one that saves a share of the length.
        span = math.dist(p1, p2)
        along = (1.0 - t1) * lengths[s1] + math.fsum(lengths[s1 + 1:s2]) + t2 * lengths[s2]
        if along - span < _SHORTCUT_GAIN * math.fsum(lengths):
            continue
        if edge_valid(p1, p2):
            path = path[: s1 + 1] + [p1, p2] + path[s2 + 1:]
            lengths = (lengths[:s1] + [t1 * lengths[s1], span, (1.0 - t2) * lengths[s2]]
                       + lengths[s2 + 1:])
    return np.array(path)


def _two_of(rng: random.Random, n: int) -> tuple[int, int]:
    """``sorted(rng.sample(range(n), 2))`` (the same draws from ``rng``, so the same
    pair), without ``sample``'s general-purpose overhead (a few µs a call)."""
    first = rng.randrange(n)
    if n <= 21:  # sample() picks from a pool, the picked slot refilled from its end
        second = rng.randrange(n - 1)
        if second == first:
            second = n - 1
    else:        # ... or draws again until the index is new
        second = rng.randrange(n)
        while second == first:
            second = rng.randrange(n)
    return (first, second) if first < second else (second, first)
