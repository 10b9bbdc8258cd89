"""CiA 408 device state machine (tables 7-19/7-20), NMT coupling (7-21), power-up, LEDs."""

from __future__ import annotations

import time

import pytest

from prm9tool.device.canlink.status import device_state
from prm9tool.device.emulator import EmulatedValve, Fault
from prm9tool.device.emulator.constants import FIRMWARE
from prm9tool.device.emulator.statemachine import STATUS_CONTROL_DEVIATION, DeviceStateMachine
from prm9tool.device.records import DeviceState
from prm9tool.errors import AbortCode, SdoAbortError, ValueRangeError

S = DeviceState
E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"
FULL = 16384


def booted_ca() -> EmulatedValve:
    valve = EmulatedValve(E02_CA)
    valve.advance(2.0)
    return valve


def state_after(valve: EmulatedValve, word: int) -> DeviceState:
    valve.write(0x6040, 0, word)
    return valve.status().device_state


def test_power_up_ends_in_init_on_a_canopen_valve():
    valve = EmulatedValve(E02_CA)
    assert valve.status().device_state is S.NOT_READY
    valve.advance(2.0)
    assert valve.status().device_state is S.INIT
    valve.write(0x6040, 0, 0x0F)
    valve.write(0x6300, 1, 8000)
    valve.advance(0.1)
    assert valve.signal("position_actual") == pytest.approx(8000, abs=0.02 * FULL)


def test_manual_commissioning_sequence_08_09_0b_0f():
    valve = booted_ca()
    assert [state_after(valve, w) for w in (0x08, 0x09, 0x0B, 0x0F)] == [
        S.INIT,
        S.DISABLED,
        S.HOLD,
        S.DEVICE_MODE_ACTIVE,
    ]
    assert valve.read(0x6040, 0) == 0x0F
    assert valve.read(0x6041, 0) & 0x07 == 0x07


@pytest.mark.parametrize(
    ("words", "expected"),
    [
        ((0x0F,), S.DEVICE_MODE_ACTIVE),  # transitions 2, 3, 4 in one write
        ((0x0F, 0x0B), S.HOLD),  # 5: M = 0
        ((0x0F, 0x09), S.DISABLED),  # 5, 6: M = H = 0
        ((0x0F, 0x00), S.INIT),  # 5, 6, 7: all off
        ((0x03,), S.HOLD),  # 2, 3
        ((0x03, 0x01), S.DISABLED),  # 6
        ((0x05,), S.DISABLED),  # M without H: no hold, no active mode
    ],
)
def test_transitions_of_table_7_20(words, expected):
    valve = booted_ca()
    for word in words:
        valve.write(0x6040, 0, word)
    assert valve.status().device_state is expected


@pytest.mark.parametrize(("word", "expected"), [(0x0F, S.FAULT_HOLD), (0x01, S.FAULT)])
def test_fault_reaction_ends_in_fault_hold_or_fault_by_the_hold_bit(word, expected):
    valve = booted_ca()
    valve.write(0x6040, 0, word)
    valve.inject(Fault.SUPPLY_LOW)
    valve.advance(0.053)  # 50 ms detection delay + 1 ms task
    assert valve.status().device_state is S.FAULT_REACTION
    valve.advance(0.01)
    assert valve.status().device_state is expected
    valve.clear(Fault.SUPPLY_LOW)
    valve.advance(0.1)
    reset_target = {S.FAULT_HOLD: S.DEVICE_MODE_ACTIVE, S.FAULT: S.DISABLED}[expected]
    valve.write(0x6040, 0, word & ~0x08)
    assert state_after(valve, word | 0x08) is reset_target  # transitions 11 / 10


@pytest.mark.parametrize(
    ("state", "bits"),
    [
        (S.NOT_READY, 0b0000),
        (S.INIT, 0b1000),
        (S.DISABLED, 0b1001),
        (S.HOLD, 0b1011),
        (S.DEVICE_MODE_ACTIVE, 0b1111),
        (S.FAULT_HOLD, 0b0011),
        (S.FAULT_REACTION, 0b0111),
        (S.FAULT, 0b0001),
    ],
)
def test_status_word_bits_0_to_3_tell_the_state_as_cia_408_defines(state, bits):
    machine = DeviceStateMachine()
    machine.state = state
    assert machine.status_word() == bits  # R M H D, nothing in bits 8…11
    assert machine.status_word(STATUS_CONTROL_DEVIATION) == bits | 0x0800
    assert device_state(machine.status_word(0xFFF0)) is state  # the master ignores the flags


def test_analog_only_valve_runs_by_itself_and_refuses_a_control_word():
    valve = EmulatedValve(E02_CA, switches=(0, 2))
    valve.set_input("setpoint", 5.0)
    valve.advance(2.0)
    assert valve.status().device_state is S.DEVICE_MODE_ACTIVE
    assert valve.signal("position_actual") == pytest.approx(FULL / 2, abs=0.02 * FULL)
    with pytest.raises(SdoAbortError) as info:
        valve.write(0x6040, 0, 0)
    assert info.value.code == AbortCode.CANNOT_STORE_LOCAL_CONTROL


def test_canopen_valve_takes_its_setpoint_from_0x6300_not_the_analog_input():
    valve = booted_ca()
    valve.set_input("setpoint", 10.0)
    valve.write(0x6040, 0, 0x0F)
    valve.write(0x6300, 1, -8000)  # figure 7-14: about -50 %
    valve.advance(0.1)
    assert valve.signal("position_actual") == pytest.approx(-8000, abs=0.02 * FULL)
    assert valve.read(0x6310, 1) == -8000


def test_hold_state_holds_the_spool_at_zero():
    valve = booted_ca()
    valve.write(0x6300, 1, 8000)
    valve.write(0x6040, 0, 0x0F)
    valve.advance(0.1)
    valve.write(0x6040, 0, 0x0B)
    valve.advance(0.1)
    assert abs(valve.signal("position_actual")) < 0.02 * FULL


def test_power_up_timeline_and_leds():
    valve = EmulatedValve(E02_CA, switches=(0, 2))
    valve.set_input("setpoint", 5.0)
    valve.advance(0.02)
    lit = []
    for _ in range(17):
        status = valve.status()
        assert status.booting
        assert status.leds[0].color == "white"
        assert (status.leds[1].color, status.leds[2].color) == ("red", "orange")
        lit.append(status.leds[0].lit)
        valve.advance(0.1)
    assert lit.count(True) == 10  # white twice: on 0…0.45 s and 0.9…1.35 s
    assert lit.index(False) == 5
    assert abs(valve.signal("position_actual")) < 0.02 * FULL  # not yet effective
    valve.advance(0.1)
    status = valve.status()
    assert not status.booting
    assert (status.leds[0].color, status.leds[0].pattern) == ("green", "on")
    valve.advance(0.1)
    assert valve.signal("position_actual") > 0.4 * FULL  # effective after 1.8 s


def test_valve_without_canopen_has_only_the_power_led():
    valve = EmulatedValve("PRM9-06.3Z11/30-24E02S02")
    valve.advance(2.0)
    status = valve.status()
    assert status.nmt_state == "off"
    assert [led.pattern for led in status.leds] == ["on", "off", "off"]


def test_can_led_follows_the_nmt_state():
    valve = booted_ca()
    assert valve.status().nmt_state == "pre-operational"
    assert valve.status().leds[2].pattern == "2.5Hz"
    valve.nmt_event("operational")
    assert valve.status().leds[2].pattern == "on"
    valve.nmt_event("stopped")
    assert valve.status().leds[2].pattern == "single_flash"


@pytest.mark.parametrize(
    "event", ["stopped", "reset_comm", "comm_error", "sync_error", "rpdo_timeout"]
)
def test_nmt_events_take_an_active_valve_to_fault_reaction(event):
    valve = booted_ca()
    valve.nmt_event("operational")
    valve.write(0x6040, 0, 0x0F)
    valve.nmt_event(event)
    assert valve.status().device_state is S.FAULT_REACTION
    valve.advance(0.01)
    assert valve.status().device_state is S.FAULT_HOLD


def test_comm_error_is_an_error_until_operational_again():
    valve = booted_ca()
    valve.nmt_event("comm_error")
    status = valve.status()
    assert status.error_code == 0x8100
    assert status.error_register == 0x11
    assert status.leds[1].pattern == "double_flash"
    valve.nmt_event("operational")
    valve.advance(10.1)
    assert valve.status().error_code == 0


@pytest.mark.parametrize(
    ("event", "text", "led2"),
    [
        ("comm_error", "", "double_flash"),  # heartbeat / guarding event
        ("sync_error", "SYNC", "triple_flash"),
        ("rpdo_timeout", "event timer", "quadruple_flash"),
    ],
)
def test_can_errors_of_table_7_18_flash_led2_and_go_when_operational_again(event, text, led2):
    valve = booted_ca()
    valve.nmt_event("operational")
    valve.nmt_event(event)
    status = valve.status()
    assert (status.error_code, status.error_register) == (0x8100, 0x11)
    assert text in status.error_text
    assert status.leds[0].color == "green" and status.leds[0].pattern == "on"
    assert status.leds[1].pattern == led2
    assert status.leds[2].pattern == "single_flash"
    valve.nmt_event("operational")
    valve.advance(10.1)
    assert valve.status().error_code == 0
    assert valve.status().leds[1].pattern == "off"


def test_reset_node_power_cycles():
    valve = booted_ca()
    valve.write(0x6332, 1, 500)  # not stored
    valve.nmt_event("reset_node")
    assert valve.status().booting
    assert valve.read(0x6332, 1) == 0


def test_reset_communication_restores_communication_objects():
    valve = booted_ca()
    valve.write(0x1017, 0, 50)
    valve.write(0x6332, 1, 500)
    valve.nmt_event("reset_comm")
    assert valve.read(0x1017, 0) == 1000
    assert valve.read(0x6332, 1) == 500
    assert valve.status().nmt_state == "pre-operational"


def test_unknown_nmt_event_is_refused():
    with pytest.raises(ValueRangeError, match="unknown NMT event 'start'"):
        booted_ca().nmt_event("start")


def test_setpoint_override_times_out_without_usb_activity():
    valve = booted_ca()
    valve.write(0x6040, 0, 0x0F)
    valve.write(0x2050, 2, 8192)
    valve.write(0x2050, 1, 1)
    for _ in range(5):
        valve.advance(0.2)
        valve.usb_activity()
    assert valve.signal("position_actual") == pytest.approx(8192, abs=0.02 * FULL)
    valve.advance(0.6)
    assert valve.read(0x2050, 1) == 0
    valve.advance(0.1)
    assert abs(valve.signal("position_actual")) < 0.02 * FULL


def test_08h_first_clears_a_fault_left_from_power_up():
    valve = EmulatedValve(E02_CA)
    valve.set_input("supply_voltage", 18.0)
    valve.advance(2.0)
    assert valve.status().device_state is S.FAULT
    valve.set_input("supply_voltage", 24.0)
    valve.advance(0.1)
    assert [state_after(valve, w) for w in (0x08, 0x09, 0x0B, 0x0F)] == [
        S.INIT,
        S.DISABLED,
        S.HOLD,
        S.DEVICE_MODE_ACTIVE,
    ]


def test_reset_node_from_inside_the_loop_restarts_cleanly():
    valve = booted_ca()
    fired: list[float] = []

    def listener(now: float) -> None:
        if not fired and now >= 2.5:
            fired.append(now)
            valve.nmt_event("reset_node")

    valve.add_cycle_listener(listener)
    valve.advance(1.0)  # 2.0 -> 2.5 s, power cycle, then 0 -> 0.5 s
    assert fired == [pytest.approx(2.5)]
    assert valve.status().booting
    assert valve.time == pytest.approx(0.5, abs=0.002)
    valve.advance(2.0)
    assert valve.status().device_state is S.INIT
    valve.write(0x6040, 0, 0x0F)
    valve.write(0x6300, 1, 8000)
    valve.advance(0.1)
    assert valve.signal("position_actual") == pytest.approx(8000, abs=0.02 * FULL)


def _caught_up(valve: EmulatedValve) -> None:
    """Wait until the paced thread has run every cycle due on its (fake) clock."""
    deadline = time.monotonic() + 30.0  # a loaded PC: the catch-up is at most a few s of CPU
    while valve.pacer.lag_s() >= valve.pacer.min_batch * valve.CYCLE_S:
        assert time.monotonic() < deadline, "the paced valve did not catch up"
        time.sleep(valve.CYCLE_S)


def test_a_report_during_a_stall_of_the_paced_valve_counts_at_its_real_time():
    """The paced valve's thread held up (the GIL, a loaded PC) catches up the simulated time
    in a burst; a report that came during the stall counts at the moment it came, as on a real
    valve, not at the stalled simulated time (the burst then passed the 0.5 s watchdog with no
    report interleaved and dropped the override although the tool kept sending)."""
    timeout = FIRMWARE.override_timeout_s
    valve = booted_ca()
    valve.write(0x6040, 0, 0x0F)
    valve.write(0x2050, 2, 8192)
    valve.write(0x2050, 1, 1)
    wall = [0.0]
    valve.pacer.clock = lambda: wall[0]
    valve.start()
    try:
        with valve.lock:  # the valve's thread stalls while the wall clock runs on
            wall[0] += 1.6 * timeout
            valve.usb_activity()  # a report arrives at the end of the stall
        _caught_up(valve)
        assert valve.read(0x2050, 1) == 1  # kept: the report came 0 s before, not 0.8 s
        wall[0] += 1.2 * timeout  # no report for longer than the watchdog: dropped
        _caught_up(valve)
        assert valve.read(0x2050, 1) == 0
    finally:
        valve.stop()
