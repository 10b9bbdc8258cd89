"""The setpoint generator's engine: a waveform on the valve's setpoint, on the valve's time base.

The PC drives the setpoint through the session's :class:`~prm9tool.device.setpoint.SetpointLink`
(``ValveSession.setpoint_link``): over USB the service override (while SETPOVRON = 1 the
firmware takes its setpoint from SETPOVR instead of its analog input), over CANopen RPDO1
(control word + 0x6300/0x6380, manual table 7-13). The driver runs in a thread of its own,
never on the GUI thread:

* An emulated valve gets the whole waveform (``ValveSession.emulator.drive_setpoint``): its
  loop applies it on its own clock, exact to the 200 µs cycle, paced or stepped faster than
  real time. The driver only keeps the link busy (the firmware drops the override 500 ms after
  the last USB report).
* Over a link to a real valve (and any valve on a CAN bus) the driver sends the setpoint when
  the waveform's value changes (and at least every 100 ms), timed against the oscilloscope's
  sample stream when one runs (sample ``n`` lies ``n / rate`` after the stream started, so the
  waveform follows the valve's clock, not the host's), otherwise against the host's monotonic
  clock. Its edges are as exact as the link's latency allows (a USB report per millisecond; one
  RPDO frame, no answer awaited, on CAN).

A refused write ends the driver and is reported (``on_refused``); a broken link just ends it:
the connection notices the dead link itself.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

from prm9tool.catalogue.commissioning import SETPOINT_OBJECTS
from prm9tool.errors import CommunicationError, Prm9Error

if TYPE_CHECKING:  # numpy and the device layer stay out of the window's start-up
    from prm9tool.device.session import ValveSession
    from prm9tool.device.setpoint import SetpointLink  # (tests/test_gui_app.py)
    from prm9tool.scope import GeneratorSettings

GENERATOR_OBJECTS = frozenset(SETPOINT_OBJECTS)  # what a refusal names when it stops a generator
KEEPALIVE_S = 0.1  # the override's watchdog is 500 ms; read at least this often (emulated)
LINK_STEP_S = 0.001  # over a link: look for a changed value every millisecond (one USB frame)
MAX_EXTRAPOLATION_S = 0.05  # trust the stream's time for this long after its last block


class StreamClock:
    """The valve's time as its sample stream tells it (thread-safe; fed by the poller)."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._rate = 0
        self._samples = 0
        self._arrived = 0.0

    def restart(self, rate_hz: int) -> None:
        """A stream at ``rate_hz`` started (0: none runs)."""
        with self._lock:
            self._rate, self._samples, self._arrived = rate_hz, 0, time.monotonic()

    def samples_arrived(self, count: int) -> None:
        """``count`` more samples of the running stream arrived."""
        with self._lock:
            self._samples += count
            self._arrived = time.monotonic()

    def mark(self) -> tuple[int, int, float]:
        """Now, to measure from: (rate, samples, wall clock)."""
        with self._lock:
            return self._rate, self._samples, time.monotonic()

    def seconds_since(self, mark: tuple[int, int, float]) -> float:
        """Valve seconds since ``mark``: from the samples when the same stream still runs
        and has delivered since, else from the host's clock."""
        rate, samples, wall = mark
        now = time.monotonic()
        with self._lock:
            same = self._rate == rate and rate > 0 and self._samples > samples
            if not same or now - self._arrived > MAX_EXTRAPOLATION_S:
                return now - wall
            return (self._samples - samples) / rate + (now - self._arrived)


class SetpointDriver:
    """Drives the setpoint with a :class:`GeneratorSettings` waveform (the module docstring)."""

    def __init__(
        self,
        session: ValveSession,
        settings: GeneratorSettings,
        on_refused: Callable[[str, Prm9Error], None],
        clock: StreamClock | None = None,
    ) -> None:
        self._session = session
        self._settings = settings
        self._on_refused = on_refused
        self._clock = clock or StreamClock()
        self._controls = session.emulator
        self._link = setpoint_link(session)
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="setpoint-generator", daemon=True)
        self._mark = self._clock.mark()
        self._writing = ""

    @property
    def exact(self) -> bool:
        """True when the valve itself runs the waveform on its cycle (an emulated valve)."""
        return self._controls is not None

    def start(self) -> None:
        """Send the first value, take the setpoint over and run. Raises what the valve
        answered (e.g. SdoAbortError, a refusal saying what to do) or a CommunicationError;
        nothing runs then."""
        if self._controls is None:
            self._mark = self._clock.mark()
            self._link.begin(self._settings.raw_at(0.0))
            self._thread.start()
            return
        self._write("SETPOVR", self._settings.raw_at(0.0))
        self._controls.drive_setpoint(self._settings.raw_values)
        self._mark = self._clock.mark()
        try:
            self._write("SETPOVRON", 1)
        except Prm9Error:
            self._release()
            raise
        self._thread.start()

    def stop(self, switch_off: bool = True) -> None:
        """End the waveform; ``switch_off``: give the setpoint back (SETPOVRON = 0, or the
        RPDO setpoint from before; not when the link is gone)."""
        self._stop.set()
        if self._thread.is_alive() and self._thread is not threading.current_thread():
            self._thread.join()
        self._release()
        if not switch_off:
            return
        if self._controls is None:
            self._link.end()
        else:
            self._write("SETPOVRON", 0)

    def leftovers(self) -> dict[str, int]:
        """What the link changed and its end would put back (``SetpointLink.leftovers``)."""
        return self._link.leftovers() if self._controls is None else {}

    def _release(self) -> None:
        if self._controls is not None:
            self._controls.drive_setpoint(None)

    def _write(self, mnemonic: str, raw: int) -> None:
        self._writing = mnemonic
        self._session.write(mnemonic, raw)

    def _run(self) -> None:
        try:
            if self._controls is not None:
                while not self._stop.wait(KEEPALIVE_S):
                    self._session.read("SETPOVRON")  # any report keeps the override alive
            else:
                self._follow_the_link()
        except CommunicationError:
            return  # the link is gone: the connection reports it
        except Prm9Error as exc:
            self._on_refused(self._writing if self._controls else self._link.writing, exc)

    def _follow_the_link(self) -> None:
        last, written = self._settings.raw_at(0.0), time.monotonic()
        while not self._stop.wait(LINK_STEP_S):
            raw = self._settings.raw_at(self._clock.seconds_since(self._mark))
            now = time.monotonic()
            if raw != last:
                self._link.set(raw)
            elif now - written >= self._link.keepalive_s:
                self._link.keep_alive()
            else:
                continue
            last, written = raw, now


def setpoint_link(session: ValveSession) -> SetpointLink:
    """The session's way to the setpoint (its link's own, or the USB service override)."""
    return session.setpoint_link()
