"""The oscilloscope's legend: per channel its colour, name (elided, full text as tooltip),
autoscale button and the value under the cursor or the latest one."""

from __future__ import annotations

import math

from PySide6.QtCore import QSize, Qt
from PySide6.QtGui import QFontMetrics, QResizeEvent
from PySide6.QtWidgets import QGridLayout, QLabel, QToolButton, QWidget

from prm9tool.catalogue.signals import Signal as MeasuringPoint
from prm9tool.i18n import format_significant, text

COLOURS = ("#ffd43b", "#4dd0e1", "#ff7eb6")  # channel 1, 2, 3
LIVE_COLOUR = "#7a7a7a"  # legend values newer than the held trace


def _format(value: float, unit: str) -> str:
    """A value with 4 significant digits and its unit ('—' for NaN)."""
    return "—" if math.isnan(value) else f"{format_significant(value, 4)} {unit}"


class ElidedLabel(QLabel):
    """A label that shortens its text with "…" when narrower than the text (full: tooltip)."""

    def __init__(self) -> None:
        super().__init__()
        self._full = ""

    def set_full_text(self, full: str) -> None:
        """Show ``full``, elided to the label's width."""
        self._full = full
        self.setToolTip(full)
        self._elide()
        self.updateGeometry()

    def sizeHint(self) -> QSize:
        """Wide enough for the whole text."""
        width = self.fontMetrics().horizontalAdvance(self._full) + 4
        return QSize(width, super().sizeHint().height())

    def minimumSizeHint(self) -> QSize:
        """Narrow: the text is elided instead."""
        return QSize(40, super().minimumSizeHint().height())

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Elide the text to the new width."""
        super().resizeEvent(event)
        self._elide()

    def _elide(self) -> None:
        metrics = self.fontMetrics()
        self.setText(metrics.elidedText(self._full, Qt.TextElideMode.ElideRight, self.width()))


class LegendEntry(QWidget):
    """Colour, name and autoscale button of one channel above its value.

    The value has a label of its own with a fixed width, so a new value never re-lays out
    the window (that would cost a full repaint at every legend update). While the plot holds
    a recording and the valve's values go on arriving, the value is marked as live.
    """

    def __init__(self, slot: int, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.swatch = QLabel("■")
        self.swatch.setStyleSheet(f"color: {COLOURS[slot]}")
        self.name = ElidedLabel()
        self.value = QLabel()
        bold = self.value.font()
        bold.setBold(True)
        self.value.setFont(bold)
        self.autoscale = QToolButton()  # a framed button, not a bare word
        grid = QGridLayout(self)
        grid.setContentsMargins(0, 0, 12, 0)
        grid.setHorizontalSpacing(4)
        grid.setVerticalSpacing(0)
        grid.addWidget(self.swatch, 0, 0)
        grid.addWidget(self.name, 0, 1)
        grid.addWidget(self.autoscale, 0, 2)
        grid.addWidget(self.value, 1, 0, 1, 3)
        grid.setColumnStretch(3, 1)  # the button next to the name, the space after it
        self._unit = ""
        self._key = ""
        self._live_prefix = ""
        self._last_prefix = ""
        self._value = math.nan
        self._live = False
        self._last = False
        self._tips = ("", "")  # what "live:" and "at stop:" mean

    def set_signal(self, signal: MeasuringPoint) -> None:
        """Show ``signal``'s name and unit (its value stays when only the language changed,
        shown in the new language's numbers)."""
        self._unit = signal.unit
        self.name.set_full_text(text(signal.text))  # the unit is in the value below
        self.name.setToolTip(f"{text(signal.text)} [{signal.unit}]")
        same = signal.key == self._key
        self._key = signal.key
        self.set_value(self._value if same else math.nan, self._live, self._last and same)

    def set_live_texts(self, prefix: str, tooltip: str, last: str = "", last_tip: str = "") -> None:
        """The words marking a live value while the plot holds and the last one after Stop,
        and what they mean."""
        self._live_prefix, self._last_prefix = prefix, last
        self._tips = (tooltip, last_tip)
        widest = max(prefix, last, key=len) + " −00000.0 mA"
        self.value.setFixedWidth(QFontMetrics(self.value.font()).horizontalAdvance(widest) + 4)
        self.set_value(self._value, self._live, self._last)

    def set_value(self, value: float, live: bool = False, last: bool = False) -> None:
        """Show ``value``; ``live``: newer than the held trace; ``last``: the value when the
        recording stopped (the valve may hold another one now)."""
        if (live, last) != (self._live, self._last):  # a style change re-polishes the label
            grey = live or last
            italic = "; font-style: italic" if live else ""
            self.value.setStyleSheet(f"color: {LIVE_COLOUR}{italic}" if grey else "")
        self._value, self._live, self._last = value, live, last
        shown = _format(value, self._unit)
        prefix = self._live_prefix if live else self._last_prefix if last else ""
        self.value.setText(f"{prefix} {shown}" if prefix and not math.isnan(value) else shown)
        self.value.setToolTip(self._tips[0] if live else self._tips[1] if last else "")
