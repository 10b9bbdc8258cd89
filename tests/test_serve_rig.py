"""The pieces of ``--serve-emulator`` as a PLC rig: fault injection by stdin commands, one paced
thread for many valves, the lateness report, the EDS's LSS entry and the EMCY named by cause."""

from __future__ import annotations

import io
import time

import pytest
from support.waiting import wait_for

from prm9tool.cli import serve_input
from prm9tool.device.emulator import EmulatedValve, Fault
from prm9tool.device.emulator.paced_group import PacedGroup
from prm9tool.device.emulator.pacing import LATE_S, Pacer
from prm9tool.files.eds import export_eds

E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"


@pytest.fixture
def valves():
    served = [EmulatedValve(E02_CA, serial) for serial in (8001, 8002)]
    for valve in served:
        valve.advance(2.0)
    return served


def test_stdin_commands_inject_and_clear_a_fault_and_say_what_they_did(valves):
    assert serve_input.execute("inject node:10 COIL_A_OPEN", valves[:1]) == (
        "COIL_A_OPEN injected on serial 8001"
    )
    assert valves[0].injected() == {Fault.COIL_A_OPEN}
    assert serve_input.execute("clear 8001 coil_a_open", valves) == (
        "COIL_A_OPEN cleared on serial 8001"
    )
    assert serve_input.execute("inject all SUPPLY_LOW", valves).endswith("serial 8001, 8002")
    assert "serial 8002: SUPPLY_LOW" in serve_input.execute("faults", valves)


@pytest.mark.parametrize(
    ("line", "answer"),
    [
        ("inject 8001 BROKEN", "inject: no fault 'BROKEN'; faults are: COIL_A_OPEN"),
        ("inject 9999 COIL_A_OPEN", "inject: no served valve '9999'"),
        ("explode", "not understood: 'explode' (commands: inject"),
    ],
)
def test_a_command_that_cannot_be_done_says_why_and_changes_nothing(valves, line, answer):
    assert serve_input.execute(line, valves).startswith(answer)
    assert not any(v.injected() for v in valves)


def test_listen_reads_lines_until_the_stream_ends(valves):
    said: list[str] = []
    serve_input.listen(io.StringIO("inject 8002 COIL_B_OPEN\n\n"), valves, said.append)
    wait_for(lambda: said == ["COIL_B_OPEN injected on serial 8002"])


def test_one_paced_group_runs_every_valve_in_real_time(valves):
    group = PacedGroup(valves)
    group.start()
    try:
        assert all(v.running for v in valves)  # the watches judge wall-clock time
        before = [v.time for v in valves]
        time.sleep(0.3)
        ran = [v.time - t for v, t in zip(valves, before, strict=True)]
    finally:
        group.stop()
    assert not any(v.running for v in valves)
    assert all(seconds > 0.1 for seconds in ran), ran  # both advanced, in one thread


def test_the_pacer_counts_how_often_and_how_far_it_fell_behind():
    now = [0.0]
    pacer = Pacer(0.0002, clock=lambda: now[0])
    now[0] = 2 * LATE_S  # a stall: behind by twice the limit
    pacer.done(pacer.due())
    now[0] += 0.001
    pacer.due()
    late = pacer.take_lateness()
    assert (late.episodes, late.dropped_cycles) == (1, 0)
    assert late.worst_s == pytest.approx(2 * LATE_S)
    assert pacer.take_lateness().episodes == 0  # reported once


def test_the_eds_says_the_valve_supports_lss():
    assert "LSS_Supported=1" in export_eds(E02_CA).splitlines()


def test_each_emcy_is_told_with_the_error_that_raised_it(valves):
    valve = valves[0]
    told: list[tuple[int, str | None]] = []
    valve.add_error_cause_listener(lambda code, _reg, kind: told.append((code, kind and kind.text)))
    valve.nmt_event("operational")
    valve.nmt_event("sync_error")
    valve.nmt_event("operational")
    valve.nmt_event("rpdo_timeout")
    assert [code for code, _ in told] == [0x8100, 0x8100]
    assert told[0][1].startswith("CANopen SYNC not received")
    assert told[1][1].startswith("CANopen RPDO not received within its event timer")


def test_the_serve_log_tells_an_lss_valve_waiting_and_its_assignment(capsys, request):
    import can
    from support.canopen_rig import unique_channel
    from support.waiting import wait_for

    from prm9tool.cli import serve
    from prm9tool.device.canlink.bus import CanOptions

    channel = unique_channel(request.node.name)
    master = can.Bus(interface="virtual", channel=channel)
    valve = EmulatedValve(E02_CA, 8005, switches=(6, 1))  # node-ID switch 1: LSS
    bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(bus)
    try:
        valve.advance(2.0)
        item = serve._Served(valve, slave, lambda: None, [], node=slave.node_id)
        options = CanOptions("virtual", channel)
        serve._report_changes(item, options)
        waiting = capsys.readouterr().out
        assert "serial 8005 (no node ID): NMT initialising, waiting for an LSS master" in waiting
        assert "node 0" not in waiting
        for data in ("04 01", "11 14", "04 00"):  # configuration state, node 20, waiting
            master.send(can.Message(arbitration_id=0x7E5, data=bytes.fromhex(data).ljust(8, b"\0"),
                                    is_extended_id=False))  # fmt: skip
        wait_for(lambda: slave.node_id == 20)
        serve._report_changes(item, options)
        told = capsys.readouterr().out
        assert "serial 8005: LSS assigned node ID 20 (was none)" in told
        assert "serial 8005 node 20: NMT pre-operational" in told
    finally:
        slave.stop()
        bus.shutdown()
        master.shutdown()
