"""The records every link shares: who a valve is, what it shows, what an upload did. No Qt.

The emulator, the USB link and the CANopen link all build and return these; the GUI, the batch
mode and scripts read them. Every record is a frozen dataclass with keyword-only fields; the
states are enums (a ``StrEnum`` compares equal to its text, which is also what the JSON shows).
"""

from __future__ import annotations

import html
import threading
from collections.abc import Callable
from dataclasses import asdict, dataclass, field, fields
from enum import StrEnum
from typing import Any

from prm9tool.errors import Prm9Error, SdoAbortError

__all__ = [
    "LED_OFF",
    "STEPS",
    "DeviceInfo",
    "DeviceState",
    "HtmlRecord",
    "LedState",
    "NmtState",
    "OperationCancelledError",
    "Progress",
    "RefusedError",
    "Steps",
    "UploadResult",
    "Value",
    "ValveStatus",
    "check_cancel",
]

Value = int | str
"""A parameter's raw value as the valve holds it: an integer, or the text of a string object."""

Progress = Callable[[int, int, str], None]
"""``progress(done, total, step)``: how far a long operation got."""

STEPS = {"write": "writing the parameters", "verify": "reading them back", "store": "storing"}
"""The steps of the transactional upload, and how a message names each."""


class HtmlRecord:
    """Mixin of the records: a table of their fields for Jupyter (``_repr_html_``) and the
    plain data the command line's JSON shows (:meth:`to_dict`)."""

    def to_dict(self) -> dict[str, Any]:
        """The fields as plain data for ``json.dumps`` (the states are StrEnums, so JSON shows
        their text; tuples become lists): what the command line's ``--json`` prints."""
        return asdict(self)  # type: ignore[call-overload, no-any-return]

    def _repr_html_(self) -> str:
        rows = "".join(
            f"<tr><th style='text-align:left'>{html.escape(f.name)}</th>"
            f"<td style='text-align:left'>{html.escape(str(getattr(self, f.name)))}</td></tr>"
            for f in fields(self)  # type: ignore[arg-type]
        )
        return f"<table><caption>{type(self).__name__}</caption>{rows}</table>"


class DeviceState(StrEnum):
    """CiA 408 / VDMA device states (manual §7.4, figure 7-11)."""

    NOT_READY = "NOT_READY"
    INIT = "INIT"
    DISABLED = "DISABLED"
    HOLD = "HOLD"
    DEVICE_MODE_ACTIVE = "DEVICE_MODE_ACTIVE"
    FAULT_HOLD = "FAULT_HOLD"
    FAULT = "FAULT"
    FAULT_REACTION = "FAULT_REACTION"


class NmtState(StrEnum):
    """CiA 301 NMT state of the valve's CANopen node (CiA 301 §7.3.2.2, manual §7.2).

    ``OFF``: the valve has no CANopen interface or it is switched off (switch at 0/1, manual
    table 7-17). ``UNKNOWN``: a CAN master has not heard the node's heartbeat yet, or heard a
    state byte CiA 301 does not define.
    """

    OFF = "off"
    INITIALISING = "initialising"
    PRE_OPERATIONAL = "pre-operational"
    OPERATIONAL = "operational"
    STOPPED = "stopped"
    UNKNOWN = "unknown"


@dataclass(frozen=True, kw_only=True)
class LedState:
    """One LED as a user sees it.

    ``color``: ``off``, ``white``, ``green``, ``orange``, ``red``, ``blue``, ``magenta``.
    ``pattern``: ``off``, ``on``, ``1Hz``, ``2Hz``, ``2.5Hz`` (CiA 303 blinking),
    ``single_flash``, ``double_flash``, ``triple_flash``, ``quadruple_flash`` (CiA 303 flashes),
    ``boot`` (the power-up pattern: two white flashes in about 2 s).
    ``lit`` tells whether the LED is lit at the instant the status was taken.
    """

    color: str
    pattern: str
    lit: bool


LED_OFF = LedState(color="off", pattern="off", lit=False)


@dataclass(frozen=True, kw_only=True)
class ValveStatus(HtmlRecord):
    """A snapshot of everything the valve shows outside: state, errors, LEDs, supply.

    ``error_code`` is the CANopen EMCY code of the most severe active error (0 = none),
    ``error_text`` its English description ("" when there is no error and no warning).
    ``status_word``: the CiA 408 status word 0x6041 the state was decoded from, where it was
    read over CANopen (None: another link).
    """

    device_state: DeviceState
    error_code: int
    error_text: str
    warning: bool
    active_errors: tuple[int, ...]
    error_register: int
    leds: tuple[LedState, LedState, LedState]
    temperature_c: float
    supply_v: float
    nmt_state: NmtState
    booting: bool
    status_word: int | None = None


@dataclass(frozen=True, kw_only=True)
class DeviceInfo(HtmlRecord):
    """Who the valve is (from the identification exchange, or as a device listing found it).

    ``device_id`` opens it again (``prm9tool.connect``); its prefix is the :attr:`link`.
    ``protocol_version``: the USB protocol version the valve speaks (0: not over USB, or not
    asked, as in a listing).
    """

    type_key: str
    serial: int
    firmware: str
    device_id: str
    protocol_version: int = 0
    # parameters whose change moves the valve away from this link at its next power-up (over
    # CANopen its node ID and bit rate); the GUI warns when one is changed online
    link_parameters: tuple[str, ...] = ()
    # over CAN: the bus (python-can interface, channel, bit rate in bit/s or None) it answers on
    can_bus: tuple[str, str, int | None] | None = None
    # the fastest oscilloscope sample rate the link delivers without losing samples (0: the
    # valve's own 5 kHz stream); over CANopen the SYNC + TPDO1 pace of docs/can-link.md
    stream_rate_limit_hz: float = 0.0
    # the stream has one row per sample period and a lost sample is a NaN row at its time
    # (over CANopen: placed by the SYNC count); False: lost samples are only counted
    stream_gaps: bool = False

    @property
    def link(self) -> str:
        """How the valve is reached: ``usb``, ``emulator`` or ``can``."""
        return self.device_id.partition(":")[0]

    def to_dict(self) -> dict[str, Any]:
        """The fields and the :attr:`link` as JSON-ready data."""
        return {**super().to_dict(), "link": self.link}


@dataclass(frozen=True, kw_only=True)
class UploadResult(HtmlRecord):
    """Outcome of an upload; ``failed_step`` is ``write``, ``verify``, ``store`` or None.

    ``stored`` means verified stored (the upload contract of
    :class:`prm9tool.device.session.ValveSession`). ``failure`` says why the step failed when
    ``mismatches`` (``{mnemonic: (uploaded, read back)}``) do not (a refused store). After a
    failed upload the session puts the valve's stored parameters back into its working values
    (no restart): ``reloaded`` says whether that worked, ``reload_error`` why not; ``restarted``:
    the verification by restart found the set not kept on a valve with a store command, which
    runs on the set it came back with (nothing is written after the restart). ``skipped``:
    parameters of the set the valve does not have on this link, left out with a warning (never
    a failed upload).
    """

    written: int
    verified: bool
    stored: bool
    mismatches: dict[str, tuple[Value, Value]] = field(default_factory=dict)
    duration_s: float
    failed_step: str | None = None
    reloaded: bool = False
    reload_error: str | None = None
    restarted: bool = False
    failure: str | None = None
    skipped: tuple[str, ...] = ()
    # how the valve keeps the set (CANopen: "stored with 0x1010", "kept by the valve as written
    # (it has no store command)", "verified after a restart"; None: the link's store command)
    store: str | None = None


class OperationCancelledError(Prm9Error):
    """The user cancelled a long operation; ``step`` says where it stopped."""

    def __init__(self, step: str, outcome: str = "") -> None:
        self.step = step
        text = f"cancelled while {STEPS[step]}; nothing was stored" if step in STEPS else ""
        text = text or f"{step} cancelled"
        super().__init__(f"{text}; {outcome}" if outcome else text)


class RefusedError(Prm9Error):
    """The valve refused one entry of a multi-entry write; ``done`` entries were written."""

    summary = SdoAbortError.summary

    def __init__(self, mnemonic: str, error: SdoAbortError, done: int) -> None:
        super().__init__(f"{mnemonic}: {error}")
        self.mnemonic, self.error, self.done = mnemonic, error, done


class Steps:
    """Progress of one step of an operation, as ``progress(done, total, step)`` calls."""

    def __init__(self, progress: Progress | None, total: int, done: int, step: str) -> None:
        self.progress, self.total, self.done, self.step = progress, total, done, step

    def advance(self, count: int) -> None:
        """``count`` more entries are done."""
        self.done += count
        if self.progress is not None:
            self.progress(self.done, self.total, self.step)


def check_cancel(cancel: threading.Event | None, step: str) -> None:
    """Raise OperationCancelledError if ``cancel`` is set."""
    if cancel is not None and cancel.is_set():
        raise OperationCancelledError(step)
