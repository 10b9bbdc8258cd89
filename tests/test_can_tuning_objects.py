"""Tuning over CANopen on a valve that follows the manual (issue 20 item 3): the controller
gains sit at this project's own addresses (0x2020/0x2021), which such a valve does not have;
the tuning says so before it writes or moves anything."""

from __future__ import annotations

import pytest
from support.can_link_rig import E04, make_link_rig
from support.waiting import wait_for

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.characterize.canrig import rig_for_session
from prm9tool.characterize.critical_gain import critical_gain_tune
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.records import DeviceState
from prm9tool.errors import Prm9Error


def test_critical_gain_tuning_names_what_it_cannot_change_before_it_starts(tmp_path, data_dir):
    rig = make_link_rig("tune-manual", tmp_path, E04, od="manual")
    rig.valve.start()
    try:
        with CanopenSession(rig.options, 10, type_key=E04) as session:
            session.write("CTRLMODE", 2)
            session.nmt(NmtCommand.START)
            wait_for(lambda: session.nmt_state == "operational")
            for word in (0x08, 0x09, 0x0B, 0x0F):
                session.write("CONTROLWORD", word)
            wait_for(lambda: rig.valve.status().device_state is DeviceState.DEVICE_MODE_ACTIVE)
            before = rig.working("POSSETP")
            with pytest.raises(Prm9Error) as caught:
                critical_gain_tune(rig_for_session(session))
    finally:
        rig.valve.stop()
        rig.close()
    assert str(caught.value) == (
        "this valve has no object for POSKP, POSKI, POSKD, POST1 on this link (their addresses "
        "are this project's, not the manual's): the tuning cannot change them here; nothing "
        "was changed — tune these over USB"
    )
    assert rig.working("POSSETP") == before  # nothing was sent
    assert rig.working("POSKP") == CATALOGUE["POSKP"].default
