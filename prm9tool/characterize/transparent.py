"""The parameter values that take the setpoint chain out of a measurement, so a test sees the
control loop itself (manual fig. 8-18): no threshold, linearization or ramps, unity gain and
no offset. The procedures here and the step-response simulator (online/tuning.py) use them."""

from __future__ import annotations

from prm9tool.catalogue.scale import FULL_SCALE

NO_SHAPING: dict[str, int] = {
    "THRESETP": 0,
    "SETPLINON": 0,
    "RAMPSETPOSUP": 0,
    "RAMPSETPOSDOWN": 0,
    "RAMPSETNEGUP": 0,
    "RAMPSETNEGDOWN": 0,
}
UNITY_GAIN: dict[str, int] = {
    "GAINSETPOS": FULL_SCALE,
    "GAINSETNEG": FULL_SCALE,
    "OFFSETPOS": 0,
    "OFFSETNEG": 0,
}
TRANSPARENT: dict[str, int] = NO_SHAPING | UNITY_GAIN
