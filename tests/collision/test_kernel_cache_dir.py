"""The compiled kernels' cache folder is named by their sources: a kernel whose helper (in
another module) changed is compiled again, never loaded stale from numba's cache, which
checks a kernel against its own source file only."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import taskrunner
from taskrunner.resources import KERNEL_PACKAGES, kernel_sources_digest

PACKAGE = Path(taskrunner.__file__).parent
_KERNEL = re.compile(r"^@(jit|jit_plain|inline)\b|numba\.njit\(|^@njit\b", re.MULTILINE)


def test_every_module_with_kernels_is_in_the_hashed_packages():
    found = sorted(p.relative_to(PACKAGE) for p in PACKAGE.rglob("*.py")
                   if _KERNEL.search(p.read_text(encoding="utf-8")))
    assert found, "no kernel module found: the pattern no longer matches the decorators"
    outside = [str(p) for p in found if p.parts[0] not in KERNEL_PACKAGES or len(p.parts) != 2]
    assert not outside, f"kernels outside {KERNEL_PACKAGES}: {outside}"


def test_a_changed_helper_module_names_another_folder(tmp_path):
    for package in KERNEL_PACKAGES:
        shutil.copytree(PACKAGE / package, tmp_path / package)
    before = kernel_sources_digest(tmp_path)
    assert before == kernel_sources_digest(PACKAGE)  # the same sources, the same name
    helper = tmp_path / "scene" / "distance_bounds.py"
    helper.write_text(helper.read_text(encoding="utf-8") + "\n# changed\n", encoding="utf-8")
    assert kernel_sources_digest(tmp_path) != before
    (tmp_path / "collision" / "new_module.py").write_text("X = 1\n", encoding="utf-8")
    helper.write_text(helper.read_text(encoding="utf-8")[:-len("\n# changed\n")],
                      encoding="utf-8")
    assert kernel_sources_digest(tmp_path) != before  # a module added counts too


def test_numba_caches_in_the_folder_of_these_sources_unless_told_otherwise(tmp_path):
    code = ("import os, taskrunner.collision.frames\n"
            "from numba.core import config\n"
            "print(os.environ['NUMBA_CACHE_DIR']); print(config.CACHE_DIR)")
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["XDG_CACHE_HOME"] = str(tmp_path)
    lines = subprocess.run([sys.executable, "-c", code], env=env, check=True,
                           capture_output=True, text=True).stdout.split()
    expected = str(tmp_path / "taskrunner" / "numba" / f"kernels-{kernel_sources_digest()}")
    assert lines == [expected, expected]
    env["NUMBA_CACHE_DIR"] = str(tmp_path / "mine")  # the user's own setting wins
    lines = subprocess.run([sys.executable, "-c", code], env=env, check=True,
                           capture_output=True, text=True).stdout.split()
    assert lines == [str(tmp_path / "mine")] * 2
