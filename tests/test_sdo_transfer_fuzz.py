"""The master's SDO client (prm9tool.device.canlink.sdo_transfer) fed random answer
sequences (hypothesis, issue 29): it returns exactly the value a clean transfer carries, or
raises a typed error — within a bound of frames and of memory — whatever the node sends."""

from __future__ import annotations

import struct
import tracemalloc
from dataclasses import dataclass, field

from hypothesis import given
from hypothesis import strategies as st

from prm9tool.device.canlink.sdo_transfer import SdoTransfer, SdoTransferError
from prm9tool.errors import DeviceTimeoutError, SdoAbortError

INDEX, SUB = 0x100A, 0
MAX_BYTES = 64


@dataclass
class ScriptedPort:
    """Answers each request with the next frame of ``answers``; then none (a timeout)."""

    answers: list[bytes]
    sent: list[bytes] = field(default_factory=list)

    def send(self, data: bytes) -> None:
        self.sent.append(data)

    def receive(self, _timeout_s: float) -> bytes | None:
        return self.answers.pop(0) if self.answers else None

    def drain(self) -> int:
        return 0


def clean_upload(value: bytes, declare: bool, chunks: list[int]) -> list[bytes]:
    """The server's frames of a correct segmented upload of ``value`` (segment lengths from
    ``chunks``, each 1…7, the last one what is left)."""
    head = 0x41 if declare else 0x40
    size = len(value) if declare else 0
    frames = [struct.pack("<BHBI", head, INDEX, SUB, size)]
    pos, toggle, i = 0, 0, 0
    while True:
        n = min(chunks[i % len(chunks)], len(value) - pos)
        i += 1
        chunk = value[pos : pos + n]
        pos += n
        last = pos >= len(value)
        frames.append(bytes([toggle | ((7 - n) << 1) | last]) + chunk.ljust(7, b"\0"))
        toggle ^= 0x10
        if last:
            return frames


def run(frames: list[bytes]) -> tuple[object, ScriptedPort]:
    port = ScriptedPort(list(frames))
    try:
        outcome: object = SdoTransfer(port, 11).upload(INDEX, SUB, MAX_BYTES, 0.01)
    except (SdoAbortError, SdoTransferError, DeviceTimeoutError) as exc:
        outcome = exc
    return outcome, port


def bounded(port: ScriptedPort) -> None:
    requests = [f for f in port.sent if f[0] != 0x80]
    # the initiate, then segments of at least one byte each up to the bound, and the last
    assert len(requests) <= MAX_BYTES + 2
    aborts = [f for f in port.sent if f[0] == 0x80]
    assert len(aborts) <= 1 and all(f[1:4] == b"\x0a\x10\x00" for f in aborts)


@given(
    st.binary(min_size=5, max_size=MAX_BYTES),
    st.booleans(),
    st.lists(st.integers(1, 7), min_size=1, max_size=5),
)
def test_a_clean_upload_returns_exactly_the_value(value, declare, chunks):
    outcome, port = run(clean_upload(value, declare, chunks))
    assert outcome == value
    bounded(port)


frame = st.binary(min_size=0, max_size=9)
mutation = st.tuples(
    st.integers(0, 200),
    st.sampled_from(["replace", "insert", "drop", "flip"]),
    frame,
    st.integers(0, 7),
)


@given(
    st.binary(min_size=5, max_size=MAX_BYTES),
    st.booleans(),
    st.lists(st.integers(1, 7), min_size=1, max_size=5),
    st.lists(mutation, max_size=4),
    st.lists(frame, max_size=30),
)
def test_any_answer_sequence_gives_an_exact_value_or_a_typed_error(
    value, declare, chunks, mutations, tail
):
    frames = clean_upload(value, declare, chunks)
    for where, how, data, bit in mutations:
        at = where % (len(frames) + 1)
        if how == "insert":
            frames.insert(at, data)
        elif at < len(frames) and how == "replace":
            frames[at] = data
        elif at < len(frames) and how == "drop":
            del frames[at]
        elif at < len(frames) and frames[at]:
            frames[at] = bytes([frames[at][0] ^ (1 << bit)]) + frames[at][1:]
    frames += tail
    tracemalloc.start()
    try:
        outcome, port = run(frames)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    bounded(port)
    assert peak < 64 * 1024  # the data held is bounded by MAX_BYTES, not by what the node sends
    if isinstance(outcome, bytes):
        assert len(outcome) <= MAX_BYTES
        declared = next((f for f in frames[:1] if len(f) == 8 and f[0] == 0x41), None)
        if declared is not None and frames[0][1:4] == b"\x0a\x10\x00":
            assert len(outcome) == struct.unpack_from("<I", declared, 4)[0]
        if frames == clean_upload(value, declare, chunks):
            assert outcome == value
    else:
        assert isinstance(outcome, (SdoAbortError, SdoTransferError, DeviceTimeoutError))


@given(
    st.lists(
        st.binary(min_size=8, max_size=8).map(lambda b: bytes([b[0] & 0xEF]) + b[1:]), max_size=400
    )
)
def test_a_node_that_never_ends_is_stopped_at_the_size_bound(segments):
    frames = [struct.pack("<BHBI", 0x40, INDEX, SUB, 0)]
    toggle = 0
    for raw in segments:  # segments with the right toggle, never the last
        frames.append(bytes([(raw[0] & 0x0E) | toggle]) + raw[1:])
        toggle ^= 0x10
    frames += [bytes([toggle]) + b"x" * 7] * 20
    outcome, port = run(frames)
    bounded(port)
    assert isinstance(outcome, (SdoTransferError, DeviceTimeoutError))
