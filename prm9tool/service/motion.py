"""Who moves the valve: one owner of its setpoint at a time.

A setpoint generator, a capture with a stimulus, a tuning test and a characterization each
drive the valve's setpoint; two at once would fight over it (and a characterization would
measure the generator's waveform instead of its own steps, and fail with NaN figures). Every
door claims the valve's motion here before it starts one (:func:`claim`, or
:meth:`MotionOwner.take` / :meth:`MotionOwner.release` around a generator that runs until it
is stopped); a second claim is refused with :class:`MotionBusyError`, in the same words at
every door, and nothing is sent. The owner belongs to the session, so two objects on one open
valve (the API's Valve and a generator it made, the GUI's worker and a tuning runner) share
it. No Qt.
"""

from __future__ import annotations

import threading
import weakref
from collections.abc import Iterator
from contextlib import contextmanager

from prm9tool.errors import Prm9Error
from prm9tool.messages import QT_TRANSLATE_NOOP, Message, Template

__all__ = ["MOTIONS", "MotionBusyError", "MotionOwner", "claim", "owner_of"]

# what each motion is called in a refusal ("… while the setpoint generator runs")
MOTIONS: dict[str, Template] = {
    "generator": QT_TRANSLATE_NOOP("Service", "the setpoint generator"),
    "capture": QT_TRANSLATE_NOOP("Service", "the capture with a stimulus"),
    "tuning": QT_TRANSLATE_NOOP("Service", "the tuning test"),
    "characterization": QT_TRANSLATE_NOOP("Service", "the characterization"),
    "autotune": QT_TRANSLATE_NOOP("Service", "the autotune"),
    "signature": QT_TRANSLATE_NOOP("Service", "the field signature"),
}
BUSY = QT_TRANSLATE_NOOP(
    "Service", "{0} cannot start while {1} runs on this valve: stop {1} first; nothing was started"
)


class MotionBusyError(Prm9Error):
    """Another motion owns the valve's setpoint (``running``, ``wanted``: keys of MOTIONS)."""

    def __init__(self, wanted: str, running: str) -> None:
        super().__init__(BUSY(_name(wanted), _name(running)))
        self.wanted, self.running = wanted, running


def _name(motion: str) -> Message | str:
    template = MOTIONS.get(motion)
    return template() if template is not None else motion


class MotionOwner:
    """The one motion running on a valve (thread-safe)."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._running: str | None = None

    @property
    def running(self) -> str | None:
        """The key of the motion running now (None: the setpoint is free)."""
        return self._running

    def take(self, motion: str) -> None:
        """Claim the setpoint for ``motion``; MotionBusyError while another runs."""
        with self._lock:
            if self._running is not None:
                raise MotionBusyError(motion, self._running)
            self._running = motion

    def release(self, motion: str) -> None:
        """Give the setpoint back (only the running motion can; idempotent)."""
        with self._lock:
            if self._running == motion:
                self._running = None


_OWNERS: weakref.WeakKeyDictionary[object, MotionOwner] = weakref.WeakKeyDictionary()
_OWNERS_LOCK = threading.Lock()


def owner_of(session: object) -> MotionOwner:
    """The motion owner of an open valve's session (made on first use, gone with it)."""
    with _OWNERS_LOCK:
        owner = _OWNERS.get(session)
        if owner is None:
            owner = _OWNERS[session] = MotionOwner()
        return owner


@contextmanager
def claim(session: object, motion: str) -> Iterator[None]:
    """``with claim(session, "characterization"): …`` — the setpoint is the block's."""
    owner = owner_of(session)
    owner.take(motion)
    try:
        yield
    finally:
        owner.release(motion)
