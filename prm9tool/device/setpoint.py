"""Driving a valve's setpoint from the PC: the setpoint generator's and the tuning procedures'
way into the valve, one class per link (``ValveSession.setpoint_link``).

* :class:`OverrideSetpoint` (USB, and any valve with this project's service objects): while
  SETPOVRON = 1 the firmware takes its setpoint from SETPOVR instead of its analog input; it
  drops the override by itself 500 ms after the last USB report.
* ``prm9tool.device.canlink.rpdo_setpoint.RpdoSetpoint`` (CANopen): the setpoint travels in
  RPDO1 (control word + 0x6300 or 0x6380, manual table 7-13), as a PLC sends it.

A link takes the setpoint with :meth:`SetpointLink.begin`, sets values with
:meth:`SetpointLink.set`, is kept alive by :meth:`SetpointLink.keep_alive` at least every
:attr:`SetpointLink.keepalive_s` and gives the setpoint back with :meth:`SetpointLink.end`. A
refusal raises the valve's error (a Prm9Error naming the object in :attr:`SetpointLink.writing`),
a dead link a CommunicationError. No Qt.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Protocol

KEEPALIVE_S = 0.1  # the override's watchdog is 500 ms; rewrite at least this often


class SetpointLink(ABC):
    """How the PC drives one valve's setpoint (see the module docstring)."""

    keepalive_s = KEEPALIVE_S
    writing = ""  # the object the last failed call was writing (named in a refusal)

    @property
    @abstractmethod
    def objects(self) -> tuple[str, ...]:
        """The parameters (mnemonics) this link writes."""

    @abstractmethod
    def begin(self, raw: int) -> None:
        """Take the setpoint over with ``raw`` as its first value (nothing runs on failure)."""

    @abstractmethod
    def set(self, raw: int) -> None:
        """A new setpoint value."""

    @abstractmethod
    def keep_alive(self) -> None:
        """Tell the valve the PC is still there (repeat the last value)."""

    @abstractmethod
    def end(self) -> None:
        """Give the setpoint back to where the valve took it from before :meth:`begin`."""

    def release(self) -> None:
        """Give the setpoint back after a lost connection (a new session, nothing begun in it):
        undo what a previous session may have left on. Nothing to do by default."""
        return

    def leftovers(self) -> dict[str, int]:
        """What :meth:`begin` changed on the valve that :meth:`end` would put back, as
        {mnemonic: value before}: for a link that broke before :meth:`end`, written back once
        the same valve is open again. Nothing by default."""
        return {}


class Writes(Protocol):
    """What the override needs of its session: writing one raw value (a ValveSession)."""

    def write(self, mnemonic: str, raw: int | str) -> None: ...


class OverrideSetpoint(SetpointLink):
    """The service override SETPOVRON/SETPOVR (see the module docstring)."""

    def __init__(self, session: Writes) -> None:
        self._session = session
        self._last = 0

    @property
    def objects(self) -> tuple[str, ...]:
        """SETPOVR and SETPOVRON."""
        return ("SETPOVR", "SETPOVRON")

    def begin(self, raw: int) -> None:
        """SETPOVR = ``raw``, then SETPOVRON = 1."""
        self.set(raw)
        self._write("SETPOVRON", 1)

    def set(self, raw: int) -> None:
        """SETPOVR = ``raw``."""
        self._write("SETPOVR", raw)
        self._last = raw

    def keep_alive(self) -> None:
        """SETPOVR again (any report keeps the override alive)."""
        self._write("SETPOVR", self._last)

    def end(self) -> None:
        """SETPOVRON = 0: the analog input again."""
        self._write("SETPOVRON", 0)

    def release(self) -> None:
        """SETPOVRON = 0 (the firmware may not have noticed the dropped link)."""
        self.end()

    def _write(self, mnemonic: str, raw: int) -> None:
        self.writing = mnemonic
        self._session.write(mnemonic, raw)
