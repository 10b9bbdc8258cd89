"""The words for what a trace's bytes mean: NMT commands and states (CiA 301), EMCY codes (the
valve's own from manual table 5-1, the rest by CiA 301's classes), SDO abort codes, LSS
services (CiA 305), control and status words (CiA 408). The valve's tables are read from the
catalogue, never copied here. No Qt."""

from __future__ import annotations

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.catalogue.error_kinds import ERROR_KINDS
from prm9tool.device.canlink.bus import NMT_STATES
from prm9tool.device.canlink.status import state_text
from prm9tool.errors import AbortCode

NMT_COMMANDS = {
    NmtCommand.START: "start (to operational)",
    NmtCommand.STOP: "stop",
    NmtCommand.PRE_OPERATIONAL: "enter pre-operational",
    NmtCommand.RESET_NODE: "reset node",
    NmtCommand.RESET_COMMUNICATION: "reset communication",
}

# The valve's errors (manual table 5-1): several rows share a code (coil over-current and open
# coil); the code names them all.
_VALVE_EMCY: dict[int, list[str]] = {}
for _kind in ERROR_KINDS:
    _VALVE_EMCY.setdefault(_kind.code, []).append(_kind.text)

# CiA 301 table 21: the specific codes every device may send, then the classes (high byte).
_CIA301_EMCY = {
    0x0000: "error reset or no error",
    0x8110: "CAN overrun (objects lost)",
    0x8120: "CAN in error passive mode",
    0x8130: "life guard error or heartbeat error",
    0x8140: "recovered from bus off",
    0x8150: "CAN-ID collision",
    0x8210: "PDO not processed due to length error",
    0x8220: "PDO length exceeded",
    0x8230: "DAM MPDO not processed, destination object not available",
    0x8240: "unexpected SYNC data length",
    0x8250: "RPDO timeout",
}
_CIA301_CLASSES = {
    0x10: "generic error",
    0x20: "current",
    0x21: "current, device input side",
    0x22: "current inside the device",
    0x23: "current, device output side",
    0x30: "voltage",
    0x31: "mains voltage",
    0x32: "voltage inside the device",
    0x33: "output voltage",
    0x40: "temperature",
    0x41: "ambient temperature",
    0x42: "device temperature",
    0x50: "device hardware",
    0x60: "device software",
    0x61: "internal software",
    0x62: "user software",
    0x63: "data set",
    0x70: "additional modules",
    0x80: "monitoring",
    0x81: "communication",
    0x82: "protocol error",
    0x90: "external error",
    0xF0: "additional functions",
    0xFF: "device specific",
}

LSS_SERVICES = {
    0x04: "switch state global",
    0x11: "configure node-ID",
    0x13: "configure bit timing",
    0x15: "activate bit timing",
    0x17: "store configuration",
    0x40: "switch state selective: vendor ID",
    0x41: "switch state selective: product code",
    0x42: "switch state selective: revision number",
    0x43: "switch state selective: serial number",
    0x44: "switch state selective: response",
    0x46: "identify remote slave: vendor ID",
    0x47: "identify remote slave: product code",
    0x48: "identify remote slave: revision number low",
    0x49: "identify remote slave: revision number high",
    0x4A: "identify remote slave: serial number low",
    0x4B: "identify remote slave: serial number high",
    0x4C: "identify non-configured remote slave",
    0x4F: "identify slave (response)",
    0x50: "identify non-configured slave (response)",
    0x51: "fastscan",
    0x5A: "inquire vendor ID",
    0x5B: "inquire product code",
    0x5C: "inquire revision number",
    0x5D: "inquire serial number",
    0x5E: "inquire node-ID",
}

CONTROL_BITS = ((0x01, "D"), (0x02, "H"), (0x04, "M"), (0x08, "R"))  # CiA 408, manual table 7-19


def nmt_command_text(command: int) -> str:
    """``reset node`` for 0x81; an unknown command specifier by its number."""
    try:
        return NMT_COMMANDS[NmtCommand(command)]
    except ValueError:
        return f"unknown NMT command 0x{command:02X}"


def heartbeat_text(state_byte: int) -> str:
    """``boot-up`` for 0x00, else the NMT state a heartbeat reports."""
    code = state_byte & 0x7F
    if code == 0:
        return "boot-up"
    state = NMT_STATES.get(code)
    return f"heartbeat: {state.value}" if state else f"heartbeat with unknown state 0x{code:02X}"


def emcy_text(code: int) -> str:
    """An EMCY code in words: the valve's own (table 5-1), else its CiA 301 meaning."""
    if code in _VALVE_EMCY:
        return " or ".join(_VALVE_EMCY[code])
    if code in _CIA301_EMCY:
        return _CIA301_EMCY[code]
    cls = _CIA301_CLASSES.get(code >> 8) or _CIA301_CLASSES.get((code >> 12) << 4)
    return f"{cls} (0x{code:04X})" if cls else f"error 0x{code:04X}"


def abort_text(code: int) -> str:
    """An SDO abort code in words (CiA 301 table 22)."""
    try:
        return AbortCode(code).text
    except ValueError:
        pass
    from canopen.sdo.exceptions import SdoAbortedError

    return SdoAbortedError.CODES.get(code, "unknown abort code")


def control_word_text(word: int) -> str:
    """``0x000F (D H M R)``: a control word and the CiA 408 bits it sets."""
    bits = " ".join(name for bit, name in CONTROL_BITS if word & bit)
    return f"0x{word & 0xFFFF:04X} ({bits or 'none'})"


def status_word_text(word: int) -> str:
    """``DEVICE_MODE_ACTIVE (status word 0x000F)``."""
    return state_text(word)


def lss_text(data: bytes, from_master: bool) -> str:
    """An LSS frame (CiA 305) in words."""
    if not data:
        return "LSS frame without data"
    cs = data[0]
    name = LSS_SERVICES.get(cs, f"unknown LSS service 0x{cs:02X}")
    side = "master" if from_master else "slave"
    detail = _lss_detail(cs, data, from_master)
    return f"LSS {side}: {name}{detail}"


def _lss_detail(cs: int, data: bytes, from_master: bool) -> str:
    padded = data + bytes(8 - len(data)) if len(data) < 8 else data
    value = int.from_bytes(padded[1:5], "little")
    if cs == 0x04 and from_master:
        return " → configuration" if padded[1] else " → waiting"
    if cs == 0x11 and from_master:
        return f" {padded[1]}"
    if cs in (0x11, 0x13, 0x17) and not from_master:
        return " done" if padded[1] == 0 else f" refused (error {padded[1]})"
    if 0x40 <= cs <= 0x4B or (0x5A <= cs <= 0x5E and not from_master):
        return f" 0x{value:08X}"
    if cs == 0x13 and from_master:
        return f" table {padded[1]} index {padded[2]}"
    return ""
