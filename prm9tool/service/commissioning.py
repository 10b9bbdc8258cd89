"""Commissioning one open valve, and what an NMT command this program sent means for the
answers that follow: :class:`Commissioning`, the part of a
:class:`~prm9tool.service.valve.ValveService` that sends NMT commands and the control word
(manual §7.2, §7.4) and remembers that it stopped the valve, so that a valve which cannot
answer says why instead of asking whether it is powered. No Qt.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TYPE_CHECKING

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.errors import DeviceTimeoutError

if TYPE_CHECKING:
    from prm9tool.device.records import ValveStatus
    from prm9tool.device.session import ValveSession

__all__ = ["Commissioning", "NmtStoppedError", "parse_nmt"]

BOOT_WAIT_S = 3.0  # commissioning waits at most this for a valve still booting
STOPPED_TEXT = (
    "the valve does not answer: this program stopped it (NMT stop), and a stopped valve "
    "answers no SDO (manual §7.2); send NMT start or pre-operational first"
)


class NmtStoppedError(DeviceTimeoutError):
    """The valve does not answer because this program stopped it by NMT (manual §7.2)."""


def parse_nmt(command: NmtCommand | str | int) -> NmtCommand:
    """An :class:`NmtCommand`, its name (``"start"``, ``"pre-operational"`` …) or its code."""
    if isinstance(command, NmtCommand):
        return command
    if isinstance(command, int):
        return NmtCommand(command)
    name = command.strip().upper().replace("-", "_").replace(" ", "_")
    if name not in NmtCommand.__members__:
        known = ", ".join(m.lower().replace("_", "-") for m in NmtCommand.__members__)
        raise ValueError(f"unknown NMT command {command!r}: one of {known}")
    return NmtCommand[name]


class Commissioning:
    """NMT, enable, disable and the status of one valve; ``session()`` gives its open
    session (the service's, which raises once it is closed)."""

    def __init__(self, session: Callable[[], ValveSession]) -> None:
        self._session = session
        self._stopped = False  # this program sent NMT stop and nothing since

    def status(self) -> ValveStatus:
        """Device state, errors, LEDs, NMT state now. A valve this program stopped by NMT
        says so instead of asking whether it is powered."""
        try:
            return self._session().status()
        except DeviceTimeoutError as exc:
            if self._stopped:
                raise NmtStoppedError(f"{STOPPED_TEXT} ({exc})") from exc
            raise

    def restarted(self) -> None:
        """The valve was restarted: it boots into pre-operational, stopped no more."""
        self._stopped = False

    def wait_booted(self, timeout_s: float = 5.0) -> ValveStatus:
        """Ask for the status until the valve has finished booting (about 2 s after power-up
        or a restart, manual §1.5, §5.6) and return it; DeviceTimeoutError after
        ``timeout_s``. A booting valve ignores its setpoint, NMT commands and the control
        word."""
        deadline = time.monotonic() + timeout_s
        while (status := self._session().status()).booting:
            if time.monotonic() > deadline:
                raise DeviceTimeoutError(f"the valve has not finished booting in {timeout_s} s")
            time.sleep(0.05)
        return status

    def nmt(self, command: NmtCommand | str | int) -> None:
        """Send an NMT command as the valve's CANopen master would (manual §7.2)."""
        code = parse_nmt(command)
        self._session().nmt(int(code))
        self._stopped = code is NmtCommand.STOP

    def enable(self) -> ValveStatus:
        """Control word 08h → 09h → 0Bh → 0Fh (manual §7.4, table 7-19): from INIT or a fault
        whose cause is gone to DEVICE_MODE_ACTIVE; the valve then follows its setpoint.
        Returns the status read back; raises :class:`~prm9tool.device.enabling.NotEnabledError`
        saying why (which error is still present, what to do) when it does not get there."""
        from prm9tool.device.enabling import enable

        return enable(self._session())

    def disable(self) -> ValveStatus:
        """Control word 0Fh → 0Bh → 09h → 08h: back to INIT step by step; returns the status
        read back; :class:`~prm9tool.device.enabling.NotDisabledError` when the valve stays in
        DEVICE_MODE_ACTIVE (it would still follow its setpoint)."""
        from prm9tool.device.enabling import disable

        return disable(self._session())

    def commission(self) -> ValveStatus:
        """What the window's "Enable it now?" does: NMT start when the valve waits in
        pre-operational or stopped (or the link has not heard its NMT state yet), then the
        enable sequence; returns the status after. A valve still booting is waited for (at
        most BOOT_WAIT_S), then enabled."""
        session = self._session()
        status = session.status()
        # just powered up, the valve boots for about 2 s (manual §1.5, §5.6): wait it out
        deadline = time.monotonic() + BOOT_WAIT_S
        while status.booting and time.monotonic() < deadline:
            time.sleep(0.05)
            status = session.status()
        # a CANopen master that heard no heartbeat yet cannot tell: NMT start, which an
        # operational valve ignores (CiA 301), rather than an enable in pre-operational
        if str(status.nmt_state) in ("pre-operational", "stopped", "unknown"):
            self.nmt(NmtCommand.START)
        return self.enable()
