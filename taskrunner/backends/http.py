"""The servo firmware over HTTP (``POST /api/command``): :class:`HttpBackend`.

Each command is one request with the JSON body ``{"cmd": "..."}`` and
``Content-Type: application/json``; the answer ``{"reply": "..."}`` carries the reply line.
Only idempotent commands (STATUS, PING, VERSION) are retried after a network error, and
only outside a stream: ``TRAJ``, ``MOVE`` and the others never are (a lost answer may hide
a command that ran), and while a trajectory streams every command has one attempt within
its short deadline (a retry would only hide a stalled board for longer).
Requests go through one pooled :class:`httpx.Client`: the connection to the board is kept
alive between commands (a trajectory streams hundreds of them), and proxies from the
environment are ignored (the board is on the local network).
"""

from __future__ import annotations

import json
import time
from typing import TYPE_CHECKING

from taskrunner.backends.calibration import ServoCalibration
from taskrunner.backends.servo_backend import ServoBackend, ServoOptions
from taskrunner.backends.servo_protocol import IDEMPOTENT_COMMANDS, command_name
from taskrunner.errors import BackendError

if TYPE_CHECKING:
    import httpx

__all__ = ["HttpBackend", "HttpTransport"]

_RETRY_PAUSE = 0.02  # s between attempts of an idempotent command


class HttpTransport:
    """One command per POST to the firmware's command URL.

    Args:
        url: e.g. ``http://10.10.10.1/api/command``.
        reply_timeout: seconds per request.
        retries: extra attempts for STATUS, PING and VERSION.
    """

    def __init__(self, url: str, reply_timeout: float = 1.0, retries: int = 2) -> None:
        if not url.startswith(("http://", "https://")):
            raise BackendError(f"servo firmware URL must be http(s)://... (got {url!r})")
        import httpx  # here, not at module level: 50 ms off every run that drives no board

        self._httpx = httpx
        self._url = url
        self._retries = retries
        self._client: httpx.Client = httpx.Client(
            timeout=httpx.Timeout(reply_timeout), trust_env=False,
            limits=httpx.Limits(max_connections=1, max_keepalive_connections=1),
            headers={"Content-Type": "application/json"})
        self._closed = False

    def exchange(self, line: str, timeout: float | None = None) -> str:
        """POST ``line``; return the reply line. With ``timeout`` (s): one attempt within
        it; without: the transport's timeout, and retries for idempotent commands.

        Raises:
            BackendError: closed, network error or timeout (after the retries of an
                idempotent command), an HTTP error status or an answer without ``reply``.
        """
        if self._closed:
            raise BackendError(f"HTTP link to {self._url} is closed")
        idempotent = command_name(line) in IDEMPOTENT_COMMANDS
        attempts = 1 + (self._retries if idempotent and timeout is None else 0)
        body = json.dumps({"cmd": line}).encode()
        httpx = self._httpx
        request_timeout = httpx.USE_CLIENT_DEFAULT if timeout is None else httpx.Timeout(timeout)
        for attempt in range(attempts):
            try:
                response = self._client.post(self._url, content=body, timeout=request_timeout)
            except httpx.HTTPError as exc:
                if attempt + 1 >= attempts:
                    within = f" within {1000 * timeout:.0f} ms" if timeout is not None else ""
                    raise BackendError(f"no answer from the servo firmware at {self._url} to "
                                       f"{line!r}{within} ({attempts} attempt(s)): "
                                       f"{exc or type(exc).__name__}") from None
                time.sleep(_RETRY_PAUSE)
                continue
            if response.status_code >= 400:
                raise BackendError(f"servo firmware at {self._url} answered HTTP "
                                   f"{response.status_code} to {line!r}: "
                                   f"{response.content[:200]!r}")
            answer = response.content
            break
        try:
            reply = json.loads(answer)["reply"]
        except (ValueError, KeyError, TypeError):
            raise BackendError(f"garbage answer from {self._url} to {line!r}: "
                               f"{answer[:200]!r}") from None
        if not isinstance(reply, str):
            raise BackendError(f"garbage answer from {self._url} to {line!r}: {answer[:200]!r}")
        return reply

    def abort(self, line: str) -> None:
        """POST ``line`` on a fresh connection, waiting at most 100 ms, errors ignored;
        then close."""
        body = json.dumps({"cmd": line}).encode()
        httpx = self._httpx
        try:
            httpx.post(self._url, content=body, timeout=0.1, trust_env=False,
                       headers={"Content-Type": "application/json"})
        except httpx.HTTPError:
            pass
        self.close()

    def close(self) -> None:
        """Close the connection and refuse further commands (idempotent)."""
        if not self._closed:
            self._closed = True
            self._client.close()


class HttpBackend(ServoBackend):
    """:class:`ServoBackend` over HTTP.

    Args:
        joint_names: joints driven (each calibrated).
        calibration: the arm's calibration.
        url: the command URL.
        options: see :class:`ServoOptions` (use ``lead_ms`` >= 500 over WiFi).

    Raises:
        BackendError: bad URL, or the handshake failed.
    """

    def __init__(self, joint_names: tuple[str, ...] | list[str], calibration: ServoCalibration,
                 url: str, options: ServoOptions | None = None) -> None:
        options = options or ServoOptions()
        super().__init__(joint_names, calibration,
                         HttpTransport(url, options.reply_timeout, options.retries), options)
