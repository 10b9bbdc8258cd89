"""Oscilloscope model: ring buffer, trigger engine, cursors, step-response figures, CSV, generator.

Numpy, no Qt (the widget lives in ``prm9tool/views/scope/``; the generator's messages are
translatable :class:`~prm9tool.messages.Message` templates). Samples arrive from the valve's
stream as raw ``(n, channels)`` blocks; :class:`Capture` converts them to display units once and
appends them to a preallocated :class:`RingBuffer`, so everything downstream (trigger level,
cursors, figures, CSV) works in the units the user sees. Sample ``i`` of a capture lies at
``i / rate`` seconds after the capture started. A link that places its samples by time (over
CANopen by the SYNC count) gives a NaN row for each lost sample: a gap at its time, drawn as a
break in the curve (:func:`curve_points`) and left out of the figures; the USB stream has no gaps
(its lost samples are counted by the session).

The names below load their module on first use (PEP 562): importing one part
(``prm9tool.scope.measure``) loads neither the others nor what they import.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from prm9tool.scope.buffer import (
        BUFFER_S,
        MAX_RATE_HZ,
        RATES_HZ,
        WINDOWS_S,
        Capture,
        RingBuffer,
        axis_ranges,
        curve_points,
        peak_decimate,
    )
    from prm9tool.scope.generator import (
        GeneratorSettings,
        Waveform,
        setpoint_limits,
    )
    from prm9tool.scope.measure import (
        StepFigures,
        StepMeasurement,
        Verdict,
        measure_step,
        step_figures,
    )
    from prm9tool.scope.readout import CursorReadout, cursor_readout, write_csv
    from prm9tool.scope.steps import Step, find_step, find_steps
    from prm9tool.scope.trigger import (
        Edge,
        Frame,
        TriggerEngine,
        TriggerMode,
        TriggerSettings,
        find_edge,
    )

__all__ = [
    "BUFFER_S",
    "MAX_RATE_HZ",
    "RATES_HZ",
    "WINDOWS_S",
    "Capture",
    "CursorReadout",
    "Edge",
    "Frame",
    "GeneratorSettings",
    "RingBuffer",
    "Step",
    "StepFigures",
    "StepMeasurement",
    "TriggerEngine",
    "TriggerMode",
    "TriggerSettings",
    "Verdict",
    "Waveform",
    "axis_ranges",
    "cursor_readout",
    "curve_points",
    "find_edge",
    "find_step",
    "find_steps",
    "measure_step",
    "peak_decimate",
    "setpoint_limits",
    "step_figures",
    "write_csv",
]

_WHERE = {
    name: module
    for module, names in {
        "buffer": (
            "BUFFER_S",
            "MAX_RATE_HZ",
            "RATES_HZ",
            "WINDOWS_S",
            "Capture",
            "RingBuffer",
            "axis_ranges",
            "curve_points",
            "peak_decimate",
        ),
        "generator": (
            "GeneratorSettings",
            "Waveform",
            "setpoint_limits",
        ),
        "measure": (
            "StepFigures",
            "StepMeasurement",
            "Verdict",
            "measure_step",
            "step_figures",
        ),
        "readout": ("CursorReadout", "cursor_readout", "write_csv"),
        "steps": ("Step", "find_step", "find_steps"),
        "trigger": (
            "Edge",
            "Frame",
            "TriggerEngine",
            "TriggerMode",
            "TriggerSettings",
            "find_edge",
        ),
    }.items()
    for name in names
}


def __getattr__(name: str) -> Any:
    """Import the submodule that defines ``name`` on first use."""
    if name not in _WHERE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{_WHERE[name]}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(__all__)
