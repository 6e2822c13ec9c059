"""run-task's lighter SciPy import (taskrunner.runtime.prestart.lighter_scipy_imports): numpy's
developer tools not imported, SciPy's capabilities table filled exactly as SciPy fills it,
SciPy's functions unchanged. Each case runs in a fresh interpreter (this one has SciPy)."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

# Prints what the interpreter ends up with after importing SciPy's modules that toppra and
# the planner import; argv[1] == "light": lighter_scipy_imports() first.
_PROBE = r"""
import json, sys
import numpy
listed_before = list(numpy.__all__)
if sys.argv[1] == "light":
    from taskrunner.runtime.prestart import lighter_scipy_imports
    done = lighter_scipy_imports()
    again = lighter_scipy_imports()
else:
    done = again = None
import scipy.interpolate, scipy.linalg, scipy.special, scipy.spatial
from scipy._lib import _array_api as api
tools = [m for m in ("numpy.f2py", "numpy.testing", "numpy.ma") if m in sys.modules]
def name(f):
    return f"{getattr(f, '__module__', '?')}.{getattr(f, '__qualname__', getattr(f, '__name__', '?'))}"
table = {name(f): repr(sorted(caps.items())) for f, caps in api.xp_capabilities_table.items()}
x = numpy.linspace(0.0, 1.0, 7)
spline = scipy.interpolate.CubicSpline(x, numpy.sin(x))
results = [float(spline(0.33)), float(scipy.special.erf(0.4)),
           float(scipy.linalg.expm(numpy.eye(2))[0, 0]),
           float(scipy.spatial.distance.cdist([[0, 0]], [[3, 4]])[0, 0])]
all_restored = list(numpy.__all__) == listed_before and "testing" in dir(numpy)
import numpy.testing
numpy.testing.assert_allclose(1.0, 1.0)
print(json.dumps({"done": done, "again": again, "tools": tools, "table": table,
                  "results": results, "all_restored": all_restored,
                  "testing_ok": numpy.testing.assert_allclose is not None}))
"""


def _probe(mode: str) -> dict:
    out = subprocess.run([sys.executable, "-c", _PROBE, mode], capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


@pytest.fixture(scope="module")
def probes() -> tuple[dict, dict]:
    return _probe("plain"), _probe("light")


def test_numpy_developer_tools_are_not_imported_and_numpy_is_restored(probes):
    plain, light = probes
    if not plain["tools"]:
        pytest.skip("this SciPy does not import numpy's tools when it is imported")
    assert light["done"] is True and light["again"] is False
    assert light["tools"] == []
    assert light["all_restored"] and light["testing_ok"]


def test_scipy_capabilities_table_is_filled_as_scipy_fills_it(probes):
    plain, light = probes
    if not plain["table"]:
        pytest.skip("this SciPy has no capabilities table")
    assert light["table"] == plain["table"]
    assert len(light["table"]) > 50


def test_scipy_functions_give_the_same_results(probes):
    plain, light = probes
    assert light["results"] == plain["results"]
