"""The STATUS exchange: device state, errors, LEDs, temperature, supply and the error text.

The error text can be longer than one report holds, so the request names the byte offset of
the text the host wants; every answer repeats the numeric fields and carries the next chunk.
"""

from __future__ import annotations

from dataclasses import dataclass

from prm9tool.device.records import NmtState
from prm9tool.device.usb.protocol.wire import BODY_SIZE, MalformedReportError, Reader, Writer

DEVICE_STATES = (
    "NOT_READY",
    "INIT",
    "DISABLED",
    "HOLD",
    "DEVICE_MODE_ACTIVE",
    "FAULT_HOLD",
    "FAULT",
    "FAULT_REACTION",
)
NMT_STATES = (  # wire codes 0…4 (docs/usb-protocol.md)
    NmtState.OFF,
    NmtState.INITIALISING,
    NmtState.PRE_OPERATIONAL,
    NmtState.OPERATIONAL,
    NmtState.STOPPED,
)
LED_COLORS = ("off", "white", "green", "orange", "red", "blue", "magenta")
LED_PATTERNS = (
    "off",
    "on",
    "1Hz",
    "2Hz",
    "2.5Hz",
    "single_flash",
    "double_flash",
    "triple_flash",
    "quadruple_flash",
    "boot",
)
UNKNOWN = 0x7F  # code of a name the table does not know (decodes to "unknown")
MAX_ACTIVE_ERRORS = 10
MAX_TEXT_BYTES = 255
_FIXED_BODY = 21  # result byte and every field but the active errors and the text chunk


def _code(table: tuple[str, ...], name: str) -> int:
    return table.index(name) if name in table else UNKNOWN


def _name(table: tuple[str, ...], code: int) -> str:
    if code == UNKNOWN:
        return "unknown"
    if code >= len(table):
        raise MalformedReportError(f"status code {code} not in {table}")
    return table[code]


@dataclass(frozen=True)
class StatusRequest:
    """Ask for the status; ``text_offset`` = first byte of the error text wanted."""

    text_offset: int = 0
    op = 0x09  # Op.STATUS
    idempotent = True

    def encode(self, w: Writer) -> None:
        """Write the body: text offset."""
        w.u8(self.text_offset)

    @classmethod
    def decode(cls, r: Reader) -> StatusRequest:
        """Parse the body."""
        return cls(r.u8())


@dataclass(frozen=True)
class StatusReply:
    """The numeric status plus ``text_chunk`` = error-text bytes from ``text_offset``.

    Temperature travels in 0.01 °C, supply in mV; unknown names travel as code 0x7F.
    """

    device_state: str
    error_code: int
    error_register: int
    warning: bool
    booting: bool
    nmt_state: NmtState
    leds: tuple[tuple[str, str, bool], ...]
    temperature_c: float
    supply_v: float
    active_errors: tuple[int, ...]
    text_total: int
    text_offset: int
    text_chunk: bytes

    @staticmethod
    def chunk_room(active_errors: int) -> int:
        """Error-text bytes that fit in one answer next to ``active_errors`` codes."""
        return BODY_SIZE - _FIXED_BODY - 2 * active_errors

    def encode(self, w: Writer) -> None:
        """Write the body (layout in docs/usb-protocol.md)."""
        flags = int(self.warning) | int(self.booting) << 1
        w.u8(_code(DEVICE_STATES, self.device_state)).u16(self.error_code)
        w.u8(self.error_register).u8(flags).u8(_code(NMT_STATES, self.nmt_state))
        for color, pattern, lit in self.leds:
            w.u8(_code(LED_COLORS, color) | int(lit) << 7).u8(_code(LED_PATTERNS, pattern))
        w.i16(_clamp(round(self.temperature_c * 100), -32768, 32767))
        w.u16(_clamp(round(self.supply_v * 1000), 0, 65535))
        w.u8(len(self.active_errors))
        for code in self.active_errors:
            w.u16(code)
        w.u8(self.text_total).u8(self.text_offset).u8(len(self.text_chunk)).raw(self.text_chunk)

    @classmethod
    def decode(cls, r: Reader) -> StatusReply:
        """Parse the body."""
        state, error_code, register = _name(DEVICE_STATES, r.u8()), r.u16(), r.u8()
        flags = r.count(0, 3)
        nmt = NmtState(_name(NMT_STATES, r.u8()))  # an unknown code: NmtState.UNKNOWN
        leds = tuple(_decode_led(r.u8(), r.u8()) for _ in range(3))
        temperature, supply = r.i16() / 100, r.u16() / 1000
        active = tuple(r.u16() for _ in range(r.count(0, MAX_ACTIVE_ERRORS)))
        total, offset = r.u8(), r.u8()
        chunk = r.raw(r.count(0, cls.chunk_room(len(active))))
        if offset + len(chunk) > total:
            raise MalformedReportError(
                f"error text chunk {offset}+{len(chunk)} beyond {total} bytes"
            )
        return cls(
            state, error_code, register, bool(flags & 1), bool(flags & 2), nmt, leds,
            temperature, supply, active, total, offset, chunk,
        )  # fmt: skip


def _decode_led(color: int, pattern: int) -> tuple[str, str, bool]:
    return (_name(LED_COLORS, color & 0x7F), _name(LED_PATTERNS, pattern), bool(color & 0x80))


def _clamp(value: int, lowest: int, highest: int) -> int:
    return max(lowest, min(highest, value))
