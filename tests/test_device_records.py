"""The records every link shares (prm9tool.device.records): one module, no emulator, no Qt."""

from __future__ import annotations

import dataclasses
import subprocess
import sys
from pathlib import Path

import pytest

from prm9tool.device.canlink.bus import CanNetwork, CanOptions
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.records import (
    DeviceInfo,
    LedState,
    NmtState,
    UploadResult,
    ValveStatus,
)
from prm9tool.device.usb.protocol.status import NMT_STATES, StatusReply
from prm9tool.device.usb.protocol.wire import Reader, Writer
from prm9tool.device.usb.session import UsbSession
from prm9tool.device.usb.transport.emulator import EmulatorTransport

ROOT = Path(__file__).resolve().parents[1]
E04 = "PRM9-06.3Z11/30-24E04S02-CA"


def loaded_by(statement: str) -> list[str]:
    """The modules of prm9tool, PySide6 and pyqtgraph that ``statement`` loads (a fresh process)."""
    code = (
        f"import sys\n{statement}\n"
        "print('\\n'.join(sorted(m for m in sys.modules "
        "if m.startswith(('prm9tool', 'PySide6', 'pyqtgraph')))))"
    )
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True
    )
    return done.stdout.split()


def test_importing_the_valve_session_loads_no_emulator_and_no_qt():
    loaded = loaded_by("from prm9tool.device.session import ValveSession")
    assert "prm9tool.device.session" in loaded  # the probe sees what it imports
    assert "prm9tool.device.records" in loaded
    assert [m for m in loaded if m.startswith("prm9tool.device.emulator")] == []
    assert [m for m in loaded if m.startswith(("PySide6", "pyqtgraph"))] == []


def test_the_canopen_link_loads_no_emulator():
    """The CAN status read the error table and the LED rules from the emulator's modules; they
    are the catalogue's (error_kinds.py) and the device layer's (leds.py) now."""
    loaded = loaded_by("import prm9tool.device.canlink.session")
    assert "prm9tool.device.canlink.status" in loaded and "prm9tool.device.leds" in loaded
    assert [m for m in loaded if m.startswith("prm9tool.device.emulator")] == []


def test_records_take_keywords_only_and_are_frozen():
    info = DeviceInfo(type_key=E04, serial=7, firmware="1.0", protocol_version=1, device_id="usb:7")
    with pytest.raises(TypeError):
        DeviceInfo(E04, 7, "1.0", 1, "usb:7")  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        info.serial = 8  # type: ignore[misc]
    result = UploadResult(written=3, verified=True, stored=True, duration_s=0.1)
    assert (result.mismatches, result.failed_step, result.skipped) == ({}, None, ())
    with pytest.raises(TypeError):
        LedState("off", "off", False)  # type: ignore[misc]


def test_every_link_reports_the_nmt_state_as_the_enum(tmp_path):
    valve = EmulatedValve(E04, 4711, "2.3.4", nv_path=tmp_path / "nv.json")
    valve.advance(3.0)  # past the power-up timeline
    assert isinstance(valve.status(), ValveStatus)
    assert valve.status().nmt_state is NmtState.PRE_OPERATIONAL
    with UsbSession(EmulatorTransport(valve), "emulator:test") as session:
        status = session.status()
    assert status.nmt_state is NmtState.PRE_OPERATIONAL  # over the USB wire and back
    assert str(status.nmt_state) == "pre-operational"  # what JSON and the status window show


def test_an_nmt_code_the_usb_protocol_does_not_define_reads_as_unknown():
    reply = StatusReply(
        device_state="INIT",
        error_code=0,
        error_register=0,
        warning=False,
        booting=False,
        nmt_state=NmtState.UNKNOWN,
        leds=(("off", "off", False),) * 3,
        temperature_c=20.0,
        supply_v=24.0,
        active_errors=(),
        text_total=0,
        text_offset=0,
        text_chunk=b"",
    )
    w = Writer()
    reply.encode(w)
    assert NmtState.UNKNOWN not in NMT_STATES
    assert StatusReply.decode(Reader(w.report())).nmt_state is NmtState.UNKNOWN


def test_a_heartbeat_state_cia_301_does_not_define_reads_as_unknown():
    import can

    network = CanNetwork(CanOptions("virtual", "x", None), network=None)  # type: ignore[arg-type]
    network.on_frame(can.Message(arbitration_id=0x70A, data=[0x05], is_extended_id=False))
    assert network.seen[10].nmt_state is NmtState.OPERATIONAL
    network.on_frame(can.Message(arbitration_id=0x70A, data=[0x33], is_extended_id=False))
    assert network.seen[10].nmt_state is NmtState.UNKNOWN
