"""CiA 305 error answers of an LSS slave in words, and the error of a failed LSS service."""

from __future__ import annotations

from prm9tool.catalogue.canopen_switches import LSS_BIT_TIMINGS_KBIT
from prm9tool.device.canlink.lss_address import LssAddress
from prm9tool.errors import CommunicationError
from prm9tool.messages import QT_TRANSLATE_NOOP

CS_CONFIGURE_NODE_ID, CS_CONFIGURE_BIT_TIMING, CS_STORE = 0x11, 0x13, 0x17

# CiA 305 error codes of configure node ID / bit timing / store configuration
ERRORS = {
    CS_CONFIGURE_NODE_ID: {1: "the node ID is out of range (1…127)"},
    CS_CONFIGURE_BIT_TIMING: {1: "the device does not support this bit rate"},
    CS_STORE: {
        1: "the device cannot store its configuration (store not supported)",
        2: "the device could not write its non-volatile memory (storage media access error)",
    },
}
SERVICE = {
    CS_CONFIGURE_NODE_ID: "configure node ID",
    CS_CONFIGURE_BIT_TIMING: "configure bit timing",
    CS_STORE: "store configuration",
}


class LssFailedError(CommunicationError):
    """An LSS service failed; ``kind``: none, duplicate, taken, refused, lost, unanswered,
    endless (devices kept answering past the scan's bounds)."""

    summary = QT_TRANSLATE_NOOP("Errors", "Node ID assignment (LSS) did not complete.")

    def __init__(self, message: str, kind: str) -> None:
        super().__init__(message)
        self.kind = kind


def service_problem(
    address: LssAddress, cs: int, value: int, answer: bytes | None
) -> LssFailedError:
    """The error for service ``cs`` (with ``value``) to ``address``: its CiA 305 error answer in
    words, or — ``answer`` None — that the device left the bus."""
    what = SERVICE[cs]
    if cs == CS_CONFIGURE_NODE_ID:
        what += f" {value}"
    elif cs == CS_CONFIGURE_BIT_TIMING:
        what += f" {kbit(value)}"
    if answer is None:
        stored = (
            "it may or may not have stored the new configuration: power it up and search the "
            "bus (and the devices without a node ID)"
            if cs == CS_STORE
            else "it stored nothing"
        )
        return LssFailedError(
            f"serial {address.serial}: no answer to {what}: the device left the bus during "
            f"configuration; {stored}",
            "lost",
        )
    code, specific = answer[1], answer[2]
    reason = ERRORS[cs].get(code)
    if reason is None:
        reason = f"manufacturer-specific error {specific} (CiA 305 error code {code})"
    return LssFailedError(
        f"serial {address.serial} refused {what}: {reason}; nothing was stored", "refused"
    )


def kbit(index: int) -> str:
    """``250 kbit/s`` for a CiA 305 table-0 index."""
    if 0 <= index < len(LSS_BIT_TIMINGS_KBIT):
        return f"{LSS_BIT_TIMINGS_KBIT[index]} kbit/s"
    return f"(table index {index})"
