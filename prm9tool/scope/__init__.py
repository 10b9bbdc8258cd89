"""Oscilloscope model: ring buffer, trigger engine, cursors, step-response figures, CSV, generator.

Numpy, no Qt widgets (the widget lives in ``prm9tool/views/scope/widget.py``; the generator's
messages go through QtCore's translate). Samples arrive from the valve's stream as raw
``(n, channels)`` blocks; :class:`Capture` converts them to display units once and appends them
to a preallocated :class:`RingBuffer`, so everything downstream (trigger level, cursors,
figures, CSV) works in the units the user sees. Sample ``i`` of a capture lies at
``i / rate`` seconds after the capture started. A link that places its samples by time (over
CANopen by the SYNC count) gives a NaN row for each lost sample: a gap at its time, drawn as a
break in the curve and left out of the figures; the USB stream has no gaps (its lost samples
are counted by the session).
"""

from __future__ import annotations

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
from prm9tool.scope.generator import GeneratorSettings, Waveform, setpoint_limits
from prm9tool.scope.measure import (
    CursorReadout,
    Step,
    StepFigures,
    StepMeasurement,
    Verdict,
    cursor_readout,
    find_step,
    find_steps,
    measure_step,
    step_figures,
    write_csv,
)
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
