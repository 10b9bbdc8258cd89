"""A message label of a fixed number of lines: its text wraps in place, nothing around it moves.

A word-wrapped QLabel grows and shrinks with its text; in a layout that moves the buttons
beside or below it while the user aims at them (the oscilloscope's status line, the reason
in Valve status: clicks were missed). This label keeps the height of ``lines`` lines whatever
it says; a text longer than that is cut below its last whole line and shown whole as its tip.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QRect, Qt
from PySide6.QtGui import QResizeEvent
from PySide6.QtWidgets import QLabel, QSizePolicy, QWidget

FLAGS = Qt.TextFlag.TextWordWrap | Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop


class FixedLinesLabel(QLabel):
    """A word-wrapped label always ``lines`` lines high."""

    def __init__(self, lines: int, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._lines = lines
        self.setWordWrap(True)
        self.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        self.setMinimumWidth(1)  # a long text wraps instead of widening the window
        self.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Fixed)
        self._fit_height()

    def setText(self, text: str) -> None:
        """Show ``text``, wrapped in the label's lines (whole in the tip when it is longer)."""
        super().setText(text)
        self._update_tip()

    def overflows(self) -> bool:
        """True when the text needs more lines than the label has (the rest is cut)."""
        metrics = self.fontMetrics()
        box = QRect(0, 0, max(1, self.contentsRect().width()), 100_000)
        needed = metrics.boundingRect(box, FLAGS, self.text()).height()
        return needed > self._lines * metrics.lineSpacing()

    def _update_tip(self) -> None:
        self.setToolTip(self.text() if self.overflows() else "")

    def _fit_height(self) -> None:
        margins = self.contentsMargins()
        lines = self._lines * self.fontMetrics().lineSpacing()
        self.setFixedHeight(lines + margins.top() + margins.bottom())

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Wrap the text anew for the new width."""
        super().resizeEvent(event)
        self._update_tip()

    def changeEvent(self, event: QEvent) -> None:
        """Keep the lines' height when the font changes."""
        super().changeEvent(event)
        if event.type() == QEvent.Type.FontChange:
            self._fit_height()
            self._update_tip()
