"""Rows of the oscilloscope's controls under the plot: a bold name, its widgets, and the texts
of the sample rates and time windows in the program language."""

from __future__ import annotations

from collections.abc import Sequence

from PySide6.QtCore import QSize
from PySide6.QtWidgets import QComboBox, QHBoxLayout, QLabel, QWidget

from prm9tool.i18n import format_significant

SPACE = None  # a gap between groups of controls in a row


class ShrinkingCombo(QComboBox):
    """A combo box as wide as its longest item when there is room, down to ``minimum``
    characters in a small window (a long item is elided there; its tooltip says it all)."""

    def __init__(self, minimum: int) -> None:
        super().__init__()
        self.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon)
        self.setMinimumContentsLength(minimum)

    def sizeHint(self) -> QSize:
        """Wide enough for the longest item."""
        hint = super().sizeHint()
        metrics = self.fontMetrics()
        widest = max(
            (metrics.horizontalAdvance(self.itemText(i)) for i in range(self.count())), default=0
        )
        short = metrics.horizontalAdvance("x") * self.minimumContentsLength()
        return QSize(hint.width() + max(0, widest - short), hint.height())


def rate_text(rate_hz: int) -> str:
    """A sample rate as its interval and frequency, "0,2 ms (5 kHz)" in German."""
    period, khz = format_significant(1000.0 / rate_hz, 6), format_significant(rate_hz / 1000, 6)
    return f"{period} ms ({khz} kHz)"


def window_text(seconds: float) -> str:
    """A time window, "0,5 s" in German."""
    return f"{format_significant(seconds, 6)} s"


def section_label() -> QLabel:
    """A bold label naming a row of controls (Recording, Trigger, Setpoint generator)."""
    label = QLabel()
    font = label.font()
    font.setBold(True)
    label.setFont(font)
    return label


def control_row(
    label: QLabel, widgets: Sequence[QWidget | None], end: QWidget | None = None
) -> QHBoxLayout:
    """``label`` and ``widgets`` in a row (None: a gap), ``end`` at the right edge."""
    row = QHBoxLayout()
    row.addWidget(label)
    for widget in widgets:
        if widget is None:
            row.addSpacing(12)
        else:
            row.addWidget(widget)
    row.addStretch(1)
    if end is not None:
        row.addWidget(end)
    return row
