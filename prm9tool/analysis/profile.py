"""Acceptance profiles: which tests an end-of-line characterization runs and the limits.

A profile is a TOML file (docs/tuning.md shows every key)::

    name = "PRM9-06 end of line"
    [test]
    step_amplitudes_pct = [5, 25, 90]
    [limits]
    step_overshoot_pct = { max = 15 }
    bode_bandwidth_hz = { min = 20 }

Any key left out keeps its default; a limit left out is not checked. A figure that could not be
measured (a step that never settles) fails a limit set on it.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from prm9tool.errors import Prm9Error
from prm9tool.messages import QT_TRANSLATE_NOOP

FIGURES = {  # figure name: unit (step figures are checked for every step amplitude)
    "step_overshoot_pct": "%",
    "step_rise_s": "s",
    "step_settling_s": "s",
    "bode_bandwidth_hz": "Hz",
    "bode_phase90_hz": "Hz",
    "static_gain": "",
    "static_hysteresis_pct": "%",
    "static_linearity_pct": "%",
    "static_dead_band_pct": "%",
    "flow_gain": "%/s per %",  # E04 in control mode 4 only
    "flow_dead_band_pct": "%",
}


class ProfileError(Prm9Error):
    """An acceptance profile cannot be used; the message names the file and the key."""

    summary = QT_TRANSLATE_NOOP("Errors", "The acceptance profile cannot be used.")


@dataclass(frozen=True)
class Limit:
    """Allowed range of one figure (None: that side is not checked)."""

    minimum: float | None = None
    maximum: float | None = None

    def passed(self, value: float) -> bool:
        """True when ``value`` is a number within the range."""
        if math.isnan(value):
            return False
        low = self.minimum is None or value >= self.minimum
        return low and (self.maximum is None or value <= self.maximum)

    def text(self) -> str:
        """``≥ a``, ``≤ b`` or ``a … b``."""
        if self.minimum is not None and self.maximum is not None:
            return f"{self.minimum:g} … {self.maximum:g}"
        if self.minimum is not None:
            return f"≥ {self.minimum:g}"
        return f"≤ {self.maximum:g}" if self.maximum is not None else "—"


@dataclass(frozen=True)
class Profile:
    """What to run and the limits (the defaults suit a PRM9-06 on the emulator's plant)."""

    name: str = "default"
    step_amplitudes_pct: tuple[float, ...] = (5.0, 25.0, 90.0)
    step_duration_s: float = 0.15
    bode_amplitude_pct: float = 10.0
    bode_f_min_hz: float = 1.0
    bode_f_max_hz: float = 200.0
    bode_duration_s: float = 10.0
    static_period_s: float = 20.0
    flow_amplitude_pct: float = 40.0  # E04: process setpoint steps centre ∓ this
    flow_duration_s: float = 1.0
    limits: dict[str, Limit] = field(default_factory=dict)


DEFAULT_LIMITS = {
    "step_overshoot_pct": Limit(maximum=15.0),
    "step_rise_s": Limit(maximum=0.03),
    "bode_bandwidth_hz": Limit(minimum=15.0),
    "static_gain": Limit(0.95, 1.05),
    "static_hysteresis_pct": Limit(maximum=2.0),
    "static_linearity_pct": Limit(maximum=2.0),
}
DEFAULT = Profile(limits=DEFAULT_LIMITS)
_TEST_KEYS = {f.name for f in fields(Profile)} - {"name", "limits"}


def load_profile(path: str | Path) -> Profile:
    """Read a TOML profile; ProfileError names the problem."""
    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except OSError as exc:
        raise ProfileError(f"cannot read the profile {path}: {exc.strerror or exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise ProfileError(f"{path}: not valid TOML: {exc}") from None
    return parse_profile(data, str(path))


def parse_profile(data: dict[str, Any], where: str = "profile") -> Profile:
    """A profile from parsed TOML (see the module docstring)."""
    unknown = set(data) - {"name", "test", "limits"}
    if unknown:
        raise ProfileError(f"{where}: unknown key {sorted(unknown)[0]!r} (name, [test], [limits])")
    changes: dict[str, Any] = {"name": str(data.get("name", Path(where).stem))}
    for key, value in data.get("test", {}).items():
        if key not in _TEST_KEYS:
            raise ProfileError(f"{where}: [test] has no key {key!r}")
        changes[key] = _number(where, key, value)
    limits = dict(DEFAULT_LIMITS)
    for key, value in data.get("limits", {}).items():
        if key not in FIGURES:
            raise ProfileError(
                f"{where}: [limits] has no figure {key!r}; figures: {', '.join(FIGURES)}"
            )
        if not isinstance(value, dict) or not set(value) <= {"min", "max"}:
            raise ProfileError(f"{where}: [limits] {key} must be {{ min = …, max = … }}")
        lo, hi = value.get("min"), value.get("max")
        limits[key] = Limit(
            None if lo is None else float(_number(where, key, lo)),
            None if hi is None else float(_number(where, key, hi)),
        )
    return replace(DEFAULT, limits=limits, **changes)


def _number(where: str, key: str, value: Any) -> Any:
    if isinstance(value, list):
        if not value or not all(_is_number(v) for v in value):
            raise ProfileError(f"{where}: {key} must be a list of numbers")
        return tuple(float(v) for v in value)
    if not _is_number(value) or (value <= 0 and key.endswith(("_s", "_hz"))):
        raise ProfileError(f"{where}: {key} must be a positive number, not {value!r}")
    return float(value)


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)
