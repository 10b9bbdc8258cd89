"""One reader of a session's stream of measuring points, for every loop over it: the API's and
the command line's capture (:func:`prm9tool.service.stream.record`), the oscilloscope's stream
in the GUI's worker (:class:`prm9tool.service.polling.Poller`) and the characterization rig's
play (:meth:`prm9tool.characterize.rig.LinkRig.play`). It starts the stream, drains its blocks,
counts the lost samples by the session's own ``samples_lost`` and says, in the same words at
every door, when the valve has gone silent. It sits in the device layer, below the service, so
that the rig (the characterization layer, which the service imports) can use it too. No Qt.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from prm9tool.errors import DeviceTimeoutError
from prm9tool.messages import QT_TRANSLATE_NOOP

if TYPE_CHECKING:
    import numpy as np

    from prm9tool.device.session import ValveSession

__all__ = ["SILENCE_S", "StreamReader", "StreamSilentError", "silence_bound_s"]

SILENCE_S = 1.0  # no sample for this long (and for 20 sample periods): the stream is dead


def silence_bound_s(rate_hz: float) -> float:
    """How long a stream at ``rate_hz`` may send nothing before it counts as dead: a second,
    or 20 sample periods where those are longer (a slow stream's reports are far apart)."""
    return max(SILENCE_S, 20 / rate_hz)


class StreamSilentError(DeviceTimeoutError):
    """The valve sent no sample of a running stream for :func:`silence_bound_s`."""

    # the link may still answer its requests while the stream is silent: not "did not answer"
    summary = QT_TRANSLATE_NOOP("Errors", "The valve stopped sending its measuring points.")


class StreamReader:
    """A stream of ``keys`` at ``rate_hz`` on ``session``: :meth:`start`, :meth:`read` its
    blocks (raw values, shape (n, len(keys)); NaN rows are lost samples over CANopen),
    :meth:`stop`. :attr:`lost` is the session's count of lost samples since the start."""

    def __init__(
        self,
        session: ValveSession,
        keys: Sequence[str],
        rate_hz: int,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        if not rate_hz > 0:
            raise ValueError(f"a stream needs a positive rate, not {rate_hz} Hz")
        self.session = session
        self.keys = list(keys)
        self.rate_hz = rate_hz
        self.silence_s = silence_bound_s(rate_hz)
        self.received = 0  # samples read since the start
        self.lost = 0  # the session's samples_lost at the last read
        self.running = False
        self._clock = clock
        self._heard = 0.0

    def start(self) -> None:
        """Start the stream (the session's count of lost samples starts again at 0)."""
        self.session.stream_start(self.keys, self.rate_hz)
        self.running = True
        self.received = self.lost = 0
        self._heard = self._clock()

    def read(self, expected: int | None = None) -> np.ndarray:
        """The samples received since the last read (may be none yet). StreamSilentError when
        none arrived for :attr:`silence_s`; its words name the count received, and of
        ``expected`` where a finite recording says how many it wants."""
        block = self.session.stream_read()
        now = self._clock()
        self.lost = self.session.samples_lost
        if len(block):
            self.received += len(block)
            self._heard = now
        elif now - self._heard > self.silence_s:
            raise StreamSilentError(self.silent_words(expected))
        return block

    def silent_words(self, expected: int | None = None) -> str:
        """What a dead stream is called at every door."""
        wanted = f" of {expected}" if expected is not None else ""
        return f"the valve sent no samples for {self.silence_s:.1f} s ({self.received} received{wanted})"

    def stop(self) -> None:
        """Stop the stream (nothing happens where it is not running)."""
        if self.running:
            self.running = False
            self.session.stream_stop()

    def __enter__(self) -> StreamReader:
        self.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()
