"""Waiting in tests for something another thread (a valve, a link, a driver) makes true."""

from __future__ import annotations

import time
from collections.abc import Callable


def wait_for(condition: Callable[[], object], timeout_s: float = 5.0) -> None:
    """Return once ``condition()`` is true; fail the test after ``timeout_s`` seconds."""
    deadline = time.monotonic() + timeout_s
    while not condition():
        assert time.monotonic() < deadline, "condition not met in time"
        time.sleep(0.002)


class HandClock:
    """A stream clock (``SetpointDriver``'s) the test moves by hand: ``now`` seconds."""

    def __init__(self) -> None:
        self.now = 0.0

    def mark(self):
        """The stream's position now (always the start)."""
        return (0, 0, 0.0)

    def seconds_since(self, _mark) -> float:
        """Seconds of stream since ``_mark``: ``now``."""
        return self.now
