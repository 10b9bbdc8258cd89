"""The hidapi backend against a fake ``hid`` module: report IDs, faults, discovery, restart."""

from __future__ import annotations

import sys
import time

import pytest
from support.usb_fakes import FakeHid
from support.valve_sets import changed_set

from prm9tool.device import emulated_valves, factory
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.usb.session import UsbSession
from prm9tool.device.usb.transport.hidapi import HidTransport, UsbFilter, load_hid
from prm9tool.errors import CommunicationError, DeviceDisconnectedError

E02 = "PRM9-06.3Z11/30-24E02S02"
E04 = "PRM9-10.3Z11/60-24E04S02-CA"
PATH = b"/dev/hidraw3"


@pytest.fixture(autouse=True)
def _fresh_emulators():
    yield
    emulated_valves.forget_emulated_valves()


@pytest.fixture
def fake_hid(monkeypatch):
    fake = FakeHid()
    monkeypatch.setitem(sys.modules, "hid", fake.as_module())
    monkeypatch.setitem(sys.modules, "hidraw", fake.as_module())  # hidapi's Linux hidraw build
    monkeypatch.setattr(HidTransport, "settle_s", 0.0)
    return fake


@pytest.fixture
def device(fake_hid):
    return fake_hid.add(EmulatedValve(E02, 321, "0.35.16"), PATH)


def open_session(timeout_s: float = 0.05) -> UsbSession:
    return UsbSession(HidTransport(PATH, timeout_s=timeout_s), f"usb:{PATH.decode()}")


def changed(variant) -> dict[str, int | str]:
    return changed_set(variant)


def test_every_write_carries_report_id_0_and_64_bytes(device):
    session = open_session()
    assert (session.info.type_key, session.info.serial, session.info.firmware) == (
        E02,
        321,
        "0.35.16",
    )
    result = session.upload(changed(session.variant))
    assert result.stored
    assert all(len(w) == 65 and w[0] == 0 for w in device.writes)
    assert session.download() == changed(session.variant)


def test_stream_reads_without_blocking(device):
    session = open_session()
    session.stream_start(["supply_voltage", "temperature"])
    device.valve.advance(0.1)
    block = session.stream_read()
    assert block.shape == (495, 2)  # 33 full reports of 15; the rest waits up to 10 ms
    assert session.samples_lost == 0
    assert session.stream_read().shape == (0, 2)


def test_dropped_request_and_dropped_answer_are_recovered(device):
    session = open_session()
    device.cable.drop_out = {device.out_count + 1}
    device.cable.drop_in = {device.in_count + 2}
    assert session.read("SNV") == 321
    assert session.read("AINSETP") == 9
    assert session.transport.stats.retries == 2


def test_duplicated_answer_is_discarded(device):
    session = open_session()
    device.cable.duplicate_in = {device.in_count + 1}
    session.write("LIMTA", 1111)
    assert session.read("LIMTA") == 1111
    assert session.transport.stats.discarded == 1


def test_late_answer_is_discarded(device):
    session = open_session()
    device.cable.late_in = {device.in_count + 1: 0.08}  # after the 0.05 s timeout
    assert session.read("SNV") == 321
    assert session.transport.stats.retries == 1
    time.sleep(0.1)  # the late answer arrives now
    assert session.read("AINSETP") == 9
    assert session.transport.stats.discarded == 1


def test_unplugged_during_upload_stores_nothing(device):
    session = open_session()
    before = session.download()
    device.cable.unplug_after_out = device.out_count + 3
    with pytest.raises(DeviceDisconnectedError, match=r"while writing the parameters \(step 1"):
        session.upload(changed(session.variant))
    device.valve.restart()
    device.plugged = True
    device.cable.unplug_after_out = None
    assert open_session().download() == before


def test_discovery_lists_valves_not_other_hid_devices(fake_hid, monkeypatch):
    fake_hid.add(EmulatedValve(E02, 11), b"/dev/hidraw0")
    fake_hid.add(EmulatedValve(E04, 12, "2.0.0"), b"/dev/hidraw1", product_id=0x5679)
    fake_hid.others.append(
        {"path": b"/dev/hidraw2", "vendor_id": 1, "product_id": 2, "product_string": "Keyboard"}
    )
    entries = factory.list_devices(["PRM9-06.2Z51/15-24E02S02:77"])
    assert [(e.kind, e.type_key, e.serial, e.firmware) for e in entries] == [
        ("usb", E02, 11, "1.0.0"),
        ("usb", E04, 12, "2.0.0"),
        ("emulator", "PRM9-06.2Z51/15-24E02S02", 77, "1.0.0"),
    ]
    assert entries[0].device_id == "usb:/dev/hidraw0"
    assert b"/dev/hidraw2" not in fake_hid.opened
    monkeypatch.setenv("PRM9TOOL_USB_VID", "1234")
    monkeypatch.setenv("PRM9TOOL_USB_PID", "0x5679")
    assert [e.serial for e in factory.list_devices()] == [12]


def test_bad_usb_id_in_the_environment_is_explained(monkeypatch):
    monkeypatch.setenv("PRM9TOOL_USB_VID", "zz")
    with pytest.raises(CommunicationError, match="PRM9TOOL_USB_VID='zz' is not a hexadecimal"):
        UsbFilter.from_env()


def test_restart_finds_the_valve_under_its_new_path(fake_hid, device):
    session = factory.open_session(f"usb:{PATH.decode()}")
    session.write("LIMTA", 1300)
    session.store()
    device.valve.add_restart_listener(lambda: fake_hid.replug(PATH, b"/dev/hidraw9"))
    session.restart()
    assert session.transport.path == b"/dev/hidraw9"
    assert session.read("LIMTA") == 1300
    session.close()


def test_without_hidapi_the_emulator_still_works(monkeypatch):
    monkeypatch.setitem(sys.modules, "hid", None)  # import hid -> ImportError
    monkeypatch.setitem(sys.modules, "hidraw", None)
    assert "hidapi library could not be loaded" in factory.usb_unavailable_reason()
    entries = factory.list_devices([E02])
    assert [e.kind for e in entries] == ["emulator"]
    with factory.open_session(entries[0], paced=False) as session:
        assert session.read("PCODE") == E02
    with pytest.raises(CommunicationError, match="USB is not available"):
        factory.open_session("usb:/dev/hidraw0")


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="hidraw exists on Linux only")
def test_linux_uses_the_hidraw_backend_and_falls_back_to_libusb(monkeypatch):
    hidraw, libusb = FakeHid().as_module(), FakeHid().as_module()
    monkeypatch.setitem(sys.modules, "hidraw", hidraw)
    monkeypatch.setitem(sys.modules, "hid", libusb)
    assert load_hid() is hidraw  # /dev/hidrawN paths, the kernel keeps its HID driver
    monkeypatch.setitem(sys.modules, "hidraw", None)
    assert load_hid() is libusb
    monkeypatch.setitem(sys.modules, "hid", None)
    with pytest.raises(CommunicationError, match=r"could not be loaded \(hidraw: .*; hid: "):
        load_hid()
