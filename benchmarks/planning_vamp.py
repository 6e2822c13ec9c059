"""Side-by-side planning benchmark: our planner and VAMP's RRT-Connect on the same seeded
Panda MoveIt problems, in the same run, interleaved; every returned path checked by the
independent exact-mesh validator of ``planning_compare.py``.

    python benchmarks/planning_vamp.py [--per-class 10] [--classes table_pick,cage]
                                       [--seed 0] [--problems DIR] [--cap 5] [--json]

Needs ``import vamp`` (PyPI ``vamp-planner``; 0.6.4 ships as an sdist whose build fetches
CPM.cmake, nigh, pdqsort and SIMDxorshift from GitHub and needs Eigen3). Without it the
script says so and exits 0 without planning (``"skipped"`` in the JSON line).

Problems: as ``planning_compare.py`` (``make_problems.py``'s seven classes, joint goals,
regenerated into ``benchmarks/problems`` unless ``--problems DIR``). Ours: the same call
as there (:func:`planning_compare.plan_ours`: start/goal checks, search, shortcut, exact
verification; scene set-up before the timer). VAMP: its Panda module (its own sphere
model, compiled in) with ``rrtc`` and ``simplify`` at the settings of
``vamp.configure_robot_and_planner_with_kwargs("panda", "rrtc")``, a Halton sampler
reset and skipped by the problem's seed; the scene file's boxes as cuboids, spheres as
spheres, cylinders as capsules (VAMP has no cylinder; a capsule contains it), cones
refused. Timed: the whole Python call (plan + simplify, wall) and VAMP's own
``nanoseconds`` of each. VAMP's 7 joints are ``panda_joint1..7``; its fingers are fixed
in its model, so the validator checks its path with the fingers at the problem's start
state (what would run), as it does ours.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin

BENCH = Path(__file__).resolve().parent
sys.path.insert(0, str(BENCH))

import make_problems
import planning_compare as pc

try:
    import vamp  # type: ignore[import-not-found]
except ImportError as exc:  # not installable here from PyPI without GitHub access
    vamp = None
    VAMP_MISSING = f"{type(exc).__name__}: {exc}"
else:
    VAMP_MISSING = ""

from taskrunner.resources import DATA_ROOT
from taskrunner.robot import load_robot
from taskrunner.scene import Scene

JOINTS = [f"panda_joint{i}" for i in range(1, 8)]


class Vamp:
    """VAMP's Panda RRT-Connect and simplifier (see the module docstring)."""

    def __init__(self) -> None:
        if vamp is None:
            raise RuntimeError(f"vamp is not importable ({VAMP_MISSING})")
        (self.module, self.planner, self.plan_settings,
         self.simplify_settings) = vamp.configure_robot_and_planner_with_kwargs("panda", "rrtc")
        names = [str(n) for n in self.module.joint_names()]
        if names != JOINTS:
            raise RuntimeError(f"VAMP's Panda joints are {names}, not {JOINTS}")
        self.sampler = self.module.halton()

    @staticmethod
    def environment(scene: pc.SceneFile) -> Any:
        env = vamp.Environment()
        for name, kind, dims, pose in scene.objects:
            centre = [float(v) for v in pose.translation]
            rpy = [float(v) for v in pin.rpy.matrixToRpy(pose.rotation)]  # Rz Ry Rx, as VAMP's
            if kind == "box":
                env.add_cuboid(vamp.Cuboid(centre, rpy, [d / 2 for d in dims]))
            elif kind == "sphere":
                env.add_sphere(vamp.Sphere(centre, dims[0]))
            elif kind == "cylinder":  # MoveIt: [height, radius]
                env.add_capsule(vamp.Cylinder(centre, rpy, dims[1], dims[0]))
            else:
                raise ValueError(f"{scene.path}: {name}: VAMP has no {kind}")
        return env

    def plan(self, env: Any, start: dict[str, float], goal: dict[str, float], seed: int
             ) -> tuple[bool, float, float, np.ndarray | None, str]:
        """(solved, wall s of plan + simplify, VAMP's own s, waypoints, error)."""
        q0 = np.array([start[n] for n in JOINTS], dtype=np.float32)  # VAMP's float
        q1 = np.array([goal[n] for n in JOINTS], dtype=np.float32)
        self.sampler.reset()
        self.sampler.skip(seed)
        t0 = time.perf_counter()
        result = self.planner(q0, q1, env, self.plan_settings, self.sampler)
        if not result.solved:
            return False, time.perf_counter() - t0, result.nanoseconds * 1e-9, None, "no path"
        simple = self.module.simplify(result.path, env, self.simplify_settings, self.sampler)
        wall = time.perf_counter() - t0
        own = (result.nanoseconds + simple.nanoseconds) * 1e-9
        return True, wall, own, np.asarray(simple.path.numpy(), dtype=float), ""


def _vamp_version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("vamp-planner")
    except PackageNotFoundError:  # built in place, not installed as a distribution
        return "unknown version"


def run(per_class: int, classes: Sequence[str], seed: int, problems: Path | None,
        cap: float) -> dict[str, Any]:
    folder = problems
    if folder is None:
        folder = BENCH / "problems"
        make_problems.generate(folder, per_class, 0, classes)
    urdf, package_root = pc.panda_urdf()
    model = load_robot(DATA_ROOT / "robots" / "panda")
    base = Scene(model)
    validator = pc.ExactValidator(urdf, package_root, pc.PANDA_SRDF)
    other = Vamp()
    started = time.time()
    out: dict[str, Any] = {"benchmark": "planning_vamp", "date": time.strftime(
        "%Y-%m-%d %H:%M UTC", time.gmtime(started)), "load_before": pc._load(),
        "per_class": per_class, "seed": seed, "cap_s": cap,
        "vamp": _vamp_version(), "classes": {}}
    warmed = False
    for c in classes:
        rows: dict[str, list[dict[str, Any]]] = {"ours": [], "vamp": []}
        for i in range(per_class):
            stem, where = f"{i + 1:04d}", folder / c
            scene_file = pc.read_scene_file(where / f"{stem}_scene.yaml", validator.root_links)
            start, goal, tolerance = pc._request_states(where / f"{stem}_request.yaml")
            env = other.environment(scene_file)
            problem_seed = seed * 100_003 + pc.CLASSES.index(c) * 1000 + i
            if not warmed:
                pc.plan_ours(model, base, where, stem, problem_seed)
                other.plan(env, start, goal, problem_seed)
                warmed = True
            for side in (("ours", "vamp") if i % 2 == 0 else ("vamp", "ours")):
                if side == "ours":
                    ok, wall, names, waypoints, error = pc.plan_ours(model, base, where, stem,
                                                                     problem_seed)
                    own = wall
                else:
                    ok, wall, own, waypoints, error = other.plan(env, start, goal, problem_seed)
                    names = JOINTS
                row: dict[str, Any] = {"problem": f"{c}/{stem}", "ms": round(wall * 1000, 3),
                                       "own_ms": round(own * 1000, 4),
                                       "solved": ok and wall <= cap, "error": error,
                                       "length": pc._length(waypoints),
                                       "waypoints": 0 if waypoints is None else len(waypoints),
                                       "valid": None, "reason": "", "penetration": 0.0}
                if waypoints is not None:
                    verdict = validator.check(scene_file, start, names, waypoints, goal, tolerance)
                    row.update(valid=verdict.valid, reason=verdict.reason,
                               penetration=verdict.penetration)
                rows[side].append(row)
        entry: dict[str, Any] = {side: pc._stats(rows[side], cap) for side in rows}
        entry["vamp"]["median_own_ms"] = round(float(np.median(
            [r["own_ms"] for r in rows["vamp"] if r["solved"]] or [np.nan])), 4)
        a, b = entry["ours"]["median_ms"], entry["vamp"]["median_ms"]
        entry["ratio"] = round(a / b, 2) if a is not None and b else None
        out["classes"][c] = entry
    out["load_after"] = pc._load()
    out["seconds"] = round(time.time() - started, 1)
    return out


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--per-class", type=int, default=10)
    parser.add_argument("--classes", default=",".join(pc.CLASSES))
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--problems", type=Path)
    parser.add_argument("--cap", type=float, default=5.0)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    if vamp is None:
        message = (f"VAMP skipped: `import vamp` failed ({VAMP_MISSING}); install "
                   f"vamp-planner (it builds from source, fetching its dependencies from GitHub)")
        print(message)
        if args.json:
            print(json.dumps({"benchmark": "planning_vamp", "skipped": message}))
        return 0
    classes = [c for c in args.classes.split(",") if c]
    result = run(args.per_class, classes, args.seed, args.problems, args.cap)
    print(f"{result['date']}; load {result['load_before']} -> {result['load_after']}; "
          f"VAMP {result['vamp']}; {result['per_class']} per class; {result['seconds']} s")
    print(f"{'class':<17} {'solved ours/vamp':>17} {'median ms ours/vamp':>20} "
          f"{'vamp own ms':>11} {'ratio':>6} {'invalid ours/vamp':>18}")
    for c, e in result["classes"].items():
        o, v = e["ours"], e["vamp"]
        print(f"{c:<17} {o['solved']:>8}/{v['solved']:<8} {o['median_ms']:>9.3f}/"
              f"{v['median_ms']:<10.3f} {v['median_own_ms']:>11.4f} {e['ratio']!s:>6} "
              f"{o['invalid_paths']:>8}/{v['invalid_paths']:<9}")
    if args.json:
        print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
