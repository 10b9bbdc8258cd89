"""Position PIDT1 and (E04) process PIDT1 (manual figure 8-12).

Kp, Ki, Kd and T1 are typed or set with logarithmic sliders; the simulated closed-loop step
response (the emulator's control loop run faster than real time off the GUI thread, see
:mod:`prm9tool.online.tuning`) follows the trial values while a slider moves. Releasing a slider or
finishing a typed entry is one undo step.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from PySide6.QtCore import Qt
from PySide6.QtGui import QCloseEvent
from PySide6.QtWidgets import QGridLayout, QLabel, QPushButton, QSlider, QWidget

from prm9tool.catalogue import CATALOGUE
from prm9tool.i18n import format_value
from prm9tool.online.connection_protocol import StepSimulation
from prm9tool.views.diagram.dialogs.base import BlockContext, BlockDialog
from prm9tool.views.diagram.dialogs.plot import BLUE, GREY, ORANGE, Axes, Curve, PlotWidget

if TYPE_CHECKING:  # imported when a simulator is made: it brings numpy and the emulator
    from prm9tool.online.tuning import StepResponse

SLIDER_STEPS = 1000
GAINS = ("KP", "KI", "KD", "T1")


def slider_to_raw(position: int, raw_max: int) -> int:
    """Logarithmic slider position (0…1000) → raw value 0…``raw_max``."""
    return round(10 ** (position / SLIDER_STEPS * math.log10(raw_max + 1)) - 1)


def raw_to_slider(raw: int, raw_max: int) -> int:
    """Raw value → nearest logarithmic slider position."""
    return round(math.log10(max(raw, 0) + 1) / math.log10(raw_max + 1) * SLIDER_STEPS)


class ControllerDialog(BlockDialog):
    """The four PIDT1 values of one loop, sliders and the simulated step response."""

    DEFAULT_SIZE = (780, 540)  # the step response is the point of the dialog

    def __init__(
        self,
        ctx: BlockContext,
        block_id: str,
        title: str,
        prefix: str,
        loop: str,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(ctx, block_id, title, parent)
        self.prefix, self.loop = prefix, loop
        self.names = [f"{prefix}{g}" for g in GAINS]
        self.gain_fields = {name: self.value_field(name) for name in self.names}
        self.sliders = {name: self._make_slider(name) for name in self.names}
        self._trial: dict[str, int] = {}
        self._last_applied: StepResponse | None = None
        self._current: StepResponse | None = None
        self.plot = PlotWidget()
        self.plot.legend_bottom_right = True  # the step rises through the top-left corner
        self.figures = QLabel()
        self.figures.setWordWrap(True)
        self.side.addWidget(self.plot, 1)
        self.side.addWidget(self.figures)
        self.side.addLayout(self._slider_grid())
        self.tuning_button = QPushButton()
        self.tuning_button.setVisible(ctx.open_tuning is not None)
        self.tuning_button.clicked.connect(self._on_tuning_clicked)
        self.side.addWidget(self.tuning_button, 0, Qt.AlignmentFlag.AlignRight)
        self.simulator = self._make_simulator()
        self.finish()
        self._simulate()

    def _make_slider(self, name: str) -> QSlider:
        slider = QSlider(Qt.Orientation.Horizontal)
        slider.setRange(0, SLIDER_STEPS)
        slider.setMinimumWidth(240)
        slider.setObjectName(name)  # the slots find their parameter through sender()
        slider.valueChanged.connect(self._on_slider_value_changed)
        slider.sliderReleased.connect(self._on_slider_released)
        return slider

    def _slider_grid(self) -> QGridLayout:
        grid = QGridLayout()
        self.slider_labels = {}
        for row, name in enumerate(self.names):
            label = QLabel(name[len(self.prefix) :].title())  # Kp, Ki, Kd, T1
            self.slider_labels[name] = label
            grid.addWidget(label, row, 0)
            grid.addWidget(self.sliders[name], row, 1)
        return grid

    def _make_simulator(self) -> StepSimulation | None:
        factory = self.ctx.simulator_factory
        if factory is None:
            return None
        simulator = factory(self.doc, self.loop)
        simulator.response_ready.connect(self._on_response_ready)
        simulator.failed.connect(self._on_simulation_failed)
        return simulator

    # --- values -------------------------------------------------------------------------------
    def trial_values(self) -> dict[str, int]:
        """The controller values the simulation uses: the document's, overlaid by slider trials."""
        values = {name: int(self.doc.value(name)) for name in self.names}
        values.update(self._trial)
        return values

    def refresh_extra(self) -> None:
        for name, slider in self.sliders.items():
            if not slider.isSliderDown():
                slider.blockSignals(True)
                slider.setValue(raw_to_slider(int(self.doc.value(name)), CATALOGUE[name].raw_max))
                slider.blockSignals(False)
        if not any(s.isSliderDown() for s in self.sliders.values()):
            self._trial.clear()
            self._simulate()

    def update_access_extra(self, read_only: bool) -> None:
        for name, slider in self.sliders.items():
            slider.setEnabled(not read_only and self.access.may_edit(CATALOGUE[name]))

    def _on_tuning_clicked(self) -> None:
        if self.ctx.open_tuning is not None:
            self.ctx.open_tuning(self.loop)

    def retranslate(self) -> None:
        super().retranslate()
        self.tuning_button.setText(self.tr("Tuning and autotune…"))
        if self.ctx.simulator_factory is None:
            self.figures.setText(self.tr("No simulation available."))

    # --- simulation -----------------------------------------------------------------------------
    def _simulate(self) -> None:
        if self.simulator is not None:
            self.simulator.request(self.trial_values())

    def _on_response_ready(self, response: StepResponse) -> None:
        if response.values == {n: int(self.doc.value(n)) for n in self.names}:
            self._last_applied = response
        self._current = response
        self._draw()

    def _on_simulation_failed(self, message: str) -> None:
        self.figures.setText(self.tr("Simulation failed: %1").replace("%1", message))

    def _draw(self) -> None:
        response = self._current
        if response is None:
            return
        curves = [Curve(_ms(response.t, response.setpoint), ORANGE, self.tr("setpoint"))]
        previous = self._last_applied
        if previous is not None and previous is not response:
            points = _ms(previous.t, previous.actual)
            curves.append(Curve(points, GREY, self.tr("applied values"), dashed=True))
        curves.append(Curve(_ms(response.t, response.actual), BLUE, self.tr("actual value")))
        peak = max([*response.actual, *response.setpoint, 1.0])
        low = min([*response.actual, *response.setpoint, 0.0])
        span = peak - low
        x_range = (response.t[0] * 1000.0, response.t[-1] * 1000.0)
        y_range = (low - 0.08 * span, peak + 0.12 * span)
        self.plot.set_axes(Axes(x_range, y_range, self.tr("Time (ms)"), self.tr("Value (%)")))
        self.plot.set_curves(curves)
        self.figures.setText(response.summary() + "\n" + self._plant_text())

    def _plant_text(self) -> str:
        """Which plant the simulated step ran on: the twin of the document's serial, else the
        emulator's own (issue 31 item 3)."""
        twin = getattr(self.simulator, "twin", None)
        if twin is None:
            return self.tr("Simulated on the emulator's plant (no twin of this serial).")
        return self.tr("Simulated on the twin of serial {0} (fitted {1}).").format(
            twin.serial, twin.date[:10]
        )

    # --- sliders ------------------------------------------------------------------------------------
    def _on_slider_value_changed(self, position: int) -> None:
        self.slider_moved(self.sender().objectName(), position)

    def slider_moved(self, name: str, position: int) -> None:
        """A slider of ``name`` moved to ``position``: trial while dragged, else an edit."""
        raw = slider_to_raw(position, CATALOGUE[name].raw_max)
        if self.sliders[name].isSliderDown():
            self._trial[name] = raw
            self.gain_fields[name].setText(format_value(CATALOGUE[name], raw))
            self._simulate()
        else:
            self.apply_value(name, raw)

    def _on_slider_released(self) -> None:
        self.slider_released(self.sender().objectName())

    def slider_released(self, name: str) -> None:
        """The drag of slider ``name`` ended: apply its trial value as one undo step."""
        raw = self._trial.pop(name, None)
        if raw is not None:
            self.apply_value(name, raw)

    def closeEvent(self, event: QCloseEvent) -> None:
        if self.simulator is not None:
            self.simulator.stop()
        super().closeEvent(event)


def _ms(times: tuple[float, ...], values: tuple[float, ...]) -> list[tuple[float, float]]:
    """Points (ms, value) of a response."""
    return [(t * 1000.0, v) for t, v in zip(times, values, strict=True)]
