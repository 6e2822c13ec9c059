"""Cached kernels loaded the lighter way (``taskrunner.planning.kernel_loads``): the same
verdicts as with numba's own loads, a later compilation still works, and a numba whose
cache loader differs is left alone."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import pytest

# Runs in a fresh interpreter (numba's target is refreshed once per process): verifies
# seeded paths in the pick-and-place cell and prints what each verification found.
_SCRIPT = textwrap.dedent("""
    import json, sys
    import numpy as np
    lighter = sys.argv[1] == "lighter"
    from taskrunner.planning.kernel_loads import lighter_cache_loads
    from taskrunner.resources import resolve_cell
    from taskrunner.robot.cell import load_cell
    from taskrunner.scene import scene_from_cell
    installed = lighter_cache_loads() if lighter else False
    scene = scene_from_cell(load_cell(resolve_cell("servo_arm_table")))
    verifier = scene.path_verifier()
    robot = scene.robot
    rng = np.random.default_rng(7)
    verdicts = []
    for _ in range(40):
        states = rng.uniform(robot.lower, robot.upper, size=(3, robot.nq))
        states[0] = scene.state
        found = verifier.verify(states)
        verdicts.append([found.valid, found.fraction, found.distance_queries, found.states])
    screen = scene.state_screen()
    inside = rng.uniform(robot.lower, robot.upper, size=(30, robot.nq))
    first = int(screen.first_in_collision(np.ascontiguousarray(inside)))
    refreshed = "numba.np.polynomial.polynomial_core" in sys.modules
    import numba
    @numba.njit(cache=False)
    def added(a, b):
        return a + b
    print(json.dumps({"installed": installed, "verdicts": verdicts, "first": first,
                      "refreshed_before_compile": refreshed, "compiled": added(2, 3)}))
""")


def _run(mode: str) -> dict:
    done = subprocess.run([sys.executable, "-c", _SCRIPT, mode], capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.mark.slow
def test_lighter_loads_give_the_same_verdicts_and_compiling_still_works():
    plain, lighter = _run("plain"), _run("lighter")
    assert lighter["installed"] and not plain["installed"]
    assert lighter["verdicts"] == plain["verdicts"]
    assert lighter["first"] == plain["first"]
    assert any(v[0] for v in plain["verdicts"]) and not all(v[0] for v in plain["verdicts"])
    # the lighter way skipped the target's refresh; numba's own loads did it
    assert not lighter["refreshed_before_compile"] and plain["refreshed_before_compile"]
    assert lighter["compiled"] == plain["compiled"] == 5  # a compilation refreshes, then works


def test_an_unexpected_cache_loader_is_left_alone(monkeypatch):
    from numba.core import caching

    from taskrunner.planning import kernel_loads

    def load_overload(self, sig, target_context):  # not numba's body: other names
        return self.load_something_else(sig)

    monkeypatch.setattr(caching.Cache, "load_overload", load_overload)
    assert not kernel_loads.lighter_cache_loads()
    assert caching.Cache.load_overload is load_overload
