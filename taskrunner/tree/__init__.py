"""Task specs compiled into py_trees behaviour trees whose leaves plan and execute."""

from __future__ import annotations

from taskrunner.tree.compiler import compile_task
from taskrunner.tree.context import Arm, TaskContext, resolve_arm

__all__ = ["Arm", "TaskContext", "compile_task", "resolve_arm"]
