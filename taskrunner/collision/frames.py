"""Compiled forward kinematics: world frames of a :class:`~taskrunner.collision.tree.KinematicTree`'s joints.

A *frame row* is a float row holding a rotation (row-major, columns :data:`ROTATION` to
``ROTATION + 9``), an origin (m, :data:`ORIGIN`) and, for a joint, its axis in the world
(:data:`AXIS`). :func:`compose` is the one rigid-transform composition of the kernels (a
placed frame times a local placement); :func:`joint_frames` the one forward kinematics.
The path verifier (:mod:`taskrunner.scene.path_verifier`) and the search's state screen
(:mod:`taskrunner.scene.screen`) write their joint rows with it, and place their
geometry with :func:`compose`.

The functions are numba kernels compiled on first use and cached on disk
(``cache=True``, in ``NUMBA_CACHE_DIR``, by default
:func:`~taskrunner.resources.kernel_cache_dir`, a folder per version of their sources; the
helpers inside the kernels that call them);
:data:`inline` ones are helpers the other kernels call (compiled once each, not inlined
at numba's IR level: inlining them cost 38 % more first compilation, 10.5 against 6.6 s
of CPU, for no measurable speed: ``benchmarks/HISTORY.md``). Called from
Python they take C-contiguous float64 arrays and a :data:`~taskrunner.collision.tree.JOINT`
record array; :func:`forward_kinematics` is the typed Python entry point.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from typing import Any, ParamSpec, TypeVar, cast

import numpy as np

from taskrunner.collision.tree import JointKind, KinematicTree
from taskrunner.resources import kernel_cache_dir

if not os.environ.get("NUMBA_CACHE_DIR"):
    # Before numba's import: an installed package's own folder may be read-only; a folder
    # per version of the kernels' sources (numba would load a kernel whose helper changed).
    os.environ["NUMBA_CACHE_DIR"] = str(kernel_cache_dir())
# Plain compiler messages: with colorama installed, numba's colour set-up registers an exit
# handler that writes a terminal reset (ESC[0m) to stdout after the command's own output.
os.environ.setdefault("NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING", "1")
# No LLVM loop vectorization (numba's documented switch; a value set by the user wins): the
# kernels' loops run over 3 coordinates or a few joints, where the vector code (and its
# checks and remainder loops) never paid: verification and the state screen measure the same
# without it, and their first compilation takes ~0.15 s less CPU (less code for LLVM to
# optimize at each level of called helpers). Process-wide, as numba reads it.
os.environ.setdefault("NUMBA_LOOP_VECTORIZE", "0")

# numba after the cache folder is chosen
import numba
from numba.core import config as _numba_config
from numba.core.dispatcher import Dispatcher

if not getattr(_numba_config, "CACHE_DIR", ""):  # numba was imported first, by someone else:
    _numba_config.reload_config()  # it reads the environment again (NUMBA_CACHE_DIR above)

from taskrunner.collision.collector_pause import pause_collector_while_compiling

pause_collector_while_compiling()  # a first compilation 15-18 % less CPU (see the module)

__all__ = ["AXIS", "FRAME_COLUMNS", "ORIGIN", "ROTATION", "ZERO", "compose",
           "forward_kinematics", "inline", "jit", "jit_plain", "joint_frames"]

ROTATION, ORIGIN, AXIS = 0, 9, 12
"""Columns of a frame row: rotation (9, row-major), origin (3, m), a joint's axis (3)."""
FRAME_COLUMNS = 15
ZERO = cast(int, np.int64(0))  # an int to the kernels' annotations
"""The kernels' start of a count that a loop raises: typed ``int64`` from the start. A
literal ``0`` is typed ``Literal[int](0)`` and only widened to ``int64`` once the loop's
back edge is typed, which costs numba's type inference one more pass over the whole kernel
per loop level (every pass resolves every operation of the kernel again: about 50 ms of
first compilation per pass over the path verifier's walk)."""

_P = ParamSpec("_P")
_R = TypeVar("_R")
# A helper has no entry from Python: without numba's CPython and C wrappers (the code that
# unboxes each argument from a Python object), which cost 25-90 ms of compilation per
# helper of 8-19 arguments and were never called. And without numba's reference counting
# (``_nrt``): a helper allocates no array and only reads and writes those it is given,
# which its caller holds; counted, each call of a helper that does not get inlined by
# LLVM paid an atomic increment and decrement per array argument (the state screen's
# scan 6 % slower per state with them). (Options numba's typed signature of ``njit`` does
# not list; it passes every keyword on to its compiler.) No kernel has numba's C wrapper
# either (``cfunc``: for passing a kernel as a function value, which no code does).
_KERNEL_OPTIONS: dict[str, Any] = {"no_cfunc_wrapper": True}
_PLAIN_OPTIONS: dict[str, Any] = {"_nrt": False, **_KERNEL_OPTIONS}
_HELPER_OPTIONS: dict[str, Any] = {"no_cpython_wrapper": True, **_PLAIN_OPTIONS}


def jit(function: Callable[_P, _R]) -> Dispatcher[Callable[_P, _R]]:
    """Compile ``function`` as a kernel called from Python (or called, not inlined, by
    other kernels), cached on disk. The dispatcher is typed as the function: mypy checks
    the calls' arguments and results against its annotations."""
    return numba.njit(function, cache=True, nogil=True, error_model="numpy", **_KERNEL_OPTIONS)


def jit_plain(function: Callable[_P, _R]) -> Dispatcher[Callable[_P, _R]]:
    """:func:`jit` for a kernel that allocates no array (it reads and writes those it is
    given): compiled without numba's reference counting, as the helpers are (less code
    to compile, no atomic counts on the arrays it slices)."""
    return numba.njit(function, cache=True, nogil=True, error_model="numpy", **_PLAIN_OPTIONS)


def inline(function: Callable[_P, _R]) -> Dispatcher[Callable[_P, _R]]:
    """Compile ``function`` as a helper of the kernels that call it: compiled once and
    called (the name is from when helpers were inlined; see the module docstring); not
    callable from Python. Not cached on disk itself: a kernel's cached code holds the
    helpers it calls (linked in), so a process that loads the kernels never reads a
    helper's entry; one would only spare a new kernel's compilation the helper's, and
    writing the entries cost ~0.1 s of the kernels' first compilation (CPU)."""
    return numba.njit(function, cache=False, nogil=True, error_model="numpy", **_HELPER_OPTIONS)


_REVOLUTE = int(JointKind.REVOLUTE)
_PRISMATIC = int(JointKind.PRISMATIC)


@inline
def compose(frames: np.ndarray, row: int, parent: int, placement: np.ndarray) -> None:
    """Frame row ``row`` := frame row ``parent`` times ``placement``, given in ``parent``'s
    frame: its rotation (row-major, elements 0-8) then its translation (m, 9-11); the
    ``placement`` field of a :data:`~taskrunner.collision.tree.JOINT` or a
    :data:`~taskrunner.collision.geometry.GEOMETRY` record (a record's field: no array of
    its own to count references to, which an inlined call inside a branch would pay for).
    Only the rotation and origin of ``row`` are written."""
    for a in range(3):
        origin = frames[parent, ORIGIN + a]
        for b in range(3):
            origin += frames[parent, ROTATION + 3 * a + b] * placement[9 + b]
            total = 0.0
            for c in range(3):
                total += frames[parent, ROTATION + 3 * a + c] * placement[3 * c + b]
            frames[row, ROTATION + 3 * a + b] = total
        frames[row, ORIGIN + a] = origin


@inline
def joint_frames(q: np.ndarray, joints: np.ndarray, frames: np.ndarray) -> None:
    """World frames of the joints at state ``q`` (rows ``0 .. len(joints) - 1`` of
    ``frames``: rotation, origin, axis)."""
    for a in range(3):
        for b in range(3):
            frames[0, ROTATION + 3 * a + b] = 1.0 if a == b else 0.0
        frames[0, ORIGIN + a] = 0.0
        frames[0, AXIS + a] = 0.0
    for jid in range(1, joints.shape[0]):
        joint = joints[jid]
        compose(frames, jid, joint.parent, joint.placement)
        index = joint.state
        value = q[index] if index >= 0 else 0.0
        kind = joint.kind
        axis = joint.axis
        x, y, z = axis[0], axis[1], axis[2]
        if kind == _PRISMATIC:
            for a in range(3):
                for b in range(3):
                    frames[jid, ORIGIN + a] += (frames[jid, ROTATION + 3 * a + b]
                                                * axis[b] * value)
        elif kind == _REVOLUTE:
            # Rodrigues: the joint's rotation about its (local) axis.
            c, s = math.cos(value), math.sin(value)
            t = 1.0 - c
            l00, l01, l02 = c + x * x * t, x * y * t - z * s, x * z * t + y * s
            l10, l11, l12 = y * x * t + z * s, c + y * y * t, y * z * t - x * s
            l20, l21, l22 = z * x * t - y * s, z * y * t + x * s, c + z * z * t
            for a in range(3):
                r0 = frames[jid, ROTATION + 3 * a]
                r1 = frames[jid, ROTATION + 3 * a + 1]
                r2 = frames[jid, ROTATION + 3 * a + 2]
                frames[jid, ROTATION + 3 * a] = r0 * l00 + r1 * l10 + r2 * l20
                frames[jid, ROTATION + 3 * a + 1] = r0 * l01 + r1 * l11 + r2 * l21
                frames[jid, ROTATION + 3 * a + 2] = r0 * l02 + r1 * l12 + r2 * l22
        for a in range(3):                               # the axis in the world
            total = 0.0
            for b in range(3):
                total += frames[jid, ROTATION + 3 * a + b] * axis[b]
            frames[jid, AXIS + a] = total


@jit
def _forward(q: np.ndarray, joints: np.ndarray, frames: np.ndarray) -> None:
    joint_frames(q, joints, frames)


def forward_kinematics(tree: KinematicTree, q: np.ndarray) -> np.ndarray:
    """The joints' world frames at full state ``q`` (rad, m): ``(n_joints, 15)`` frame
    rows (see the module's text), row ``i`` pinocchio's joint ``i``."""
    frames = np.zeros((len(tree.joints), FRAME_COLUMNS))
    _forward(np.ascontiguousarray(q, dtype=float), tree.joints, frames)
    return frames
