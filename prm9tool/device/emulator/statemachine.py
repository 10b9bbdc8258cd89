"""The CiA 408 / VDMA device state machine (manual §7.4, tables 7-19 and 7-20).

Control word bits: D (0) disabled, H (1) hold enabled, M (2) device mode active enabled,
R (3) reset fault. Level-triggered transitions cascade until the state is stable, so the
manual's sequence 08h → 09h → 0Bh → 0Fh walks INIT → DISABLED → HOLD → DEVICE_MODE_ACTIVE one
step per write, and a single 0Fh does the same in one write.

Decisions where table 7-20 is garbled (documented in docs/emulator.md):

* FAULT_REACTION ends in FAULT_HOLD when H = 1 and in FAULT when H = 0 (transitions 9/12).
* A fault is reset while no fault condition is present by a rising edge of R (CiA 408): from
  FAULT to DISABLED, from FAULT_HOLD to HOLD (transitions 10/11); the level rules then continue.
* Table 7-20 gives transition 10 ("reset fault (disabled)") by levels, R = 1 and H = 0, not by
  an edge: so a control word with R = 1 and H = 0 (08h or 09h) resets FAULT *and* FAULT_HOLD to
  DISABLED without an edge. That is what makes the documented 08h → 09h → 0Bh → 0Fh leave a
  fault entered in DEVICE_MODE_ACTIVE (R was already 1 there, so 08h is no edge), and a PLC
  that sends 0Fh cyclically never re-enables a valve by itself: with H = 1 only an edge resets.
"""

from __future__ import annotations

from prm9tool.device.records import DeviceState as S

BIT_D = 0x01
BIT_H = 0x02
BIT_M = 0x04
BIT_R = 0x08

_FUNCTIONAL = (S.INIT, S.DISABLED, S.HOLD, S.DEVICE_MODE_ACTIVE)


class DeviceStateMachine:
    """State, last control word and the fault-reaction timer."""

    def __init__(self) -> None:
        self.state = S.NOT_READY
        self.control_word = 0
        self.reaction_left_s = 0.0

    def power_on(self) -> None:
        """Transition 0: power on, self test."""
        self.state = S.NOT_READY
        self.control_word = 0
        self.reaction_left_s = 0.0

    def init_done(self) -> None:
        """Transition 1: device initialisation successful."""
        if self.state is S.NOT_READY:
            self.state = S.INIT
            self._settle()

    def write_control_word(self, word: int, fault_present: bool) -> None:
        """Apply a new control word (edge of R resets a fault that has gone)."""
        rising_r = bool(word & BIT_R) and not self.control_word & BIT_R
        reset_disabled = bool(word & BIT_R) and not word & BIT_H  # table 7-20, row 10
        self.control_word = word & 0xFFFF
        if not fault_present and self.state in (S.FAULT, S.FAULT_HOLD):
            if self.state is S.FAULT_HOLD and rising_r and not reset_disabled:
                self.state = S.HOLD  # transition 11
            elif rising_r or reset_disabled:
                self.state = S.DISABLED  # transition 10
        self._settle()

    def fault(self, reaction_s: float) -> None:
        """Transition 8: a fault was detected."""
        if self.state in _FUNCTIONAL:
            self.state = S.FAULT_REACTION
            self.reaction_left_s = reaction_s

    def tick(self, dt: float) -> None:
        """Advance the fault-reaction timer (transitions 9 and 12)."""
        if self.state is S.FAULT_REACTION:
            self.reaction_left_s -= dt
            if self.reaction_left_s <= 0.0:
                self.state = S.FAULT_HOLD if self.control_word & BIT_H else S.FAULT

    def deactivate(self) -> None:
        """NMT coupling (table 7-21, reset node): DEVICE_MODE_ACTIVE → INIT."""
        if self.state in (S.DEVICE_MODE_ACTIVE, S.HOLD, S.DISABLED):
            self.state = S.INIT

    def status_word(self, flags: int = 0) -> int:
        """0x6041 as CiA 408 defines it: bits 0…3 (D, H, M, R) tell the state, ``flags`` the
        profile's upper bits the caller knows (:data:`STATUS_LOCAL` …)."""
        return STATE_BITS[self.state] | (flags & ~0x0F & 0xFFFF)

    def _settle(self) -> None:
        word = self.control_word
        d, h, m = word & BIT_D, word & BIT_H, word & BIT_M
        for _ in range(4):
            s = self.state
            if s is S.INIT and d:
                self.state = S.DISABLED  # 2
            elif s is S.DISABLED and d and h:
                self.state = S.HOLD  # 3
            elif s is S.DISABLED and not (d or h or m):
                self.state = S.INIT  # 7
            elif s is S.HOLD and d and h and m:
                self.state = S.DEVICE_MODE_ACTIVE  # 4
            elif s is S.HOLD and not (h or m):
                self.state = S.DISABLED  # 6
            elif s is S.DEVICE_MODE_ACTIVE and not m:
                self.state = S.HOLD  # 5
            else:
                return


# CiA 408 status word bits 0…3 per state, written R M H D (bit 3 … bit 0); the manual
# (§7.4) delegates the state machine to the profile and its figure 7-11 is not in the text
STATE_BITS = {
    S.NOT_READY: 0b0000,
    S.INIT: 0b1000,
    S.DISABLED: 0b1001,
    S.HOLD: 0b1011,
    S.DEVICE_MODE_ACTIVE: 0b1111,
    S.FAULT_HOLD: 0b0011,
    S.FAULT_REACTION: 0b0111,
    S.FAULT: 0b0001,
}
# CiA 408 upper flags of the status word this valve has
STATUS_LOCAL = 1 << 4  # the setpoint comes from the valve's own (analog) input, not the bus
STATUS_CONTROL_DEVIATION = 1 << 11  # |0x6350| beyond the monitoring threshold 0x6353
