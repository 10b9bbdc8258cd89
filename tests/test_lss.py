"""LSS (CiA 305): the emulated valve at node-ID switch 1 as LSS slave, the tool's LSS master
(prm9tool.device.canlink.lss on canopen's LssMaster), golden frames of every service used, and
bad input: two devices alike, an ID already taken, a refused service, a valve leaving the bus
during configuration, a Fastscan that finds nothing — each with the user's message and no
valve left with a half-applied stored configuration."""

from __future__ import annotations

import json

import can
import pytest
from support.lss_rig import make_lss_rig
from support.waiting import wait_for

from prm9tool.cli.main import main
from prm9tool.device.canlink.lss import LssAddress, LssFailedError, LssMasterLink

ADDRESS_4711 = LssAddress(0xE6, 0x9, 0x10000, 4711)


@pytest.fixture
def rig(request: pytest.FixtureRequest):
    rig = make_lss_rig(request.node.name)
    yield rig
    rig.close()


def _cli(rig, *args: str) -> int:
    bus = ["--can-interface", "virtual", "--can-channel", rig.options.channel]
    return main([*args, *bus])


def test_a_valve_at_switch_1_has_no_node_id_and_stays_silent_until_given_one(rig):
    valve = rig.add(4711)
    wait_for(lambda: not valve.status().booting, 10)
    rig.frames()
    rig.recorder.send(can.Message(arbitration_id=0x60A, data=bytes(8), is_extended_id=False))
    rig.recorder.send(can.Message(arbitration_id=0x000, data=b"\x01\x00", is_extended_id=False))
    valve.write(0x1017, 0, 10)  # a heartbeat would be due every 10 ms
    start = valve.time
    wait_for(lambda: valve.time > start + 0.1)
    assert valve.node_id == 0
    assert rig.frames() == []  # no SDO answer, no boot-up, no heartbeat


def test_golden_frames_of_scan_and_assign(rig):
    valve = rig.add(4711)
    link = LssMasterLink(rig.shared)
    assert link.scan() == [ADDRESS_4711]
    frames = rig.frames()
    for expected in (
        "7E5 04 00 00 00 00 00 00 00",  # switch state global: waiting
        "7E5 4C 00 00 00 00 00 00 00",  # identify non-configured remote slave
        "7E4 50 00 00 00 00 00 00 00",  # identify non-configured slave
        "7E5 51 00 00 00 00 80 00 00",  # Fastscan: BitChecked 128, everyone answers
        "7E4 4F 00 00 00 00 00 00 00",  # identify slave
        "7E5 51 E6 00 00 00 00 00 01",  # Fastscan: vendor 0xE6 confirmed, next: product
        "7E5 51 67 12 00 00 00 03 00",  # Fastscan: serial 4711 confirmed: configuration state
        "7E5 40 E6 00 00 00 00 00 00",  # switch state selective: vendor ID
        "7E5 41 09 00 00 00 00 00 00",  # product code
        "7E5 42 00 00 01 00 00 00 00",  # revision number
        "7E5 43 67 12 00 00 00 00 00",  # serial number
        "7E4 44 00 00 00 00 00 00 00",  # switch state selective response
    ):
        assert expected in frames, expected
    link.assign(ADDRESS_4711, 21, bit_timing=3)
    wait_for(lambda: valve.node_id == 21)
    frames = rig.frames()
    wait_for(lambda: "715 00" in frames or frames.extend(rig.frames()))
    sequence = [
        "7E5 43 67 12 00 00 00 00 00",
        "7E4 44 00 00 00 00 00 00 00",
        "7E5 5E 00 00 00 00 00 00 00",  # inquire node ID
        "7E4 5E FF 00 00 00 00 00 00",  # none yet (0xFF)
        "7E5 11 15 00 00 00 00 00 00",  # configure node ID 21
        "7E4 11 00 00 00 00 00 00 00",  # success
        "7E5 13 00 03 00 00 00 00 00",  # configure bit timing: table 0, index 3 = 250 kbit/s
        "7E4 13 00 00 00 00 00 00 00",
        "7E5 17 00 00 00 00 00 00 00",  # store configuration
        "7E4 17 00 00 00 00 00 00 00",
        "7E5 04 00 00 00 00 00 00 00",  # back to waiting: it boots with node ID 21
        "715 00",  # boot-up
    ]
    start = frames.index(sequence[0])
    assert frames[start : start + len(sequence)] == sequence
    assert valve.firmware.nv.lss == {"node_id": 21, "bit_timing": 3}


def test_activate_bit_timing_frame_and_switch_delay(rig):
    valve = rig.add(4711)
    link = LssMasterLink(rig.shared)
    link.assign(ADDRESS_4711, 21, bit_timing=3)
    wait_for(lambda: valve.node_id == 21)
    rig.frames()
    link.activate_bit_timing(100)
    frames = rig.frames()
    assert frames == [
        "7E5 04 01 00 00 00 00 00 00",
        "7E5 15 64 00 00 00 00 00 00",  # activate bit timing, switch delay 100 ms
        "7E5 04 00 00 00 00 00 00 00",
    ]
    wait_for(lambda: valve.bitrate == 250000)


def test_the_assigned_node_id_survives_a_power_cycle_and_fastscan_skips_it(rig):
    valve = rig.add(4711)
    link = LssMasterLink(rig.shared)
    link.assign(ADDRESS_4711, 21)
    valve.restart()
    assert valve.node_id == 21
    assert link.scan() == []


def test_two_devices_with_the_same_identity_are_refused_and_left_alone(rig):
    twins = [rig.add(4711), rig.add(4711)]
    with pytest.raises(LssFailedError) as caught:
        LssMasterLink(rig.shared).scan()
    assert caught.value.kind == "duplicate"
    assert str(caught.value).startswith(
        "2 devices answer with the same LSS address (PRM9 (vendor 0xE6), product 0x9, "
        "revision 0x10000, serial 4711): LSS cannot tell them apart and prm9tool changed neither"
    )
    assert not any(f.startswith(("7E5 11", "7E5 17")) for f in rig.frames())
    assert [(v.node_id, v.firmware.nv.lss) for v in twins] == [(0, {}), (0, {})]


def test_assigning_one_of_two_alike_changes_neither_and_releases_both(rig, capsys):
    twins = [rig.add(4711), rig.add(4711)]
    with pytest.raises(LssFailedError) as caught:
        LssMasterLink(rig.shared).assign(ADDRESS_4711, 21)
    assert caught.value.kind == "duplicate"
    wait_for(lambda: [s.lss.state for s in rig.slaves] == [0, 0])  # both waiting again
    assert not any(f.startswith(("7E5 11", "7E5 17")) for f in rig.frames())
    assert [(v.node_id, v.firmware.nv.lss) for v in twins] == [(0, {}), (0, {})]
    assert _cli(rig, "--lss-scan") == 2
    assert "2 devices answer with the same LSS address" in capsys.readouterr().err


def test_a_fastscan_that_finds_nothing_says_what_to_check(rig, capsys):
    rig.add(4711, switches=(6, 2))  # node 10 by its switch: it has a node ID
    assert LssMasterLink(rig.shared).scan() == []
    assert _cli(rig, "--lss-scan") == 4
    err = capsys.readouterr().err
    assert "no device without a node ID answered on virtual channel" in err
    assert "--list-devices lists them" in err and "--find-bitrate" in err


def test_lss_scan_lists_identities_and_json(rig, capsys):
    rig.add(4712)
    assert _cli(rig, "--lss-scan") == 0
    assert capsys.readouterr().out == (
        "serial 4712\tPRM9\tvendor 0xE6\tproduct 0x9\trevision 0x10000\n"
    )


def test_lss_scan_json_out_file_is_written_like_the_other_json_files(rig, capsys, tmp_path):
    # issue 28: "--lss-scan --json scan.json" was refused; --json OUT.json means a file everywhere
    rig.add(4712)
    out = tmp_path / "scan.json"
    assert _cli(rig, "--lss-scan", "--json", str(out)) == 0
    assert capsys.readouterr().out == ""
    (found,) = json.loads(out.read_text(encoding="utf-8"))
    assert found["serial"] == 4712


def test_an_id_already_taken_is_refused_before_anything_is_sent(rig, capsys):
    rig.add(4700, switches=(6, 2))  # node 10
    valve = rig.add(4712)
    wait_for(lambda: rig.valves[0].status().nmt_state == "pre-operational", 10)
    assert _cli(rig, "--lss-assign", "4712=10") == 2
    err = capsys.readouterr().err
    assert "node ID 10 is taken: serial 4700 answers there. Choose a free node ID; nothing " in err
    assert "(free: 1, 2, 3, …)" in err
    assert (valve.node_id, valve.firmware.nv.lss) == (0, {})


def test_assign_names_a_serial_that_has_no_lss_device(rig, capsys):
    rig.add(4712)
    assert _cli(rig, "--lss-assign", "4711=21") == 4
    err = capsys.readouterr().err
    assert "no device without a node ID has serial 4711 (devices without a node ID: 4712)" in err


def test_a_refused_bit_rate_stores_nothing_and_gives_no_node_id(rig):
    valve = rig.add(4711)
    link = LssMasterLink(rig.shared)
    with pytest.raises(LssFailedError) as caught:
        link.assign(ADDRESS_4711, 21, bit_timing=5)  # 100 kbit/s: not a PRM9 rate
    assert str(caught.value) == (
        "serial 4711 refused configure bit timing 100 kbit/s: the device does not support this "
        "bit rate; nothing was stored"
    )
    frames = rig.frames()
    assert "7E5 11 FF 00 00 00 00 00 00" in frames  # the pending node ID put back
    assert "715 00" not in frames
    assert (valve.node_id, valve.firmware.nv.lss) == (0, {})
    assert link.scan() == [ADDRESS_4711]  # still a device without a node ID


def test_a_failed_store_is_named_and_the_valve_keeps_no_node_id(rig, monkeypatch):
    valve = rig.add(4711)

    def broken(node_id: int, bit_timing: int | None) -> None:
        raise OSError("EEPROM write failed")

    monkeypatch.setattr(valve.canopen, "lss_store", broken)
    rig.slaves[0].lss._host.store = broken
    with pytest.raises(LssFailedError) as caught:
        LssMasterLink(rig.shared).assign(ADDRESS_4711, 21)
    assert str(caught.value) == (
        "serial 4711 refused store configuration: the device could not write its non-volatile "
        "memory (storage media access error); nothing was stored"
    )
    assert (valve.node_id, valve.firmware.nv.lss) == (0, {})


def test_a_valve_that_leaves_the_bus_during_configuration(rig):
    valve = rig.add(4711)
    lss = rig.slaves[0].lss
    answer, gone = lss.handle, []

    def handle(data: bytes) -> None:  # it answers "configure node ID", then its cable is pulled
        if not gone:
            answer(data)
            gone.extend([True] * (data[0] == 0x11))

    lss.handle = handle
    with pytest.raises(LssFailedError) as caught:
        LssMasterLink(rig.shared).assign(ADDRESS_4711, 21)
    assert caught.value.kind == "lost"
    assert str(caught.value) == (
        "serial 4711: no answer to store configuration: the device left the bus during "
        "configuration; it may or may not have stored the new configuration: power it up and "
        "search the bus (and the devices without a node ID)"
    )
    assert valve.firmware.nv.lss == {}  # it never got the store: nothing half-applied stored
    valve.restart()
    assert valve.node_id == 0


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--lss-assign", "4711"], "--lss-assign 4711: give SERIAL=NODE, e.g. 4711=21"),
        (["--lss-assign", "4711=200"], "--lss-assign 4711=200: CANopen node IDs are 1…127"),
        (["--lss-assign", "4711=21", "4712=21"], "node ID 21 is given to two valves"),
        (["--lss-scan", "--batch", "x.prm"], "--lss-scan and --batch are separate commands"),
        (["--lss-assign", "4711=21", "--json"], "--json [OUT.json] belongs to --lss-scan"),
    ],
)
def test_lss_usage_errors(args, message, capsys):
    assert main([*args, "--can-interface", "virtual"]) == 2
    assert message in capsys.readouterr().err


def test_lss_commands_need_a_bus(capsys):
    assert main(["--lss-scan"]) == 2
    assert "--lss-scan needs --can-interface" in capsys.readouterr().err


def test_a_restart_from_prm9tool_finds_an_lss_valve_at_its_lss_node_id(rig, data_dir):
    """At switch 1 NODEID does not apply (table 7-17): a stored NODEID change does not move
    the valve, and the session's restart finds it at the node ID LSS gave it."""
    from prm9tool.device.canlink.session import CanopenSession

    valve = rig.add(4711)
    LssMasterLink(rig.shared).assign(ADDRESS_4711, 21)
    # released, it boots at the new node ID: its boot-up says when (not a guessed wait)
    wait_for(lambda: rig.shared.node_seen(21).boot_ups > 0, 10)
    with CanopenSession(rig.options, 21) as session:
        session.write("NODEID", 30)
        session.store()
        session.restart()
        assert (session.node_id, session.info.device_id) == (21, "can:21")
    assert valve.node_id == 21


def _send(rig, *data: int) -> None:
    rig.recorder.send(
        can.Message(arbitration_id=0x7E5, data=bytes(data).ljust(8, b"\0"), is_extended_id=False)
    )


def test_the_slave_answers_identify_remote_slave_within_its_range_and_inquiries(rig):
    rig.add(4711)
    rig.frames()
    low, high = (4700).to_bytes(4, "little"), (4720).to_bytes(4, "little")
    for cs, value in ((0x46, b"\xe6\0\0\0"), (0x47, b"\x09\0\0\0"), (0x48, bytes(4)),
                      (0x49, b"\xff\xff\xff\xff"), (0x4A, low), (0x4B, high)):  # fmt: skip
        _send(rig, cs, *value)
    wait_for(lambda: "7E4 4F 00 00 00 00 00 00 00" in rig.frames())
    _send(rig, 0x4A, *(4712).to_bytes(4, "little"))  # out of sequence: nothing
    _send(rig, 0x04, 0x01)  # switch state global: configuration
    for cs in (0x5A, 0x5B, 0x5C, 0x5D, 0x5E):
        _send(rig, cs)
    answers: list[str] = []
    wait_for(lambda: len(answers) >= 5 or answers.extend(rig.frames()))
    assert answers == [
        "7E4 5A E6 00 00 00 00 00 00",
        "7E4 5B 09 00 00 00 00 00 00",
        "7E4 5C 00 00 01 00 00 00 00",
        "7E4 5D 67 12 00 00 00 00 00",
        "7E4 5E FF 00 00 00 00 00 00",
    ]
    _send(rig, 0x11, 0x80)  # node ID 128: out of range
    wait_for(lambda: "7E4 11 01 00 00 00 00 00 00" in rig.frames())
    _send(rig, 0x04, 0x00)


def test_serve_emulator_node_id_takes_a_number_or_lss(capsys):
    args = ["--serve-emulator", "PRM9-06.3Z11/30-24E04S02-CA:1", "--can-interface", "virtual"]
    assert main([*args, "--node-id", "ten"]) == 2
    assert "'ten' is neither a node ID 1-127 nor 'lss'" in capsys.readouterr().err
    assert main([*args, "--node-id", "200"]) == 2
    assert "--node-id 200: CANopen node IDs are 1…127" in capsys.readouterr().err


def test_the_bus_bit_rate_changes_by_lss_on_every_lss_valve_together(rig):
    valves = [rig.add(4711), rig.add(4712)]
    link = LssMasterLink(rig.shared)
    for node, address in enumerate(link.scan(), start=21):
        link.assign(address, node)
    rig.frames()
    assert link.change_bus_bit_timing(3, 100) == 2  # 250 kbit/s
    frames = rig.frames()
    assert frames[:2] == ["7E5 04 01 00 00 00 00 00 00", "7E5 13 00 03 00 00 00 00 00"]
    assert "7E5 15 64 00 00 00 00 00 00" in frames  # activate, switch delay 100 ms
    wait_for(lambda: [v.bitrate for v in valves] == [250_000] * 2)
    assert [v.firmware.nv.lss["bit_timing"] for v in valves] == [3, 3]
    # the emulated valves keep CiA 305's silence in their own (simulated) time: let it end
    wait_for(lambda: all(s._now_ms >= s._silent_until_ms for s in rig.slaves))
    with pytest.raises(LssFailedError) as caught:
        link.change_bus_bit_timing(5, 100)  # 100 kbit/s: refused by both
    assert str(caught.value) == (
        "2 of 2 devices refused configure bit timing 100 kbit/s: the device does not support "
        "this bit rate; no device switched now"
    )
    assert not any(f.startswith("7E5 15") for f in rig.frames())  # nothing activated
    assert [v.bitrate for v in valves] == [250_000] * 2


def test_changing_the_bus_bit_rate_without_lss_valves_says_so(rig):
    rig.add(4700, switches=(6, 2))
    with pytest.raises(LssFailedError) as caught:
        LssMasterLink(rig.shared).change_bus_bit_timing(3, 100)
    assert str(caught.value) == (
        "no device answers LSS on this bus (configure bit timing 250 kbit/s): none has its "
        "node-ID switch at 1; nothing was changed"
    )
