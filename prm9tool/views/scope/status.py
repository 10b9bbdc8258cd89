"""The oscilloscope's status line: why the valve does not follow its setpoint, what the
recording does (stopped, waiting for the trigger, paused, recording at a rate, offline) and
why the recording or the setpoint generator stopped without the user."""

from __future__ import annotations

from PySide6.QtCore import QObject

from prm9tool.i18n import format_significant
from prm9tool.online.connection_protocol import ScopeConnection, StatusView
from prm9tool.online.valve_control import blocker_text, status_blocker
from prm9tool.views.scope.display import ScopeDisplay


class ScopeStatusText(QObject):
    """The texts of the status line for ``connection`` and ``display``."""

    def __init__(self, connection: ScopeConnection, display: ScopeDisplay, parent: QObject) -> None:
        super().__init__(parent)
        self._connection = connection
        self._display = display

    def blocked(self, status: StatusView | None) -> str:
        """Why the valve does not follow its setpoint (empty when it does, or offline)."""
        reason = status_blocker(status) if self._connection.is_online else None
        if reason is None:
            return ""
        text = blocker_text(reason, status)
        return self.tr("The valve does not follow its setpoint: {0}").format(text)

    def state(self, running: bool) -> str:
        """What the recording does."""
        display = self._display
        if not self._connection.is_online:
            return self.offline()
        if not running:
            return self.tr("Stopped. Choose up to three measuring points and press Start.")
        if display.engine.done:
            return self.tr("Single capture complete. Resume arms the trigger again.")
        if display.frozen:
            return self.tr("Paused: zoom and pan with the mouse; recording continues.")
        if display.waiting:
            return self.tr("Waiting for the trigger…")
        return self._recording()

    def _recording(self) -> str:
        rate = self._display.capture.rate_hz if self._display.capture else 0
        lost = self._connection.samples_lost
        if not lost:
            return self.tr("Recording at {0} Hz.").format(rate)
        rows = self._display.capture.buffer.total if self._display.capture else 0
        device = getattr(self._connection, "device", None)
        if getattr(device, "stream_gaps", False):  # lost samples are NaN rows at their time
            real = rate * max(rows - lost, 0) / rows if rows else 0.0
        else:
            real = rate * rows / (rows + lost)  # what the link really delivers
        return self.tr(
            "Recording at {0} Hz of the {1} Hz asked for: {2} samples lost on the link."
        ).format(format_significant(real, 3), rate, lost)

    def offline(self) -> str:
        """Offline, the scope has nothing to show."""
        return self.tr(
            "The oscilloscope needs a connected valve: go online (Communication → Online)."
        )

    def stream_taken(self) -> str:
        """The recording stopped because another operation took the stream."""
        return self.tr("The recording stopped: another operation (a tuning test…) took the stream.")

    def stream_silent(self, why: str) -> str:
        """The recording stopped because the valve sent no more samples."""
        return self.tr("The recording stopped: {0}").format(why)

    def generator_link_dropped(self) -> str:
        """The setpoint generator stopped with the link."""
        return self.tr("The link dropped: the setpoint generator has stopped.")

    def generator_displaced(self) -> str:
        """The setpoint generator stopped for another operation."""
        return self.tr(
            "The setpoint generator has stopped: another operation (a tuning test, an upload…) "
            "drives the valve now."
        )

    def generator_refused(self, reason: str) -> str:
        """The valve refused a value of the setpoint generator (``reason``: its answer)."""
        return self.tr(
            "The valve refused a value of the setpoint generator ({0}): the generator has stopped."
        ).format(reason or self.tr("no reason given"))
