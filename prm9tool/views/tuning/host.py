"""What the Tuning window's pages use of the window, and the fields they share.

The pages see the window through :class:`TuningHost`, so they do not import the window that
imports them.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any, Protocol

from PySide6.QtWidgets import QDoubleSpinBox, QHeaderView, QTableWidget

from prm9tool.analysis.profile import Profile
from prm9tool.catalogue import CATALOGUE
from prm9tool.i18n import format_value
from prm9tool.model.document import ParameterDocument


class TuningHost(Protocol):
    """The Tuning window as its pages see it."""

    doc: ParameterDocument
    connection: Any | None

    def start(
        self, kind: str, what: str, procedure: Callable[..., Any], planned_s: float | None = None
    ) -> bool:
        """Confirm (on a valve) what the test will do, then run ``procedure(rig)``;
        ``planned_s``: the valve seconds it plays (the progress bar; None: unknown). True when
        it started."""

    def profile(self) -> Profile:
        """The acceptance profile chosen on the test report page (ProfileError if unusable)."""

    def accept_values(self, values: dict[str, int], text: str) -> bool:
        """Put ``values`` into the document as one undo step; False (and why in the status
        line) when the access level locks one of them: the result stays to accept later."""

    def current_loop(self) -> str:
        """``position`` or ``process``."""

    def save_file(self, title: str, pattern: str, suggestion: str) -> Path | None:
        """Ask for a file name to write."""


def spin(value: float, low: float, high: float, suffix: str, decimals: int = 1) -> QDoubleSpinBox:
    """A number field with a unit."""
    box = QDoubleSpinBox()
    box.setRange(low, high)
    box.setDecimals(decimals)
    box.setValue(value)
    box.setSuffix(f" {suffix}")
    return box


def gain_text(mnemonic: str, raw: int) -> str:
    """``0.4`` (``0,4`` in German and Czech) with the catalogue's unit."""
    param = CATALOGUE[mnemonic]
    return f"{format_value(param, raw)} {param.unit}".strip()


def figure_table(columns: int) -> QTableWidget:
    """A table of figures whose first column (the figure's name) takes the width left and
    wraps, and whose other columns fit their contents and headers: beside a plot, a German
    "Ergebnis" column was cut off behind a scroll bar."""
    table = QTableWidget(0, columns)
    table.verticalHeader().setVisible(False)
    table.setWordWrap(True)
    header = table.horizontalHeader()
    header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
    header.setSectionResizeMode(0, QHeaderView.ResizeMode.Stretch)
    return table
