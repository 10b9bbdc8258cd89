"""The links a valve drops off and comes back on, for the reconnect tests that run once per
link: a main window online with an emulated valve over USB (its cable pulled and plugged back
through Valve → Emulated valve) or over CANopen — an emulated -CA valve in real time on a
private virtual bus whose CAN cable is pulled (it leaves the bus, runs on, and joins again), or
whose master's adapter goes bus-off and recovers (tests/support/bus_off_rig.py).
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.device import factory
from prm9tool.online.connection import ValveConnection
from prm9tool.service.valve_listing import default_lister
from support.bus_off_rig import Adapter, install
from support.can_link_rig import LinkRig, make_link_rig
from support.gui_support import E02, E02_CA, emulated, go_online, main_window, session_of

TIMEOUT = 10_000
USB_SERIAL = 4301
LINKS = ("usb", "can", "bus-off")


class Link:
    """One window online with one emulated valve on one link."""

    name = ""
    canopen = True  # the valve is reached over CANopen

    def __init__(self, qtbot: Any, window: Any) -> None:
        self.qtbot = qtbot
        self.window = window

    @property
    def valve(self) -> Any:
        """The emulated valve (EmulatedValve)."""
        raise NotImplementedError

    @property
    def serial(self) -> int:
        """Its serial number."""
        return int(self.valve.serial)

    def raw(self, mnemonic: str) -> int:
        """What the valve works with for ``mnemonic`` (read inside the emulator)."""
        param = CATALOGUE[mnemonic]
        return int(self.valve.read(param.index, param.subindex))

    def pull(self) -> None:
        """Take the valve off the link (GUI thread); returns once the window looks for it."""
        with self.qtbot.waitSignal(self.window.connection.reconnecting, timeout=TIMEOUT):
            self._pull()
        assert not self.window.connection.is_online

    def plug(self) -> None:
        """Put it back (GUI thread); returns once the window is online with it again."""
        with self.qtbot.waitSignal(self.window.connection.reconnected, timeout=TIMEOUT):
            self._plug()

    def pull_from_worker(self) -> None:
        """:meth:`pull` without waiting, called inside a job of the connection's worker (in
        the middle of an upload or a tuning test): the very next exchange fails."""
        self._pull()

    def _pull(self) -> None:
        raise NotImplementedError

    def _plug(self) -> None:
        raise NotImplementedError


class UsbLink(Link):
    """Over USB: Valve → Emulated valve → Pull the USB cable / Plug it back in."""

    name = "usb"
    canopen = False

    @property
    def valve(self) -> Any:
        return emulated(USB_SERIAL)

    def pull_from_worker(self) -> None:
        session_of(self.window).emulator.pull_cable()  # what the menu runs in the worker

    def _pull(self) -> None:
        self.window.emulated_menu.cable_action.trigger()

    def _plug(self) -> None:
        assert self.window.emulated_menu.plug_action.isEnabled()
        self.window.emulated_menu.plug_action.trigger()


class CanLink(Link):
    """Over CANopen: the valve's CAN cable out (its node leaves the bus; the valve and its
    CAN controller run on with what they had) and in again."""

    name = "can"

    def __init__(self, qtbot: Any, window: Any, rig: LinkRig) -> None:
        super().__init__(qtbot, window)
        self.rig = rig

    @property
    def valve(self) -> Any:
        return self.rig.valve

    def _pull(self) -> None:
        self.rig.unplug()

    def _plug(self) -> None:
        self.rig.plug()


class BusOffLink(CanLink):
    """Over CANopen, the tool's adapter going bus-off (every frame refused, none received) and
    back on the bus; the valve stays where it is."""

    name = "bus-off"

    def __init__(self, qtbot: Any, window: Any, rig: LinkRig, adapter: Adapter) -> None:
        super().__init__(qtbot, window, rig)
        self.adapter = adapter

    def pull_from_worker(self) -> None:
        """Bus-off, and back once the tool's bus has seen it (its next frame is refused)."""
        self._pull()
        deadline = time.monotonic() + TIMEOUT / 1000
        while not self.adapter.told() and time.monotonic() < deadline:
            time.sleep(0.001)

    def _pull(self) -> None:
        self.adapter.go_bus_off()

    def _plug(self) -> None:
        self.adapter.recover()


def can_connection(rig: LinkRig) -> ValveConnection:
    """The program's connection for a valve on ``rig``'s bus (lists and opens CAN nodes)."""
    return ValveConnection(
        opener=lambda entry: factory.open_session(entry, can_link=rig.options),  # type: ignore[arg-type]
        lister=default_lister,
    )


@contextmanager
def online_window(
    qtbot: Any, tmp_path: Path, link: str, monkeypatch: pytest.MonkeyPatch | None = None
) -> Iterator[Link]:
    """A main window online and in step with an emulated valve on ``link`` (one of
    :data:`LINKS`; "bus-off" needs ``monkeypatch`` for the adapter), looking for it when it
    drops off (as the program does)."""
    if link == "usb":
        with main_window(qtbot, tmp_path) as window:
            window.connection.auto_reconnect = True
            go_online(qtbot, window, f"{E02}:{USB_SERIAL}")
            qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
            yield UsbLink(qtbot, window)
        return
    rig = make_link_rig("reconnect-window", tmp_path, E02_CA, switches=(6, 2))  # node 10
    rig.valve.start()
    adapter = None
    if link == "bus-off":
        assert monkeypatch is not None
        adapter = install(monkeypatch, rig.options.channel)
    try:
        with main_window(qtbot, tmp_path, E02_CA, can_connection(rig)) as window:
            window.connection.auto_reconnect = True
            with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
                window.valve.go_online("can:10")
            qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
            yield (
                CanLink(qtbot, window, rig)
                if adapter is None
                else BusOffLink(qtbot, window, rig, adapter)
            )
    finally:
        rig.valve.stop()
        rig.close()
