"""An emulated -CA valve on a private virtual CAN channel, for the tool's CANopen link.

``real_valve=True`` makes the emulated valve answer like a real PRM9 is expected to: the
objects whose address is this project's decision (catalogue ``address_from_manual`` False)
do not exist (abort 0x06020000). Faults: :meth:`LinkRig.refuse` (an SDO abort on one object),
:meth:`LinkRig.go_silent_after` (the node stops answering after n SDO requests),
:meth:`LinkRig.unplug` / :meth:`LinkRig.plug` (its CAN cable).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import can
import numpy as np
import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.canopen_slave import CanopenSlave
from prm9tool.errors import AbortCode, SdoAbortError
from prm9tool.twin.syncstep import SyncStepper as PackageStepper
from support.canopen_rig import BOOT_S, unique_channel

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
E04 = "PRM9-06.3Z11/30-24E04S02-CA"
DECIDED = {p.key for p in CATALOGUE if not p.address_from_manual}
_serials = itertools.count(3000)


@dataclass
class LinkRig:
    """The valve, its slave and the bus options the tool uses to reach it."""

    valve: EmulatedValve
    slave: CanopenSlave
    bus: can.BusABC
    options: CanOptions
    refused: dict[tuple[int, int], int] = field(default_factory=dict)
    missing: set[tuple[int, int]] = field(default_factory=set)
    silent_after: int | None = None
    reset_at: int | None = None
    requests: int = 0
    unplugged: bool = False

    def unplug(self) -> None:
        """Pull the valve's CAN cable: no frame reaches it or leaves it; the valve and its CAN
        controller run on (its heartbeat and RPDO deadline timers keep counting)."""
        self.unplugged = True

    def plug(self) -> None:
        """Plug the valve's CAN cable back in."""
        self.unplugged = False

    def refuse(self, index: int, subindex: int, code: int = AbortCode.INVALID_VALUE) -> None:
        """Writes to this object are aborted with ``code``."""
        self.refused[(index, subindex)] = code

    def go_silent_after(self, requests: int) -> None:
        """The node answers ``requests`` more SDO requests, then none (power lost, cable cut)."""
        self.silent_after = self.requests + requests

    def reset_after(self, requests: int) -> None:
        """The valve is reset (NMT reset node by another master, a power dip) when the
        ``requests``-th SDO request from now arrives: that one and those during the ~2 s
        boot get no answer."""
        self.reset_at = self.requests + requests

    def stored_set(self) -> dict[str, int | str]:
        """The valve's non-volatile memory (what it holds after a power cycle; entries not
        stored yet are at their factory defaults)."""
        with self.valve.lock:
            return dict(self.valve.firmware.nv.values)

    def working(self, mnemonic: str) -> int | str:
        """The value the valve works with now (RAM)."""
        param = CATALOGUE[mnemonic]
        return self.valve.read(param.index, param.subindex)

    def close(self) -> None:
        """Take the valve off the bus."""
        self.slave.stop()
        self.bus.shutdown()


def make_link_rig(
    name: str,
    tmp_path: Path,
    type_key: str = E04,
    real_valve: bool = False,
    switches: tuple[int, int] | None = None,
    od: str = "full",
) -> LinkRig:
    """A booted valve (node 10) on a fresh virtual channel; its EEPROM in ``tmp_path``.
    ``switches``: its rotary switches (interface/bit rate, node ID; default 6, 2); ``od``:
    ``manual`` for a valve with only the objects the manual lists (``--od manual``)."""
    channel = unique_channel(name)
    serial = next(_serials)
    valve = EmulatedValve(
        type_key, serial, nv_path=tmp_path / f"{serial}.json", switches=switches, od=od
    )
    bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(bus)
    rig = LinkRig(valve, slave, bus, CanOptions("virtual", channel))
    if real_valve:
        rig.missing |= DECIDED
    _wrap_sdo(rig)
    valve.advance(BOOT_S)
    return rig


def _wrap_sdo(rig: LinkRig) -> None:
    server = rig.slave._sdo
    read, write = server._read, server._write

    def checked(index: int, subindex: int) -> None:
        if (index, subindex) in rig.missing or (index, 0xFF) in rig.missing:
            raise SdoAbortError(index, subindex, AbortCode.NO_SUCH_OBJECT)

    def new_read(index: int, subindex: int) -> bytes:
        checked(index, subindex)
        return read(index, subindex)

    def new_write(index: int, subindex: int, data: bytes) -> None:
        checked(index, subindex)
        code = rig.refused.get((index, subindex))
        if code is not None:
            raise SdoAbortError(index, subindex, code)
        write(index, subindex, data)

    server._read, server._write = new_read, new_write
    on_message: Callable[[can.Message], None] = rig.slave._on_message

    def filtered(msg: can.Message) -> None:
        if rig.unplugged:
            return
        if msg.arbitration_id == 0x600 + rig.slave.node_id:
            rig.requests += 1
            if rig.silent_after is not None and rig.requests > rig.silent_after:
                return
            if rig.reset_at is not None and rig.requests == rig.reset_at:
                rig.valve.nmt_event("reset_node")
                return
        on_message(msg)

    rig.slave._on_message = filtered  # type: ignore[method-assign]  # its receive thread's
    send = rig.bus.send

    def cabled_send(msg: can.Message, timeout: float | None = None) -> None:
        if not rig.unplugged:  # a controller without a bus: its frames go nowhere
            send(msg, timeout)

    rig.bus.send = cabled_send  # type: ignore[method-assign]


@dataclass
class SyncStepper:
    """The valve of a :class:`LinkRig` stepped by the master's SYNC
    (:class:`prm9tool.twin.syncstep.SyncStepper`, which says how) for a test that runs the
    tool's own path (the command line's CanRig): :meth:`install` makes that path's SYNC clock
    the stepper's. :attr:`lost` counts the samples the master lost and bridged (a skipped or
    late SYNC) of the :attr:`recorded` ones; :attr:`skipped` the ticks the valve ran through
    unseen."""

    rig: LinkRig
    period_s: float
    recorded: int = 0  # samples of the plays whose response the master kept
    lost: int = 0  # of them, lost on the master's side and bridged (a skipped or late SYNC)
    stepper: PackageStepper | None = None

    @property
    def syncs(self) -> int:
        """SYNCs the valve took."""
        return self.stepper.syncs if self.stepper is not None else 0

    @property
    def skipped(self) -> int:
        """Ticks the master did not send (the valve ran through them)."""
        return self.stepper.skipped if self.stepper is not None else 0

    def install(self, monkeypatch: pytest.MonkeyPatch) -> SyncStepper:
        """Stop the valve's paced thread (if any), make the tool's CanRig produce SYNC with the
        stepper's clock and step the valve by SYNC from now on (its bus must keep the time
        stamps it is given: ``preserve_timestamps=True``)."""
        from prm9tool.characterize import canrig

        self.stepper = PackageStepper(self.rig.valve, self.rig.bus, self.period_s).attach()
        monkeypatch.setattr(canrig, "SyncClock", self.stepper.clock)
        bridged = canrig.bridged

        def counted(response: np.ndarray) -> np.ndarray:
            self.recorded += len(response)
            self.lost += int(np.isnan(response).sum())
            return bridged(response)

        monkeypatch.setattr(canrig, "bridged", counted)
        return self
