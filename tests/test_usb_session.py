"""The valve session against the emulator over the emulated USB link (client ↔ firmware)."""

from __future__ import annotations

import dataclasses
import threading

import pytest
from support.valve_sets import changed_set

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve, Fault
from prm9tool.device.emulator.usb_firmware import UsbFirmware
from prm9tool.device.records import OperationCancelledError
from prm9tool.device.usb.session import UsbSession
from prm9tool.device.usb.transport.emulator import EmulatorTransport
from prm9tool.errors import AbortCode, Prm9Error, SdoAbortError, ValueRangeError
from prm9tool.files.backup import ensure_backup
from prm9tool.files.prmfile import read_file

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
E02 = "PRM9-06.2Z51/15-24E02S02"


@pytest.fixture
def valve(tmp_path):
    valve = EmulatedValve(E04, 4711, "2.3.4", nv_path=tmp_path / "nv.json")
    valve.advance(3.0)  # past the power-up timeline
    return valve


@pytest.fixture
def session(valve):
    with UsbSession(EmulatorTransport(valve), "emulator:test") as session:
        yield session


def changed_values(session: UsbSession) -> dict[str, int | str]:
    """Every file parameter moved one step away from its current value, within its range."""
    return changed_set(session.variant, session.download())


def test_identify_reports_the_valve(session):
    assert session.info.type_key == E04
    assert (session.info.serial, session.info.firmware) == (4711, "2.3.4")
    assert session.info.protocol_version == 1
    assert session.info.device_id == "emulator:test"


def test_read_numbers_and_segmented_strings(session, valve):
    assert session.read("PCODE") == E04
    assert session.read("SNV") == 4711
    values = session.read_many(["FWVER", "AINSETP", "DEVNAME", "LIMTA"])
    assert values == {m: valve.read(*CATALOGUE[m].key) for m in values}


def test_write_then_read_back(session, valve):
    session.write("LIMTA", 1234)
    assert session.read("LIMTA") == 1234 == valve.read(*CATALOGUE["LIMTA"].key)


def test_write_out_of_range_is_refused_before_sending(session):
    sent = session.transport.stats.reports_out
    with pytest.raises(ValueRangeError, match=r"THRESETP: .* outside the allowed range"):
        session.write_many({"AINSETP": 6, "THRESETP": 99999})
    assert session.transport.stats.reports_out == sent


def test_the_valve_refuses_with_the_cia301_abort_code(session):
    with pytest.raises(SdoAbortError) as caught:
        session.write("SNV", 5)
    assert caught.value.code == AbortCode.READ_ONLY
    assert "0x1018/4" in str(caught.value)


def test_unknown_parameter_names_the_variant(session):
    with pytest.raises(Prm9Error, match="NOPE: no such parameter in the catalogue"):
        session.read("NOPE")


def test_download_is_the_file_parameter_set(session, valve):
    values = session.download()
    params = CATALOGUE.file_parameters(session.variant)
    assert list(values) == [p.mnemonic for p in params]
    assert values == {p.mnemonic: valve.read(*p.key) for p in params}


def test_upload_writes_verifies_stores_and_survives_restart(session, valve):
    new = changed_values(session)
    steps: list[tuple[int, int, str]] = []
    result = session.upload(new, progress=lambda d, t, s: steps.append((d, t, s)))
    assert (result.verified, result.stored, result.failed_step) == (True, True, None)
    assert result.written == len(new) and result.mismatches == {}
    assert steps[-1] == (2 * len(new) + 1, 2 * len(new) + 1, "store")
    assert [s for _, _, s in steps] == sorted(
        (s for _, _, s in steps), key=["write", "verify", "store"].index
    )
    valve.restart()
    assert session.download() == new


def test_written_but_not_stored_values_vanish_on_restart(session, valve):
    before = session.download()
    session.write_many(changed_values(session))
    valve.restart()
    assert session.download() == before


class CorruptingTransport(EmulatorTransport):
    """Changes the first value of every READ answer once armed (a valve that stores badly)."""

    armed = False

    def _read(self, timeout_s):
        report = super()._read(timeout_s)
        if self.armed and report is not None and report[0] == 0x82 and report[3] > 0:
            report = report[:5] + bytes([report[5] ^ 0x01]) + report[6:]
        return report


def test_verification_mismatch_stores_nothing(valve):
    transport = CorruptingTransport(valve)
    session = UsbSession(transport, "emulator:test")
    before = session.download()
    new = changed_values(session)
    transport.armed = True
    result = session.upload(new)
    assert (result.verified, result.stored, result.failed_step) == (False, False, "verify")
    assert "AINSETP" in result.mismatches
    transport.armed = False
    valve.restart()
    assert session.download() == before


def test_cancel_stops_the_upload_and_stores_nothing(session, valve):
    before = session.download()
    cancel = threading.Event()

    def progress(done, total, step):
        if step == "verify":
            cancel.set()

    with pytest.raises(OperationCancelledError, match="nothing was stored"):
        session.upload(changed_values(session), progress=progress, cancel=cancel)
    valve.restart()
    assert session.download() == before


def test_restore_factory_takes_effect_after_restart(session):
    session.upload(changed_values(session))
    session.restore_factory()
    session.restart()
    defaults = {
        p.mnemonic: p.default_for(session.variant)
        for p in CATALOGUE.file_parameters(session.variant)
    }
    assert session.download() == defaults


def test_status_matches_the_valve(session, valve):
    valve.inject(Fault.COIL_A_OPEN)
    valve.advance(0.05)
    expected = valve.status()
    status = session.status()
    assert status.temperature_c == pytest.approx(expected.temperature_c, abs=0.005)
    assert status.supply_v == pytest.approx(expected.supply_v, abs=0.0005)
    rounded = {"temperature_c": status.temperature_c, "supply_v": status.supply_v}
    assert status == dataclasses.replace(expected, **rounded)
    assert status.error_code == 0x5411 and status.error_text


def test_long_error_text_arrives_in_pieces(session, valve, monkeypatch):
    text = "Überstrom an Spule A – bitte Verkabelung prüfen, Ventil neu starten, Handbuch §5.5"
    real = valve.status
    monkeypatch.setattr(valve, "status", lambda: dataclasses.replace(real(), error_text=text))
    sent = session.transport.stats.reports_out
    assert session.status().error_text == text
    assert session.transport.stats.reports_out - sent == 3


def test_stream_three_channels_at_full_rate(session, valve):
    keys = ["position_actual", "current_a", "setpoint_raw"]
    session.stream_start(keys)
    valve.set_input("setpoint", 5.0)
    valve.advance(0.2)
    block = session.stream_read()
    assert block.shape == (1000, 3)
    assert session.samples_lost == 0
    assert block[-1, 2] == pytest.approx(valve.signal("setpoint_raw"), abs=1)
    session.stream_stop()
    valve.advance(0.05)
    assert session.stream_read().shape == (0, 3)


def test_stream_at_a_lower_rate_arrives_at_most_11_ms_late(session, valve):
    session.stream_start(["temperature"], rate_hz=1000)  # 30 samples would fill a report
    valve.advance(0.1)
    assert len(session.stream_read()) > 0
    valve.advance(0.1)  # 100 samples; partial reports are sent 10 ms after their first sample
    assert 100 - 11 <= len(session.stream_read()) <= 100 + 11


def test_samples_lost_when_nobody_reads(session, valve):
    session.stream_start(["position_actual", "current_a", "demand"])
    valve.advance(2.0)  # ≈ 1000 reports; the valve's outbox keeps the newest 256
    sent = UsbFirmware.of(valve).stream_sequence  # reports the firmware produced
    assert sent > 900
    block = session.stream_read()
    assert block.shape == (2560, 3)
    assert session.samples_lost == (sent - 256) * 10


def test_stream_checks_its_arguments(session):
    with pytest.raises(ValueRangeError, match="1 to 3 measuring points"):
        session.stream_start(["demand"] * 4)
    with pytest.raises(ValueRangeError, match="'nope' is not a measuring point"):
        session.stream_start(["nope"])
    with pytest.raises(ValueRangeError, match="5000 Hz divided by a whole number"):
        session.stream_start(["demand"], rate_hz=3000)


def test_stream_of_a_signal_the_variant_lacks_is_refused(tmp_path):
    valve = EmulatedValve(E02, 5)
    session = UsbSession(EmulatorTransport(valve), "emulator:e02")
    with pytest.raises(SdoAbortError) as caught:
        session.stream_start(["process_actual"])
    assert caught.value.code == AbortCode.INVALID_VALUE


def test_a_firmware_text_with_cr_lf_cannot_inject_an_entry_into_the_backup():
    valve = EmulatedValve(E04, 4712, "1.0\r\nLIMTA = 5\nX=1")
    with UsbSession(EmulatorTransport(valve), "emulator:crlf") as session:
        path = ensure_backup(session)
    assert path is not None
    lines = path.read_text(encoding="utf-8").splitlines()
    assert [line for line in lines if "LIMTA" in line] == [
        "firmware = 1.0\\x0d\\x0aLIMTA = 5\\x0aX=1",
        "LIMTA = 2400  # Solenoid A: maximum current [mA]",
    ]
    contents = read_file(path)
    assert (contents.firmware, contents.unknown) == ("1.0\r\nLIMTA = 5\nX=1", [])  # exactly
    assert contents.values["LIMTA"] == 2400
