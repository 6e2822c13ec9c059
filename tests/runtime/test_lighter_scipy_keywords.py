"""The lighter capabilities decorator (taskrunner.runtime.prestart.lighter_scipy_decorator)
takes SciPy's keywords as SciPy's does: the defaults for those not given, a TypeError for
one it does not know. In a fresh interpreter (the decorator stays installed there)."""

from __future__ import annotations

import json
import subprocess
import sys

_PROBE = r"""
import inspect, json
from scipy._lib import _array_api as api
original = api.xp_capabilities
from taskrunner.runtime.prestart import lighter_scipy_decorator
installed = lighter_scipy_decorator()
table = {}
def f(): pass
def g(): pass
api.xp_capabilities(capabilities_table=table)(f)
api.xp_capabilities(capabilities_table=table, out_of_scope=True, reason="r", extra_note="n")(g)
bound = inspect.signature(original).bind(capabilities_table=table)
bound.apply_defaults()
expected = {k: v for k, v in bound.arguments.items() if k not in ("capabilities_table", "extra_note")}
try:
    api.xp_capabilities(no_such_keyword=1)
    unknown = None
except TypeError as exc:
    unknown = str(exc)
print(json.dumps({"installed": installed, "f": repr(table[f]), "expected": repr(expected),
                  "g_np_only": table[g]["np_only"], "g_reason": table[g]["reason"],
                  "g_keys": list(table[g]), "f_keys": list(table[f]), "unknown": unknown}))
"""


def test_defaults_and_unknown_keywords_as_scipy_takes_them():
    out = subprocess.run([sys.executable, "-c", _PROBE], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    found = json.loads(out.stdout.strip().splitlines()[-1])
    if not found["installed"]:
        return  # a SciPy without that decorator: nothing replaced, nothing to compare
    assert found["f"] == found["expected"]  # same values, same order as binding gives
    assert found["g_np_only"] is True and found["g_reason"] == "r"  # out of scope: NumPy only
    assert found["g_keys"] == found["f_keys"]
    assert found["unknown"] is not None and "no_such_keyword" in found["unknown"]
