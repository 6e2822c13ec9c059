"""The garbage collector is paused while numba compiles, and resumed as it was."""

from __future__ import annotations

import gc

import numba
from numba.core import event

import taskrunner.collision.frames  # noqa: F401  (registers the pause)


class _Seen(event.Listener):
    def __init__(self) -> None:
        self.enabled: list[bool] = []

    def on_start(self, event: event.Event) -> None:
        self.enabled.append(gc.isenabled())

    def on_end(self, event: event.Event) -> None:
        pass


def _compile_new_function() -> list[bool]:
    seen = _Seen()
    with event.install_listener("numba:compile", seen):
        numba.njit(lambda x: x + 1.0)(1.0)
    return seen.enabled


def test_collector_is_paused_while_a_kernel_compiles_and_resumed_after():
    assert gc.isenabled()
    assert _compile_new_function() == [False]
    assert gc.isenabled()


def test_collector_disabled_before_a_compilation_stays_disabled():
    gc.disable()
    try:
        _compile_new_function()
        assert not gc.isenabled()
    finally:
        gc.enable()
