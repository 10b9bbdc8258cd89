"""E02 or E04 over CANopen, from what really tells (issue 20 item 3): control mode 0x6043 = 4
exists on E04 valves only; the external-sensor objects 0x2005–0x2100 are objects of all valves
(manual table 7-14) and tell nothing. Otherwise the label decides, and the tool says the
objects could not confirm it."""

from __future__ import annotations

import logging

import pytest
from support.can_link_rig import E02, E04, make_link_rig

from prm9tool.cli.main import main
from prm9tool.device.canlink.session import CanopenSession


def _bus(rig) -> list[str]:
    return ["--can-interface", "virtual", "--can-channel", rig.options.channel]


@pytest.mark.parametrize("od", ["full", "manual"])
def test_an_e04_in_control_mode_2_is_not_called_either(tmp_path, data_dir, capsys, od):
    rig = make_link_rig(f"mode2-{od}", tmp_path, E04, real_valve=True, od=od)
    try:
        rig.valve.write(0x6043, 0, 2)  # spool position control: possible on E02 and E04
        assert main(["--list-devices", *_bus(rig)]) == 0
        out = capsys.readouterr().out
        assert "? (-CA (E02 or E04: its objects do not tell); type key unknown)" in out
    finally:
        rig.close()


@pytest.mark.parametrize("od", ["full", "manual"])
def test_an_e02_with_the_sensor_objects_of_all_valves_is_not_taken_for_an_e04(
    tmp_path, data_dir, capsys, od
):
    rig = make_link_rig(f"e02-{od}", tmp_path, E02, real_valve=True, od=od)
    try:
        # table 7-14: the external sensor objects are on every valve, and so on this E02
        assert rig.valve.read(0x2005, 1) == 9 and rig.valve.read(0x2100, 6) == 0
        assert main(["--list-devices", *_bus(rig)]) == 0
        out = capsys.readouterr().out
        assert "? (-CA (E02 or E04: its objects do not tell); type key unknown)" in out
        assert "E04 -CA" not in out
    finally:
        rig.close()


def test_process_control_tells_e04_and_a_label_saying_e02_is_refused(tmp_path, data_dir):
    rig = make_link_rig("mode4", tmp_path, E04, real_valve=True, od="manual")
    try:
        with pytest.raises(Exception, match="is an E02 valve, the valve's objects say E04"):
            CanopenSession(rig.options, 10, label_key=E02)
    finally:
        rig.close()


def test_the_label_decides_where_the_objects_cannot_and_the_tool_says_so(
    tmp_path, data_dir, caplog
):
    rig = make_link_rig("label", tmp_path, E02, real_valve=True, od="manual")
    try:
        with (
            caplog.at_level(logging.WARNING),
            CanopenSession(rig.options, 10, label_key=E02) as session,
        ):
            assert session.info.type_key == E02
    finally:
        rig.close()
    assert "PRM9-06.3Z11/30-24E02S02-CA taken from its label; its objects cannot confirm E02" in (
        caplog.text
    )
