"""The shortcut's draw of two segments: distinct, ordered, every pair as likely."""

from __future__ import annotations

import random
from collections import Counter

from taskrunner.planning.shortcut import _two_of


def test_two_distinct_segments_every_pair_about_as_often() -> None:
    for n in (2, 3, 7, 21, 22, 40):
        rng = random.Random(n)
        seen = Counter(_two_of(rng, n) for _ in range(400 * n * (n - 1) // 2))
        assert all(0 <= a < b < n for a, b in seen)
        assert len(seen) == n * (n - 1) // 2           # every pair comes
        assert max(seen.values()) < 1.5 * min(seen.values())


def test_the_same_seed_draws_the_same_pairs() -> None:
    draws = []
    for _ in range(2):
        rng = random.Random(7)
        draws.append([_two_of(rng, 30) for _ in range(20)])
    assert draws[0] == draws[1] and len(set(draws[0])) > 10
