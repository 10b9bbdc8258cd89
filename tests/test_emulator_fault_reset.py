"""Leaving a fault the documented way (manual §7.4, tables 7-19/7-20; CiA 408): the control
word 08h → 09h → 0Bh → 0Fh clears a fault whose cause is gone from every state a fault can be
entered, ``enable()`` says why when it cannot, and a fault that comes back is announced again."""

from __future__ import annotations

import pytest

import prm9tool
from prm9tool.device.emulator import EmulatedValve, Fault
from prm9tool.device.enabling import NotEnabledError
from prm9tool.device.records import DeviceState

E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"
ENABLE = (0x08, 0x09, 0x0B, 0x0F)
HOLD_S = 10.0  # the error display hold (manual §5.5)
# the control word that brings the valve to each state a fault can be entered from
ENTRY_WORDS = {
    DeviceState.INIT: (0x08,),
    DeviceState.DISABLED: (0x08, 0x09),
    DeviceState.HOLD: (0x08, 0x09, 0x0B),
    DeviceState.DEVICE_MODE_ACTIVE: ENABLE,
}


def _booted() -> EmulatedValve:
    valve = EmulatedValve(E02_CA)
    valve.advance(2.0)
    return valve


def _write(valve: EmulatedValve, words: tuple[int, ...]) -> None:
    for word in words:
        valve.write(0x6040, 0, word)


@pytest.mark.parametrize("entered_in", list(ENTRY_WORDS), ids=str)
def test_the_documented_sequence_clears_a_fault_whose_cause_is_gone(entered_in: DeviceState):
    valve = _booted()
    _write(valve, ENTRY_WORDS[entered_in])
    assert valve.device_state is entered_in
    valve.inject(Fault.SUPPLY_HIGH)
    valve.advance(0.1)
    assert valve.device_state in (DeviceState.FAULT, DeviceState.FAULT_HOLD)
    _write(valve, ENABLE)  # the cause is still there: refused
    assert valve.device_state in (DeviceState.FAULT, DeviceState.FAULT_HOLD)
    valve.clear(Fault.SUPPLY_HIGH)
    valve.advance(0.1)
    _write(valve, ENABLE)  # the error is still shown (display hold), but its cause is gone
    assert valve.device_state is DeviceState.DEVICE_MODE_ACTIVE


def test_a_cyclic_0fh_does_not_re_enable_the_valve_by_itself():
    valve = _booted()
    _write(valve, ENABLE)
    valve.inject(Fault.SUPPLY_HIGH)
    valve.advance(0.1)
    valve.clear(Fault.SUPPLY_HIGH)
    valve.advance(0.1)
    _write(valve, (0x0F, 0x0F, 0x0F))  # a PLC's RPDO every cycle: no edge of R, H = 1
    assert valve.device_state is DeviceState.FAULT_HOLD
    _write(valve, (0x07, 0x0F))  # CiA 408: a rising edge of R resets (FAULT_HOLD -> HOLD)
    assert valve.device_state is DeviceState.DEVICE_MODE_ACTIVE


def test_a_fault_that_comes_back_sends_its_emcy_again():
    valve = _booted()
    sent: list[int] = []
    valve.add_error_listener(lambda code, _register: sent.append(code))
    _write(valve, ENABLE)
    for _ in range(2):
        valve.inject(Fault.COIL_A_OPEN)
        valve.advance(0.2)
        valve.clear(Fault.COIL_A_OPEN)
        valve.advance(0.2)  # well inside the display hold: the error is still shown
        _write(valve, ENABLE)
        assert valve.device_state is DeviceState.DEVICE_MODE_ACTIVE
    assert sent == [0x5411, 0x5411]
    assert valve.read(0x1003, 1) == valve.read(0x1003, 2) == 0x5411  # two events in 0x1003
    valve.advance(HOLD_S + 0.5)
    assert sent == [0x5411, 0x5411, 0x0000]


def test_enable_says_which_error_is_still_present_and_then_reaches_active():
    with prm9tool.connect(f"emulator:{E02_CA}:4790", record_history=False) as valve:
        valve.wait_booted()
        valve.nmt("start")
        valve.enable()
        controls = valve._session.emulator
        assert controls is not None
        controls.set_fault("COIL_A_OPEN", True)
        _wait_state(valve, prm9tool.DeviceState.FAULT_HOLD)
        with pytest.raises(NotEnabledError) as refused:
            valve.enable()
        assert str(refused.value) == (
            "the valve stays in FAULT_HOLD: error 0x5411 (Solenoid A disconnected) is still "
            "present — remove its cause, then enable again (the control word 08h resets the "
            "fault once it is gone)"
        )
        controls.set_fault("COIL_A_OPEN", False)
        _wait(lambda: 0x5411 not in _present(valve))
        valve.enable()
        assert valve.status().device_state is prm9tool.DeviceState.DEVICE_MODE_ACTIVE


def _present(valve) -> set[int]:
    """EMCY codes of the errors whose cause is present now (the emulated valve's own view)."""
    fw = valve._session.emulator.valve.firmware
    return {fw.faults.timers[k].present and kind for k, kind in _codes().items()} - {False}


def _codes() -> dict[str, int]:
    from prm9tool.catalogue.error_kinds import ERROR_KINDS

    return {k.key: k.code for k in ERROR_KINDS}


def _wait_state(valve, state) -> None:
    _wait(lambda: valve.status().device_state is state)


def _wait(condition) -> None:
    from support.waiting import wait_for

    wait_for(condition, 10.0)
