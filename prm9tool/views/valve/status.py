"""Valve status window (manual §8.5, figure 8-3): state, identity, errors and the three LEDs.

The LEDs blink by themselves in the pattern the valve reports (manual tables 5-1, 5-2,
7-18; CiA 303-3 timing), because a 2 Hz status poll cannot sample a 2.5 Hz blink.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QPointF, QRectF, Qt, QTimer
from PySide6.QtGui import (
    QColor,
    QPainter,
    QPaintEvent,
    QPen,
    QRadialGradient,
    QResizeEvent,
    QShowEvent,
)
from PySide6.QtWidgets import (
    QDialog,
    QFormLayout,
    QGridLayout,
    QGroupBox,
    QLabel,
    QListWidget,
    QVBoxLayout,
    QWidget,
)

from prm9tool.i18n import format_measured
from prm9tool.online.connection_protocol import StatusConnection, StatusView, ValveIdentity
from prm9tool.online.valve_control import ValveControl
from prm9tool.views.emcy import emcy_text
from prm9tool.views.valve.commissioning import CommissioningPanel

COLOURS = {
    "white": "#f4f4f4",
    "green": "#30c040",
    "orange": "#ff9a1a",
    "red": "#ee2a2a",
    "blue": "#3a7bff",
    "magenta": "#e040e0",
}
# pattern -> ((lit, milliseconds), ...) repeated; CiA 303-3 indicator timing
PATTERNS: dict[str, tuple[tuple[bool, int], ...]] = {
    "on": ((True, 1000),),
    "off": ((False, 1000),),
    "1Hz": ((True, 500), (False, 500)),
    "2Hz": ((True, 250), (False, 250)),
    "2.5Hz": ((True, 200), (False, 200)),
    "single_flash": ((True, 200), (False, 1000)),
    "double_flash": ((True, 200), (False, 200), (True, 200), (False, 1000)),
    "triple_flash": ((True, 200), (False, 200)) * 2 + ((True, 200), (False, 1000)),
    "quadruple_flash": ((True, 200), (False, 200)) * 3 + ((True, 200), (False, 1000)),
    "boot": ((True, 500), (False, 500), (True, 500), (False, 500)),
}


class LedWidget(QWidget):
    """One LED drawn as a lamp; blinks in its pattern while visible."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.colour = "off"
        self.pattern = "off"
        self.lit = False
        self._step = 0
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.timeout.connect(self._on_timer_timeout)
        self.setMinimumSize(36, 36)

    def set_state(self, colour: str, pattern: str, lit: bool) -> None:
        """Show ``colour`` in ``pattern`` (restarts the blink cycle if the pattern changed)."""
        changed = (colour, pattern) != (self.colour, self.pattern)
        self.colour, self.pattern = colour, pattern
        if changed:
            self._step = 0
            self._timer.stop()
            self.lit = lit if pattern not in PATTERNS else PATTERNS[pattern][0][0]
            self._schedule()
        self.update()

    def _schedule(self) -> None:
        steps = PATTERNS.get(self.pattern)
        if steps and len(steps) > 1:
            self._timer.start(steps[self._step][1])

    def _on_timer_timeout(self) -> None:
        steps = PATTERNS[self.pattern]
        self._step = (self._step + 1) % len(steps)
        self.lit = steps[self._step][0]
        self.update()
        self._schedule()

    def paintEvent(self, event: QPaintEvent) -> None:
        """Draw the lamp: coloured and glowing when lit, dark grey when not."""
        side = min(self.width(), self.height()) - 4
        rect = QRectF((self.width() - side) / 2, (self.height() - side) / 2, side, side)
        on = self.lit and self.colour in COLOURS
        base = QColor(COLOURS.get(self.colour, "#555555")) if on else QColor("#3c3f44")
        gradient = QRadialGradient(rect.center() - QPointF(side / 6, side / 6), side / 1.6)
        gradient.setColorAt(0.0, base.lighter(170 if on else 130))
        gradient.setColorAt(1.0, base.darker(130))
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.setPen(QPen(QColor("#202225"), 1.5))
        painter.setBrush(gradient)
        painter.drawEllipse(rect)
        painter.end()


class ValveStatusWindow(QDialog):
    """Non-modal window that follows the connection's status live."""

    def __init__(
        self,
        connection: StatusConnection,
        parent: QWidget | None = None,
        control: ValveControl | None = None,
    ) -> None:
        super().__init__(parent)
        self._connection = connection
        self.commissioning = CommissioningPanel(control) if control is not None else None
        self._status: StatusView | None = None
        self.fields = {name: QLabel() for name in _FIELDS}
        for label in self.fields.values():
            label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self._field_titles = {name: QLabel() for name in _FIELDS}
        self.errors = QListWidget()
        self.leds = [LedWidget() for _ in range(3)]
        self._led_titles = [QLabel() for _ in range(3)]
        self._led_states = [QLabel() for _ in range(3)]
        self._groups = {name: QGroupBox() for name in ("valve", "errors", "leds")}
        self._build_layout()
        connection.status_changed.connect(self._on_connection_status_changed)
        connection.device_changed.connect(self._on_connection_device_changed)
        connection.online_changed.connect(self._on_connection_online_changed)
        self.retranslate()

    def _build_layout(self) -> None:
        form = QFormLayout(self._groups["valve"])
        for name in _FIELDS:
            form.addRow(self._field_titles[name], self.fields[name])
        QVBoxLayout(self._groups["errors"]).addWidget(self.errors)
        grid = QGridLayout(self._groups["leds"])
        for column, (led, title, state) in enumerate(
            zip(self.leds, self._led_titles, self._led_states, strict=True)
        ):
            grid.addWidget(led, 0, column, Qt.AlignmentFlag.AlignCenter)
            # the labels fill their column (a centred label keeps the width of its first
            # text, "—", and cut "green, on" short); a long pattern wraps
            for row, label in ((1, title), (2, state)):
                label.setAlignment(Qt.AlignmentFlag.AlignHCenter | Qt.AlignmentFlag.AlignTop)
                label.setWordWrap(True)
                grid.addWidget(label, row, column)
            grid.setColumnStretch(column, 1)
        layout = QVBoxLayout(self)
        for group in self._groups.values():
            layout.addWidget(group, 1 if group is self._groups["errors"] else 0)
        if self.commissioning is not None:
            layout.insertWidget(1, self.commissioning)
        self.errors.setMinimumHeight(60)
        self.resize(460, 640 if self.commissioning is not None else 520)

    def retranslate(self) -> None:
        """Set every text in the current language and refresh the values."""
        self.setWindowTitle(self.tr("Valve status"))
        self._groups["valve"].setTitle(self.tr("Valve"))
        self._groups["errors"].setTitle(self.tr("Active errors"))
        self._groups["leds"].setTitle(self.tr("LEDs"))
        titles = {
            "mode": self.tr("Mode:"),
            "firmware": self.tr("Firmware version:"),
            "serial": self.tr("Serial number:"),
            "type_key": self.tr("Type key:"),
            "state": self.tr("Device state:"),
            "nmt": self.tr("CANopen NMT state:"),
            "temperature": self.tr("Temperature:"),
            "supply": self.tr("Supply voltage:"),
        }
        for name, title in titles.items():
            self._field_titles[name].setText(title)
        led_names = (self.tr("LED 1 power"), self.tr("LED 2 error"), self.tr("LED 3 CAN"))
        for label, name in zip(self._led_titles, led_names, strict=True):
            label.setText(name)
        if self.commissioning is not None:
            self.commissioning.retranslate()
        self._show_device(self._connection.device)
        self._show_status(self._status)

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
            QTimer.singleShot(0, self, self._keep_whole)
        super().changeEvent(event)

    def showEvent(self, event: QShowEvent) -> None:
        """Shown: at least as high as its wrapped texts need at its width."""
        super().showEvent(event)
        self._keep_whole()

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Narrower: the wrapped texts take more lines; the window's least height follows."""
        super().resizeEvent(event)
        self._keep_whole()

    def _keep_whole(self) -> None:
        """The least height is what the layout needs at this width, wrapped texts included (a
        dialog's minimum ignores them: the LEDs' box lost its bottom edge; issue 34)."""
        layout = self.layout()
        if layout is None or not layout.hasHeightForWidth():
            return
        needed = layout.totalHeightForWidth(self.width())
        if needed > 0 and needed != self.minimumHeight():
            self.setMinimumHeight(needed)

    def _on_connection_online_changed(self, online: bool) -> None:
        if not online:
            self._status = None
        self._show_device(self._connection.device)
        self._show_status(self._status)

    def _on_connection_device_changed(self, info: ValveIdentity | None) -> None:
        self._show_device(info)

    def _on_connection_status_changed(self, status: StatusView) -> None:
        self._status = status
        self._show_status(status)
        QTimer.singleShot(0, self, self._keep_whole)  # a longer text may need another line

    def _show_device(self, info: ValveIdentity | None) -> None:
        online = self._connection.is_online
        self.fields["mode"].setText(self.tr("ONLINE") if online else self.tr("OFFLINE"))
        self.fields["firmware"].setText(info.firmware if info else "—")
        self.fields["serial"].setText(str(info.serial) if info else "—")
        self.fields["type_key"].setText(info.type_key if info else "—")

    def _show_status(self, status: StatusView | None) -> None:
        if self.commissioning is not None:
            self.commissioning.show_status(status)
        if status is None:
            for name in ("state", "nmt", "temperature", "supply"):
                self.fields[name].setText("—")
            self.errors.clear()
            self.errors.addItem(self.tr("No status: the valve is offline."))
            for led, state in zip(self.leds, self._led_states, strict=True):
                led.set_state("off", "off", False)
                state.setText("—")
            return
        self.fields["state"].setText(str(status.device_state))
        self.fields["nmt"].setText(self._nmt_text(str(status.nmt_state)))
        self.fields["temperature"].setText(f"{format_measured(status.temperature_c, '°C')} °C")
        self.fields["supply"].setText(f"{format_measured(status.supply_v, 'V')} V")
        self._show_errors(status)
        for led, state, led_state in zip(self.leds, self._led_states, status.leds, strict=False):
            led.set_state(led_state.color, led_state.pattern, led_state.lit)
            state.setText(self._led_text(led_state.color, led_state.pattern))

    def _nmt_text(self, state: str) -> str:
        """The NMT state as CANopen names it (CiA 301: "pre-operational", "operational",
        "stopped"); the program's own words in the program language (German read "off")."""
        words = {
            "off": self.tr("off (no CANopen)"),
            "initialising": self.tr("initialising"),
            "unknown": self.tr("unknown"),
        }
        return words.get(state, state)

    def _led_text(self, colour: str, pattern: str) -> str:
        """An LED's state in words, colour above pattern, e.g. "green\nblinking 2.5 Hz"."""
        colours = {
            "white": self.tr("white"),
            "green": self.tr("green"),
            "orange": self.tr("orange"),
            "red": self.tr("red"),
            "blue": self.tr("blue"),
            "magenta": self.tr("magenta"),
        }
        patterns = {
            "on": self.tr("on"),
            "1Hz": self.tr("blinking 1 Hz"),
            "2Hz": self.tr("blinking 2 Hz"),
            "2.5Hz": self.tr("blinking 2.5 Hz"),
            "single_flash": self.tr("single flash"),
            "double_flash": self.tr("double flash"),
            "triple_flash": self.tr("triple flash"),
            "quadruple_flash": self.tr("quadruple flash"),
            "boot": self.tr("power-up"),
        }
        if colour not in colours or pattern not in patterns:
            return self.tr("off")
        return f"{colours[colour]}\n{patterns[pattern]}"

    def _show_errors(self, status: StatusView) -> None:
        self.errors.clear()
        codes = list(status.active_errors)
        fallback = status.error_text
        for code in codes:
            self.errors.addItem(f"0x{code:04X}  {emcy_text(code, fallback)}")
        if not codes and status.warning:
            self.errors.addItem(f"0x0000  {emcy_text(0, fallback)}")
        if self.errors.count() == 0 and str(status.device_state) in _FAULT_STATES:
            # the error's display hold ended, the fault the state machine holds did not
            self.errors.addItem(
                self.tr(
                    "No error is present any more, but the valve still holds the fault "
                    "(device state {0}): press Enable (control word 08h → 09h → 0Bh → 0Fh) to "
                    "reset it."
                ).format(status.device_state)
            )
        if self.errors.count() == 0:
            self.errors.addItem(self.tr("No error."))


_FAULT_STATES = ("FAULT", "FAULT_HOLD", "FAULT_REACTION")
_FIELDS = ("mode", "firmware", "serial", "type_key", "state", "nmt", "temperature", "supply")
