"""EmulatedValve: the public face of the emulated PRM9 (API contract: docs/emulator.md)."""

from __future__ import annotations

import math
import os
import threading
from collections.abc import Callable, Iterable, Sequence
from typing import TYPE_CHECKING

import numpy as np

from prm9tool.catalogue import CATALOGUE, LOAD_SIGNATURE, SAVE_SIGNATURE
from prm9tool.catalogue.error_kinds import WARNING_TEXT
from prm9tool.catalogue.signals import BY_KEY
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Variant
from prm9tool.device.emulator import manual_od
from prm9tool.device.emulator.capture import Capture
from prm9tool.device.emulator.constants import (
    CYCLE_S,
    FIRMWARE,
    PLANT,
    FirmwareConstants,
    PlantConstants,
)
from prm9tool.device.emulator.firmware import Firmware
from prm9tool.device.emulator.override import OverrideProgram, Source
from prm9tool.device.emulator.pacing import GROUPED_MIN_BATCH, Pacer
from prm9tool.device.emulator.states import Fault
from prm9tool.device.emulator.valve_canopen import CanopenSide
from prm9tool.device.leds import leds
from prm9tool.device.records import DeviceState, ValveStatus
from prm9tool.errors import AccessDeniedError, SdoAbortError, ValueRangeError

if TYPE_CHECKING:
    import can

    from prm9tool.catalogue.error_kinds import ErrorKind
    from prm9tool.device.emulator.canopen_slave import CanopenSlave

_CONTROL_MODE = CATALOGUE["CTRLMODE"].key  # 0x6043
INPUT_NAMES = (
    "setpoint",
    "sensor",
    "supply_voltage",
    "ambient_temperature",
    "switch_baud",
    "switch_node",
    "sensor_from_plant",
)


class EmulatedValve:
    """An emulated PRM9 valve: firmware, control loop, plant, faults, LEDs and NV memory.

    Every public method takes :attr:`lock`; the paced thread holds it for one batch of at most
    10 ms of simulated time, so callers wait at most that long. Its CANopen side (SDO access,
    LSS, NMT: what its CANopen slave uses) is the part :attr:`canopen`.
    """

    CYCLE_S = CYCLE_S

    def __init__(
        self,
        type_key: str | TypeKey,
        serial: int = 1,
        firmware_version: str = str(CATALOGUE["FWVER"].default),  # what the EDS describes
        nv_path: str | os.PathLike[str] | None = None,
        switches: tuple[int, int] | None = None,
        plant: PlantConstants = PLANT,
        constants: FirmwareConstants = FIRMWARE,
        od: str = manual_od.FULL,
    ) -> None:
        """``od``: ``full`` (every catalogue object over CANopen, store on command) or
        ``manual`` (only the objects the manual lists, keeps what is written:
        :mod:`prm9tool.device.emulator.manual_od`)."""
        if od not in manual_od.OD_PROFILES:
            raise ValueError(f"object dictionary {od!r}: one of {', '.join(manual_od.OD_PROFILES)}")
        self.od = od
        self.type_key = type_key if isinstance(type_key, TypeKey) else TypeKey.parse(type_key)
        self.variant: Variant = self.type_key.variant
        self.serial = serial
        self.firmware_version = firmware_version
        self.lock = threading.RLock()
        self._fw = Firmware(
            self.type_key, serial, firmware_version, nv_path, switches, plant, constants
        )
        self._capture = Capture(self._fw.loop)
        self._restart_listeners: list[Callable[[], None]] = []
        self.canopen = CanopenSide(self.lock, self._fw, od, self.restart)
        self._thread: threading.Thread | None = None
        self._grouped = False  # paced by a PacedGroup's thread
        self._stop = threading.Event()
        self.pacer = Pacer(CYCLE_S)
        self._own_min_batch = self.pacer.min_batch  # its own paced thread's batch

    @property
    def firmware(self) -> Firmware:
        """The emulated firmware itself (NV memory, object dictionary, kernel, program): the
        test hook for what a real valve does not show over its link. Hold :attr:`lock` while
        touching it from another thread than the paced one."""
        return self._fw

    # --- object dictionary ------------------------------------------------------------
    def read(self, index: int, subindex: int) -> int | str:
        """Read an object; raises SdoAbortError with the CiA 301 abort code."""
        with self.lock:
            return self._fw.od.read(index, subindex)

    def write(self, index: int, subindex: int, value: int | str) -> None:
        """Write an object; raises SdoAbortError with the CiA 301 abort code."""
        with self.lock:
            self._fw.od.write(index, subindex, value)

    def read_bytes(self, index: int, subindex: int) -> bytes:
        """Read an object encoded per its catalogue data type (little-endian)."""
        with self.lock:
            return self._fw.od.read_bytes(index, subindex)

    def read_values(self, addresses: tuple[tuple[int, int], ...]) -> tuple[int | str, ...]:
        """:meth:`read` of each address, under one lock (the CANopen slave's parameter poll)."""
        with self.lock:
            return self._fw.od.read_all(addresses)

    def read_mapped(self, entries: tuple[tuple[int, int, int], ...]) -> bytes:
        """A PDO's data: the mapped ``(index, subindex, bits)`` objects encoded and joined."""
        with self.lock:
            return self._fw.od.read_mapped(entries)

    def control_mode(self) -> int:
        """0x6043 as :meth:`read` answers it, by one look-up: a PDO's mapping follows it, and
        it is read for every PDO sent or received."""
        with self.lock:
            od = self._fw.od
            value = od.values.get(_CONTROL_MODE)
            if value is None or _CONTROL_MODE in od.getters:  # as read() answers
                value = od.read(*_CONTROL_MODE)
            return int(value)

    def pdo_sampler(self, entries: tuple[tuple[int, int, int], ...]) -> Callable[[], bytes] | None:
        """A function returning :meth:`read_mapped` of ``entries`` the fast way (the compiled
        loop's state read directly, :mod:`.pdo_fast`), or None when the mapping has none.
        Call it with :attr:`lock` held (the CANopen slave does)."""
        from prm9tool.device.emulator import pdo_fast

        with self.lock:
            return pdo_fast.sampler(self._fw, entries)

    def write_mapped(
        self, entries: tuple[tuple[int, int, int], ...], data: bytes
    ) -> list[SdoAbortError]:
        """A received PDO's data into the mapped objects; the aborts of those that refused."""
        with self.lock:
            return self._fw.od.write_mapped(entries, data)

    def read_encoded(self, addresses: Iterable[tuple[int, int]], room: int) -> list[bytes | int]:
        """Encoded values (abort codes for refused entries) that fit ``room`` bytes of a USB
        READ answer (:meth:`.objdict.ObjectDictionary.read_encoded`)."""
        with self.lock:
            return self._fw.od.read_encoded(addresses, room)

    def write_bytes(self, index: int, subindex: int, data: bytes) -> None:
        """Write encoded bytes; a wrong length aborts (LENGTH_TOO_HIGH / LENGTH_TOO_LOW)."""
        with self.lock:
            self._fw.od.write_bytes(index, subindex, data)

    def store(self) -> None:
        """RAM → non-volatile image (and the nv_path file, atomically)."""
        self.write(0x1010, 1, SAVE_SIGNATURE)

    def restore_factory(self) -> None:
        """Non-volatile image ← factory defaults; effective after the next restart."""
        self.write(0x1011, 1, LOAD_SIGNATURE)

    def reload(self) -> None:
        """Working parameters ← non-volatile image, without a restart (the valve keeps running)."""
        with self.lock:
            self._fw.reload()

    def restart(self) -> None:
        """Power cycle: RAM ← NV image, switches re-read, boot timeline replayed."""
        with self.lock:
            self._fw.power_up()
            for listener in self._restart_listeners:
                listener()

    # --- listeners (the CANopen slave's and the USB firmware's hooks) -------------------
    def add_cycle_listener(
        self, fn: Callable[[float], None], quiet: Callable[[int], int] | None = None
    ) -> None:
        """``fn(sim_time)`` every 1 ms of simulated time (loop thread, lock held).

        ``quiet(first_ms)``: how many 1 ms tasks from the one at ``first_ms`` (simulated ms
        since power-up, as :attr:`tick_ms` counts) on ``fn`` would pass doing nothing; the
        compiled kernel may pass those itself, without calling ``fn`` (:mod:`.fasttick`).
        Without it every 1 ms task runs in Python while ``fn`` is registered."""
        with self.lock:  # a new list: a listener may add or remove one while they are called
            self._fw.cycle_listeners = [*self._fw.cycle_listeners, fn]
            if quiet is not None:
                self._fw.cycle_quiet = {**self._fw.cycle_quiet, fn: quiet}

    def remove_cycle_listener(self, fn: Callable[[float], None]) -> None:
        """Stop calling ``fn`` (no error if it is not registered). Without listeners, the
        compiled kernel may pass the 1 ms tasks that change nothing itself (fasttick)."""
        with self.lock:
            self._fw.cycle_listeners = [f for f in self._fw.cycle_listeners if f != fn]
            self._fw.cycle_quiet = {f: q for f, q in self._fw.cycle_quiet.items() if f != fn}

    @property
    def tick_ms(self) -> int:
        """The simulated millisecond of the last 1 ms task since power-up (those the compiled
        kernel passed included): what a cycle listener was last, or would have been, given."""
        return self._fw.ticks

    def add_error_listener(self, fn: Callable[[int, int], None]) -> None:
        """``fn(emcy_code, error_register)`` on every change of the active error set."""
        with self.lock:
            self._fw.faults.listeners.append(fn)

    def add_error_cause_listener(self, fn: Callable[[int, int, ErrorKind | None], None]) -> None:
        """``fn(emcy_code, error_register, kind)`` with each EMCY: ``kind`` is the error that
        raised it (its ``text`` names the cause: several share 8100h), None when all cleared."""
        with self.lock:
            self._fw.faults.cause_listeners.append(fn)

    def add_restart_listener(self, fn: Callable[[], None]) -> None:
        """``fn()`` after every power cycle."""
        with self.lock:
            self._restart_listeners.append(fn)

    # --- CANopen (the part :attr:`canopen`; these read it for the program) -------------
    @property
    def node_id(self) -> int:
        """CANopen node ID latched at power-up (0 on a valve without -CA)."""
        return self._fw.node_id

    @property
    def bitrate(self) -> int:
        """CAN bit rate latched at power-up in bit/s (0 when CANopen is off)."""
        return self._fw.bitrate

    @property
    def can_enabled(self) -> bool:
        """True on a -CA valve whose interface switch enables CANopen."""
        return self._fw.can_enabled

    @property
    def lss_mode(self) -> bool:
        """Node-ID switch at 1 at power-up: node ID by LSS, automatic bit rate (table 7-17)."""
        return self._fw.lss_mode

    def nmt_command(self, command: int) -> None:
        """An NMT command from the USB side (:meth:`.valve_canopen.CanopenSide.nmt_command`)."""
        self.canopen.nmt_command(command)

    def nmt_event(self, event: str) -> None:
        """An NMT state change or communication error as the CANopen slave reports it (how a
        test causes one: docs/emulator.md, the fault table): :attr:`canopen`'s."""
        self.canopen.nmt_event(event)

    # --- simulation -------------------------------------------------------------------
    @property
    def plant(self) -> PlantConstants:
        """The plant constants this valve runs on (a twin's: its twin file's)."""
        return self._fw.plant

    @property
    def time(self) -> float:
        """Simulated seconds since the last power-up."""
        return self._fw.time

    def advance(self, seconds: float) -> None:
        """Run the firmware for ``seconds`` of simulated time (rounded to whole cycles)."""
        if seconds < 0:
            raise ValueRangeError(f"advance: {seconds} s is negative")
        cycles = round(seconds / CYCLE_S)
        done = 0
        while done < cycles:
            batch = min(cycles - done, 5000)
            with self.lock:
                self._fw.run(batch)
                self._capture.trim()
            done += batch

    def start(self) -> None:
        """Run paced to the wall clock in a background thread."""
        with self.lock:
            if self._thread is not None or self._grouped:
                return
            self._stop.clear()
            self.pacer.reset()
            self._thread = threading.Thread(target=self._paced, name="prm9-emulator", daemon=True)
            self._thread.start()

    def stop(self) -> None:
        """Stop the paced thread (returns when it has ended)."""
        thread = self._thread
        if thread is None:
            return
        self._stop.set()
        if thread is threading.current_thread():
            self._thread = None  # called from a listener inside the loop: ends after this batch
            return
        thread.join()
        self._thread = None

    @property
    def running(self) -> bool:
        """True while the valve runs in real time (its paced thread, or a PacedGroup's)."""
        return self._thread is not None or self._grouped

    def paced_step(self) -> float:
        """Run the cycles due at this wall-clock moment; returns the seconds until the next
        batch is due (0: call again at once). The paced thread's step, and a
        :class:`~.paced_group.PacedGroup`'s for each of its valves."""
        pacer = self.pacer
        with self.lock:  # the pacer too: a SYNC may run the cycles due by it (run_due_by)
            due = pacer.due()
            if due == 0:
                return pacer.wait_s()
            self._fw.run(due)
            self._capture.trim()
            pacer.done(due)
        return 0.0

    def run_due_by(self, at: float) -> int:
        """While running in real time: the cycles of the present batch due by ``at``
        (``time.monotonic``), run now; returns how many. The CANopen slave's SYNC: the batch
        of 2 ms or more would let several SYNCs of 1 ms sample the same state, where a real
        valve's TPDO carries a value of the moment the SYNC came (issue 30). Nothing when the
        simulation is behind the wall clock (:meth:`.pacing.Pacer.due_by`): its batches catch
        up, frames first."""
        with self.lock:
            if not self.running:
                return 0
            due = self.pacer.due_by(at)
            if due:
                self._fw.run(due)
                self._capture.trim()
                self.pacer.done(due)
            return due

    def paced_by_group(self, grouped: bool) -> None:
        """A :class:`~.paced_group.PacedGroup` paces this valve from now on (True: a new time
        base at this moment, batches of :data:`~.pacing.GROUPED_MIN_BATCH` cycles) or no
        longer (False)."""
        with self.lock:
            if grouped and self._thread is not None:
                raise RuntimeError("the valve already runs in its own paced thread")
            if grouped and not self._grouped:
                self.pacer.reset()
            self.pacer.min_batch = GROUPED_MIN_BATCH if grouped else self._own_min_batch
            self._grouped = grouped

    def _paced(self) -> None:
        while not self._stop.is_set():
            wait = self.paced_step()
            if wait:
                self._stop.wait(wait)

    # --- inputs and faults ------------------------------------------------------------
    def set_input(self, name: str, value: float) -> None:
        """Set an input: see INPUT_NAMES (switches are read at power-up only)."""
        if name not in INPUT_NAMES:
            raise ValueRangeError(f"unknown input {name!r}; inputs are: {', '.join(INPUT_NAMES)}")
        value = float(value)
        if not math.isfinite(value):
            raise ValueRangeError(f"{name}: {value} is not a finite number")
        with self.lock:
            if name.startswith("switch_"):
                if not (0 <= value <= 15 and value.is_integer()):
                    raise ValueRangeError(f"{name}: {value:g} is not a switch position 0…15")
                self._fw.switches[0 if name == "switch_baud" else 1] = int(value)
                return
            self._fw.inputs[name] = value
            self._fw.setpoint_dirty = True
            if name == "supply_voltage":
                self._fw.config_dirty = True

    def inputs(self) -> dict[str, float]:
        """The analog inputs as set (see :meth:`set_input`; switches: :attr:`switches`)."""
        with self.lock:
            return dict(self._fw.inputs)

    @property
    def switches(self) -> tuple[int, int]:
        """The rotary switch positions (interface/bit rate, node ID) as set now."""
        return self._fw.switches[0], self._fw.switches[1]

    @property
    def latched_switches(self) -> tuple[int, int]:
        """The rotary switch positions the valve read at its last power-up."""
        return self._fw.latched_switches

    def injected(self) -> frozenset[Fault]:
        """The physical faults injected now."""
        with self.lock:
            return frozenset(self._fw.injected)

    def inject(self, fault: Fault) -> None:
        """Make the physical fault happen (see docs/emulator.md for what each one does)."""
        fault = _fault(fault)
        with self.lock:
            self._fw.injected.add(fault)
            self._fw.setpoint_dirty = self._fw.config_dirty = True

    def clear(self, fault: Fault) -> None:
        """Remove an injected physical fault; the firmware recovers by itself."""
        fault = _fault(fault)
        with self.lock:
            self._fw.injected.discard(fault)
            self._fw.setpoint_dirty = self._fw.config_dirty = True

    def drive_override(self, source: Source | None) -> None:
        """Apply ``source`` (times in s since now → SETPOVR raw values) to the setpoint
        override on the valve's own clock, exact to the cycle (None: stop). It counts while
        SETPOVRON = 1; a power cycle ends it."""
        with self.lock:
            self._fw.program = (
                OverrideProgram(source, self._fw.cycles) if source is not None else None
            )

    def usb_activity(self) -> None:
        """Called by the USB firmware for every report it receives and by the CANopen slave
        for every SDO request (the setpoint override's watchdog).

        The report counts at the moment it came: when the paced thread is behind the wall
        clock (held up by the GIL or a loaded PC, it then catches up in a burst), that is the
        simulated time the valve will reach at that moment, not the stalled one; otherwise
        the burst would pass the watchdog's 0.5 s with no report interleaved, an artefact a
        real valve, on its own clock, does not have."""
        with self.lock:
            behind = min(self.pacer.lag_s(), self.pacer.max_lag_s) if self.running else 0.0
            self._fw.override_last = self._fw.time + max(0.0, behind)

    # --- measuring points -------------------------------------------------------------
    def signal(self, key: str) -> float:
        """Latest raw value of a measuring point (prm9tool.catalogue.signals key)."""
        if key not in BY_KEY:
            raise ValueRangeError(f"unknown measuring point {key!r}")
        with self.lock:
            return self._fw.signal_values()[key]

    def capture_start(self, keys: Sequence[str], decimation: int = 1) -> None:
        """Record up to three measuring points every ``decimation`` cycles."""
        with self.lock:
            self._capture.start(keys, decimation)

    def capture_read(self) -> np.ndarray:
        """Drain the capture buffer: shape (n, len(keys)), raw values."""
        with self.lock:
            return self._capture.read()

    def capture_stop(self) -> None:
        """Stop recording (the buffer is discarded)."""
        with self.lock:
            self._capture.stop()

    # --- status -----------------------------------------------------------------------
    def status(self) -> ValveStatus:
        """Snapshot of state, errors, LEDs, temperature and supply."""
        with self.lock:
            fw = self._fw
            active = fw.faults.active
            text = active[0].text if active else (WARNING_TEXT if fw.warning else "")
            return ValveStatus(
                device_state=fw.sm.state,
                error_code=fw.faults.code(),
                error_text=text,
                warning=fw.warning,
                active_errors=tuple(dict.fromkeys(k.code for k in active)),
                error_register=fw.faults.register(),
                leds=leds(
                    fw.time, fw.booting, self.variant.canopen, fw.nmt_state, active, fw.warning
                ),
                temperature_c=fw.temperature,
                supply_v=fw.supply,
                nmt_state=fw.nmt_state,
                booting=fw.booting,
            )

    @property
    def device_state(self) -> DeviceState:
        """Current CiA 408 device state."""
        return self._fw.sm.state

    # --- on a CAN bus -------------------------------------------------------------------
    def connect_can(self, bus: can.BusABC, receive: bool = True) -> CanopenSlave:
        """Put the valve on a python-can bus; AccessDeniedError on a valve without -CA.
        ``receive=False``: no receive thread of its own, a
        :class:`~.canopen_hub.SharedBus` attached to it hands it the frames."""
        if not self.variant.canopen:
            raise AccessDeniedError(f"{self.type_key} has no CANopen interface (no -CA suffix)")
        from prm9tool.device.emulator.canopen_slave import CanopenSlave

        return CanopenSlave(self, bus, receive)


def _fault(fault: Fault | str) -> Fault:
    try:
        return Fault(fault)
    except ValueError:
        names = ", ".join(f.value for f in Fault)
        raise ValueRangeError(f"unknown fault {fault!r}; faults are: {names}") from None
