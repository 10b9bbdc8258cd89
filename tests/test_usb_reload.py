"""RELOAD: after a failed upload the valve runs on its stored parameters again, no restart."""

from __future__ import annotations

import threading

import pytest
from support.valve_sets import changed_set

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.usb_firmware import UsbFirmware
from prm9tool.device.records import OperationCancelledError
from prm9tool.device.usb.protocol import (
    Done,
    Op,
    Reload,
    Store,
    decode_request,
    decode_response,
    encode_request,
    encode_response,
)
from prm9tool.device.usb.session import UsbSession
from prm9tool.device.usb.transport.emulator import EmulatorTransport, LinkFaults
from prm9tool.errors import AbortCode, DeviceDisconnectedError, DeviceTimeoutError, SdoAbortError

E04 = "PRM9-06.3Z11/30-24E04S02-CA"


def frame(text: str) -> bytes:
    return bytes.fromhex(text).ljust(64, b"\x00")


def test_reload_golden_frames():
    assert encode_request(0x21, Reload()) == frame("0c 21 72 76 72 74")
    assert decode_request(frame("0c 21 72 76 72 74")) == (0x21, Reload())
    assert encode_response(Op.RELOAD, 0x21, Done()) == frame("8c 21 00")
    assert decode_response(frame("8c 21 00")) == (Op.RELOAD, 0x21, Done())
    assert Reload().idempotent


def test_reload_needs_its_signature(tmp_path):
    valve = EmulatedValve(E04, 3)
    valve.write(*CATALOGUE["LIMTA"].key, 1234)
    answer = UsbFirmware.of(valve).handle(frame("0c 01 72 76 72 75"))
    assert answer == frame("8c 01 01 01 00 04 05 00 00 00 ff")  # malformed: not executed
    assert valve.read(*CATALOGUE["LIMTA"].key) == 1234


def file_values(valve: EmulatedValve) -> dict[str, int | str]:
    """The working (RAM) values of the valve's file parameters."""
    return {p.mnemonic: valve.read(*p.key) for p in CATALOGUE.file_parameters(valve.variant)}


def new_values() -> dict[str, int | str]:
    """A complete parameter set that differs from the factory defaults in every entry."""
    variant = EmulatedValve(E04, 99).variant
    return changed_set(variant)


def stored_values() -> dict[str, int | str]:
    """Another set: the factory defaults with every other entry changed."""
    variant = EmulatedValve(E04, 99).variant
    values = {p.mnemonic: p.default_for(variant) for p in CATALOGUE.file_parameters(variant)}
    changed = new_values()
    for mnemonic in list(values)[::2]:
        values[mnemonic] = changed[mnemonic]
    return values


class Rig:
    """A running valve (past boot, setpoint applied) with a stored set that is not factory."""

    def __init__(self, tmp_path, transport_class=EmulatorTransport) -> None:
        self.valve = EmulatedValve(E04, 4711, nv_path=tmp_path / "nv.json")
        self.valve.advance(3.0)
        self.transport = transport_class(self.valve)
        self.session = UsbSession(self.transport, "emulator:reload")
        self.stored = stored_values()
        assert self.session.upload(self.stored).stored
        self.valve.set_input("setpoint", 4.0)
        self.valve.advance(0.2)
        self.restarts: list[int] = []
        self.valve.add_restart_listener(lambda: self.restarts.append(1))
        self.upload = new_values()

    def snapshot(self) -> tuple[float, object, bool]:
        return self.valve.time, self.valve.device_state, self.valve.status().booting

    def check_back_on_the_stored_set(self, before: tuple[float, object, bool]) -> None:
        """Working values = stored ones, with no restart: time went on, same state."""
        assert file_values(self.valve) == self.stored
        time_before, state_before, _ = before
        time_after, state_after, booting = self.snapshot()
        assert self.restarts == []
        assert time_after > time_before  # a restart would have reset the valve's clock
        assert (state_after, booting) == (state_before, False)


def test_session_reload_discards_unstored_values(tmp_path):
    rig = Rig(tmp_path)
    before = rig.snapshot()
    rig.session.write_many({"LIMTA": 1500, "DTAMP": 1000})
    assert rig.session.read("LIMTA") == 1500
    rig.session.reload()
    rig.valve.advance(0.01)
    rig.check_back_on_the_stored_set(before)


def test_refused_value_reloads_the_stored_set(tmp_path, monkeypatch):
    rig = Rig(tmp_path)
    original = rig.valve.write_bytes

    def refuse_dither(index, subindex, data):
        if (index, subindex) == CATALOGUE["DTAMP"].key:
            raise SdoAbortError(index, subindex, AbortCode.CANNOT_STORE_DEVICE_STATE)
        original(index, subindex, data)

    monkeypatch.setattr(rig.valve, "write_bytes", refuse_dither)
    before = rig.snapshot()
    result = rig.session.upload(rig.upload)
    assert (result.failed_step, result.reloaded, result.reload_error) == ("write", True, None)
    assert result.written > 0  # parameters before DTAMP had been written
    rig.check_back_on_the_stored_set(before)


class CorruptingTransport(EmulatorTransport):
    """Flips a bit in the first value of every READ answer once armed."""

    armed = False

    def _read(self, timeout_s):
        report = super()._read(timeout_s)
        if self.armed and report is not None and report[0] == 0x82 and report[3] > 0:
            report = report[:5] + bytes([report[5] ^ 0x01]) + report[6:]
        return report


def test_verify_mismatch_reloads_the_stored_set(tmp_path):
    rig = Rig(tmp_path, CorruptingTransport)
    rig.transport.armed = True
    before = rig.snapshot()
    result = rig.session.upload(rig.upload)
    assert (result.failed_step, result.stored, result.reloaded) == ("verify", False, True)
    assert result.mismatches
    rig.check_back_on_the_stored_set(before)


@pytest.mark.parametrize("at", ["write", "verify", "store"])
def test_cancel_reloads_the_stored_set(tmp_path, at):
    rig = Rig(tmp_path)
    cancel = threading.Event()

    def progress(done, total, step):
        if step == at or (at == "store" and done == total - 1):
            cancel.set()

    before = rig.snapshot()
    with pytest.raises(OperationCancelledError) as caught:
        rig.session.upload(rig.upload, progress=progress, cancel=cancel)
    assert "nothing was stored; the valve's working parameters were reset to its stored ones" in (
        str(caught.value)
    )
    rig.check_back_on_the_stored_set(before)


def test_timeout_while_writing_reloads_once_the_link_answers_again(tmp_path):
    rig = Rig(tmp_path)
    first = rig.transport.reports_on_link + 3  # the second WRITE request and its 3 repeats
    rig.transport.faults = LinkFaults(drop=frozenset(range(first, first + 4)))
    before = rig.snapshot()
    with pytest.raises(DeviceTimeoutError) as caught:
        rig.session.upload(rig.upload)
    assert caught.value.step == "write" and caught.value.reloaded
    assert "working parameters were reset to its stored ones" in str(caught.value)
    rig.check_back_on_the_stored_set(before)


def test_dead_link_says_that_the_reload_failed_too(tmp_path):
    rig = Rig(tmp_path)
    rig.transport.faults = LinkFaults(die_after=rig.transport.reports_on_link + 3)
    with pytest.raises(DeviceDisconnectedError) as caught:
        rig.session.upload(rig.upload)
    message = str(caught.value)
    assert caught.value.step == "write" and not caught.value.reloaded
    assert "nothing was stored; resetting its working parameters to the stored ones failed" in (
        message
    )
    assert "restart the valve, hydraulics off" in message
    assert file_values(rig.valve) != rig.stored  # half written: the valve needs the restart
    rig.valve.restart()
    assert file_values(rig.valve) == rig.stored


def test_reload_that_is_refused_is_reported_in_the_result(tmp_path, monkeypatch):
    rig = Rig(tmp_path, CorruptingTransport)
    rig.transport.armed = True

    def broken_reload():
        raise SdoAbortError(0, 0, AbortCode.GENERAL_ERROR)

    monkeypatch.setattr(rig.valve, "reload", broken_reload)
    result = rig.session.upload(rig.upload)
    assert (result.failed_step, result.reloaded) == ("verify", False)
    assert "abort 0x08000000" in result.reload_error


def test_refused_store_reloads_the_stored_set_and_says_so(tmp_path, monkeypatch):
    rig = Rig(tmp_path)

    def refuse_store():
        raise SdoAbortError(0x1010, 1, AbortCode.CANNOT_STORE)

    monkeypatch.setattr(rig.valve, "store", refuse_store)
    before = rig.snapshot()
    result = rig.session.upload(rig.upload)
    assert (result.failed_step, result.verified, result.stored) == ("store", True, False)
    assert result.written == len(rig.upload)  # every value was written and read back
    assert result.reloaded and "refused to store" in result.failure
    assert "0x08000020" in result.failure
    rig.check_back_on_the_stored_set(before)


class BrownOutBeforeStore(EmulatorTransport):
    """The valve power-cycles just before it receives the STORE request, once armed."""

    armed = False

    def request(self, message):
        if self.armed and isinstance(message, Store):
            self.valve.restart()
        return super().request(message)


def test_a_restart_just_before_the_store_is_not_reported_as_stored(tmp_path):
    rig = Rig(tmp_path, BrownOutBeforeStore)
    rig.transport.armed = True
    result = rig.session.upload(rig.upload)
    assert (result.failed_step, result.verified, result.stored) == ("store", True, False)
    assert result.mismatches and "restarted" in result.failure
    assert file_values(rig.valve) == rig.stored  # the old set, working and stored
    rig.valve.restart()
    assert file_values(rig.valve) == rig.stored
