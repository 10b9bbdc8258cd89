"""Offscreen screenshot of Communication → CAN bus with its live node table.

Usage (from the repository root)::

    QT_QPA_PLATFORM=offscreen python tools/can_bus_screenshot.py [OUTPUT.png]

Real, on a virtual bus: an emulated E04 -CA valve (node 10, heartbeat 100 ms) in real time, a
node that is not a PRM9 (node 5), and a node that boots, beats a few times, sends an EMCY and
goes silent (node 20), and two valves at node-ID switch 1 (LSS) without a node ID, which the
dialog lists under "devices without a node ID". The dialog searches the bus; its monitor then
keeps the table live.
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
os.environ.setdefault("PRM9TOOL_DATA_DIR", tempfile.mkdtemp(prefix="can_bus_shot_"))

import can
import canopen
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QApplication

from prm9tool.device import factory
from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.emulator import EmulatedValve
from prm9tool.online.bus_monitor import BusMonitor
from prm9tool.online.connection import ValveConnection
from prm9tool.online.lss_commissioning import LssCommissioning
from prm9tool.views.canbus.bus_dialog import CanBusDialog

CHANNEL = "prm9tool-screenshot"


def main(output: Path) -> None:
    """Build the scene, grab the dialog, save it to ``output``."""
    app = QApplication.instance() or QApplication([])
    folder = Path(os.environ["PRM9TOOL_DATA_DIR"])
    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA", 4711, nv_path=folder / "4711.json")
    valve_bus = can.Bus(interface="virtual", channel=CHANNEL)
    slave = valve.connect_can(valve_bus)
    valve.advance(2.0)
    valve.start()
    valve.write(0x1017, 0, 100)
    unconfigured = []
    for serial in (4801, 4802):  # node-ID switch at 1: LSS, no node ID yet
        lss_valve = EmulatedValve("PRM9-06.3Z11/30-24E02S02-CA", serial, switches=(6, 1))
        lss_bus = can.Bus(interface="virtual", channel=CHANNEL)
        unconfigured.append((lss_valve, lss_valve.connect_can(lss_bus), lss_bus))
        lss_valve.start()
    other = canopen.Network()
    other.connect(interface="virtual", channel=CHANNEL)
    od = canopen.ObjectDictionary()
    var = canopen.objectdictionary.ODVariable("device type", 0x1000, 0)
    var.data_type, var.default = canopen.objectdictionary.UNSIGNED32, 0x191
    od.add_object(var)
    other.add_node(canopen.LocalNode(5, od))
    raw = can.Bus(interface="virtual", channel=CHANNEL)
    options = CanOptions("virtual", CHANNEL)
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=options))
    settings = QSettings(str(folder / "settings.ini"), QSettings.Format.IniFormat)
    monitor = BusMonitor()
    dialog = CanBusDialog(
        lambda bus, deliver: connection.list_devices_async((), deliver, bus),
        settings,
        None,
        monitor,
        LssCommissioning(),
    )
    dialog.interface.setCurrentText("virtual")
    dialog.channel.setText(CHANNEL)
    dialog.show()
    dialog.search.click()
    _spin(app, lambda: dialog.search.isEnabled() and dialog.table.rowCount() >= 2, 10)
    panel = dialog.lss_panel
    assert panel is not None
    _spin(app, lambda: panel.table.rowCount() == 2 and panel.look.isEnabled(), 60)
    raw.send(can.Message(arbitration_id=0x714, data=[0], is_extended_id=False))
    for _ in range(4):
        time.sleep(0.1)
        raw.send(can.Message(arbitration_id=0x714, data=[0x7F], is_extended_id=False))
    raw.send(can.Message(arbitration_id=0x094, data=[0, 0x81, 0x10, 0, 0, 0, 0, 0],
                         is_extended_id=False))  # fmt: skip
    _spin(app, lambda: "silent" in (dialog.table.item(2, 5) or dialog.state).text(), 5)
    dialog.table.selectRow(1)
    _spin(app, lambda: False, 0.3)
    dialog.grab().save(str(output))
    dialog.reject()
    _spin(app, lambda: False, 0.3)
    for closing in (raw.shutdown, other.disconnect, valve.stop, slave.stop, valve_bus.shutdown):
        closing()
    for lss_valve, lss_slave, lss_bus in unconfigured:
        lss_valve.stop()
        lss_slave.stop()
        lss_bus.shutdown()
    connection.shutdown()
    print(f"wrote {output}")  # noqa: T201


def _spin(app: QApplication, done, seconds: float) -> None:  # type: ignore[no-untyped-def]
    deadline = time.monotonic() + seconds
    while not done() and time.monotonic() < deadline:
        app.processEvents()
        time.sleep(0.01)


if __name__ == "__main__":
    main(
        Path(sys.argv[1])
        if len(sys.argv) > 1
        else Path("docs/screenshots/window_dialog_can_bus.png")
    )
