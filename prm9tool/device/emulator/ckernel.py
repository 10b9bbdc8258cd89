"""The compiled control loop behind the reference loop's interface (docs/emulator.md).

:class:`CompiledLoop` is driven exactly like :func:`.kernel.control_loop`'s generator
(``send(n)`` runs ``n`` cycles, ``send(0)`` writes every measuring point back) and reads and
writes the same :class:`~.loopstate.LoopState`; the cycles themselves run in the C extension
``_ckernel`` on flat arrays of doubles, without the GIL (batches of 100 cycles or more). What
happens between batches (reading new coefficients and inputs, the bumpless start of the ramp,
the write-back) stays here, in the same order as in the reference.
"""

from __future__ import annotations

from array import array
from hashlib import sha256
from pathlib import Path
from typing import Any

from prm9tool.catalogue.signals import MAX_CHANNELS
from prm9tool.device.emulator import _ckernel, fasttick  # type: ignore[attr-defined]
from prm9tool.device.emulator.constants import FULL, TICK_CYCLES
from prm9tool.device.emulator.loopstate import MODE_ACTIVE, MODE_OFF, LoopState

# Slots of the flat arrays; the order is the C enums' (_ckernel.c).
STATE = [
    "r",
    "x",
    "v",
    "act",
    "ia",
    "ib",
    "f",
    "ia_i",
    "ib_i",
    "p_int",
    "p_d",
    "p_prev",
    "q_int",
    "q_d",
    "q_prev",
    "ph",
    "cap_count",
    "w",
    "u",
    "ca",
    "cb",
    "ka",
    "kb",
    "da",
    "db",
    "xm",
    "pe",
    "s0",
    "s1",
    "s2",
    "s3",
    "pv",
    "dev",
    "dg",
]
S = {name: i for i, name in enumerate(STATE)}
SCALARS = [
    "e04",
    "process_on",
    "two",
    "only_b",
    "rpu",
    "rpd",
    "rnu",
    "rnd",
    "pkp",
    "pki",
    "pkd",
    "pt1",
    "qkp",
    "qki",
    "qkd",
    "qt1",
    "out_lo",
    "kcur",
    "lim_a",
    "lim_b",
    "damp",
    "dph",
    "ckp",
    "cki",
    "rff_a",
    "rff_b",
    "vmax_i",
    "kf",
    "ks",
    "cd",
    "fc",
    "fs",
    "im",
    "h",
    "nsub",
    "xmax",
    "flag",
    "kx",
    "lvdt_q",
    "lvdt_lo",
    "lvdt_ma_k",
    "lvdt_sat",
    "s_a",
    "s_b",
    "s_q",
    "s_o",
    "sinv",
    "soffs",
    "sgain",
    "slin",
    "gp",
    "op",
    "gn",
    "on",
    "act_k",
    "overlap",
    "act_ret",
    "full",
    "sl_n",
]
CURVE = _ckernel.CURVE_POINTS  # room per curve array
INPUTS = [
    "mode",
    "tgt",
    "vs",
    "inv_vs",
    "short_a",
    "short_b",
    "on_a",
    "on_b",
    "aa",
    "ba",
    "ab",
    "bb",
    "lvdt_break",
    "plant_sensor",
    "s_static",
    "active",
    "process",
    "stat0",
    "stat1",
    "stat2",
    "stat3",
    "temp10",
    "cap_on",
    "cap_dec",
    "cap0",
    "cap1",
    "cap2",
]
if (
    len(STATE) != _ckernel.STATE_COUNT
    or len(SCALARS) + 3 * CURVE + 2 != _ckernel.COEFFICIENT_COUNT
    or len(INPUTS) != _ckernel.INPUT_COUNT
):
    raise ImportError("_ckernel was built from another version of the layout: rebuild it")
_SOURCE = Path(__file__).with_name("_ckernel.c")  # absent in a wheel or a bundled program
_BUILT_FROM = getattr(_ckernel, "SOURCE_HASH", None)
if _SOURCE.exists() and sha256(_SOURCE.read_bytes()).hexdigest()[:16] != _BUILT_FROM:
    raise ImportError("_ckernel is older than _ckernel.c: rebuild it")
if (fasttick.TICK_RISE, fasttick.TICK_TEMPERATURE, fasttick.TICK_DEADLINES) != (
    _ckernel.TICK_RISE,
    _ckernel.TICK_TEMPERATURE,
    _ckernel.TICK_DEADLINES,
) or fasttick.TICK_DEADLINES + 3 * fasttick.MAX_DEADLINES != _ckernel.TICK_COUNT:
    raise ImportError("_ckernel was built from another version of the tick layout: rebuild it")
_X, _V, _ACT, _R, _PV, _XM = S["x"], S["v"], S["act"], S["r"], S["pv"], S["xm"]
_IA, _IB, _DA, _DB, _DEV = S["ia"], S["ib"], S["da"], S["db"], S["dev"]


def coefficient_array(c: dict[str, Any]) -> array:
    """The coefficients of :func:`.config.coefficients` in the C layout."""
    coils = c["coils"]
    two = coils == "AB"
    sl_x, sl_k, sl_b = c["sensor_curve"]
    if len(sl_x) > CURVE - 1:
        raise ValueError(f"sensor curve of {len(sl_x)} points; the compiled loop holds {CURVE - 1}")
    values = [
        c["e04_plant"],
        c["process_loop"],
        two,
        coils == "B",
        *c["ramp_steps"],
        *c["position_pid"],
        *c["process_pid"],
        0.0 if not two else -FULL,
        c["ma_per_count"],
        *c["limits_ma"],
        *c["dither"],
        *c["current_pi"],
        c["max_current_v"],
        *c["mechanics"][:10],
        *c["lvdt"],
        *c["sensor"],
        *c["deviation_gain"],
        *c["actuator"],
        FULL,
        len(sl_x),
    ]
    # mechanics: kf ks cd fc fs im h nsub xmax flag (nsub is an int: exact in a double)
    pad = [0.0] * (CURVE - len(sl_x))
    values += [*sl_x, *pad, *sl_k, *pad[1:], 0.0, *sl_b, *pad[1:], 0.0]
    out = array("d", [float(v) for v in values])
    assert len(out) == _ckernel.COEFFICIENT_COUNT
    return out


class CompiledLoop:
    """The control loop with its cycles in C (same protocol as the reference generator)."""

    def __init__(self, s: LoopState) -> None:
        self.s = s
        st = array("d", bytes(8 * len(STATE)))
        st[_X], st[_V], st[_ACT] = s.spool_m, s.spool_v, s.actuator
        self.state = st
        self.inputs = array("d", bytes(8 * len(INPUTS)))
        self.coef = array("d")
        self.coef_of: dict[str, Any] | None = None  # the coefficients ``coef`` was built from
        self.version = -1
        self.inputs_version = -1
        self.last_mode = MODE_OFF
        self.process_on = False
        self.lvdt_ma_k = self.lvdt_sat = 0.0
        self.stat: tuple[float, ...] = (0.0, 0.0, 0.0, 0.0)
        self.vs = self.temp10 = 0.0
        self.lvdt_break = False
        self.cap_buffer: Any = None
        self.scratch = array("d")

    # the generator protocol Firmware uses
    def __next__(self) -> None:
        """Start, as ``next()`` starts the reference generator (it reads the plant state)."""
        s, st = self.s, self.state
        st[_X], st[_V], st[_ACT] = s.spool_m, s.spool_v, s.actuator

    def send(self, n: int) -> None:
        """Run ``n`` cycles (``n`` ≤ 5, the 1 ms task's period); ``0`` = write everything back."""
        self.prepare()
        if n:
            self.cycles(n, TICK_CYCLES, None)
        else:
            self.flush()
        self.write_back()

    def prepare(self) -> None:
        """Pick up new coefficients and inputs, as the reference does at the start of a batch."""
        s = self.s
        if s.version != self.version:
            c = s.coefficients
            self.version = s.version
            if c is not self.coef_of:  # the firmware's memo hands back the same coefficients
                self.coef, self.coef_of = coefficient_array(c), c
            self.process_on = bool(c["process_loop"])
            if not self.process_on:
                self.state[S["dev"]] = self.state[S["dg"]] = 0.0
            _, _, _, lvdt_ma_k, lvdt_sat = c["lvdt"]
            self.lvdt_ma_k, self.lvdt_sat = lvdt_ma_k, lvdt_sat
            self.inputs_version = -1
        if s.inputs_version != self.inputs_version:
            self._read_inputs()

    def _read_inputs(self) -> None:
        s, st, c = self.s, self.state, self.s.coefficients
        self.inputs_version = s.inputs_version
        mode = s.mode
        vs = s.supply_v
        open_a, open_b = s.coil_open
        short_a, short_b = s.coil_short
        on_a, on_b = s.stage_on
        aa_c, ba_c, ab_c, bb_c = c["coil_discrete"]
        plant_sensor = s.sensor_from_plant
        s_static = s.sensor_static
        if s.sensor_break_value is not None:
            plant_sensor = False
            s_static = s.sensor_break_value
        active = mode == MODE_ACTIVE
        process = self.process_on and active
        if active and self.last_mode != MODE_ACTIVE:
            st[_R] = st[_PV] if process else st[_XM]  # bumpless, as the reference
        self.last_mode = mode
        if mode == MODE_OFF:
            for name in ("ia_i", "ib_i", "p_int", "p_d", "p_prev"):
                st[S[name]] = 0.0
        if not process:
            for name in ("q_int", "q_d", "q_prev"):
                st[S[name]] = 0.0
        self.stat = stat = s.static_signals
        self.vs = vs
        self.temp10 = s.temperature_c * 10.0
        self.lvdt_break = s.lvdt_break
        cap = s.capture
        index: list[int] = [0, 0, 0]
        if cap is not None:
            _, _, cap_dec, self.cap_buffer, index = cap
        self.inputs = array(
            "d",
            [
                mode,
                s.target,
                vs,
                1.0 / vs if vs > 0.5 else 2.0,
                short_a,
                short_b,
                on_a,
                on_b,
                0.0 if open_a else aa_c,
                0.0 if open_a else ba_c,
                0.0 if open_b else ab_c,
                0.0 if open_b else bb_c,
                s.lvdt_break,
                plant_sensor,
                s_static,
                active,
                process,
                *stat,
                self.temp10,
                cap is not None,
                cap_dec if cap is not None else 1,
                *index[:MAX_CHANNELS],
            ],
        )

    def cycles(
        self, n: int, countdown: int, tick: array | None, program: Any = None
    ) -> tuple[int, int, int]:
        """Run up to ``n`` cycles in C (see ``_ckernel.run``): (cycles, no-op 1 ms tasks passed,
        cycles to the next 1 ms task; 0 = it is due and left to the caller).

        ``program``: the static setpoint chain per cycle (a C-contiguous float array of ``n``
        rows raw, threshold, gain, linearized), or None for the inputs' values.
        """
        if len(self.scratch) < MAX_CHANNELS * n:
            self.scratch = array("d", bytes(8 * MAX_CHANNELS * n))
        done, ticks, samples, countdown = _ckernel.run(
            self.state, self.coef, self.inputs, n, countdown, tick, self.scratch, program
        )
        if samples:
            self.cap_buffer.extend(self.scratch[: MAX_CHANNELS * samples])
        return done, ticks, countdown

    def flush(self) -> None:
        """Every measuring point and the plant state to the mailbox (the reference's send(0))."""
        s, st = self.s, self.state
        stat = self.stat
        s.signals = (
            *stat,
            st[_R],
            st[_R],
            st[_PV],
            st[S["dg"]],
            st[S["w"]],
            st[_XM],
            st[S["pe"]],
            st[S["u"]],
            st[S["ca"]],
            st[S["cb"]],
            st[_IA],
            st[_IB],
            st[_DA] * 10000.0,
            st[_DB] * 10000.0,
            self.vs * 1000.0,
            self.temp10,
            st[S["s0"]],
        )
        s.spool_m, s.spool_v, s.actuator = st[_X], st[_V], st[_ACT]
        s.sensor_chain = (st[S["s0"]], st[S["s1"]], st[S["s2"]], st[S["s3"]], st[_PV])

    def write_back(self) -> None:
        """What the 1 ms task reads after every batch, as the reference writes it."""
        s, st = self.s, self.state
        s.ctrl_dev = st[_DEV] if self.process_on else st[_R] - st[_XM]
        s.current_ma = (st[_IA], st[_IB])
        s.duty = (st[_DA], st[_DB])
        if self.lvdt_break:
            s.lvdt_ma = 0.0
        else:
            lvdt_ma = 12.0 + st[_X] * self.lvdt_ma_k
            s.lvdt_ma = lvdt_ma if lvdt_ma > self.lvdt_sat else self.lvdt_sat
