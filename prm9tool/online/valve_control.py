"""Driving the connected valve by hand: NMT, the enable sequence and the emulated valve's world.

A -CA valve as delivered waits in NMT pre-operational and device state INIT for a CANopen
master (manual §7.4, §7.6); :class:`ValveControl` is that master's part for a valve on the
desk: NMT commands (``ValveSession.nmt``) and the control word sequence 08h → 09h → 0Bh → 0Fh
(:mod:`prm9tool.catalogue.commissioning`) as plain object writes, the same on every link. For
an emulated valve it also sets the analog inputs and rotary switches and injects the physical
faults the emulator knows (``ValveSession.emulator``). Everything runs as jobs of the
connection's worker thread; QtCore only, the device layer is reached through the session.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject, Signal

from prm9tool.catalogue.commissioning import (
    Blocker,
    NmtCommand,
    blocker,
)
from prm9tool.online.connection import ValveConnection
from prm9tool.online.connection_protocol import StatusView

if TYPE_CHECKING:
    from prm9tool.device.emulated import EmulatorControls
    from prm9tool.device.session import ValveSession


def status_blocker(status: StatusView | None) -> Blocker | None:
    """Why the valve with ``status`` (a ValveStatus) does not follow its setpoint; None: it
    does (or there is no status)."""
    if status is None:
        return None
    return blocker(
        str(status.device_state), str(status.nmt_state), tuple(status.active_errors), status.booting
    )


def blocker_text(reason: Blocker, status: StatusView | None = None, in_status: bool = False) -> str:
    """The reason in a sentence for the user (the program language).

    ``in_status``: the sentence is shown in the Valve status window itself, so it names the
    button to press there instead of sending the user to that window.
    """
    translate = QCoreApplication.translate  # the name pyside6-lupdate looks for
    state = str(status.device_state) if status is not None else ""
    nmt = str(status.nmt_state) if status is not None else ""
    if in_status and reason is Blocker.WAITING_FOR_MASTER and nmt == "operational":
        return translate(  # NMT start was pressed already: only Enable is left
            "ValveControl",
            "it is operational on CANopen but not enabled yet (device state {0}). Press Enable "
            "(control word 08h → 09h → 0Bh → 0Fh).",
        ).format(state)
    if in_status and reason in _HERE:
        return translate("ValveControl", str(_HERE[reason])).format(state, nmt)
    texts = {
        Blocker.OFFLINE: translate("ValveControl", "no valve is connected."),
        Blocker.BOOTING: translate("ValveControl", "the valve is starting up (about 2 s)."),
        Blocker.FAULT: translate(
            "ValveControl",
            "an error stops it (device state {0}); Valve → Valve status lists the error and "
            "resets it with Enable once the cause is gone.",
        ).format(state),
        Blocker.WAITING_FOR_MASTER: translate(
            "ValveControl",
            "it waits for a CANopen master (NMT {0}, device state {1}). Enable it under "
            "Valve → Valve status (control word 08h → 09h → 0Bh → 0Fh).",
        ).format(nmt, state),
        Blocker.NMT_STOPPED: translate(
            "ValveControl",
            "its CANopen master stopped it (NMT stopped). Start it under Valve → Valve status.",
        ),
        Blocker.DISABLED: translate(
            "ValveControl",
            "it is not enabled (device state {0}). Enable it under Valve → Valve status.",
        ).format(state),
        Blocker.HOLD: translate(
            "ValveControl",
            "it holds its position (device state HOLD). Enable it under Valve → Valve status.",
        ),
    }
    return texts[reason]


_HERE = {  # in the Valve status window: which button of its Commissioning panel to press
    Blocker.FAULT: QT_TRANSLATE_NOOP(
        "ValveControl",
        "an error stops it (device state {0}); the list of errors shows it. Press Enable once "
        "the cause is gone.",
    ),
    Blocker.WAITING_FOR_MASTER: QT_TRANSLATE_NOOP(
        "ValveControl",
        "it waits for a CANopen master (NMT {1}, device state {0}). Press NMT start, then "
        "Enable (control word 08h → 09h → 0Bh → 0Fh).",
    ),
    Blocker.NMT_STOPPED: QT_TRANSLATE_NOOP(
        "ValveControl", "its CANopen master stopped it (NMT stopped). Press NMT start."
    ),
    Blocker.DISABLED: QT_TRANSLATE_NOOP(
        "ValveControl", "it is not enabled (device state {0}). Press Enable."
    ),
    Blocker.HOLD: QT_TRANSLATE_NOOP(
        "ValveControl", "it holds its position (device state HOLD). Press Enable."
    ),
}


def blocker_summary(reason: Blocker) -> str:
    """The reason in a few words, for the status bar."""
    translate = QCoreApplication.translate
    texts = {
        Blocker.OFFLINE: translate("ValveControl", "offline"),
        Blocker.BOOTING: translate("ValveControl", "starting up"),
        Blocker.FAULT: translate("ValveControl", "fault"),
        Blocker.WAITING_FOR_MASTER: translate("ValveControl", "waiting for a CANopen master"),
        Blocker.NMT_STOPPED: translate("ValveControl", "NMT stopped"),
        Blocker.DISABLED: translate("ValveControl", "not enabled"),
        Blocker.HOLD: translate("ValveControl", "hold"),
    }
    return texts[reason]


class ValveControl(QObject):
    """NMT, enable/disable and, for an emulated valve, inputs, switches and faults."""

    emulator_changed = Signal(object)  # EmulatorState, or None (offline or a real valve)
    cable_out_changed = Signal(bool)  # the lost valve is an emulated one with its cable pulled

    def __init__(self, connection: ValveConnection, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._connection = connection
        self._state: object | None = None
        connection.online_changed.connect(self._on_connection_online_changed)
        connection.reconnecting.connect(lambda _s: self.cable_out_changed.emit(self.cable_out))
        connection.reconnect_ended.connect(lambda: self.cable_out_changed.emit(False))

    @property
    def cable_out(self) -> bool:
        """True while the valve looked for is an emulated one whose USB cable is pulled."""
        from prm9tool.device.emulated import cable_plugged

        lost = self._connection.lost_valve
        return bool(lost and lost.emulators and not cable_plugged(lost.serial))

    def plug_cable_back(self) -> None:
        """Plug the pulled USB cable of the emulated valve looked for back in: the reconnect
        finds it at its next listing."""
        from prm9tool.device.emulated import plug_cable

        lost = self._connection.lost_valve
        if lost is not None and lost.emulators:
            plug_cable(lost.serial)
        self.cable_out_changed.emit(self.cable_out)

    @property
    def connection(self) -> ValveConnection:
        """The connection the commands go through."""
        return self._connection

    @property
    def emulator_state(self) -> object | None:
        """The emulated valve's inputs, switches and faults (None: not an emulated valve)."""
        return self._state

    # --- commissioning (every link) -----------------------------------------------------------
    def nmt(self, command: NmtCommand) -> None:
        """Send an NMT command to the valve (the valve service's, as a script's)."""
        self._connection.run(
            "nmt", lambda s: self._connection.service(s).commissioning.nmt(command)
        )

    def enable(self) -> None:
        """Control word 08h → 09h → 0Bh → 0Fh: from INIT (or a fault whose cause is gone) to
        DEVICE_MODE_ACTIVE; when the valve does not get there the job fails saying why."""
        self._connection.run(
            "control word", lambda s: self._connection.service(s).commissioning.enable()
        )

    def disable(self) -> None:
        """Control word 0Fh → 0Bh → 09h → 08h: back to INIT step by step."""
        self._connection.run(
            "control word", lambda s: self._connection.service(s).commissioning.disable()
        )

    # --- the emulated valve -------------------------------------------------------------------
    def set_input(self, name: str, value: float) -> None:
        """Set an analog input (V, mA, °C) or a rotary switch (0…15) of the emulated valve."""
        self._emulator_job(lambda e: e.set_input(name, value))

    def set_fault(self, fault: str, present: bool) -> None:
        """Inject (``present``) or repair a physical fault of the emulated valve."""
        self._emulator_job(lambda e: e.set_fault(fault, present))

    def pull_cable(self) -> None:
        """Pull the emulated valve's USB cable: the link drops as with a real one."""
        self._emulator_job(lambda e: e.pull_cable(), report=False)

    def refresh(self) -> None:
        """Read the emulated valve's state again (``emulator_changed`` follows)."""
        self._emulator_job(lambda e: None)

    def _emulator_job(
        self, change: Callable[[EmulatorControls], object], report: bool = True
    ) -> None:
        def run(session: ValveSession) -> object:
            controls = session.emulator
            if controls is None:
                return None
            change(controls)
            return controls.state() if report else self._state

        self._connection.run("emulator", run, self._on_state)

    def _on_state(self, state: object) -> None:
        self._state = state
        self.emulator_changed.emit(state)

    def _on_connection_online_changed(self, online: bool) -> None:
        if online:
            self.refresh()
        elif self._state is not None:
            self._on_state(None)
