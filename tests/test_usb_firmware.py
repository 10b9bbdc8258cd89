"""The emulated valve's USB firmware handler, report in, report out (no transport)."""

from __future__ import annotations

import pytest

from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.usb_firmware import UsbFirmware
from prm9tool.device.usb.protocol import (
    AbortReply,
    Identify,
    IdentifyReply,
    Op,
    ReadEntries,
    SegmentWrite,
    SegmentWriteReply,
    decode_response,
    encode_request,
)
from prm9tool.errors import AbortCode

E02 = "PRM9-06.3Z11/30-24E02S02"


def frame(text: str) -> bytes:
    return bytes.fromhex(text).ljust(64, b"\x00")


@pytest.fixture
def valve():
    return EmulatedValve(E02, 0x1267, "0.35.16")


@pytest.fixture
def firmware(valve):
    return UsbFirmware.of(valve)


def test_one_firmware_per_valve(valve, firmware):
    assert UsbFirmware.of(valve) is firmware


def test_identify_answer_byte_for_byte(firmware):
    answer = firmware.handle(encode_request(5, Identify()))
    key = E02.encode()
    expected = bytes([0x81, 5, 0, 1]) + (0x1267).to_bytes(4, "little") + b"\x88\x13"
    expected += bytes([len(key)]) + key + b"\x070.35.16"
    assert answer == expected.ljust(64, b"\x00")


def test_read_serial_and_an_unknown_object(firmware):
    answer = firmware.handle(frame("02 06 02 18 10 04 01 34 12 00 01"))
    assert answer == frame("82 06 00 02 04 67 12 00 00 ff 00 00 02 06")


def test_long_value_in_a_read_asks_for_a_segmented_read(firmware, valve, monkeypatch):
    monkeypatch.setitem(valve.firmware.od.getters, (0x1008, 0), lambda: "x" * 70)  # name: 70 bytes
    answer = decode_response(firmware.handle(encode_request(1, ReadEntries(((0x1008, 0),)))))
    assert answer[2].values == (int(AbortCode.LENGTH_TOO_HIGH),)


def test_write_stops_at_the_first_refusal(firmware, valve):
    # LIMTA = 2000 (fine), then SNV (read-only), then LIMTB = 2100 (never reached)
    report = frame("03 07 03 04 20 02 01 02 d0 07 18 10 04 01 04 05 00 00 00 04 20 03 01 02 34 08")
    answer = decode_response(firmware.handle(report))
    assert answer == (Op.WRITE, 7, AbortReply(AbortCode.READ_ONLY, 0x1018, 4, 1))
    assert (valve.read(0x2004, 2), valve.read(0x2004, 3)) == (2000, 2400)


def test_a_repeated_report_is_answered_but_not_executed_again(firmware, valve, monkeypatch):
    calls = []
    monkeypatch.setattr(valve, "write_bytes", lambda i, s, d: calls.append((i, s, d)))
    report = frame("03 09 01 04 20 02 01 02 d0 07")
    assert firmware.handle(report) == firmware.handle(report)
    assert len(calls) == 1
    firmware.handle(frame("03 0a 01 04 20 02 01 02 d0 07"))  # a new seq is a new request
    assert len(calls) == 2


def segment(seq: int, total: int, offset: int, data: bytes) -> bytes:
    return encode_request(seq, SegmentWrite(0x2041, 0, total, offset, data))


def test_segmented_write_assembles_the_value(firmware, valve, monkeypatch):
    written = []
    monkeypatch.setattr(valve, "write_bytes", lambda i, s, d: written.append((i, s, d)))
    value = bytes(range(100))
    first = decode_response(firmware.handle(segment(1, 100, 0, value[:54])))
    last = decode_response(firmware.handle(segment(2, 100, 54, value[54:])))
    assert first[2] == SegmentWriteReply(54, False)
    assert last[2] == SegmentWriteReply(100, True)
    assert written == [(0x2041, 0, value)]


@pytest.mark.parametrize(
    ("pieces", "code"),
    [
        ([(10, 4, b"abc")], AbortCode.TOGGLE_BIT),  # no first segment
        ([(10, 0, b"abc"), (10, 5, b"de")], AbortCode.TOGGLE_BIT),  # out of sequence
        ([(10, 0, b"abc"), (11, 3, b"de")], AbortCode.TOGGLE_BIT),  # another total
        ([(2, 0, b"abc")], AbortCode.LENGTH_TOO_HIGH),  # more data than announced
        ([(2000, 0, b"abc")], AbortCode.LENGTH_TOO_HIGH),  # beyond 1024 bytes
    ],
)
def test_segmented_write_errors(firmware, pieces, code):
    answers = [
        decode_response(firmware.handle(segment(n + 1, *piece))) for n, piece in enumerate(pieces)
    ]
    assert answers[-1][2] == AbortReply(code, 0x2041, 0)


def test_the_string_parameters_are_read_only(firmware):
    answer = decode_response(firmware.handle(segment(1, 3, 0, b"abc")))
    assert answer[2].code == AbortCode.READ_ONLY


def test_store_writes_the_eeprom_file(tmp_path):
    valve = EmulatedValve(E02, 2, nv_path=tmp_path / "nv.json")
    firmware = UsbFirmware.of(valve)
    firmware.handle(frame("03 01 01 04 20 02 01 02 d0 07"))  # LIMTA = 2000 mA
    assert firmware.handle(frame("06 02 73 61 76 65")) == frame("86 02 00")
    assert (tmp_path / "nv.json").exists()
    restarted = EmulatedValve(E02, 2, nv_path=tmp_path / "nv.json")
    assert restarted.read(0x2004, 2) == 2000


def test_restart_answers_first_then_forgets_the_session_state(firmware, valve):
    firmware.handle(frame("0a 01 01 00 01 13"))  # stream the supply voltage
    assert firmware.streaming
    assert firmware.handle(frame("08 02 62 6f 6f 74")) == frame("88 02 00")
    assert not firmware.streaming
    assert valve.status().booting


def test_a_duplicated_restart_executes_once(firmware, valve):
    restarts = []
    valve.add_restart_listener(lambda: restarts.append(valve.time))
    valve.advance(3.0)
    report = frame("08 07 62 6f 6f 74")
    assert firmware.handle(report) == frame("88 07 00")
    valve.advance(0.5)
    assert firmware.handle(report) == frame("88 07 00")  # the same report again: answered only
    assert len(restarts) == 1 and valve.time > 0.4
    firmware.handle(frame("08 08 62 6f 6f 74"))  # a new seq is a new request
    assert len(restarts) == 2


@pytest.mark.parametrize(
    ("firmware_text", "sent"),
    [
        ("1.0.0-" + "x" * 40, "1.0.0-" + "x" * 19),  # cut to 25 bytes
        ("1.0.0-" + "é" * 20, "1.0.0-" + "é" * 9),  # never in the middle of a character
        ("1.0.0", "1.0.0"),
    ],
)
def test_a_long_firmware_text_is_cut_to_the_room_identify_has(firmware_text, sent):
    key = "PRM9-06.3Z11/30-24E04S02-CA"
    firmware = UsbFirmware.of(EmulatedValve(key, 7, firmware_text))
    _op, _seq, reply = decode_response(firmware.handle(encode_request(3, Identify())))
    assert (reply.type_key, reply.firmware) == (key, sent)
    assert firmware.internal_errors == 0


def test_an_answer_that_does_not_fit_a_report_is_a_general_error_not_an_exception(
    firmware, monkeypatch
):
    too_long = IdentifyReply(1, 1, "K" * 70, "1.0")
    monkeypatch.setattr(firmware, "_dispatch", lambda request: too_long)
    answer = firmware.handle(encode_request(4, Identify()))
    assert decode_response(answer) == (Op.IDENTIFY, 4, AbortReply(AbortCode.GENERAL_ERROR))
    assert firmware.internal_errors == 1


def test_a_set_the_catalogue_rejects_is_not_stored(tmp_path):
    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA", 77, nv_path=tmp_path / "nv.json")
    firmware = UsbFirmware.of(valve)
    # SETPLINXA = 10000: point A above point B (-12288), the curve no longer goes one way
    assert firmware.handle(frame("03 01 01 00 20 01 01 02 10 27")) == frame("83 01 00 01")
    # STORE: abort 0x08000020 at 0x1010/1 (cannot be stored)
    assert firmware.handle(frame("06 02 73 61 76 65")) == frame("86 02 01 20 00 00 08 10 10 01 ff")
    assert valve.read(0x2000, 1) == 10000  # the working value stays until reloaded
    valve.restart()
    assert valve.read(0x2000, 1) == -16384  # the stored set is the one before
    assert not (tmp_path / "nv.json").exists()


def test_the_firmware_listens_to_the_1_ms_task_only_while_it_streams(firmware, valve):
    """Without a listener the compiled kernel passes the 1 ms tasks that change nothing
    itself (fasttick); a USB link that does not stream must not take that away."""
    listeners = valve.firmware.cycle_listeners
    assert listeners == []
    firmware.handle(frame("0a 01 01 00 01 13"))  # stream the supply voltage
    assert valve.firmware.cycle_listeners == [firmware._on_cycle]
    valve.advance(0.02)
    assert firmware.outbox  # the stream still runs from the 1 ms task
    firmware.handle(frame("0a 02 01 00 01 13"))  # a new stream replaces the old one
    assert len(valve.firmware.cycle_listeners) == 1
    firmware.handle(frame("0b 03"))  # STREAM_STOP
    assert valve.firmware.cycle_listeners == []
    firmware.handle(frame("0a 04 01 00 01 13"))
    firmware.handle(frame("08 05 62 6f 6f 74"))  # a restart ends the stream too
    assert valve.firmware.cycle_listeners == []
