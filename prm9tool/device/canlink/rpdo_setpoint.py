"""The setpoint from the PC over CANopen: RPDO1, as a PLC sends it (manual §7.6, figure 7-14).

RPDO1 (COB-ID 0x1400/1, default 0x200 + node ID) carries the control word 0x6040 and the
setpoint: 0x6300 (spool position) in control mode 2, 0x6380 (process command value) in mode 4
(mapping 0x1600/2, table 7-13). The valve applies it only in NMT OPERATIONAL and in
DEVICE_MODE_ACTIVE (§7.6: "the state machine must be in DEVICE_MODE_ACTIVE and stay there"), so
:meth:`RpdoSetpoint.begin` checks both and refuses with what to do (the commissioning panel).

* The frames repeat the control word the valve has (0x000F when enabled), so the state
  machine stays where it is; the setpoint object's value before :meth:`begin` is sent again
  at :meth:`end` — the valve goes back to the setpoint it had.
* **Decision (a lost link):** a valve holds the last RPDO value when its master vanishes.
  Where the valve has the RPDO1 event timer 0x1400/5 (this project's reception deadline), the
  link sets it to :data:`DEADLINE_MS` while it runs (when it was off), so a missing frame is the
  communication error 8100h and the fault reaction, as the USB override's 500 ms watchdog
  drops the override; :meth:`end` puts the old value back. A valve without the object holds the
  last value: docs/can-link.md says so.
* RPDO1 must be asynchronous (transmission type 254/255, the manual's delivery state): a
  synchronous one waits for a SYNC that only the scope's PDO stream produces.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.signals import SETPOINT_SIGNALS
from prm9tool.device.canlink.status import device_state, state_text
from prm9tool.device.records import DeviceState, NmtState
from prm9tool.device.session import NotAvailableError
from prm9tool.device.setpoint import SetpointLink
from prm9tool.errors import AccessDeniedError
from prm9tool.messages import QT_TRANSLATE_NOOP

if TYPE_CHECKING:
    from prm9tool.device.canlink.session import CanopenSession

DEADLINE_MS = 500  # RPDO1 reception deadline while the generator runs (the override's watchdog)
# RPDO1 entry 2 (table 7-13): the setpoint object's index -> its mnemonic, and the mnemonic ->
# the scope channel that shows it (catalogue.signals.SETPOINT_SIGNALS)
SETPOINT_OBJECTS = {CATALOGUE[m].index: m for m in SETPOINT_SIGNALS.values()}
DEMAND_KEYS = {m: key for key, m in SETPOINT_SIGNALS.items()}
ASYNCHRONOUS = (254, 255)
_NOT_OPERATIONAL = QT_TRANSLATE_NOOP(
    "Errors",
    "node {0} is NMT {1}: the valve takes RPDOs only when OPERATIONAL — start it first "
    "(Valve status → Commissioning: NMT start)",
)
_NOT_ENABLED = QT_TRANSLATE_NOOP(
    "Errors",
    "node {0} is in {1}: the valve applies a setpoint from the bus only in DEVICE_MODE_ACTIVE "
    "— enable it first (Valve status → Commissioning: control word 08h→09h→0Bh→0Fh)",
)
_SWITCHED_OFF = QT_TRANSLATE_NOOP(
    "Errors",
    "node {0}: RPDO1 is switched off (0x1400/1 = {1}, bit 31): clear bit 31 to drive the "
    "setpoint from prm9tool",
)
_SYNCHRONOUS = QT_TRANSLATE_NOOP(
    "Errors",
    "node {0}: RPDO1 is synchronous (0x1400/2 = {1}), so the setpoint would wait for a SYNC: "
    "set 0x1400/2 to 255 (the delivery state)",
)
_OTHER_MAPPING = QT_TRANSLATE_NOOP(
    "Errors", "node {0}: RPDO1 maps {1}, not the setpoint 0x6300/0x6380"
)


class RpdoSetpointError(AccessDeniedError):
    """The valve would not apply an RPDO1 setpoint now (the message says what to do)."""


class RpdoSetpoint(SetpointLink):
    """RPDO1 frames carrying control word and setpoint (see the module docstring)."""

    def __init__(self, session: CanopenSession) -> None:
        self._session = session
        self._cob_id = 0
        self._control = 0
        self._object = "POSSETP"
        self._before = 0
        self._timer_before: int | None = None  # None: the valve has no 0x1400/5 or it was on
        self._last = 0

    @property
    def objects(self) -> tuple[str, ...]:
        """The setpoint objects and the event timer."""
        return (*SETPOINT_OBJECTS.values(), "RPDO1TIMER")

    @property
    def setpoint_object(self) -> str:
        """POSSETP or PRCSETP: what RPDO1's second entry sets on this valve now."""
        return self._object

    @property
    def deadline_ms(self) -> int | None:
        """The reception deadline armed by :meth:`begin` (None: the valve has none)."""
        return None if self._timer_before is None else DEADLINE_MS

    def begin(self, raw: int) -> None:
        """Check NMT state, device state and RPDO1, arm the deadline, send the first frame."""
        sdo = self._session.sdo
        node = self._session.node_id
        self._check_operational()
        self.writing = self._object
        cob = sdo.read_u32(0x1400, 1)
        if cob & 0x8000_0000:
            raise RpdoSetpointError(_SWITCHED_OFF(node, f"0x{cob:08X}"))
        kind = sdo.read_u32(0x1400, 2) & 0xFF
        if kind not in ASYNCHRONOUS:
            raise RpdoSetpointError(_SYNCHRONOUS(node, kind))
        entry = sdo.read_u32(0x1600, 2) >> 16
        if entry not in SETPOINT_OBJECTS:
            raise RpdoSetpointError(_OTHER_MAPPING(node, f"0x{entry:04X}"))
        self._cob_id, self._object = cob & 0x7FF, SETPOINT_OBJECTS[entry]
        self._control = sdo.read_u32(0x6040, 0) & 0xFFFF
        word = sdo.read_u32(0x6041, 0) & 0xFFFF
        if device_state(word) != DeviceState.DEVICE_MODE_ACTIVE:
            raise RpdoSetpointError(_NOT_ENABLED(node, state_text(word)))
        self._before = int(self._session.read(self._object))
        self._arm_deadline()
        self.set(raw)

    def set(self, raw: int) -> None:
        """One RPDO1 frame: control word, ``raw``."""
        CATALOGUE[self._object].check_raw(raw)
        self._last = raw
        self._send(raw)
        self._session.stream.sent_setpoint = (DEMAND_KEYS[self._object], float(raw))

    def keep_alive(self) -> None:
        """The last frame again (keeps the reception deadline)."""
        self._send(self._last)

    def end(self) -> None:
        """The setpoint the valve had before, and the event timer as it was."""
        self._session.stream.sent_setpoint = None  # from now on the valve's own (or its PLC's)
        self._send(self._before)
        if self._timer_before is not None:
            self.writing = "RPDO1TIMER"
            self._session.write("RPDO1TIMER", self._timer_before)
            self._timer_before = None

    def leftovers(self) -> dict[str, int]:
        """The RPDO1 event timer as it was, while the deadline :meth:`begin` armed is on."""
        return {} if self._timer_before is None else {"RPDO1TIMER": self._timer_before}

    def _check_operational(self) -> None:
        nmt = self._session.nmt_state
        if nmt is not None and nmt is not NmtState.OPERATIONAL:
            raise RpdoSetpointError(_NOT_OPERATIONAL(self._session.node_id, nmt))

    def _arm_deadline(self) -> None:
        self.writing = "RPDO1TIMER"
        try:
            timer = int(self._session.read("RPDO1TIMER"))
        except NotAvailableError:
            return  # a valve without this project's object: it holds the last value
        if timer:
            return  # no deadline on this valve, or the user set one: keep it
        self._session.write("RPDO1TIMER", DEADLINE_MS)
        self._timer_before = timer

    def _send(self, raw: int) -> None:
        data = (self._control & 0xFFFF).to_bytes(2, "little") + int(raw).to_bytes(
            2, "little", signed=True
        )
        self.writing = self._object
        self._session.send_frame(self._cob_id, data)
