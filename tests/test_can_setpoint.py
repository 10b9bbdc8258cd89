"""The setpoint generator over CANopen: RPDO1 (control word + 0x6300/0x6380, manual table 7-13)
instead of the override objects a real valve lacks; the same stop rules as over USB (Stop gives
the setpoint back, a refusal says what to do, a lost link makes the valve's RPDO deadline fire).
The emulated -CA valve runs in real time on a virtual bus."""

from __future__ import annotations

import time

import pytest
from support.can_link_rig import E04, make_link_rig
from support.waiting import HandClock, wait_for

from prm9tool.catalogue.commissioning import CONTROL_WORD, ENABLE_SEQUENCE, NmtCommand
from prm9tool.device.canlink.rpdo_setpoint import DEADLINE_MS, RpdoSetpoint, RpdoSetpointError
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.records import DeviceState
from prm9tool.scope import GeneratorSettings, Waveform
from prm9tool.service.setpoint_driver import SetpointDriver

NODE = 10
SQUARE = GeneratorSettings(Waveform.SQUARE, 40.0, 10.0, 0.2)  # 10 % … 50 %


@pytest.fixture(params=[False, True], ids=["emulated", "real-valve"])
def online(request, tmp_path, data_dir):
    """(rig, session): the valve running in real time, heartbeat every 20 ms, control mode 2
    (RPDO1 entry 2 = 0x6300). ``real-valve``: without this project's objects (no 0x2050
    override, no RPDO event timer 0x1400/5)."""
    rig = make_link_rig(request.node.name, tmp_path, real_valve=request.param)
    rig.valve.start()
    session = CanopenSession(rig.options, NODE, type_key=E04 if request.param else None)
    try:
        session.write("HEARTBEAT", 20)
        session.write("CTRLMODE", 2)
        wait_for(lambda: session.nmt_state == "pre-operational")
        yield rig, session
    finally:
        session.close()
        rig.valve.stop()
        rig.close()


def enable(session: CanopenSession) -> None:
    """NMT start and the control word 08h→09h→0Bh→0Fh (manual §7.6)."""
    session.nmt(NmtCommand.START)
    wait_for(lambda: session.nmt_state == "operational")
    for word in ENABLE_SEQUENCE:
        session.write(CONTROL_WORD, word)
        time.sleep(0.01)
    wait_for(lambda: session.status().device_state == DeviceState.DEVICE_MODE_ACTIVE)


def _never(mnemonic: str, exc: Exception) -> None:
    raise AssertionError(f"refused {mnemonic}: {exc}")


def test_the_generator_drives_the_setpoint_over_rpdo1_and_gives_it_back(online):
    rig, session = online
    real = rig.missing != set()
    if real:
        with pytest.raises(Exception, match="not available over CANopen"):
            session.read("SETPOVRON")  # what a real valve lacks: the override
    enable(session)
    before = rig.working("POSSETP")
    clock = HandClock()
    driver = SetpointDriver(session, SQUARE, _never, clock)
    driver.start()
    assert not driver.exact  # the waveform is sent over the bus, not run inside the valve
    wait_for(lambda: rig.working("POSSETP") == 1638)  # 10 % of ±16384, from RPDO1
    assert rig.working(CONTROL_WORD) == 0x0F  # the state machine stays active
    if not real:
        assert rig.working("RPDO1TIMER") == DEADLINE_MS  # a lost link makes it fire
    clock.now = 0.1  # half a period: 50 %
    wait_for(lambda: rig.working("POSSETP") == 8192)
    wait_for(lambda: abs(int(rig.working("POSACT")) - 8192) < 800)  # the spool follows
    time.sleep(0.6)  # longer than the deadline: the keepalive frames keep the valve active
    assert rig.valve.status().device_state == DeviceState.DEVICE_MODE_ACTIVE
    driver.stop()
    wait_for(lambda: rig.working("POSSETP") == before)  # Stop: the setpoint from before
    if not real:
        assert rig.working("RPDO1TIMER") == 0  # the event timer as it was
    assert rig.valve.status().device_state == DeviceState.DEVICE_MODE_ACTIVE


def test_a_valve_not_operational_or_not_enabled_is_refused_with_what_to_do(online):
    rig, session = online
    with pytest.raises(RpdoSetpointError, match=r"NMT pre-operational.*NMT start"):
        SetpointDriver(session, SQUARE, _never).start()
    session.nmt(NmtCommand.START)
    wait_for(lambda: session.nmt_state == "operational")
    with pytest.raises(RpdoSetpointError, match=r"DEVICE_MODE_ACTIVE.*08h→09h→0Bh→0Fh"):
        SetpointDriver(session, SQUARE, _never).start()
    assert rig.working("POSSETP") == 0  # nothing was sent


def test_a_lost_link_lets_the_valves_rpdo_deadline_end_the_motion(tmp_path, data_dir):
    rig = make_link_rig("rpdo-lost", tmp_path)
    rig.valve.start()
    session = CanopenSession(rig.options, NODE)
    try:
        session.write("HEARTBEAT", 20)
        session.write("CTRLMODE", 2)
        wait_for(lambda: session.nmt_state == "pre-operational")
        enable(session)
        driver = SetpointDriver(session, SQUARE, _never, HandClock())
        driver.start()
        wait_for(lambda: rig.working("POSSETP") == 1638)
        driver.stop(switch_off=False)  # the link is gone: nothing more is sent
        wait_for(lambda: rig.valve.status().device_state != DeviceState.DEVICE_MODE_ACTIVE)
        assert 0x8100 in rig.valve.status().active_errors  # the event-timer error
    finally:
        session.close()
        rig.valve.stop()
        rig.close()


def test_the_session_offers_rpdo1_and_a_synchronous_rpdo_is_refused(online):
    _rig, session = online
    link = session.setpoint_link()
    assert isinstance(link, RpdoSetpoint)
    from prm9tool.device.setpoint import OverrideSetpoint
    from prm9tool.service.setpoint_driver import GENERATOR_OBJECTS

    assert {*link.objects, *OverrideSetpoint(session).objects} == GENERATOR_OBJECTS
    enable(session)
    session.nmt(NmtCommand.PRE_OPERATIONAL)  # PDO parameters are written outside OPERATIONAL
    wait_for(lambda: session.nmt_state == "pre-operational")
    session.write("RPDO1TYPE", 1)
    session.nmt(NmtCommand.START)
    wait_for(lambda: session.nmt_state == "operational")
    with pytest.raises(RpdoSetpointError, match=r"synchronous.*255"):
        link.begin(0)


def test_the_scopes_generator_over_can_refuses_then_runs_and_stops(qtbot, tmp_path, data_dir):
    """The GUI's path (connection + the scope's generator switch): a refusal says what to do and
    stops it; started on an enabled valve it drives RPDO1; Stop gives the setpoint back."""
    from prm9tool.device import factory
    from prm9tool.online.connection import ValveConnection
    from prm9tool.online.valve_control import ValveControl
    from prm9tool.views.scope.generator import SetpointGenerator

    rig = make_link_rig("rpdo-gui", tmp_path)
    rig.valve.start()
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
    generator = SetpointGenerator(connection)
    failures: list[str] = []
    connection.failed.connect(failures.append)
    try:
        with qtbot.waitSignal(connection.online_changed, timeout=10000):
            connection.go_online("can:10")
        connection.write_many({"HEARTBEAT": 20, "CTRLMODE": 2})
        with qtbot.waitSignal(generator.refused, timeout=5000) as refused:
            generator.start(SQUARE)
        assert "Commissioning" in refused.args[0]  # what to do
        assert not generator.running
        control = ValveControl(connection)  # the commissioning panel's commands
        control.nmt(NmtCommand.START)
        control.enable()
        qtbot.waitUntil(
            lambda: rig.valve.status().device_state == DeviceState.DEVICE_MODE_ACTIVE, timeout=3000
        )
        qtbot.waitUntil(lambda: not connection.is_busy, timeout=3000)
        generator.start(SQUARE)
        qtbot.waitUntil(lambda: rig.working("POSSETP") == 1638 or len(failures) > 1, timeout=3000)
        assert generator.running and len(failures) == 1, failures
        generator.stop()
        qtbot.waitUntil(lambda: rig.working("POSSETP") == 0, timeout=3000)
        qtbot.waitUntil(lambda: rig.working("RPDO1TIMER") == 0, timeout=3000)
        assert rig.valve.status().device_state == DeviceState.DEVICE_MODE_ACTIVE
    finally:
        connection.go_offline()
        connection.shutdown()
        rig.valve.stop()
        rig.close()
