"""Runs for tools ROS users already have: MCAP files of ROS 2 messages and a live
Foxglove WebSocket feed (see ``docs/foxglove.md``).

- :func:`export_mcap`: a run record → an MCAP file (:mod:`.mcapfile`, :mod:`.timeline`).
- :class:`FoxgloveFeed`: a run's robots live over Foxglove's protocol (:mod:`.live`).

Both need the ``foxglove`` extra (``pip install 'taskrunner-robotics[foxglove]'``). The
names are imported when first used: the command line builds its parser from
:mod:`.command` without loading robots' libraries.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from taskrunner.export.live import FoxgloveFeed, FoxgloveFeedOptions
    from taskrunner.export.mcapfile import export_mcap

__all__ = ["FoxgloveFeed", "FoxgloveFeedOptions", "export_mcap"]


def __getattr__(name: str) -> Any:
    if name == "export_mcap":
        from taskrunner.export.mcapfile import export_mcap

        return export_mcap
    if name in ("FoxgloveFeed", "FoxgloveFeedOptions"):
        from taskrunner.export import live

        return getattr(live, name)
    raise AttributeError(f"module 'taskrunner.export' has no attribute {name!r}")
