"""The compiled walk of the path verifier (:mod:`taskrunner.scene.path_verifier`):
conservative advancement over a path, unit by unit (:func:`_walk`), with the motion
bounds of each pair of bodies between two positions (:func:`_bound`) and the grouping of
pairs whose bound is the same function into units (:func:`_group_pairs`).

The packed arrays it reads and writes: ``pair_i`` (columns ``_PI_*``), the walk state
(one row per unit, columns ``_HAS_L`` ..), the schedule, and the settings (``_S_*``);
the frames and geometry records are those of :mod:`taskrunner.scene.distance_bounds`.
"""

from __future__ import annotations

import math

import numpy as np

from taskrunner.collision.frames import AXIS, ORIGIN, ZERO, inline, jit, jit_plain, joint_frames
from taskrunner.scene.distance_bounds import (
    _FR_CENTRE,
    _FR_PLACED,
    _geometry_frame,
    _lower_bound,
    _pieces_bound,
    _support_bound,
)

_BISECTIONS = 4  # at most this many evaluations to place a step inside a segment
_CLOSE = 0.1  # a step placed within this fraction short of its bound is close enough

# Columns of the walk state (a float array, one row per unit: pairs whose motion bound is
# the same function, see :func:`_group_pairs`; its lever arms on the left and on the right
# follow): the measurements on the left and right of a gap, and while a unit's members wait
# for coal's distances, the least distance of those in and how many are pending. When each
# unit is due next, and from where it may be measured early, are rows 0 and 1 of the
# schedule (inf: done).
_HAS_L, _PL, _DL, _HAS_R, _PR, _DR, _UMIN, _UPENDING = range(8)
_COLUMNS = 8
# pair_i (n_pairs, 3 + 4 nq): the pair's geometries, how many joints count, then per
# such joint (deepest first): its state index, code, the geometry it moves, its joint id.
_PI_FIRST, _PI_SECOND, _PI_COUNT, _PI_JOINTS = range(4)
# settings: margin, slack, gain, early, cheap-from; compiled states, cheap bounds; exact
# distances pending (count, position); per-state lever arms; the contact (index into the
# selected pairs) or the first state that is not finite; the walk started.
_S_STATES, _S_BOUNDS, _S_PENDING, _S_AT, _S_PER_STATE, _S_BAD, _S_STARTED = 5, 6, 7, 8, 9, 10, 11
_S_EXACT_FROM, _S_SUPPORTS = 12, 13  # below CHEAP_FROM, coal's distance below this; bounds so
# m: a clearance kept off every distance (0: the bodies themselves; > 0: each pair is
# verified as bodies grown by it, a space-time check's clearance between arms)
_S_CLEARANCE = 14
_S_COUNT = 15
_NOT_FINITE = -2  # what :func:`_walk` returns for a state that is not finite


@inline
def _bound(cumulative: np.ndarray, pair_i: np.ndarray, pair_levers: np.ndarray, k: int,
           start: float, walk: np.ndarray, column: int, position: float) -> float:
    """Pair ``k``'s motion bound (m) from path position ``start`` to ``position``, with
    the lever arms ``walk[k, column + j]`` taken at the former.

    A revolute joint's lever arm grows by at most how far the joints below it (same
    body, deeper in the tree) move the body relative to its axis, which is their own
    contribution: the joints are taken deepest first. Each counted joint's cumulative
    motion is interpolated here at both positions (a helper of its own for the start's
    cost a compiled function more: ~0.1 s of first compilation)."""
    nq = pair_levers.shape[1]
    n = cumulative.shape[0]
    if n == 1:
        return 0.0  # a single state: nothing moves
    seg0 = math.floor(start)  # >= 0: int()'s value, without compiling numba's int()
    if seg0 > n - 2:
        seg0 = n - 2
    frac0 = start - seg0
    seg = math.floor(position)
    if seg > n - 2:
        seg = n - 2
    frac = position - seg
    share_first = 0.0                   # what each body's deeper joints contributed
    share_second = 0.0
    total = 0.0
    for i in range(pair_i[k, _PI_COUNT]):
        j = pair_i[k, _PI_JOINTS + i]
        code = pair_i[k, _PI_JOINTS + nq + i]
        c0 = cumulative[seg0, j] + frac0 * (cumulative[seg0 + 1, j] - cumulative[seg0, j])
        c1 = cumulative[seg, j] + frac * (cumulative[seg + 1, j] - cumulative[seg, j])
        moved = c1 - c0
        if moved <= 0.0:
            continue
        first = code % 2 == 1
        lever = walk[k, column + j]
        if code >= 3:
            lever += share_first if first else share_second
            if lever > pair_levers[k, j]:
                lever = pair_levers[k, j]
        contribution = lever * moved
        if first:
            share_first += contribution
        else:
            share_second += contribution
        total += contribution
    return total


@inline
def _measure(k: int, d: float, s: float, cumulative: np.ndarray, pair_i: np.ndarray,
             pair_levers: np.ndarray, geometries: np.ndarray, frames: np.ndarray, nj: int,
             walk: np.ndarray, schedule: np.ndarray, settings: np.ndarray) -> None:
    """Take a lower bound ``d`` > 0 on pair ``k``'s distance at position ``s`` (the state
    of ``frames``) and schedule the pair's next measurement. A called function, not
    inlined: the walk takes measurements in two places (a unit's exact distances, its
    cheap bounds), and inlined twice it took the kernels' first compilation from about
    8 to 24 s of CPU (the call costs about 1 % of a verification)."""
    margin, gain, early = settings[0], settings[2], settings[3]
    per_state = settings[_S_PER_STATE] != 0.0
    nq = cumulative.shape[1]
    # The left lever arms' first column, _COLUMNS, read from the walk's width: passed as the
    # constant, numba would type it Literal[int](8) and compile _bound and _levers_here once
    # more for it than for the right ones' column (a second copy, ~0.3 s of first
    # compilation). Then the right lever arms.
    left = walk.shape[1] - 2 * nq
    right = left + nq
    last = float(cumulative.shape[0] - 1)
    if walk[k, _HAS_L] == 0.0:
        extends = True
    else:
        moved = _bound(cumulative, pair_i, pair_levers, k, walk[k, _PL], walk, left, s)
        reach = walk[k, _DL] + d
        extends = moved <= (margin if margin > reach else reach)  # max(), as numba's
    # Covered from the left: extends the stretch; else a gap: this one waits on the right.
    side = _HAS_L if extends else _HAS_R  # its columns: _HAS_*, then _P*, then _D*
    walk[k, side] = 1.0
    walk[k, side + 1] = s
    walk[k, side + 2] = d
    # The lever arms here (on that side), of the joints that count: for a revolute joint,
    # the distance from its axis to the moved body's bounding sphere centre plus the
    # radius (never more than the full-reach bound); otherwise the full-reach bound.
    column = left if extends else right
    for i in range(pair_i[k, _PI_COUNT]):
        j = pair_i[k, _PI_JOINTS + i]
        full = pair_levers[k, j]
        value = full
        if per_state and pair_i[k, _PI_JOINTS + nq + i] >= 3 and full != 0.0:
            g = pair_i[k, _PI_JOINTS + 2 * nq + i]
            jid = pair_i[k, _PI_JOINTS + 3 * nq + i]
            along = 0.0
            length2 = 0.0
            for a in range(3):
                v = frames[nj + g, _FR_CENTRE + a] - frames[jid, ORIGIN + a]
                along += v * frames[jid, AXIS + a]
                length2 += v * v
            off_axis = length2 - along * along
            lever = math.sqrt(off_axis if off_axis > 0.0 else 0.0) + geometries[g].radius
            if lever < full:
                value = lever
        walk[k, column + j] = value
    start = walk[k, _PL]
    # After a gap, the test below is the one that just failed (same start, lever arms
    # and position): skipped.
    if extends and walk[k, _HAS_R] != 0.0:
        moved = _bound(cumulative, pair_i, pair_levers, k, start, walk, left, walk[k, _PR])
        reach = walk[k, _DL] + walk[k, _DR]
        if moved <= (margin if margin > reach else reach):
            walk[k, _HAS_R] = 0.0
            walk[k, _PL] = walk[k, _PR]
            walk[k, _DL] = walk[k, _DR]
            for i in range(pair_i[k, _PI_COUNT]):
                j = pair_i[k, _PI_JOINTS + i]
                walk[k, left + j] = walk[k, right + j]
            start = walk[k, _PL]
    d_left = walk[k, _DL]
    to_end = _bound(cumulative, pair_i, pair_levers, k, start, walk, left, last)
    if walk[k, _HAS_R] != 0.0:
        # Fill the gap from the left: this step is covered whatever the distance there.
        step = margin if margin > d_left else d_left
    else:
        if to_end <= d_left:
            schedule[0, k] = np.inf  # done: its distance cannot reach 0 before the end
            schedule[1, k] = np.inf
            return
        step = d_left * (1.0 + gain)
        if margin > step:
            step = margin
    # The next measurement: a path position after ``start`` where the pair's motion bound
    # from ``start`` (the left lever arms) is at most ``step`` (> 0), and close to the
    # furthest one: the last node where it is, then within that node's segment to
    # ``_CLOSE`` of ``step``, or as far as ``_BISECTIONS`` evaluations get (written here,
    # not called: one level of compiled calls less over _bound).
    last_node = cumulative.shape[0] - 1
    if to_end <= step:
        due = float(last_node)
    else:
        lo_node = math.floor(start) + 1      # first node after start
        lo, f_lo = start, 0.0         # no motion yet
        if lo_node == last_node:      # the bound there is ``to_end``
            f_node = to_end
        else:
            f_node = _bound(cumulative, pair_i, pair_levers, k, start, walk, left, float(lo_node))
        if f_node <= step:
            hi_node, f_hi = last_node, to_end   # bound(lo_node) <= step < bound(hi_node)
            while hi_node - lo_node > 1:
                node = (lo_node + hi_node) // 2
                f_mid = _bound(cumulative, pair_i, pair_levers, k, start, walk, left, float(node))
                if f_mid <= step:
                    lo_node, f_node = node, f_mid
                else:
                    hi_node, f_hi = node, f_mid
            lo, f_lo = float(lo_node), f_node
            hi = float(hi_node)
        else:
            hi, f_hi = float(lo_node), f_node
        # Regula falsi, keeping the bracket: bound(lo) <= step < bound(hi).
        for _ in range(_BISECTIONS):
            if f_lo >= (1.0 - _CLOSE) * step or f_hi <= f_lo:
                break
            width = hi - lo
            mid = lo + width * (step - f_lo) / (f_hi - f_lo)
            if mid < lo + _CLOSE * width:
                mid = lo + _CLOSE * width
            if mid > hi - _CLOSE * width:
                mid = hi - _CLOSE * width
            f_mid = _bound(cumulative, pair_i, pair_levers, k, start, walk, left, mid)
            if f_mid <= step:
                lo, f_lo = mid, f_mid
            else:
                hi, f_hi = mid, f_mid
        due = lo
        if lo <= start:
            # Never stay put (the walk must advance): halve towards the start; the bound
            # is continuous and 0 there, so this ends.
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if mid <= start:
                    break
                if _bound(cumulative, pair_i, pair_levers, k, start, walk, left, mid) <= step:
                    due = mid
                    break
                hi = mid
    schedule[0, k] = due
    schedule[1, k] = start + (1.0 - early) * (due - start)


@jit_plain
def _walk(joints: np.ndarray, geometries: np.ndarray, points: np.ndarray,
          pieces: np.ndarray | None, pair_i: np.ndarray, unit_i: np.ndarray,
          unit_levers: np.ndarray, members: np.ndarray, unit_from: np.ndarray, unit_of: np.ndarray,
          states: np.ndarray, cumulative: np.ndarray, frames: np.ndarray,
          walk: np.ndarray, schedule: np.ndarray, picked: np.ndarray, selected: np.ndarray,
          distances: np.ndarray, q: np.ndarray, settings: np.ndarray) -> int:
    """Walk the path through ``states`` until some pairs need an exact distance: returns
    their count (in ``selected``; the position in ``settings[_S_AT]``, its state in ``q``,
    its frames in ``frames``). The caller writes their distances to ``distances`` and
    calls again, which takes them first. Returns 0 when every pair is done, -1 for a
    contact (``settings[_S_BAD]``: its index into ``selected``), ``_NOT_FINITE`` for a
    state that is not finite (its row in ``settings[_S_BAD]``). The first call fills
    ``cumulative`` (per joint, the sum of ``|dq|`` up to each state) and resets ``walk``.
    The kernel allocates nothing (it is compiled without numba's reference counting).

    The walk schedules units (``unit_i``, ``unit_levers``: rows like ``pair_i``'s and the
    pair lever arms, one per unit; the pairs of unit ``u`` are ``members[unit_from[u]:
    unit_from[u + 1]]``, ``unit_of`` the reverse): a unit's measurement is the least of
    its pairs' lower bounds. Pairs whose cheap lower bound is at least ``settings[4]``
    take it as their measurement. Every distance and bound is taken less the clearance
    ``settings[_S_CLEARANCE]`` (a contact: a pair closer than it).

    ``pieces``: per geometry, the first record of its mesh's convex pieces and their count
    (:func:`~taskrunner.scene.distance_bounds._pieces_bound`); None where no geometry has
    any: numba then compiles the walk without the pieces' code (a type of its own)."""
    nj = joints.shape[0]
    n, nq = states.shape
    if settings[_S_STARTED] == 0.0:
        settings[_S_STARTED] = 1.0
        for i in range(n):
            for j in range(nq):
                if not math.isfinite(states[i, j]):
                    settings[_S_BAD] = i
                    return _NOT_FINITE
                cumulative[i, j] = (0.0 if i == 0 else
                                    cumulative[i - 1, j] + abs(states[i, j] - states[i - 1, j]))
        for k in range(walk.shape[0]):
            for column in range(_COLUMNS):
                walk[k, column] = 0.0
            schedule[0, k] = 0.0                   # every unit is measured at the start
            schedule[1, k] = 0.0
        for g in range(geometries.shape[0]):
            frames[nj + g, _FR_PLACED] = -1.0      # not placed
    per_state = settings[_S_PER_STATE] != 0.0
    cheap_from = settings[4]
    exact_from = settings[_S_EXACT_FROM]
    slack = settings[1]
    clearance = settings[_S_CLEARANCE]
    s = settings[_S_AT]
    # First the exact distances the caller measured (if any): each unit whose pairs are all
    # in takes the least distance as its measurement.
    count = math.floor(settings[_S_PENDING])
    settings[_S_PENDING] = 0.0
    for i in range(count):
        k = selected[i]
        d = distances[i] - slack - clearance
        if not d > 0.0:  # also NaN
            settings[_S_BAD] = i
            return -1
        u = unit_of[k]
        if d < walk[u, _UMIN]:
            walk[u, _UMIN] = d
        walk[u, _UPENDING] -= 1.0
    for i in range(count):
        u = unit_of[selected[i]]
        if walk[u, _UPENDING] == 0.0:
            walk[u, _UPENDING] = -1.0  # measured once
            _measure(u, walk[u, _UMIN], s, cumulative, unit_i, unit_levers, geometries, frames, nj,
                     walk, schedule, settings)
    # Then on along the path: the next position to evaluate (the earliest due unit's), the
    # units measured there (in ``picked``: due there, or due soon and past their early
    # position) and the state there (in ``q``).
    due, early_at = schedule[0], schedule[1]
    while True:
        s = np.inf
        for k in range(walk.shape[0]):
            if due[k] < s:
                s = due[k]
        if s == np.inf:
            return 0
        picks = ZERO
        for k in range(walk.shape[0]):
            # Measuring early (after the last measurement) is always sound.
            if due[k] <= s or (early_at[k] <= s and walk[k, _PL] < s and walk[k, _HAS_L] != 0.0):
                picked[picks] = k
                picks += 1
        seg = math.floor(s)
        if seg > n - 2:
            seg = n - 2 if n >= 2 else 0
        frac = s - seg
        for j in range(nq):
            if n == 1:
                q[j] = states[0, j]
            else:
                q[j] = states[seg, j] + frac * (states[seg + 1, j] - states[seg, j])
        settings[_S_AT] = s
        if per_state:
            joint_frames(q, joints, frames)
            settings[_S_STATES] += 1.0
        stamp = settings[_S_STATES]
        exact = ZERO
        for i in range(picks):
            u = picked[i]
            least = np.inf
            pending = ZERO
            first, last = unit_from[u], unit_from[u + 1]
            if not per_state:
                for m in range(first, last):
                    selected[exact] = members[m]
                    exact += 1
                    pending += 1
                walk[u, _UMIN] = least
                walk[u, _UPENDING] = pending
                continue
            # The pairs' bounding sphere gaps first (``distances`` serves as scratch: the
            # caller's distances were taken above); then, from the nearest on, the full
            # bound of each pair whose gap is below the least bound so far: the others'
            # bounds (at least their gap) cannot lower the unit's measurement.
            nearest = first
            for m in range(first, last):
                k = members[m]
                for side in range(2):              # its geometries placed, first then second
                    g = pair_i[k, _PI_FIRST + side]
                    if frames[nj + g, _FR_PLACED] < stamp:
                        _geometry_frame(g, geometries, frames, nj)
                        frames[nj + g, _FR_PLACED] = np.inf if geometries[g].joint == 0 else stamp
                a, b = pair_i[k, _PI_FIRST], pair_i[k, _PI_SECOND]
                gap = 0.0                          # their bounding spheres' distance
                for c in range(3):
                    offset = frames[nj + a, _FR_CENTRE + c] - frames[nj + b, _FR_CENTRE + c]
                    gap += offset * offset
                distances[m] = (math.sqrt(gap) - geometries[a].radius - geometries[b].radius
                                - clearance)
                if distances[m] < distances[nearest]:
                    nearest = m
            for t in range(first - 1, last):
                m = nearest if t < first else t
                if (t >= first and m == nearest) or distances[m] >= least:
                    continue
                k = members[m]
                a, b = pair_i[k, _PI_FIRST], pair_i[k, _PI_SECOND]
                d = _lower_bound(a, b, geometries, frames, nj) - clearance
                if d < cheap_from or not d > 0.0:
                    if pieces is None:  # (numba compiles the branch taken by the type)
                        bound = (_support_bound(a, b, geometries, frames, points, nj, np.inf)
                                 - clearance)
                    else:
                        bound = _pieces_bound(a, b, geometries, frames, points, nj, pieces, stamp,
                                              exact_from + clearance, np.inf,
                                              cheap_from + clearance) - clearance
                    if bound > d:
                        d = bound
                    if not (bound > -np.inf and d >= exact_from):
                        selected[exact] = k
                        exact += 1
                        pending += 1
                        continue
                    settings[_S_SUPPORTS] += 1.0
                settings[_S_BOUNDS] += 1.0
                if d < least:
                    least = d
            if pending == 0:
                _measure(u, least, s, cumulative, unit_i, unit_levers, geometries, frames, nj, walk,
                         schedule, settings)
            else:
                walk[u, _UMIN] = least
                walk[u, _UPENDING] = pending
        if exact > 0:
            settings[_S_PENDING] = exact
            return exact


def _segment_bounds(cumulative: np.ndarray, geometries: np.ndarray, pair_i: np.ndarray,
                    pair_levers: np.ndarray, frames: np.ndarray, nj: int, per_state: bool,
                    out: np.ndarray) -> None:
    """Per pair, the motion bound from the first state to the second (``cumulative``, two
    rows: their cumulative joint motion), lever arms taken at the first (its ``frames``): what
    :func:`_measure` and :func:`_bound` take, for every pair at once in NumPy (not a
    kernel: nothing more to compile for the walk's lever arms)."""
    n_pairs, nq = pair_levers.shape
    rows = np.arange(n_pairs)
    count = pair_i[:, _PI_COUNT]
    c0 = cumulative[0] + 0.0 * (cumulative[1] - cumulative[0])  # _bound's, at 0 and 1
    c1 = cumulative[0] + 1.0 * (cumulative[1] - cumulative[0])
    share_first = np.zeros(n_pairs)
    share_second = np.zeros(n_pairs)
    total = np.zeros(n_pairs)
    radius = geometries["radius"]
    for i in range(nq):
        j = pair_i[:, _PI_JOINTS + i]
        code = pair_i[:, _PI_JOINTS + nq + i]
        full = pair_levers[rows, j]
        here = full.copy()                     # the lever arm at the first state
        revolute = (count > i) & (code >= 3) & (full != 0.0) if per_state else np.zeros(n_pairs, bool)
        if revolute.any():
            g = pair_i[revolute, _PI_JOINTS + 2 * nq + i]
            jid = pair_i[revolute, _PI_JOINTS + 3 * nq + i]
            along = np.zeros(len(g))
            length2 = np.zeros(len(g))
            for a in range(3):
                v = frames[nj + g, _FR_CENTRE + a] - frames[jid, ORIGIN + a]
                along += v * frames[jid, AXIS + a]
                length2 += v * v
            off_axis = length2 - along * along
            lever = np.sqrt(np.where(off_axis > 0.0, off_axis, 0.0)) + radius[g]
            here[revolute] = np.where(lever < full[revolute], lever, full[revolute])
        moved = c1[j] - c0[j]
        counts = (count > i) & (moved > 0.0)
        first = code % 2 == 1
        lever = here + np.where(code >= 3, np.where(first, share_first, share_second), 0.0)
        lever = np.where((code >= 3) & (lever > full), full, lever)
        contribution = np.where(counts, lever * moved, 0.0)
        share_first += np.where(first, contribution, 0.0)
        share_second += np.where(first, 0.0, contribution)
        total += contribution
    out[:] = total


@jit
def _lower_bounds(pair_i: np.ndarray, geometries: np.ndarray, frames: np.ndarray, nj: int,
                  out: np.ndarray) -> None:
    """Per pair, :func:`_lower_bound` at the state of ``frames``."""
    for k in range(pair_i.shape[0]):
        out[k] = _lower_bound(pair_i[k, _PI_FIRST], pair_i[k, _PI_SECOND], geometries,
                              frames, nj)


@jit
def _support_bounds(pair_i: np.ndarray, geometries: np.ndarray, frames: np.ndarray, points: np.ndarray,
                    pieces: np.ndarray, nj: int, out: np.ndarray) -> None:
    """Per pair, :func:`_pieces_bound` at the state of ``frames`` (every geometry placed
    there: :func:`~taskrunner.scene.distance_bounds._forward`)."""
    for k in range(pair_i.shape[0]):
        out[k] = _pieces_bound(pair_i[k, _PI_FIRST], pair_i[k, _PI_SECOND], geometries,
                               frames, points, nj, pieces, 0.0, -np.inf, np.inf, np.inf)


def _group_pairs(pair_i: np.ndarray, pair_levers: np.ndarray, unit_of: np.ndarray,
                 representative: np.ndarray) -> int:
    """Sort the pairs into units of pairs whose motion bound is the same function (the
    same joints counting, each with the same code, moved geometry and lever arms; the
    codes may all name the other body, which bounds alike): ``unit_of[k]`` is pair ``k``'s
    unit, ``representative[u]`` the first pair of unit ``u``. Returns the count of units.
    A link and each world object form such pairs: one unit per link.

    Units are numbered in the order of their first pair. Plain NumPy, run once per
    verifier (not a kernel: nothing to compile)."""
    n, nq = pair_levers.shape
    if n == 0:
        return 0
    count = pair_i[:, _PI_COUNT]
    listed = np.arange(nq)[None, :] < count[:, None]        # the joints that count
    block = pair_i[:, _PI_JOINTS:_PI_JOINTS + 4 * nq].reshape(n, 4, nq).copy()
    codes = block[:, 1]
    # Codes naming the other body bound alike: each row's codes flipped (1 <-> 2, 3 <-> 4)
    # so that its first code names the first body.
    flip = (codes[:, 0] % 2 == 0)[:, None] & listed
    codes[flip] = np.where(codes[flip] % 2 == 1, codes[flip] + 1, codes[flip] - 1)
    block[~np.broadcast_to(listed[:, None, :], block.shape)] = 0
    levers = (pair_levers + 0.0).view(np.int64)              # -0.0 as 0.0, then its bits
    keys = np.ascontiguousarray(np.hstack([count[:, None], block.reshape(n, -1), levers]))
    # Each row as one opaque value (its bytes): equal rows, equal values; sorted as bytes,
    # ~10x faster than np.unique's rows (axis=0) and the same groups.
    rows = keys.view(np.dtype((np.void, keys.shape[1] * keys.itemsize))).reshape(n)
    _, first_at, inverse = np.unique(rows, return_index=True, return_inverse=True)
    rank = np.empty(len(first_at), dtype=np.int64)
    rank[np.argsort(first_at, kind="stable")] = np.arange(len(first_at))
    unit_of[:] = rank[inverse.reshape(-1)]
    representative[rank] = first_at
    return len(first_at)


def _pair_rows(first: np.ndarray, second: np.ndarray, levers: np.ndarray, order: np.ndarray,
               revolute: np.ndarray, state_joint: np.ndarray, supported: bool,
               pair_levers: np.ndarray, pair_i: np.ndarray) -> None:
    """Per pair, its lever arms (``pair_levers``) and its row of ``pair_i``.

    Joints moving both bodies of a pair move them rigidly together: they do not count;
    a joint that moves one body only counts with that body's lever arm. The joints that
    count are listed deepest in the tree first, with their codes: 1 or 2 if the joint
    moves the pair's first or second body only, 3 or 4 likewise for a revolute joint
    whose lever arm is taken per state (``supported``). The joints of the same body
    deeper in the tree lie between such a joint and the body: they move the body relative
    to its axis, so its lever arm grows by at most what they contribute."""
    nq = levers.shape[1]
    pair_i[:, _PI_FIRST] = first
    pair_i[:, _PI_SECOND] = second
    moves_a = levers[first][:, order] > 0.0                  # (pair, joint deepest first)
    moves_b = levers[second][:, order] > 0.0
    counts = moves_a != moves_b
    slot = np.cumsum(counts, axis=1) - 1                     # its place in the pair's list
    rows, cols = np.nonzero(counts)
    joint = order[cols]
    moves_first = moves_a[rows, cols]
    owner = np.where(moves_first, first[rows], second[rows])
    pair_levers[rows, joint] = levers[owner, joint]
    code = np.where(moves_first, 1, 2)
    if supported:
        code = code + 2 * (revolute[joint] != 0)
    at = _PI_JOINTS + slot[rows, cols]
    pair_i[rows, at] = joint
    pair_i[rows, at + nq] = code
    pair_i[rows, at + 2 * nq] = owner
    pair_i[rows, at + 3 * nq] = state_joint[joint]
    pair_i[:, _PI_COUNT] = counts.sum(axis=1)
