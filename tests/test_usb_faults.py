"""Link faults on the emulated USB cable: unplug at every point of an upload; lost,
duplicated and late reports."""

from __future__ import annotations

import logging
import threading

import pytest
from support.valve_sets import changed_set

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.device.emulator import EmulatedValve, usb_firmware
from prm9tool.device.records import OperationCancelledError
from prm9tool.device.usb.session import UsbSession
from prm9tool.device.usb.transport.emulator import EmulatorTransport, LinkFaults
from prm9tool.errors import DeviceDisconnectedError, DeviceTimeoutError, ProtocolError

E04 = "PRM9-06.3Z11/30-24E04S02-CA"


def new_values(variant) -> dict[str, int | str]:
    """A complete parameter set that differs from the factory defaults in every entry."""
    return changed_set(variant)


def open_session(valve: EmulatedValve) -> tuple[UsbSession, EmulatorTransport]:
    transport = EmulatorTransport(valve)
    return UsbSession(transport, "emulator:faults"), transport


def reports_of_a_full_upload(tmp_path) -> int:
    return reports_until_the_store(tmp_path)[1]


def reports_until_the_store(tmp_path) -> tuple[int, int]:
    """Reports an upload exchanges before its STORE request, and in all (the store is
    followed by the read-back that confirms it)."""
    valve = EmulatedValve(E04, 1, nv_path=tmp_path / "count.json")
    session, transport = open_session(valve)
    before = transport.reports_on_link
    store, at = session.store, []

    def counting_store() -> None:
        at.append(transport.reports_on_link - before)
        store()

    session.store = counting_store  # type: ignore[method-assign]
    session.upload(new_values(session.variant))
    return at[0], transport.reports_on_link - before


def stored_values(variant) -> dict[str, int | str]:
    """A previously stored set: the factory defaults with every other entry changed."""
    values = {p.mnemonic: p.default_for(variant) for p in CATALOGUE.file_parameters(variant)}
    changed = new_values(variant)
    for mnemonic in list(values)[::2]:
        values[mnemonic] = changed[mnemonic]
    return values


def test_unplugged_at_every_point_of_an_upload(tmp_path):
    store_at, total = reports_until_the_store(tmp_path)
    nv_file = tmp_path / "nv.json"
    variant = TypeKey.parse(E04).variant
    previous, upload = stored_values(variant), new_values(variant)
    for survived in range(total):
        setup = open_session(EmulatedValve(E04, 1, nv_path=nv_file))[0]
        assert setup.upload(previous).stored  # the valve's stored parameters before the test

        valve = EmulatedValve(E04, 1, nv_path=nv_file)
        session, transport = open_session(valve)
        transport.faults = LinkFaults(die_after=transport.reports_on_link + survived)
        with pytest.raises(DeviceDisconnectedError) as caught:
            session.upload(upload)
        message, step = str(caught.value), caught.value.step
        assert f"upload failed while {STEP_TEXT[step]}" in message
        assert "USB link is down" in message
        store_request_arrived = survived > store_at  # the STORE request is report store_at + 1

        valve.restart()
        after = open_session(valve)[0].download()
        if store_request_arrived:  # the store's answer or the read-back lost: the new set
            assert step == "store" and "may not have completed" in message
            assert after == upload
        else:
            assert after == previous, f"half-written valve after report {survived}"
        reloaded = EmulatedValve(E04, 1, nv_path=nv_file)  # the EEPROM file agrees
        assert open_session(reloaded)[0].download() == after


STEP_TEXT = {"write": "writing the parameters", "verify": "reading them back", "store": "storing"}


def test_every_step_can_fail_and_is_named_with_how_far_the_upload_got(tmp_path):
    total = reports_of_a_full_upload(tmp_path)
    upload = new_values(TypeKey.parse(E04).variant)
    reached: dict[str, list[tuple[int, bool]]] = {}
    for survived in range(0, total, 1):
        valve = EmulatedValve(E04, 1)
        session, transport = open_session(valve)
        transport.faults = LinkFaults(die_after=transport.reports_on_link + survived)
        with pytest.raises(DeviceDisconnectedError) as caught:
            session.upload(upload)
        error = caught.value
        reached.setdefault(error.step, []).append((error.written, error.verified))
    assert set(reached) == {"write", "verify", "store"}
    written = [count for count, _ in reached["write"]]
    assert written == sorted(written) and 0 == written[0] < written[-1] < len(upload)
    assert not any(verified for _, verified in reached["write"])
    assert set(reached["verify"]) == {(len(upload), False)}
    assert set(reached["store"]) == {(len(upload), True)}  # all written and read back equal


def test_after_the_link_died_every_request_fails_at_once(tmp_path):
    session, transport = open_session(EmulatedValve(E04, 1))
    transport.faults = LinkFaults(die_after=transport.reports_on_link)
    for _ in range(2):
        with pytest.raises(DeviceDisconnectedError, match="USB link is down"):
            session.read("LIMTA")


@pytest.fixture
def link():
    valve = EmulatedValve(E04, 1)
    session, transport = open_session(valve)
    return valve, session, transport


def count_writes(valve, monkeypatch) -> list[tuple[int, int]]:
    calls: list[tuple[int, int]] = []
    original = valve.write_bytes

    def counting(index, subindex, data):
        calls.append((index, subindex))
        original(index, subindex, data)

    monkeypatch.setattr(valve, "write_bytes", counting)
    return calls


def test_lost_request_is_repeated(link):
    _valve, session, transport = link
    transport.faults = LinkFaults(drop=frozenset({transport.reports_on_link + 1}))
    assert session.read("SNV") == 1
    assert transport.stats.retries == 1


def test_lost_answer_to_a_write_repeats_the_request_but_not_the_write(link, monkeypatch):
    valve, session, transport = link
    calls = count_writes(valve, monkeypatch)
    transport.faults = LinkFaults(drop=frozenset({transport.reports_on_link + 2}))
    session.write("LIMTA", 1500)
    assert transport.stats.retries == 1
    assert calls == [CATALOGUE["LIMTA"].key]  # the valve answered the repeat from its cache
    assert session.read("LIMTA") == 1500


def test_duplicated_request_is_executed_once_and_the_extra_answer_discarded(link, monkeypatch):
    valve, session, transport = link
    calls = count_writes(valve, monkeypatch)
    transport.faults = LinkFaults(duplicate=frozenset({transport.reports_on_link + 1}))
    session.write("LIMTB", 1600)
    assert calls == [CATALOGUE["LIMTB"].key]
    assert session.read("LIMTB") == 1600
    assert transport.stats.discarded == 1


def test_late_answer_is_discarded_after_the_retry(link):
    valve, session, transport = link
    late = {transport.reports_on_link + 2: 0.4}  # later than the 0.25 s timeout
    transport.faults = LinkFaults(late=late)
    assert session.read_many(["SNV", "AINSETP"]) == {"SNV": 1, "AINSETP": 9}
    assert transport.stats.retries == 1
    valve.advance(0.5)  # the late answer arrives meanwhile
    assert session.read("SNV") == 1
    assert transport.stats.discarded == 1


def test_a_lost_restart_is_not_repeated(link):
    _valve, session, transport = link
    transport.faults = LinkFaults(drop=frozenset({transport.reports_on_link + 1}))
    with pytest.raises(DeviceTimeoutError, match=r"did not answer RESTART within 0.25 s"):
        session.restart()
    assert transport.stats.retries == 0


def test_silent_valve_times_out_after_the_retries(link):
    _valve, session, transport = link
    first = transport.reports_on_link + 1
    transport.faults = LinkFaults(drop=frozenset(range(first, first + 8)))
    with pytest.raises(
        DeviceTimeoutError, match=r"did not answer READ within 0.25 s \(4 attempts\)"
    ):
        session.read("SNV")


class NonsenseTransport(EmulatorTransport):
    """Replaces the valve's next answer with ``junk`` (a valve that answers nonsense)."""

    junk: bytes | None = None

    def _read(self, timeout_s):
        report = super()._read(timeout_s)
        if report is not None and self.junk is not None:
            report, self.junk = self.junk.ljust(64, b"\x00"), None
        return report


@pytest.mark.parametrize(
    ("junk", "message"),
    [
        (b"\x82\x00\x07", r"the valve sent an invalid report \(result code 7\): 82 \w\w 07 00"),
        (b"\x42\x01", r"byte 0 = 0x42 is not an answer"),
        (b"\x82\x00\x00\x05", r"the valve answered 5 values to 1 reads"),
    ],
)
def test_a_valve_answering_nonsense_raises_protocol_error(junk, message):
    transport = NonsenseTransport(EmulatedValve(E04, 1))
    session = UsbSession(transport, "emulator:nonsense")
    seq = transport._seq % 255 + 1  # the answer must carry the request's sequence number
    transport.junk = junk[:1] + bytes([seq]) + junk[2:] if junk[0] == 0x82 else junk
    with pytest.raises(ProtocolError, match=message):
        session.read("SNV")
    assert session.read("SNV") == 1  # the link itself still works


def test_a_valve_that_does_not_know_a_request_is_named(link):
    _valve, session, transport = link
    seq = transport._seq % 255 + 1
    transport.__class__ = NonsenseTransport
    transport.junk = bytes([0xFF, seq, 0x01, 0x01, 0x00, 0x04, 0x05, 0, 0, 0, 0xFF])
    with pytest.raises(ProtocolError, match="did not understand request RELOAD"):
        session.reload()


def test_a_valve_of_another_protocol_version_is_refused(monkeypatch):
    monkeypatch.setattr(usb_firmware, "PROTOCOL_VERSION", 2)
    with pytest.raises(ProtocolError, match="speaks USB protocol version 2; this prm9tool"):
        open_session(EmulatedValve(E04, 1))


def test_cancelled_download(link):
    _valve, session, _transport = link
    cancel = threading.Event()
    cancel.set()
    with pytest.raises(OperationCancelledError, match=r"^download cancelled$"):
        session.download(cancel=cancel)


def test_the_transport_logs_reports_and_retries(link, caplog):
    _valve, session, transport = link
    transport.faults = LinkFaults(drop=frozenset({transport.reports_on_link + 1}))
    with caplog.at_level(logging.DEBUG, logger="prm9tool.device.usb.transport"):
        session.read("SNV")
    lines = [record.getMessage() for record in caplog.records]
    seq = transport._seq
    request = f"TX 02 {seq:02x} 01 18 10 04 01 00"
    sent = [line for line in lines if " TX " in line]
    assert len(sent) == 2 and all(line.startswith(f"emulator:1 {request}") for line in sent)
    assert "emulator:1: no answer to READ, retry 1" in lines
    assert any(f" RX 82 {seq:02x} 00 01 04 01 00 00 00" in line for line in lines)


def test_the_emulated_link_carries_one_report_per_millisecond_each_way(link):
    _valve, session, transport = link
    start = transport.link_time  # simulated: the unpaced link keeps its own clock
    for _ in range(10):
        session.read("SNV")
    # request k+1 leaves in the frame in which answer k arrives: one frame per request
    assert transport.link_time - start == pytest.approx(0.010, abs=0.0002)
