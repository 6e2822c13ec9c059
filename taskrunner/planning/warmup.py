"""The planner's compiled kernels, ready before a run needs them.

The path verifier (:mod:`taskrunner.scene.sweep`) and the search's state screen
(:mod:`taskrunner.scene.screen`) run numba kernels that numba compiles the first time on a
machine (about 7 s of CPU, ~5 s on an idle 2-core machine, half a minute or more on a busy one) and
keeps in its on-disk cache (:func:`taskrunner.resources.kernel_cache_dir`); every later
process loads them from there in a fraction of a second.

The compilation is done ahead, never inside a plan: by ``run-task warm-up``
(:func:`warm_up_kernels`), or by a run that finds them missing, which says so and waits
for them before its clock starts (the run record keeps that wait apart, as
``warm_up_s``). The kernels do not depend on the robot: one warm-up on the shipped servo
arm serves every robot and cell.

Why not compiled at build or install time: numba's cache index is keyed by each source
file's full path and modification time, so a cache built elsewhere is not used after the
package is installed at another path, and a wheel has no install step that could run code.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path

__all__ = ["kernel_cache_files", "kernels_ready", "warm_up_kernels"]


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
    warm_kernels(scene.path_verifier(), scene.state)
    _warm_geometry_kernels()
    return 0.0 if ready else time.perf_counter() - started


def _warm_geometry_kernels() -> None:
    """The kernels a verifier's build runs on mesh and convex geometry only (the servo
    arm has none): the enclosing sphere's centre, on a one-point cloud, with the argument
    types the build passes."""
    import numpy as np

    from taskrunner.scene import sweep

    sweep._farthest_point_centre(np.zeros((1, 3)), np.zeros(3), 100)


def kernel_cache_files() -> list[Path]:
    """Every file of numba's cache for taskrunner's kernels (index and compiled code),
    sorted: what a compilation adds to."""
    from taskrunner.resources import kernel_cache_dir

    root = kernel_cache_dir()
    if not root.is_dir():
        return []
    return sorted(p for p in root.rglob("*") if p.suffix in (".nbi", ".nbc"))
