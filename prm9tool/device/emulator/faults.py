"""Error detection bookkeeping: debounce, display hold, error register, history, EMCY listeners.

Each error kind of manual table 5-1 has a raw *condition* the firmware evaluates every 1 ms.
A condition that has lasted its detection delay makes the error *present* (the valve centres
the spool). An error stays *active* (shown by the LEDs, 0x2040, 0x1001 and the EMCY state) while
it is present and for ``fault_display_hold_s`` (~10 s, manual §5.5) after the condition went
away; the valve itself resumes as soon as the error is no longer present. An error that comes
back while still shown is announced again (its EMCY and a 0x1003 entry): it is a new event.
"""

from __future__ import annotations

from collections.abc import Callable

from prm9tool.catalogue import ERROR_HISTORY_DEPTH
from prm9tool.catalogue.error_kinds import ERROR_KINDS, KINDS, ErrorKind

ErrorListener = Callable[[int, int], None]
# (EMCY code, error register, the error that caused it or None when all are cleared)
CauseListener = Callable[[int, int, ErrorKind | None], None]


class _Timer:
    __slots__ = ("active_until", "present", "since")

    def __init__(self) -> None:
        self.since = -1.0  # time the raw condition started, -1 = not pending
        self.present = False
        self.active_until = -1.0  # display hold end; -1 = not active


class FaultMonitor:
    """Debounces conditions, keeps the active set, error register and history 0x1003."""

    def __init__(self, hold_s: float) -> None:
        self.hold_s = hold_s
        self.timers = {k.key: _Timer() for k in ERROR_KINDS}
        self.history: list[int] = []  # newest first (0x1003 sub 1 = newest)
        self.listeners: list[ErrorListener] = []
        self.cause_listeners: list[CauseListener] = []
        self._returned: list[str] = []  # became present again while still shown
        self.active: tuple[ErrorKind, ...] = ()
        self.any_present = False  # some error is present (the spool must stay centred)
        self.busy = False  # some condition is pending, present or on display hold

    def update(self, now: float, conditions: dict[str, tuple[bool, float]]) -> None:
        """Feed the raw conditions ``{key: (condition, delay_s)}`` at time ``now``."""
        for key, (condition, delay) in conditions.items():
            t = self.timers[key]
            if condition:
                if t.since < 0.0:
                    t.since = now
                if not t.present and now - t.since >= delay - 1e-9:
                    t.present = True
                    if t.active_until > now:
                        self._returned.append(key)
                if t.present:
                    t.active_until = float("inf")
            else:
                t.since = -1.0
                if t.present:
                    t.present = False
                    t.active_until = now + self.hold_s
        self._refresh(now)

    def force(self, key: str, present: bool, now: float) -> None:
        """Set an error directly (communication errors reported by the CANopen slave)."""
        t = self.timers[key]
        if present:
            if not t.present and t.active_until > now:
                self._returned.append(key)
            t.present, t.since, t.active_until = True, now, float("inf")
        elif t.present:
            # a reported-only protocol error (8210) ends with its cause: CiA 301 error reset
            hold = self.hold_s if KINDS[key].fault else 0.0
            t.present, t.since, t.active_until = False, -1.0, now + hold
        self._refresh(now)

    def is_present(self, key: str) -> bool:
        """True while the error ``key`` is present."""
        return self.timers[key].present

    def register(self) -> int:
        """Error register 0x1001 (CiA 301 bits: 0 generic, 1 current, 2 voltage, ...)."""
        if not self.active:
            return 0
        reg = 1
        for kind in self.active:
            if kind.register_bit > 0:
                reg |= 1 << kind.register_bit
        return reg

    def code(self) -> int:
        """EMCY code of the most severe active error (0 = none)."""
        return self.active[0].code if self.active else 0

    def clear_history(self) -> None:
        """0x1003 sub 0 written with 0."""
        self.history.clear()

    def reset(self) -> None:
        """Power cycle: forget every condition (the history is kept in RAM: cleared too)."""
        self.timers = {k.key: _Timer() for k in ERROR_KINDS}
        self.active = ()
        self._returned.clear()
        self.any_present = self.busy = False
        self.history.clear()

    def _refresh(self, now: float) -> None:
        timers = self.timers.values()
        for t in timers:
            if 0.0 <= t.active_until <= now:
                t.active_until = -1.0  # display hold over
        self.any_present = any(self.timers[k.key].present for k in ERROR_KINDS if k.fault)
        self.busy = any(t.since >= 0.0 or t.active_until >= 0.0 for t in timers)
        before = self.active
        self.active = tuple(k for k in ERROR_KINDS if self.timers[k.key].active_until > now)
        returned = [KINDS[key] for key in self._returned]
        self._returned.clear()
        if self.active == before and not returned:
            return
        appeared = [k for k in self.active if k not in before] + returned
        for kind in appeared:
            self.history.insert(0, kind.code)
        del self.history[ERROR_HISTORY_DEPTH:]
        cause = appeared[0] if appeared else (self.active[0] if self.active else None)
        code = cause.code if cause is not None else 0
        reg = self.register()
        for listener in self.listeners:
            listener(code, reg)
        for cause_listener in self.cause_listeners:
            cause_listener(code, reg, cause)
