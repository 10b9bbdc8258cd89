"""Translated texts of the valve's error codes (CANopen EMCY codes, manual tables 5-1, 7-18)."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from prm9tool.online.connection_protocol import StatusView
from prm9tool.online.valve_control import blocker_summary, status_blocker

translate = QCoreApplication.translate


def emcy_text(code: int, fallback: str = "") -> str:
    """A user-facing description of EMCY ``code`` in the current language."""
    texts = {
        0x0000: translate("Emcy", "Warning: electronics temperature above 70 °C"),
        0x1000: translate("Emcy", "General error"),
        0x3410: translate("Emcy", "Supply voltage out of range"),
        0x3420: translate("Emcy", "Setpoint signal error (e.g. 4…20 mA wire break)"),
        0x4211: translate("Emcy", "Electronics temperature above 100 °C"),
        0x5230: translate("Emcy", "External sensor error"),
        0x5411: translate("Emcy", "Solenoid A over-current or disconnected"),
        0x5412: translate("Emcy", "Solenoid B over-current or disconnected"),
        0x7300: translate("Emcy", "Internal position sensor error"),
        0x8100: translate("Emcy", "CANopen communication error (heartbeat, SYNC or RPDO missing)"),
        0x8210: translate("Emcy", "CANopen RPDO too short: not processed"),
    }
    return texts.get(code) or fallback or translate("Emcy", "Unknown error")


def status_summary(status: StatusView | None) -> str:
    """``ok``, the most severe active error, or why the valve does not follow its setpoint
    (e.g. waiting for a CANopen master), for the status bar (manual §8.8)."""
    if status is None:
        return ""
    code = status.error_code
    if code:
        return f"0x{code:04X} {emcy_text(code, status.error_text)}"
    if status.warning:
        return emcy_text(0, status.error_text)
    reason = status_blocker(status)
    if reason is not None:
        return blocker_summary(reason)
    return translate("Emcy", "ok")
