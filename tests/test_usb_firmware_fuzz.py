"""Random reports thrown at the emulated valve's USB firmware handler.

The firmware must never raise, must answer every report with one well-formed 64-byte answer
carrying the request's sequence number (an error answer for anything it cannot parse), and
junk must never reach the non-volatile memory. "Junk" is every report except the valid store
commands themselves (STORE "save", RESTORE_FACTORY "load", or a CiA 301 write of 0x1010 /
0x1011): Hypothesis mines the signatures from the source and does build those. Deterministic:
no paced thread, no waiting. 2000 examples in every run (pinned here, not left to the profile:
the issue asks for at least 2000 in CI, and CI need not set ``CI``); about 3 s.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.usb_firmware import UsbFirmware
from prm9tool.device.usb.protocol import (
    ERROR_OP,
    AbortReply,
    MalformedReportError,
    Op,
    RestoreFactory,
    SegmentWrite,
    Store,
    StreamData,
    WriteEntries,
    decode_request,
    decode_response,
)
from prm9tool.errors import AbortCode

_DIR = Path(tempfile.mkdtemp(prefix="prm9-fuzz-"))
NV_FILE = _DIR / "nv.json"
VALVE = EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA", 99, nv_path=NV_FILE)
FIRMWARE = UsbFirmware.of(VALVE)
FILE_KEYS = [p.key for p in CATALOGUE.file_parameters(VALVE.variant)]
STORED_AT_START = {key: VALVE.read(*key) for key in FILE_KEYS}

any_bytes = st.binary(min_size=0, max_size=80)
full_reports = st.binary(min_size=64, max_size=64)
known_opcode = st.builds(
    lambda op, seq, body: (bytes([op, seq]) + body).ljust(64, b"\x00")[:64],
    st.sampled_from([int(op) for op in Op]),
    st.integers(0, 255),
    st.binary(max_size=62),
)
reports = st.lists(st.one_of(any_bytes, full_reports, known_opcode), min_size=1, max_size=6)


NV_OBJECTS = (0x1010, 0x1011)  # CiA 301 store / restore parameters


def is_store_command(report: bytes) -> bool:
    """True for a valid request that writes the non-volatile memory by design."""
    try:
        _, request = decode_request(report)
    except MalformedReportError:
        return False
    if isinstance(request, (Store, RestoreFactory)):
        return True
    if isinstance(request, WriteEntries):
        return any(index in NV_OBJECTS for index, _, _ in request.entries)
    return isinstance(request, SegmentWrite) and request.index in NV_OBJECTS


def check_answer(report: bytes, answer: bytes) -> None:
    """One well-formed answer to ``report``; an error answer if the request is malformed."""
    assert len(answer) == 64
    decoded = decode_response(answer)
    assert not isinstance(decoded, StreamData)
    op, seq, response = decoded
    assert seq == (report[1] if len(report) > 1 else 0)
    try:
        request_seq, request = decode_request(report)
    except MalformedReportError:
        assert isinstance(response, AbortReply)
        assert response.code == AbortCode.INVALID_COMMAND
        assert op == ERROR_OP or op == report[0]
        return
    assert (op, seq) == (request.op, request_seq)


@settings(max_examples=2000)
@given(reports)
def test_random_reports_get_well_formed_answers_and_never_touch_stored_parameters(batch):
    assume(not any(is_store_command(report) for report in batch))
    for report in batch:
        check_answer(report, FIRMWARE.handle(report))
    assert FIRMWARE.internal_errors == 0
    assert not NV_FILE.exists(), "junk reached the non-volatile memory"


def test_stored_parameters_survive_the_fuzzing_and_a_restart():
    # runs after the hypothesis test in file order; alone it is a plain restart check
    for report in (b"", b"\x06\x01save", b"\x07" * 64, bytes(64)):
        FIRMWARE.handle(report)
    VALVE.restart()
    assert {key: VALVE.read(*key) for key in FILE_KEYS} == STORED_AT_START
    assert not NV_FILE.exists()
