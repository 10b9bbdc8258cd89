"""The CANopen session's parts on their own, without a bus (issue 28: modules cut at seams):
the SDO entry reads and writes (canlink/entries.py) and the measuring-point stream's demand
channel (canlink/stream.py)."""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.canlink.entries import SdoEntries
from prm9tool.device.canlink.sdo import MISSING
from prm9tool.device.canlink.stream import CanStream
from prm9tool.device.records import RefusedError
from prm9tool.errors import SdoAbortError

LACKED, REFUSED = min(MISSING), 0x06010002  # no such object; read-only object (CiA 301)


class FakeSdo:
    """An SDO channel over a dict {(index, subindex): bytes}; ``refuse``: (index, sub) → code."""

    def __init__(self, objects: dict[tuple[int, int], bytes], refuse: dict | None = None):
        self.objects, self.refuse, self.written = objects, refuse or {}, []

    def _check(self, index: int, sub: int) -> None:
        if (index, sub) in self.refuse:
            raise SdoAbortError(index, sub, self.refuse[index, sub])

    def upload(self, index: int, sub: int) -> bytes:
        self._check(index, sub)
        return self.objects[index, sub]

    def download(self, index: int, sub: int, data: bytes) -> None:
        self._check(index, sub)
        self.written.append((index, sub, data))
        self.objects[index, sub] = data


def _upload_state(snapshot=None):
    return SimpleNamespace(known={}, touched=[], snapshot=snapshot)


def _parts(*mnemonics: str):
    return [CATALOGUE[m] for m in mnemonics]


def _entries(objects, refuse=None, snapshot=None):
    sdo, unavailable, state = FakeSdo(objects, refuse), set(), _upload_state(snapshot)
    return SdoEntries(lambda: sdo, unavailable, state), sdo, unavailable, state


def test_a_lacked_object_is_noted_unavailable_and_left_out_of_reads_and_writes():
    kp, ki = _parts("POSKP", "POSKI")
    objects = {kp.key: kp.dtype.encode(300)}
    entries, sdo, unavailable, state = _entries(objects, {ki.key: LACKED})
    assert entries.read([kp, ki], None, None) == {"POSKP": 300}
    assert unavailable == {"POSKI"} and state.known == {"POSKP": 300}
    assert entries.write([kp, ki], {"POSKP": 310, "POSKI": 5}, None, None) == 1
    assert [w[:2] for w in sdo.written] == [kp.key]  # the lacked object is not asked again
    assert state.known == {"POSKP": 310} and state.touched == ["POSKP"]


def test_another_abort_is_the_reads_answer_and_ends_a_write_with_the_count_done():
    kp, ki = _parts("POSKP", "POSKI")
    objects = {kp.key: kp.dtype.encode(300), ki.key: ki.dtype.encode(5)}
    entries, _sdo, unavailable, state = _entries(objects, {ki.key: REFUSED})
    outcome = entries.read([ki], None, None)["POSKI"]
    assert isinstance(outcome, SdoAbortError) and outcome.code == REFUSED and not unavailable
    with pytest.raises(RefusedError) as refused:
        entries.write([kp, ki], {"POSKP": 310, "POSKI": 6}, None, None)
    assert refused.value.mnemonic == "POSKI" and refused.value.done == 1
    assert "POSKI" not in state.known  # its value is unknown after the refused write


def test_during_an_upload_a_value_the_valve_holds_is_counted_but_not_sent():
    kp, ki = _parts("POSKP", "POSKI")
    objects = {kp.key: kp.dtype.encode(300), ki.key: ki.dtype.encode(5)}
    entries, sdo, _unavailable, _state = _entries(objects, snapshot={"POSKP": 300, "POSKI": 5})
    assert entries.write([kp, ki], {"POSKP": 300, "POSKI": 6}, None, None) == 2
    assert [w[:2] for w in sdo.written] == [ki.key]


def test_the_streams_demand_channel_is_the_setpoint_the_tool_sends_and_nothing_else():
    stream = CanStream(lambda: None, lambda: None)  # type: ignore[arg-type,return-value]
    assert math.isnan(stream._demand("position_setpoint"))  # the tool sends none
    stream.sent_setpoint = ("position_setpoint", 1234.0)
    assert stream._demand("position_setpoint") == 1234.0
    assert math.isnan(stream._demand("process_setpoint"))  # another key: not this one
    assert stream.read().shape == (0, 1) and stream.lost == 0 and stream.achieved_hz == 0.0
    stream.stop()  # none runs: nothing to stop
    assert stream.source == ""
