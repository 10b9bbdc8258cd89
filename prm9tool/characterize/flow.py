"""E04: the flow characteristic (the actuator's velocity over the spool's opening).

In control mode 4 the process PIDT1 drives the spool. With that controller made proportional
(Ki = Kd = 0, the valve's own Kp) and the dead-band offsets at 0, a process setpoint step from
``centre − amplitude`` to ``centre + amplitude`` opens the spool fully and lets it close as the
actuator approaches: the spool's opening sweeps from 100 % through the working range down to
the edge of the dead band, where the actuator stops. The step back sweeps the negative side.
Spool position and process value are recorded in the same firmware cycle, so each sample is
one point of velocity over opening — the characteristic a spool-position setpoint would give
in control mode 2 (there the spool follows its setpoint), measured without switching the
control mode (which an analog-only valve allows only outside DEVICE_MODE_ACTIVE). The
controller parameters, the chain and the offsets are put back afterwards in every case.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from prm9tool.analysis.deadband import deviation_offset
from prm9tool.analysis.flow import FlowCharacteristic, flow_characteristic, velocity
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Coils, Config
from prm9tool.characterize.frame import Record, chain_changes, preserved, record
from prm9tool.characterize.rig import Rig
from prm9tool.errors import Prm9Error
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

QUASI_STATIC_PCT_S = 1500.0  # opening changing faster than this: a transition, not a point
FLOW_KEYS = ("position_setpoint", "process_actual", "position_actual")  # [1]: band check


@dataclass(frozen=True)
class FlowResult:
    """The two steps' record, the velocity, the characteristic and the offsets it proposes."""

    record: Record
    velocity: np.ndarray  # %/s, per sample
    characteristic: FlowCharacteristic
    kp: float  # the process controller's Kp during the test
    offsets: dict[str, int]  # OFFSETPOS/OFFSETNEG that jump over the dead band (deviation)


FLOW_PARAMETERS = ("CTRLMODE", "PRCKP", "PRCKI", "PRCKD", "OFFSETPOS")


def flow_objects_missing(rig: Rig) -> Message | str:
    """Why the flow test cannot run on this valve ("" when it can): it sets the process
    controller's gains, which a valve with only the manual's CANopen objects does not have."""
    absent = [name for name in FLOW_PARAMETERS if name not in rig.read(list(FLOW_PARAMETERS))]
    if not absent:
        return ""
    return QT_TRANSLATE_NOOP(
        "Characterize",
        "flow characteristic not measured: this valve has no object for {0} over this "
        "link (measure it over USB)",
    )(", ".join(absent))


def flow_test(
    rig: Rig, amplitude_pct: float = 40.0, centre_pct: float = 0.0, duration_s: float = 1.0
) -> FlowResult:
    """Steps of the process setpoint ``centre ∓ amplitude`` (see the module docstring)."""
    key = TypeKey.parse(rig.info.type_key)
    if key.variant.config is not Config.E04:
        raise Prm9Error(
            QT_TRANSLATE_NOOP(
                "Characterize",
                "the flow characteristic is measured on E04 valves (with an actuator)",
            )()
        )
    missing = flow_objects_missing(rig)
    if missing:
        raise Prm9Error(missing)
    present = rig.read(["CTRLMODE", "PRCKP"])
    if "PRCKP" not in present:  # a valve without this project's objects on this link (CAN)
        raise Prm9Error(
            QT_TRANSLATE_NOOP(
                "Characterize",
                "this valve has no object for the process controller's gains on this link: "
                "the flow characteristic (made proportional for the test) cannot be measured "
                "here; nothing was changed — measure it over USB",
            )()
        )
    if present["CTRLMODE"] != 4:
        raise Prm9Error(
            QT_TRANSLATE_NOOP(
                "Characterize",
                "the flow characteristic is measured in control mode 4 (process loop); the "
                "valve is in control mode {0}",
            )(present["CTRLMODE"])
        )
    if present["PRCKP"] <= 0:
        raise Prm9Error(
            QT_TRANSLATE_NOOP(
                "Characterize", "the process controller's Kp is 0: the spool would not move"
            )()
        )
    two_coils = key.variant.coils is Coils.AB
    changes = {**chain_changes(rig, "process"), "PRCKI": 0, "PRCKD": 0, "OFFSETPOS": 0}
    if two_coils:
        changes["OFFSETNEG"] = 0
    fs = rig.info.sample_rate_hz
    n = int(duration_s * fs)
    low, high = centre_pct - amplitude_pct, centre_pct + amplitude_pct
    if not two_coils:  # one coil: the spring returns the actuator, the spool opens one way
        low = max(low, 0.0)
    stimulus = np.concatenate([np.full(n, high), np.full(n, low)])
    with preserved(rig, [], changes):
        rig.play(np.full(n, low), [FLOW_KEYS[1]], gaps=True)  # settle at the start
        rec = record(rig, stimulus, list(FLOW_KEYS), centre_pct, amplitude_pct + 15.0)
    return flow_result(rec, fs, present["PRCKP"])


def flow_result(rec: Record, fs: float, prckp_raw: int) -> FlowResult:
    """The flow test's analysis of its record (``process_actual`` and ``position_actual`` at
    ``fs``) with the process controller's Kp (raw PRCKP) it ran with — the test's and a
    report's read back (:mod:`prm9tool.twin.report`)."""
    speed = velocity(rec.channels["process_actual"], fs)
    opening = rec.channels["position_actual"]
    # the spool crossing its dead band at a step is not a flow point: the smoothed velocity
    # lags it there; only samples where the spool moves slowly enough count
    steady = np.abs(velocity(opening, fs)) < QUASI_STATIC_PCT_S
    flow = flow_characteristic(opening[steady], speed[steady])
    kp = prckp_raw * CATALOGUE["PRCKP"].scale
    return FlowResult(rec, speed, flow, kp, deviation_offset(flow.band, kp))
