"""SerialTransport on a pseudo-terminal: a reply that came in time is taken even when the
reading thread runs again only after the deadline (a busy host)."""

from __future__ import annotations

import os
import time

import pytest

from taskrunner.backends.serial import SerialTransport
from taskrunner.errors import BackendError


def test_a_reply_in_the_port_is_taken_when_the_thread_wakes_after_the_deadline() -> None:
    board, host = os.openpty()
    try:
        transport = SerialTransport(os.ttyname(host), reply_timeout=0.05, banner_timeout=0.0)
        try:
            os.write(board, b"ok 1 80*3D\n")  # the reply, there before the deadline
            deadline = time.monotonic() + 10.0  # bounds a hang only
            while transport._serial.in_waiting < 11:  # the kernel moves it to the port
                assert time.monotonic() < deadline
                time.sleep(0.001)
            late = time.monotonic() - 1.0  # the thread ran again 1 s after its deadline
            assert transport._read_line(late, 0.05) == "ok 1 80*3D"
            with pytest.raises(BackendError, match="no reply from the servo firmware"):
                transport._read_line(late, 0.05)  # nothing there: the deadline holds
        finally:
            transport.close()
    finally:
        os.close(board)
        os.close(host)
