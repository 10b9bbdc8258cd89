"""The CANopen upload with fewer frames and the same guarantees (docs/can-link.md): values the
valve holds already are not sent but still verified; a value the session believed wrongly is
written after all; the store is made sure of by the node's boot-up frame (a valve that restarted
between verify and store is not reported stored) and one read-back."""

from __future__ import annotations

import time

import pytest
from support.can_link_rig import make_link_rig

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.canlink.session import CanopenSession

NODE = 10


@pytest.fixture
def rig(tmp_path, request, data_dir):
    rig = make_link_rig(request.node.name, tmp_path)
    yield rig
    rig.close()


CHANGES = {"LIMTA": 1500, "LIMTB": 1600, "DYNFREQ": 120, "DTAMP": 1000}


def test_only_changed_values_are_sent_and_every_value_is_verified(rig):
    with CanopenSession(rig.options, NODE) as session:
        values = session.download() | CHANGES
        before = session.sdo.requests
        result = session.upload(values)
        requests = session.sdo.requests - before
    assert result.stored and result.written == len(values)  # the valve holds every value
    # its store capability 0x1010/1 (CiA 301), 4 writes, every value read back, the store,
    # one read-back after it
    assert requests == 1 + len(CHANGES) + len(values) + 1 + 1
    assert result.store == "stored with 0x1010"
    stored = rig.stored_set()
    assert all(stored[m] == v for m, v in values.items() if m in stored)


def test_a_value_changed_behind_the_sessions_back_is_written_after_all(rig):
    with CanopenSession(rig.options, NODE) as session:
        values = session.download() | CHANGES
        rig.valve.write(*CATALOGUE["POSKP"].key, int(values["POSKP"]) + 7)  # another master
        result = session.upload(values)
    assert (result.stored, result.failed_step) == (True, None)
    assert rig.stored_set()["POSKP"] == values["POSKP"]
    assert rig.working("POSKP") == values["POSKP"]


def test_a_valve_that_restarts_between_verify_and_store_is_not_reported_stored(tmp_path, data_dir):
    rig = make_link_rig("restart-before-store", tmp_path)
    rig.valve.start()  # real time: the restart's boot-up goes out on the bus
    try:
        with CanopenSession(rig.options, NODE, timeout_s=0.2) as session:
            stored_before = rig.stored_set()
            values = session.download() | CHANGES
            store = session.store

            def brown_out_then_store() -> None:
                rig.valve.nmt_event("reset_node")  # power dip after the verify
                deadline = time.monotonic() + 5
                while rig.valve.status().nmt_state != "pre-operational":
                    assert time.monotonic() < deadline
                    time.sleep(0.02)
                store()

            session.store = brown_out_then_store  # type: ignore[method-assign]
            result = session.upload(values)
        assert (result.stored, result.verified, result.failed_step) == (False, True, "store")
        assert "restarted (its boot-up frame)" in (result.failure or "")
        after = rig.stored_set()  # it stored its previous set (entries not stored before: defaults)
        for mnemonic in CHANGES:
            assert after[mnemonic] == stored_before.get(mnemonic, CATALOGUE[mnemonic].default)
            assert after[mnemonic] != values[mnemonic]
    finally:
        rig.valve.stop()
        rig.close()
