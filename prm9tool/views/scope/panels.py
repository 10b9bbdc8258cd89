"""The oscilloscope's measuring-point panel (right) and control rows (bottom), figure 8-20."""

from __future__ import annotations

from collections.abc import Sequence

from PySide6.QtCore import QSize, Qt, QTimer, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDoubleSpinBox,
    QGroupBox,
    QLabel,
    QListView,
    QListWidget,
    QListWidgetItem,
    QMenu,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue.signals import MAX_CHANNELS
from prm9tool.catalogue.signals import Signal as MeasuringPoint
from prm9tool.i18n import text
from prm9tool.scope import RATES_HZ, WINDOWS_S, Edge, TriggerMode, TriggerSettings
from prm9tool.views.diagram.colours import toned_style
from prm9tool.views.scope.rows import (
    SPACE,
    ShrinkingCombo,
    control_row,
    rate_text,
    section_label,
    window_text,
)

KEY_ROLE = Qt.ItemDataRole.UserRole
MIN_LIST_WIDTH = 230  # px: the measuring-point list in a 1024-pixel window
MESSAGE_MS = 8000  # how long a notice about the measuring points stays
MAX_LIST_WIDTH = 340  # px: wider names are elided rather than the legend's in a 1024-px window


class _PointList(QListWidget):
    """The measuring points: as wide as the longest name (within limits), narrower in a small
    window; a name wider than the list goes on onto a second line (elided, "Prozessabweichung
    nach Verstärkung und Offset …" was not told from its neighbours; issue 34 item 20), its
    tooltip says it all too."""

    def __init__(self) -> None:
        super().__init__()
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.setWordWrap(True)
        self.setTextElideMode(Qt.TextElideMode.ElideNone)
        self.setResizeMode(QListView.ResizeMode.Adjust)  # wrapped anew when the width changes

    def sizeHint(self) -> QSize:
        """The width of the longest name and a scroll bar, up to MAX_LIST_WIDTH."""
        scroll_bar = self.verticalScrollBar().sizeHint().width()
        wanted = self.sizeHintForColumn(0) + 2 * self.frameWidth() + scroll_bar + 4
        width = min(max(wanted, MIN_LIST_WIDTH), MAX_LIST_WIDTH)
        return QSize(width, super().sizeHint().height())

    def minimumSizeHint(self) -> QSize:
        """Narrow enough for a 1024-pixel window."""
        return QSize(MIN_LIST_WIDTH, super().minimumSizeHint().height())


class ChannelPanel(QGroupBox):
    """Every measuring point of the variant as a check box; at most three are active."""

    selection_changed = Signal(list)  # keys, in channel order
    same_scale_toggled = Signal(bool)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.list = _PointList()
        self.message = QLabel()
        self.message.setWordWrap(True)
        self.message.setStyleSheet(toned_style("color: #c01c28", self.palette()))
        self.message.hide()
        self._message_timer = QTimer(self)  # a refusal or replacement notice, then gone
        self._message_timer.setSingleShot(True)
        self._message_timer.setInterval(MESSAGE_MS)
        self._message_timer.timeout.connect(lambda: self._say(""))
        self.same_scale = QCheckBox()
        self.same_scale.setChecked(True)
        self.same_scale.toggled.connect(self.same_scale_toggled)
        layout = QVBoxLayout(self)
        layout.addWidget(self.list, 1)
        layout.addWidget(self.message)
        layout.addWidget(self.same_scale)
        self._selected: list[str] = []
        self._signals: list[MeasuringPoint] = []
        self.list.itemChanged.connect(self._on_item_changed)
        self.retranslate()

    def retranslate(self) -> None:
        """Re-read user-visible texts (after a language change)."""
        self.setTitle(self.tr("Measuring points"))
        self.same_scale.setText(self.tr("Same scale per unit"))
        self.same_scale.setToolTip(
            self.tr("Autoscaled channels with the same unit share one scale and one axis")
        )
        self.set_signals(self._signals)

    def set_signals(self, signals: Sequence[MeasuringPoint]) -> None:
        """List ``signals`` (the variant's); the selection keeps those still listed."""
        self._signals = list(signals)
        self._say("")  # another valve type: what was said about the points no longer applies
        keys = {s.key for s in signals}
        self._selected = [k for k in self._selected if k in keys]
        self.list.blockSignals(True)
        self.list.clear()
        for signal in signals:
            item = QListWidgetItem(f"{text(signal.text)} [{signal.unit}]")
            item.setToolTip(item.text())
            item.setData(KEY_ROLE, signal.key)
            item.setFlags(item.flags() | Qt.ItemFlag.ItemIsUserCheckable)
            self.list.addItem(item)
        self.list.blockSignals(False)
        self.list.updateGeometry()  # its size hint follows the longest name
        self._show_selection()

    def selected(self) -> list[str]:
        """Active measuring-point keys in channel order."""
        return list(self._selected)

    def set_selected(self, keys: Sequence[str]) -> None:
        """Activate ``keys`` (the first three that are listed)."""
        self._say("")
        self._select(keys)

    def _select(self, keys: Sequence[str]) -> None:
        listed = [s.key for s in self._signals]
        self._selected = [k for k in keys if k in listed][:MAX_CHANNELS]
        self._show_selection()
        self.selection_changed.emit(self.selected())

    def preselect(self, key: str) -> None:
        """Activate ``key`` (from the diagram); with three active it replaces the third."""
        if key in self._selected or key not in [s.key for s in self._signals]:
            return
        self._say("")
        if len(self._selected) >= MAX_CHANNELS:
            self._say(
                self.tr("At most three measuring points: {0} replaces {1}.").format(
                    self._name(key), self._name(self._selected[-1])
                )
            )
            self._selected = self._selected[:-1]
        self._select([*self._selected, key])

    def _say(self, message: str) -> None:
        """Show ``message`` for a while (it concerns the last action only); '' hides it."""
        self.message.setText(message)
        self.message.setVisible(bool(message))  # no gap above the check box when empty
        if message:
            self._message_timer.start()
        else:
            self._message_timer.stop()

    def _name(self, key: str) -> str:
        return next(text(s.text) for s in self._signals if s.key == key)

    def _on_item_changed(self, item: QListWidgetItem) -> None:
        key = item.data(KEY_ROLE)
        checked = item.checkState() == Qt.CheckState.Checked
        self._say("")
        if checked and key not in self._selected:
            if len(self._selected) >= MAX_CHANNELS:
                self._say(
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
    """Recording, trigger and export controls, in two rows under the plot."""

    start_requested = Signal()
    stop_requested = Signal()
    pause_toggled = Signal(bool)
    rate_changed = Signal(int)
    window_changed = Signal(float)
    trigger_changed = Signal(object)  # TriggerSettings
    csv_requested = Signal(bool)  # True: the whole recording, False: the visible window
    png_requested = Signal()

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.rate = QComboBox()
        for rate in RATES_HZ:
            self.rate.addItem(rate_text(rate), rate)
        self.time_window = QComboBox()
        for seconds in WINDOWS_S:
            self.time_window.addItem(window_text(seconds), seconds)
        self.time_window.setCurrentIndex(WINDOWS_S.index(1.0))
        self.start, self.stop, self.pause = QPushButton(), QPushButton(), QPushButton()
        self.pause.setCheckable(True)
        self.mode, self.channel, self.edge = QComboBox(), ShrinkingCombo(12), QComboBox()
        for combo in (self.rate, self.time_window, self.mode, self.edge):  # not only at the
            combo.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToContents)  # first show
        for mode in TriggerMode:
            self.mode.addItem("", mode)
        for edge in Edge:
            self.edge.addItem("", edge)
        self.level, self.pre = QDoubleSpinBox(), QDoubleSpinBox()
        self.level.setRange(-99999.99, 99999.99)  # wider than any measuring point
        self.level.setDecimals(2)
        self.level.setKeyboardTracking(False)
        self.pre.setRange(0, 100)
        self.pre.setDecimals(0)
        self.pre.setSuffix(" %")
        self.pre.setValue(20)
        # a push button with its menu: the arrow has room of its own beside the text (a tool
        # button's drew over the "t" of "Export"), and it is as high as Start beside it
        self.export = QPushButton()
        self.export.setMenu(QMenu(self.export))
        self._units: list[str] = []
        self._build_layout()
        self._connect()
        self.retranslate()
        self.set_running(False)

    def _build_layout(self) -> None:
        self.recording_label, self.trigger_label = section_label(), section_label()
        self.rate_label, self.time_window_label = QLabel(), QLabel()
        self.level_label, self.pre_label = QLabel(), QLabel()
        recording: tuple[QWidget | None, ...] = (self.start, self.stop, self.pause, SPACE)
        recording += (self.rate_label, self.rate, SPACE, self.time_window_label, self.time_window)
        trigger: tuple[QWidget | None, ...] = (self.mode, self.channel, self.edge, SPACE)
        trigger += (self.level_label, self.level, SPACE, self.pre_label, self.pre)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addLayout(control_row(self.recording_label, recording, self.export))
        layout.addLayout(control_row(self.trigger_label, trigger))

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

    def retranslate(self) -> None:
        """Re-read user-visible texts (after a language change)."""
        self.recording_label.setText(self.tr("Recording"))
        self.rate_label.setText(self.tr("Interval"))
        self.time_window_label.setText(self.tr("Time window"))
        self.start.setText(self.tr("Start"))
        self.stop.setText(self.tr("Stop"))
        self._on_pause_label()
        self.trigger_label.setText(self.tr("Trigger"))
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
        for row in range(self.rate.count()):  # the decimal separator of the new language
            self.rate.setItemText(row, rate_text(self.rate.itemData(row)))
        for row in range(self.time_window.count()):
            self.time_window.setItemText(row, window_text(self.time_window.itemData(row)))
        self.channel.setToolTip(self.tr("Trigger channel"))
        self.level_label.setText(self.tr("Level"))
        self.pre_label.setText(self.tr("Pre-trigger"))
        self.level.setToolTip(self.tr("Trigger level in the trigger channel's unit"))
        self.export.setText(self.tr("Export"))
        menu = self.export.menu()
        menu.clear()
        menu.addAction(
            self.tr("CSV of the visible window…"), lambda: self.csv_requested.emit(False)
        )
        menu.addAction(
            self.tr("CSV of the whole recording…"), lambda: self.csv_requested.emit(True)
        )
        menu.addAction(self.tr("PNG image of the plot…"), self.png_requested.emit)

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

    def limit_rates(self, limit_hz: float) -> None:
        """Offer only the rates the link delivers (``limit_hz``; 0: all), the fastest of them
        selected when the chosen one is not among them (at least the slowest is offered)."""
        allowed = [r for r in RATES_HZ if not limit_hz or r <= limit_hz] or [RATES_HZ[-1]]
        if [self.rate.itemData(i) for i in range(self.rate.count())] == allowed:
            return
        current = self.rate_hz()
        self.rate.blockSignals(True)
        self.rate.clear()
        for rate in allowed:
            self.rate.addItem(rate_text(rate), rate)
        self.rate.setCurrentIndex(allowed.index(current) if current in allowed else 0)
        self.rate.blockSignals(False)
        if self.rate_hz() != current:
            self.rate_changed.emit(self.rate_hz())

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
            self.channel.setItemData(slot, text(signal.text), Qt.ItemDataRole.ToolTipRole)
        self.channel.setCurrentIndex(min(max(row, 0), len(signals) - 1))
        self.channel.updateGeometry()  # its size hint follows the longest name
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
