"""Setpoint generator for tuning: drives the valve's setpoint from the PC.

Over USB through the override objects (while SETPOVRON = 1 the firmware takes its setpoint from
SETPOVR instead of the analog input), over CANopen through RPDO1 (0x6300/0x6380, manual table
7-13; prm9tool.device.canlink.rpdo_setpoint).
The waveform itself runs off the GUI thread, on the valve's own time base
(``connection.start_generator``, :mod:`prm9tool.service.setpoint_driver`): exact to the
valve's 200 µs cycle on an emulated valve, timed against the sample stream over a link. This
class is its switch: it starts it (the override goes on), stops it (SETPOVRON = 0) on Stop,
when the scope closes and before the program goes offline, and stops and says why when the
valve refuses one of its writes, and before a long operation of the connection (a tuning
test, an upload, a restart) whose own writes it would otherwise fight. When the link drops it only stops: nothing can be written
any more, and the firmware switches the override off by itself 500 ms after the last USB
report; the generator still switches it off at the next connection, in case the valve did not
notice (an emulated valve stands still while offline).
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QComboBox, QDoubleSpinBox, QLabel, QPushButton, QWidget

from prm9tool.online.connection_protocol import ScopeConnection
from prm9tool.scope import GeneratorSettings, Waveform, setpoint_limits
from prm9tool.service.setpoint_driver import GENERATOR_OBJECTS
from prm9tool.views.scope.rows import SPACE, control_row, section_label

OVERRIDE_OBJECTS = GENERATOR_OBJECTS  # a refusal of one of these stops the generator


class SetpointGenerator(QObject):
    """Starts and stops a :class:`GeneratorSettings` waveform on the valve's setpoint."""

    running_changed = Signal(bool)
    stopped_by_link = Signal()  # the link dropped while running
    refused = Signal(str)  # the valve refused a write while running (the reason): stopped
    stopped_by_operation = Signal()  # a long operation (e.g. a tuning test) began: stopped

    def __init__(self, connection: ScopeConnection, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._connection = connection
        self._settings = GeneratorSettings()
        self._running = False
        self._override_left_on = False  # SETPOVRON may be 1 in the valve without us running
        self._last_failure = ""
        connection.lost.connect(self._on_link_lost)
        connection.online_changed.connect(self._on_online_changed)
        connection.failed.connect(self._on_connection_failed)
        connection.write_failed.connect(self._on_connection_write_failed)
        connection.busy_changed.connect(self._on_busy_changed)

    @property
    def running(self) -> bool:
        """True while the generator drives the setpoint."""
        return self._running

    @property
    def settings(self) -> GeneratorSettings:
        """The waveform last started."""
        return self._settings

    def start(self, settings: GeneratorSettings) -> None:
        """Check ``settings``, switch the override on and start the waveform.

        Raises ValueRangeError for a waveform outside the setpoint range and RuntimeError
        when no valve is online. The caller has asked the user to confirm.
        """
        settings.check()
        if not self._connection.is_online:
            raise RuntimeError(self.tr("The setpoint generator needs a connected valve."))
        if self._connection.is_busy:
            raise RuntimeError(
                self.tr("The valve is busy with another operation; start the generator after it.")
            )
        self._settings = settings
        self._running = True  # running from here: a refusal of the first writes stops it
        self._override_left_on = True
        self._connection.start_generator(settings)
        self.running_changed.emit(True)

    def stop(self) -> None:
        """Switch the override off (when online) and stop."""
        if not self.running:
            return
        self._running = False
        self._switch_off()
        self.running_changed.emit(False)

    def _switch_off(self) -> None:
        if self._connection.is_online:
            self._connection.stop_generator()
            self._override_left_on = False

    def _on_connection_failed(self, message: str) -> None:
        self._last_failure = message  # write_failed follows for a refused write

    def _on_connection_write_failed(self, mnemonics: list[str]) -> None:
        mine = OVERRIDE_OBJECTS.intersection(mnemonics)
        if not mine:
            return
        if self.running:
            self.stop()
            self.refused.emit(self._last_failure)
        elif "SETPOVRON" in mine:
            self._override_left_on = True  # switching off failed: again at the next connection

    def _on_busy_changed(self, busy: bool) -> None:
        """A long operation starts: stop first (the stop is queued before the operation)."""
        if busy and self.running:
            self.stop()
            self.stopped_by_operation.emit()

    def _on_link_lost(self, *_: object) -> None:
        if self.running:
            self._running = False
            self.running_changed.emit(False)
            self.stopped_by_link.emit()

    def _on_online_changed(self, online: bool) -> None:
        if not online:
            self._on_link_lost()
        elif self._override_left_on and not self.running:
            self._connection.stop_generator()  # gives back what may have been left on
            self._override_left_on = False


class GeneratorPanel(QWidget):
    """Waveform, amplitude, offset and period, and a Start/Stop button, in one row."""

    start_requested = Signal(object)  # GeneratorSettings
    stop_requested = Signal()

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        low, high = setpoint_limits()
        self.waveform = QComboBox()
        self.waveform.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToContents)  # "Rechteck"
        for waveform in Waveform:
            self.waveform.addItem("", waveform)
        self.amplitude, self.offset, self.period = (QDoubleSpinBox() for _ in range(3))
        for box, value in ((self.amplitude, 20.0), (self.offset, 0.0)):
            box.setRange(low - high, high - low)
            box.setDecimals(1)
            box.setSuffix(" %")
            box.setValue(value)
        self.offset.setRange(low, high)
        self.period.setRange(0.05, 60.0)
        self.period.setDecimals(2)
        self.period.setSuffix(" s")
        self.period.setValue(1.0)
        self.button = QPushButton()
        self.button.setCheckable(True)
        self.button.clicked.connect(self._on_button_clicked)
        self.title = section_label()
        self.labels = [QLabel() for _ in range(4)]
        fields = (self.waveform, self.amplitude, self.offset, self.period)
        widgets: list[QWidget | None] = []
        for label, field in zip(self.labels, fields, strict=True):
            widgets += [label, field, SPACE]
        layout = control_row(self.title, [*widgets, self.button])
        layout.setContentsMargins(0, 0, 0, 0)
        self.setLayout(layout)
        self.retranslate()

    def retranslate(self) -> None:
        """Re-read user-visible texts (after a language change)."""
        self.title.setText(self.tr("Generator"))
        self.title.setToolTip(
            self.tr("Setpoint generator: drives the valve's setpoint for tuning (manual §8.7.2)")
        )
        names = {
            Waveform.STEP: self.tr("Step"),
            Waveform.SQUARE: self.tr("Square"),
            Waveform.SINE: self.tr("Sine"),
        }
        for row in range(self.waveform.count()):
            self.waveform.setItemText(row, names[Waveform(self.waveform.itemData(row))])
        labels = (self.tr("Waveform"), self.tr("Amplitude"), self.tr("Offset"), self.tr("Period"))
        for label, label_text in zip(self.labels, labels, strict=True):
            label.setText(label_text)
        self.amplitude.setToolTip(
            self.tr(
                "Step and square: height of the step above the offset. Sine: peak value. "
                "In % of the setpoint range."
            )
        )
        self.set_running(self.button.isChecked())

    def settings(self) -> GeneratorSettings:
        """The waveform as set up."""
        return GeneratorSettings(
            waveform=Waveform(self.waveform.currentData()),
            amplitude=self.amplitude.value(),
            offset=self.offset.value(),
            period=self.period.value(),
        )

    def set_running(self, running: bool) -> None:
        """Show the generator as running or stopped."""
        self.button.setChecked(running)
        self.button.setText(self.tr("Stop generator") if running else self.tr("Start generator"))
        for box in (self.waveform, self.amplitude, self.offset, self.period):
            box.setEnabled(not running)

    def _on_button_clicked(self, checked: bool) -> None:
        self.button.setChecked(not checked)  # the widget confirms the state via set_running
        if checked:
            self.start_requested.emit(self.settings())
        else:
            self.stop_requested.emit()
