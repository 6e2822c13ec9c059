"""toppra imported without matplotlib (taskrunner.planning.toppra_import), in a fresh
interpreter each: what a process has imported before decides the path taken."""

from __future__ import annotations

import subprocess
import sys

import pytest


def _run(code: str) -> str:
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    return done.stdout.strip()


@pytest.mark.slow
def test_toppra_without_matplotlib_then_real_pyplot_on_use() -> None:
    out = _run(
        "import sys\n"
        "from taskrunner.planning.toppra_import import import_toppra\n"
        "toppra = import_toppra()\n"
        "import toppra.algorithm.algorithm as algorithm\n"
        "print('matplotlib' in sys.modules, 'matplotlib.pyplot' in sys.modules)\n"
        "figure = algorithm.plt.figure\n"  # the placeholder imports the real pyplot
        "import matplotlib.pyplot as plt\n"
        "print(figure is plt.figure, type(sys.modules['matplotlib.pyplot']).__name__)\n"
    )
    assert out.splitlines() == ["False False", "True module"]


@pytest.mark.slow
def test_timing_works_and_matplotlib_imported_first_is_kept() -> None:
    out = _run(
        "import sys\n"
        "import matplotlib.pyplot as plt\n"
        "from taskrunner.planning.toppra_import import import_toppra\n"
        "import_toppra()\n"
        "import toppra.parametrizer as parametrizer\n"
        "print(parametrizer.plt is plt)\n"
    )
    assert out == "True"


@pytest.mark.slow
def test_scipy_optimize_is_imported_when_first_used_not_with_toppra() -> None:
    out = _run(
        "import sys\n"
        "import numpy as np\n"
        "from taskrunner.planning.toppra_import import import_toppra\n"
        "import_toppra()\n"
        "print('scipy.optimize' in sys.modules)\n"
        # scipy.interpolate's one module-level use: a smoothing spline (its minimize_scalar)
        "from scipy.interpolate import make_smoothing_spline\n"
        "x = np.linspace(0.0, 1.0, 30)\n"
        "spline = make_smoothing_spline(x, np.sin(6 * x), lam=1e-3)\n"
        "import scipy.optimize\n"
        "print(type(scipy.optimize).__name__, hasattr(scipy.optimize, 'linprog'))\n"
        "gcv = make_smoothing_spline(x, np.sin(6 * x))\n"  # lam=None: minimize_scalar
        "print(abs(float(gcv(0.5)) - np.sin(3.0)) < 0.01)\n"
    )
    assert out.splitlines() == ["False", "module True", "True"]


@pytest.mark.slow
def test_scipy_optimize_imported_first_is_kept() -> None:
    out = _run(
        "import scipy.optimize\n"
        "from taskrunner.planning.toppra_import import import_toppra\n"
        "import_toppra()\n"
        "import scipy.interpolate._bsplines as bsplines\n"
        "print(bsplines.minimize_scalar is scipy.optimize.minimize_scalar)\n"
    )
    assert out == "True"
