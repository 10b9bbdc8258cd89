"""The pages of the Tuning window: the common page and the Bode page (autotune: autotune.py)."""

from __future__ import annotations

import math
from typing import Any

from PySide6.QtCore import QRectF
from PySide6.QtGui import QPainter, QPaintEvent
from PySide6.QtWidgets import (
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from prm9tool.analysis.profile import DEFAULT
from prm9tool.characterize.procedures import (
    BodeResult,
    bode_test,
)
from prm9tool.characterize.run import Characterization
from prm9tool.i18n import format_number, format_significant
from prm9tool.views.tuning.host import TuningHost, spin
from prm9tool.views.tuning.plot import Plot, paint_plot
from prm9tool.views.tuning.report import (
    bode_plots,
)


class PlotView(QWidget):
    """Shows one or more :class:`Plot` stacked vertically (three or more in two columns), in
    the palette's colours."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.plots: list[Plot] = []
        self.setMinimumHeight(200)

    def show_plots(self, plots: list[Plot]) -> None:
        """Replace what is shown."""
        self.plots = plots
        self.update()

    def paintEvent(self, _event: QPaintEvent) -> None:
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.fillRect(self.rect(), self.palette().base())
        ink = self.palette().text().color()
        columns = 2 if len(self.plots) >= 3 else 1  # four plots: two by two
        rows = max(1, -(-len(self.plots) // columns))
        width, height = self.width() / columns, self.height() / rows
        for k, plot in enumerate(self.plots):
            row, column = divmod(k, columns)
            area = QRectF(column * width, row * height, width, height)
            paint_plot(painter, area, plot, ink)
        painter.end()


class Page(QWidget):
    """Common parts: a form of settings, a Run button, a result text and a plot."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__()  # the window's tabs become its parent
        self.window_ = window
        self.form = QFormLayout()
        self.labels: dict[str, QLabel] = {}
        self.run_button = QPushButton()
        self.run_button.clicked.connect(self.run)
        self.result = QLabel()
        self.result.setWordWrap(True)
        self.result.setMinimumHeight(self.result.fontMetrics().height() * 3)
        self.plot = PlotView()
        self.buttons = QHBoxLayout()
        self.buttons.addWidget(self.run_button)
        self.buttons.addStretch(1)
        layout = QVBoxLayout(self)
        layout.addLayout(self.form)
        layout.addLayout(self.buttons)
        layout.addWidget(self.result)
        layout.addWidget(self.plot, 1)

    def field(self, key: str, widget: QWidget) -> Any:
        """Add a labelled settings field."""
        self.labels[key] = QLabel()
        self.form.addRow(self.labels[key], widget)
        return widget

    def set_busy(self, busy: bool) -> None:
        """Disable the Run button while a test runs."""
        self.run_button.setEnabled(not busy)

    def run(self) -> None:
        """Start this page's test."""

    def show_result(self, result: object) -> None:
        """Show a finished test's result."""

    def retranslate(self) -> None:
        """Texts in the program language."""

    def tr_label(self, key: str, text: str) -> None:
        """Set a field's label."""
        self.labels[key].setText(text)


def _g(value: float) -> str:
    """A setting's value as the program language writes it (``0,2`` in German)."""
    return format_significant(value, 6).replace("-", "−")


# per loop: the sweep's default range (Hz): the spool's, the integrating process loop's
SWEEP_DEFAULTS = {"position": (1.0, 200.0), "process": (0.2, 20.0)}


class BodePage(Page):
    """A logarithmic sine sweep around an operating point."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__(window)

        self.amplitude = self.field("amplitude", spin(10.0, 1.0, 90.0, "%"))
        self.centre = self.field("centre", spin(0.0, -50.0, 50.0, "%"))
        self.f_min = self.field("f_min", spin(1.0, 0.1, 100.0, "Hz"))
        self.f_max = self.field("f_max", spin(200.0, 10.0, 1000.0, "Hz"))
        self.duration = self.field("duration", spin(10.0, 1.0, 60.0, "s"))

    def set_loop(self, loop: str, before: str) -> None:
        """The sweep's range follows the loop (where the user left the other's default)."""
        for box, old, new in zip(
            (self.f_min, self.f_max), SWEEP_DEFAULTS[before], SWEEP_DEFAULTS[loop], strict=True
        ):
            if box.value() == old:
                box.setValue(new)

    def run(self) -> None:
        """Sweep."""
        a, c, lo, hi, d = (
            w.value() for w in (self.amplitude, self.centre, self.f_min, self.f_max, self.duration)
        )
        loop = self.window_.current_loop()
        n = _g
        what = self.tr("a sine sweep %1 … %2 Hz of ±%3 % around %4 %, %5 s").replace("%1", n(lo)).replace(
            "%2", n(hi)).replace("%3", n(a)).replace("%4", n(c)).replace("%5", n(d))  # fmt: skip
        self.window_.start("bode", what, lambda rig: bode_test(rig, a, c, lo, hi, d, loop))

    def _frequency(self, value: float, above: float) -> str:
        """``29.3 Hz``, ``above 100 Hz`` (not reached by the sweep's end) or ``not reached``."""
        if not math.isnan(value):
            return f"{format_number(value, 1)} Hz"
        if not math.isnan(above):
            return self.tr("above %1 Hz").replace("%1", _g(above))
        return self.tr("not reached")

    def show_result(self, result: object) -> None:
        """Magnitude, phase, −3 dB and −90°."""
        assert isinstance(result, BodeResult)
        fake = Characterization(None, DEFAULT, "", {}, bode=result)  # type: ignore[arg-type]
        self.plot.show_plots(list(bode_plots(fake)))
        r = result.response
        text = self.tr("−3 dB: %1, −90°: %2.").replace(
            "%1", self._frequency(r.bandwidth_hz(), r.bandwidth_above_hz())).replace(
            "%2", self._frequency(r.phase_90_hz(), r.phase_90_above_hz()))  # fmt: skip
        if result.lost_samples:
            text += " " + self.tr(
                "%1 of %2 samples were lost on the link and left out of the estimate."
            ).replace("%1", str(result.lost_samples)).replace("%2", str(len(result.record.t)))
        if result.held_s:  # a busy PC wrote the setpoint too seldom from there on
            text += " " + self.tr(
                "The PC held the valve's setpoint for %1 ms at %2 Hz: the sweep counts up to "
                "there (at least 4 setpoint changes per period)."
            ).replace("%1", format_number(result.held_s * 1000, 0)).replace(
                "%2", _g(round(result.limited_to_hz or 0.0, 1))
            )
        elif result.limited_to_hz is not None:
            text += " " + self.tr(
                "The link's sample rate limited the sweep to %1 Hz (nothing interpolated)."
            ).replace("%1", _g(result.limited_to_hz))
        self.result.setText(text)

    def retranslate(self) -> None:
        """Texts."""
        for key, text in (
            ("amplitude", self.tr("Amplitude:")),
            ("centre", self.tr("Operating point:")),
            ("f_min", self.tr("From:")),
            ("f_max", self.tr("To:")),
            ("duration", self.tr("Duration:")),
        ):
            self.tr_label(key, text)  # fmt: skip
        self.run_button.setText(self.tr("Measure the frequency response"))
