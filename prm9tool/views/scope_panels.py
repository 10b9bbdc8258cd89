"""The oscilloscope's measuring-point panel (right) and control panel (bottom), figure 8-20."""

from __future__ import annotations

from collections.abc import Sequence

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDoubleSpinBox,
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QListWidget,
    QListWidgetItem,
    QMenu,
    QPushButton,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from prm9tool.i18n import text
from prm9tool.scope import RATES_HZ, WINDOWS_S, Edge, TriggerMode, TriggerSettings
from prm9tool.signals import MAX_CHANNELS
from prm9tool.signals import Signal as MeasuringPoint

KEY_ROLE = Qt.ItemDataRole.UserRole


class ChannelPanel(QGroupBox):
    """Every measuring point of the variant as a check box; at most three are active."""

    selection_changed = Signal(list)  # keys, in channel order

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.list = QListWidget()
        self.message = QLabel()
        self.message.setWordWrap(True)
        self.message.setStyleSheet("color: #c01c28")
        layout = QVBoxLayout(self)
        layout.addWidget(self.list, 1)
        layout.addWidget(self.message)
        self._selected: list[str] = []
        self._signals: list[MeasuringPoint] = []
        self.list.itemChanged.connect(self._on_item_changed)
        self.retranslate()

    def retranslate(self) -> None:
        """Re-read user-visible texts (after a language change)."""
        self.setTitle(self.tr("Measuring points"))
        self.set_signals(self._signals)

    def set_signals(self, signals: Sequence[MeasuringPoint]) -> None:
        """List ``signals`` (the variant's); the selection keeps those still listed."""
        self._signals = list(signals)
        keys = {s.key for s in signals}
        self._selected = [k for k in self._selected if k in keys]
        self.list.blockSignals(True)
        self.list.clear()
        for signal in signals:
            item = QListWidgetItem(f"{text(signal.text)} [{signal.unit}]")
            item.setData(KEY_ROLE, signal.key)
            item.setFlags(item.flags() | Qt.ItemFlag.ItemIsUserCheckable)
            self.list.addItem(item)
        self.list.blockSignals(False)
        self.list.setMinimumWidth(self.list.sizeHintForColumn(0) + 24)
        self._show_selection()

    def selected(self) -> list[str]:
        """Active measuring-point keys in channel order."""
        return list(self._selected)

    def set_selected(self, keys: Sequence[str]) -> None:
        """Activate ``keys`` (the first three that are listed)."""
        listed = [s.key for s in self._signals]
        self._selected = [k for k in keys if k in listed][:MAX_CHANNELS]
        self._show_selection()
        self.selection_changed.emit(self.selected())

    def preselect(self, key: str) -> None:
        """Activate ``key`` (from the diagram); with three active it replaces the third."""
        if key in self._selected or key not in [s.key for s in self._signals]:
            return
        self.message.clear()
        if len(self._selected) >= MAX_CHANNELS:
            self.message.setText(
                self.tr("At most three measuring points: {0} replaces {1}.").format(
                    self._name(key), self._name(self._selected[-1])
                )
            )
            self._selected = self._selected[:-1]
        self.set_selected([*self._selected, key])

    def _name(self, key: str) -> str:
        return next(text(s.text) for s in self._signals if s.key == key)

    def _on_item_changed(self, item: QListWidgetItem) -> None:
        key = item.data(KEY_ROLE)
        checked = item.checkState() == Qt.CheckState.Checked
        self.message.clear()
        if checked and key not in self._selected:
            if len(self._selected) >= MAX_CHANNELS:
                self.message.setText(
                    self.tr(
                        "At most three measuring points can be recorded at once. "
                        "Switch one off before adding {0}."
                    ).format(self._name(key))
                )
                self._show_selection()
                return
            self._selected.append(key)
        elif not checked and key in self._selected:
            self._selected.remove(key)
        else:
            return
        self.selection_changed.emit(self.selected())

    def _show_selection(self) -> None:
        self.list.blockSignals(True)
        for row in range(self.list.count()):
            item = self.list.item(row)
            on = item.data(KEY_ROLE) in self._selected
            item.setCheckState(Qt.CheckState.Checked if on else Qt.CheckState.Unchecked)
        self.list.blockSignals(False)


class ControlPanel(QWidget):
    """Recording, trigger, cursor and export controls."""

    start_requested = Signal()
    stop_requested = Signal()
    pause_toggled = Signal(bool)
    rate_changed = Signal(int)
    window_changed = Signal(float)
    trigger_changed = Signal(object)  # TriggerSettings
    cursors_toggled = Signal(bool)
    same_scale_toggled = Signal(bool)
    csv_requested = Signal(bool)  # True: the whole recording, False: the visible window
    png_requested = Signal()

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.rate = QComboBox()
        for rate in RATES_HZ:
            self.rate.addItem(f"{1000.0 / rate:g} ms ({rate / 1000:g} kHz)", rate)
        self.time_window = QComboBox()
        for seconds in WINDOWS_S:
            self.time_window.addItem(f"{seconds:g} s", seconds)
        self.time_window.setCurrentIndex(WINDOWS_S.index(1.0))
        self.start, self.stop, self.pause = QPushButton(), QPushButton(), QPushButton()
        self.pause.setCheckable(True)
        self.mode, self.channel, self.edge = QComboBox(), QComboBox(), QComboBox()
        self.channel.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToContents)
        for mode in TriggerMode:
            self.mode.addItem("", mode)
        for edge in Edge:
            self.edge.addItem("", edge)
        self.level, self.pre = QDoubleSpinBox(), QDoubleSpinBox()
        self.level.setRange(-1e6, 1e6)
        self.level.setDecimals(2)
        self.level.setKeyboardTracking(False)
        self.pre.setRange(0, 100)
        self.pre.setDecimals(0)
        self.pre.setSuffix(" %")
        self.pre.setValue(20)
        self.cursors, self.same_scale = QCheckBox(), QCheckBox()
        self.same_scale.setChecked(True)
        self.csv, self.png = QToolButton(), QPushButton()
        self.csv.setPopupMode(QToolButton.ToolButtonPopupMode.InstantPopup)
        self.csv.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextOnly)
        self.csv.setMenu(QMenu(self.csv))
        self._units: list[str] = []
        self._build_layout()
        self._connect()
        self.retranslate()
        self.set_running(False)

    def _build_layout(self) -> None:
        self.recording = QGroupBox()
        grid = QGridLayout(self.recording)
        self.rate_label, self.time_window_label = QLabel(), QLabel()
        grid.addWidget(self.rate_label, 0, 0)
        grid.addWidget(self.rate, 0, 1)
        grid.addWidget(self.time_window_label, 1, 0)
        grid.addWidget(self.time_window, 1, 1)
        grid.addWidget(self.start, 0, 2)
        grid.addWidget(self.stop, 1, 2)
        grid.addWidget(self.pause, 0, 3)
        self.trigger = QGroupBox()
        grid = QGridLayout(self.trigger)
        grid.addWidget(self.mode, 0, 0)
        grid.addWidget(self.edge, 1, 0)
        grid.addWidget(self.channel, 0, 1)
        grid.addWidget(self.level, 1, 1)
        self.pre_label = QLabel()
        grid.addWidget(self.pre_label, 0, 2)
        grid.addWidget(self.pre, 1, 2)
        self.tools = QGroupBox()
        grid = QGridLayout(self.tools)
        grid.addWidget(self.cursors, 0, 0)
        grid.addWidget(self.same_scale, 0, 1)
        grid.addWidget(self.csv, 1, 0)
        grid.addWidget(self.png, 1, 1)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        for box in (self.recording, self.trigger, self.tools):
            layout.addWidget(box)

    def _connect(self) -> None:
        self.start.clicked.connect(self.start_requested)
        self.stop.clicked.connect(self.stop_requested)
        self.pause.toggled.connect(self._on_pause_toggled)
        self.rate.currentIndexChanged.connect(lambda _: self.rate_changed.emit(self.rate_hz()))
        self.time_window.currentIndexChanged.connect(
            lambda _: self.window_changed.emit(self.window_s())
        )
        for combo in (self.mode, self.channel, self.edge):
            combo.currentIndexChanged.connect(self._on_trigger_edited)
        self.level.valueChanged.connect(self._on_trigger_edited)
        self.pre.valueChanged.connect(self._on_trigger_edited)
        self.cursors.toggled.connect(self.cursors_toggled)
        self.same_scale.toggled.connect(self.same_scale_toggled)
        self.png.clicked.connect(self.png_requested)

    def retranslate(self) -> None:
        """Re-read user-visible texts (after a language change)."""
        self.recording.setTitle(self.tr("Recording"))
        self.rate_label.setText(self.tr("Interval"))
        self.time_window_label.setText(self.tr("Time window"))
        self.start.setText(self.tr("Start"))
        self.stop.setText(self.tr("Stop"))
        self._on_pause_label()
        self.trigger.setTitle(self.tr("Trigger"))
        names = {
            TriggerMode.ROLL: self.tr("Roll (no trigger)"),
            TriggerMode.AUTO: self.tr("Auto"),
            TriggerMode.NORMAL: self.tr("Normal"),
            TriggerMode.SINGLE: self.tr("Single"),
            Edge.RISING: self.tr("Rising edge"),
            Edge.FALLING: self.tr("Falling edge"),
        }
        for combo in (self.mode, self.edge):
            for row in range(combo.count()):
                combo.setItemText(row, names[combo.itemData(row)])  # StrEnum == its str
        self.pre_label.setText(self.tr("Pre-trigger"))
        self.level.setToolTip(self.tr("Trigger level in the trigger channel's unit"))
        self.tools.setTitle(self.tr("Display and export"))
        self.cursors.setText(self.tr("Cursors A/B"))
        self.same_scale.setText(self.tr("Same scale per unit"))
        self.same_scale.setToolTip(
            self.tr("Autoscaled channels with the same unit share one scale")
        )
        self.csv.setText(self.tr("Export CSV"))
        menu = self.csv.menu()
        menu.clear()
        menu.addAction(self.tr("Visible window…"), lambda: self.csv_requested.emit(False))
        menu.addAction(self.tr("Whole recording…"), lambda: self.csv_requested.emit(True))
        self.png.setText(self.tr("Export PNG…"))

    def _on_pause_toggled(self, paused: bool) -> None:
        self._on_pause_label()
        self.pause_toggled.emit(paused)

    def _on_pause_label(self) -> None:
        self.pause.setText(self.tr("Resume") if self.pause.isChecked() else self.tr("Pause"))

    def _on_trigger_edited(self, *_: object) -> None:
        row = self.channel.currentIndex()
        self.level.setSuffix(f" {self._units[row]}" if 0 <= row < len(self._units) else "")
        self.trigger_changed.emit(self.trigger_settings())

    # --- state in and out --------------------------------------------------------------------
    def rate_hz(self) -> int:
        """Selected sample rate."""
        return int(self.rate.currentData())

    def window_s(self) -> float:
        """Selected time window."""
        return float(self.time_window.currentData())

    def trigger_settings(self) -> TriggerSettings:
        """The trigger as set up."""
        return TriggerSettings(
            mode=TriggerMode(self.mode.currentData()),
            channel=max(0, self.channel.currentIndex()),
            level=self.level.value(),
            edge=Edge(self.edge.currentData()),
            pre=self.pre.value() / 100.0,
        )

    def set_channels(self, signals: Sequence[MeasuringPoint]) -> None:
        """Offer the active channels as trigger sources."""
        self._units = [s.unit for s in signals]
        self.channel.blockSignals(True)
        row = self.channel.currentIndex()
        self.channel.clear()
        for slot, signal in enumerate(signals):
            self.channel.addItem(f"{slot + 1}: {text(signal.text)}")
        self.channel.setCurrentIndex(min(max(row, 0), len(signals) - 1))
        self.channel.blockSignals(False)
        self._on_trigger_edited()

    def set_running(self, running: bool, can_start: bool = True) -> None:
        """Enable Start/Stop for a running or stopped capture."""
        self.start.setEnabled(not running and can_start)
        self.stop.setEnabled(running)
        self.pause.setEnabled(running)
        if not running:
            self.set_paused(False)

    def set_paused(self, paused: bool) -> None:
        """Reflect a display hold the widget decided on (single trigger done, stop)."""
        self.pause.blockSignals(True)
        self.pause.setChecked(paused)
        self.pause.blockSignals(False)
        self._on_pause_label()
