"""Valve selection (manual §8.7.1): build a type key from its parts, or type one in.

The parts are the ones of the type key: nominal size, spool, nominal flow, supply voltage,
configuration (internal position feedback E02 / external feedback E04) and CANopen. Every
combination offered is valid; a typed key is validated and the reason shown if it is not.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QSignalBlocker
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue.typekey import FLOWS, SPOOLS, SUPPLIES, SpoolSource, TypeKey
from prm9tool.catalogue.variant import Config
from prm9tool.errors import TypeKeyError
from prm9tool.translate import error_text
from prm9tool.views.diagram.colours import toned_style

DEFAULT_TYPE_KEY = "PRM9-06.3Z11/30-24E02S02"


class ValveSelectionDialog(QDialog):
    """The type-key builder; ``selected_type_key()`` is valid after ``accept``."""

    def __init__(self, current: TypeKey | None = None, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._key: TypeKey = current or TypeKey.parse(DEFAULT_TYPE_KEY)
        self.nominal_size = QComboBox()
        self.spool = QComboBox()
        self.flow = QComboBox()
        self.supply = QComboBox()
        self.config = QComboBox()
        self.canopen = QCheckBox("CANopen (-CA)")
        self.key_edit = QLineEdit()
        self.error_label = QLabel()
        self.error_label.setStyleSheet(toned_style("color: #d03030;", self.palette()))
        self.error_label.setWordWrap(True)
        self._error: TypeKeyError | None = None  # why the typed key is refused
        self._titles = [QLabel() for _ in range(7)]
        self._intro = QLabel()
        self._intro.setWordWrap(True)
        self.buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        self._fill_static_choices()
        self._build_layout()
        self._connect()
        self.retranslate()
        self._show_key(self._key)

    def _fill_static_choices(self) -> None:
        for size in FLOWS:
            self.nominal_size.addItem(f"Dn{size}", size)
        for spool in SPOOLS.values():
            self.spool.addItem(spool.code, spool.code)
        for supply in SUPPLIES:
            self.supply.addItem(f"{supply} V DC", supply)
        for config in Config:  # item data is the plain value: Qt hands enums back as str
            self.config.addItem(config.value, config.value)

    def _build_layout(self) -> None:
        form = QFormLayout()
        fields = (self.nominal_size, self.spool, self.flow, self.supply, self.config, self.canopen)
        for title, field in zip(self._titles, fields, strict=False):
            form.addRow(title, field)
        form.addRow(self._titles[6], self.key_edit)
        layout = QVBoxLayout(self)
        layout.addWidget(self._intro)
        layout.addLayout(form)
        layout.addWidget(self.error_label)
        layout.addWidget(self.buttons)
        self.key_edit.setMinimumWidth(self.key_edit.fontMetrics().horizontalAdvance("M" * 26))

    def _connect(self) -> None:
        self.nominal_size.currentIndexChanged.connect(self._on_size_changed)
        for combo in (self.spool, self.flow, self.supply, self.config):
            combo.currentIndexChanged.connect(self._on_parts_changed)
        self.canopen.toggled.connect(self._on_parts_changed)
        self.key_edit.textEdited.connect(self._on_key_edited)

    def retranslate(self) -> None:
        """Set every text in the current language."""
        self.setWindowTitle(self.tr("Valve selection"))
        self._intro.setText(
            self.tr(
                "Choose the valve by its type key. The new parameter set holds the factory "
                "defaults of that type; valve-specific calibration data is not included."
            )
        )
        titles = (
            self.tr("Nominal size:"),
            self.tr("Spool:"),
            self.tr("Nominal flow (Δp 10 bar):"),
            self.tr("Supply voltage:"),
            self.tr("Configuration:"),
            self.tr("Interface:"),
            self.tr("Type key:"),
        )
        for label, title in zip(self._titles, titles, strict=True):
            label.setText(title)
        self.config.setItemText(0, self.tr("E02 – internal position feedback"))
        self.config.setItemText(1, self.tr("E04 – internal position and external feedback"))
        for row, spool in enumerate(SPOOLS.values()):
            note = self._source_note(spool.source)
            self.spool.setItemText(row, f"{spool.code} – {self._coil_text(spool.code)}{note}")
        if self._error is not None:
            self.error_label.setText(error_text(self._error))

    def _source_note(self, source: SpoolSource) -> str:
        if source is SpoolSource.ASSUMED:
            return self.tr(" (assumption)")
        if source is SpoolSource.USER:
            return self.tr(" (your spools.json)")
        return ""

    def _coil_text(self, code: str) -> str:
        coils = SPOOLS[code].coils.value
        if coils == "AB":
            return self.tr("two solenoids A and B")
        return self.tr("one solenoid on side {0}").format(coils)

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

    # --- state ------------------------------------------------------------------------------
    def selected_type_key(self) -> TypeKey:
        """The chosen type key (always valid)."""
        return self._key

    def _show_key(self, key: TypeKey) -> None:
        blockers = [
            QSignalBlocker(w)
            for w in (
                self.nominal_size,
                self.spool,
                self.flow,
                self.supply,
                self.config,
                self.canopen,
            )
        ]
        self.nominal_size.setCurrentIndex(self.nominal_size.findData(key.size))
        self._fill_flows(key.size)
        self.spool.setCurrentIndex(self.spool.findData(key.spool))
        self.flow.setCurrentIndex(self.flow.findData(key.flow))
        self.supply.setCurrentIndex(self.supply.findData(key.supply))
        self.config.setCurrentIndex(self.config.findData(key.config.value))
        self.canopen.setChecked(key.canopen)
        del blockers
        self._set_valid(key)

    def _fill_flows(self, size: str) -> None:
        current = self.flow.currentData()
        with QSignalBlocker(self.flow):
            self.flow.clear()
            for flow in FLOWS[size]:
                self.flow.addItem(f"{int(flow)} l/min", flow)
            self.flow.setCurrentIndex(max(0, self.flow.findData(current)))

    def _set_valid(self, key: TypeKey) -> None:
        self._key = key
        if self.key_edit.text() != str(key):
            self.key_edit.setText(str(key))
        self._error = None
        self.error_label.hide()
        self.buttons.button(QDialogButtonBox.StandardButton.Ok).setEnabled(True)

    def _on_size_changed(self) -> None:
        self._fill_flows(str(self.nominal_size.currentData()))
        self._on_parts_changed()

    def _on_parts_changed(self) -> None:
        key = TypeKey(
            size=str(self.nominal_size.currentData()),
            spool=str(self.spool.currentData()),
            flow=str(self.flow.currentData()),
            supply=str(self.supply.currentData()),
            config=Config(self.config.currentData()),
            canopen=self.canopen.isChecked(),
        )
        self._set_valid(key)

    def _on_key_edited(self, typed: str) -> None:
        try:
            key = TypeKey.parse(typed)
        except TypeKeyError as exc:
            self._error = exc
            self.error_label.setText(error_text(exc))
            self.error_label.show()
            self.buttons.button(QDialogButtonBox.StandardButton.Ok).setEnabled(False)
            return
        self._show_key(key)
