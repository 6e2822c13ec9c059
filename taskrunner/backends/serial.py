"""The servo firmware over USB serial (pyserial): :class:`SerialBackend`.

Opening the port resets most ESP32 boards: the transport waits for the boot banner
(``# taskrunner-servo ... ready``, or ``banner_timeout``), discards what came before, ends
any partial line, then the backend handshakes (PING, VERSION). ``#`` lines are skipped;
the banner seen again means the board restarted, which fails the link.
"""

from __future__ import annotations

import time

import serial as pyserial

from taskrunner.backends.calibration import ServoCalibration
from taskrunner.backends.servo_backend import ServoBackend, ServoOptions
from taskrunner.errors import BackendError

__all__ = ["SerialBackend", "SerialTransport"]

BANNER = "# taskrunner-servo"


class SerialTransport:
    """One command line out, one reply line back, over a serial port.

    Args:
        port: device path (``/dev/ttyUSB0``, a pty of the host firmware).
        baud: baud rate (the firmware uses 115200).
        reply_timeout: seconds to wait for a reply line.
        banner_timeout: seconds to wait for the boot banner after opening.

    Raises:
        BackendError: the port cannot be opened (names it).
    """

    def __init__(self, port: str, baud: int = 115200, reply_timeout: float = 1.0,
                 banner_timeout: float = 2.0) -> None:
        self._port_name = port
        self._timeout = reply_timeout
        try:
            self._serial = pyserial.Serial(port, baud, timeout=reply_timeout,
                                           write_timeout=reply_timeout)
        except (pyserial.SerialException, OSError, ValueError) as exc:
            raise BackendError(f"cannot open serial port {port!r}: {exc}") from None
        self._pending = b""
        self._wait_banner(banner_timeout)
        try:
            self._serial.reset_input_buffer()
            self._serial.write(b"\n")  # end any partial line; a blank line gets no reply
        except (pyserial.SerialException, OSError) as exc:
            self.close()
            raise BackendError(f"serial port {port!r} failed: {exc}") from None
        self._pending = b""

    def _wait_banner(self, timeout: float) -> None:
        deadline = time.monotonic() + timeout
        while True:
            try:
                line = self._read_line(deadline)
            except BackendError:
                return  # no banner (the board did not reset): go on with the handshake
            if line.startswith(BANNER):
                return

    def _read_line(self, deadline: float, wait: float | None = None) -> str:
        while b"\n" not in self._pending:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                # This thread may run again only after the deadline (a busy host) while
                # the reply came in time: what the port holds is taken before giving up.
                try:
                    self._serial.timeout = 0
                    self._pending += self._serial.read(self._serial.in_waiting)
                except (pyserial.SerialException, OSError, TypeError) as exc:
                    raise BackendError(f"serial port {self._port_name!r} failed: {exc}") \
                        from None
                if b"\n" in self._pending:
                    break
                wait = self._timeout if wait is None else wait
                raise BackendError(f"no reply from the servo firmware on {self._port_name!r} "
                                   f"within {1000 * wait:.0f} ms")
            try:
                self._serial.timeout = min(remaining, 0.01)
                chunk = self._serial.read(max(1, self._serial.in_waiting))
            except (pyserial.SerialException, OSError, TypeError) as exc:
                raise BackendError(f"serial port {self._port_name!r} failed: {exc}") from None
            self._pending += chunk
        raw, self._pending = self._pending.split(b"\n", 1)
        return raw.decode("ascii", errors="replace").rstrip("\r")

    def exchange(self, line: str, timeout: float | None = None) -> str:
        """Send ``line`` and return the next reply line (``#`` lines skipped), waiting
        ``timeout`` seconds (default: ``reply_timeout``).

        Raises:
            BackendError: write/read error (device gone), no reply within the timeout,
                or the boot banner (the board restarted: all state lost).
        """
        try:
            self._serial.write(line.encode("ascii") + b"\n")
        except (pyserial.SerialException, OSError, TypeError) as exc:
            raise BackendError(f"serial port {self._port_name!r} failed: {exc}") from None
        wait = self._timeout if timeout is None else timeout
        deadline = time.monotonic() + wait
        while True:
            reply = self._read_line(deadline, wait)
            if reply.startswith(BANNER):
                raise BackendError(f"the servo board on {self._port_name!r} restarted "
                                   f"({reply!r}): its state is lost")
            if not reply.startswith("#"):
                return reply

    def abort(self, line: str) -> None:
        """Write ``line`` without waiting for a reply (errors ignored), then close."""
        try:
            self._serial.write(line.encode("ascii") + b"\n")
            self._serial.flush()
        except (pyserial.SerialException, OSError, TypeError):
            pass
        self.close()

    def close(self) -> None:
        """Close the port (idempotent)."""
        try:
            self._serial.close()
        except (pyserial.SerialException, OSError):
            pass


class SerialBackend(ServoBackend):
    """:class:`ServoBackend` over a serial port.

    Args:
        joint_names: joints driven (each calibrated).
        calibration: the arm's calibration.
        port: the serial device.
        options: see :class:`ServoOptions`.

    Raises:
        BackendError: the port cannot be opened (names it), or the handshake failed.
    """

    def __init__(self, joint_names: tuple[str, ...] | list[str], calibration: ServoCalibration,
                 port: str, options: ServoOptions | None = None) -> None:
        options = options or ServoOptions()
        transport = SerialTransport(port, calibration.baud, options.reply_timeout,
                                    options.banner_timeout)
        super().__init__(joint_names, calibration, transport, options)
