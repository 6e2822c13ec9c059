"""The planner's compiled kernels: compiled once per machine, never waited for.

The path verifier (:mod:`taskrunner.scene.path_verifier`) and the search's state screen
(:mod:`taskrunner.scene.screen`) run numba kernels that numba compiles the first time on a
machine (6-8 s of CPU: ~5 s on an idle 2-core machine, half a minute or more on a busy one)
and keeps in its on-disk cache (:func:`taskrunner.resources.kernel_cache_dir`); every later
process loads them from there in a fraction of a second.

A planner that finds them missing does not wait: :class:`CompiledKernels` starts their
compilation in a process of its own, at the lowest CPU priority, and the planner checks
with coal alone meanwhile (``MotionPlanner(compiled=False)``: :mod:`taskrunner.scene.coalpath`,
the same state verdicts and the same path guarantee, slower per path); between two requests
it switches to the kernels once they are in the cache. The first plan on a machine starts
when the robot is loaded, not seconds later. A compilation that outlives the run finishes by
itself (the next runs load it); one at a time per cache (a lock file). ``run-task warm-up``
(:func:`warm_up_kernels`) compiles them in the foreground, for a machine prepared ahead.

Measured (``benchmarks/kernel_compile.py``): the verifier's kernels alone take 4.7-5.7 s of
CPU and the screen's 2.0-2.5 s, each more than the 2 s a first run has between its check
and a 3 s first motion: no split of the compilation reaches that; planning beside it does.

The kernels do not depend on the robot: one compilation on the shipped servo arm serves
every robot and cell. Why not compiled at build or install time: numba's cache index is
keyed by each source file's full path and modification time, so a cache built elsewhere is
not used after the package is installed at another path, and a wheel has no install step
that could run code.
"""

from __future__ import annotations

import logging
import os
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from taskrunner.planning.planner import MotionPlanner
    from taskrunner.scene import Scene
    from taskrunner.scene.coalpath import CoalPathVerifier
    from taskrunner.scene.path_verifier import PathVerifier

__all__ = ["CompiledKernels", "compile_in_background", "compiling_pid", "exact_path_verifier",
           "kernel_cache_files", "kernels_ready", "warm_up_kernels"]

_LOCK_NAME = "compiling.lock"  # in the kernel cache: held (flock) by the compiling process
_COMPILE_LIMIT = 1800.0  # s: a background compilation that takes longer gives up


def kernels_ready() -> bool:
    """Whether the kernels of this installation are compiled in the cache (a finished
    warm-up left its mark for these sources, this numba and this Python). Imports numba
    (0.2-0.4 s the first time in a process)."""
    from taskrunner.scene.screen import _warm_mark

    return _warm_mark().exists()


def warm_up_kernels(robot: str | Path | None = None,
                    on_compile: Callable[[], None] | None = None) -> float:
    """Compile the planner's kernels into the cache, or load them if they are there.

    Args:
        robot: the robot (folder, manifest or URDF) whose scene exercises the kernels;
            None: the shipped servo arm (any robot compiles the same kernels).
        on_compile: called once, before compiling, when the kernels are not in the cache
            (to tell the user why the wait).

    Returns:
        The seconds spent compiling (0.0 when the kernels were in the cache already).
    """
    from taskrunner.resources import DATA_ROOT
    from taskrunner.robot import load_robot
    from taskrunner.scene import Scene
    from taskrunner.scene.screen import warm_kernels

    ready = kernels_ready()
    scene = Scene(load_robot(DATA_ROOT / "robots" / "servo_arm" if robot is None else robot))
    if not ready and on_compile is not None:
        on_compile()
    started = time.perf_counter()
    if not ready:
        # Another process compiling them into this cache (a first run's, in the
        # background): wait for it rather than compile the same kernels beside it.
        while (pid := compiling_pid()) is not None and pid != os.getpid():
            time.sleep(0.2)
    # The mesh-only kernel first: the warm-up's mark, once there, covers every kernel.
    _warm_geometry_kernels()
    warm_kernels(scene.path_verifier(), scene.state)
    return 0.0 if ready else time.perf_counter() - started


def _warm_geometry_kernels() -> None:
    """The kernels a verifier's build runs on mesh and convex geometry only (the servo
    arm has none): the enclosing sphere's centre, on a one-point cloud, with the argument
    types the build passes."""
    import numpy as np

    from taskrunner.scene import distance_bounds

    distance_bounds._farthest_point_centre(np.zeros((1, 3)), np.zeros(3), 100)


def kernel_cache_files() -> list[Path]:
    """Every file of numba's cache for taskrunner's kernels (index and compiled code),
    sorted: what a compilation adds to."""
    from taskrunner.resources import kernel_cache_dir

    root = kernel_cache_dir()
    if not root.is_dir():
        return []
    return sorted(p for p in root.rglob("*") if p.suffix in (".nbi", ".nbc"))


class CompiledKernels:
    """Switches a planner to the compiled kernels once they are in the cache, compiling
    them meanwhile in the background; the planner checks with coal alone until then.

    Args:
        ready: whether the kernels are in the cache (default :func:`kernels_ready`).
        start: starts their compilation in the background (default
            :func:`compile_in_background`); returns the process, or None where one is
            running already.

    Call :meth:`prepare` once the planner's scene is loaded, then :meth:`update` before
    each request (never during one: a plan is checked by one kind of check throughout).
    """

    def __init__(self, ready: Callable[[], bool] | None = None,
                 start: Callable[[], subprocess.Popen[bytes] | None] | None = None) -> None:
        self._ready = ready or _ready_mark()
        self._start = start or compile_in_background
        self.process: subprocess.Popen[bytes] | None = None
        """The background compilation this started (None: none, or another's)."""

    def prepare(self, planner: MotionPlanner) -> bool:
        """Load the kernels into ``planner`` if they are compiled (True); else start
        compiling them and let it check with coal meanwhile (False)."""
        if self._ready():
            self._load(planner)
            return True
        planner.compiled = False
        self.process = self._start()
        return False

    def update(self, planner: MotionPlanner) -> bool:
        """Switch ``planner`` to the kernels if they are compiled now; whether it uses them.
        A background compilation that ended without them is logged (a warning, once): the
        planner goes on with coal alone."""
        if planner.compiled:
            return True
        if not self._ready():
            process = self.process
            if process is not None and process.poll() is not None:
                self.process = None  # reaped
                if process.returncode != 0:
                    logging.getLogger(__name__).warning(
                        "the background compilation of the planner's kernels failed (exit "
                        "code %s); planning goes on with coal alone (as exact, slower); "
                        "`run-task warm-up` compiles them in the foreground and says why",
                        process.returncode)
            return False
        if self.process is not None:
            self.process.poll()  # reaped if it has ended
        self._load(planner)
        return True

    @staticmethod
    def _load(planner: MotionPlanner) -> None:
        """Load the compiled kernels (from the cache) by checking a short motion."""
        from taskrunner.scene.screen import warm_kernels

        scene = planner.scene
        warm_kernels(scene.path_verifier(), scene.state)
        planner.compiled = True


def _ready_mark() -> Callable[[], bool]:
    """:func:`kernels_ready`, the mark's path computed once (a stat per call)."""
    from taskrunner.scene.screen import _warm_mark

    return _warm_mark().exists


def exact_path_verifier(scene: Scene) -> PathVerifier | CoalPathVerifier:
    """The scene's path verifier (:meth:`Scene.path_verifier`, compiled) where the kernels
    are in the cache; else one with coal alone (the same guarantee), so that a check made
    while they compile in the background does not compile them a second time here."""
    if kernels_ready():
        return scene.path_verifier()
    from taskrunner.scene.coalpath import CoalPathVerifier

    return CoalPathVerifier(scene.robot, scene.checker)


def compile_in_background() -> subprocess.Popen[bytes] | None:
    """Start compiling the kernels into the cache in a process of their own, at the lowest
    CPU priority, detached from the caller's terminal (a Ctrl-C of the run does not stop
    it; it ends by itself, within :data:`_COMPILE_LIMIT`). None where a compilation into
    this cache is running already (its lock is held)."""
    if _lock_held():
        return None
    return subprocess.Popen([sys.executable, "-m", "taskrunner.planning.warmup"],
                            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)


def compiling_pid() -> int | None:
    """The process compiling the kernels into this cache in the background, if any."""
    lock = _lock_path()
    if not _lock_held():
        return None
    try:
        return int(lock.read_text(encoding="ascii").strip())
    except (OSError, ValueError):
        return None


def _lock_path() -> Path:
    from taskrunner.resources import kernel_cache_dir

    return kernel_cache_dir() / _LOCK_NAME


def _lock_held() -> bool:
    """Whether some process holds the compilation lock of this cache."""
    try:
        import fcntl
    except ImportError:  # no flock: no lock, at worst two compilations of the same kernels
        return False
    try:
        with open(_lock_path(), "a+b") as handle:
            try:
                fcntl.flock(handle, fcntl.LOCK_SH | fcntl.LOCK_NB)
            except OSError:
                return True
            return False
    except OSError:
        return False


def _compile_here() -> int:
    """The background compilation (``python -m taskrunner.planning.warmup``): take the
    cache's lock (exit at once if another process holds it), compile, exit 0."""
    if hasattr(os, "nice"):
        os.nice(19)
    lock = _lock_path()
    lock.parent.mkdir(parents=True, exist_ok=True)
    with open(lock, "a+b") as handle:
        try:
            import fcntl

            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except ImportError:
            pass
        except OSError:
            return 0  # another process compiles them
        handle.truncate(0)
        handle.write(str(os.getpid()).encode("ascii"))
        handle.flush()
        if not kernels_ready():
            import signal

            if hasattr(signal, "alarm"):
                signal.alarm(int(_COMPILE_LIMIT))
            warm_up_kernels()
    return 0


if __name__ == "__main__":
    sys.exit(_compile_here())
